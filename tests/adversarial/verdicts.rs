//! One verdict for a coupling that cannot seat; validation of every file kinrepro reads; text hygiene (issue 28 items 3-5).

use std::path::{Path, PathBuf};
use std::process::Command;

use crate::common;

/// Run kinrepro in `dir`: (exit code, stdout, stderr).
pub(crate) fn run_in(dir: &Path, args: &[&str]) -> (i32, String, String) {
    let out =
        Command::new(env!("CARGO_BIN_EXE_kinrepro")).current_dir(dir).args(args).output().unwrap();
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Scene 01 with `from` replaced by `to`, written as `dir/name`.
pub(crate) fn variant(dir: &Path, name: &str, edits: &[(&str, &str)]) -> PathBuf {
    variant_of("01_maxwell_vgroove_steel.toml", dir, name, edits)
}

/// The bundled `scene` with each `from` replaced by its `to` (each must
/// occur), written as `dir/name`.
pub(crate) fn variant_of(scene: &str, dir: &Path, name: &str, edits: &[(&str, &str)]) -> PathBuf {
    let mut text = std::fs::read_to_string(common::scene(scene)).unwrap();
    for (from, to) in edits {
        assert!(text.contains(from), "{from}");
        text = text.replace(from, to);
    }
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p
}

/// The two couplings that cannot seat: a 170 degree groove and mu 1.5.
fn unseatable(dir: &Path) -> Vec<PathBuf> {
    vec![
        variant(dir, "g170.toml", &[("opening_angle_deg = 90.0", "opening_angle_deg = 170.0")]),
        variant(dir, "mu15.toml", &[("mu_static = 0.5 ", "mu_static = 1.5 ")]),
    ]
}

/// The reason `check` gives after `CANNOT SEAT: ` (up to its `;`).
fn check_reason(out: &str) -> String {
    let line = out.lines().find(|l| l.contains("CANNOT SEAT: ")).unwrap();
    let r = line.split("CANNOT SEAT: ").nth(1).unwrap();
    r.split(';').next().unwrap().to_string()
}

/// A sigma table row or detail row: a number with three decimals.
fn has_scatter_number(out: &str) -> bool {
    out.split_whitespace()
        .any(|w| w.parse::<f64>().is_ok() && w.contains('.') && w.len() - w.find('.').unwrap() == 4)
}

#[test]
fn a_coupling_that_cannot_seat_gets_one_verdict_and_exit_code_from_every_command() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let cal = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/calibration/calibration_02.json");
    for p in unseatable(d) {
        let s = p.file_name().unwrap().to_str().unwrap();
        let (check_rc, out, _) = run_in(d, &["check", s]);
        assert_eq!(check_rc, 1, "{s}: check");
        let reason = check_reason(&out);
        assert!(reason.contains("every contact sticks"), "{reason}");
        for extra in [&[][..], &["--solver", "dynamic"][..]] {
            let mut args = vec!["study", s, "--samples", "4"];
            args.extend_from_slice(extra);
            let (rc, out, err) = run_in(d, &args);
            assert_eq!(rc, check_rc, "{s} {extra:?}: {err}");
            assert!(err.contains(&reason), "{s} {extra:?}: {err}");
            assert!(out.contains("CANNOT SEAT"), "{out}");
            // Neither the quasi-static zero nor the dynamic solver's noise
            // is printed as a scatter.
            assert!(!has_scatter_number(&out), "{s} {extra:?}: {out}");
        }
        let (rc, out, err) =
            run_in(d, &["predict", s, "--calibration", cal.to_str().unwrap(), "--samples", "100"]);
        assert_eq!(rc, check_rc, "{s}: predict: {out}");
        assert!(err.contains("cannot seat") && err.contains(s), "{err}");
        assert!(!has_scatter_number(&out), "{out}");
        // Shards of it, merged, exit as the study does.
        let mut parts = Vec::new();
        for i in 1..=2 {
            let shard = format!("{i}/2");
            let (_, json, err) =
                run_in(d, &["study", s, "--samples", "4", "--shard", &shard, "--format", "json"]);
            let part = d.join(format!("{s}.{i}.json"));
            std::fs::write(&part, json).unwrap_or_else(|e| panic!("{e}: {err}"));
            parts.push(part.to_str().unwrap().to_string());
        }
        let (rc, _, err) = run_in(d, &["merge", &parts[0], &parts[1]]);
        assert_eq!(rc, check_rc, "{s}: merge: {err}");
        assert!(err.contains(&reason), "{err}");
        let (rc, json, err) = run_in(d, &["merge", &parts[0], &parts[1], "--allow-unseated"]);
        assert_eq!(rc, 0, "{err}");
        let doc: kinrepro::study::StudyReport = serde_json::from_str(&json).unwrap();
        assert!(doc.variants[0].cannot_seat.as_deref() == Some(reason.as_str()));
    }
}

