//! Bad scenes get an error naming the file, the line, the field and the
//! reason — never a panic — and `kinrepro check` exits non-zero.

use std::path::Path;

use kinrepro::assembly::Coupling;
use kinrepro::scene::Scene;
use proptest::prelude::*;

fn scene_text(name: &str) -> String {
    std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name))
        .unwrap()
}

fn line_of(text: &str, needle: &str) -> usize {
    text.lines().position(|l| l.contains(needle)).unwrap_or_else(|| panic!("{needle}")) + 1
}

/// Load text as file `bad.toml`, through assembly; the error as a string.
fn load_err(text: &str) -> String {
    match Scene::parse(text, "bad.toml") {
        Err(e) => e.to_string(),
        Ok(s) => match Coupling::new(&s) {
            Err(e) => format!("bad.toml: {e}"),
            Ok(_) => panic!("scene should be rejected:\n{text}"),
        },
    }
}

#[test]
fn each_kind_of_bad_scene_is_named_with_file_line_field_and_reason() {
    let base = scene_text("01_maxwell_vgroove_steel.toml");
    let cases: Vec<(String, String, &str, &str)> = vec![
        // (text, line needle, field, reason fragment)
        (base.replace("force = 20.0", "force = = 20.0"), "force = = 20.0".into(), "", "expected"),
        (
            base.replace("[preload]", "[preload]\ncolour = 3"),
            "colour = 3".into(),
            "",
            "unknown field `colour`",
        ),
        (
            base.replace("ball_material = \"steel\"", ""),
            "[coupling]".into(),
            "",
            "missing field `ball_material`",
        ),
        (
            base.replace("groove_material = \"steel\"", "groove_material = \"unobtainium\""),
            "unobtainium".into(),
            "coupling.groove_material",
            "unknown material `unobtainium`",
        ),
        (
            base.replace("ball_diameter = 0.010", "ball_diameter = -0.010"),
            "ball_diameter".into(),
            "coupling.ball_diameter",
            "must be positive (a length in m)",
        ),
        (
            base.replace("force = 20.0", "force = 0.0"),
            "force = 0.0".into(),
            "preload.force",
            "must be positive",
        ),
        (
            base.replace("mu_static = 0.5", "mu_static = 2.5"),
            "mu_static".into(),
            "friction.mu_static",
            "outside [0, 2]",
        ),
        (
            base.replace("mu_static = 0.5", "mu_static = -0.1"),
            "mu_static".into(),
            "friction.mu_static",
            "outside [0, 2]",
        ),
        (
            base.replace("spread = 0.05", "spread = 0.6"),
            "spread = 0.6".into(),
            "friction.spread",
            "must lie in [0, mu_static",
        ),
        (
            base.replace("samples = 25", "samples = 1"),
            "samples = 1".into(),
            "study.samples",
            "at least 2",
        ),
        (
            base.replace("sampler = \"lhs\"", "sampler = \"sobol\""),
            "sobol".into(),
            "study.sampler",
            "sobol",
        ),
    ];
    for (text, needle, field, reason) in cases {
        let err = load_err(&text);
        let line = line_of(&text, &needle);
        assert!(err.starts_with(&format!("bad.toml:{line}:")), "line {line} expected: {err}");
        assert!(err.contains(field), "field {field}: {err}");
        assert!(err.contains(reason), "reason {reason}: {err}");
    }
}

