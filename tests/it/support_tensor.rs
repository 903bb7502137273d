//! An anisotropic tangential support compliance (`support_compliance =
//! { along, across }`): the series tensor against springs in series
//! (compliances add) and its closed forms, its derivative against finite
//! differences, a contact's history against Mindlin plus the support, and
//! the scene keys (expansion, explicit axes, errors).

use crate::common;
use kinrepro::contact::{PrincipalStiffness, TangentialSupport};
use kinrepro::scene::Scene;
use nalgebra::{Matrix3, Vector3};

fn rel(a: &Matrix3<f64>, b: &Matrix3<f64>) -> f64 {
    (a - b).norm() / b.norm()
}

/// A tilted contact normal and a major axis that is not in its plane.
fn frame() -> (Vector3<f64>, Vector3<f64>) {
    (Vector3::new(0.3, -0.5, 0.8).normalize(), Vector3::new(1.0, 0.2, 0.1))
}

/// Along = across = c through the anisotropic path is the scalar series
/// k' = k / (1 + k c) per principal axis of Mindlin's, and its derivative
/// factor k / (1 + k c)^2 (dK/dF_n = dlog K K_m^-1 K).
#[test]
fn equal_compliances_along_and_across_are_the_scalar_series() {
    let (n, major) = frame();
    for k in [[3e7, 3e7], [5e7, 2e7]] {
        for c in [1e-8, 3e-7] {
            for axis in [Vector3::x(), Vector3::new(-0.4, 0.9, 0.3)] {
                let s = TangentialSupport { along: c, across: c, axis };
                let series = s.series(k, &n, &major);
                let expect = PrincipalStiffness::new(k.map(|k| k / (1.0 + k * c)), &n, &major);
                assert!(rel(&series.tensor, &expect.tensor(&n)) < 1e-12, "{k:?} {c}");
                let d = k.map(|k| k / ((1.0 + k * c) * (1.0 + k * c)));
                let expect_d = PrincipalStiffness::new(d, &n, &major).tensor(&n);
                assert!(rel(&series.derivative, &expect_d) < 1e-12, "{k:?} {c}");
            }
        }
    }
}

/// Springs in series: the displacement under a tangential force Q is
/// Mindlin's K_m^-1 Q plus the support's C Q, with C = c_along u u^T +
/// c_across v v^T; the series tensor maps it back to Q.
#[test]
fn the_series_tensor_inverts_the_sum_of_compliances() {
    let (n, major) = frame();
    let k = [6e7, 2.5e7];
    let s = TangentialSupport { along: 2e-8, across: 4e-7, axis: Vector3::new(0.2, 1.0, -0.3) };
    let series = s.series(k, &n, &major);
    let e1 = (major - n * n.dot(&major)).normalize();
    let e2 = n.cross(&e1);
    let u = (s.axis - n * n.dot(&s.axis)).normalize();
    let v = n.cross(&u);
    let compliance = e1 * e1.transpose() / k[0]
        + e2 * e2.transpose() / k[1]
        + u * u.transpose() * s.along
        + v * v.transpose() * s.across;
    for q in [e1, e2, e1 * 0.3 - e2 * 1.7, u, v] {
        let back = series.tensor * (compliance * q);
        assert!((back - q).norm() < 1e-12 * q.norm(), "{q:?}: {back:?}");
    }
    // The tensor lies in the tangent plane and is symmetric.
    assert!((series.tensor * n).norm() < 1e-9 * series.tensor.norm());
    assert!(rel(&series.tensor.transpose(), &series.tensor) < 1e-15);
}

