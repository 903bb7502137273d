//! The general Hertz contact (`contact --radii1 --radii2 --angle-deg`)
//! against an independent evaluation written here from the literature:
//!
//! - the relative curvatures A <= B as half the eigenvalues of the sum of
//!   the two bodies' curvature tensors (the second fundamental forms,
//!   body 2's turned by theta), not Johnson's closed form eq. 4.2;
//! - the complete elliptic integrals K(m), E(m) by the trapezoidal rule
//!   on their defining integrals, not the AGM;
//! - the ellipticity by bisection on m = 1 - (b/a)^2 of Johnson's
//!   B/A = ((a/b)^2 E - K)/(K - E) (1985, eqs. 3.59-3.60, 4.39);
//! - a from the Hamrock-Brewe (1983) form a^3 = 3 k^2 E F / (2 pi E* (A + B)),
//!   k = a/b, with the exact integrals; b = a/k; approach
//!   delta = 3 F K / (2 pi a E*); p0 = 3 F / (2 pi a b) (Johnson §4.3);
//! - and, loosely, Hamrock & Brewe's curve fits of k and E (a within
//!   3 %, a/b within 4 %, for B/A up to 100).

use std::f64::consts::PI;

use crate::common;
use crate::common::{E_STAR_STEEL, kinrepro};

const INF: f64 = f64::INFINITY;

/// The trapezoidal rule for f over [0, pi/2] with n panels: f(phi) =
/// g(sin^2 phi) is smooth, even and pi-periodic, so this is a quarter of
/// the periodic trapezoidal rule, which converges exponentially.
fn trapezoid(f: &dyn Fn(f64) -> f64, n: usize) -> f64 {
    let h = 0.5 * PI / n as f64;
    let inner: f64 = (1..n).map(|i| f(i as f64 * h)).sum();
    h * (0.5 * (f(0.0) + f(0.5 * PI)) + inner)
}

/// K(m), E(m) by quadrature of their integrals over [0, pi/2].
fn elliptic(m: f64) -> (f64, f64) {
    let k = trapezoid(&|p: f64| 1.0 / (1.0 - m * p.sin().powi(2)).sqrt(), 4000);
    let e = trapezoid(&|p: f64| (1.0 - m * p.sin().powi(2)).sqrt(), 4000);
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
        for _ in 0..80 {
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
        "contact",
        "--radii1",
        &r1s,
        "--radii2",
        &r2s,
        "--angle-deg",
        &degs,
        "--material1",
        "steel",
        "--material2",
        "steel",
        "--load",
        &fs,
        "--json",
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
        for (name, g, w) in
            ["a", "b", "p0", "approach"].into_iter().zip(got).zip(want).map(|((n, g), w)| (n, g, w))
        {
            assert!((g / w - 1.0).abs() < 1e-6, "{label}: {name} {g:e} vs {w:e}");
        }
        // Hamrock & Brewe's fits (1983), Ry/Rx = B/A: k = 1.0339 (B/A)^0.636,
        // E = 1.0003 + 0.5968 A/B: a loose second check of the ellipse, in
        // the range of their fits (B/A up to 100; k within 4 %).
        let (a_c, b_c) = relative_curvatures(r1, r2, deg.to_radians());
        if b_c / a_c <= 100.0 {
            let k_fit = 1.0339 * (b_c / a_c).powf(0.636);
            let e_fit = 1.0003 + 0.5968 * a_c / b_c;
            let a_fit =
                (3.0 * k_fit * k_fit * e_fit * f / (2.0 * PI * E_STAR_STEEL * (a_c + b_c))).cbrt();
            assert!((got[0] / a_fit - 1.0).abs() < 0.03, "{label}: a {:e} vs {a_fit:e}", got[0]);
            assert!((got[0] / got[1] / k_fit - 1.0).abs() < 0.04, "{label}: a/b vs {k_fit}");
        }
        println!(
            "{label}: b/a = {kp:.6}, a = {:.4} um, approach {:.4} nm",
            got[0] * 1e6,
            got[3] * 1e9
        );
    }
    // Equal crossed pins at 90 degrees are a ball of that radius on a flat.
    let pins = contact_json([0.004, INF], [0.004, INF], 90.0, f);
    let ball = contact_json([0.004, 0.004], [INF, INF], 0.0, f);
    for key in [
        "approach_m",
        "max_pressure_pa",
        "max_shear_stress_pa",
        "tangential_stiffness_major_n_per_m",
    ] {
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
        assert!(
            !ok && err.contains("not a point contact") && !err.contains("panicked"),
            "{r1} {r2}: {err}"
        );
    }
    let mut args = base.to_vec();
    args.extend(["--radii1", "0.005", "--radii2", "inf,inf"]);
    let (ok, _, err) = kinrepro(&args);
    assert!(!ok && err.contains("two comma-separated"), "{err}");
}

