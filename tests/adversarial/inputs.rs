//! Files kinrepro reads, checked like a scene (measurement summaries,
//! calibration files, reference CSV, byte-order marks), and text hygiene
//! (control characters, spreadsheet formulas, evaluation-point names):
//! issue 28 items 4-5.

use std::path::Path;

use crate::common;
use crate::verdicts::{run_in, variant, variant_of};

#[test]
fn a_measurement_summary_is_checked_like_a_scene() {
    use kinrepro::calibrate::measurement::Measurement;
    let ok = "dof,unit,sigma,cycles\nx,nm,12,50\nphi_x,nrad,80,50\n";
    let m = Measurement::parse(ok, "m.csv", None).unwrap();
    assert!((m.sigma()[0] - 12e-9).abs() < 1e-21);
    for (text, line, field) in [
        ("dof,unit,sigma,cycles\nx,nm,-3,50\n", 2, "sigma"),
        ("dof,unit,sigma,cycles\nx,nm,0,50\n", 2, "sigma"),
        // 1e10 m as a sigma: no coupling scatters by that much.
        ("dof,unit,sigma,cycles\nx,m,1e10,50\n", 2, "sigma"),
        ("dof,unit,sigma,cycles\nx,nm,12,100000000000\n", 2, "cycles"),
        ("dof,unit,sigma,cycles,extra\nx,nm,12,50,7\n", 1, "extra"),
    ] {
        let e = Measurement::parse(text, "m.csv", None).unwrap_err().to_string();
        assert!(
            e.starts_with(&format!("m.csv: line {line}, column ")) && e.contains(field),
            "{text}: {e}"
        );
    }
}

#[test]
fn a_calibration_file_is_checked_like_a_scene() {
    use kinrepro::calibrate::file::Calibration;
    let path = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/calibration/calibration_02.json");
    let text = std::fs::read_to_string(path).unwrap();
    Calibration::parse(&text, "cal.json").unwrap();
    let v: serde_json::Value = serde_json::from_str(&text).unwrap();
    let spread = v["parameters"]["spread"].clone();
    let high = spread["high"].as_f64().unwrap();
    let low = spread["low"].as_f64().unwrap();
    type Edit = Box<dyn Fn(&mut serde_json::Value)>;
    let cases: Vec<(&str, Edit)> = vec![
        ("outside", Box::new(move |v| v["parameters"]["spread"]["estimate"] = (2.0 * high).into())),
        (
            "low > high",
            Box::new(move |v| {
                v["parameters"]["spread"]["low"] = high.into();
                v["parameters"]["spread"]["high"] = low.into();
            }),
        ),
        (
            "spread 0",
            Box::new(|v| {
                v["parameters"]["spread"]["estimate"] = 0.0.into();
                v["parameters"]["spread"]["low"] = 0.0.into();
            }),
        ),
        (
            "huge region",
            Box::new(|v| {
                let p = v["region"][0].clone();
                v["region"] = serde_json::Value::Array(vec![p; 100_000]);
            }),
        ),
    ];
    for (what, edit) in cases {
        let mut w = v.clone();
        edit(&mut w);
        let e = Calibration::parse(&w.to_string(), "cal.json").unwrap_err().to_string();
        assert!(e.starts_with("cal.json: "), "{what}: {e}");
        let field = if what == "huge region" { "region" } else { "parameters.spread" };
        assert!(e.contains(field), "{what}: {e}");
    }
}

#[test]
fn a_reference_csv_refuses_duplicates_and_absurd_values_with_its_line() {
    use kinrepro::report::study::reference::parse_reference;
    let head = "label,scene,point,x_nm,y_nm,z_nm,phi_x_nrad,phi_y_nrad,phi_z_nrad\n";
    let row = "paper,01_maxwell_vgroove_steel,centre,1,2,3,4,5,\n";
    assert_eq!(parse_reference(&format!("{head}{row}"), "r.csv").unwrap().len(), 1);
    let e = parse_reference(&format!("{head}{row}{row}"), "r.csv").unwrap_err().to_string();
    assert!(e.starts_with("r.csv:3: row: ") && e.contains("twice"), "{e}");
    let big = "paper,01_maxwell_vgroove_steel,centre,1e308,2,3,4,5,\n";
    let e = parse_reference(&format!("{head}{big}"), "r.csv").unwrap_err().to_string();
    assert!(e.starts_with("r.csv:2: x_nm: "), "{e}");
}

