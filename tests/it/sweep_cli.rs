//! `kinrepro sweep` on the command line: the friction-limit column against
//! `check`, designs that cannot seat, bad input, and shards + merge equal
//! to the single run byte for byte.

use crate::common::{kinrepro, scene};

fn json(text: &str) -> serde_json::Value {
    serde_json::from_str(text).unwrap()
}

#[test]
fn opening_angle_sweep_agrees_with_check_and_reports_unseated_designs() {
    let s01 = scene("01_maxwell_vgroove_steel.toml");
    let (ok, out, err) = kinrepro(&[
        "sweep",
        s01.to_str().unwrap(),
        "--set",
        "coupling.opening_angle_deg=40:140:6",
        "--samples",
        "10",
        "--format",
        "json",
    ]);
    assert!(ok, "{err}");
    let doc = json(&out);
    let designs = doc["designs"].as_array().unwrap();
    assert_eq!(designs.len(), 6);
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(&s01).unwrap();
    for d in designs {
        let angle = d["values"]["coupling.opening_angle_deg"].as_f64().unwrap();
        // `check` on the same scene written by hand with this angle.
        let path = dir.path().join(format!("a{angle}.toml"));
        let edited =
            text.replace("opening_angle_deg = 90.0", &format!("opening_angle_deg = {angle:.1}"));
        assert_ne!(edited, text);
        std::fs::write(&path, edited).unwrap();
        let (ok, check, err) = kinrepro(&["check", path.to_str().unwrap()]);
        // check fails exactly where the coupling cannot seat.
        assert_eq!(ok, !check.contains("CANNOT SEAT"), "{angle}: {err}");
        let limit: f64 = check
            .split("friction limit for seating: mu < ")
            .nth(1)
            .and_then(|r| r.split_whitespace().next())
            .unwrap()
            .parse()
            .unwrap();
        let column = d["friction_limit"].as_f64().unwrap();
        assert!((column - limit).abs() <= 0.5e-4, "{angle}: {column} vs check {limit}");
        let margin = d["friction_limit_margin"].as_f64().unwrap();
        assert!((margin - (column - 0.55)).abs() < 1e-12);
        let status = d["status"].as_str().unwrap();
        let points = d["points"].as_array().unwrap();
        if angle >= 140.0 {
            // Every contact sticks from the first increment: not seating,
            // with the reason, and no sigma at all (never zero scatter).
            assert!(status.starts_with("cannot seat: "), "{status}");
            assert!(status.contains("sticks"), "{status}");
            assert!(points.is_empty());
            assert_eq!(d["pareto"], serde_json::json!(false));
            assert!(check.contains("CANNOT SEAT"), "check disagrees at {angle}");
        } else {
            assert_eq!(status, "ok", "{angle}");
            assert!(!check.contains("CANNOT SEAT"), "check disagrees at {angle}");
            for k in ["x_nm", "y_nm", "z_nm", "phi_x_nrad", "phi_y_nrad", "phi_z_nrad"] {
                assert!(points[0]["sigma"][k].as_f64().unwrap() > 0.0, "{angle} {k}");
            }
        }
    }
    // The table says it too.
    let (_, table, _) = kinrepro(&[
        "sweep",
        s01.to_str().unwrap(),
        "--set",
        "coupling.opening_angle_deg=90,140",
        "--samples",
        "10",
    ]);
    assert!(table.contains("cannot seat: with mu_s = 0.5 +- 0.05"), "{table}");
    assert!(table.contains("σx [nm]") && table.contains("σφz [nrad]"));
}