#[test]
fn a_too_conformal_contact_is_warned_about() {
    // A 10 mm ball in a groove 0.4 % wider: the contact's major semi-axis
    // (across the groove) is a sizeable part of the ball radius.
    let args = |groove: &'static str| {
        [
            "contact",
            "--radii1",
            "0.005,0.005",
            "--radii2",
            groove,
            "--material1",
            "steel",
            "--material2",
            "steel",
            "--load",
            "20",
        ]
    };
    let (ok, out, err) = kinrepro(&args("-0.00502,inf"));
    assert!(ok && out.contains("general"), "{err}");
    assert!(err.contains("too conformal for Hertz") && err.contains("half-spaces"), "{err}");
    // A 10 % wider groove at the same load is not.
    let (ok, _, err) = kinrepro(&args("-0.0055,inf"));
    assert!(ok && !err.contains("conformal"), "{err}");
}

#[test]
fn a_conformal_ball_in_a_concave_seat() {
    // A 10 mm ball in a spherical seat of radius Rs: a circle of relative
    // radius R = r Rs / (Rs - r), a = (3 F R / 4 E*)^(1/3), delta = a^2 / R
    // (Johnson §4.2), here R = 20 r: the seat carries the load on a contact
    // ~2.7 times wider than a flat's.
    let (r, rs, f) = (0.005, 0.00525, 20.0);
    let v = contact_json([r, r], [-rs, -rs], 0.0, f);
    let rel = r * rs / (rs - r);
    let (a, delta) = common::hertz_circle(f, rel, E_STAR_STEEL);
    for (key, want) in [("approach_m", delta), ("max_pressure_pa", 3.0 * f / (2.0 * PI * a * a))] {
        let got = v[key].as_f64().unwrap();
        assert!((got / want - 1.0).abs() < 1e-12, "{key}: {got} vs {want}");
    }
    for k in 0..2 {
        assert!((v["semi_axes_m"][k].as_f64().unwrap() / a - 1.0).abs() < 1e-12);
    }
    // a/r = 4.5 %: below the conformity limit, no warning.
    let (ok, _, err) = kinrepro(&[
        "contact",
        "--radii1",
        "0.005,0.005",
        "--radii2",
        "-0.00525,-0.00525",
        "--material1",
        "steel",
        "--material2",
        "steel",
        "--load",
        "20",
    ]);
    assert!(ok && !err.contains("conformal"), "{err}");
}

#[test]
fn the_general_contact_is_symmetric_in_angle_and_bodies() {
    let (f, keys) = (
        7.0,
        [
            "approach_m",
            "max_pressure_pa",
            "tangential_stiffness_major_n_per_m",
            "tangential_stiffness_minor_n_per_m",
            "max_shear_stress_pa",
            "max_shear_depth_m",
        ],
    );
    let same = |x: &serde_json::Value, y: &serde_json::Value, what: &str| {
        for key in keys {
            let (p, q) = (x[key].as_f64().unwrap(), y[key].as_f64().unwrap());
            assert!((p / q - 1.0).abs() < 1e-12, "{what} {key}: {p} vs {q}");
        }
        for k in 0..2 {
            let (p, q) =
                (x["semi_axes_m"][k].as_f64().unwrap(), y["semi_axes_m"][k].as_f64().unwrap());
            assert!((p / q - 1.0).abs() < 1e-12, "{what} semi-axis {k}");
        }
    };
    for (label, r1, r2, deg) in CASES {
        let v = contact_json(r1, r2, deg, f);
        // theta and theta + 180 deg describe the same pair.
        same(&v, &contact_json(r1, r2, deg + 180.0, f), label);
        // Swapping the bodies (body 2 at -theta from body 1 is body 1 at
        // +theta from body 2) changes nothing for equal materials.
        same(&v, &contact_json(r2, r1, deg, f), label);
        // Nor does swapping the order of one body's principal radii with
        // theta turned by 90 degrees.
        same(&v, &contact_json([r1[1], r1[0]], r2, deg + 90.0, f), label);
    }
}

