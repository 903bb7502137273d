//! The study report of every bundled scene in Chromium at 1400 x 2000 px:
//! no table wider than its box, also under the print rules at the width of
//! an A4 page; the coupling drawings' labels at least 11 px and apart; their
//! dimensions the scene file's values (read here from the TOML).

use super::*;

use crate::common::PAPER_SCENES as SCENES;
use rayon::prelude::*;

/// The dimensions a scene's drawing must show, from its `[coupling]`:
/// circle of ball centres and ball diameter [mm], opening angle [deg], and
/// how many V's show it (Maxwell: three grooves; Kelvin: one V).
pub(super) struct Dimensions {
    circle_mm: f64,
    ball_mm: f64,
    angle_deg: f64,
    vees: usize,
}

pub(super) fn dimensions(toml_text: &str) -> Dimensions {
    let v: toml::Value = toml::from_str(toml_text).unwrap();
    let c = &v["coupling"];
    let num = |k: &str| c[k].as_float().unwrap_or_else(|| panic!("coupling.{k}"));
    Dimensions {
        circle_mm: num("diameter") * 1e3,
        ball_mm: num("ball_diameter") * 1e3,
        angle_deg: num("opening_angle_deg"),
        vees: match c["arrangement"].as_str().unwrap() {
            "maxwell" => 3,
            "kelvin" => 1,
            a => panic!("arrangement {a}"),
        },
    }
}

/// `study --html` of `scene_file` (10 samples); the report's text.
fn study_html(dir: &Path, scene_file: &Path) -> String {
    let name = scene_file.file_name().unwrap().to_str().unwrap();
    let file = dir.join(format!("{name}.html"));
    let (ok, _, err) = kinrepro(&[
        "study",
        scene_file.to_str().unwrap(),
        "--samples",
        "10",
        "--html",
        file.to_str().unwrap(),
    ]);
    assert!(ok, "{name}: {err}");
    std::fs::read_to_string(&file).unwrap()
}

#[test]
fn study_html_of_every_bundled_scene_fits_and_is_dimensioned() {
    let tmp = tempfile::tempdir().unwrap();
    let exe = chromium();
    // The bundled scenes, and scene 01 with other dimensions (an opening
    // angle whose supplement differs from itself).
    let mut files: Vec<PathBuf> = SCENES.iter().map(|s| scene(s)).collect();
    let other = tmp.path().join("01_other.toml");
    let text = std::fs::read_to_string(scene(SCENES[0])).unwrap();
    let text = (text.replacen("diameter = 0.080", "diameter = 0.070", 1))
        .replacen("ball_diameter = 0.010", "ball_diameter = 0.0127", 1)
        .replacen("opening_angle_deg = 90.0", "opening_angle_deg = 100.0", 1);
    std::fs::write(&other, text).unwrap();
    files.push(other);
    // The scenes side by side (each in a folder of its own): the study and
    // the two Chromium runs of a scene are independent of the others'.
    files.par_iter().enumerate().for_each(|(i, file)| {
        let dir = tmp.path().join(i.to_string());
        std::fs::create_dir(&dir).unwrap();
        let name = file.file_name().unwrap().to_str().unwrap();
        let html = study_html(&dir, file);
        let Some(exe) = &exe else { return };
        let r = probe_result(&probe_dom(exe, &dir, &html, "1400,2000"), name);
        tables_fit(&r, &format!("{name} 1400"));
        let want = dimensions(&std::fs::read_to_string(file).unwrap());
        drawing_labels(&r, name, &want);
        // The print rules on screen, at A4's width less its margins:
        // (210 - 2 x 12) mm at 96 px per inch = 703 px.
        let print = html.replace("@media print", "@media all");
        let r = probe_result(&probe_dom(exe, &dir, &print, "703,2000"), name);
        tables_fit(&r, &format!("{name} A4 print"));
    });
}

/// Every text of every drawing at least 11 px, no two in one drawing
/// overlapping; the layout dimensions the circle of ball centres, every
/// side view its ball's diameter, `vees` side views the opening angle.
pub(super) fn drawing_labels(r: &serde_json::Value, name: &str, want: &Dimensions) {
    let texts = r["texts"].as_object().unwrap();
    assert!(texts.len() >= 7, "{name}: {} drawings", texts.len());
    let number = |t: &str, unit: &str| -> Option<f64> {
        let t = t.strip_prefix('Ø').unwrap_or(t).strip_suffix(unit)?;
        t.trim().parse().ok()
    };
    let (mut circles, mut balls, mut angles) = (0, 0, 0);
    for (id, labels) in texts {
        let labels = labels.as_array().unwrap();
        let boxes: Vec<[f64; 4]> =
            labels.iter().map(|l| [0, 1, 2, 3].map(|k| l["box"][k].as_f64().unwrap())).collect();
        for (i, l) in labels.iter().enumerate() {
            let px = l["px"].as_f64().unwrap();
            assert!(px >= 11.0, "{name} {id}: {l} at {px} px");
            let a = boxes[i];
            for (b, m) in boxes[i + 1..].iter().zip(&labels[i + 1..]) {
                let apart = a[2] <= b[0] + 0.5
                    || b[2] <= a[0] + 0.5
                    || a[3] <= b[1] + 0.5
                    || b[3] <= a[1] + 0.5;
                assert!(apart, "{name} {id}: {l} and {m} overlap");
            }
            if l["dim"] != true {
                continue;
            }
            let t = l["text"].as_str().unwrap();
            let near = |x: f64, y: f64, tol: f64| (x - y).abs() <= tol * y;
            if let Some(mm) = number(t, "mm") {
                if id.ends_with("-layout") {
                    assert!(near(mm, want.circle_mm, 5e-4), "{name} {id}: {t}");
                    circles += 1;
                } else {
                    assert!(near(mm, want.ball_mm, 5e-4), "{name} {id}: {t}");
                    assert!(id.ends_with("-side"), "{name} {id}: {t}");
                    balls += 1;
                }
            } else {
                let deg = number(t, "°").unwrap_or_else(|| panic!("{name} {id}: {t}"));
                assert!((deg - want.angle_deg).abs() <= 0.05, "{name} {id}: {t}");
                angles += 1;
            }
        }
    }
    assert_eq!((circles, balls, angles), (1, 3, want.vees), "{name}");
}
