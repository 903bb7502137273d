//! Validity warnings, flags without effect, and errors that name the option, field and reason (issue 28 items 6-7).

use crate::common::{self, E_STAR_STEEL, hertz_circle, kinrepro};

const SCENE01: &str = "01_maxwell_vgroove_steel.toml";
const SCENE02: &str = "02_maxwell_pins_steel.toml";

fn s01() -> String {
    common::scene(SCENE01).display().to_string()
}

/// Run and expect a refusal: non-zero exit, one `error:` line that contains
/// every word of `names`; returns stderr.
fn refused(args: &[&str], names: &[&str]) -> String {
    let (ok, _, err) = kinrepro(args);
    assert!(!ok, "{args:?} should be refused, stderr: {err}");
    assert!(!err.contains("panicked"), "{args:?}: {err}");
    for n in names {
        assert!(err.contains(n), "{args:?}: the message should name `{n}`: {err}");
    }
    err
}

/// Scene 02 with `from` replaced by `to` in a temporary directory.
fn edited(from: &str, to: &str) -> (tempfile::TempDir, String) {
    let text = std::fs::read_to_string(common::scene(SCENE02)).unwrap();
    assert!(text.contains(from), "{from}");
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("s.toml");
    std::fs::write(&path, text.replacen(from, to, 1)).unwrap();
    (dir, path.display().to_string())
}

fn contact(extra: &[&str]) -> (bool, String, String) {
    let mut args = vec!["contact", "--material1", "steel", "--material2", "steel"];
    args.extend_from_slice(extra);
    kinrepro(&args)
}

// ---- item 6: Hertz validity ----

/// Load 1e300 N on a 5 mm ball: Hertz's contact radius a = (3 F R / 4 E*)^(1/3)
/// is far larger than the ball, so the numbers mean nothing: refused, naming --load.
#[test]
fn contact_load_far_outside_hertz_is_refused() {
    let (a, _) = hertz_circle(1e300, 0.005, E_STAR_STEEL);
    assert!(a > 0.005, "the case must have a contact wider than the ball");
    let (ok, out, err) =
        contact(&["--shape", "sphere-plane", "--radius1", "0.005", "--load", "1e300"]);
    assert!(!ok && out.is_empty(), "{out}");
    assert!(err.contains("--load 1e300") && err.contains("body radius"), "{err}");
    // The same ball at 10 N (a/R about 2 %) is valid: no warning.
    let (a, _) = hertz_circle(10.0, 0.005, E_STAR_STEEL);
    assert!(a < 0.1 * 0.005);
    let (ok, _, err) = contact(&["--shape", "sphere-plane", "--radius1", "0.005", "--load", "10"]);
    assert!(ok && !err.contains("warning"), "{err}");
}

/// A 1 nm pin under a 5 mm ball: the contact (about 0.16 mm wide at 10 N)
/// is wider than the pin: refused.
#[test]
fn contact_nanometre_pin_is_refused() {
    let (ok, _, err) = contact(&[
        "--shape",
        "sphere-cylinder",
        "--radius1",
        "0.005",
        "--radius2",
        "1e-9",
        "--load",
        "10",
    ]);
    assert!(!ok && err.contains("--load 10") && err.contains("1.0000e-9 m"), "{err}");
}

/// A conformal seat (ball 5 mm in a 5.01 mm socket): the relative radius
/// R1 R2 / (R2 - R1) = 2.505 m makes a/R_rel tiny, but a = (3 F R / 4 E*)^(1/3)
/// is over 10 % of the ball's own radius: warned, still printed.
#[test]
fn contact_conformal_seat_warns() {
    let (r1, r2) = (0.005, 0.00501);
    let (a, _) = hertz_circle(100.0, r1 * r2 / (r2 - r1), E_STAR_STEEL);
    assert!(a > 0.1 * r1 && a < r1, "a / r1 = {}", a / r1);
    let (ok, out, err) = contact(&[
        "--shape",
        "sphere-seat",
        "--radius1",
        "0.005",
        "--radius2",
        "0.00501",
        "--load",
        "100",
    ]);
    assert!(ok && out.contains("semi-axes"), "{err}");
    assert!(
        err.contains("warning: conformal contact")
            && err.contains("smallest body radius 5.0000 mm"),
        "{err}"
    );
}

