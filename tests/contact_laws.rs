//! Contact laws against independent values: Hertz closed forms, Boussinesq
//! superposition of the elliptical Hertz pressure, the circular limit,
//! Hamrock-Brewe, Coulomb and Mindlin-Deresiewicz hysteresis.

use std::f64::consts::PI;

use kinrepro::contact::elliptic::hamrock_brewe;
use kinrepro::contact::{
    ContactPair, ContactShape, Friction, HertzLaw, SlipState, TangentialInput, TangentialLaw,
    TangentialState,
};
use kinrepro::material::{Material, builtin_names, effective_modulus};
use nalgebra::Vector3;
use proptest::prelude::*;

fn steel() -> Material {
    Material::builtin("steel").unwrap()
}

fn rel(a: f64, b: f64) -> f64 {
    (a / b - 1.0).abs()
}

/// Surface displacement at (x0, y0) inside the ellipse under the Hertz
/// pressure p0 sqrt(1 - x^2/a^2 - y^2/b^2), by Boussinesq superposition
/// u = 1/(pi E*) int p / s dA (Johnson eq. 3.20), in polar coordinates about
/// the point: the radial integral of sqrt(gamma (r1 - r)(r - r2)) is done in
/// closed form, the angle by the trapezoidal rule (periodic: converges fast).
fn boussinesq_displacement(a: f64, b: f64, p0: f64, e_star: f64, x0: f64, y0: f64) -> f64 {
    let n = 4096;
    let mut sum = 0.0;
    for i in 0..n {
        let th = 2.0 * PI * (i as f64) / (n as f64);
        let (s, c) = th.sin_cos();
        let gamma = c * c / (a * a) + s * s / (b * b);
        let beta = x0 * c / (a * a) + y0 * s / (b * b);
        let alpha = 1.0 - x0 * x0 / (a * a) - y0 * y0 / (b * b);
        // alpha - 2 beta r - gamma r^2 = gamma (r1 - r)(r - r2)
        let disc = (beta * beta + alpha * gamma).sqrt();
        let r1 = (-beta + disc) / gamma;
        let r2 = (-beta - disc) / gamma;
        let h = 0.5 * (r1 - r2);
        let m = 0.5 * (r1 + r2);
        let phi0 = (-m / h).asin();
        let f = |p: f64| p + p.sin() * p.cos();
        let radial = gamma.sqrt() * h * h / 2.0 * (f(PI / 2.0) - f(phi0));
        sum += radial;
    }
    p0 * sum * (2.0 * PI / n as f64) / (PI * e_star)
}

#[test]
fn elliptical_hertz_satisfies_boussinesq_compatibility() {
    // Crossed 5 mm ball on 2 mm pin, steel/silicon carbide, 4.7 N.
    let e_star = effective_modulus(&steel(), &Material::builtin("silicon-carbide").unwrap());
    let (rx, ry) = (1.0 / (1.0 / 5e-3 + 1.0 / 2e-3), 5e-3);
    let law = HertzLaw::elliptical(rx, ry, e_star);
    let f = 4.7;
    let [a, b] = law.semi_axes(f);
    let p0 = law.max_pressure(f);
    let delta = law.approach(f);
    // Inside the contact the surfaces must conform: u(x, y) = delta - x^2/(2 Ry) - y^2/(2 Rx)
    // (major axis a along the larger radius Ry).
    for (fx, fy) in [(0.0, 0.0), (0.5, 0.0), (0.0, 0.5), (0.3, 0.6), (0.7, -0.2)] {
        let (x, y) = (fx * a, fy * b);
        let u = boussinesq_displacement(a, b, p0, e_star, x, y);
        let gap = delta - x * x / (2.0 * ry) - y * y / (2.0 * rx);
        assert!(rel(u, gap) < 1e-9, "at ({fx},{fy}): u {u:e} vs {gap:e}");
    }
    // Load equals the integral of the pressure: F = 2/3 pi a b p0.
    assert!(rel(2.0 / 3.0 * PI * a * b * p0, f) < 1e-14);
}