/// A circular contact (k1 = k2 = k) behind a support compliant across an
/// axis: the principal stiffnesses are k / (1 + k c_along) along the axis
/// and k / (1 + k c_across) across it.
#[test]
fn a_circle_on_an_anisotropic_support_has_the_supports_axes() {
    let n = Vector3::z();
    let k = 4e7;
    let s = TangentialSupport { along: 1e-8, across: 5e-7, axis: Vector3::new(1.0, 1.0, 0.7) };
    let p = s.series([k, k], &n, &Vector3::zeros()).principal;
    let stiff = k / (1.0 + k * s.along);
    let soft = k / (1.0 + k * s.across);
    assert!((p.k[0] / stiff - 1.0).abs() < 1e-12 && (p.k[1] / soft - 1.0).abs() < 1e-12);
    let axes = p.axes.expect("an anisotropic support orients a circle");
    let u = Vector3::new(1.0, 1.0, 0.0).normalize();
    assert!((axes[0].dot(&u).abs() - 1.0).abs() < 1e-12, "{:?}", axes[0]);
}

/// dK/dF_n = dlog K K_m^-1 K: the factor of dlog against a central
/// difference of the tensor in ln a (K_m scales with a).
#[test]
fn the_derivative_factor_is_the_tensors_slope_in_ln_a() {
    let (n, major) = frame();
    let k = [6e7, 2.5e7];
    let s = TangentialSupport { along: 1e-7, across: 3e-8, axis: Vector3::new(0.5, -1.0, 0.2) };
    let h = 1e-5_f64;
    let at = |f: f64| s.series(k.map(|k| k * f), &n, &major).tensor;
    let slope = (at(h.exp()) - at((-h).exp())) / (2.0 * h);
    let d = s.series(k, &n, &major).derivative;
    assert!(rel(&d, &slope) < 1e-8, "{d} vs {slope}");
}

/// A steel ball on a steel plane behind a support compliant 2e-7 m/N along
/// x and 5e-8 m/N along y: under proportional loading below slip (Q =
/// (0.12, 0.16) P, P to 10 N in 40 steps) each displacement component is
/// Mindlin's 1.5 Q_i / (8 G* a) plus the support's c_i Q_i (Johnson 1985
/// sec. 7.3, springs in series).
#[test]
fn a_history_on_an_anisotropic_support_adds_c_along_and_c_across() {
    let tmp = tempfile::tempdir().unwrap();
    let rows: String = (1..=40)
        .map(|k| {
            let p = 10.0 * k as f64 / 40.0;
            format!("{p},{},{}\n", 0.12 * p, 0.16 * p)
        })
        .collect();
    let file = tmp.path().join("prop.csv");
    std::fs::write(&file, format!("P_N,Qx_N,Qy_N\n{rows}")).unwrap();
    let file = file.display().to_string();
    let (e, nu) = (210e9_f64, 0.3_f64);
    let g_star = e / (2.0 * (1.0 + nu)) / (2.0 * (2.0 - nu));
    let a = (3.0 * 10.0 * 5e-3 / (4.0 * e / (2.0 * (1.0 - nu * nu)))).cbrt();
    let (c_x, c_y) = (2e-7, 5e-8);
    let support = ["--tangential-compliance", "2e-7", "--tangential-compliance-across", "5e-8"];
    let history = ["--history", file.as_str()];
    let args = [&crate::cli_contact::STEEL_BALL_ON_PLANE[..], &history[..], &support[..]].concat();
    let (ok, out, err) = common::kinrepro(&args);
    assert!(ok, "{err}");
    assert!(out.contains("2e-7 m/N along x, 5e-8 m/N along y"), "{out}");
    let last: Vec<&str> = out.lines().last().unwrap().split(',').collect();
    assert_eq!(last[6], "stick");
    for (q, c, s) in [(1.2, c_x, last[4]), (1.6, c_y, last[5])] {
        let s: f64 = s.parse().unwrap();
        let expect = 1.5 * q / (8.0 * g_star * a) + c * q;
        assert!((s / expect - 1.0).abs() < 1e-9, "{s} vs {expect}");
    }
}

fn scene01_with_support(value: &str) -> String {
    std::fs::read_to_string(common::scene("01_maxwell_vgroove_steel.toml")).unwrap().replace(
        "groove_material = \"steel\"",
        &format!("groove_material = \"steel\"\nsupport_compliance = {value}"),
    )
}