#[test]
fn contact_radius_in_millimetres_gets_a_hint() {
    let (ok, _, err) = contact(&["--shape", "sphere-plane", "--radius1", "5", "--load", "10"]);
    assert!(ok, "{err}");
    assert!(err.contains("--radius1 5") && err.contains("millimetres"), "{err}");
}

#[test]
fn load_at_far_point_is_refused() {
    let s = s01();
    refused(
        &["load", &s, "--force", "0,0,-10", "--at", "1e300,0,0"],
        &["--at 1e300,0,0", "coupling's size"],
    );
}

/// A pull of 50 N along +z against the 20 N preload lifts the coupling off
/// at 20/50 = 0.4 of the load: the contacts have no normal force, so no
/// friction ratio may be printed for them.
#[test]
fn load_lift_off_prints_no_friction_ratio() {
    let s = s01();
    let (ok, out, err) = kinrepro(&["load", &s, "--force", "0,0,50", "--at", "0,0,0"]);
    assert!(ok, "{err}");
    assert!(out.contains("load factor 0.4"), "{out}");
    let rows: Vec<&str> = out.lines().filter(|l| l.ends_with("lift-off")).collect();
    assert_eq!(rows.len(), 6, "{out}");
    for r in rows {
        let cells: Vec<&str> = r.split_whitespace().collect();
        assert_eq!(&cells[4..6], &["-", "-"], "{r}");
    }
    assert!(out.contains("WARNING: 6 contact(s) lifted off"), "{out}");
    // The JSON says the same: every contact lifted off; a 1 N side load
    // at the centre lifts none.
    for (force, off) in [("0,0,50", true), ("1,0,0", false)] {
        let args = ["load", &s, "--force", force, "--at", "0,0,0", "--json"];
        let (ok, out, err) = kinrepro(&args);
        assert!(ok, "{err}");
        let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
        let flags = doc["lifted_off"].as_array().unwrap();
        assert_eq!(flags.len(), 6, "{out}");
        assert!(flags.iter().all(|f| f.as_bool() == Some(off)), "{force}: {flags:?}");
    }
}

// ---- item 6: flags without effect ----

#[test]
fn flags_without_effect_are_refused() {
    let s = s01();
    let m = common::worked_measurement().display().to_string();
    let cases: Vec<(Vec<&str>, Vec<&str>)> = vec![
        (vec!["study", &s, "--sobol-samples", "10"], vec!["--sensitivity"]),
        (vec!["study", &s, "--force"], vec!["--force", "--out"]),
        (vec!["sweep", &s, "--set", "preload.force=10,20", "--force"], vec!["--force", "--out"]),
        (
            vec!["run", &s, "--solver", "dynamic", "--increments", "5"],
            vec!["--increments 5", "dynamic"],
        ),
        (
            vec!["study", &s, "--solver", "dynamic", "--increments", "5"],
            vec!["--increments 5", "dynamic"],
        ),
        (vec!["run", &s, "--force"], vec!["--trace"]),
        (vec!["calibrate", &s, "--measured", &m, "--force"], vec!["--out"]),
        (vec!["predict", &s, "--calibration", "c.json", "--force"], vec!["--plot"]),
        (
            vec!["calibrate", &s, "--measured", &m, "--noise", "x=1nm,x=2nm"],
            vec!["--noise", "x=2nm", "twice"],
        ),
    ];
    for (args, names) in cases {
        refused(&args, &names);
    }
    let base = [
        "contact",
        "--material1",
        "steel",
        "--material2",
        "steel",
        "--shape",
        "sphere-plane",
        "--radius1",
        "0.005",
        "--load",
        "10",
    ];
    for (extra, name) in [
        (["--mu", "0.3"], "--history"),
        (["--dynamic-ratio", "0.5"], "--history"),
        (["--tangential-law", "mindlin-deresiewicz"], "--history"),
        (["--radius2", "0.003"], "--radius2 0.003"),
    ] {
        let args: Vec<&str> = base.iter().copied().chain(extra).collect();
        refused(&args, &[name]);
    }
}

// ---- item 7: errors that name the file, the field and the reason ----