#[test]
fn elliptical_law_tends_to_circular_as_cylinder_radius_grows() {
    let plane = ContactPair {
        shape: ContactShape::SpherePlane,
        radius1: 5e-3,
        radius2: None,
        material1: steel(),
        material2: steel(),
    }
    .evaluate(5.0)
    .unwrap();
    let mut last = f64::INFINITY;
    for r2 in [1e-1, 1e1, 1e3, 1e5] {
        let cyl = ContactPair {
            shape: ContactShape::SphereCylinder,
            radius2: Some(r2),
            ..ContactPair {
                shape: ContactShape::SpherePlane,
                radius1: 5e-3,
                radius2: None,
                material1: steel(),
                material2: steel(),
            }
        }
        .evaluate(5.0)
        .unwrap();
        let err = rel(cyl.approach_m, plane.approach_m)
            .max(rel(cyl.semi_axes_m[0], plane.semi_axes_m[0]))
            .max(rel(cyl.semi_axes_m[1], plane.semi_axes_m[1]))
            .max(rel(cyl.hertz_constant, plane.hertz_constant));
        // The difference is first order in the curvature ratio R1/R2.
        assert!(err < 5e-3 / r2 * 5.0, "R2 = {r2}: {err:e}");
        assert!(err < last);
        last = err;
    }
}

#[test]
fn hamrock_brewe_agrees_within_its_stated_accuracy() {
    // Hamrock & Brewe's curve fits are a few percent off: their kappa(1) =
    // 1.0339 instead of 1 costs 5.4 % in delta at a circle; between radius
    // ratios 2 and 20 they are within 1.5 %.
    let e_star = 115e9;
    for ratio in [1.0, 1.5, 2.0, 3.5, 5.0, 10.0, 20.0, 50.0, 100.0] {
        let rx = 1e-3;
        let ry = rx * ratio;
        let law = HertzLaw::elliptical(rx, ry, e_star);
        let f = 10.0;
        let hb = hamrock_brewe(rx, ry, e_star, f);
        let [a, b] = law.semi_axes(f);
        let tol = if (2.0..=20.0).contains(&ratio) {
            0.015
        } else {
            0.06
        };
        assert!(rel(hb.a, a) < tol, "ratio {ratio}: a {} vs {}", hb.a, a);
        assert!(rel(hb.b, b) < tol, "ratio {ratio}: b {} vs {}", hb.b, b);
        assert!(
            rel(hb.approach, law.approach(f)) < tol,
            "ratio {ratio}: delta"
        );
    }
}

#[test]
fn force_is_the_integral_of_the_stiffness() {
    let law = HertzLaw::elliptical(1.4e-3, 5e-3, 120e9);
    let delta: f64 = 7e-7;
    // Simpson on s = sqrt(delta') removes the sqrt singularity of the slope at 0:
    // F = int_0^delta k(d) dd = int_0^sqrt(delta) k(s^2) 2 s ds.
    let n = 2000;
    let h = delta.sqrt() / n as f64;
    let g = |s: f64| law.stiffness(s * s) * 2.0 * s;
    let mut sum = g(0.0) + g(delta.sqrt());
    for i in 1..n {
        sum += g(i as f64 * h) * if i % 2 == 1 { 4.0 } else { 2.0 };
    }
    assert!(rel(sum * h / 3.0, law.force(delta)) < 1e-12);
}

#[test]
fn no_force_in_tension() {
    let law = HertzLaw::circular(5e-3, 115e9);
    assert_eq!(law.force(-1e-9), 0.0);
    assert_eq!(law.force(0.0), 0.0);
    let st = TangentialState::new(Vector3::z());
    for tl in [TangentialLaw::Coulomb, TangentialLaw::CattaneoMindlin] {
        let r = st.update(tl, &input(-1.0, Vector3::new(1e-6, 0.0, 0.0), 0.5, 0.4));
        assert_eq!(r.force, Vector3::zeros());
    }
}

