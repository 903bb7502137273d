//! The couplings beyond balls on planes, pins and balls: gothic-arch
//! grooves, canoe balls and crossed pins, each against an independent value
//! (Hertz closed forms and scaling laws, an equivalent coupling, the
//! scene's own expansion read back).

use crate::common::{kinrepro, load, scene};

use kinrepro::analysis::stiffness::CouplingStiffness;
use kinrepro::assembly::Coupling;
use kinrepro::contact::{ContactPair, ContactShape};
use kinrepro::material::Material;
use kinrepro::scene::Scene;
use kinrepro::solve::quasistatic::seat;
use kinrepro::solve::{Load, SolverOptions};

/// Scene 01 with its `[coupling]` lines edited: `(old line, new lines)`.
fn scene01_with(edits: &[(&str, &str)]) -> (Scene, Coupling) {
    let mut text = std::fs::read_to_string(scene("01_maxwell_vgroove_steel.toml")).unwrap();
    for (old, new) in edits {
        let line = text.lines().find(|l| l.starts_with(old)).unwrap().to_string();
        text = text.replace(&line, new);
    }
    let scene = Scene::parse(&text, "edited 01").unwrap();
    let c = Coupling::new(&scene).unwrap();
    (scene, c)
}

/// The principal stiffnesses (three translational, three rotational) of
/// the coupling seated at nominal friction, at the centre.
fn principal((scene, c): &(Scene, Coupling)) -> [f64; 6] {
    let mu = Load::nominal(scene);
    let s = seat(c, &mu, &SolverOptions::default()).unwrap();
    let k = CouplingStiffness::new(c, &s, &mu).unwrap();
    let p = k.principal_at(&s.pose().translation).unwrap();
    let t = p.translational.map(|(k, _)| k);
    let r = p.rotational.map(|(k, _)| k);
    [t[0], t[1], t[2], r[0], r[1], r[2]]
}

#[test]
fn a_ball_in_a_gothic_arch_has_the_closed_form_radii() {
    // A ball of radius r in a concave cylinder of radius R_g: R_across =
    // r R_g / (R_g - r) and R_along = r (Johnson eq. 4.2 with one body's
    // curvature -1/R_g across and 0 along).
    let steel = Material::builtin("steel").unwrap();
    let (r, rg) = (0.005, 0.0055);
    let pair =
        ContactPair::from_shape(ContactShape::SphereGroove, r, Some(rg), steel.clone(), steel)
            .unwrap();
    let radii = pair.relative_radii().unwrap();
    assert!((radii[0] / r - 1.0).abs() < 1e-12, "{radii:?}");
    assert!((radii[1] / (r * rg / (rg - r)) - 1.0).abs() < 1e-12, "{radii:?}");
    // In scene 08 every contact is that pair, the long axis across the groove.
    let (_, c) = load("maxwell_gothic_arch_steel.toml");
    for k in &c.contacts {
        assert_eq!(k.shape, ContactShape::SphereGroove);
        let groove = match k.surface {
            kinrepro::scene::SurfaceGeometry::ConcaveCylinder { direction, .. } => direction,
            _ => unreachable!("scene 08 has gothic-arch flanks only"),
        };
        assert!(k.major_axis.dot(&groove).abs() < 1e-12);
        assert!(k.major_axis.norm() > 0.99);
    }
}

#[test]
fn a_canoe_coupling_is_stiffer_by_the_hertz_factor() {
    // At equal contact loads every Hertz and Mindlin stiffness grows as
    // a ~ (F R)^(1/3): the canoe patch of 0.25 m against the 5 mm ball on
    // the same footprint (same contact points and normals, so the same
    // forces) stiffens every principal direction by (0.25 / 0.005)^(1/3).
    let ball = principal(&load("01_maxwell_vgroove_steel.toml"));
    let canoe = principal(&load("maxwell_canoe_steel.toml"));
    let factor = (0.25f64 / 0.005).cbrt();
    for (k, (b, c)) in ball.iter().zip(&canoe).enumerate() {
        assert!(
            (c / b / factor - 1.0).abs() < 1e-6,
            "principal stiffness {k}: canoe {c:.6e}, ball {b:.6e}, ratio {} against {factor}",
            c / b
        );
    }
}