#[test]
fn a_byte_order_mark_is_accepted_in_every_csv_kinrepro_reads() {
    use kinrepro::calibrate::measurement::Measurement;
    use kinrepro::report::study::reference::parse_reference;
    let bom = '\u{feff}';
    let m = "x_nm,y_nm\n1,2\n3,5\n4,1\n";
    assert_eq!(
        Measurement::parse(&format!("{bom}{m}"), "m.csv", None).unwrap().data,
        Measurement::parse(m, "m.csv", None).unwrap().data
    );
    let r = "label,scene,point,x_nm,y_nm,z_nm,phi_x_nrad,phi_y_nrad,phi_z_nrad\na,s,centre,1,2,3,4,5,6\n";
    assert_eq!(
        parse_reference(&format!("{bom}{r}"), "r.csv").unwrap(),
        parse_reference(r, "r.csv").unwrap()
    );
    let dir = tempfile::tempdir().unwrap();
    let h = "P_N,Qx_N,Qy_N\n10,0,0\n10,1,0\n10,2,0\n";
    let mut outs = Vec::new();
    for (name, text) in [("plain.csv", h.to_string()), ("bom.csv", format!("{bom}{h}"))] {
        std::fs::write(dir.path().join(name), text).unwrap();
        let (rc, out, err) = run_in(
            dir.path(),
            &[
                "contact",
                "--shape",
                "sphere-plane",
                "--radius1",
                "5e-3",
                "--material1",
                "steel",
                "--material2",
                "steel",
                "--mu",
                "0.5",
                "--history",
                name,
            ],
        );
        assert_eq!(rc, 0, "{name}: {err}");
        outs.push(out.replace(name, "FILE"));
    }
    assert_eq!(outs[0], outs[1]);
}

#[test]
fn names_reach_the_terminal_escaped_and_a_spreadsheet_as_text() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let p = variant(
        d,
        "evil.toml",
        &[(
            "name = \"Maxwell clamp, V-groove of planes, steel/steel\"",
            "name = \"a\\u0000b\\u0007c\\u001b[31md\\re\"\n\n[[evaluation_points]]\nname = \"=cmd|' /C calc'!A0\"\nposition = [0.0, 0.0, 0.0]\n\n[[evaluation_points]]\nname = \"@SUM(1+1)\"\nposition = [0.0, 0.0, 0.01]",
        )],
    );
    let s = p.to_str().unwrap();
    for format in ["table", "csv"] {
        let (rc, out, err) = run_in(d, &["study", s, "--samples", "4", "--format", format]);
        assert_eq!(rc, 0, "{err}");
        assert!(
            !out.chars().any(|c| c.is_control() && c != '\n'),
            "{format}: a raw control character reached stdout"
        );
        assert!(out.contains("a\\u{0}b\\u{7}c\\u{1b}[31md\\re"), "{format}: {out}");
    }
    let (_, out, _) = run_in(d, &["check", s]);
    assert!(!out.chars().any(|c| c.is_control() && c != '\n'), "{out}");
    // Every CSV cell a spreadsheet would run as a formula starts with `'`.
    let (_, csv, _) = run_in(d, &["study", s, "--samples", "4", "--format", "csv", "--out", "o"]);
    let files: Vec<String> = std::fs::read_dir(d.join("o"))
        .unwrap()
        .filter_map(|e| {
            let p = e.unwrap().path();
            (p.extension()? == "csv").then(|| std::fs::read_to_string(p).unwrap())
        })
        .chain([csv])
        .collect();
    for text in &files {
        for rec in csv::ReaderBuilder::new()
            .has_headers(false)
            .flexible(true)
            .comment(Some(b'#'))
            .from_reader(text.as_bytes())
            .records()
        {
            for cell in rec.unwrap().iter() {
                let formula =
                    cell.starts_with(['=', '+', '-', '@']) && cell.parse::<f64>().is_err();
                assert!(!formula, "unneutralised cell `{cell}`");
            }
        }
        assert!(text.contains("'=cmd") && text.contains("'@SUM"), "{text}");
    }
}