#[test]
fn scene_values_in_the_wrong_unit_name_the_field() {
    let material =
        "\n[[materials]]\nname = \"mysteel\"\nyoungs_modulus = 200\npoisson_ratio = 0.3\n";
    let text = std::fs::read_to_string(common::scene(SCENE02))
        .unwrap()
        .replace("\"steel\"", "\"mysteel\"")
        + material;
    let dir = tempfile::tempdir().unwrap();
    let gpa = dir.path().join("gpa.toml");
    std::fs::write(&gpa, text).unwrap();
    let gpa = gpa.display().to_string();
    refused(&["check", &gpa], &["gpa.toml:", "materials[1].youngs_modulus", "GPa"]);
    refused(&["run", &gpa], &["materials[1].youngs_modulus", "GPa"]);
    let cases = [
        ("force = 20.0 ", "force = 1e-300 ", "preload.force"),
        (
            "groove_material = \"steel\"",
            "groove_material = \"steel\"\nsupport_compliance = 1e10",
            "coupling.support_compliance",
        ),
        ("ball_diameter = 0.010 ", "ball_diameter = 10e-9 ", "coupling.ball_diameter"),
        (
            "groove_element_diameter = 0.004 ",
            "groove_element_diameter = 4e-9 ",
            "coupling.groove_element_diameter",
        ),
    ];
    for (from, to, field) in cases {
        let (_dir, path) = edited(from, to);
        refused(&["run", &path], &["s.toml:", field, "implausibly"]);
    }
}

#[test]
fn load_path_failures_name_the_load_options() {
    let s = s01();
    refused(
        &["load", &s, "--force", "1e12,0,0", "--at", "0,0,0"],
        &[SCENE01, "--force 1e12,0,0", "of the applied load"],
    );
    let e = refused(
        &["load", &s, "--force", "0,0,0", "--at", "0,0,0", "--moment", "1e9,0,0"],
        &["--moment 1e9,0,0"],
    );
    assert!(!e.contains("of the preload"), "{e}");
}

#[test]
fn option_errors_name_the_option() {
    let s = s01();
    let e =
        refused(&["validate-hertz", "--convergence", "100", &s], &["--convergence 100", "(0, 1]"]);
    assert!(!e.contains("MeshOptions"), "{e}");
    let m = common::worked_measurement().display().to_string();
    let e = refused(
        &["calibrate", &s, "--measured", &m, "--noise", "x=nan"],
        &["--noise", "x=nan", "finite"],
    );
    assert!(!e.contains("unit"), "{e}");
}

/// A history file whose header begins with an invisible byte-order mark:
/// accepted, or refused with a message that shows the mark.
#[test]
fn history_header_bom_is_accepted_or_named() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("h.csv");
    std::fs::write(&path, "\u{feff}P_N,Qx_N,Qy_N\n1,0,0\n2,0,0\n").unwrap();
    let p = path.display().to_string();
    let (ok, _, err) =
        contact(&["--shape", "sphere-plane", "--radius1", "0.005", "--history", &p, "--mu", "0.3"]);
    assert!(ok || (err.contains("h.csv:1") && err.contains("\\u{feff}")), "{err}");
}

/// `contact --history --mu` beyond the bound every scene keeps (mu_static
/// <= 2) is refused naming the option and the bound, as zero and negative
/// values are; 2 itself is accepted.
#[test]
fn history_mu_outside_the_scenes_bound_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("h.csv");
    std::fs::write(&path, "P_N,Qx_N,Qy_N\n5,1.5,0\n").unwrap();
    let p = path.display().to_string();
    let base =
        ["contact", "--material1", "steel", "--material2", "steel", "--shape", "sphere-plane"];
    for mu in ["5", "2.0000001", "0", "-0.1"] {
        let mut args = base.to_vec();
        args.extend(["--radius1", "0.005", "--history", &p, "--mu", mu]);
        refused(&args, &[&format!("--mu {}", mu.parse::<f64>().unwrap()), "(0, 2]"]);
    }
    let (ok, _, err) =
        contact(&["--shape", "sphere-plane", "--radius1", "0.005", "--history", &p, "--mu", "2"]);
    assert!(ok, "{err}");
}

/// `--samples 0` (or 1) names the option, not the scene file.
#[test]
fn too_few_samples_name_the_option() {
    for n in ["0", "1"] {
        let err =
            refused(&["study", &s01(), "--samples", n], &[&format!("--samples {n}"), "at least 2"]);
        assert!(!err.contains("01_maxwell"), "{err}");
    }
}

