//! Contact laws against independent values: Hertz closed forms, Boussinesq
//! superposition of the elliptical Hertz pressure, the circular limit,
//! Hamrock-Brewe, Coulomb and Mindlin-Deresiewicz hysteresis.

use std::f64::consts::PI;

use kinrepro::contact::{
    ContactPair, ContactShape, Friction, HertzLaw, PrincipalStiffness, SlipState, TangentialInput,
    TangentialLaw, TangentialResponse, TangentialState,
};
use kinrepro::material::{Material, builtin_names, effective_modulus};
use nalgebra::{Matrix3, Vector3};
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
    let plane = ContactPair::from_shape(ContactShape::SpherePlane, 5e-3, None, steel(), steel())
        .unwrap()
        .evaluate(5.0)
        .unwrap();
    let mut last = f64::INFINITY;
    for r2 in [1e-1, 1e1, 1e3, 1e5] {
        let cyl =
            ContactPair::from_shape(ContactShape::SphereCylinder, 5e-3, Some(r2), steel(), steel())
                .unwrap()
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

/// Hamrock & Brewe (1983) curve fits (J. Lubrication Technol.
/// 105:171-177; stated accuracy a few percent) for load `f`: the semi-axes
/// a > b and the approach, `rx` < `ry` the relative radii of curvature:
/// ```text
/// kappa = 1.0339 (Ry/Rx)^0.6360,  Eps = 1.0003 + 0.5968 Rx/Ry,
/// Fi = 1.5277 + 0.6023 ln(Ry/Rx), 1/R = 1/Rx + 1/Ry, E' = 2 E*,
/// a = (6 kappa^2 Eps f R / (pi E'))^(1/3),  b = (6 Eps f R / (pi kappa E'))^(1/3),
/// delta = Fi (9/(2 Eps R) (f / (pi kappa E'))^2)^(1/3)
/// ```
fn hamrock_brewe(rx: f64, ry: f64, e_star: f64, f: f64) -> [f64; 3] {
    let alpha = ry / rx;
    let kappa = 1.0339 * alpha.powf(0.6360);
    let eps = 1.0003 + 0.5968 / alpha;
    let fi = 1.5277 + 0.6023 * alpha.ln();
    let r = 1.0 / (1.0 / rx + 1.0 / ry);
    let ep = 2.0 * e_star;
    [
        (6.0 * kappa * kappa * eps * f * r / (PI * ep)).cbrt(),
        (6.0 * eps * f * r / (PI * kappa * ep)).cbrt(),
        fi * (9.0 / (2.0 * eps * r) * (f / (PI * kappa * ep)).powi(2)).cbrt(),
    ]
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
        let [hb_a, hb_b, hb_approach] = hamrock_brewe(rx, ry, e_star, f);
        let [a, b] = law.semi_axes(f);
        let tol = if (2.0..=20.0).contains(&ratio) { 0.015 } else { 0.06 };
        assert!(rel(hb_a, a) < tol, "ratio {ratio}: a {hb_a} vs {a}");
        assert!(rel(hb_b, b) < tol, "ratio {ratio}: b {hb_b} vs {b}");
        assert!(rel(hb_approach, law.approach(f)) < tol, "ratio {ratio}: delta");
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
    for tl in TangentialLaw::ALL {
        let r = respond(&st, tl, &input(-1.0, Vector3::new(1e-6, 0.0, 0.0), 0.5, 0.4));
        assert_eq!(r.force, Vector3::zeros());
    }
}

/// A contact with 10 N normal load, k_t = 1e7 N/m, contact radius 50 um.
fn input(fn_: f64, du: Vector3<f64>, mu_s: f64, mu_d: f64) -> TangentialInput {
    let plane = Matrix3::identity() - Vector3::z() * Vector3::z().transpose();
    let k = 8.0 * 25e9 * 50e-6;
    TangentialInput {
        normal: Vector3::z(),
        du,
        normal_force: fn_,
        stiffness: k * plane,
        principal: PrincipalStiffness::new([k, k], &Vector3::z(), &Vector3::x()),
        d_stiffness_d_fn: Matrix3::zeros(),
        contact_radius: 50e-6,
        g_star: 25e9,
        mindlin_shape: plane,
        friction: Friction::switch(mu_s, mu_d),
    }
}

/// The law's response to one increment from `old`, with its tangent.
fn respond(old: &TangentialState, law: TangentialLaw, inp: &TangentialInput) -> TangentialResponse {
    let mut r = TangentialResponse::open(inp.normal);
    old.update(law, inp, true, &mut r);
    r
}

/// Drive a contact along x through displacements `path`, return (u, F_x) pairs.
fn drive(law: TangentialLaw, path: &[f64], fn_: f64, mu_s: f64, mu_d: f64) -> Vec<(f64, f64)> {
    let mut st = TangentialState::new(Vector3::z());
    let mut u = 0.0;
    let mut out = vec![(0.0, 0.0)];
    for &target in path {
        let r = respond(&st, law, &input(fn_, Vector3::new(target - u, 0.0, 0.0), mu_s, mu_d));
        st = r.state;
        u = target;
        out.push((u, r.force.x));
    }
    out
}

fn cycle_path(amplitude: f64, steps: usize, cycles: usize) -> Vec<f64> {
    // 0 -> +A, then full cycles +A -> -A -> +A.
    let mut p: Vec<f64> = (1..=steps).map(|i| amplitude * i as f64 / steps as f64).collect();
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
    tail.windows(2).map(|w| 0.5 * (w[0].1 + w[1].1) * (w[1].0 - w[0].0)).sum::<f64>().abs()
}

#[test]
fn coulomb_cycle_dissipates_the_closed_form_energy() {
    let (fn_, mu_s, mu_d) = (10.0, 0.5, 0.4);
    let k = 8.0 * 25e9 * 50e-6;
    let u0 = 3.0 * mu_s * fn_ / k;
    let steps = 20000;
    let hist = drive(TangentialLaw::Coulomb, &cycle_path(u0, steps, 2), fn_, mu_s, mu_d);
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

/// dF/d(du) of one update against central finite differences in the
/// contact plane (x, y), to 1e-5 of the tangent's norm.
fn assert_du_tangent(old: &TangentialState, law: TangentialLaw, inp: &TangentialInput) {
    let r = respond(old, law, inp);
    for j in 0..2 {
        let h = 1e-13;
        let (mut ip, mut im) = (*inp, *inp);
        ip.du[j] += h;
        im.du[j] -= h;
        let fd = (respond(old, law, &ip).force - respond(old, law, &im).force) / (2.0 * h);
        let an = r.d_force_d_du.column(j).into_owned();
        assert!(
            (fd - an).norm() <= 1e-5 * r.d_force_d_du.norm() + 1e-9,
            "{law:?} {:?} col {j}: fd {fd:?} an {an:?}",
            r.slip
        );
    }
}

#[test]
fn consistent_tangents_match_finite_differences() {
    let old_slip = {
        let mut st = TangentialState::new(Vector3::z());
        st = respond(
            &st,
            TangentialLaw::Coulomb,
            &input(10.0, Vector3::new(1e-5, 2e-6, 0.0), 0.5, 0.4),
        )
        .state;
        st
    };
    let old_stick = TangentialState::new(Vector3::z());
    for law in TangentialLaw::ALL {
        for (old, du) in [
            (old_stick.clone(), Vector3::new(1e-7, 3e-8, 0.0)), // stick
            (old_stick.clone(), Vector3::new(2e-7, -4e-7, 0.0)), // partial slip (MD)
            (old_slip.clone(), Vector3::new(2e-6, 1e-6, 0.0)),  // slip
        ] {
            let mut inp = input(10.0, du, 0.5, 0.4);
            inp.d_stiffness_d_fn = inp.stiffness / 30.0;
            // Mindlin-Deresiewicz starts a fresh row at this load.
            let old = &TangentialState { normal_force: 10.0, ..old };
            let r = respond(old, law, &inp);
            assert_du_tangent(old, law, &inp);
            if law == TangentialLaw::Coulomb {
                // K_t(F_n + s) = K_t (1 + s/30), both as the tensor and
                // by its principal values.
                let loaded = |s: f64| {
                    let f = 1.0 + s / 30.0;
                    let mut i = inp;
                    i.normal_force += s;
                    i.stiffness *= f;
                    i.principal.k = i.principal.k.map(|k| k * f);
                    i
                };
                let h = 1e-6;
                let (ip, im) = (loaded(h), loaded(-h));
                let fd = (respond(old, law, &ip).force - respond(old, law, &im).force) / (2.0 * h);
                assert!((fd - r.d_force_d_fn).norm() < 1e-6 * (1.0 + fd.norm()));
            }
        }
    }
}

#[test]
fn old_force_is_rotated_into_the_new_tangent_plane() {
    let mut st = TangentialState::new(Vector3::z());
    st = respond(&st, TangentialLaw::Coulomb, &input(10.0, Vector3::new(1e-7, 0.0, 0.0), 0.5, 0.4))
        .state;
    let n2 = Vector3::new(0.01, 0.0, 1.0).normalize();
    let rot = st.rotated_to(&n2);
    assert!(rot.force.dot(&n2).abs() < 1e-15 * rot.force.norm());
    assert!(rel(rot.force.norm(), st.force.norm()) < 1e-15);
    let r = respond(
        &st,
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
        shape_i in 0usize..6,
    ) {
        let shape = ContactShape::ALL[shape_i];
        let concave = matches!(shape, ContactShape::SphereSeat | ContactShape::SphereGroove);
        let r2 = if concave { r1 * (1.0 + r2 * 10.0) } else { r2 };
        // Independent moduli (docs/model.md, Hertz; Johnson 1985 eq. 4.22 and 7.18):
        // 1/E* = sum (1 - v^2)/E, 1/G* = sum (2 - v)/G, G = E / (2 (1 + v)).
        let e_star = 1.0 / [&m1, &m2].iter().map(|m| (1.0 - m.poisson_ratio.powi(2)) / m.youngs_modulus).sum::<f64>();
        let g_star = 1.0 / [&m1, &m2].iter()
            .map(|m| (2.0 - m.poisson_ratio) * 2.0 * (1.0 + m.poisson_ratio) / m.youngs_modulus)
            .sum::<f64>();
        let pair = ContactPair::from_shape(shape, r1, Some(r2), m1, m2).unwrap();
        let e = pair.evaluate(f).unwrap();
        let law = pair.law().unwrap();
        // F = K delta^1.5 round trip, and dF/ddelta = 3F/(2 delta).
        prop_assert!(rel(law.hertz.force(e.approach_m), f) < 1e-12);
        prop_assert!(rel(e.normal_stiffness_n_per_m, 1.5 * f / e.approach_m) < 1e-12);
        // a >= b, p0 = 3F/(2 pi a b).
        prop_assert!(e.semi_axes_m[0] >= e.semi_axes_m[1]);
        prop_assert!(rel(e.max_pressure_pa, 3.0 * f / (2.0 * PI * e.semi_axes_m[0] * e.semi_axes_m[1])) < 1e-12);
        prop_assert!(rel(e.effective_modulus_pa, e_star) < 1e-12);
        prop_assert!(rel(e.effective_shear_modulus_pa, g_star) < 1e-12);
        // Relative radii from the shapes (docs/model.md, Hertz): plane R = r1, convex
        // ball 1/R = 1/r1 + 1/r2, concave seat 1/R = 1/r1 - 1/r2; crossed
        // cylinder: 1/(1/r1 + 1/r2) across the axis and r1 along it; concave
        // groove: 1/(1/r1 - 1/r2) across and r1 along; pins crossed at 90
        // degrees: r1 and r2 (each pin's curvature alone in its direction).
        let across = 1.0 / (1.0 / r1 + 1.0 / r2);
        let radii = match shape {
            ContactShape::SpherePlane => [r1, r1],
            ContactShape::SphereSphere => [across, across],
            ContactShape::SphereSeat => [1.0 / (1.0 / r1 - 1.0 / r2); 2],
            ContactShape::SphereCylinder => [across, r1],
            ContactShape::SphereGroove => [1.0 / (1.0 / r1 - 1.0 / r2), r1],
            ContactShape::CrossedCylinders => [r1, r2],
            ContactShape::General => unreachable!("not in ContactShape::ALL"),
        };
        let mut got = e.relative_radii_m;
        got.sort_by(f64::total_cmp);
        prop_assert!(rel(got[0], radii[0].min(radii[1])) < 1e-12 && rel(got[1], radii[0].max(radii[1])) < 1e-12, "{got:?} vs {radii:?}");
        if matches!(shape, ContactShape::SpherePlane | ContactShape::SphereSphere | ContactShape::SphereSeat) {
            // Circular contacts: Hertz closed forms a = (3FR/4E*)^(1/3), delta = a^2/R.
            let r = radii[0];
            let a = (3.0 * f * r / (4.0 * e_star)).cbrt();
            prop_assert!(rel(e.semi_axes_m[0], a) < 1e-12);
            prop_assert!(rel(e.approach_m, a * a / r) < 1e-12);
            prop_assert!(rel(e.tangential_stiffness_n_per_m, 8.0 * g_star * a) < 1e-12);
        } else {
            // The ellipse's tangential stiffness lies between those of the
            // circles of radius b and a (Mindlin: k_t = 8 G* a for a circle).
            let kt = e.tangential_stiffness_n_per_m;
            prop_assert!(kt <= 8.0 * g_star * e.semi_axes_m[0] && kt >= 8.0 * g_star * e.semi_axes_m[1]);
        }
    }
}

/// sigma_z/p0 on the axis of an elliptical Hertz contact, closed form:
/// -a b / sqrt((a^2 + z^2)(b^2 + z^2)) (Johnson 1985, §3.7, from the
/// ellipsoidal potential; the circle gives -1/(1 + (z/a)^2), Johnson eq. 3.45,
/// and the line contact -b/sqrt(b^2 + z^2), Johnson eq. 2.44).
fn sigma_z_closed_form(kp: f64, zeta_b: f64) -> f64 {
    let (a, b, z) = (1.0 / kp, 1.0, zeta_b);
    -a * b / ((a * a + z * z) * (b * b + z * z)).sqrt()
}

#[test]
fn elliptical_tau_max_matches_published_values() {
    use kinrepro::contact::stress::{
        circular_axis_shear, elliptical_axis_shear, elliptical_axis_stresses, max_shear_ratio,
    };
    // The quadrature on a circle against Johnson's closed form (eq. 3.45).
    for nu in [0.2, 0.3, 0.45] {
        for zeta in [0.2, 0.48, 1.0, 2.0] {
            let q = elliptical_axis_shear(nu, 1.0, zeta);
            let c = circular_axis_shear(nu, zeta);
            assert!((q - c).abs() < 1e-9, "nu {nu} z {zeta}: {q} vs {c}");
        }
    }
    // sigma_z against its closed form for several shapes and depths.
    for kp in [1.0, 0.7, 0.436, 0.2, 0.05, 0.002] {
        for zeta in [0.3, 0.654, 1.5] {
            let s = elliptical_axis_stresses(0.3, kp, zeta)[2];
            let c = sigma_z_closed_form(kp, zeta);
            let tol = if kp < 0.01 { 1e-5 } else { 1e-8 };
            assert!(rel(s, c) < tol, "b/a {kp} z {zeta}: {s} vs {c}");
        }
    }
    // Published values: b/a = 1, nu = 0.3: 0.31 p0 at z = 0.48 a (Johnson
    // 1985, §3.4); b/a -> 0: the line contact's 0.300 p0 at z = 0.786 b
    // (Johnson §4.3; the in-plane pair, independent of nu; for nu < 0.25 the
    // out-of-plane pair exceeds it near the surface: (1 - 2 nu)/2 at z = 0);
    // b/a = 0.436 (the 5 mm ball on the 2 mm
    // steel pin): 0.325 p0 at z = 0.654 b (issue 13).
    let (t, z) = max_shear_ratio(0.3, 1.0);
    assert!(rel(t, 0.31) < 5e-3 && rel(z, 0.48) < 5e-3, "{t} at {z}");
    for nu in [0.27, 0.3, 0.45] {
        let (t, z) = max_shear_ratio(nu, 0.002);
        assert!(rel(t, 0.300) < 5e-3 && rel(z, 0.786) < 5e-3, "nu {nu}: {t} at {z}");
    }
    let (t, _) = max_shear_ratio(0.1, 0.002);
    assert!(t > 0.4, "nu 0.1: the out-of-plane pair governs: {t}");
    let (t, z) = max_shear_ratio(0.3, 0.436);
    assert!(rel(t, 0.325) < 5e-3 && rel(z, 0.654) < 5e-3, "{t} at {z}");
    println!("tau_max/p0 at b/a = 0.436: {t:.5} at z = {z:.4} b");
}

// ---- Mindlin-Deresiewicz (method of dimensionality reduction) under force
// control, through `contact::history::drive`, against closed forms. ----

use kinrepro::contact::history::{LoadStep, drive as drive_history};

/// 5 mm steel ball on a steel plane: a circular contact.
fn steel_ball_on_plane() -> kinrepro::contact::ContactLaw {
    ContactPair::from_shape(ContactShape::SpherePlane, 5e-3, None, steel(), steel())
        .unwrap()
        .law()
        .unwrap()
}

/// Hertz radius a = (3 P R / (4 E*))^(1/3) and G* = 1 / sum((2 - nu)/G),
/// computed here from the material constants (Johnson eqs. 4.22, 7.40).
fn circle_constants(p: f64) -> (f64, f64) {
    let (e, nu) = (210e9_f64, 0.3_f64);
    let e_star = 1.0 / (2.0 * (1.0 - nu * nu) / e);
    let g = e / (2.0 * (1.0 + nu));
    let g_star = 1.0 / (2.0 * (2.0 - nu) / g);
    ((3.0 * p * 5e-3 / (4.0 * e_star)).cbrt(), g_star)
}

fn steps(rows: &[(f64, f64)]) -> Vec<LoadStep> {
    rows.iter().map(|&(p, q)| LoadStep { normal_force: p, tangential_force: [q, 0.0] }).collect()
}

const MU: Friction = Friction::switch(0.5, 0.4);

#[test]
fn cattaneo_ramp_matches_the_closed_form_at_every_step() {
    let law = steel_ball_on_plane();
    let p = 10.0;
    let (a, g) = circle_constants(p);
    let n = 200;
    // Row 0 applies P; then Q ramps at constant P.
    let rows: Vec<(f64, f64)> =
        (0..=n).map(|i| (p, 0.9 * MU.mu_s * p * i as f64 / n as f64)).collect();
    let out = drive_history(&law, TangentialLaw::MindlinDeresiewicz, MU, &steps(&rows)).unwrap();
    // Cattaneo (1938), Mindlin (1949); Johnson eq. 7.49:
    // s = 3 mu P / (16 G* a) [1 - (1 - Q/(mu P))^(2/3)].
    let mut worst: f64 = 0.0;
    for st in &out[1..] {
        let q = st.load.tangential_force[0] / (MU.mu_s * p);
        let s = 3.0 * MU.mu_s * p / (16.0 * g * a) * (1.0 - (1.0 - q).powf(2.0 / 3.0));
        worst = worst.max(rel(st.displacement[0], s));
        if std::env::var("DBG").is_ok() {
            println!("q {q:.4} err {:.3e}", st.displacement[0] / s - 1.0);
        }
        assert_eq!(st.displacement[1], 0.0);
        assert_eq!(st.slip, SlipState::Stick);
    }
    assert!(worst < 5e-3, "worst relative error {worst:e}");
    println!("Cattaneo ramp: worst relative error {worst:.2e}");
}

/// Work of Q over the closed load path, trapezoidal in s.
fn loop_work(out: &[kinrepro::contact::history::HistoryStep]) -> f64 {
    out.windows(2)
        .map(|w| {
            0.5 * (w[0].load.tangential_force[0] + w[1].load.tangential_force[0])
                * (w[1].displacement[0] - w[0].displacement[0])
        })
        .sum::<f64>()
        .abs()
}

#[test]
fn masing_loop_dissipates_the_mindlin_deresiewicz_energy() {
    let law = steel_ball_on_plane();
    let p = 10.0;
    let (a, g) = circle_constants(p);
    let n = 400;
    for q_star in [0.3, 0.6, 0.9] {
        let qs = q_star * MU.mu_s * p;
        let mut rows: Vec<(f64, f64)> = (0..=n).map(|i| (p, qs * i as f64 / n as f64)).collect();
        let cycle: Vec<(f64, f64)> = (1..=2 * n)
            .map(|i| (p, qs * (1.0 - i as f64 / n as f64)))
            .chain((1..=2 * n).map(|i| (p, qs * (-1.0 + i as f64 / n as f64))))
            .collect();
        rows.extend(&cycle);
        rows.extend(&cycle);
        let out =
            drive_history(&law, TangentialLaw::MindlinDeresiewicz, MU, &steps(&rows)).unwrap();
        let last = &out[out.len() - 4 * n - 1..];
        // Mindlin & Deresiewicz (1953); Johnson eq. 7.60:
        // W = 9 mu^2 P^2/(10 a G*) [1 - (1-q)^(5/3) - 5q/6 (1 + (1-q)^(2/3))].
        let (mu, q) = (MU.mu_s, q_star);
        let expect = 9.0 * mu * mu * p * p / (10.0 * a * g)
            * (1.0 - (1.0 - q).powf(5.0 / 3.0) - 5.0 * q / 6.0 * (1.0 + (1.0 - q).powf(2.0 / 3.0)));
        let w = loop_work(last);
        assert!(rel(w, expect) < 1e-2, "Q*/muP {q}: W {w:e} vs {expect:e}");
        println!("Masing loop Q*/muP = {q}: W/W_MD - 1 = {:.2e}", w / expect - 1.0);
        // The loop closes (Masing): the second cycle ends where the first did.
        let s1 = out[out.len() - 4 * n - 1].displacement[0];
        let s2 = out.last().unwrap().displacement[0];
        assert!((s2 - s1).abs() < 1e-3 * s1.abs(), "{s1:e} {s2:e}");
    }
}

#[test]
fn proportional_loading_has_the_mindlin_deresiewicz_compliance() {
    let law = steel_ball_on_plane();
    let p_max = 20.0;
    // Geometric load steps from 1e-6 P_max: each step is a proportional
    // increment, which the law follows exactly (the springs that enter
    // during a step take their share of it, `Row::share`), from the first.
    let n = 900;
    for lambda in [0.1, 0.4] {
        let rows: Vec<(f64, f64)> = (0..=n)
            .map(|i| p_max * 1e-6_f64.powf(1.0 - i as f64 / n as f64))
            .map(|p| (p, lambda * p))
            .collect();
        let out =
            drive_history(&law, TangentialLaw::MindlinDeresiewicz, MU, &steps(&rows)).unwrap();
        let mut worst: f64 = 0.0;
        for st in &out {
            let (p, q) = (st.load.normal_force, st.load.tangential_force[0]);
            let (a, g) = circle_constants(p);
            // Mindlin & Deresiewicz (1953); Johnson §7.3: dQ/dP = lambda < mu
            // from zero: no slip, s = 1.5 Q / (8 G* a).
            let md = 1.5 * q / (8.0 * g * a);
            worst = worst.max(rel(st.displacement[0], md));
            // The old law: Cattaneo's curve with the current P on the total s,
            // s = 3 mu P/(16 G* a) [1 - (1 - lambda/mu)^(2/3)], 1/1.5 of it at small lambda.
            let old = 3.0 * MU.mu_s * p / (16.0 * g * a)
                * (1.0 - (1.0 - lambda / MU.mu_s).powf(2.0 / 3.0));
            assert!(st.displacement[0] / old > 1.2, "{} vs old {old}", st.displacement[0]);
            assert_eq!(st.slip, SlipState::Stick);
        }
        assert!(worst < 1e-9, "lambda {lambda}: worst {worst:e}");
        println!("proportional loading lambda = {lambda}: worst relative error {worst:.2e}");
    }
}

/// The issue's history: P to 5 N and Q to 1.5 N together from zero in 1, 5
/// or 2000 force-controlled steps. Both laws give Mindlin's
/// s = 1.5 Q / (8 G* a) within 1e-6 at every step count (the MD law was
/// 23.8 % below it in one step, 10 % in 5, 0.25 % in 2000).
#[test]
fn a_proportional_step_from_zero_is_exact_in_both_laws() {
    let law = steel_ball_on_plane();
    for n in [1, 5, 2000] {
        let rows: Vec<(f64, f64)> =
            (1..=n).map(|i| i as f64 / n as f64).map(|f| (5.0 * f, 1.5 * f)).collect();
        for tangential in [TangentialLaw::MindlinDeresiewicz, TangentialLaw::Coulomb] {
            let out = drive_history(&law, tangential, MU, &steps(&rows)).unwrap();
            let st = out.last().unwrap();
            let (a, g) = circle_constants(5.0);
            let md = 1.5 * 1.5 / (8.0 * g * a);
            let e = rel(st.displacement[0], md);
            assert!(e < 1e-6, "{tangential:?}, {n} steps: {:e} vs {md:e}", st.displacement[0]);
        }
    }
}

/// Mindlin's compliance along (`along_major`) or across the major axis of an
/// ellipse with semi-axes a = 1 >= b = kp, per body, by the trapezoidal rule
/// (periodic integrand: spectral convergence) over the Cerruti kernel:
/// C = 1/(8 pi a b G) int_0^2pi R(theta) [(1 - nu) + nu cos^2(theta)] dtheta
/// (sin^2 across), R(theta) = a b / sqrt(b^2 cos^2 + a^2 sin^2) (docs/model.md, Hertz;
/// Johnson 1985 §7.2 with Cerruti's point-force displacement, eq. 3.86a).
fn cerruti_compliance(m: &Material, kp: f64, along_major: bool) -> f64 {
    let (a, b) = (1.0, kp);
    let g = m.youngs_modulus / (2.0 * (1.0 + m.poisson_ratio));
    let nu = m.poisson_ratio;
    let n = 20_000;
    let sum: f64 = (0..n)
        .map(|i| {
            let th = 2.0 * PI * i as f64 / n as f64;
            let (s, c) = th.sin_cos();
            let r = a * b / (b * b * c * c + a * a * s * s).sqrt();
            let dir = if along_major { c * c } else { s * s };
            r * ((1.0 - nu) + nu * dir)
        })
        .sum();
    sum * (2.0 * PI / n as f64) / (8.0 * PI * a * b * g)
}

#[test]
fn elliptical_tangential_stiffness_matches_cerruti_quadrature() {
    use kinrepro::contact::mindlin_axis_coefficients;
    let sic = Material::builtin("silicon-carbide").unwrap();
    for (m1, m2) in [(steel(), steel()), (steel(), sic.clone())] {
        for kp in [1.0, 0.7, 0.436, 0.2] {
            let k = mindlin_axis_coefficients(&m1, &m2, kp); // a = 1
            for (axis, along) in [(0, true), (1, false)] {
                let c = cerruti_compliance(&m1, kp, along) + cerruti_compliance(&m2, kp, along);
                assert!(
                    rel(k[axis], 1.0 / c) < 5e-3,
                    "b/a {kp} axis {axis}: {} vs {}",
                    k[axis],
                    1.0 / c
                );
                assert!(rel(k[axis], 1.0 / c) < 1e-9, "b/a {kp}: closed form vs quadrature");
            }
            if kp == 1.0 {
                // Circle: 8 G* a, 1/G* = sum (2 - nu)/G (Mindlin 1949).
                let cg = |m: &Material| {
                    (2.0 - m.poisson_ratio) * 2.0 * (1.0 + m.poisson_ratio) / m.youngs_modulus
                };
                let k8 = 8.0 / (cg(&m1) + cg(&m2));
                assert!(rel(k[0], k8) < 1e-12 && rel(k[1], k8) < 1e-12);
            }
        }
    }
    // The steel pin contact (5 mm ball, 2 mm pin): across the pin (minor
    // axis) about 8 % and along it about 0.8 % stiffer than 8 G* sqrt(a b).
    let e =
        ContactPair::from_shape(ContactShape::SphereCylinder, 5e-3, Some(2e-3), steel(), steel())
            .unwrap()
            .evaluate(6.5)
            .unwrap();
    let [a, b] = e.semi_axes_m;
    let k_eq = 8.0 * e.effective_shear_modulus_pa * (a * b).sqrt();
    let (major, minor) =
        (e.tangential_stiffness_major_n_per_m / k_eq, e.tangential_stiffness_minor_n_per_m / k_eq);
    assert!((1.075..1.09).contains(&minor), "{minor}");
    assert!((1.004..1.012).contains(&major), "{major}");
    println!("steel pin: k_minor/k_eq = {minor:.4}, k_major/k_eq = {major:.4}");
}

/// A second, independent MDR for a circle and a tangential load of fixed
/// direction: 4000 scalar springs on a fixed grid up to the largest contact
/// radius, 4 sub-steps per row (P and Q linear in between), each a normal
/// update (springs leaving the contact lose their displacement, springs over
/// their limit slide to it) and a bisection on the rigid displacement for
/// the prescribed Q (Popov & Hess 2015, §7.2).
fn reference_mdr(rows: &[(f64, f64)], mu: f64) -> Vec<f64> {
    let p_max = rows.iter().map(|r| r.0).fold(0.0, f64::max);
    let (a_max, _) = circle_constants(p_max);
    let m = 4000;
    let dx = 1.0001 * a_max / m as f64;
    let mut u = vec![0.0_f64; m];
    let mut s = 0.0;
    let mut prev = (rows[0].0, 0.0);
    let mut out = Vec::new();
    for &row in rows {
        for k in 1..=4 {
            let f = k as f64 / 4.0;
            let (p, q) = (prev.0 + f * (row.0 - prev.0), prev.1 + f * (row.1 - prev.1));
            let (a, g) = circle_constants(p);
            let delta_star = 3.0 * mu * p / (16.0 * g * a);
            let lim: Vec<f64> = (0..m)
                .map(|i| {
                    let x = (i as f64 + 0.5) * dx;
                    if x < a { delta_star * (1.0 - x * x / (a * a)) } else { -1.0 }
                })
                .collect();
            for i in 0..m {
                u[i] = if lim[i] < 0.0 { 0.0 } else { u[i].clamp(-lim[i], lim[i]) };
            }
            let force = |ds: f64| -> f64 {
                8.0 * g
                    * dx
                    * (0..m)
                        .filter(|&i| lim[i] >= 0.0)
                        .map(|i| (u[i] + ds).clamp(-lim[i], lim[i]))
                        .sum::<f64>()
            };
            let (mut lo, mut hi) = (-4.0 * delta_star, 4.0 * delta_star);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if force(mid) < q { lo = mid } else { hi = mid }
            }
            let ds = 0.5 * (lo + hi);
            for i in 0..m {
                if lim[i] >= 0.0 {
                    u[i] = (u[i] + ds).clamp(-lim[i], lim[i]);
                }
            }
            s += ds;
        }
        prev = row;
        out.push(s);
    }
    out
}

#[test]
fn growing_and_shrinking_contact_agrees_with_a_fine_mdr_reference() {
    let law = steel_ball_on_plane();
    let seg = |from: (f64, f64), to: (f64, f64), n: usize| -> Vec<(f64, f64)> {
        (1..=n)
            .map(|i| {
                let f = i as f64 / n as f64;
                (from.0 + f * (to.0 - from.0), from.1 + f * (to.1 - from.1))
            })
            .collect()
    };
    // P first, then: Q grows with P (a grows), Q to 0.8 mu P at constant P,
    // P falls with Q (a shrinks, the edge slips), Q reverses, P and Q grow again.
    let mut rows = vec![(0.5, 0.0)];
    let pts = [(0.5, 0.0), (10.0, 2.0), (10.0, 4.0), (6.0, 2.0), (6.0, -2.2), (12.0, 3.0)];
    for w in pts.windows(2) {
        rows.extend(seg(w[0], w[1], 100));
    }
    let out = drive_history(&law, TangentialLaw::MindlinDeresiewicz, MU, &steps(&rows)).unwrap();
    let reference = reference_mdr(&rows, MU.mu_s);
    let scale = reference.iter().fold(0.0_f64, |m, s| m.max(s.abs()));
    let worst = out
        .iter()
        .zip(&reference)
        .map(|(o, r)| (o.displacement[0] - r).abs() / scale)
        .fold(0.0, f64::max);
    assert!(worst < 1e-2, "worst |s - s_ref| / max|s_ref| = {worst:e}");
    println!("growing/shrinking history: worst |s - s_ref| / max|s_ref| = {worst:.2e}");
}

#[test]
fn the_removed_cattaneo_mindlin_law_is_a_clear_scene_error() {
    let text = std::fs::read_to_string(
        std::path::Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("scenes/01_maxwell_vgroove_steel.toml"),
    )
    .unwrap()
    .replace("tangential_law = \"coulomb\"", "tangential_law = \"cattaneo-mindlin\"");
    let e = kinrepro::scene::Scene::parse(&text, "test.toml").unwrap_err().to_string();
    assert!(e.contains("test.toml") && e.contains("mindlin-deresiewicz"), "{e}");
    let ok = text.replace("\"cattaneo-mindlin\"", "\"mindlin-deresiewicz\"");
    assert!(kinrepro::scene::Scene::parse(&ok, "test.toml").is_ok());
}

#[test]
fn a_sliding_contact_under_growing_load_carries_mu_d_p_in_both_laws() {
    // As in a V groove during seating: P grows while the ball slides. Coulomb
    // (and Mindlin-Deresiewicz in gross slip): |F_t| = mu_d P at the end load.
    for law in TangentialLaw::ALL {
        let mut st = TangentialState { normal_force: 9.0, ..TangentialState::new(Vector3::z()) };
        for k in 0..5 {
            let p = 10.0 + k as f64;
            let r = respond(&st, law, &input(p, Vector3::new(2e-6, 0.0, 0.0), 0.5, 0.4));
            st = r.state;
            st.normal_force = p;
            if k > 0 {
                assert_eq!(r.slip, SlipState::Slip, "{law:?}");
                assert!(rel(r.force.norm(), 0.4 * p) < 1e-12, "{law:?}: {}", r.force.norm());
            }
        }
    }
}

#[test]
fn anisotropic_slip_return_is_associated_and_its_tangent_is_consistent() {
    use kinrepro::contact::mindlin::project_on_circle;
    use nalgebra::{Matrix2, Vector2};
    let k = [1.0e7, 1.08e7];
    let limit = 2.0;
    for (i, trial) in [(3.0, 0.5), (-1.0, 2.5), (0.3, -4.0), (2.0, 2.0)].iter().enumerate() {
        let tr = Vector2::new(trial.0, trial.1);
        let (f, d_trial, d_limit) = project_on_circle(k, &tr, limit);
        // On the circle, and the slip K^-1 (F_trial - F) is along F, positive
        // (associated Coulomb slip: the friction force opposes the slip).
        assert!(rel(f.norm(), limit) < 1e-13, "case {i}");
        let slip = Vector2::new((tr.x - f.x) / k[0], (tr.y - f.y) / k[1]);
        assert!((slip.x * f.y - slip.y * f.x).abs() < 1e-12 * slip.norm() * f.norm());
        assert!(slip.dot(&f) > 0.0);
        // Equal stiffnesses: the radial return.
        let (fr, _, _) = project_on_circle([k[0], k[0]], &tr, limit);
        assert!((fr - tr * (limit / tr.norm())).norm() < 1e-13 * limit);
        // Derivatives against central differences.
        let h = 1e-6;
        let mut fd = Matrix2::zeros();
        for j in 0..2 {
            let mut e = Vector2::zeros();
            e[j] = h;
            let col = (project_on_circle(k, &(tr + e), limit).0
                - project_on_circle(k, &(tr - e), limit).0)
                / (2.0 * h);
            fd.set_column(j, &col);
        }
        assert!((fd - d_trial).norm() < 1e-7, "case {i}: {fd} vs {d_trial}");
        let fl = (project_on_circle(k, &tr, limit + h).0 - project_on_circle(k, &tr, limit - h).0)
            / (2.0 * h);
        assert!((fl - d_limit).norm() < 1e-7);
    }
    // Both laws with an elliptical K_t: tangent of the whole update against
    // finite differences, in stick, partial slip and gross slip.
    let n = Vector3::z();
    let (e1, e2) = (Vector3::new(0.6, 0.8, 0.0), Vector3::new(-0.8, 0.6, 0.0));
    let kt = 1e7 * e1 * e1.transpose() + 1.08e7 * e2 * e2.transpose();
    for law in TangentialLaw::ALL {
        for du in [
            Vector3::new(1e-7, 3e-8, 0.0),
            Vector3::new(2e-7, -4e-7, 0.0),
            Vector3::new(2e-6, 1e-6, 0.0),
        ] {
            let inp = TangentialInput {
                stiffness: kt,
                principal: PrincipalStiffness::new([1e7, 1.08e7], &n, &e1),
                mindlin_shape: kt / 1e7,
                ..input(10.0, du, 0.5, 0.4)
            };
            let old = TangentialState { normal_force: 10.0, ..TangentialState::new(n) };
            assert_du_tangent(&old, law, &inp);
        }
    }
}

/// The solver's lazy tangent (`TangentialState::update` with `tangent`
/// false): force, state and slip those of the update with the tangent (to
/// 1e-12 relative), for both laws, stick, partial slip and slip, the
/// switch and the decay friction law, circular and elliptical K_t; the
/// derivatives of the slot are left as they were (a Newton iterate that
/// converges never reads them), and with `tangent` the slot holds the
/// whole response of a fresh update.
#[test]
fn the_tangent_free_update_gives_the_full_updates_force_and_state() {
    use kinrepro::contact::FrictionLaw;
    let close = |a: &[f64], b: &[f64]| {
        let scale = b.iter().fold(0.0f64, |m, v| m.max(v.abs()));
        a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-12 * scale)
    };
    let slid = respond(
        &TangentialState::new(Vector3::z()),
        TangentialLaw::Coulomb,
        &input(10.0, Vector3::new(1e-5, 2e-6, 0.0), 0.5, 0.4),
    )
    .state;
    let stuck = TangentialState { normal_force: 9.0, ..TangentialState::new(Vector3::z()) };
    let (mut cases, mut slips) = (0, 0);
    for law in TangentialLaw::ALL {
        for friction in [FrictionLaw::Switch, FrictionLaw::Decay { coefficient: 1e6 }] {
            if law == TangentialLaw::MindlinDeresiewicz && friction != FrictionLaw::Switch {
                continue; // the decay law works with Coulomb only
            }
            for k in [[4e7, 4e7], [5e7, 3e7]] {
                let principal = PrincipalStiffness::new(k, &Vector3::z(), &Vector3::x());
                for (old, du) in [
                    (&stuck, Vector3::new(1e-7, 3e-8, 0.0)),
                    (&stuck, Vector3::new(2e-7, -4e-7, 0.0)),
                    (&slid, Vector3::new(2e-6, 1e-6, 0.0)),
                ] {
                    let mut inp = input(10.0, du, 0.5, 0.4);
                    inp.stiffness = principal.tensor(&Vector3::z());
                    inp.principal = principal;
                    inp.d_stiffness_d_fn = inp.stiffness / 30.0;
                    inp.friction.law = friction;
                    inp.friction.duration = 1e-3;
                    let full = respond(old, law, &inp);
                    // A slot holding another contact's response.
                    let mut slot = TangentialResponse {
                        d_force_d_du: Matrix3::from_element(7.0),
                        d_force_d_fn: Vector3::repeat(-3.0),
                        ..respond(&slid, law, &input(10.0, Vector3::new(-3e-6, 0.0, 0.0), 0.5, 0.4))
                    };
                    old.update(law, &inp, false, &mut slot);
                    let (got, want) = (&slot.state, &full.state);
                    assert!(close(slot.force.as_slice(), full.force.as_slice()));
                    assert!(close(got.force.as_slice(), want.force.as_slice()));
                    assert!(close(&[got.slip_velocity], &[want.slip_velocity]));
                    assert_eq!(got.sliding, want.sliding, "{law:?} {friction:?}");
                    assert!(close(got.normal.as_slice(), want.normal.as_slice()));
                    assert!(close(&[got.normal_force], &[want.normal_force]));
                    assert_eq!(got.row.is_some(), want.row.is_some());
                    if let (Some(a), Some(b)) = (&got.row, &want.row) {
                        assert!(close(a.q.as_flattened(), b.q.as_flattened()));
                        assert!(close(&[a.h], &[b.h]));
                    }
                    assert_eq!(slot.slip, full.slip);
                    if law == TangentialLaw::Coulomb {
                        assert_eq!(slot.d_force_d_du, Matrix3::from_element(7.0));
                        assert_eq!(slot.d_force_d_fn, Vector3::repeat(-3.0));
                    }
                    old.update(law, &inp, true, &mut slot);
                    assert!(close(slot.force.as_slice(), full.force.as_slice()));
                    let (got, want) = (&slot.d_force_d_du, &full.d_force_d_du);
                    assert!(close(got.as_slice(), want.as_slice()), "{got} vs {want}");
                    let (got, want) = (&slot.d_force_d_fn, &full.d_force_d_fn);
                    assert!(close(got.as_slice(), want.as_slice()), "{got} vs {want}");
                    cases += 1;
                    slips += usize::from(full.slip == SlipState::Slip);
                }
            }
        }
    }
    assert_eq!(cases, 18);
    assert!((6..18).contains(&slips), "{slips} of the cases slip");
}
