//! `kinrepro stiffness` and `kinrepro load`: JSON against the library and
//! statics, and bad input gets a clear message and a non-zero exit code.

use crate::common;
use crate::common::kinrepro;

const SCENE: &str = concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/01_maxwell_vgroove_steel.toml");

#[test]
fn stiffness_json_has_the_frictionless_closed_form() {
    let (ok, out, err) = kinrepro(&["stiffness", SCENE, "--mu", "0,0,0,0,0,0", "--json"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    // k_z = 6 k_n cos^2 45 = 3 k_n, k_n = 3/2 K^(2/3) F^(1/3), F = 20 / (6 cos 45).
    let f = 20.0 / (6.0 * 45f64.to_radians().cos());
    let kh = 4.0 / 3.0 * common::E_STAR_STEEL * 5e-3f64.sqrt();
    let kn = 1.5 * kh * (f / kh).powf(1.0 / 3.0);
    let kz = v["points"][0]["matrix"][2][2].as_f64().unwrap();
    assert!((kz / (3.0 * kn) - 1.0).abs() < 1e-6, "{kz}");
    let t = &v["points"][0]["translational"];
    assert!((t[0]["stiffness"].as_f64().unwrap() / (1.5 * kn) - 1.0).abs() < 1e-6);
}

#[test]
fn load_reports_the_envelope_and_a_table() {
    let (ok, out, err) =
        kinrepro(&["load", SCENE, "--force", "1,0,0", "--at", "0,0,0.05", "--json"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let f = v["envelope"]["factor"].as_f64().unwrap();
    assert!(f > 0.0 && v["envelope"]["event"]["kind"] == "slip", "{}", v["envelope"]);
    // Statics of the reported forces: the contacts carry preload plus load.
    let mut fx = 1.0;
    let mut fz = -20.0;
    for c in v["contacts"].as_array().unwrap() {
        let n: Vec<f64> =
            c["normal"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
        let t: Vec<f64> =
            c["tangential_force"].as_array().unwrap().iter().map(|x| x.as_f64().unwrap()).collect();
        let fnn = c["normal_force_n"].as_f64().unwrap();
        fx += fnn * n[0] + t[0];
        fz += fnn * n[2] + t[2];
    }
    assert!(fx.abs() < 1e-8 && fz.abs() < 1e-8, "{fx} {fz}");
    let (ok, table, _) = kinrepro(&["load", SCENE, "--force", "1,0,0", "--at", "0,0,0.05"]);
    assert!(ok && table.contains("safe load envelope: contact") && table.contains("x [nm]"));
}

#[test]
fn bad_load_input_is_a_clear_error_with_nonzero_exit() {
    let cases: &[(&[&str], &str)] = &[
        (&["load", SCENE, "--force", "1,0,0", "--at", "a,b,c"], "invalid"),
        (&["load", SCENE, "--force", "1,0", "--at", "0,0,0"], "--force needs three"),
        (&["load", SCENE, "--force", "1,0,0", "--at", "0,0,0,0"], "--at needs three"),
        (&["load", SCENE, "--force", "NaN,0,0", "--at", "0,0,0"], "finite"),
        (&["load", SCENE, "--force", "1,0,0", "--at", "0,inf,0"], "finite"),
        (&["load", SCENE, "--force", "0,0,0", "--at", "0,0,0"], "no load"),
        (&["load", SCENE, "--force", "1,0,0"], "--at"),
        (&["load", SCENE, "--force", "1,0,0", "--at", "0,0,0", "--mu", "0.5"], "needs 6 values"),
        (&["stiffness", SCENE, "--at", "x,y,z"], "invalid"),
        (&["stiffness", SCENE, "--at", "0,nan,0"], "finite"),
        (&["stiffness", SCENE, "--at", "0,0"], "--at needs three"),
    ];
    for (args, needle) in cases {
        let (ok, _, err) = kinrepro(args);
        assert!(!ok, "{args:?} succeeded");
        assert!(err.contains(needle), "{args:?}: {err}");
    }
}