#[test]
fn crossed_equal_pins_at_right_angles_seat_like_a_ball_on_planes() {
    // Two pins of radius R crossed at 90 degrees are, for Hertz, a ball of
    // radius R on a flat (relative radii R and R); with the moving pins
    // through the ball centres they touch where scene 01's balls touch its
    // planes, along the same normals. The two couplings then differ only in
    // second-order geometry, of the order of the contact's motion over its
    // radius (um against mm).
    let (pins_scene, pins) = scene01_with(&[(
        "groove = ",
        "groove = \"cylinders\"\ngroove_element_diameter = 0.010\nball_shape = \"pins\"",
    )]);
    let (balls_scene, balls) = load("01_maxwell_vgroove_steel.toml");
    for k in &pins.contacts {
        assert_eq!(k.shape, ContactShape::CrossedCylinders);
        let radii = k.law.hertz.radii;
        assert!(radii.iter().all(|r| (r / 0.005 - 1.0).abs() < 1e-12), "{radii:?}");
    }
    for mu in [[0.45, 0.55, 0.5, 0.47, 0.53, 0.5], [0.55, 0.45, 0.52, 0.5, 0.46, 0.54]] {
        let a = seat(&pins, &Load::nominal(&pins_scene).with_mu(&mu), &SolverOptions::default())
            .unwrap();
        let b = seat(&balls, &Load::nominal(&balls_scene).with_mu(&mu), &SolverOptions::default())
            .unwrap();
        let (da, db) = (a.pose().translation, b.pose().translation);
        assert!(
            (da - db).norm() <= 1e-4 * db.norm(),
            "crossed pins {da} against balls on planes {db}"
        );
    }
}

#[test]
fn expanded_new_couplings_load_back_to_the_same_results() {
    for name in [
        "maxwell_gothic_arch_steel.toml",
        "maxwell_canoe_steel.toml",
        "maxwell_crossed_pins_steel.toml",
    ] {
        let path = scene(name);
        let (ok, explicit, err) = kinrepro(&["expand", path.to_str().unwrap()]);
        assert!(ok, "{err}");
        let dir = tempfile::tempdir().unwrap();
        let written = dir.path().join("explicit.toml");
        std::fs::write(&written, &explicit).unwrap();
        let sigma = |p: &std::path::Path| {
            let (ok, out, err) = kinrepro(&[
                "study",
                p.to_str().unwrap(),
                "--sampler",
                "mc",
                "--samples",
                "30",
                "--format",
                "json",
            ]);
            assert!(ok, "{err}");
            let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
            doc["variants"][0]["points"][0]["sigma"].clone()
        };
        // `expand` writes 15 significant digits, so the reloaded geometry
        // differs from the expanded one by rounding (5e-16 of 0.04 m
        // coordinates). A seated pose resolves only a few eps of the
        // coupling's size either way, so the two scatters agree to that in
        // absolute terms: 4 eps 0.04 m (3.6e-8 nm) and 4 eps rad
        // (8.9e-7 nrad); relative to a 1 nm sigma that is 4e-8, not 1e-12.
        let (a, b) = (sigma(&path), sigma(&written));
        let eps = 4.0 * f64::EPSILON * 1e9;
        for (key, tol) in [
            ("x_nm", eps * 0.04),
            ("y_nm", eps * 0.04),
            ("z_nm", eps * 0.04),
            ("phi_x_nrad", eps),
            ("phi_y_nrad", eps),
            ("phi_z_nrad", eps),
        ] {
            let (x, y) = (a[key].as_f64().unwrap(), b[key].as_f64().unwrap());
            assert!(x > 0.0 && (x - y).abs() <= tol, "{name} {key}: {x} vs {y}");
        }
    }
}

