//! The study's outputs as a user and a script meet them (issue 12, items
//! 3-5, 7): metadata in every format, physical inputs in the JSON records,
//! strict merge, safe files, closed pipes, full disks, non-finite values,
//! couplings that cannot seat, bounded --jobs and --increments.

use crate::common;

use std::io::Read;
use std::path::{Path, PathBuf};
use std::process::{Command, Stdio};

use crate::common::{kinrepro, scene};
use kinrepro::study::StudyReport;

fn s01() -> String {
    scene("01_maxwell_vgroove_steel.toml").to_str().unwrap().to_string()
}

/// Scene 01 with `from` replaced by `to`, written into `dir`.
fn scene_variant(dir: &Path, name: &str, from: &str, to: &str) -> String {
    let text = std::fs::read_to_string(s01()).unwrap();
    assert!(text.contains(from), "{from}");
    let p = dir.join(name);
    std::fs::write(&p, text.replace(from, to)).unwrap();
    p.to_str().unwrap().to_string()
}

/// Fields of one CSV line (RFC 4180 quoting).
fn split_csv(line: &str) -> Vec<String> {
    let (mut fields, mut cur, mut quoted) = (Vec::new(), String::new(), false);
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                cur.push('"');
                chars.next();
            }
            ('"', _) => quoted = !quoted,
            (',', false) => fields.push(std::mem::take(&mut cur)),
            _ => cur.push(c),
        }
    }
    fields.push(cur);
    fields
}

fn json(args: &[&str]) -> StudyReport {
    let (ok, out, err) = kinrepro(args);
    assert!(ok, "{err}");
    serde_json::from_str(&out).unwrap()
}

#[test]
fn every_format_names_version_solver_sampler_seed_samples_and_vary() {
    let s = s01();
    let base = ["study", &s, "--sampler", "mc", "--samples", "12", "--seed", "7"];
    let version = env!("CARGO_PKG_VERSION");
    // Table: the first line.
    let (ok, table, err) = kinrepro(&base);
    assert!(ok, "{err}");
    let first = table.lines().next().unwrap();
    for needle in [
        &format!("kinrepro {version}"),
        "output schema 3",
        "solver quasi-static",
        "sampler mc",
        "seed 7",
        "samples 12",
        "vary friction",
    ] {
        assert!(first.contains(needle), "{needle} not in {first}");
    }
    assert!(table.contains("sigma_phi_z[nrad]"));
    // CSV: provenance columns on every row, six DOFs.
    let mut args = base.to_vec();
    args.extend(["--format", "csv"]);
    let (ok, csv, err) = kinrepro(&args);
    assert!(ok, "{err}");
    let mut lines = csv.lines();
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    let col = |name: &str| head.iter().position(|h| *h == name).unwrap();
    let rows: Vec<Vec<String>> = lines.map(split_csv).collect();
    assert_eq!(rows.len(), 6);
    for r in &rows {
        assert_eq!(r[col("kinrepro_version")], version);
        assert_eq!(r[col("schema_version")], "3");
        assert_eq!(r[col("solver")], "quasi-static");
        assert_eq!(r[col("sampler")], "mc");
        assert_eq!(r[col("seed")], "7");
        assert_eq!(r[col("samples")], "12");
        assert_eq!(r[col("vary")], "friction");
    }
    let dofs: Vec<&str> = rows.iter().map(|r| r[col("dof")].as_str()).collect();
    assert_eq!(dofs, ["x", "y", "z", "phi_x", "phi_y", "phi_z"]);
    // JSON: top level and the fingerprint of the variant.
    let mut args = base.to_vec();
    args.extend(["--format", "json"]);
    let (ok, text, err) = kinrepro(&args);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    assert_eq!(v["schema_version"], 3);
    assert_eq!(v["kinrepro_version"], version);
    assert_eq!(v["solver"], "quasi-static");
    assert_eq!(v["sampler"], "mc");
    assert_eq!(v["seed"], 7);
    assert_eq!(v["samples"], 12);
    assert_eq!(v["vary"], serde_json::json!(["friction"]));
    let f = &v["variants"][0]["fingerprint"];
    assert_eq!(f["mu_static"], 0.5);
    assert_eq!(f["samples"], 12);
    assert!(v["variants"][0]["points"][0]["sigma"]["phi_z_nrad"].as_f64().unwrap() > 0.0);
}

