//! The study fingerprint that `merge` compares is a hash of canonical
//! serialisations (serde_json text, FNV-1a 64), never of Rust's `Debug`
//! text: a compiler release cannot change it. Each bundled scene's
//! fingerprint is pinned here; a changed pin means shards written before
//! and after the change no longer merge, so a pin changes only with a
//! deliberate change of a scene file or of the fingerprint (raising
//! `FINGERPRINT_VERSION`). Shards written by kinrepro before the canonical
//! fingerprint (b51b948, `tests/data/shards_b51b948`) still merge with
//! each other, to the numbers of one run, and are refused beside a new
//! shard with a message naming both fingerprint versions.

use std::path::Path;

use kinrepro::study::provenance::{
    FINGERPRINT_VERSION, Fingerprint, canonical_text, content_hash, fnv1a64,
};
use kinrepro::study::{StudyOptions, StudyPlan, StudyReport};

use crate::common::{self, kinrepro};

/// Each bundled scene's `scene_content` under its own `[study]` design.
const PINNED: [(&str, &str); 17] = [
    ("01_maxwell_vgroove_steel.toml", "22a74c32637fd702"),
    ("02_maxwell_pins_steel.toml", "09a2030cf11862f9"),
    ("03_maxwell_pins_sic.toml", "2621f3b51126e9ea"),
    ("04_maxwell_balls_steel.toml", "7ae669a60dedbd69"),
    ("05_maxwell_balls_sic.toml", "ff418d5418c6cbee"),
    ("06_kelvin_steel.toml", "cad54ab6352b9604"),
    ("07_kelvin_sic.toml", "a70fd7a1fb281b0d"),
    ("custom_kelvin_explicit.toml", "c8c196d6d068b2ac"),
    ("example_stage_mount.toml", "3a783328ed0f3e22"),
    ("kelvin_magnet_wall_mount.toml", "cd11b75bbfdd6e08"),
    ("maxwell_canoe_steel.toml", "58d7618e6b6c7f90"),
    ("maxwell_crossed_pins_steel.toml", "3c6b9475e40986e1"),
    ("maxwell_flexure_grooves.toml", "e28221e225e9f9a7"),
    ("maxwell_gothic_arch_steel.toml", "48972e3adcc23cb7"),
    ("maxwell_mixed_friction.toml", "f9e2e79bdf8af2aa"),
    ("maxwell_thermal_alu_invar.toml", "f1d7dd4ed04c04b0"),
    ("tolerances_maxwell_vgroove.toml", "bd54322ea50f98b8"),
];

fn fingerprint_of_text(text: &str, file: &str) -> Fingerprint {
    let model = kinrepro::error::parse_scene(text, file).unwrap();
    let plan = StudyPlan::new(vec![model], &StudyOptions::default()).unwrap();
    let v = &plan.variants[0];
    Fingerprint::new(&v.scene, &plan.settings, &v.design)
}

fn fingerprint(name: &str) -> Fingerprint {
    let path = common::scene(name);
    let text = std::fs::read_to_string(&path).unwrap();
    fingerprint_of_text(&text, path.to_str().unwrap())
}