fn points(text: &str) -> serde_json::Value {
    let tmp = tempfile::tempdir().unwrap();
    let file = tmp.path().join("s.toml");
    std::fs::write(&file, text).unwrap();
    let file = file.display().to_string();
    let args = ["study", &file, "--samples", "20", "--sampler", "mc", "--format", "json"];
    let (ok, out, err) = common::kinrepro(&args);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    v["variants"][0]["points"].clone()
}

/// Equal `along` and `across` are `tangential`; the [coupling] form puts
/// each groove's axis on its surfaces, and `expand` writes it.
#[test]
fn along_and_across_in_the_coupling_form_expand_to_groove_axes() {
    let same = points(&scene01_with_support("{ along = 3e-7, across = 3e-7 }"));
    assert_eq!(same, points(&scene01_with_support("{ tangential = 3e-7 }")));
    let text = scene01_with_support("{ normal = 1e-9, along = 4e-8, across = 6e-7 }");
    let scene = Scene::parse(&text, "s.toml").unwrap();
    for s in &scene.surfaces {
        let t = &s.tangential_support;
        assert_eq!((t.along, t.across), (4e-8, 6e-7));
        // Maxwell's grooves are radial: the axis is the ball's e_r.
        let c = scene.balls[s.ball].centre;
        let radial = Vector3::new(c.x, c.y, 0.0).normalize();
        assert!((t.axis - radial).norm() < 1e-15, "{:?} vs {radial:?}", t.axis);
    }
    let expanded = Scene::expand_text(&text, "s.toml").unwrap();
    assert_eq!(expanded.matches("axis = [").count(), 6, "{expanded}");
    let back = Scene::parse(&expanded, "e.toml").unwrap();
    let key = |s: &Scene| -> Vec<_> { s.surfaces.iter().map(|x| x.tangential_support).collect() };
    common::assert_close_debug(&key(&back), &key(&scene), "expanded supports");
}

#[test]
fn bad_anisotropic_supports_are_refused_at_their_field() {
    for (value, field, says) in [
        ("{ tangential = 1e-8, along = 2e-8 }", "support_compliance.tangential", "not both"),
        ("{ along = 1e-8, axis = [1, 0, 0] }", "support_compliance.axis", "explicit"),
        ("{ across = -1e-8 }", "support_compliance.across", ">= 0"),
    ] {
        let err = Scene::parse(&scene01_with_support(value), "bad.toml").unwrap_err().to_string();
        assert!(err.contains(field) && err.contains(says), "{value}: {err}");
    }
    // An explicit plane has no direction of its own: it needs `axis`.
    let explicit = |support: &str| {
        format!(
            "[[balls]]\ncentre = [0.0, 0.0, 0.0]\nradius = 0.005\nmaterial = \"steel\"\n\n\
             [[surfaces]]\ntype = \"plane\"\nball = 1\nmaterial = \"steel\"\n\
             point = [0.0, 0.0, -0.005]\nnormal = [0.0, 0.0, 1.0]\nsupport_compliance = {support}\n\n\
             [preload]\nforce = 10.0\n\n[friction]\nmu_static = 0.5\nspread = 0.05\n"
        )
    };
    let err = Scene::parse(&explicit("{ along = 1e-8 }"), "e.toml").unwrap_err().to_string();
    assert!(err.contains("surfaces[1].support_compliance.axis"), "{err}");
    for (axis, says) in [("[0, 0, 0]", "not all zero"), ("[1, 2]", "three numbers")] {
        let text = explicit(&format!("{{ along = 1e-8, axis = {axis} }}"));
        let err = Scene::parse(&text, "e.toml").unwrap_err().to_string();
        assert!(err.contains(says), "{axis}: {err}");
    }
    // An axis along the contact normal has no direction in its plane.
    let text = explicit("{ along = 1e-8, axis = [0, 0.01, 1] }");
    let scene = Scene::parse(&text, "e.toml").unwrap();
    let err = kinrepro::assembly::Coupling::new(&scene).unwrap_err().to_string();
    assert!(err.contains("deg from the contact normal"), "{err}");
}