#[test]
fn evaluation_point_names_are_unique_and_not_empty() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let point = |name: &str, z: f64| {
        format!("\n[[evaluation_points]]\nname = \"{name}\"\nposition = [0.0, 0.0, {z}]\n")
    };
    for (file, points, line, reason) in [
        ("dup.toml", point("a", 0.0) + &point("a", 0.01), 7, "also the name of evaluation point 1"),
        ("empty.toml", point(" ", 0.0), 3, "empty"),
    ] {
        let base = std::fs::read_to_string(common::scene("01_maxwell_vgroove_steel.toml")).unwrap();
        let lines = base.lines().count();
        std::fs::write(d.join(file), format!("{base}{points}")).unwrap();
        let (rc, _, err) = run_in(d, &["check", file]);
        assert_eq!(rc, 1);
        let field = if file == "dup.toml" {
            "evaluation_points[2].name"
        } else {
            "evaluation_points[1].name"
        };
        let at = format!("{file}:{}: {field}: ", lines + line);
        assert!(err.contains(&at) && err.contains(reason), "{at}: {err}");
    }
}

/// `report --reference` names the rows it does not show: a scene that is
/// in no study, and a second label for a variant and point that has one.
#[test]
fn reference_rows_not_shown_are_named() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    let s = variant(d, "s01.toml", &[]);
    let (rc, json, err) =
        run_in(d, &["study", s.to_str().unwrap(), "--samples", "6", "--format", "json"]);
    assert_eq!(rc, 0, "{err}");
    std::fs::write(d.join("s.json"), json).unwrap();
    let head = "label,scene,point,x_nm,y_nm,z_nm,phi_x_nrad,phi_y_nrad,phi_z_nrad\n";
    let rows = "a,s01,centre,1,2,3,4,5,\nb,s01,centre,1,2,3,4,5,\na,s99,centre,1,2,3,4,5,\n";
    std::fs::write(d.join("r.csv"), format!("{head}{rows}")).unwrap();
    let args = ["report", "s.json", "--reference", "r.csv", "--out", "r.html"];
    let (rc, _, err) = run_in(d, &args);
    assert_eq!(rc, 0, "{err}");
    let warning = err.lines().find(|l| l.starts_with("warning: r.csv:")).expect(&err);
    assert!(warning.contains("2 reference row(s)"), "{warning}");
    assert!(warning.contains("`b` s01/centre") && warning.contains("`a` s99/centre"), "{warning}");
    assert!(!warning.contains("`a` s01/centre"), "the shown row is not listed: {warning}");
}

/// A measured covariance with a DOF that did not move (singular, 50 cycles
/// of 2 DOFs) is not testable for that reason, not for "fewer cycles"; 2
/// cycles of 2 DOFs are too few; a regular one is tested.
#[test]
fn goodness_of_fit_names_why_it_cannot_test() {
    use kinrepro::calibrate::likelihood::{Observed, goodness_of_fit};
    use nalgebra::DMatrix;
    let fitted = DMatrix::from_diagonal_element(2, 2, 1.0);
    let singular = DMatrix::from_row_slice(2, 2, &[1.0, 0.0, 0.0, 0.0]);
    let g = goodness_of_fit(&Observed::Covariance { s: singular.clone(), n: 50 }, &fitted, 1);
    assert!(g.statistic.is_none() && g.test.contains("singular"), "{}", g.test);
    assert!(!g.test.contains("fewer cycles"), "{}", g.test);
    let g = goodness_of_fit(&Observed::Covariance { s: singular, n: 2 }, &fitted, 1);
    assert!(g.test.contains("fewer cycles"), "{}", g.test);
    let regular = DMatrix::from_diagonal_element(2, 2, 1.0);
    let g = goodness_of_fit(&Observed::Covariance { s: regular, n: 50 }, &fitted, 1);
    // S = F: the statistic is zero and the fit cannot be rejected.
    assert!(g.statistic.unwrap().abs() < 1e-12 && g.ok, "{g:?}");
}

/// A cycles file with a reading of 1e10 m (a unit slip) is refused with its
/// line and column; the same file with sane readings loads.
#[test]
fn a_cycles_file_refuses_absurd_readings() {
    use kinrepro::calibrate::measurement::Measurement;
    let mut ok = String::from("x_nm,y_nm\n");
    for i in 0..10 {
        ok += &format!("{},{}\n", i as f64 * 0.7 - 3.0, 2.0 - i as f64 * 0.3);
    }
    Measurement::parse(&ok, "m.csv", None).unwrap();
    let bad = ok.replacen("-3,2\n", "1e19,2\n", 1);
    assert_ne!(bad, ok);
    let e = Measurement::parse(&bad, "m.csv", None).unwrap_err().to_string();
    assert!(e.starts_with("m.csv: line 2, column 1 (x_nm)") && e.contains("within 1 m"), "{e}");
}