/// The verdict is read from the contacts' stick/slip state, not from
/// equal samples: a spread of 1e-17 (the probes' coefficients equal to
/// rounding) or mu_d = 1e-20 mu_s (sliding contacts carry no friction, so
/// the pose does not depend on mu_s) gives equal poses of a coupling whose
/// six contacts all slide (`run`), and it seats.
#[test]
fn equal_samples_of_sliding_contacts_are_not_a_cannot_seat_verdict() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    for (name, edit) in [
        ("tiny_spread.toml", ("spread = 0.05 ", "spread = 1e-17 ")),
        ("no_mu_d.toml", ("dynamic_ratio = 0.8 ", "dynamic_ratio = 1e-20 ")),
    ] {
        let p = variant(d, name, &[edit]);
        let s = p.to_str().unwrap();
        let (rc, json, err) = run_in(d, &["run", s, "--json"]);
        assert_eq!(rc, 0, "{name}: {err}");
        let run: serde_json::Value = serde_json::from_str(&json).unwrap();
        let states: Vec<&str> = run["contacts"]
            .as_array()
            .unwrap()
            .iter()
            .map(|c| c["state"].as_str().unwrap())
            .collect();
        assert!(states.iter().all(|s| *s == "slip"), "{name}: {states:?}");
        let (rc, out, err) = run_in(d, &["check", s]);
        assert_eq!(rc, 0, "{name}: {out}{err}");
        assert!(!out.contains("CANNOT SEAT"), "{name}: {out}");
        let (rc, json, err) = run_in(d, &["study", s, "--samples", "8", "--format", "json"]);
        assert_eq!(rc, 0, "{name}: {err}");
        let doc: kinrepro::study::StudyReport = serde_json::from_str(&json).unwrap();
        assert!(doc.variants[0].cannot_seat.is_none(), "{name}");
    }
}

#[test]
fn a_frictionless_coupling_seats_and_its_zero_scatter_is_the_result() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let p = variant(
        d,
        "mu0.toml",
        &[("mu_static = 0.5 ", "mu_static = 0.0 "), ("spread = 0.05 ", "spread = 0.0 ")],
    );
    let s = p.to_str().unwrap();
    let (rc, out, err) = run_in(d, &["check", s]);
    assert_eq!(rc, 0, "{out}{err}");
    assert!(!out.contains("CANNOT SEAT"), "{out}");
    // Without friction every contact slides into the one equilibrium of
    // the preload: every sample seats at the nominal pose, sigma = 0 exactly.
    for solver in ["quasi-static", "dynamic"] {
        let (rc, json, err) =
            run_in(d, &["study", s, "--samples", "4", "--solver", solver, "--format", "json"]);
        assert_eq!(rc, 0, "{solver}: {err}");
        let doc: kinrepro::study::StudyReport = serde_json::from_str(&json).unwrap();
        assert!(doc.variants[0].cannot_seat.is_none());
        for p in &doc.variants[0].points {
            assert!(p.sigma.values().iter().all(|s| *s == 0.0), "{solver}: {:?}", p.sigma);
        }
    }
}

#[test]
fn a_sweep_point_that_cannot_seat_has_the_verdict_of_check() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let p = unseatable(d).remove(1);
    let (_, out, _) = run_in(d, &["check", p.to_str().unwrap()]);
    let reason = check_reason(&out);
    let s01 = common::scene("01_maxwell_vgroove_steel.toml");
    let (rc, out, err) = run_in(
        d,
        &["sweep", s01.to_str().unwrap(), "--set", "friction.mu_static=0.5,1.5", "--samples", "4"],
    );
    assert_eq!(rc, 0, "{err}");
    assert!(out.contains(&format!("cannot seat: {reason}")), "{out}");
    // A sweep in which no point seats gives no result: exit 1, as study.
    let (rc, out, err) = run_in(
        d,
        &["sweep", s01.to_str().unwrap(), "--set", "friction.mu_static=1.5", "--samples", "4"],
    );
    assert_eq!(rc, 1, "{out}");
    assert!(out.contains(&format!("cannot seat: {reason}")), "{out}");
    assert!(err.contains("none of the 1 design points was evaluated"), "{err}");
}