#[test]
fn a_ball_on_a_large_ball_tends_to_a_ball_on_a_plane() {
    // R2 -> inf: the relative radius 1/(1/r + 1/R2) -> r, the approach
    // converges to the flat's at the rate r/R2 (delta ~ R^(-1/3)).
    let plane = contact_json([0.005, 0.005], [INF, INF], 0.0, 5.0)["approach_m"].as_f64().unwrap();
    let mut last = f64::INFINITY;
    for r2 in [0.05, 5.0, 500.0, 5e4] {
        let got = contact_json([0.005, 0.005], [r2, r2], 0.0, 5.0)["approach_m"].as_f64().unwrap();
        let err = (got / plane - 1.0).abs();
        assert!(err < last && err < 0.5 * 0.005 / r2, "R2 = {r2}: {err}");
        last = err;
    }
}

/// The JSON of `contact --shape` and of its radii form.
fn shape_and_radii(
    shape: &str,
    radius2: Option<&str>,
    r2: &str,
) -> (serde_json::Value, serde_json::Value) {
    let base =
        ["--material1", "steel", "--material2", "silicon-carbide", "--load", "3.3", "--json"];
    let mut a = vec!["contact", "--shape", shape, "--radius1", "0.005"];
    if let Some(r) = radius2 {
        a.extend(["--radius2", r]);
    }
    a.extend(base);
    let mut b = vec!["contact", "--radii1", "0.005,0.005", "--radii2", r2];
    b.extend(base);
    let ((ok1, o1, e1), (ok2, o2, e2)) = (kinrepro(&a), kinrepro(&b));
    assert!(ok1 && ok2, "{shape}: {e1} {e2}");
    (serde_json::from_str(&o1).unwrap(), serde_json::from_str(&o2).unwrap())
}

#[test]
fn each_shape_is_its_radii_form() {
    for (shape, radius2, radii2) in [
        ("sphere-plane", None, "inf,inf"),
        ("sphere-sphere", Some("0.0062"), "0.0062,0.0062"),
        ("sphere-seat", Some("0.0062"), "-0.0062,-0.0062"),
        ("sphere-cylinder", Some("0.0062"), "0.0062,inf"),
    ] {
        let (by_shape, by_radii) = shape_and_radii(shape, radius2, radii2);
        assert_eq!(by_shape["shape"], shape);
        let serde_json::Value::Object(fields) = &by_shape else { panic!() };
        for (key, x) in fields {
            let (x, y) = (x.to_string(), by_radii[key].to_string());
            if key == "shape" {
                continue;
            }
            let nums = |s: &str| -> Vec<f64> {
                s.trim_matches(['[', ']']).split(',').map(|t| t.parse().unwrap()).collect()
            };
            for (p, q) in nums(&x).into_iter().zip(nums(&y)) {
                assert!((p / q - 1.0).abs() < 1e-12 || p == q, "{shape} {key}: {p} vs {q}");
            }
        }
    }
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
    ] {
        let law = HertzLaw::elliptical(rx, ry, e_star);
        let pair =
            ContactPair::from_shape(shape, r1, Some(r2), steel.clone(), sic.clone()).unwrap();
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

#[test]
fn check_warns_about_a_contact_too_large_for_its_radii() {
    // Scene 02 on 20 um pins: each contact's semi-axis along the pin is
    // several times the relative radius across it (~10 um), so `check`
    // warns per contact; on the 4 mm pins it does not.
    let text = std::fs::read_to_string(common::scene("02_maxwell_pins_steel.toml")).unwrap();
    let thin = text.replace("groove_element_diameter = 0.004", "groove_element_diameter = 0.00002");
    assert_ne!(text, thin);
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("thin_pins.toml");
    std::fs::write(&path, thin).unwrap();
    let (_, out, err) = kinrepro(&["check", path.to_str().unwrap()]);
    assert!(out.contains("WARNING: contact 6: too conformal for Hertz"), "{out}{err}");
    let scene = common::scene("02_maxwell_pins_steel.toml");
    let (ok, out, _) = kinrepro(&["check", scene.to_str().unwrap()]);
    assert!(ok && !out.contains("conformal"), "{out}");
}
