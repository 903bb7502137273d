//! Concept sweeps (`kinrepro sweep` over string fields): arrangement x
//! groove of scene 01, invalid combinations reported with the scene
//! loader's reason in every format, each valid point equal to a `study`
//! of the same scene written out by hand, and a built-in material's
//! constant overridden per point exactly like a `[[materials]]` entry with
//! `override = true`.

use crate::common::{kinrepro, scene};
use serde_json::Value;

const SAMPLES: &str = "10";

fn json(text: &str) -> Value {
    serde_json::from_str(text).unwrap()
}

/// Scene 01 written out by hand with the given arrangement and groove, a
/// pin / fixed-ball diameter, and `extra` appended (e.g. `[[materials]]`).
fn scene_text(arrangement: &str, groove: &str, element: Option<f64>, extra: &str) -> String {
    let element = element.map_or(String::new(), |d| format!("groove_element_diameter = {d}\n"));
    format!(
        "name = \"Maxwell clamp, V-groove of planes, steel/steel\"\n\
         [coupling]\narrangement = \"{arrangement}\"\ndiameter = 0.080\n\
         ball_diameter = 0.010\nball_material = \"steel\"\ngroove = \"{groove}\"\n\
         {element}groove_material = \"steel\"\nopening_angle_deg = 90.0\n\
         [preload]\nforce = 20.0\n\
         [friction]\nmu_static = 0.5\nspread = 0.05\ndistribution = \"uniform\"\n\
         dynamic_ratio = 0.8\ntangential_law = \"coulomb\"\n\
         [study]\nsamples = 25\nsampler = \"lhs\"\nseed = 1\n{extra}"
    )
}

/// `kinrepro study` of a scene text (10 samples, the scene's seed): its
/// first variant's `points`.
fn study_points(text: &str) -> Value {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("scene.toml");
    std::fs::write(&path, text).unwrap();
    let (ok, out, err) =
        kinrepro(&["study", path.to_str().unwrap(), "--samples", SAMPLES, "--format", "json"]);
    assert!(ok, "{err}");
    json(&out)["variants"][0]["points"].clone()
}

/// Every sigma of two `points` arrays agrees within 1e-12 relative, point
/// by point (same names, same order).
fn assert_same_sigma(sweep: &Value, study: &Value, what: &str) {
    let (a, b) = (sweep.as_array().unwrap(), study.as_array().unwrap());
    assert_eq!(a.len(), b.len(), "{what}");
    for (p, q) in a.iter().zip(b) {
        assert_eq!(p["name"], q["name"], "{what}");
        let (s, t) = (p["sigma"].as_object().unwrap(), q["sigma"].as_object().unwrap());
        assert_eq!(s.len(), 6, "{what}");
        for (k, x) in s {
            let (x, y) = (x.as_f64().unwrap(), t[k].as_f64().unwrap());
            assert!(
                (x - y).abs() <= 1e-12 * y.abs(),
                "{what} {} {k}: sweep {x} vs study {y}",
                p["name"]
            );
        }
    }
}

fn sweep(extra: &[&str], format: &str) -> (bool, String, String) {
    let s01 = scene("01_maxwell_vgroove_steel.toml");
    let mut args = vec!["sweep", s01.to_str().unwrap()];
    args.extend_from_slice(extra);
    args.extend_from_slice(&["--samples", SAMPLES, "--format", format]);
    kinrepro(&args)
}

const CONCEPT: [&str; 4] = [
    "--set",
    "coupling.arrangement=maxwell,kelvin",
    "--set",
    "coupling.groove=planes,cylinders,balls",
];

