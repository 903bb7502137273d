//! Measurement files and the calibrate / predict command line (issue 15):
//! bad files get one error naming file, line and column; a calibration
//! file round-trips into `predict`, whose JSON uses the study's fields.

use crate::common;

use kinrepro::calibrate::Measurement;
use kinrepro::calibrate::predict::PREDICTION_METHOD;
use kinrepro::calibrate::units::{UnitError, parse_column, parse_noise, parse_value};

fn err(text: &str) -> String {
    Measurement::parse(text, "m.csv", None).unwrap_err().to_string()
}

#[test]
fn bad_measurement_files_name_file_line_and_column() {
    let e = err("# rig: test\nx,y_nm\n1,2\n3,4\n5,6\n");
    assert!(e.starts_with("m.csv: line 2, column 1 (x):") && e.contains("no unit"), "{e}");
    let e = err("x_nm,w_nm\n1,2\n3,4\n5,6\n");
    assert!(e.starts_with("m.csv: line 1, column 2 (w_nm):") && e.contains("unknown DOF"), "{e}");
    let e = err("x_nm,phi_x_nm\n1,2\n3,4\n5,6\n");
    assert!(e.contains("column 2 (phi_x_nm)") && e.contains("does not fit"), "{e}");
    let e = err("x_nm,y_nm\n1,2\n3,4\n");
    assert!(
        e.starts_with("m.csv: line 3, column 1 (x_nm):") && e.contains("need at least 3"),
        "{e}"
    );
    // With a `point` column first, the first DOF column is named.
    let e = err("point,x_nm\na,1\na,2\n");
    assert!(e.starts_with("m.csv: line 3, column 2 (x_nm):") && e.contains("2 cycle(s)"), "{e}");
    let e = err("x_nm,y_nm\n1,2\n3,abc\n5,6\n");
    assert!(
        e.starts_with("m.csv: line 3, column 2 (y_nm):") && e.contains("`abc` is not a number"),
        "{e}"
    );
    let e = err("x_nm,y_nm\n1,2\n3,4\nNaN,6\n");
    assert!(e.starts_with("m.csv: line 4, column 1 (x_nm):") && e.contains("not a finite"), "{e}");
    let e = err("x_nm,y_nm\n1,2\n3,4\n5\n");
    assert!(e.starts_with("m.csv: line 4:") && e.contains("1 values, the header has 2"), "{e}");
    let e = err("x_nm,x_um\n1,2\n3,4\n5,6\n");
    assert!(e.contains("column 2 (x_um)") && e.contains("measured twice"), "{e}");
    let e = err("point,x_nm\na,1\na,2\nb,3\n");
    assert!(
        e.starts_with("m.csv: line 4, column 1 (point):") && e.contains("one evaluation point"),
        "{e}"
    );
    let e = err("# noise: x=1 nrad\nx_nm\n1\n2\n3\n");
    assert!(e.starts_with("m.csv: line 1: # noise:") && e.contains("does not fit"), "{e}");
    // Summary files.
    let e = err("dof,unit,sigma,cycles\nx,nm,5,2\n");
    assert!(
        e.starts_with("m.csv: line 2, column 4 (cycles):") && e.contains("need at least 3"),
        "{e}"
    );
    let e = err("dof,unit,sigma,cycles\nx,,5,20\n");
    assert!(e.contains("column 2 (unit)") && e.contains("missing unit"), "{e}");
    let e = err("dof,unit,sigma,cycles\nq,nm,5,20\n");
    assert!(e.contains("column 1 (dof)") && e.contains("unknown DOF"), "{e}");
    let e = err("dof,unit,sigma,cycles\nx,nm,inf,20\n");
    assert!(e.contains("column 3 (sigma)") && e.contains("not a finite"), "{e}");
}

