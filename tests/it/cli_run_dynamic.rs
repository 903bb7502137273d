//! `kinrepro run --solver dynamic`: trace file, offset start, errors.

use crate::common;
use crate::common::kinrepro;

fn scene01() -> String {
    common::scene("01_maxwell_vgroove_steel.toml").display().to_string()
}

/// The pose's z of a `run --json` output.
fn z_of(json: &str) -> f64 {
    let v: serde_json::Value = serde_json::from_str(json).unwrap();
    v["pose"]["z_m"].as_f64().unwrap()
}

#[test]
fn dynamic_run_writes_a_trace() {
    let dir = tempfile::tempdir().unwrap();
    let trace = dir.path().join("trace.csv");
    let t = trace.to_str().unwrap();
    let s1 = scene01();
    let (ok, out, err) = kinrepro(&[
        "run",
        &s1,
        "--solver",
        "dynamic",
        "--offset",
        "0,0,20e-6",
        "--trace",
        t,
        "--json",
    ]);
    assert!(ok, "{err}");
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(json["solver"], "dynamic");
    // A second solver: the quasi-static seating at the same (nominal) friction.
    let (ok, qs, err) = kinrepro(&["run", &s1, "--json"]);
    assert!(ok, "{err}");
    let (z, z_qs) = (z_of(&out), z_of(&qs));
    assert!((z / z_qs - 1.0).abs() < 1e-3, "dynamic {z:e} vs quasi-static {z_qs:e}");
    // Friction holds the balls up the flanks: above the frictionless closed form
    // z = -delta / cos 45, delta = (F_n / K)^(2/3), F_n = 20 N / (6 cos 45),
    // K = 4/3 E* sqrt(R), E* = 210 GPa / (2 (1 - 0.3^2)), R = 5 mm (-809.8 nm).
    let c45 = 45f64.to_radians().cos();
    let k = 4.0 / 3.0 * common::E_STAR_STEEL * 5e-3f64.sqrt();
    let z_free = -(20.0 / (6.0 * c45) / k).powf(2.0 / 3.0) / c45;
    assert!(z < 0.0 && z > 0.95 * z_free, "{z:e} vs frictionless {z_free:e}");
    let csv = std::fs::read_to_string(&trace).unwrap();
    let mut lines = csv.lines();
    // What produced it, as the study's CSV says.
    let first = lines.next().unwrap();
    assert!(
        first.starts_with("# kinrepro ") && first.contains("solver dynamic") && first.contains(&s1),
        "{first}"
    );
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(head.len(), 9 + 4 * 6);
    assert_eq!(head[0], "time_s");
    assert_eq!(head[32], "state6");
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len() as u64, json["increments"].as_u64().unwrap());
    // Starts in the air (all open), ends seated.
    assert!(rows[0][12] == "open" && rows[0][32] == "open");
    assert!(rows.last().unwrap()[12] != "open");
}

#[test]
fn dynamic_options_need_the_dynamic_solver_and_errors_are_clear() {
    let s1 = scene01();
    let (ok, _, err) = kinrepro(&["run", &s1, "--offset", "0,0,1e-5"]);
    assert!(!ok);
    assert!(err.contains("--solver dynamic"), "{err}");
    let (ok, _, err) = kinrepro(&[
        "run",
        &s1,
        "--solver",
        "dynamic",
        "--offset",
        "50e-6,0,80e-6",
        "--mu",
        "0.8,0.8,0.8,0.8,0.8,0.8",
    ]);
    assert!(!ok);
    assert!(err.contains("does not centre"), "{err}");
}
