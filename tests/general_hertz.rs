//! The general Hertz contact (`contact --radii1 --radii2 --angle-deg`)
//! against an independent evaluation written here from the literature:
//!
//! - the relative curvatures A <= B as half the eigenvalues of the sum of
//!   the two bodies' curvature tensors (the second fundamental forms,
//!   body 2's turned by theta), not Johnson's closed form eq. 4.2;
//! - the complete elliptic integrals K(m), E(m) by adaptive Simpson
//!   quadrature of their defining integrals, not the AGM;
//! - the ellipticity by bisection on m = 1 - (b/a)^2 of Johnson's
//!   B/A = ((a/b)^2 E - K)/(K - E) (1985, eqs. 3.59-3.60, 4.39);
//! - a from the Hamrock-Brewe (1983) form a^3 = 3 k^2 E F / (2 pi E* (A + B)),
//!   k = a/b, with the exact integrals; b = a/k; approach
//!   delta = 3 F K / (2 pi a E*); p0 = 3 F / (2 pi a b) (Johnson §4.3);
//! - and, loosely, Hamrock & Brewe's curve fits of k, E and K (within 3 %).

use std::f64::consts::PI;

mod common;
use common::{E_STAR_STEEL, kinrepro};

const INF: f64 = f64::INFINITY;

/// Adaptive Simpson quadrature of f on [a, b] to `tol`.
fn simpson(f: &dyn Fn(f64) -> f64, a: f64, b: f64, tol: f64) -> f64 {
    fn step(f: &dyn Fn(f64) -> f64, a: f64, b: f64, fa: f64, fm: f64, fb: f64, whole: f64, tol: f64, depth: u32) -> f64 {
        let m = 0.5 * (a + b);
        let (lm, rm) = (0.5 * (a + m), 0.5 * (m + b));
        let (flm, frm) = (f(lm), f(rm));
        let left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
        let right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
        let delta = left + right - whole;
        if depth == 0 || delta.abs() <= 15.0 * tol {
            return left + right + delta / 15.0;
        }
        step(f, a, m, fa, flm, fm, left, 0.5 * tol, depth - 1)
            + step(f, m, b, fm, frm, fb, right, 0.5 * tol, depth - 1)
    }
    let (fa, fm, fb) = (f(a), f(0.5 * (a + b)), f(b));
    let whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
    step(f, a, b, fa, fm, fb, whole, tol, 50)
}

/// K(m), E(m) by quadrature of their integrals over [0, pi/2].
fn elliptic(m: f64) -> (f64, f64) {
    let k = simpson(&|p: f64| 1.0 / (1.0 - m * p.sin().powi(2)).sqrt(), 0.0, 0.5 * PI, 1e-15);
    let e = simpson(&|p: f64| (1.0 - m * p.sin().powi(2)).sqrt(), 0.0, 0.5 * PI, 1e-15);
    (k, e)
}

/// A <= B: half the eigenvalues of diag(1/R11, 1/R12) + R(theta) diag(1/R21, 1/R22) R(theta)^T.
fn relative_curvatures(r1: [f64; 2], r2: [f64; 2], theta: f64) -> (f64, f64) {
    let k = |r: f64| if r.is_infinite() { 0.0 } else { 1.0 / r };
    let (c, s) = (theta.cos(), theta.sin());
    let m11 = k(r1[0]) + k(r2[0]) * c * c + k(r2[1]) * s * s;
    let m22 = k(r1[1]) + k(r2[0]) * s * s + k(r2[1]) * c * c;
    let m12 = (k(r2[0]) - k(r2[1])) * c * s;
    let (mean, radius) = (0.5 * (m11 + m22), (0.5 * (m11 - m22)).hypot(m12));
    (0.5 * (mean - radius), 0.5 * (mean + radius))
}