#[test]
fn units_convert_to_si() {
    let m = Measurement::parse(
        "# noise: x=2nm, phi_y=0.05urad\npoint,x_um,phi_y_urad\nc,0.001,0.1\nc,0.003,0.3\nc,0.002,0.2\n",
        "u.csv",
        None,
    )
    .unwrap();
    assert_eq!(m.point.as_deref(), Some("c"));
    assert_eq!(m.dofs, vec![0, 4]);
    let s = m.sigma();
    // sigma of (1, 3, 2) nm is 1 nm; of (0.1, 0.3, 0.2) urad is 0.1 urad.
    assert!((s[0] - 1e-9).abs() < 1e-18 && (s[1] - 1e-7).abs() < 1e-16, "{s:?}");
    assert_eq!(m.noise[0], Some(2e-9));
    assert!((m.noise[4].unwrap() - 5e-8).abs() < 1e-20);
    let sm = Measurement::parse(
        "dof,unit,sigma,cycles\nz,um,0.004,30\nphi_z,nrad,150,30\n",
        "s.csv",
        None,
    )
    .unwrap();
    assert_eq!(sm.dofs, vec![2, 5]);
    assert_eq!(sm.cycles(), vec![30, 30]);
    assert!((sm.sigma()[0] - 4e-9).abs() < 1e-20);
}

#[test]
fn cli_calibrate_and_predict() {
    let dir = tempfile::tempdir().unwrap();
    let path = |n: &str| dir.path().join(n).display().to_string();
    let s02 = common::scene("02_maxwell_pins_steel.toml").display().to_string();
    let s01 = common::scene("01_maxwell_vgroove_steel.toml").display().to_string();
    let measured = common::worked_measurement().display().to_string();
    let measured = measured.as_str();
    // A bad file: one error line, non-zero exit.
    std::fs::write(path("bad.csv"), "x_nm,y_nm\n1,2\n3,zz\n4,5\n").unwrap();
    let (ok, _, e) = common::kinrepro(&["calibrate", &s02, "--measured", &path("bad.csv")]);
    assert!(!ok && e.trim().lines().count() == 1, "{e}");
    assert!(e.contains("bad.csv: line 3, column 2 (y_nm)"), "{e}");
    let (ok, _, e) =
        common::kinrepro(&["calibrate", &s02, "--measured", measured, "--point", "nowhere"]);
    assert!(!ok && e.contains("`nowhere` is not in the scene"), "{e}");
    let (ok, _, e) =
        common::kinrepro(&["calibrate", &s02, "--measured", measured, "--noise", "x=abc"]);
    assert!(!ok && e.contains("--noise"), "{e}");
    // Calibrate (small model studies to keep the test quick), JSON to stdout and file.
    let cal = path("cal.json");
    let args = [
        "calibrate",
        &s02,
        "--measured",
        measured,
        "--model-samples",
        "300",
        "--format",
        "json",
        "--out",
        &cal,
    ];
    let (ok, out, e) = common::kinrepro(&args);
    assert!(ok, "{e}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(
        j,
        serde_json::from_str::<serde_json::Value>(&std::fs::read_to_string(&cal).unwrap()).unwrap()
    );
    assert_eq!(j["schema_version"], 2);
    assert_eq!(j["kinrepro_version"], env!("CARGO_PKG_VERSION"));
    let sp = &j["parameters"]["spread"];
    let (est, lo, hi) = (
        sp["estimate"].as_f64().unwrap(),
        sp["low"].as_f64().unwrap(),
        sp["high"].as_f64().unwrap(),
    );
    assert!(lo < est && est < hi && sp["level"] == 0.9, "{sp}");
    assert!(
        j["goodness_of_fit"]["p_value"].as_f64().is_some() && j["goodness_of_fit"]["ok"] == true
    );
    // Written whole or not at all; no overwrite without --force.
    let (ok, _, e) = common::kinrepro(&args);
    assert!(!ok && e.contains("--force"), "{e}");
    // Predict two scenes.
    let svg = path("pred.svg");
    let (ok, out, e) = common::kinrepro(&[
        "predict",
        &s02,
        &s01,
        "--calibration",
        &cal,
        "--samples",
        "300",
        "--format",
        "json",
        "--plot",
        &svg,
    ]);
    assert!(ok, "{e}");
    let p: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(p["schema_version"], 3);
    assert_eq!(p["calibration"]["spread"]["estimate"], sp["estimate"]);
    let v = p["variants"].as_array().unwrap();
    assert!(v[0]["measured"]["sigma"]["x_nm"].as_f64().unwrap() > 0.0);
    assert!(v[1]["measured"].is_null());
    for var in v {
        let pt = &var["points"][0];
        assert_eq!(pt["sigma_interval_method"], PREDICTION_METHOD);
        for k in ["x_nm", "z_nm", "phi_z_nrad"] {
            let (l, s, h) = (
                pt["sigma_ci90_low"][k].as_f64().unwrap(),
                pt["sigma"][k].as_f64().unwrap(),
                pt["sigma_ci90_high"][k].as_f64().unwrap(),
            );
            assert!(0.0 < l && l < s && s < h, "{k}: {l} {s} {h}");
        }
        assert!((var["spread"].as_f64().unwrap() - est).abs() < 1e-15);
    }
    let text = std::fs::read_to_string(&svg).unwrap();
    assert!(text.starts_with("<svg") && text.contains("kinrepro"), "svg");
    // A study JSON is not a calibration file.
    std::fs::write(path("study.json"), out).unwrap();
    let (ok, _, e) = common::kinrepro(&["predict", &s01, "--calibration", &path("study.json")]);
    assert!(!ok && e.contains("not a kinrepro calibration file"), "{e}");
    two_parameters(&s02, &s01, measured, &path);
}

