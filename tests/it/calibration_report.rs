//! A prediction in the HTML report (issue 15, item 4: the predicted
//! intervals in the HTML report): `kinrepro report` reads a prediction JSON,
//! applies the calibrated parameters to the scene before checking it, says
//! which calibration the numbers come from, and shows the measured sigma of
//! the calibrated design beside its prediction. The measured sigma is
//! checked against the sample standard deviation computed here from the
//! measurement CSV.

use crate::common;

/// Sample standard deviation (divisor n - 1) of column `col` of a
/// measurement CSV (comment lines `#`, one header line).
fn sample_sd(text: &str, col: usize) -> f64 {
    let v: Vec<f64> = text
        .lines()
        .filter(|l| !l.trim().is_empty() && !l.starts_with('#'))
        .skip(1)
        .map(|l| l.split(',').nth(col).unwrap().trim().parse().unwrap())
        .collect();
    let n = v.len() as f64;
    let m = v.iter().sum::<f64>() / n;
    (v.iter().map(|x| (x - m).powi(2)).sum::<f64>() / (n - 1.0)).sqrt()
}

#[test]
fn report_of_a_prediction_names_its_calibration_and_shows_the_measurement() {
    let dir = tempfile::tempdir().unwrap();
    let path = |n: &str| dir.path().join(n).display().to_string();
    let s02 = common::scene("02_maxwell_pins_steel.toml").display().to_string();
    let measured = common::worked_measurement().display().to_string();
    let measured = measured.as_str();
    let cal = path("cal.json");
    let (ok, _, e) = common::kinrepro(&[
        "calibrate",
        &s02,
        "--measured",
        measured,
        "--model-samples",
        "300",
        "--out",
        &cal,
    ]);
    assert!(ok, "{e}");
    // A copy of scene 04 beside the JSON, so that it can be changed later.
    let s04 = path("s04.toml");
    let text04 = std::fs::read_to_string(common::scene("04_maxwell_balls_steel.toml")).unwrap();
    std::fs::write(&s04, &text04).unwrap();
    let pred = path("pred.json");
    let (ok, json, e) = common::kinrepro(&[
        "predict",
        &s02,
        &s04,
        "--calibration",
        &cal,
        "--samples",
        "200",
        "--format",
        "json",
    ]);
    assert!(ok, "{e}");
    std::fs::write(&pred, &json).unwrap();
    let html = path("pred.html");
    let (ok, _, e) = common::kinrepro(&["report", &pred, "--out", &html]);
    assert!(ok, "{e}");
    let page = std::fs::read_to_string(&html).unwrap();

    // The calibration the numbers come from, with the spread's estimate
    // and interval as the calibration file has them.
    let c: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&cal).unwrap()).unwrap();
    let sp = &c["parameters"]["spread"];
    let f = |k: &str| format!("{:.5}", sp[k].as_f64().unwrap());
    assert!(page.contains("Prediction with the parameters calibrated"), "no calibration note");
    assert!(page.contains(&cal), "calibration file not named");
    assert!(
        page.contains(&format!(
            "spread = {} (90 % interval [{}, {}]",
            f("estimate"),
            f("low"),
            f("high")
        )),
        "spread and interval not shown"
    );
    // Nowhere its 16 digits (the run table's spread column too: 4 digits).
    let full = sp["estimate"].as_f64().unwrap().to_string();
    assert!(full.len() > 10 && !page.contains(&full), "{full} in the page");
    assert!(page.contains(&format!("<td>{}</td>", f("estimate"))));

    // The measured row: the sample sigma of the CSV's columns (x_nm first,
    // phi_z_nrad last), as printed (nm to 3 decimals, nrad to 2).
    let csv = std::fs::read_to_string(measured).unwrap();
    let row_start = page.find("measured (50 cycles)").expect("no measured row");
    let row = &page[row_start..row_start + page[row_start..].find("</tr>").unwrap()];
    for (col, digits) in [(0, 3), (2, 3), (5, 2)] {
        let want = format!("{:.*}", digits, sample_sd(&csv, col));
        assert!(row.contains(&want), "measured sigma {want} (column {col}) not in {row}");
    }

    // The scene of a prediction is checked with the calibrated parameters
    // applied: changing the file is still caught.
    std::fs::write(&s04, text04.replace("force = 20.0", "force = 21.0")).unwrap();
    let (ok, _, e) = common::kinrepro(&["report", &pred, "--out", &path("again.html")]);
    assert!(!ok && e.contains("scene_content") && e.trim().lines().count() == 1, "{e}");
}