#[test]
fn json_records_carry_physical_mu_equal_to_the_per_sample_csv() {
    let dir = tempfile::tempdir().unwrap();
    let s = s01();
    let out = dir.path().join("out");
    let r = json(&["study", &s, "--format", "json", "--out", out.to_str().unwrap()]);
    let v = &r.variants[0];
    let (mu0, spread) = (0.5, 0.05);
    assert_eq!(v.records.len(), 25);
    // The CSV: a provenance comment line, the header, one row per sample.
    let csv = std::fs::read_to_string(out.join("samples_01_01_maxwell_vgroove_steel.csv")).unwrap();
    let mut lines = csv.lines();
    assert!(lines.next().unwrap().starts_with("# kinrepro "));
    let head: Vec<&str> = lines.next().unwrap().split(',').collect();
    assert_eq!(&head[1..7], ["mu_1", "mu_2", "mu_3", "mu_4", "mu_5", "mu_6"]);
    for (rec, line) in v.records.iter().zip(lines) {
        let cells: Vec<f64> = line.split(',').map(|c| c.parse().unwrap()).collect();
        assert_eq!(cells[0] as usize, rec.index);
        for k in 0..6 {
            let mu = rec.physical[k];
            // mu_s = mu0 + spread (2u - 1) (docs/model.md, "Coulomb stick and slip"), independently of the code's map.
            let expected = mu0 + spread * (2.0 * rec.inputs[k] - 1.0);
            assert!((mu - expected).abs() < 1e-15, "{mu} vs {expected}");
            assert!(mu >= mu0 - spread && mu <= mu0 + spread, "{mu}");
            assert_eq!(cells[1 + k], mu, "sample {} mu_{}", rec.index, k + 1);
        }
        assert_eq!(&cells[7..], &rec.outputs[..]);
    }
    // The raw JSON names the two separately.
    let (_, text, _) = kinrepro(&["study", &s, "--samples", "4", "--format", "json"]);
    let j: serde_json::Value = serde_json::from_str(&text).unwrap();
    let rec = &j["variants"][0]["records"][0];
    assert!(rec["inputs_si"].is_array() && rec["design_u"].is_array());
    assert!(rec["outputs_si"].as_array().unwrap().len() == 6);
}

/// Four shards of scene `s` (24 MC samples) as files in `dir`.
fn shards(dir: &Path, s: &str, extra: &[&str], tag: &str) -> Vec<PathBuf> {
    (1..=4)
        .map(|i| {
            let shard = format!("{i}/4");
            let mut args = vec![
                "study",
                s,
                "--sampler",
                "mc",
                "--samples",
                "24",
                "--shard",
                &shard,
                "--format",
                "json",
            ];
            args.extend(extra);
            let (ok, out, err) = kinrepro(&args);
            assert!(ok, "{err}");
            let p = dir.join(format!("{tag}_{i}.json"));
            std::fs::write(&p, out).unwrap();
            p
        })
        .collect()
}

fn merge(parts: &[&PathBuf]) -> (bool, String, String) {
    let mut args = vec!["merge".to_string()];
    args.extend(parts.iter().map(|p| p.to_str().unwrap().to_string()));
    let a: Vec<&str> = args.iter().map(|s| s.as_str()).collect();
    kinrepro(&a)
}