#[test]
fn explicit_scene_errors() {
    let base = scene_text("custom_kelvin_explicit.toml");
    // Non-positive radius of a moving ball.
    let t = base.replacen("radius = 0.003175", "radius = 0.0", 1);
    let err = load_err(&t);
    assert!(err.contains("balls[1].radius") && err.contains("must be positive"), "{err}");
    assert!(err.starts_with(&format!("bad.toml:{}:", line_of(&t, "radius = 0.0"))), "{err}");
    // A cylinder without its radius.
    let t = base.replacen("radius = 0.0015", "", 1);
    let err = load_err(&t);
    assert!(
        err.contains("surfaces[4].radius") && err.contains("a cylinder needs `radius`"),
        "{err}"
    );
    // A ball that touches no surface: the flat now claims ball 2.
    let i = base.rfind("ball = 3").unwrap();
    let t = format!("{}ball = 2{}", &base[..i], &base[i + 8..]);
    let err = load_err(&t);
    assert!(err.contains("balls[3]") && err.contains("touches no fixed surface"), "{err}");
    // A surface that names a ball that does not exist.
    let t = format!("{}ball = 4{}", &base[..i], &base[i + 8..]);
    assert!(load_err(&t).contains("names no moving ball"));
    // A surface that does not touch its ball.
    let t = base.replace(
        "point = [0.0216506351, -0.0125, -0.003175]",
        "point = [0.0216506351, -0.0125, -0.004]",
    );
    assert_ne!(t, base);
    let err = load_err(&t);
    assert!(err.contains("contact 6") && err.contains("does not touch"), "{err}");
    // Under-constrained: drop the third plane of the trihedral seat (5 contacts).
    let starts: Vec<usize> = base.match_indices("[[surfaces]]").map(|(i, _)| i).collect();
    let t = format!("{}{}", &base[..starts[2]], &base[starts[3]..]);
    let err = load_err(&t);
    assert!(err.contains("not exactly constrained") && err.contains("5 contacts"), "{err}");
    assert!(err.contains("under-constrained") && err.contains("free"), "{err}");
    // Over-constrained: the flat twice (7 contacts).
    let t = format!("{base}\n{}", &base[starts[5]..]);
    let err = load_err(&t);
    assert!(err.contains("7 contacts") && err.contains("over-constrained"), "{err}");
}

/// Three parallel V-grooves along x: six contacts, but x is free and the
/// grooves over-constrain the rest.
#[test]
fn parallel_grooves_are_reported_as_a_free_translation() {
    let r = 0.005;
    let mut text = String::from("[preload]\nforce = 20.0\n[friction]\nmu_static = 0.5\n");
    let centres = [[0.0, 0.04, 0.0], [-0.0346, -0.02, 0.0], [0.0346, -0.02, 0.0]];
    for c in centres {
        text += &format!(
            "[[balls]]\ncentre = [{}, {}, {}]\nradius = {r}\nmaterial = \"steel\"\n",
            c[0], c[1], c[2]
        );
    }
    let s = 0.5f64.sqrt();
    for (k, c) in centres.iter().enumerate() {
        for sign in [1.0, -1.0] {
            let n = [0.0, sign * s, s];
            text += &format!(
                "[[surfaces]]\ntype = \"plane\"\nball = {}\nmaterial = \"steel\"\npoint = [{}, {}, {}]\nnormal = [{}, {}, {}]\n",
                k + 1,
                c[0] - r * n[0],
                c[1] - r * n[1],
                c[2] - r * n[2],
                n[0],
                n[1],
                n[2]
            );
        }
    }
    let err = load_err(&text);
    assert!(
        err.contains("translation along (1.000, 0.000, 0.000)")
            || err.contains("translation along (-1.000, 0.000, 0.000)"),
        "{err}"
    );
    assert!(err.contains("over-constrained"), "{err}");
}

#[test]
fn check_exits_nonzero_and_names_the_file() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let bad = dir.join("bad_scene.toml");
    std::fs::write(
        &bad,
        scene_text("01_maxwell_vgroove_steel.toml").replace("mu_static = 0.5", "mu_static = 3"),
    )
    .unwrap();
    let good = Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/01_maxwell_vgroove_steel.toml");
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_kinrepro"))
        .arg("check")
        .arg(&good)
        .arg(&bad)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(!out.status.success());
    assert!(err.contains("bad_scene.toml:") && err.contains("friction.mu_static"), "{err}");
    assert!(!err.contains("panicked"));
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_kinrepro"))
        .arg("check")
        .arg(dir.join("missing.toml"))
        .output()
        .unwrap();
    assert!(!out.status.success());
    assert!(String::from_utf8_lossy(&out.stderr).contains("cannot read the file"));
}

/// Load without panicking; the result itself does not matter.
fn try_load(text: &str) {
    if let Ok(s) = Scene::parse(text, "fuzz.toml") {
        let _ = Coupling::new(&s);
    }
}