#[test]
fn shards_merge_to_the_single_run_byte_for_byte() {
    let s01 = scene("01_maxwell_vgroove_steel.toml");
    let common = [
        "sweep",
        s01.to_str().unwrap(),
        "--set",
        "preload.force=10:30:3",
        "--set",
        "friction.mu_static=0.3,0.5",
        "--samples",
        "6",
        "--sampler",
        "mc",
    ];
    let run = |extra: &[&str]| {
        let args: Vec<&str> = common.iter().chain(extra).copied().collect();
        let (ok, out, err) = kinrepro(&args);
        assert!(ok, "{err}");
        out
    };
    let single = run(&["--format", "json"]);
    let single_csv = run(&["--format", "csv"]);
    let dir = tempfile::tempdir().unwrap();
    let mut parts = Vec::new();
    for i in 1..=4 {
        let p = dir.path().join(format!("part_{i}.json"));
        let part = run(&["--format", "json", "--shard", &format!("{i}/4")]);
        assert!(json(&part)["designs"][0]["pareto"].is_null());
        std::fs::write(&p, part).unwrap();
        parts.push(p.to_str().unwrap().to_string());
    }
    let merge = |names: &[String], format: &str| {
        let mut args = vec!["merge".to_string()];
        args.extend(names.iter().cloned());
        args.extend(["--format".to_string(), format.to_string()]);
        let a: Vec<&str> = args.iter().map(String::as_str).collect();
        kinrepro(&a)
    };
    let (ok, merged, err) = merge(&parts, "json");
    assert!(ok, "{err}");
    assert_eq!(merged, single);
    let (_, merged_csv, _) = merge(&parts, "csv");
    assert_eq!(merged_csv, single_csv);
    assert!(json(&single)["designs"].as_array().unwrap().len() == 6);
    // A missing shard is named.
    let (ok, _, err) = merge(&parts[..3], "json");
    assert!(!ok && err.contains("shard 4/4"), "{err}");
    // A part of another sweep is refused, naming the field.
    let other = dir.path().join("other.json");
    let args: Vec<&str> = common
        .iter()
        .copied()
        .map(|a| if a == "6" { "8" } else { a })
        .chain(["--format", "json", "--shard", "4/4"])
        .collect();
    let (ok, out, err) = kinrepro(&args);
    assert!(ok, "{err}");
    std::fs::write(&other, out).unwrap();
    let mut mixed = parts[..3].to_vec();
    mixed.push(other.to_str().unwrap().to_string());
    let (ok, _, err) = merge(&mixed, "json");
    assert!(!ok && err.contains("samples"), "{err}");
}

#[test]
fn bad_fields_and_values_fail_with_one_line_and_bad_points_are_reported() {
    let s01 = scene("01_maxwell_vgroove_steel.toml");
    let s = s01.to_str().unwrap();
    for (set, expect) in [
        ("preload.forse=1,2", "preload.forse: not a sweepable field"),
        ("coupling.groove_material=1,2", "coupling.groove_material=1,2"),
        ("preload.force=steel", "\"steel\" is not a number"),
        ("materials.probe.youngs_modulus=1e9,2e9", "no [[materials]] entry named \"probe\""),
        ("coupling.name=1", "coupling.name: not a sweepable field"),
    ] {
        let (ok, out, err) = kinrepro(&["sweep", s, "--set", set]);
        assert!(!ok && out.is_empty(), "{set}");
        assert_eq!(err.lines().count(), 1, "{err}");
        assert!(err.starts_with("error: ") && err.contains(expect), "{err}");
    }
    // An explicit scene has no [coupling] table to sweep.
    let explicit = scene("custom_kelvin_explicit.toml");
    let (ok, _, err) =
        kinrepro(&["sweep", explicit.to_str().unwrap(), "--set", "preload.force=1,2"]);
    assert!(!ok && err.contains("high-level form"), "{err}");
    // An invalid design point is reported with its reason; the sweep goes on.
    let (ok, out, err) = kinrepro(&[
        "sweep",
        s,
        "--set",
        "friction.mu_static=-0.2,0.5",
        "--set",
        "coupling.groove_material=steel,unobtainium",
        "--samples",
        "10",
        "--format",
        "json",
    ]);
    assert!(ok, "{err}");
    let doc = json(&out);
    let status: Vec<&str> =
        doc["designs"].as_array().unwrap().iter().map(|d| d["status"].as_str().unwrap()).collect();
    assert!(status[0].starts_with("invalid: friction.mu_static"), "{status:?}");
    assert!(status[1].starts_with("invalid: ") && status[1].contains("unobtainium"), "{status:?}");
    assert_eq!(status[2], "ok");
    assert!(status[3].contains("unobtainium"));
    assert_eq!(doc["designs"][2]["pareto"], serde_json::json!(true));
    assert_eq!(doc["schema_version"], serde_json::json!(3));
    assert_eq!(doc["document"], serde_json::json!("sweep"));
}

