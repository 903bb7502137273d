//! `kinrepro run --solver dynamic`: trace file, offset start, errors.

use std::process::Command;

fn kinrepro(args: &[&str]) -> std::process::Output {
    Command::new(env!("CARGO_BIN_EXE_kinrepro"))
        .args(args)
        .output()
        .unwrap()
}

#[test]
fn dynamic_run_writes_a_trace() {
    let trace = std::env::temp_dir().join(format!("kinrepro-trace-{}.csv", std::process::id()));
    let t = trace.to_str().unwrap();
    let out = kinrepro(&[
        "run",
        "scenes/01_maxwell_vgroove_steel.toml",
        "--solver",
        "dynamic",
        "--offset",
        "0,0,20e-6",
        "--trace",
        t,
        "--json",
    ]);
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    assert_eq!(json["solver"], "dynamic");
    let z = json["pose"]["z_m"].as_f64().unwrap();
    assert!(z < -600e-9 && z > -700e-9, "{z}");
    let csv = std::fs::read_to_string(&trace).unwrap();
    std::fs::remove_file(&trace).unwrap();
    let mut lines = csv.lines();
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
    let out = kinrepro(&[
        "run",
        "scenes/01_maxwell_vgroove_steel.toml",
        "--offset",
        "0,0,1e-5",
    ]);
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("--solver dynamic"));
    let out = kinrepro(&[
        "run",
        "scenes/01_maxwell_vgroove_steel.toml",
        "--solver",
        "dynamic",
        "--offset",
        "50e-6,0,80e-6",
        "--mu",
        "0.8,0.8,0.8,0.8,0.8,0.8",
    ]);
    assert!(!out.status.success());
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(err.contains("does not centre"), "{err}");
}
