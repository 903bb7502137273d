//! `kinrepro validate-hertz`: the FE check of a scene's contact pairs, coarse
//! mesh, against the Hertz closed form (within 5 %), with the documented keys.

use crate::common;

#[test]
fn coarse_validation_of_a_scene_reports_every_pair_within_five_percent() {
    let scene = common::scene("06_kelvin_steel.toml");
    let (ok, out, err) = common::kinrepro(&[
        "validate-hertz",
        scene.to_str().unwrap(),
        "--mesh",
        "coarse",
        "--json",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let rows = v.as_array().unwrap();
    // Kelvin steel/steel: balls on fixed balls (sphere-sphere) and the flat (sphere-plane).
    assert_eq!(rows.len(), 2);
    for r in rows {
        for key in [
            "shape",
            "radii_m",
            "materials",
            "load_n",
            "fe_approach_m",
            "hertz_approach_m",
            "approach_error_rel",
            "fe_semi_axes_m",
            "hertz_semi_axes_m",
            "element_size_m",
            "dofs",
            "seconds",
        ] {
            assert!(r.get(key).is_some(), "missing {key}");
        }
        let f = r["load_n"].as_f64().unwrap();
        // Independent Hertz (common::hertz_circle), steel/steel.
        let radius = match r["shape"].as_str().unwrap() {
            "sphere-plane" => 4e-3,
            "sphere-sphere" => 1.0 / (1.0 / 4e-3 + 1.0 / 3e-3),
            s => panic!("{s}"),
        };
        let (a, delta) = common::hertz_circle(f, radius, common::E_STAR_STEEL);
        assert!((r["hertz_approach_m"].as_f64().unwrap() / delta - 1.0).abs() < 1e-12);
        assert!((r["fe_approach_m"].as_f64().unwrap() / delta - 1.0).abs() < 0.05);
        for k in 0..2 {
            assert!((r["fe_semi_axes_m"][k].as_f64().unwrap() / a - 1.0).abs() < 0.05);
        }
        assert!(r["dofs"].as_u64().unwrap() > 1000);
    }
    // Load per pair: the largest contact force of that shape in the seating at
    // nominal friction. Statics of the preload at the centre of the ball
    // triangle: each ball carries 20/3 N vertically; the flat's normal is
    // vertical and its friction horizontal, so the flat takes all 20/3 N as
    // normal force (up to the small moments of the friction forces about the
    // ball centres), while the V and the trihedral seat share theirs over two
    // and three inclined contacts with friction: the flat carries the larger share.
    let load = |shape: &str| {
        rows.iter().find(|r| r["shape"] == shape).map(|r| r["load_n"].as_f64().unwrap()).unwrap()
    };
    let (flat, balls) = (load("sphere-plane"), load("sphere-sphere"));
    assert!((flat / (20.0 / 3.0) - 1.0).abs() < 1e-3, "flat {flat}");
    assert!(balls > 0.0 && balls < flat, "flat {flat}, fixed balls {balls}");
}

/// `--conformity` on the gothic-arch scene at one mild ratio (coarse mesh):
/// one study with one row, the groove radius set by the ratio, the exact
/// and quadratic gaps within 0.2 % of each other at a/r = 0.02 (the gap's
/// quartic excess is 3/4 (a/r)^2 = 3e-4 at the contact edge), no 2 %
/// crossing among the ratios, and the warning ratio where Hertz's a/R_x
/// (elliptical closed form via kinrepro's HertzLaw with R_x = r,
/// R_y = r R_g / (R_g - r) by hand) is 0.1.
#[test]
fn conformity_study_of_the_gothic_arch_scene() {
    let scene = common::scene("maxwell_gothic_arch_steel.toml");
    let (ok, out, err) = common::kinrepro(&[
        "validate-hertz",
        "--conformity",
        scene.to_str().unwrap(),
        "--mesh",
        "coarse",
        "--ratios",
        "1.5",
        "--json",
    ]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let st = &v.as_array().unwrap()[0];
    let rows = st["rows"].as_array().unwrap();
    assert_eq!(rows.len(), 1);
    let row = &rows[0];
    assert_eq!(row["groove_over_ball"].as_f64().unwrap(), 1.5);
    assert!((row["groove_radius_m"].as_f64().unwrap() / 7.5e-3 - 1.0).abs() < 1e-12);
    assert!(row["gap_effect_rel"][0].as_f64().unwrap().abs() < 2e-3);
    assert!(row["approach_error_rel"].as_f64().unwrap().abs() < 0.05);
    assert!(st["ratio_at_limit"].is_null());
    assert!((st["groove_radius_m"].as_f64().unwrap() / 5.5e-3 - 1.0).abs() < 1e-12);
    let (r, load) = (5e-3, st["load_n"].as_f64().unwrap());
    let w = st["warning_ratio"].as_f64().unwrap();
    let rg = w * r;
    let law = kinrepro::contact::HertzLaw::elliptical(r, r * rg / (rg - r), common::E_STAR_STEEL);
    let conformity = law.semi_axes(load)[0] / r;
    assert!((conformity / 0.1 - 1.0).abs() < 1e-6, "{conformity}");
}

#[test]
fn conformity_flags_are_checked() {
    let gothic = common::scene("maxwell_gothic_arch_steel.toml");
    let planes = common::scene("01_maxwell_vgroove_steel.toml");
    for (args, needle) in [
        (vec!["--ratios", "1.5", gothic.to_str().unwrap()], "--ratios goes with --conformity"),
        (vec!["--conformity", "--ratios", "0.9", gothic.to_str().unwrap()], "above 1"),
        (vec!["--conformity", "--ratios", "1.1,1.5", gothic.to_str().unwrap()], "descending"),
        (vec!["--conformity", planes.to_str().unwrap()], "no sphere-groove"),
    ] {
        let mut all = vec!["validate-hertz"];
        all.extend(args);
        let (ok, _, err) = common::kinrepro(&all);
        assert!(!ok && err.contains(needle), "{all:?}: {err}");
    }
}