/// `load`: a moment alone is a load (no --force, no --at); a force needs
/// its point, and the message says so instead of a count of values.
#[test]
fn load_takes_a_moment_alone_and_a_force_with_its_point() {
    let (ok, out, err) = kinrepro(&["load", &s01(), "--moment", "0,0,0.01"]);
    assert!(ok && out.contains("load factor"), "{err}");
    refused(&["load", &s01(), "--force", "0,0,-10"], &["--force needs --at"]);
    refused(&["load", &s01()], &["--force", "--moment"]);
}

/// A study JSON saved with a byte-order mark (as some editors do) reads
/// as the same document, as scenes and CSV files do.
#[test]
fn a_study_json_with_a_byte_order_mark_is_read() {
    let (ok, json, err) = kinrepro(&["study", &s01(), "--samples", "10", "--format", "json"]);
    assert!(ok, "{err}");
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bom.json");
    std::fs::write(&path, format!("\u{feff}{json}")).unwrap();
    let (ok, merged, err) = kinrepro(&["merge", path.to_str().unwrap()]);
    assert!(ok, "{err}");
    assert_eq!(merged, json);
}

/// A hand-edited statistic that its records contradict (sigma_x set to
/// 1e6 nm) is refused by `report` and `merge`, naming the field and the
/// value the records give; the untouched document is accepted.
#[test]
fn a_statistic_its_records_contradict_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let scene = dir.path().join("s.toml");
    std::fs::copy(common::scene(SCENE01), &scene).unwrap();
    let (ok, json, err) =
        kinrepro(&["study", scene.to_str().unwrap(), "--samples", "10", "--format", "json"]);
    assert!(ok, "{err}");
    let mut doc: serde_json::Value = serde_json::from_str(&json).unwrap();
    let true_sigma = doc["variants"][0]["points"][0]["sigma"]["x_nm"].as_f64().unwrap();
    doc["variants"][0]["points"][0]["sigma"]["x_nm"] = serde_json::json!(1e6);
    let (good, bad) = (dir.path().join("good.json"), dir.path().join("bad.json"));
    std::fs::write(&good, &json).unwrap();
    std::fs::write(&bad, doc.to_string()).unwrap();
    let html = dir.path().join("r.html").display().to_string();
    let (ok, _, err) = kinrepro(&["report", good.to_str().unwrap(), "--out", &html]);
    assert!(ok, "{err}");
    for cmd in [
        vec!["report", bad.to_str().unwrap(), "--out", &html, "--force"],
        vec!["merge", bad.to_str().unwrap()],
    ] {
        let err = refused(
            &cmd,
            &["points[0] (centre).sigma.x_nm", "1000000", "disagrees with the records"],
        );
        assert!(err.contains(&true_sigma.to_string()), "{err}");
    }
}

/// Keys accepted without effect are refused at file:line:field: a
/// sampler spelt `MC` (every keyword is exact), an empty material name, a
/// `radius` on an explicit plane; and `--angle-deg` beyond a turn.
#[test]
fn inputs_without_effect_are_refused() {
    let (_dir, path) = edited("sampler = \"lhs\"", "sampler = \"MC\"");
    refused(&["check", &path], &[":", "study.sampler", "unknown sampler 'MC'"]);
    refused(&["study", &s01(), "--sampler", "MC"], &["--sampler", "unknown sampler 'MC'"]);
    let (_dir, path) = edited(
        "[friction]",
        "[[materials]]\nname = \"\"\nyoungs_modulus = 2e11\npoisson_ratio = 0.3\n\n[friction]",
    );
    refused(&["check", &path], &["materials[1].name", "is empty"]);
    let explicit = std::fs::read_to_string(common::scene("custom_kelvin_explicit.toml")).unwrap();
    let plane = "normal = [0.0, 0.707106781187, 0.707106781187]";
    assert!(explicit.contains(plane));
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("r.toml");
    std::fs::write(&path, explicit.replacen(plane, &format!("radius = 0.002\n{plane}"), 1))
        .unwrap();
    refused(
        &["check", path.to_str().unwrap()],
        &["surfaces[1].radius", "a plane takes point, normal, not radius"],
    );
    let curv = ["--radii1", "0.005,0.005", "--radii2", "0.002,inf", "--load", "5", "--angle-deg"];
    for angle in ["1e308", "361", "nan"] {
        let mut args = vec!["contact", "--material1", "steel", "--material2", "steel"];
        args.extend(curv);
        args.push(angle);
        refused(&args, &["--angle-deg", "[-360, 360]"]);
    }
}