#[test]
fn lhs_sweep_with_charts() {
    let s01 = scene("01_maxwell_vgroove_steel.toml");
    let dir = tempfile::tempdir().unwrap();
    let out = dir.path().join("charts");
    let args = [
        "sweep",
        s01.to_str().unwrap(),
        "--set",
        "preload.force=log:5:40",
        "--set",
        "coupling.groove_material=steel,silicon-carbide",
        "--design",
        "lhs",
        "--points",
        "4",
        "--samples",
        "10",
        "--format",
        "csv",
        "--out",
        out.to_str().unwrap(),
    ];
    let (ok, csv, err) = kinrepro(&args);
    assert!(ok, "{err}");
    let header = csv.lines().next().unwrap();
    assert!(header.starts_with("kinrepro_version,schema_version,solver,sampler,seed,samples,vary,design,scene,design_index,preload.force,coupling.groove_material,status,pareto,point,dof,"), "{header}");
    // 4 designs x 1 point x 6 DOFs.
    assert_eq!(csv.lines().count(), 1 + 4 * 6);
    for name in [
        "sweep_sigma_preload_force.svg",
        "sweep_sigma_coupling_groove_material.svg",
        "sweep_pareto.svg",
    ] {
        let svg = std::fs::read_to_string(out.join(name)).unwrap();
        assert!(svg.contains("<svg") && svg.contains("kinrepro 0.1.0"), "{name}");
    }
    // Existing charts are refused without --force.
    let (ok, _, err) = kinrepro(&args);
    assert!(!ok && err.contains("--force"), "{err}");
}

#[test]
fn a_design_point_equal_to_the_scene_gives_the_study_statistics() {
    // The sweep sets preload.force to the scene's own 20 N: its points must
    // be exactly those of `kinrepro study` on the unchanged file (same
    // design, same seed, the study's statistics), field for field.
    let s01 = scene("01_maxwell_vgroove_steel.toml");
    let s = s01.to_str().unwrap();
    let (ok, sweep, err) = kinrepro(&[
        "sweep",
        s,
        "--set",
        "preload.force=10,20",
        "--samples",
        "10",
        "--format",
        "json",
    ]);
    assert!(ok, "{err}");
    let (ok, study, err) = kinrepro(&["study", s, "--samples", "10", "--format", "json"]);
    assert!(ok, "{err}");
    let (sweep, study) = (json(&sweep), json(&study));
    assert_eq!(sweep["designs"][1]["points"], study["variants"][0]["points"]);
    assert_ne!(sweep["designs"][0]["points"], study["variants"][0]["points"]);
}

/// The table's header names the estimate of sigma of the sampler that ran:
/// the replicated-LHS estimate over its replicates for an LHS (the default,
/// 5 replicates of 2), the divisor n-1 for Monte Carlo.
#[test]
fn sweep_header_names_the_estimate_of_the_sampler_that_ran() {
    let s01 = scene("01_maxwell_vgroove_steel.toml");
    let head = |sampler: &str| {
        let (ok, out, err) = kinrepro(&[
            "sweep",
            s01.to_str().unwrap(),
            "--set",
            "preload.force=10,20",
            "--samples",
            "10",
            "--sampler",
            sampler,
        ]);
        assert!(ok, "{err}");
        out.lines().nth(1).unwrap().to_string()
    };
    let lhs = head("lhs");
    assert!(
        lhs.contains("(replicated LHS: the unbiased estimate over its 5 replicates")
            && !lhs.contains("divisor n-1"),
        "{lhs}"
    );
    let mc = head("mc");
    assert!(mc.contains("(Monte Carlo: divisor n-1)") && !mc.contains("replicated LHS"), "{mc}");
}