#[test]
fn pins_and_balls_without_their_diameter_are_invalid_with_the_reason() {
    // Scene 01 gives no groove_element_diameter: planes are valid, while
    // cylinders and balls need the pin or ball diameter (docs/scenes.md).
    let (ok, out, err) = sweep(&CONCEPT, "json");
    assert!(ok, "at least one point is valid: exit 0; {err}");
    let doc = json(&out);
    let designs = doc["designs"].as_array().unwrap();
    assert_eq!(designs.len(), 6, "one design per point of the 2 x 3 grid");
    for (i, d) in designs.iter().enumerate() {
        let (arrangement, groove) =
            (["maxwell", "kelvin"][i / 3], ["planes", "cylinders", "balls"][i % 3]);
        assert_eq!(d["index"], i);
        assert_eq!(d["values"]["coupling.arrangement"], arrangement);
        assert_eq!(d["values"]["coupling.groove"], groove);
        if groove == "planes" {
            assert_eq!(d["invalid_reason"], Value::Null, "{d}");
            assert_eq!(d["status"], "ok");
            assert!(!d["points"].as_array().unwrap().is_empty());
        } else {
            let reason = d["invalid_reason"].as_str().unwrap();
            assert_eq!(
                reason,
                format!(
                    "coupling.groove_element_diameter: missing: groove = \"{groove}\" needs the pin or ball diameter"
                )
            );
            assert_eq!(d["status"], format!("invalid: {reason}"));
            assert_eq!(d["pareto"], false, "an invalid point is never on the front");
            assert!(d["points"].as_array().unwrap().is_empty());
        }
    }
    assert_eq!(doc["sets"][0]["kind"], "string");
    // The table and the CSV name the reason too.
    let (_, table, _) = sweep(&CONCEPT, "table");
    assert!(
        table.contains("invalid: coupling.groove_element_diameter: missing: groove = \"balls\""),
        "{table}"
    );
    let (_, csv, _) = sweep(&CONCEPT, "csv");
    let bad: Vec<&str> = csv.lines().filter(|l| l.contains(",kelvin,cylinders,")).collect();
    assert_eq!(bad.len(), 1, "one row for a design not evaluated: {csv}");
    assert!(bad[0].contains("\"invalid: coupling.groove_element_diameter: missing"), "{}", bad[0]);
}

#[test]
fn valid_concepts_equal_a_study_of_the_scene_written_by_hand() {
    let mut args = CONCEPT.to_vec();
    args.extend_from_slice(&["--set", "coupling.groove_element_diameter=0.006"]);
    let (ok, out, err) = sweep(&args, "json");
    assert!(ok, "{err}");
    let doc = json(&out);
    let designs = doc["designs"].as_array().unwrap();
    assert_eq!(designs.len(), 6);
    for d in designs {
        assert_eq!(d["status"], "ok", "{d}");
        let arrangement = d["values"]["coupling.arrangement"].as_str().unwrap();
        let groove = d["values"]["coupling.groove"].as_str().unwrap();
        let text = scene_text(arrangement, groove, Some(0.006), "");
        assert_same_sigma(&d["points"], &study_points(&text), &format!("{arrangement}/{groove}"));
    }
    // The concepts differ: the Kelvin clamp reports its trihedral ball too.
    assert_eq!(designs[0]["points"].as_array().unwrap().len(), 1);
    assert_eq!(designs[3]["points"].as_array().unwrap().len(), 2);
}

#[test]
fn a_built_in_material_constant_is_overridden_for_its_point() {
    // Steel's built-in constants, as `kinrepro materials` lists them.
    let (ok, out, err) = kinrepro(&["materials", "--format", "json"]);
    assert!(ok, "{err}");
    let materials = json(&out)["materials"].clone();
    let steel =
        materials.as_array().unwrap().iter().find(|m| m["name"] == "steel").unwrap().clone();
    let (e, nu, p) = (
        steel["youngs_modulus"].as_f64().unwrap(),
        steel["poisson_ratio"].as_f64().unwrap(),
        steel["allowable_pressure"].as_f64().unwrap(),
    );
    let (ok, out, err) =
        sweep(&["--set", &format!("materials.steel.youngs_modulus=1.9e11,{e}")], "json");
    assert!(ok, "{err}");
    let doc = json(&out);
    for (d, modulus) in doc["designs"].as_array().unwrap().iter().zip([1.9e11, e]) {
        let entry = format!(
            "[[materials]]\nname = \"steel\"\noverride = true\nyoungs_modulus = {modulus:e}\n\
             poisson_ratio = {nu}\nallowable_pressure = {p:e}\n"
        );
        let text = scene_text("maxwell", "planes", None, &entry);
        assert_same_sigma(&d["points"], &study_points(&text), &format!("E = {modulus}"));
    }
    // The built-in's own modulus leaves scene 01 as it is.
    let plain = study_points(&scene_text("maxwell", "planes", None, ""));
    assert_same_sigma(&doc["designs"][1]["points"], &plain, "E of the built-in");
    // A softer steel scatters more (sigma ~ E*^(-2/3)).
    let soft = doc["designs"][0]["points"][0]["sigma"]["x_nm"].as_f64().unwrap();
    assert!(soft > plain[0]["sigma"]["x_nm"].as_f64().unwrap());
}