fn toml_value() -> impl Strategy<Value = toml::Value> {
    let keys = prop::sample::select(vec![
        "name",
        "coupling",
        "arrangement",
        "diameter",
        "ball_diameter",
        "ball_material",
        "groove",
        "groove_element_diameter",
        "groove_material",
        "opening_angle_deg",
        "preload",
        "force",
        "point",
        "direction",
        "friction",
        "mu_static",
        "spread",
        "dynamic_ratio",
        "study",
        "samples",
        "seed",
        "balls",
        "centre",
        "radius",
        "material",
        "surfaces",
        "type",
        "ball",
        "normal",
        "axis_point",
        "materials",
        "youngs_modulus",
        "poisson_ratio",
        "maxwell",
        "x",
    ]);
    let leaf = prop_oneof![
        any::<bool>().prop_map(toml::Value::Boolean),
        any::<i64>().prop_map(toml::Value::Integer),
        prop_oneof![any::<f64>(), -1.0f64..1.0, Just(f64::NAN), Just(f64::INFINITY), Just(0.0)]
            .prop_map(toml::Value::Float),
        prop::sample::select(vec![
            "steel",
            "maxwell",
            "kelvin",
            "planes",
            "balls",
            "cylinders",
            "plane",
            "sphere",
            "lhs",
            ""
        ])
        .prop_map(|s| toml::Value::String(s.to_string())),
    ];
    leaf.prop_recursive(4, 64, 8, move |inner| {
        prop_oneof![
            prop::collection::vec(inner.clone(), 0..4).prop_map(toml::Value::Array),
            prop::collection::vec((keys.clone(), inner), 0..8).prop_map(|kv| {
                toml::Value::Table(kv.into_iter().map(|(k, v)| (k.to_string(), v)).collect())
            }),
        ]
    })
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]

    #[test]
    fn arbitrary_bytes_never_panic(bytes in prop::collection::vec(any::<u8>(), 0..400)) {
        try_load(&String::from_utf8_lossy(&bytes));
    }

    #[test]
    fn arbitrary_toml_values_never_panic(v in toml_value()) {
        if let Ok(text) = toml::to_string(&v) {
            try_load(&text);
        }
    }

    #[test]
    fn mutated_numbers_in_real_scenes_never_panic(
        file in prop::sample::select(vec!["01_maxwell_vgroove_steel.toml", "02_maxwell_pins_steel.toml", "06_kelvin_steel.toml", "custom_kelvin_explicit.toml"]),
        which in 0usize..40,
        value in prop_oneof![any::<f64>(), -1.0f64..1.0, Just(0.0), Just(1e300), Just(-1e-300)],
    ) {
        let text = scene_text(file);
        // Replace the which-th number-looking token on an assignment line.
        let mut count = 0;
        let out: Vec<String> = text.lines().map(|l| {
            if let Some(eq) = l.find(" = ") {
                let rhs = l[eq + 3..].split('#').next().unwrap().trim();
                if rhs.parse::<f64>().is_ok() {
                    count += 1;
                    if count == which + 1 {
                        let v = if value.is_finite() { format!("{value:e}") } else { "nan".into() };
                        return format!("{} = {v}", &l[..eq]);
                    }
                }
            }
            l.to_string()
        }).collect();
        try_load(&out.join("\n"));
    }
}

/// Issue 12, case 7: an array longer or shorter than its field needs, or with
/// an element that is not a number, is an error naming the file, the line,
/// the field and the reason; nothing is cut off (today the extra elements
/// were dropped and the scene accepted).
#[test]
fn arrays_of_the_wrong_length_or_type_are_errors() {
    let explicit = scene_text("custom_kelvin_explicit.toml");
    let tol = scene_text("tolerances_maxwell_vgroove.toml");
    let cases: Vec<(String, &str, &str, &str)> = vec![
        // (text, new line, field, reason fragment)
        (
            explicit.replacen("point = [0.0, 0.0, 0.0]", "point = [0, 0, 0, 0.01]", 1),
            "point = [0, 0, 0, 0.01]",
            "preload.point",
            "expected an array of 3 numbers [x, y, z], found 4 elements",
        ),
        (
            explicit.replacen("direction = [0.0, 0.0, -1.0]", "direction = [0, 0, 1, \"junk\"]", 1),
            "\"junk\"",
            "preload.direction",
            "found 4 elements",
        ),
        (
            explicit.replacen("direction = [0.0, 0.0, -1.0]", "direction = [0, 0, \"down\"]", 1),
            "\"down\"",
            "preload.direction",
            "element 3 (\"down\") is not a number",
        ),
        (
            explicit.replacen("centre = [0.0, 0.025, 0.0]", "centre = [0.0, 0.025]", 1),
            "centre = [0.0, 0.025]",
            "balls[1].centre",
            "found 2 elements",
        ),
        (
            explicit.replacen(
                "normal = [0.0, 0.707106781187, 0.707106781187]",
                "normal = [0.0, 0.707106781187, 0.707106781187, 0.0]",
                1,
            ),
            "0.707106781187, 0.0]",
            "surfaces[1].normal",
            "found 4 elements",
        ),
        (
            explicit.replacen(
                "position = [0.0, 0.0, 0.012]",
                "position = [0.0, 0.0, 0.012, 1.0]",
                1,
            ),
            "0.012, 1.0]",
            "evaluation_points[2].position",
            "found 4 elements",
        ),
        (
            tol.replacen(
                "preload_offset = [1.0e-3, 1.0e-3]",
                "preload_offset = [1.0e-3, 1.0e-3, 5.0]",
                1,
            ),
            "preload_offset",
            "variation.preload_offset",
            "expected an array of 2 numbers [x, y], found 3 elements",
        ),
        (
            tol.replacen(
                "ball_position = [10e-6, 10e-6, 5e-6]",
                "ball_position = [10e-6, 10e-6]",
                1,
            ),
            "ball_position",
            "variation.ball_position",
            "found 2 elements",
        ),
    ];
    for (text, needle, field, reason) in cases {
        let err = load_err(&text);
        let line = line_of(&text, needle);
        assert!(
            err.starts_with(&format!("bad.toml:{line}: {field}: ")),
            "line {line}, field {field}: {err}"
        );
        assert!(err.contains(reason), "reason {reason}: {err}");
    }
    // Integers are numbers: the same scene with integral coordinates loads.
    let t = explicit.replacen("point = [0.0, 0.0, 0.0]", "point = [0, 0, 0]", 1);
    Coupling::new(&Scene::parse(&t, "ok.toml").unwrap()).unwrap();
}