/// A whole study JSON of scene 01 (6 samples) in `d`, and its two shards.
fn study_files(d: &Path) -> (PathBuf, [PathBuf; 2]) {
    let s = variant(d, "s01.toml", &[]);
    let s = s.to_str().unwrap();
    let write = |name: &str, extra: &[&str]| {
        let mut args = vec!["study", s, "--samples", "6", "--format", "json"];
        args.extend_from_slice(extra);
        let (rc, json, err) = run_in(d, &args);
        assert_eq!(rc, 0, "{err}");
        let p = d.join(name);
        std::fs::write(&p, json).unwrap();
        p
    };
    let whole = write("whole.json", &[]);
    let parts = [write("p1.json", &["--shard", "1/2"]), write("p2.json", &["--shard", "2/2"])];
    (whole, parts)
}

/// `from` with the JSON edited by `f`, written as `d/name`.
fn edited(from: &Path, d: &Path, name: &str, f: impl Fn(&mut serde_json::Value)) -> String {
    let mut v: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(from).unwrap()).unwrap();
    f(&mut v);
    let p = d.join(name);
    std::fs::write(&p, serde_json::to_string(&v).unwrap()).unwrap();
    p.to_str().unwrap().to_string()
}

#[test]
fn merge_and_report_check_a_study_json_like_a_scene() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (whole, [p1, p2]) = study_files(d);
    let p2 = p2.to_str().unwrap();
    let (rc, _, err) = run_in(d, &["merge", p1.to_str().unwrap(), p2]);
    assert_eq!(rc, 0, "{err}");
    // mu = 5 in one record: outside the scene's range and outside
    // mu0 +- spread = [0.45, 0.55], which the design maps every row into.
    let mu5 =
        edited(&p1, d, "mu5.json", |v| v["variants"][0]["records"][0]["inputs_si"][0] = 5.0.into());
    let (rc, _, err) = run_in(d, &["merge", &mu5, p2]);
    assert_eq!(rc, 1);
    assert!(
        err.contains("mu5.json") && err.contains("records[0].inputs_si[0]") && err.contains("5"),
        "{err}"
    );
    assert_eq!(err.lines().count(), 1, "{err}");
    let mu_static = edited(&p1, d, "mus5.json", |v| v["variants"][0]["mu_static"] = 5.0.into());
    let (rc, _, err) = run_in(d, &["merge", &mu_static, p2]);
    assert!(rc == 1 && err.contains("mu_static"), "{err}");
    // samples = 1e18 against 6 records, for report and merge.
    let big = edited(&whole, d, "big.json", |v| {
        v["variants"][0]["samples"] = 1_000_000_000_000_000_000u64.into()
    });
    for args in [vec!["report", big.as_str(), "--out", "r.html"], vec!["merge", big.as_str()]] {
        let (rc, _, err) = run_in(d, &args);
        assert!(rc == 1 && err.contains("big.json") && err.contains("samples"), "{err}");
    }
    assert!(!d.join("r.html").exists());
    // A negative sigma names the file and the field.
    let neg = edited(&whole, d, "neg.json", |v| {
        v["variants"][0]["points"][0]["sigma"]["x_nm"] = (-1.0).into()
    });
    let (rc, _, err) = run_in(d, &["report", &neg, "--out", "r.html"]);
    assert!(rc == 1 && err.contains("neg.json") && err.contains("sigma"), "{err}");
}

#[test]
fn report_opens_no_scene_outside_the_current_and_the_json_folder() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let (whole, _) = study_files(d);
    let (rc, _, err) = run_in(d, &["report", whole.to_str().unwrap(), "--out", "ok.html"]);
    assert_eq!(rc, 0, "{err}");
    let sub = d.join("sub");
    std::fs::create_dir(&sub).unwrap();
    for (name, scene) in [
        ("shadow.json", "/etc/shadow"),
        ("passwd.json", "/etc/passwd"),
        ("up.json", "../../../../../../../../etc/passwd"),
    ] {
        let j = edited(&whole, &sub, name, |v| v["variants"][0]["scene"] = scene.into());
        let (rc, _, err) = run_in(&sub, &["report", &j, "--out", "x.html"]);
        assert_eq!(rc, 1, "{name}: {err}");
        assert!(err.contains(name) && err.contains(scene) && err.contains("outside"), "{err}");
        // Nothing of the file's content (passwd begins with `root:`).
        assert!(!err.contains("root"), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
    }
}
