//! Measurement files as lab spreadsheets export them: copies of the worked
//! example's docs/calibration/measured_02.csv separated by semicolons, by
//! tabs, with quoted header cells, or with a byte-order mark and CRLF line
//! ends read to the same cycles as the original and calibrate to the same
//! estimate; `--delimiter` overrides the detection, and a wrong one is an
//! error naming file, line and column.

use crate::common;

use std::path::Path;

use kinrepro::calibrate::Measurement;

/// The original file with every data and header line rewritten by `line`
/// (comment lines kept, so the `# noise:` metadata stays the same).
fn copy(original: &str, line: impl Fn(&str) -> String) -> String {
    original
        .lines()
        .map(|l| if l.starts_with('#') { l.to_string() } else { line(l) })
        .collect::<Vec<_>>()
        .join("\n")
        + "\n"
}

/// The calibrated spread of `file` (`extra` arguments added), from the CLI's JSON.
fn estimate(file: &Path, extra: &[&str]) -> f64 {
    let scene = common::scene("02_maxwell_pins_steel.toml");
    let mut args = vec![
        "calibrate",
        scene.to_str().unwrap(),
        "--measured",
        file.to_str().unwrap(),
        "--model-samples",
        "300",
        "--format",
        "json",
    ];
    args.extend_from_slice(extra);
    let (ok, out, e) = common::kinrepro(&args);
    assert!(ok, "{}: {e}", file.display());
    let j: serde_json::Value = serde_json::from_str(&out).unwrap();
    j["parameters"]["spread"]["estimate"].as_f64().unwrap()
}

#[test]
fn semicolon_and_quoted_header_copies_calibrate_to_the_original_estimate() {
    let original_path = common::worked_measurement();
    let original = std::fs::read_to_string(&original_path).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let quote_header = |l: &str| {
        if l.starts_with("x_nm") {
            l.split(',').map(|c| format!("\"{c}\"")).collect::<Vec<_>>().join(",")
        } else {
            l.to_string()
        }
    };
    let copies = [
        ("semicolon.csv", copy(&original, |l| l.replace(',', ";"))),
        ("quoted_header.csv", copy(&original, quote_header)),
        ("tab.csv", copy(&original, |l| l.replace(',', "\t"))),
        (
            "quoted_semicolon_spaced.csv",
            copy(&original, |l| match l.starts_with("x_nm") {
                true => quote_header(l).replace(',', ";"),
                false => l.replace(',', " ; "),
            }),
        ),
        ("bom_crlf.csv", format!("\u{feff}{}", original.replace('\n', "\r\n"))),
    ];
    let base = Measurement::load(&original_path, None).unwrap();
    let s0 = base.covariance().unwrap();
    let want = estimate(&original_path, &[]);
    for (name, text) in &copies {
        let path = dir.path().join(name);
        std::fs::write(&path, text).unwrap();
        // The same cycles: the same DOFs and sample covariance.
        let m = Measurement::load(&path, None).unwrap();
        assert_eq!(m.dofs, base.dofs, "{name}");
        let s = m.covariance().unwrap();
        assert!((s - &s0).abs().max() <= 1e-12 * s0.abs().max(), "{name}");
        let got = estimate(&path, &[]);
        assert!((got / want - 1.0).abs() < 1e-12, "{name}: {got} vs {want}");
    }
    // --delimiter overrides the detection: given right it agrees, given
    // wrong it is one error line naming file, line, column and the cause.
    let semi = dir.path().join("semicolon.csv");
    let got = estimate(&semi, &["--delimiter", ";"]);
    assert!((got / want - 1.0).abs() < 1e-12);
    let scene = common::scene("02_maxwell_pins_steel.toml");
    let (ok, _, e) = common::kinrepro(&[
        "calibrate",
        scene.to_str().unwrap(),
        "--measured",
        semi.to_str().unwrap(),
        "--delimiter",
        ",",
    ]);
    assert!(!ok && e.trim().lines().count() == 1, "{e}");
    assert!(
        e.contains("semicolon.csv: line 5, column 1 (x_nm;y_nm;")
            && e.contains("a file separated by `;`? see --delimiter"),
        "{e}"
    );
    let (ok, _, e) = common::kinrepro(&[
        "calibrate",
        scene.to_str().unwrap(),
        "--measured",
        semi.to_str().unwrap(),
        "--delimiter",
        "ab",
    ]);
    assert!(!ok && e.contains("--delimiter"), "{e}");
}

/// A decimal comma (a semicolon file from a German spreadsheet) is named
/// as the likely cause.
#[test]
fn decimal_comma_is_named() {
    let e =
        Measurement::parse("x_nm;y_nm\n1,5;2\n3;4\n5;6\n", "m.csv", None).unwrap_err().to_string();
    assert!(
        e.starts_with("m.csv: line 2, column 1 (x_nm): `1,5` is not a number")
            && e.contains("decimal comma"),
        "{e}"
    );
}