/// A contact with 10 N normal load, k_t = 1e7 N/m, contact radius 50 um.
fn input(fn_: f64, du: Vector3<f64>, mu_s: f64, mu_d: f64) -> TangentialInput {
    TangentialInput {
        normal: Vector3::z(),
        du,
        normal_force: fn_,
        stiffness: 8.0 * 25e9 * 50e-6,
        d_stiffness_d_fn: 0.0,
        contact_radius: 50e-6,
        g_star: 25e9,
        friction: Friction::switch(mu_s, mu_d),
    }
}

/// Drive a contact along x through displacements `path`, return (u, F_x) pairs.
fn drive(law: TangentialLaw, path: &[f64], fn_: f64, mu_s: f64, mu_d: f64) -> Vec<(f64, f64)> {
    let mut st = TangentialState::new(Vector3::z());
    let mut u = 0.0;
    let mut out = vec![(0.0, 0.0)];
    for &target in path {
        let r = st.update(
            law,
            &input(fn_, Vector3::new(target - u, 0.0, 0.0), mu_s, mu_d),
        );
        st = r.state;
        u = target;
        out.push((u, r.force.x));
    }
    out
}

fn cycle_path(amplitude: f64, steps: usize, cycles: usize) -> Vec<f64> {
    // 0 -> +A, then full cycles +A -> -A -> +A.
    let mut p: Vec<f64> = (1..=steps)
        .map(|i| amplitude * i as f64 / steps as f64)
        .collect();
    for _ in 0..cycles {
        p.extend((1..=2 * steps).map(|i| amplitude * (1.0 - i as f64 / steps as f64)));
        p.extend((1..=2 * steps).map(|i| amplitude * (-1.0 + i as f64 / steps as f64)));
    }
    p
}

/// Work of F over the last full cycle (trapezoidal), = dissipated energy.
fn last_cycle_work(hist: &[(f64, f64)], steps: usize) -> f64 {
    let n = 4 * steps;
    let tail = &hist[hist.len() - n - 1..];
    tail.windows(2)
        .map(|w| 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0))
        .sum::<f64>()
        .abs()
}

#[test]
fn coulomb_cycle_dissipates_the_closed_form_energy() {
    let (fn_, mu_s, mu_d) = (10.0, 0.5, 0.4);
    let k = 8.0 * 25e9 * 50e-6;
    let u0 = 3.0 * mu_s * fn_ / k;
    let steps = 20000;
    let hist = drive(
        TangentialLaw::Coulomb,
        &cycle_path(u0, steps, 2),
        fn_,
        mu_s,
        mu_d,
    );
    // Elastic to mu_s Fn, sudden drop to mu_d Fn, slide; per cycle
    // W = 4 mu_d Fn u0 - (mu_s + mu_d)(3 mu_d - mu_s) Fn^2 / k (derived in the test notes).
    let expect = 4.0 * mu_d * fn_ * u0 - (mu_s + mu_d) * (3.0 * mu_d - mu_s) * fn_ * fn_ / k;
    let w = last_cycle_work(&hist, steps);
    assert!(rel(w, expect) < 2e-3, "W {w} vs {expect}");
    // Static-to-dynamic drop on first loading: max |F| = mu_s Fn (to one step), then mu_d Fn.
    let fmax = hist.iter().map(|p| p.1).fold(0.0, f64::max);
    assert!(fmax <= mu_s * fn_ && fmax > mu_s * fn_ * (1.0 - 1e-3));
    let first_peak = hist[steps].1;
    assert!(rel(first_peak, mu_d * fn_) < 1e-12);
}