#[test]
fn merge_refuses_parts_of_another_study_naming_the_field() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let s = s01();
    let good = shards(d, &s, &[], "good");
    let (ok, _, err) = merge(&good.iter().collect::<Vec<_>>());
    assert!(ok, "{err}");
    let mu = scene_variant(d, "mu.toml", "mu_static = 0.5 ", "mu_static = 0.4 ");
    let preload = scene_variant(d, "pre.toml", "force = 20.0 ", "force = 25.0 ");
    let cases: Vec<(Vec<PathBuf>, &str)> = vec![
        (shards(d, &mu, &[], "mu"), "mu_static"),
        (shards(d, &preload, &[], "preload"), "preload force"),
        (shards(d, &s, &["--solver", "dynamic"], "dyn"), "solver"),
        (shards(d, &s, &["--seed", "2"], "seed"), "seed"),
        (shards(d, &s, &["--increments", "30"], "inc"), "solver_settings"),
    ];
    for (other, field) in &cases {
        let (ok, out, err) = merge(&[&good[0], &good[1], &other[2], &good[3]]);
        assert!(!ok && out.is_empty(), "{field}: merged");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.contains(&format!("{field} (")) && err.contains("_3.json"), "{field}: {err}");
    }
    // A different sample count: the part's fingerprint names it.
    let dir2 = tempfile::tempdir().unwrap();
    let (ok, out, err) = kinrepro(&[
        "study",
        &s,
        "--sampler",
        "mc",
        "--samples",
        "28",
        "--shard",
        "3/4",
        "--format",
        "json",
    ]);
    assert!(ok, "{err}");
    let p = dir2.path().join("n28.json");
    std::fs::write(&p, out).unwrap();
    let (ok, _, err) = merge(&[&good[0], &good[1], &p, &good[3]]);
    assert!(!ok && err.contains("samples (24 vs 28)"), "{err}");
    // A missing shard is named with its samples.
    let (ok, _, err) = merge(&[&good[0], &good[1], &good[3]]);
    assert!(!ok && err.contains("shard 3/4 (samples 12..17) missing"), "{err}");
}

#[test]
fn a_part_holding_1e308_is_an_error_naming_the_sample_not_sigma_zero() {
    let dir = tempfile::tempdir().unwrap();
    let good = shards(dir.path(), &s01(), &[], "p");
    let mut doc: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&good[1]).unwrap()).unwrap();
    let rec = &mut doc["variants"][0]["records"][2];
    let index = rec["index"].as_u64().unwrap();
    rec["outputs_si"][0] = serde_json::json!(1e308);
    std::fs::write(&good[1], doc.to_string()).unwrap();
    let (ok, out, err) = merge(&good.iter().collect::<Vec<_>>());
    assert!(!ok && out.is_empty(), "{out}");
    assert!(err.contains(&format!("sample {index}")) && err.contains("centre/x_m"), "{err}");
    // The statistics layer itself: a variance that overflows is not zero.
    let r = kinrepro::study::stats::mean_sigma(&[1e308, -1e308, 1e308]);
    assert!(!matches!(r, Ok((_, sigma)) if sigma == 0.0), "{r:?}");
    let s = kinrepro::study::stats::summarize(
        &[1e308, -1e308, 1e308],
        kinrepro::study::stats::SigmaMethod::Iid,
    );
    assert!(s.is_err(), "{s:?}");
}

#[test]
fn files_are_not_overwritten_without_force_and_never_left_half_written() {
    let dir = tempfile::tempdir().unwrap();
    let s = s01();
    let out = dir.path().join("out");
    let o = out.to_str().unwrap();
    let (ok, _, err) = kinrepro(&["study", &s, "--samples", "6", "--out", o]);
    assert!(ok, "{err}");
    let csv = out.join("samples_01_01_maxwell_vgroove_steel.csv");
    let before = std::fs::read_to_string(&csv).unwrap();
    // A second run refuses, the results still on stdout, the file intact.
    let (ok, table, err) = kinrepro(&["study", &s, "--samples", "8", "--out", o]);
    assert!(!ok && err.contains("exists") && err.contains("--force"), "{err}");
    assert!(table.contains("sigma_x [nm]"));
    assert_eq!(std::fs::read_to_string(&csv).unwrap(), before);
    let (ok, _, err) = kinrepro(&["study", &s, "--samples", "8", "--out", o, "--force"]);
    assert!(ok, "{err}");
    assert_eq!(std::fs::read_to_string(&csv).unwrap().lines().count(), 2 + 8);
    // No temporary file is left behind.
    for e in std::fs::read_dir(&out).unwrap() {
        let name = e.unwrap().file_name().to_string_lossy().into_owned();
        assert!(!name.starts_with('.'), "{name}");
    }
    // --trace refuses an existing file, as --out does.
    let trace = dir.path().join("trace.csv");
    std::fs::write(&trace, "keep").unwrap();
    let t = trace.to_str().unwrap();
    let (ok, _, err) = kinrepro(&["run", &s, "--solver", "dynamic", "--trace", t]);
    assert!(!ok && err.contains("exists"), "{err}");
    assert_eq!(std::fs::read_to_string(&trace).unwrap(), "keep");
    let (ok, _, err) = kinrepro(&["run", &s, "--solver", "dynamic", "--trace", t, "--force"]);
    assert!(ok, "{err}");
    let written = std::fs::read_to_string(&trace).unwrap();
    assert!(
        written.starts_with("# kinrepro ") && written.lines().nth(1).unwrap().starts_with("time_s"),
        "{}",
        &written[..80.min(written.len())]
    );
}