/// Issue 12, case 7: a `[[materials]]` entry that reuses a built-in name or
/// an earlier entry's name is an error unless it says `override = true`;
/// `override = true` on a name that replaces nothing is an error too. With
/// the key, the last definition is the one used.
#[test]
fn material_redefinitions_need_override() {
    let base = scene_text("01_maxwell_vgroove_steel.toml");
    let entry = |name: &str, e: &str, extra: &str| {
        format!(
            "\n[[materials]]\nname = \"{name}\"\nyoungs_modulus = {e}\npoisson_ratio = 0.3\n{extra}"
        )
    };
    let groove = |name: &str| {
        base.replace("groove_material = \"steel\"", &format!("groove_material = \"{name}\""))
    };
    // A built-in name, silently replacing steel today.
    let t = base.clone() + &entry("steel", "100e9", "");
    let err = load_err(&t);
    let line = line_of(&t, "name = \"steel\"");
    assert!(err.starts_with(&format!("bad.toml:{line}: materials[1].name: ")), "{err}");
    assert!(
        err.contains("`steel` is a built-in material") && err.contains("override = true"),
        "{err}"
    );
    // Two entries of one name: the second is named, with the first.
    let t = groove("my-steel") + &entry("my-steel", "100e9", "") + &entry("my-steel", "300e9", "");
    let err = load_err(&t);
    let second = t.rfind("name = \"my-steel\"").unwrap();
    let line = t[..second].lines().count() + 1;
    assert!(err.starts_with(&format!("bad.toml:{line}: materials[2].name: ")), "{err}");
    assert!(err.contains("already defined in materials[1]"), "{err}");
    // `override = true` on a name that replaces nothing.
    let t = groove("my-steel") + &entry("my-steel", "100e9", "override = true\n");
    let err = load_err(&t);
    let line = line_of(&t, "override = true");
    assert!(err.starts_with(&format!("bad.toml:{line}: materials[1].override: ")), "{err}");
    assert!(err.contains("nothing to override"), "{err}");

    // Intended overrides load, and the last definition is used: compare E*
    // with the closed form 1/E* = (1 - v1^2)/E1 + (1 - v2^2)/E2.
    let e_star = |e1: f64, e2: f64| 1.0 / ((1.0 - 0.09) / e1 + (1.0 - 0.09) / e2);
    let t = base.clone() + &entry("steel", "100e9", "override = true\n");
    let c = Coupling::new(&Scene::parse(&t, "ok.toml").unwrap()).unwrap();
    let got = c.contacts[0].law.hertz.e_star;
    assert!((got / e_star(100e9, 100e9) - 1.0).abs() < 1e-12, "{got}");
    let t = groove("my-steel")
        + &entry("my-steel", "100e9", "")
        + &entry("my-steel", "300e9", "override = true\n");
    let c = Coupling::new(&Scene::parse(&t, "ok.toml").unwrap()).unwrap();
    let got = c.contacts[0].law.hertz.e_star;
    assert!((got / e_star(210e9, 300e9) - 1.0).abs() < 1e-12, "{got}");
    // `override = false` is the same as leaving the key out.
    let t = base + &entry("steel", "100e9", "override = false\n");
    assert!(load_err(&t).contains("is a built-in material"));
}