#[test]
fn a_sweep_without_a_valid_point_lists_them_all_and_fails() {
    let dir = tempfile::tempdir().unwrap();
    let html = dir.path().join("sweep.html");
    let (ok, out, err) = sweep(
        &["--set", "coupling.groove=cylinders,balls", "--html", html.to_str().unwrap()],
        "json",
    );
    assert!(!ok, "no valid point: non-zero exit");
    assert!(err.contains("none of the 2 design points was evaluated"), "{err}");
    let doc = json(&out);
    let designs = doc["designs"].as_array().unwrap();
    assert_eq!(designs.len(), 2, "the document is still written");
    assert!(designs.iter().all(|d| d["invalid_reason"].is_string()));
    // The HTML report lists the points not evaluated with their reason.
    let page = std::fs::read_to_string(&html).unwrap();
    assert!(page.contains("<h3>Design points not evaluated</h3>"), "no list of invalid points");
    assert!(page.contains("needs the pin or ball diameter"));
}

#[test]
fn values_are_numbers_unless_they_do_not_parse_or_are_quoted() {
    // A quoted item is a name whatever it holds: "1" is then an unknown
    // material at its point, not a bad --set.
    let (ok, out, err) = sweep(&["--set", "coupling.ball_material=steel,\"1\""], "json");
    assert!(ok, "{err}");
    let doc = json(&out);
    assert_eq!(doc["designs"][1]["values"]["coupling.ball_material"], "1");
    let reason = doc["designs"][1]["invalid_reason"].as_str().unwrap();
    assert!(reason.starts_with("coupling.ball_material: unknown material `1`"), "{reason}");
    // Unquoted, it is a number: refused for a name field, naming the fix.
    let (ok, _, err) = sweep(&["--set", "coupling.groove=planes,1"], "json");
    assert!(!ok && err.contains("\"1\" is a number (quote it"), "{err}");
    // A name for a numeric field is refused as before.
    let (ok, _, err) = sweep(&["--set", "preload.force=\"20\""], "json");
    assert!(!ok && err.contains("is not a number"), "{err}");
}

/// README's concept sweep evaluates every point it shows: the canoe scene
/// carries the keys of each concept (groove pins and canoe faces).
#[test]
fn the_readme_concept_sweep_evaluates_every_point() {
    let readme =
        std::fs::read_to_string(std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("README.md"))
            .unwrap();
    let line = readme
        .lines()
        .find(|l| l.starts_with("kinrepro sweep ") && l.contains("coupling.ball_shape"))
        .expect("README shows a concept sweep");
    let mut args: Vec<&str> = line.split_whitespace().skip(1).collect();
    let scene = crate::common::scene(args[1].trim_start_matches("scenes/"));
    let scene = scene.to_str().unwrap().to_string();
    args[1] = &scene;
    args.extend(["--samples", "10", "--format", "json"]);
    let (ok, out, err) = crate::common::kinrepro(&args);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let designs = v["designs"].as_array().unwrap();
    assert_eq!(designs.len(), 4);
    for d in designs {
        assert_eq!(d["status"], "ok", "{}", d["values"]);
    }
}