#[test]
fn a_closed_pipe_exits_quietly_and_a_full_disk_is_one_error_line() {
    let s = s01();
    for format in ["table", "csv", "json"] {
        let mut child = Command::new(env!("CARGO_BIN_EXE_kinrepro"))
            .args(["study", &s, "--samples", "30", "--format", format])
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        let mut first = [0u8; 10];
        child.stdout.take().unwrap().read_exact(&mut first).unwrap();
        // The pipe is closed here (stdout dropped), as by `| head -c 10`.
        let out = child.wait_with_output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert!(out.status.success(), "{format}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    let full = std::fs::OpenOptions::new().write(true).open("/dev/full").unwrap();
    let out = Command::new(env!("CARGO_BIN_EXE_kinrepro"))
        .args(["study", &s, "--samples", "6"])
        .stdout(full)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert_eq!(err.lines().count(), 1, "{err}");
    assert!(err.contains("stdout") && err.contains("No space left"), "{err}");
}

#[test]
fn a_coupling_that_cannot_seat_fails_unless_allowed() {
    let dir = tempfile::tempdir().unwrap();
    for (name, from, to) in [
        ("mu15.toml", "mu_static = 0.5 ", "mu_static = 1.5 "),
        ("open170.toml", "opening_angle_deg = 90.0", "opening_angle_deg = 170.0"),
    ] {
        let p = scene_variant(dir.path(), name, from, to);
        let (ok, table, err) = kinrepro(&["study", &p, "--samples", "6"]);
        assert!(!ok, "{name}: rc 0");
        assert!(err.contains("cannot seat") && err.contains("--allow-unseated"), "{err}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(table.contains("CANNOT SEAT"), "{table}");
        let (ok, text, err) =
            kinrepro(&["study", &p, "--samples", "6", "--format", "json", "--allow-unseated"]);
        assert!(ok, "{err}");
        let r: StudyReport = serde_json::from_str(&text).unwrap();
        assert!(r.variants[0].cannot_seat.is_some());
        // check: the stronger, distinct message.
        let (ok, out, err) = kinrepro(&["check", &p]);
        assert!(out.contains("CANNOT SEAT"), "{out}");
        assert!(!ok && err.contains("1 of 1 scenes cannot seat"), "{err}");
    }
    // The paper's scene: above the friction limit, yet it seats from the
    // touching pose; check says what the limit means and no CANNOT SEAT.
    let (ok, out, _) = kinrepro(&["check", &s01()]);
    assert!(ok);
    assert!(out.contains("off-centre") && !out.contains("CANNOT SEAT"), "{out}");
    let (ok, _, err) = kinrepro(&["study", &s01(), "--samples", "6"]);
    assert!(ok, "{err}");
}

#[test]
fn jobs_and_increments_are_bounded() {
    let s = s01();
    let (ok, _, err) = kinrepro(&["study", &s, "--samples", "6", "--jobs", "100000"]);
    assert!(ok, "{err}");
    assert!(err.contains("--jobs 100000 capped to"), "{err}");
    for n in ["0", "4294967296"] {
        for verb in ["run", "study"] {
            let (ok, _, err) = kinrepro(&[verb, &s, "--increments", n]);
            assert!(!ok, "{verb} --increments {n}");
            assert!(err.contains("1..=100000") && err.lines().count() == 1, "{err}");
        }
    }
    let (ok, _, err) = kinrepro(&["study", &s, "--jobs", "0"]);
    assert!(!ok && err.contains("--jobs 0"), "{err}");
}

#[test]
fn phi_z_is_the_rotation_seen_by_two_points() {
    // phi_z (the clocking) from the study equals the rotation a second
    // method sees: the y motion of a point 10 mm along x from the centre,
    // minus the centre's, divided by 10 mm (small rotation).
    use kinrepro::solve::{Load, Method, PointPose};
    let (scene, c) = common::load("01_maxwell_vgroove_steel.toml");
    let m = Method::default();
    let load = Load::nominal(&scene);
    let nominal = m.seat(&c, &load.with_mu(&[0.5; 6])).unwrap();
    let s = m.seat(&c, &load.with_mu(&[0.45, 0.55, 0.5, 0.46, 0.54, 0.5])).unwrap();
    let p = scene.evaluation_points[0].position;
    let q = p + nalgebra::Vector3::new(0.01, 0.0, 0.0);
    let a = PointPose::between(&nominal.pose(), &s.pose(), &p);
    let b = PointPose::between(&nominal.pose(), &s.pose(), &q);
    let phi_z = a.components()[5];
    assert!(phi_z.abs() > 1e-9, "{phi_z}");
    let seen = (b.y_m - a.y_m) / 0.01;
    assert!((phi_z - seen).abs() < 1e-6 * phi_z.abs(), "{phi_z} vs {seen}");
}

#[test]
fn a_streamed_mc_study_equals_its_merged_shards_and_writes_its_csv() {
    // Above STREAM_ABOVE Monte Carlo samples the study keeps no records.
    let n = (kinrepro::study::stream::STREAM_ABOVE + 1).to_string();
    let dir = tempfile::tempdir().unwrap();
    let s = s01();
    let out = dir.path().join("out");
    let base = ["study", &s, "--sampler", "mc", "--samples", &n];
    let mut args = base.to_vec();
    args.extend(["--out", out.to_str().unwrap()]);
    let (ok, one, err) = kinrepro(&args);
    assert!(ok, "{err}");
    assert!(one.contains("streamed"), "{one}");
    let csv = std::fs::read_to_string(out.join("samples_01_01_maxwell_vgroove_steel.csv")).unwrap();
    assert_eq!(csv.lines().count(), 2 + n.parse::<usize>().unwrap());
    let mut parts = Vec::new();
    for i in 1..=2 {
        let shard = format!("{i}/2");
        let mut a = base.to_vec();
        a.extend(["--shard", &shard, "--format", "json"]);
        let (ok, text, err) = kinrepro(&a);
        assert!(ok, "{err}");
        let p = dir.path().join(format!("part{i}.json"));
        std::fs::write(&p, text).unwrap();
        parts.push(p);
    }
    let (ok, merged, err) = kinrepro(&[
        "merge",
        parts[0].to_str().unwrap(),
        parts[1].to_str().unwrap(),
        "--format",
        "table",
    ]);
    assert!(ok, "{err}");
    assert_eq!(merged, one, "merged shards differ from one streamed run");
}

/// A written output file gets an ordinary file's mode (what `File::create`
/// gives under the same umask), not a private temporary file's 0600.
#[cfg(unix)]
#[test]
fn output_files_have_the_mode_of_an_ordinary_file() {
    use std::os::unix::fs::PermissionsExt;
    let dir = tempfile::tempdir().unwrap();
    let plain = dir.path().join("plain.txt");
    std::fs::File::create(&plain).unwrap();
    let want = std::fs::metadata(&plain).unwrap().permissions().mode() & 0o777;
    let out = dir.path().join("out");
    let out_s = out.to_str().unwrap();
    let s = s01();
    let (ok, _, err) =
        kinrepro(&["study", &s, "--sampler", "mc", "--samples", "8", "--out", out_s]);
    assert!(ok, "{err}");
    let file = out.join("samples_01_01_maxwell_vgroove_steel.csv");
    let got = std::fs::metadata(&file).unwrap().permissions().mode() & 0o777;
    assert_eq!(got, want, "mode {got:o}, File::create gives {want:o}");
}

/// `run` reports phi_z like the other five DOFs (issue 27): its JSON lists
/// nothing as not evaluated, its table marks nothing, and the phi_z it
/// prints is the clocking a second point sees (as in the test above).
#[test]
fn run_reports_phi_z_as_evaluated() {
    let s = s01();
    let mu = "0.45,0.55,0.5,0.46,0.54,0.5";
    let (ok, out, err) = kinrepro(&["run", &s, "--mu", mu, "--json"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(v["not_evaluated"], serde_json::json!([]));
    let p = &v["pose_rel_nominal"];
    let phi_z = p["phi_z_rad"].as_f64().unwrap();
    assert!(phi_z.abs() > 1e-9, "{phi_z}");
    // The same seating seen from a point 10 mm along x: y moves by phi_z * 10 mm.
    let (scene, c) = common::load("01_maxwell_vgroove_steel.toml");
    let m = kinrepro::solve::Method::default();
    // The touching start.
    let load = kinrepro::solve::Load::nominal(&scene);
    let nominal = m.seat(&c, &load.with_mu(&[0.5; 6])).unwrap();
    let seated = m.seat(&c, &load.with_mu(&[0.45, 0.55, 0.5, 0.46, 0.54, 0.5])).unwrap();
    let q = scene.evaluation_points[0].position + nalgebra::Vector3::new(0.01, 0.0, 0.0);
    let b = kinrepro::solve::PointPose::between(&nominal.pose(), &seated.pose(), &q);
    let seen = (b.y_m - p["y_m"].as_f64().unwrap()) / 0.01;
    assert!((phi_z - seen).abs() < 1e-6 * phi_z.abs(), "{phi_z} vs {seen}");
    let (ok, table, _) = kinrepro(&["run", &s, "--mu", mu]);
    assert!(ok && !table.contains("not evaluated"), "{table}");
    assert!(table.contains("phi_z[nrad]") && !table.contains("phi_z[nrad]*"));
}

/// The verdict of a study (issue 39): its JSON `assessment` holds the
/// friction limit and safety factors `check` prints, and the text table
/// opens each variant with +-3 sigma (with 3 times sigma's interval), the
/// friction-limit line and the smallest safety factor naming what it
/// leaves out (the stage's silicon-nitride balls, as `check` says).
#[test]
fn a_study_carries_the_verdict_check_gives() {
    let stage = common::scene("example_stage_mount.toml").display().to_string();
    let (ok, out, err) = common::kinrepro(&["check", &stage]);
    assert!(ok, "{err}");
    let limit: f64 = out
        .split("friction limit for seating: mu < ")
        .nth(1)
        .and_then(|r| r.split_whitespace().next())
        .and_then(|x| x.parse().ok())
        .expect("check prints the limit");
    assert!(out.contains("leave out `silicon-nitride`"), "{out}");
    let args = ["study", &stage, "--samples", "20", "--format", "json"];
    let (ok, json, err) = common::kinrepro(&args);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&json).unwrap();
    let a = &v["variants"][0]["assessment"];
    assert!((a["friction_limit"].as_f64().unwrap() - limit).abs() < 5e-5, "{a}");
    assert_eq!(a["above_friction_limit"], false);
    let left: Vec<&str> = a["contacts"]
        .as_array()
        .unwrap()
        .iter()
        .flat_map(|c| c["left_out"].as_array().unwrap())
        .map(|l| l["material"].as_str().unwrap())
        .collect();
    assert!(left.iter().all(|m| *m == "silicon-nitride") && left.len() == 6, "{left:?}");
    let (ok, table, err) = common::kinrepro(&["study", &stage, "--samples", "20"]);
    assert!(ok, "{err}");
    let p = &v["variants"][0]["points"][0];
    let three = p["three_sigma"]["x_nm"].as_f64().unwrap();
    let hi = 3.0 * p["sigma_ci90_high"]["x_nm"].as_f64().unwrap();
    assert!(
        table.contains(&format!("+-3 sigma at centre [nm, nrad; 90 % interval]: x {three:.2} [")),
        "{table}"
    );
    assert!(table.contains(&format!(", {hi:.2}], y ")), "{table}");
    assert!(table.contains(&format!("friction limit for seating {limit:.4}")), "{table}");
    assert!(table.contains("it leaves out silicon-nitride (no allowable_pressure)"), "{table}");
}