#[test]
fn cattaneo_mindlin_follows_the_virgin_curve_and_mindlin_deresiewicz_loop() {
    let (fn_, mu) = (10.0, 0.5);
    let (g, a) = (25e9, 50e-6);
    let delta_star = 3.0 * mu * fn_ / (16.0 * g * a);
    let steps = 20000;
    let q_star: f64 = 0.6; // amplitude Q*/(mu P)
    let amp = delta_star * (1.0 - (1.0 - q_star).powf(2.0 / 3.0));
    let hist = drive(
        TangentialLaw::CattaneoMindlin,
        &cycle_path(amp, steps, 2),
        fn_,
        mu,
        0.8 * mu,
    );
    // Virgin curve: Q = mu P (1 - (1 - s/delta*)^1.5) (Johnson eq. 7.48).
    for &(u, q) in &hist[1..=steps] {
        let expect = mu * fn_ * (1.0 - (1.0 - u / delta_star).powf(1.5));
        assert!((q - expect).abs() < 1e-12 * mu * fn_);
    }
    assert!(rel(hist[steps].1, q_star * mu * fn_) < 1e-12);
    // Initial slope = Mindlin 8 G* a.
    let slope0 = hist[1].1 / hist[1].0;
    assert!(rel(slope0, 8.0 * g * a) < 1e-3);
    // Loop energy (Mindlin & Deresiewicz 1953; Johnson eq. 7.60):
    // W = 9 mu^2 P^2/(10 a G*) [1 - (1-q)^(5/3) - 5q/6 (1 + (1-q)^(2/3))].
    let q = q_star;
    let expect = 9.0 * mu * mu * fn_ * fn_ / (10.0 * a * g)
        * (1.0 - (1.0 - q).powf(5.0 / 3.0) - 5.0 * q / 6.0 * (1.0 + (1.0 - q).powf(2.0 / 3.0)));
    let w = last_cycle_work(&hist, steps);
    assert!(rel(w, expect) < 1e-4, "W {w:e} vs {expect:e}");
    // The loop closes (Masing): back at +amp the force is Q* again.
    assert!(rel(hist.last().unwrap().1, q_star * mu * fn_) < 1e-9);
}

#[test]
fn consistent_tangents_match_finite_differences() {
    let old_slip = {
        let mut st = TangentialState::new(Vector3::z());
        st = st
            .update(
                TangentialLaw::Coulomb,
                &input(10.0, Vector3::new(1e-5, 2e-6, 0.0), 0.5, 0.4),
            )
            .state;
        st
    };
    let old_stick = TangentialState::new(Vector3::z());
    for law in [TangentialLaw::Coulomb, TangentialLaw::CattaneoMindlin] {
        for (old, du) in [
            (old_stick, Vector3::new(1e-7, 3e-8, 0.0)),  // stick
            (old_stick, Vector3::new(2e-7, -4e-7, 0.0)), // partial slip (CM)
            (old_slip, Vector3::new(2e-6, 1e-6, 0.0)),   // slip
        ] {
            let mut inp = input(10.0, du, 0.5, 0.4);
            inp.d_stiffness_d_fn = inp.stiffness / 30.0;
            let r = old.update(law, &inp);
            for j in 0..2 {
                let h = 1e-12;
                let mut ip = inp;
                ip.du[j] += h;
                let mut im = inp;
                im.du[j] -= h;
                let fd = (old.update(law, &ip).force - old.update(law, &im).force) / (2.0 * h);
                let an = r.d_force_d_du.column(j).into_owned();
                assert!(
                    (fd - an).norm() <= 1e-5 * r.d_force_d_du.norm() + 1e-9,
                    "{law:?} {:?} col {j}: fd {fd:?} an {an:?}",
                    r.slip
                );
            }
            if law == TangentialLaw::Coulomb {
                let h = 1e-6;
                let mut ip = inp;
                ip.normal_force += h;
                ip.stiffness += h * inp.d_stiffness_d_fn;
                let mut im = inp;
                im.normal_force -= h;
                im.stiffness -= h * inp.d_stiffness_d_fn;
                let fd = (old.update(law, &ip).force - old.update(law, &im).force) / (2.0 * h);
                assert!((fd - r.d_force_d_fn).norm() < 1e-6 * (1.0 + fd.norm()));
            }
        }
    }
}