/// The independent Hertz solution: [a, b, p0, delta] and b/a.
fn independent(r1: [f64; 2], r2: [f64; 2], theta: f64, e_star: f64, f: f64) -> ([f64; 4], f64) {
    let (a_c, b_c) = relative_curvatures(r1, r2, theta);
    assert!(a_c > 0.0);
    let target = b_c / a_c;
    let ratio = |m: f64| {
        let (k, e) = elliptic(m);
        (e / (1.0 - m) - k) / (k - e)
    };
    let m = if target - 1.0 < 1e-12 {
        0.0
    } else {
        // B/A rises monotonically with m from 1 (m -> 0) to infinity (m -> 1).
        let (mut lo, mut hi) = (0.0, 1.0 - 1e-15);
        for _ in 0..200 {
            let mid = 0.5 * (lo + hi);
            if mid <= 0.0 || ratio(mid) < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    };
    let (kk, ee) = elliptic(m);
    let k = 1.0 / (1.0 - m).sqrt(); // a/b
    let a = (3.0 * k * k * ee * f / (2.0 * PI * e_star * (a_c + b_c))).cbrt();
    let b = a / k;
    ([a, b, 3.0 * f / (2.0 * PI * a * b), 3.0 * f * kk / (2.0 * PI * a * e_star)], b / a)
}

/// `kinrepro contact --json` for steel on steel at load f.
fn contact_json(r1: [f64; 2], r2: [f64; 2], deg: f64, f: f64) -> serde_json::Value {
    let fmt = |r: [f64; 2]| format!("{},{}", r[0], r[1]);
    let (r1s, r2s, degs, fs) = (fmt(r1), fmt(r2), deg.to_string(), f.to_string());
    let (ok, out, err) = kinrepro(&[
        "contact", "--radii1", &r1s, "--radii2", &r2s, "--angle-deg", &degs, "--material1", "steel",
        "--material2", "steel", "--load", &fs, "--json",
    ]);
    assert!(ok, "{r1s} {r2s} {degs}: {err}");
    serde_json::from_str(&out).unwrap()
}

/// (label, body 1 radii, body 2 radii, angle in degrees), lengths in m.
const CASES: [(&str, [f64; 2], [f64; 2], f64); 8] = [
    ("ball on a flat", [0.005, 0.005], [INF, INF], 0.0),
    ("crossed pins at 90 deg", [0.004, INF], [0.004, INF], 90.0),
    ("crossed pins at 30 deg", [0.003, INF], [0.002, INF], 30.0),
    ("ball in a concave groove", [0.005, 0.005], [-0.0055, INF], 0.0),
    ("canoe patch on a flat", [0.25, 0.25], [INF, INF], 0.0),
    ("canoe patch on a pin", [0.25, 0.25], [0.002, INF], 0.0),
    ("torus on a flat", [0.005, 0.02], [INF, INF], 17.0),
    ("saddle on a ball", [0.01, -0.03], [0.005, 0.005], 40.0),
];

#[test]
fn general_contact_agrees_with_an_independent_hertz_evaluation() {
    let f = 5.0;
    for (label, r1, r2, deg) in CASES {
        let v = contact_json(r1, r2, deg, f);
        let got = [
            v["semi_axes_m"][0].as_f64().unwrap(),
            v["semi_axes_m"][1].as_f64().unwrap(),
            v["max_pressure_pa"].as_f64().unwrap(),
            v["approach_m"].as_f64().unwrap(),
        ];
        let (want, kp) = independent(r1, r2, deg.to_radians(), E_STAR_STEEL, f);
        for (name, g, w) in ["a", "b", "p0", "approach"].into_iter().zip(got).zip(want).map(|((n, g), w)| (n, g, w)) {
            assert!((g / w - 1.0).abs() < 1e-6, "{label}: {name} {g:e} vs {w:e}");
        }
        // Hamrock & Brewe's fits (1983), Ry/Rx = B/A: k = 1.0339 (B/A)^0.636,
        // E = 1.0003 + 0.5968 A/B: a loose second check of the ellipse.
        let (a_c, b_c) = relative_curvatures(r1, r2, deg.to_radians());
        let k_fit = 1.0339 * (b_c / a_c).powf(0.636);
        let e_fit = 1.0003 + 0.5968 * a_c / b_c;
        let a_fit = (3.0 * k_fit * k_fit * e_fit * f / (2.0 * PI * E_STAR_STEEL * (a_c + b_c))).cbrt();
        assert!((got[0] / a_fit - 1.0).abs() < 0.03, "{label}: a {:e} vs fit {a_fit:e}", got[0]);
        assert!((got[1] / got[0] / (1.0 / k_fit) - 1.0).abs() < 0.03 || kp > 0.97, "{label}: b/a");
        println!("{label}: b/a = {kp:.6}, a = {:.4} um, approach {:.4} nm", got[0] * 1e6, got[3] * 1e9);
    }
    // Equal crossed pins at 90 degrees are a ball of that radius on a flat.
    let pins = contact_json([0.004, INF], [0.004, INF], 90.0, f);
    let ball = contact_json([0.004, 0.004], [INF, INF], 0.0, f);
    for key in ["approach_m", "max_pressure_pa", "max_shear_stress_pa", "tangential_stiffness_major_n_per_m"] {
        let (p, b) = (pins[key].as_f64().unwrap(), ball[key].as_f64().unwrap());
        assert!((p / b - 1.0).abs() < 1e-12, "{key}: {p} vs {b}");
    }
}

#[test]
fn a_negative_or_zero_a_is_a_clear_error() {
    let base = ["contact", "--material1", "steel", "--material2", "steel", "--load", "1"];
    for (r1, r2) in [
        ("0.005,0.005", "-0.004,-0.004"), // a ball larger than its seat: A < 0
        ("0.005,0.005", "-0.0045,inf"),   // ... than its groove
        ("0.004,inf", "inf,inf"),         // a pin on a flat: A = 0, a line
        ("0.01,-0.03", "inf,inf"),        // a saddle on a flat: A < 0
    ] {
        let mut args = base.to_vec();
        args.extend(["--radii1", r1, "--radii2", r2]);
        let (ok, _, err) = kinrepro(&args);
        assert!(!ok && err.contains("not a point contact") && !err.contains("panicked"), "{r1} {r2}: {err}");
    }
    let mut args = base.to_vec();
    args.extend(["--radii1", "0.005", "--radii2", "inf,inf"]);
    let (ok, _, err) = kinrepro(&args);
    assert!(!ok && err.contains("two comma-separated"), "{err}");
}

#[test]
fn a_too_conformal_contact_is_warned_about() {
    // A 10 mm ball in a groove 0.4 % wider: the contact's semi-axis is a
    // sizeable part of the ball radius.
    let args = [
        "contact", "--shape", "sphere-arch", "--radius1", "0.005", "--radius2", "0.00502", "--material1",
        "steel", "--material2", "steel", "--load", "20",
    ];
    let (ok, out, err) = kinrepro(&args);
    assert!(ok && out.contains("sphere-arch"), "{err}");
    assert!(err.contains("too conformal for Hertz") && err.contains("half-spaces"), "{err}");
    // A 10 % wider groove at the same load is not.
    let mut wide = args;
    wide[6] = "0.0055";
    let (ok, _, err) = kinrepro(&wide);
    assert!(ok && !err.contains("conformal"), "{err}");
}

#[test]
fn the_named_shapes_are_cases_of_the_general_contact() {
    use kinrepro::contact::{ContactPair, ContactShape, HertzLaw};
    use kinrepro::material::{Material, effective_modulus};
    let steel = Material::builtin("steel").unwrap();
    let sic = Material::builtin("silicon-carbide").unwrap();
    let e_star = effective_modulus(&steel, &sic);
    let (r1, r2, f) = (0.005, 0.0062, 3.3);
    // The relative radii of each shape written out (docs/model.md's table),
    // through the elliptical law as it was used before the general geometry.
    let across = 1.0 / (1.0 / r1 + 1.0 / r2);
    let concave = 1.0 / (1.0 / r1 - 1.0 / r2);
    for (shape, [rx, ry]) in [
        (ContactShape::SpherePlane, [r1, r1]),
        (ContactShape::SphereSphere, [across, across]),
        (ContactShape::SphereSeat, [concave, concave]),
        (ContactShape::SphereCylinder, [across, r1]),
        (ContactShape::SphereArch, [r1, concave]),
        (ContactShape::CrossedCylinders, [r1, r2]),
    ] {
        let law = HertzLaw::elliptical(rx, ry, e_star);
        let pair = ContactPair::from_shape(shape, r1, Some(r2), steel.clone(), sic.clone()).unwrap();
        let e = pair.evaluate(f).unwrap();
        let close = |a: f64, b: f64| (a / b - 1.0).abs() < 1e-12;
        assert!(close(e.approach_m, law.approach(f)), "{shape:?}");
        assert!(close(e.max_pressure_pa, law.max_pressure(f)), "{shape:?}");
        for k in 0..2 {
            assert!(close(e.semi_axes_m[k], law.semi_axes(f)[k]), "{shape:?}");
            assert!(close(e.relative_radii_m[k], law.radii[k]), "{shape:?}");
        }
    }
}
