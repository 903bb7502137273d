//! `[friction] mu_static` and `spread` per contact (lists in contact
//! order): equal lists are the scalar scene's study, a contact without
//! spread has no Sobol index, the values and their count are checked, and
//! calibration (one spread for all contacts) refuses them.

use crate::common::{self, kinrepro};
use kinrepro::scene::Scene;

fn scene01(friction: &str) -> String {
    let text = std::fs::read_to_string(common::scene("01_maxwell_vgroove_steel.toml")).unwrap();
    let start = text.find("mu_static = ").unwrap();
    let end = start + text[start..].find("distribution").unwrap();
    format!("{}{friction}\n{}", &text[..start], &text[end..])
}

fn write(name: &str, text: &str) -> String {
    let path = std::env::temp_dir().join(format!("kinrepro_contact_friction_{name}.toml"));
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

fn study(file: &str, extra: &[&str]) -> serde_json::Value {
    let mut args = vec![
        "study",
        file,
        "--samples",
        "40",
        "--sampler",
        "mc",
        "--seed",
        "4",
        "--format",
        "json",
    ];
    args.extend(extra);
    let (ok, out, err) = kinrepro(&args);
    assert!(ok, "{err}");
    serde_json::from_str(&out).unwrap()
}

#[test]
fn lists_equal_to_the_scalar_give_the_scalar_study() {
    let scalar = write("scalar", &scene01("mu_static = 0.5\nspread = 0.05"));
    let lists = write(
        "lists",
        &scene01(
            "mu_static = [0.5, 0.5, 0.5, 0.5, 0.5, 0.5]\nspread = [0.05, 0.05, 0.05, 0.05, 0.05, 0.05]",
        ),
    );
    let (a, b) = (study(&scalar, &[]), study(&lists, &[]));
    let (va, vb) = (&a["variants"][0], &b["variants"][0]);
    assert_eq!(va["points"], vb["points"]);
    assert_eq!(va["records"], vb["records"]);
    assert_eq!(vb["contact_friction"][0], serde_json::json!([0.5, 0.05]));
    // The list study's document reads back (its records inside each
    // contact's own mu0 +- spread).
    let file = std::env::temp_dir().join("kinrepro_contact_friction_lists.json");
    std::fs::write(&file, serde_json::to_string(&b).unwrap()).unwrap();
    let (ok, _, err) = kinrepro(&["merge", file.to_str().unwrap(), "--format", "table"]);
    assert!(ok, "{err}");
}

/// Contact 4 without spread (a lubricated groove flank held at its mu0):
/// its friction input never changes, so its Sobol indices are zero, and
/// every sample gives it mu0.
#[test]
fn a_contact_without_spread_has_no_sobol_index() {
    let file = write(
        "one_fixed",
        &scene01(
            "mu_static = [0.5, 0.5, 0.5, 0.3, 0.5, 0.5]\nspread = [0.05, 0.05, 0.05, 0.0, 0.05, 0.05]",
        ),
    );
    let v = study(&file, &["--sensitivity", "--sobol-samples", "64"]);
    let variant = &v["variants"][0];
    for r in variant["records"].as_array().unwrap() {
        assert_eq!(r["inputs_si"][3], serde_json::json!(0.3));
    }
    let sobol = &variant["sensitivity"][0]["sobol"];
    for dof in sobol["dofs"].as_array().unwrap() {
        let indices = &dof["indices"];
        assert_eq!(indices["first"][3].as_f64(), Some(0.0), "{dof}");
        assert_eq!(indices["total"][3].as_f64(), Some(0.0), "{dof}");
        assert!(indices["total"][0].as_f64().unwrap() > 0.0, "{dof}");
    }
}

#[test]
fn bad_lists_are_refused_naming_the_field_and_line() {
    for (friction, field, says) in [
        ("mu_static = [0.5, 0.5]\nspread = 0.05", "friction.mu_static", "2 values for 6 contacts"),
        (
            "mu_static = 0.5\nspread = [0.05, 0.05, 0.05, 0.05, 0.05, 0.6]",
            "friction.spread",
            "(contact 6)",
        ),
        (
            "mu_static = [0.5, 0.5, 0.5, 0.5, \"dry\", 0.5]\nspread = 0.05",
            "friction.mu_static",
            "number",
        ),
    ] {
        common::refused_at_key(&scene01(friction), field, says);
    }
    let file =
        write("calibrate", &scene01("mu_static = [0.5, 0.5, 0.5, 0.5, 0.5, 0.4]\nspread = 0.05"));
    let measured = common::worked_measurement();
    let (ok, _, err) = kinrepro(&["calibrate", &file, "--measured", measured.to_str().unwrap()]);
    assert!(!ok && err.contains("per contact"), "{err}");
}

/// A table by ball gives each ball's contacts its value: the same study,
/// record for record, as the list that repeats it per contact (scene 01:
/// contacts 1-2 on ball 1, 3-4 on ball 2, 5-6 on ball 3); a table must
/// name every ball, by its number, with numbers.
#[test]
fn a_table_by_ball_is_the_list_per_contact() {
    let table = write(
        "by_ball",
        &scene01(
            "mu_static = { 1 = 0.5, 2 = 0.15, 3 = 0.5 }\nspread = { 1 = 0.05, 3 = 0.05, 2 = 0.02 }",
        ),
    );
    let list = write(
        "by_contact",
        &scene01(
            "mu_static = [0.5, 0.5, 0.15, 0.15, 0.5, 0.5]\nspread = [0.05, 0.05, 0.02, 0.02, 0.05, 0.05]",
        ),
    );
    let (a, b) = (study(&table, &[]), study(&list, &[]));
    assert_eq!(a["variants"][0]["records"], b["variants"][0]["records"]);
    assert_eq!(a["variants"][0]["contact_friction"][2], serde_json::json!([0.15, 0.02]));
    for (friction, says) in [
        ("mu_static = { 1 = 0.5, 2 = 0.15 }\nspread = 0.01", "ball 3 is missing"),
        ("mu_static = { 1 = 0.5, 2 = 0.15, 3 = 0.5, 4 = 0.5 }\nspread = 0.01", "'4' is not a ball"),
        (
            "mu_static = { 1 = 0.5, 2 = \"oil\", 3 = 0.5 }\nspread = 0.01",
            "ball 2: the value must be a number",
        ),
    ] {
        let text = scene01(friction);
        let line = text.lines().position(|l| l.starts_with("mu_static =")).unwrap() + 1;
        let err = Scene::parse(&text, "bad.toml").unwrap_err().to_string();
        assert!(
            err.starts_with(&format!("bad.toml:{line}: friction.mu_static: "))
                && err.contains(says),
            "{err}"
        );
    }
}
