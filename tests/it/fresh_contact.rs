//! A fresh contact loaded from zero along a fixed direction: whether it
//! sticks, and the force ratio it then carries, must not depend on the
//! load increments. Mindlin (1949; Johnson 1985, §7.3): a Hertz contact
//! whose tangential and normal displacements grow in a fixed ratio u / delta
//! carries F_t / F_n = (k_t / k_n) (u / delta) with no slip anywhere, where
//! k_t / k_n = 8 G* a / (2 E* a) = 2 (1 - nu) / (2 - nu) for equal
//! materials; it sticks if mu_s exceeds that ratio and slides otherwise.
//!
//! Scene 01 (three V-grooves of planes, 45-degree flanks, steel, no
//! support compliance) seated with one mu_s at every contact descends
//! along z alone (its three-fold symmetry), so every contact's
//! u / delta = tan 45 = 1 and the ratio is 2 (1 - nu) / (2 - nu) = 0.8235
//! for nu = 0.3. Each increment's K_t integrates Mindlin's stiffness over
//! the increment (`contact::ContactLaw::increment_semi_axis`), so the first
//! increment already carries the exact ratio and the stick/slip decision,
//! which a fresh contact keeps along a proportional path, is the limit's
//! at any number of increments.

use crate::common::load;

use kinrepro::contact::SlipState;
use kinrepro::solve::quasistatic::seat;
use kinrepro::solve::{Load, Seating, SolverOptions};

/// Mindlin's F_t / F_n of a contact of equal materials with u / delta = 1.
fn mindlin_ratio(nu: f64) -> f64 {
    2.0 * (1.0 - nu) / (2.0 - nu)
}

/// Scene 01 seated with mu_s = `factor` x Mindlin's ratio at every
/// contact, at 1, 2, 20 and 320 fixed increments and on the controlled path.
fn seatings(factor: f64) -> Vec<(String, Seating)> {
    let (scene, c) = load("01_maxwell_vgroove_steel.toml");
    let mu = Load::nominal(&scene).with_mu(&vec![factor * mindlin_ratio(0.3); c.contacts.len()]);
    let mut opts: Vec<(String, SolverOptions)> = [1, 2, 20, 320]
        .into_iter()
        .map(|n| (format!("{n} fixed increments"), SolverOptions::fixed(n)))
        .collect();
    opts.push(("the controlled path".into(), SolverOptions::default()));
    opts.into_iter().map(|(label, o)| (label, seat(&c, &mu, &o).unwrap())).collect()
}

#[test]
fn a_fresh_contact_above_mindlins_ratio_sticks_at_that_ratio_at_any_increments() {
    let ratio = mindlin_ratio(0.3);
    for (label, s) in seatings(1.01) {
        for (i, k) in s.contacts.iter().enumerate() {
            assert_eq!(k.state, SlipState::Stick, "{label}: contact {}", i + 1);
            let r = k.tangential_force_n / k.normal_force_n;
            assert!(
                (r / ratio - 1.0).abs() < 1e-6,
                "{label}: contact {} carries {r}, Mindlin {ratio}",
                i + 1
            );
        }
    }
}

/// Below the ratio every contact slides at mu_d F_n.
#[test]
fn a_fresh_contact_below_mindlins_ratio_slides_at_any_increments() {
    for (label, s) in seatings(0.99) {
        for (i, k) in s.contacts.iter().enumerate() {
            assert_eq!(k.state, SlipState::Slip, "{label}: contact {}", i + 1);
            let r = k.tangential_force_n / k.normal_force_n;
            assert!(
                (r / k.mu_dynamic - 1.0).abs() < 1e-9,
                "{label}: contact {} carries {r}, mu_d {}",
                i + 1,
                k.mu_dynamic
            );
        }
    }
}

/// The increment's effective semi-axis against an independent quadrature:
/// a_eff = int a d(a^2) / int d(a^2) over the increment, by Simpson's rule
/// on a fine grid of the normal force (a ~ F^(1/3)), for increments from
/// zero, small and large; and its relative derivative against a central
/// difference in the new normal force.
#[test]
fn the_increments_semi_axis_is_mindlins_stiffness_integrated_over_the_increment() {
    let (_, c) = load("02_maxwell_pins_steel.toml");
    let law = &c.contacts[0].law;
    let a = |f: f64| law.hertz.semi_axes(f)[0];
    for (f0, f1) in [(0.0, 3.0), (1.0, 1.1), (0.2, 3.0), (3.0, 1.0), (2.0, 2.0)] {
        let (a_eff, dlog) = law.increment_semi_axis(f0, f1);
        // Simpson on F in [f0, f1] of a(F) d(a^2)/dF, over the same of d(a^2)/dF,
        // d(a^2)/dF = (2/3) a^2 / F; in the variable t = F^(1/3) it is smooth.
        let n = 2000;
        let (t0, t1) = (f0.cbrt(), f1.cbrt());
        let (mut num, mut den) = (0.0, 0.0);
        for k in 0..=n {
            let t = t0 + (t1 - t0) * k as f64 / n as f64;
            let w = if k == 0 || k == n {
                1.0
            } else if k % 2 == 1 {
                4.0
            } else {
                2.0
            };
            let f = t * t * t;
            let ai = a(f);
            // d(a^2)/dt = 2 a da/dt, a ~ t: d(a^2)/dt = 2 a^2 / t.
            let da2 = if t > 0.0 { 2.0 * ai * ai / t } else { 0.0 };
            num += w * ai * da2;
            den += w * da2;
        }
        let expect = if f0 == f1 { a(f1) } else { num / den };
        assert!((a_eff / expect - 1.0).abs() < 1e-9, "{f0} -> {f1}: {a_eff} against {expect}");
        let h = 1e-6 * f1;
        let (up, _) = law.increment_semi_axis(f0, f1 + h);
        let (down, _) = law.increment_semi_axis(f0, f1 - h);
        let numeric = (up - down) / (2.0 * h) / a_eff;
        assert!(
            (dlog / numeric - 1.0).abs() < 1e-6,
            "{f0} -> {f1}: d ln a_eff / dF {dlog} against {numeric}"
        );
    }
}
