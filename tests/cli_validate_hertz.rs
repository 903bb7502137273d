//! `kinrepro validate-hertz`: the FE check of a scene's contact pairs, coarse
//! mesh, against the Hertz closed form (within 5 %), with the documented keys.

mod common;

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
        rows.iter()
            .find(|r| r["shape"] == shape)
            .map(|r| r["load_n"].as_f64().unwrap())
            .unwrap()
    };
    let (flat, balls) = (load("sphere-plane"), load("sphere-sphere"));
    assert!((flat / (20.0 / 3.0) - 1.0).abs() < 1e-3, "flat {flat}");
    assert!(
        balls > 0.0 && balls < flat,
        "flat {flat}, fixed balls {balls}"
    );
}
