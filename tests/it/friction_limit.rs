//! The friction limit for seating (`check`, `assembly::friction_limit`)
//! against a second, independent statics solver of the symmetric Maxwell coupling.
//!
//! Statics (Hale 1999; Patti & Vogels 2019): the coupling can stick off its seat
//! when, with one contact open, the other five can balance the preload with forces
//! inside their Coulomb cones |F_t| <= mu F_n. The least such mu is the limit.
//! Here the geometry is built by hand from docs/model.md's axes and contact numbering (balls at 90, 210, 330 deg
//! on the 80 mm circle, 90-degree grooves: normals 45 deg from z, 5 mm balls,
//! contact point = ball centre - radius * normal) and the cone is bracketed
//! between an inscribed and a circumscribed pyramid of 256 facets, so the true
//! limit is known to cos(pi/256) (0.008 %) without the code's geometry or its
//! 64-facet pyramid.

use crate::common;

use microlp::{ComparisonOp, OptimizationDirection, Problem};
use nalgebra::Vector3;

/// (contact point, normal into the ball) of the six Maxwell contacts: the
/// contact point lies one ball radius from the centre against the normal.
fn maxwell(ball_radius: f64, alpha: f64) -> Vec<(Vector3<f64>, Vector3<f64>)> {
    common::maxwell_contacts(alpha).into_iter().map(|(c, n)| (c - n * ball_radius, n)).collect()
}

/// Can the contacts other than `open` carry a unit upward force through the
/// origin with cone generators n + r (e1 cos phi + e2 sin phi), r = `radius`?
fn feasible(contacts: &[(Vector3<f64>, Vector3<f64>)], open: usize, radius: f64, k: usize) -> bool {
    let mut lp = Problem::new(OptimizationDirection::Minimize);
    let mut rows: [Vec<(microlp::Variable, f64)>; 6] = Default::default();
    for (j, (p, n)) in contacts.iter().enumerate() {
        if j == open {
            continue;
        }
        // A tangent basis unrelated to the code's choice.
        let e1 = n.cross(&Vector3::new(0.3, -0.5, 0.8)).normalize();
        let e2 = n.cross(&e1);
        for f in 0..k {
            let phi = std::f64::consts::TAU * (f as f64 + 0.5) / k as f64;
            let g = n + (e1 * phi.cos() + e2 * phi.sin()) * radius;
            // Moments about the origin, scaled by the circle radius.
            let m = (p / 0.04).cross(&g);
            let v = lp.add_var(1.0, (0.0, f64::INFINITY));
            for r in 0..3 {
                rows[r].push((v, g[r]));
                rows[3 + r].push((v, m[r]));
            }
        }
    }
    let rhs = [0.0, 0.0, 1.0, 0.0, 0.0, 0.0];
    for (r, row) in rows.iter().enumerate() {
        lp.add_constraint(row.as_slice(), ComparisonOp::Eq, rhs[r]);
    }
    lp.solve().is_ok()
}

/// Least mu at which contact `open` can stay open; `scale` widens the pyramid
/// (1 inscribed, 1/cos(pi/k) circumscribed).
fn least_mu(contacts: &[(Vector3<f64>, Vector3<f64>)], open: usize, k: usize, scale: f64) -> f64 {
    let (mut lo, mut hi) = (0.0, 2.0);
    assert!(feasible(contacts, open, hi * scale, k));
    while hi - lo > 1e-6 {
        let mid = 0.5 * (lo + hi);
        if feasible(contacts, open, mid * scale, k) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    hi
}

#[test]
fn maxwell_friction_limit_matches_an_independent_statics_solution() {
    let contacts = maxwell(0.005, 45f64.to_radians());
    let k = 256;
    let widen = 1.0 / (std::f64::consts::PI / k as f64).cos();
    // By the three-fold rotation and the mirror of each groove, every contact
    // has the same limit; contact 1 stands for all (checked for contact 4).
    let upper = least_mu(&contacts, 0, k, 1.0);
    let lower = least_mu(&contacts, 0, k, widen);
    assert!(lower <= upper && upper / lower - 1.0 < 1e-4, "{lower} {upper}");
    let other = least_mu(&contacts, 3, k, 1.0);
    assert!(other >= lower - 1e-6 && other * (2.0 - widen) <= upper + 1e-6, "{other}");

    let (scene, c) = common::load("01_maxwell_vgroove_steel.toml");
    let limit = kinrepro::assembly::friction_limit::friction_limit(&c, &scene.preload);
    // The code reports its inscribed 64-facet pyramid's limit (bisection to
    // 1e-4), which lies in [true, true / cos(pi/64)] = true + at most 0.12 %.
    let code = limit.mu_limit;
    assert!(
        code >= lower - 1e-4 && code * (1.0 - limit.cone_error_bound) <= upper + 1e-4,
        "code {code} vs statics [{lower}, {upper}]"
    );
    println!("friction limit: statics [{lower:.6}, {upper:.6}], code {code:.6}");

    // The same limit through `check`.
    let scene = common::scene("01_maxwell_vgroove_steel.toml");
    let (ok, out, err) = common::kinrepro(&["check", scene.to_str().unwrap()]);
    assert!(ok, "{err}");
    let shown = out
        .split("friction limit for seating: mu < ")
        .nth(1)
        .and_then(|s| s.split_whitespace().next())
        .unwrap();
    assert!((shown.parse::<f64>().unwrap() - code).abs() <= 5e-5, "{shown} vs {code}");
}

/// Statics is homogeneous in the load: the friction limit of a coupling
/// does not depend on the preload's size (only on the geometry and the
/// preload's line of action). Solved anew for scaled preloads, the limit
/// and its critical contact stay within the bisection's resolution; and
/// the code's memo of solved limits returns exactly what a solve anew
/// gives, for each of them.
#[test]
fn friction_limit_does_not_depend_on_the_preload_size() {
    use kinrepro::assembly::friction_limit::{friction_limit, friction_limit_solved_anew};
    for name in ["01_maxwell_vgroove_steel.toml", "06_kelvin_steel.toml"] {
        let (scene, c) = common::load(name);
        let reference = friction_limit_solved_anew(&c, &scene.preload);
        assert!(reference.mu_limit.is_finite() && reference.mu_limit > 0.05, "{name}");
        for factor in [0.013, 3.7, 250.0] {
            let mut preload = scene.preload.clone();
            for f in &mut preload.forces {
                f.force *= factor;
            }
            let scaled = friction_limit_solved_anew(&c, &preload);
            assert_eq!(friction_limit(&c, &preload), scaled, "{name} x{factor}");
            assert!(
                (scaled.mu_limit - reference.mu_limit).abs() <= 1e-4,
                "{name} x{factor}: {} vs {}",
                scaled.mu_limit,
                reference.mu_limit
            );
            assert_eq!(scaled.critical_contact, reference.critical_contact, "{name} x{factor}");
        }
        assert_eq!(friction_limit(&c, &scene.preload), reference, "{name}");
    }
}