#[test]
fn old_force_is_rotated_into_the_new_tangent_plane() {
    let mut st = TangentialState::new(Vector3::z());
    st = st
        .update(
            TangentialLaw::Coulomb,
            &input(10.0, Vector3::new(1e-7, 0.0, 0.0), 0.5, 0.4),
        )
        .state;
    let n2 = Vector3::new(0.01, 0.0, 1.0).normalize();
    let rot = st.rotated_to(&n2);
    assert!(rot.force.dot(&n2).abs() < 1e-15 * rot.force.norm());
    assert!(rel(rot.force.norm(), st.force.norm()) < 1e-15);
    let r = st.update(
        TangentialLaw::Coulomb,
        &TangentialInput {
            normal: n2,
            du: Vector3::zeros(),
            ..input(10.0, Vector3::zeros(), 0.5, 0.4)
        },
    );
    assert_eq!(r.slip, SlipState::Stick);
}

fn any_material() -> impl Strategy<Value = Material> {
    prop::sample::select(builtin_names()).prop_map(|n| Material::builtin(n).unwrap())
}

proptest! {
    #[test]
    fn hertz_identities_hold_for_random_pairs(
        r1 in 1e-4f64..5e-2,
        r2 in 1e-4f64..1.0,
        m1 in any_material(),
        m2 in any_material(),
        f in 1e-3f64..1e3,
        shape_i in 0usize..4,
    ) {
        let shape = ContactShape::ALL[shape_i];
        let r2 = if shape == ContactShape::SphereSeat { r1 * (1.0 + r2 * 10.0) } else { r2 };
        let pair = ContactPair { shape, radius1: r1, radius2: Some(r2), material1: m1, material2: m2 };
        let e = pair.evaluate(f).unwrap();
        let law = pair.law().unwrap();
        // F = K delta^1.5 round trip, and dF/ddelta = 3F/(2 delta).
        prop_assert!(rel(law.hertz.force(e.approach_m), f) < 1e-12);
        prop_assert!(rel(e.normal_stiffness_n_per_m, 1.5 * f / e.approach_m) < 1e-12);
        // a >= b, p0 = 3F/(2 pi a b).
        prop_assert!(e.semi_axes_m[0] >= e.semi_axes_m[1]);
        prop_assert!(rel(e.max_pressure_pa, 3.0 * f / (2.0 * PI * e.semi_axes_m[0] * e.semi_axes_m[1])) < 1e-12);
        // Circular contacts: Hertz closed forms a = (3FR/4E*)^(1/3), delta = a^2/R.
        if shape != ContactShape::SphereCylinder {
            let r = e.relative_radii_m[0];
            let a = (3.0 * f * r / (4.0 * e.effective_modulus_pa)).cbrt();
            prop_assert!(rel(e.semi_axes_m[0], a) < 1e-12);
            prop_assert!(rel(e.approach_m, a * a / r) < 1e-12);
            prop_assert!(rel(e.tangential_stiffness_n_per_m, 8.0 * e.effective_shear_modulus_pa * a) < 1e-12);
        } else {
            // Equal-area circle: k_t = 8 G* sqrt(ab); delta = pi a E*... via stiffness = pi a E* / K(e)
            // bounded by the circles of radius b and a.
            let kt = e.tangential_stiffness_n_per_m;
            let g = e.effective_shear_modulus_pa;
            prop_assert!(kt <= 8.0 * g * e.semi_axes_m[0] && kt >= 8.0 * g * e.semi_axes_m[1]);
        }
    }
}