/// Issue 12, case 7: magnitudes that look like millimetres in an SI file are
/// an error with the hint, naming file, line and field; the top-level key
/// `allow_large_values = true` accepts them.
#[test]
fn millimetre_looking_values_are_errors_unless_allowed() {
    let s01 = scene_text("01_maxwell_vgroove_steel.toml");
    let s02 = scene_text("02_maxwell_pins_steel.toml");
    let explicit = scene_text("custom_kelvin_explicit.toml");
    let cases: Vec<(String, &str, &str)> = vec![
        // (text, new line = field value, field)
        (s01.replace("diameter = 0.080 ", "diameter = 80 "), "diameter = 80 ", "coupling.diameter"),
        (
            s01.replace("ball_diameter = 0.010", "ball_diameter = 10"),
            "ball_diameter = 10",
            "coupling.ball_diameter",
        ),
        (
            s02.replace("groove_element_diameter = 0.004", "groove_element_diameter = 4"),
            "groove_element_diameter = 4",
            "coupling.groove_element_diameter",
        ),
        (s01.replace("force = 20.0", "force = 2.0e6"), "force = 2.0e6", "preload.force"),
        (
            explicit.replacen("radius = 0.003175", "radius = 3.175", 1),
            "radius = 3.175",
            "balls[1].radius",
        ),
        (
            explicit.replacen("centre = [0.0, 0.025, 0.0]", "centre = [0.0, 25, 0.0]", 1),
            "centre = [0.0, 25, 0.0]",
            "balls[1].centre",
        ),
        (
            explicit.replacen("radius = 0.0015", "radius = 1.5", 1),
            "radius = 1.5",
            "surfaces[4].radius",
        ),
    ];
    for (text, needle, field) in cases {
        assert_ne!(text, s01);
        let err = load_err(&text);
        let line = line_of(&text, needle);
        assert!(
            err.starts_with(&format!("bad.toml:{line}: {field}: ")),
            "line {line}, field {field}: {err}"
        );
        assert!(
            err.contains("did you give millimetres? scene files are in SI")
                && err.contains("allow_large_values = true"),
            "{err}"
        );
        // With the key, the magnitude check is off: the scene fails later
        // for its geometry, or loads, but never for looking like millimetres.
        let allowed = format!("allow_large_values = true\n{text}");
        if let Err(e) = Scene::parse(&allowed, "big.toml").map(|s| Coupling::new(&s)) {
            assert!(!e.to_string().contains("millimetres"), "{e}");
        }
    }
    // Scene 01 with both lengths in millimetres (an 80 m circle of 10 m
    // balls) is a consistent coupling: with the key it loads.
    let big = format!(
        "allow_large_values = true\n{}",
        s01.replace("diameter = 0.080 ", "diameter = 80 ")
            .replace("ball_diameter = 0.010", "ball_diameter = 10")
    );
    let c = Coupling::new(&Scene::parse(&big, "big.toml").unwrap()).unwrap();
    assert_eq!(c.contacts.len(), 6);
    // expand keeps the key, so the explicit form loads back.
    let text = Scene::expand_text(&big, "big.toml").unwrap();
    assert!(text.contains("allow_large_values = true"), "{text}");
    Scene::parse(&text, "big.toml").unwrap();
}

/// `kinrepro check` on scene 01 with `diameter = 80` (80 mm typed as metres)
/// exits non-zero with the hint (rc 0 today).
#[test]
fn check_rejects_a_millimetre_diameter_with_the_hint() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let bad = dir.join("mm_scene.toml");
    std::fs::write(
        &bad,
        scene_text("01_maxwell_vgroove_steel.toml").replace("diameter = 0.080 ", "diameter = 80 "),
    )
    .unwrap();
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_kinrepro"))
        .arg("check")
        .arg(&bad)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&out.stderr);
    assert_eq!(out.status.code(), Some(1), "{err}");
    assert!(
        err.contains("mm_scene.toml:9: coupling.diameter: 80 m is implausibly large")
            && err.contains("did you give millimetres?"),
        "{err}"
    );
    assert!(!err.contains("panicked"));
}