/// `--fit spread,mu_static` through the CLI: both parameters in
/// `parameters` with their intervals, a 2 x 2 correlation, region points,
/// and `predict` with the calibration.
fn two_parameters(s02: &str, s01: &str, measured: &str, path: &dyn Fn(&str) -> String) {
    let cal = path("cal2.json");
    let (ok, out, e) = common::kinrepro(&[
        "calibrate",
        s02,
        "--measured",
        measured,
        "--fit",
        "spread,mu_static",
        "--model-samples",
        "300",
        "--format",
        "json",
        "--out",
        &cal,
    ]);
    assert!(ok, "{e}");
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    for name in ["spread", "mu_static"] {
        let p = &j["parameters"][name];
        let (lo, est, hi) = (
            p["low"].as_f64().unwrap(),
            p["estimate"].as_f64().unwrap(),
            p["high"].as_f64().unwrap(),
        );
        assert!(lo <= est && est <= hi && p["level"] == 0.9, "{name}: {p}");
        assert!(p["range"].as_array().unwrap().len() == 2, "{p}");
    }
    assert!(j["fixed"]["mu_static"].is_null() && j["fixed"]["dynamic_ratio"] == 0.8);
    let r = &j["correlation"]["matrix"];
    let (r01, r10) = (r[0][1].as_f64().unwrap(), r[1][0].as_f64().unwrap());
    assert!((r01 - r10).abs() < 1e-12 && r01.abs() <= 1.0, "{r}");
    assert!((r[0][0].as_f64().unwrap() - 1.0).abs() < 1e-12, "{r}");
    assert!(j["region"].as_array().unwrap().len() >= 4);
    // 21 variances and covariances of 6 DOFs, 2 fitted parameters.
    assert_eq!(j["goodness_of_fit"]["df"], 19);
    let (ok, out, e) = common::kinrepro(&[
        "predict",
        s01,
        "--calibration",
        &cal,
        "--samples",
        "300",
        "--format",
        "json",
    ]);
    assert!(ok, "{e}");
    let p: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(
        p["calibration"]["parameters"]["mu_static"]["estimate"],
        j["parameters"]["mu_static"]["estimate"]
    );
    let pt = &p["variants"][0]["points"][0];
    let (l, s, h) = (
        pt["sigma_ci90_low"]["x_nm"].as_f64().unwrap(),
        pt["sigma"]["x_nm"].as_f64().unwrap(),
        pt["sigma_ci90_high"]["x_nm"].as_f64().unwrap(),
    );
    assert!(0.0 < l && l < s && s < h, "{l} {s} {h}");
    // A region point naming a parameter that was not fitted is refused.
    let mut bad = j.clone();
    bad["region"][0]["dynamic_ratio"] = serde_json::json!(0.5);
    std::fs::write(path("bad_region.json"), bad.to_string()).unwrap();
    let (ok, _, e) = common::kinrepro(&["predict", s01, "--calibration", &path("bad_region.json")]);
    assert!(!ok && e.trim().lines().count() == 1, "{e}");
    assert!(e.contains("`region[0]`: `dynamic_ratio`"), "{e}");
}

