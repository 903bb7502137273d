//! `kinrepro validate-hertz`: the FE check of a scene's contact pairs, coarse
//! mesh, against the Hertz closed form (within 5 %), with the documented keys.

use std::path::Path;
use std::process::Command;

#[test]
fn coarse_validation_of_a_scene_reports_every_pair_within_five_percent() {
    let scene = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/06_kelvin_steel.toml");
    let out = Command::new(env!("CARGO_BIN_EXE_kinrepro"))
        .args([
            "validate-hertz",
            scene.to_str().unwrap(),
            "--mesh",
            "coarse",
            "--json",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
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
        // Independent Hertz: a = (3 F R / 4 E*)^(1/3), delta = a^2 / R, steel/steel E* = 210 GPa / (2 * 0.91).
        let e_star = 210e9 / (2.0 * 0.91);
        let radius = match r["shape"].as_str().unwrap() {
            "sphere-plane" => 4e-3,
            "sphere-sphere" => 1.0 / (1.0 / 4e-3 + 1.0 / 3e-3),
            s => panic!("{s}"),
        };
        let a: f64 = (3.0 * f * radius / (4.0 * e_star)).cbrt();
        let delta = a * a / radius;
        assert!((r["hertz_approach_m"].as_f64().unwrap() / delta - 1.0).abs() < 1e-12);
        assert!((r["fe_approach_m"].as_f64().unwrap() / delta - 1.0).abs() < 0.05);
        for k in 0..2 {
            assert!((r["fe_semi_axes_m"][k].as_f64().unwrap() / a - 1.0).abs() < 0.05);
        }
        assert!(r["dofs"].as_u64().unwrap() > 1000);
    }
    // Load: the flat carries the larger share of the 20 N preload.
    let loads: Vec<f64> = rows.iter().map(|r| r["load_n"].as_f64().unwrap()).collect();
    assert!(loads.iter().all(|l| *l > 0.0 && *l < 20.0));
}