/// A cycles file whose `_mm` header carries nm values (the worked
/// example's readings, 5 to 20 nm, read as millimetres) scatters by
/// millimetres: refused at the header naming the column and the unit,
/// where it used to fit the spread at the end of its range.
#[test]
fn a_cycles_column_in_the_wrong_unit_is_refused_at_its_header() {
    use kinrepro::calibrate::measurement::Measurement;
    let worked = std::fs::read_to_string(common::worked_measurement()).unwrap();
    Measurement::parse(&worked, "m.csv", None).unwrap();
    let slipped = worked.replace("x_nm,", "x_mm,");
    assert_ne!(slipped, worked);
    let e = Measurement::parse(&slipped, "m.csv", None).unwrap_err().to_string();
    assert!(e.contains("(x_mm)") && e.contains("`_mm` header"), "{e}");
}

/// `[variation]` bounds are checked against the coupling's size like its
/// other lengths (a unit slip): a length tolerance above 10 % of the
/// smallest ball radius (0.5 mm here), a preload offset beyond the circle
/// of ball centres, a tilt above 0.1 rad (surfaces) or 0.5 rad (preload)
/// is refused at its line, unless `allow_large_values`.
#[test]
fn variation_bounds_pass_the_plausibility_guard() {
    let text = std::fs::read_to_string(common::scene("tolerances_maxwell_vgroove.toml")).unwrap();
    let dir = tempfile::tempdir().unwrap();
    for (from, to, field, says) in [
        (
            "surface_normal = 5e-6 ",
            "surface_normal = 0.01 ",
            "variation.surface_normal",
            "millimetres",
        ),
        (
            "ball_position = [10e-6, 10e-6, 5e-6]",
            "ball_position = [10e-3, 0, 0]",
            "variation.ball_position",
            "millimetres",
        ),
        (
            "groove_position = [10e-6, 10e-6]",
            "groove_position = [0, 1e-3]",
            "variation.groove_position",
            "millimetres",
        ),
        (
            "preload_offset = [1.0e-3, 1.0e-3]",
            "preload_offset = [0.1, 0]",
            "variation.preload_offset",
            "circle of ball centres",
        ),
        ("surface_tilt = 1e-4 ", "surface_tilt = 2.0 ", "variation.surface_tilt", "degrees"),
        ("preload_tilt = 0.01 ", "preload_tilt = 3.0 ", "variation.preload_tilt", "degrees"),
    ] {
        assert!(text.contains(from), "{from}");
        let path = dir.path().join("v.toml");
        std::fs::write(&path, text.replace(from, to)).unwrap();
        let (ok, _, err) = common::kinrepro(&["check", path.to_str().unwrap()]);
        assert!(!ok && err.contains(field) && err.contains(says), "{to}: {err}");
        assert!(err.contains("v.toml:"), "{err}");
        let allowed = format!("allow_large_values = true\n{}", text.replace(from, to));
        std::fs::write(&path, allowed).unwrap();
        let (_, _, err) = common::kinrepro(&["check", path.to_str().unwrap()]);
        assert!(!err.contains("implausibly"), "{to}: {err}");
    }
}

/// A `[variation]` bound that passes the guard but reaches beyond what
/// the coupling carries (a preload offset of 35 mm on a 40 mm circle
/// tips the half) fails at a sample whose error names the `[variation]`
/// keys it drew within, not only "sample N".
#[test]
fn a_sample_that_fails_names_the_variation_keys_it_drew_within() {
    let dir = tempfile::tempdir().unwrap();
    let edit = ("preload_offset = [1.0e-3, 1.0e-3]", "preload_offset = [0.035, 0.035]");
    let path = variant_of("tolerances_maxwell_vgroove.toml", dir.path(), "v.toml", &[edit]);
    let args = ["study", path.to_str().unwrap(), "--vary", "friction,preload", "--samples", "20"];
    let (ok, _, err) = common::kinrepro(&args);
    assert!(!ok && err.contains("sample ") && err.contains("[variation] preload_offset"), "{err}");
}
