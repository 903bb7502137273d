//! `kinrepro contact`: JSON keys against the closed form, and bad input gets
//! a clear message and a non-zero exit code.

mod common;
use common::kinrepro;

#[test]
fn json_output_has_the_documented_keys_and_hertz_values() {
    let (ok, out, _) = kinrepro(&[
        "contact",
        "--shape",
        "sphere-plane",
        "--radius1",
        "5e-3",
        "--material1",
        "steel",
        "--material2",
        "steel",
        "--load",
        "20",
        "--json",
    ]);
    assert!(ok);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    // Closed form: E* = 210e9 / (2 (1 - 0.09)), a = (3 F R / 4 E*)^(1/3), delta = a^2/R.
    let e_star: f64 = 210e9 / (2.0 * 0.91);
    let a = (3.0 * 20.0 * 5e-3 / (4.0 * e_star)).cbrt();
    let get = |k: &str| v[k].as_f64().unwrap_or_else(|| panic!("missing {k}"));
    assert!((get("approach_m") / (a * a / 5e-3) - 1.0).abs() < 1e-12);
    assert!((v["semi_axes_m"][0].as_f64().unwrap() / a - 1.0).abs() < 1e-12);
    assert!(
        (get("max_pressure_pa") / (3.0 * 20.0 / (2.0 * std::f64::consts::PI * a * a)) - 1.0).abs()
            < 1e-12
    );
    assert!((get("hertz_constant") / (4.0 / 3.0 * e_star * 5e-3_f64.sqrt()) - 1.0).abs() < 1e-12);
    assert!((get("normal_stiffness_n_per_m") / (2.0 * e_star * a) - 1.0).abs() < 1e-12);
    assert!(get("tangential_stiffness_n_per_m") > 0.0);
}

#[test]
fn bad_input_is_a_clear_error_with_nonzero_exit() {
    let base = ["contact", "--material1", "steel", "--material2", "steel"];
    let cases: &[(&[&str], &str)] = &[
        (
            &[
                "--shape",
                "sphere-plane",
                "--radius1",
                "-5e-3",
                "--load",
                "1",
            ],
            "radius1",
        ),
        (
            &[
                "--shape",
                "sphere-sphere",
                "--radius1",
                "5e-3",
                "--radius2",
                "0",
                "--load",
                "1",
            ],
            "radius2",
        ),
        (
            &[
                "--shape",
                "sphere-cylinder",
                "--radius1",
                "5e-3",
                "--load",
                "1",
            ],
            "needs radius2",
        ),
        (
            &[
                "--shape",
                "sphere-plane",
                "--radius1",
                "5e-3",
                "--load",
                "0",
            ],
            "load",
        ),
        (
            &[
                "--shape",
                "sphere-plane",
                "--radius1",
                "5e-3",
                "--load",
                "-3",
            ],
            "load",
        ),
        (
            &[
                "--shape",
                "sphere-seat",
                "--radius1",
                "5e-3",
                "--radius2",
                "4e-3",
                "--load",
                "1",
            ],
            "seat",
        ),
        (
            &["--shape", "sphere-cone", "--radius1", "5e-3", "--load", "1"],
            "sphere-cone",
        ),
    ];
    for (args, needle) in cases {
        let mut all: Vec<&str> = base.to_vec();
        all.extend_from_slice(args);
        let (ok, _, err) = kinrepro(&all);
        assert!(!ok, "{args:?} should fail");
        assert!(
            err.contains(needle),
            "{args:?}: stderr lacks `{needle}`: {err}"
        );
        assert!(!err.contains("panicked"), "{err}");
    }
    let (ok, _, err) = kinrepro(&[
        "contact",
        "--shape",
        "sphere-plane",
        "--radius1",
        "5e-3",
        "--material1",
        "unobtainium",
        "--material2",
        "steel",
        "--load",
        "1",
    ]);
    assert!(!ok && err.contains("unknown material `unobtainium`") && err.contains("--material1"));
}