/// Column headers, values with units and `--noise` entries.
#[test]
fn unit_columns_and_values() {
    assert_eq!(parse_column("phi_x_nrad").unwrap(), (3, 1e-9));
    assert_eq!(parse_column("x_um").unwrap(), (0, 1e-6));
    let e = parse_column("x").unwrap_err();
    assert!(matches!(e, UnitError::NoUnit { dof: 0, .. }), "{e:?}");
    assert_eq!(e.to_string(), "`x` has no unit: write x_m, x_mm, x_um, x_nm");
    assert!(parse_column("w_nm").unwrap_err().to_string().contains("unknown DOF"));
    let e = parse_column("z_nrad").unwrap_err();
    assert_eq!(e.to_string(), "`z_nrad`: unit `nrad` does not fit z (use m, mm, um, nm)");
    assert_eq!(parse_value(0, "1nm").unwrap(), 1e-9);
    assert_eq!(parse_value(4, "20 nrad").unwrap(), 20e-9);
    assert_eq!(parse_value(0, "1e-9").unwrap(), 1e-9);
    assert!(matches!(parse_value(0, "1 nrad"), Err(UnitError::ValueUnit { dof: 0, .. })));
    assert!(parse_value(0, "NaN").is_err());
    assert!(matches!(parse_value(0, "-1nm"), Err(UnitError::OutOfRange { .. })));
    let mut n = [None; 6];
    parse_noise("x=1nm, phi_z=2e-8", &mut n).unwrap();
    assert_eq!(n[0], Some(1e-9));
    assert_eq!(n[5], Some(2e-8));
    assert_eq!(
        parse_noise("q=1nm", &mut n).unwrap_err().to_string(),
        "`q=1nm`: unknown DOF `q` (one of x, y, z, phi_x, phi_y, phi_z)"
    );
}

/// Cycles given as numbers in SI (`Measurement::from_cycles`, the Python
/// package's array) are the cycles of the same readings in a file, with
/// the file's checks: a unit slip, a non-finite value, too few cycles.
#[test]
fn cycles_given_as_numbers_are_the_files() {
    use kinrepro::calibrate::MeasuredData;
    use kinrepro::dof::Dof;
    let text = "x_nm,phi_y_nrad\n1.5,-20\n-3.25,40\n2,10\n0.5,-5\n";
    let file = Measurement::parse(text, "m.csv", None).unwrap();
    let rows =
        vec![vec![1.5e-9, -20e-9], vec![-3.25e-9, 40e-9], vec![2e-9, 10e-9], vec![0.5e-9, -5e-9]];
    let dofs = [Dof::X, Dof::PhiY];
    let array = Measurement::from_cycles("array", None, &dofs, rows.clone(), [None; 6]).unwrap();
    assert_eq!(array.dofs, file.dofs);
    let (MeasuredData::Cycles(a), MeasuredData::Cycles(f)) = (&array.data, &file.data) else {
        panic!("cycles expected");
    };
    for (ra, rf) in a.iter().zip(f) {
        for (x, y) in ra.iter().zip(rf) {
            assert!((x - y).abs() <= 1e-12 * y.abs(), "{x} {y}");
        }
    }
    assert_eq!(array.sigma().len(), 2);
    let e = |rows: Vec<Vec<f64>>| {
        Measurement::from_cycles("array", None, &dofs, rows, [None; 6]).unwrap_err().to_string()
    };
    let mut slip = rows.clone();
    slip[2][0] = 2.0;
    assert!(e(slip).starts_with("array: row 3, x_m: 2e0 m: a reading"));
    let mut nan = rows.clone();
    nan[1][1] = f64::NAN;
    assert!(e(nan).contains("row 2, phi_y_rad: NaN is not a finite"));
    assert!(e(rows[..2].to_vec()).contains("2 cycle(s), need at least 3"));
}

/// The bundled worked example's calibration files name the design they were
/// fitted on by `scene_content`; `predict` shows the measured sigma beside
/// the scene whose design hash equals it. When the scene types change, that
/// hash changes and the files must be regenerated by their documented
/// commands (docs/calibration.md), else predict silently drops the column.
#[test]
fn bundled_calibrations_still_name_scene_02() {
    let root = std::path::Path::new(env!("CARGO_MANIFEST_DIR"));
    let hash =
        kinrepro::calibrate::file::design_hash(&common::load("02_maxwell_pins_steel.toml").0);
    for name in ["calibration_02.json", "calibration_02_mu.json"] {
        let text = std::fs::read_to_string(root.join("docs/calibration").join(name)).unwrap();
        let v: serde_json::Value = serde_json::from_str(&text).unwrap();
        assert_eq!(
            v["scene_content"],
            hash.as_str(),
            "{name}: regenerate it (docs/calibration.md)"
        );
    }
}