/// An evaluation point 12 m from the origin (12 mm meant) is refused by
/// the length guard at its line, as a preload point is; 1 m is accepted.
#[test]
fn an_evaluation_point_in_millimetres_is_refused() {
    let point = |z: &str| {
        format!("[[evaluation_points]]\nname = \"tip\"\nposition = [0.0, 0.0, {z}]\n\n[friction]")
    };
    let (_dir, path) = edited("[friction]", &point("12.0"));
    refused(&["check", &path], &["evaluation_points[1].position", "12 m", "millimetres"]);
    let (_dir, path) = edited("[friction]", &point("1.0"));
    let (ok, _, err) = kinrepro(&["check", &path]);
    assert!(ok, "{err}");
}

/// A study document whose friction distribution no scene could give (no
/// empirical values, an sd per contact short of the contacts, a
/// correlation above 1) is refused naming the field, before anything
/// describes it.
#[test]
fn a_document_with_an_impossible_distribution_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let scene = common::scene("maxwell_mixed_friction.toml");
    let args = [
        "study",
        scene.to_str().unwrap(),
        "--samples",
        "10",
        "--sampler",
        "mc",
        "--format",
        "json",
    ];
    let (ok, json, err) = kinrepro(&args);
    assert!(ok, "{err}");
    let doc: serde_json::Value = serde_json::from_str(&json).unwrap();
    let edits: [(&str, serde_json::Value, &str); 3] = [
        (
            "mu_distribution",
            serde_json::json!({"kind": "empirical", "values": []}),
            "mu_distribution.values: is empty",
        ),
        (
            "mu_distribution",
            serde_json::json!({"kind": "normal", "sd": vec![0.05; 5]}),
            "mu_distribution.sd: 5 values for the 6 contacts",
        ),
        ("mu_correlation", serde_json::json!(1.5), "mu_correlation: 1.5 must lie in [0, 1]"),
    ];
    for (key, value, says) in edits {
        let mut bad = doc.clone();
        bad["variants"][0][key] = value;
        let path = dir.path().join("bad.json");
        std::fs::write(&path, bad.to_string()).unwrap();
        refused(&["merge", path.to_str().unwrap(), "--format", "table"], &[says]);
    }
}

/// A negative number to an option that takes none names the option and
/// the value (clap's tip `-- -1` would turn it into a file name); a
/// `--samples` bound reached by the Sobol rows names `--sobol-samples`;
/// mu_static = 2 without spread is probed within [0, 2] and gets the
/// cannot-seat verdict, not an internal probe outside [0, 2].
#[test]
fn negative_numbers_sobol_bounds_and_the_probe_name_what_was_given() {
    let s01 = common::scene("01_maxwell_vgroove_steel.toml").display().to_string();
    for (args, says) in [
        (
            vec!["study", &s01, "--samples", "-1"],
            "--samples -1: --samples takes no negative number",
        ),
        (
            vec!["run", &s01, "--increments", "-5"],
            "--increments -5: --increments takes no negative number",
        ),
    ] {
        let (ok, _, err) = common::kinrepro(&args);
        assert!(!ok && err.contains(says) && !err.contains("-- -"), "{args:?}: {err}");
    }
    let args = ["study", &s01, "--sensitivity", "--sobol-samples", "2097152"];
    let (ok, _, err) = common::kinrepro(&args);
    assert!(!ok && err.contains("--sobol-samples:") && !err.contains("--samples:"), "{err}");
    let text = std::fs::read_to_string(&s01).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("mu2.toml");
    let edited = text
        .replace("mu_static = 0.5 ", "mu_static = 2.0 ")
        .replace("spread = 0.05 ", "spread = 0.0 ");
    std::fs::write(&path, edited).unwrap();
    let (ok, out, err) = common::kinrepro(&["check", path.to_str().unwrap()]);
    assert!(!ok && out.contains("CANNOT SEAT") && !err.contains("2.2"), "{out}{err}");
}