#[test]
fn couplings_that_cannot_be_built_say_why() {
    let text = std::fs::read_to_string(scene("maxwell_gothic_arch_steel.toml")).unwrap();
    let cases = [
        (
            text.replace("groove_radius = 0.0055", "groove_radius = 0.0045"),
            "must exceed the ball radius",
        ),
        (text.replace("groove_radius = 0.0055", ""), "needs the flank radius `groove_radius`"),
        (
            text.replace(
                "groove = \"gothic-arch\"",
                "groove = \"gothic-arch\"\nball_shape = \"canoe\"\ncanoe_radius = 0.25",
            ),
            "must be smaller than groove_radius",
        ),
        (
            text.replace("groove = \"gothic-arch\"", "groove = \"planes\"\nball_shape = \"pins\""),
            "crossed pins need a fixed pin at every contact",
        ),
        (
            text.replace(
                "groove = \"gothic-arch\"",
                "groove = \"gothic-arch\"\nball_shape = \"canoe\"",
            ),
            "needs the patch radius `canoe_radius`",
        ),
    ];
    for (bad, reason) in cases {
        let err = Scene::parse(&bad, "bad.toml").unwrap_err().to_string();
        assert!(err.contains(reason), "{err}");
        assert!(err.contains("coupling."), "names the field: {err}");
    }
}

#[test]
fn the_new_bundled_scenes_check_study_and_validate() {
    for (name, shape, radii) in [
        ("maxwell_gothic_arch_steel.toml", "sphere-groove", [0.005, -0.0055]),
        ("maxwell_canoe_steel.toml", "sphere-plane", [0.25, f64::NAN]),
        ("maxwell_crossed_pins_steel.toml", "crossed-cylinders", [0.005, 0.002]),
    ] {
        let path = scene(name);
        let path = path.to_str().unwrap();
        let (ok, _, err) = kinrepro(&["check", path]);
        assert!(ok, "{name}: {err}");
        let (ok, out, err) = kinrepro(&["study", path, "--format", "json"]);
        assert!(ok, "{name}: {err}");
        let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
        let sigma = &doc["variants"][0]["points"][0]["sigma"];
        for key in ["x_nm", "y_nm", "z_nm", "phi_x_nrad", "phi_y_nrad", "phi_z_nrad"] {
            let s = sigma[key].as_f64().unwrap();
            assert!(s.is_finite() && s > 0.0, "{name} {key}: {s}");
        }
        // The FE (a second solver of the same contact problem) against the
        // Hertz law of the pair, on the coarse mesh (within 5 %; the default
        // mesh's 2 % is measured by `kinrepro validate-hertz SCENE`).
        let (ok, out, err) = kinrepro(&["validate-hertz", path, "--mesh", "coarse", "--json"]);
        assert!(ok, "{name}: {err}");
        let rows: serde_json::Value = serde_json::from_str(&out).unwrap();
        let rows = rows.as_array().unwrap();
        assert_eq!(rows.len(), 1, "{name}: one distinct pair");
        let r = &rows[0];
        assert_eq!(r["shape"], shape);
        assert_eq!(r["radii_m"][0].as_f64().unwrap(), radii[0]);
        if radii[1].is_finite() {
            assert_eq!(r["radii_m"][1].as_f64().unwrap(), radii[1]);
        }
        assert!(r["approach_error_rel"].as_f64().unwrap().abs() < 0.05, "{r}");
        for k in 0..2 {
            assert!(r["semi_axes_error_rel"][k].as_f64().unwrap().abs() < 0.05, "{r}");
        }
    }
}

#[test]
fn every_shape_has_one_name_in_text_and_json() {
    for shape in ContactShape::ALL {
        let json = serde_json::to_string(&shape).unwrap();
        assert_eq!(json, format!("\"{}\"", shape.name()));
        assert_eq!(shape.name().parse::<ContactShape>().unwrap(), shape);
    }
}