#[test]
fn every_bundled_scene_has_its_pinned_fingerprint() {
    let mut bundled: Vec<String> =
        std::fs::read_dir(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes"))
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .filter(|n| n.ends_with(".toml"))
            .collect();
    bundled.sort();
    let pinned: Vec<&str> = PINNED.iter().map(|(n, _)| *n).collect();
    assert_eq!(bundled, pinned, "a bundled scene without a pin, or a pin without a scene");
    for (name, hash) in PINNED {
        let f = fingerprint(name);
        assert_eq!(f.fingerprint_version, FINGERPRINT_VERSION);
        assert_eq!(f.scene_content, hash, "{name}");
    }
    // The settings are compact JSON of the typed values, not Debug text.
    let f = fingerprint("01_maxwell_vgroove_steel.toml");
    assert_eq!(
        f.solver_settings,
        r#"{"quasi-static":{"increments":20,"path_tolerance":0.00001,"max_splits":8,"max_newton":40,"tolerance":1e-10}}"#
    );
    assert_eq!(f.friction_law, r#"{"law":"switch"}"#);
    assert_eq!(f.tangential_law, "coulomb");
}

#[test]
fn the_hash_is_fnv1a_of_the_canonical_text() {
    // Hashing while serialising equals hashing the text (FNV-1a 64 has
    // its published vectors in unit_study::provenance).
    let (scene, _) = common::load("06_kelvin_steel.toml");
    let text = canonical_text(&scene);
    assert!(text.starts_with('{') && !text.contains("Vector") && !text.contains("Some("));
    assert_eq!(content_hash(&scene), format!("{:016x}", fnv1a64(text.as_bytes())));
}

#[test]
fn the_scene_content_is_the_coupling_not_the_file() {
    let path = common::scene("02_maxwell_pins_steel.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let base = fingerprint_of_text(&text, "a.toml").scene_content;
    // Another path, comments and blank lines (every line number moves):
    // the same coupling, the same hash.
    let moved = format!("# a comment\n\n\n{text}\n# another\n");
    assert_eq!(fingerprint_of_text(&moved, "elsewhere/b.toml").scene_content, base);
    // A value changed: another coupling, another hash.
    let stiffer = text.replace("mu_static = 0.5", "mu_static = 0.51");
    assert_ne!(stiffer, text);
    assert_ne!(fingerprint_of_text(&stiffer, "a.toml").scene_content, base);
}

fn shard(name: &str) -> String {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("tests/data/shards_b51b948")
        .join(name)
        .to_string_lossy()
        .into_owned()
}

/// sigma of every point of a study document.
fn sigmas(doc: &serde_json::Value) -> Vec<serde_json::Value> {
    let points = doc["variants"][0]["points"].as_array().unwrap();
    points.iter().map(|p| p["sigma"].clone()).collect()
}

#[test]
fn shards_written_before_the_canonical_fingerprint_merge_with_each_other_only() {
    // The two parts and the whole of `study scenes/01... --samples 12
    // --sampler mc --seed 5 --shard i/2 --format json`, written by b51b948.
    let (p1, p2, whole) = (shard("part1.json"), shard("part2.json"), shard("whole.json"));
    let (ok, out, err) = kinrepro(&["merge", &p1, &p2, "--format", "json"]);
    assert!(ok, "{err}");
    let merged: serde_json::Value = serde_json::from_str(&out).unwrap();
    let old: serde_json::Value =
        serde_json::from_str(&std::fs::read_to_string(&whole).unwrap()).unwrap();
    assert_eq!(sigmas(&merged), sigmas(&old));
    // The same study now: the same numbers, to 1e-12 of each sigma (the
    // Hertz law's F^(1/3) formed from its square root moved them by 2e-14
    // here, at most 4e-13 over the paper scenes).
    let s01 = common::scene("01_maxwell_vgroove_steel.toml");
    let args =
        ["study", s01.to_str().unwrap(), "--samples", "12", "--sampler", "mc", "--seed", "5"];
    let (ok, now, err) = kinrepro(&[&args[..], &["--format", "json"]].concat());
    assert!(ok, "{err}");
    let now: serde_json::Value = serde_json::from_str(&now).unwrap();
    for (new, was) in sigmas(&now).iter().zip(&sigmas(&old)) {
        let (new, was) = (new.as_object().unwrap(), was.as_object().unwrap());
        assert_eq!(new.len(), was.len());
        for (key, w) in was {
            let (n, w) = (new[key].as_f64().unwrap(), w.as_f64().unwrap());
            assert!((n - w).abs() <= 1e-12 * w.abs(), "{key}: {n} now, {w} at b51b948");
        }
    }
    let doc: StudyReport = serde_json::from_str(&out).unwrap();
    assert_eq!(doc.variants[0].fingerprint.fingerprint_version, 1);
    // A new shard 2/2 beside the old shard 1/2: refused, naming both versions.
    let dir = tempfile::tempdir().unwrap();
    let new2 = dir.path().join("new2.json");
    let (ok, part, err) = kinrepro(&[&args[..], &["--shard", "2/2", "--format", "json"]].concat());
    assert!(ok, "{err}");
    std::fs::write(&new2, part).unwrap();
    let (ok, _, err) = kinrepro(&["merge", &p1, new2.to_str().unwrap()]);
    assert!(!ok);
    assert!(err.contains("fingerprint is of version 2") && err.contains("has version 1"), "{err}");
}
