//! Bundled scenes: load, expand and load back to the same scene (1e-12); exactly
//! constrained; contact normals at the angles of docs/model.md ("Axes and contact numbering"); balls touch
//! at zero gap (the geometry itself: tests/it/geometry.rs).

use crate::common;

use std::path::{Path, PathBuf};

use kinrepro::assembly::{BodyPose, Coupling, constraint};
use kinrepro::scene::{Scene, SurfaceGeometry};
use nalgebra::Vector3;

use crate::common::PAPER_SCENES;

fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name)
}

fn all_scenes() -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = PAPER_SCENES.iter().map(|n| scene_path(n)).collect();
    v.push(scene_path("custom_kelvin_explicit.toml"));
    v
}

/// Scenes compare equal apart from source lines (which differ between the
/// high-level file and its expansion).
fn strip_lines(mut s: Scene) -> Scene {
    s.balls.iter_mut().for_each(|b| b.line = None);
    s.surfaces.iter_mut().for_each(|b| b.line = None);
    s
}

#[test]
fn every_scene_loads_expands_and_loads_back_identically() {
    for path in all_scenes() {
        let file = path.display().to_string();
        let source = std::fs::read_to_string(&path).unwrap();
        let scene = Scene::parse(&source, &file).unwrap();
        let text = Scene::expand_text(&source, &file).unwrap();
        let back = Scene::parse(&text, &file).unwrap();
        // expand writes rounding noise (cos 90 deg) as 0 and 15 digits.
        common::assert_close_debug(&strip_lines(scene.clone()), &strip_lines(back), &file);
        // Expanding the explicit form again is a fixed point.
        assert_eq!(Scene::expand_text(&text, &file).unwrap(), text);
        let c = Coupling::new(&scene).unwrap();
        let report = constraint::analyse(&c);
        assert!(report.exactly_constrained, "{file}: {}", report.describe());
        assert!(report.condition_number < 10.0);
    }
}

#[test]
fn balls_touch_every_surface_at_zero_gap() {
    for path in all_scenes() {
        let (_, c) = kinrepro::error::read_scene(&path).unwrap();
        for i in 0..6 {
            let g = c.geometry(i, &c.touching_pose);
            assert!(g.gap.abs() < 1e-15, "{path:?} contact {}: gap {:e}", i + 1, g.gap);
        }
    }
}

#[test]
fn contact_normals_follow_the_conventions() {
    let alpha = 45f64.to_radians();
    let ez = Vector3::z();
    for name in PAPER_SCENES {
        let (_, c) = kinrepro::error::read_scene(&scene_path(name)).unwrap();
        let centre = |k: usize| c.balls[k].centre;
        // Ball azimuths 90, 210, 330 degrees on the 80 mm circle.
        for (k, az) in [90.0f64, 210.0, 330.0].iter().enumerate() {
            let t = az.to_radians();
            let expect = Vector3::new(t.cos(), t.sin(), 0.0) * 0.040;
            assert!((centre(k) - expect).norm() < 1e-17);
        }
        let n = |i: usize| c.geometry(i, &BodyPose::identity()).normal;
        let kelvin = name.contains("kelvin");
        let vees: Vec<(usize, usize, Vector3<f64>)> = if kelvin {
            // Ball 2's V points at ball 1: contacts 4, 5 with e_r -> unit(c1 - c2).
            vec![(3, 1, (centre(0) - centre(1)).normalize())]
        } else {
            (0..3).map(|k| (2 * k, k, centre(k).normalize())).collect()
        };
        for (first, _ball, er) in vees {
            let s = ez.cross(&er);
            let n1 = s * alpha.sin() + ez * alpha.cos();
            let n2 = -s * alpha.sin() + ez * alpha.cos();
            assert!((n(first) - n1).norm() < 1e-15, "{name}: contact {}", first + 1);
            assert!((n(first + 1) - n2).norm() < 1e-15, "{name}: contact {}", first + 2);
        }
        if kelvin {
            // Trihedral seat: first element radially inward, then +120, +240 deg
            // counter-clockwise; each normal 45 deg from z, pointing from the element
            // into the ball.
            let er = centre(0).normalize();
            for j in 0..3 {
                let a = (120.0 * j as f64).to_radians();
                let d = Vector3::new(
                    -er.x * a.cos() + er.y * a.sin(),
                    -er.x * a.sin() - er.y * a.cos(),
                    0.0,
                );
                let expect = -d * alpha.sin() + ez * alpha.cos();
                assert!((n(j) - expect).norm() < 1e-15, "{name}: trihedral contact {}", j + 1);
            }
            assert!((n(5) - ez).norm() < 1e-15);
        }
        for i in 0..6 {
            let angle = n(i).dot(&ez).acos();
            let expect = if kelvin && i == 5 { 0.0 } else { alpha };
            assert!((angle - expect).abs() < 1e-12, "{name} contact {}", i + 1);
        }
    }
}

#[test]
fn a_pin_is_the_same_wherever_its_axis_point_lies_on_its_axis() {
    // A pin is the cylinder about a line: moving each pin's axis_point along
    // the line by +-30 mm (beyond the 28 mm that the pin's shape reaches
    // either way from where the assembly centres it) changes nothing but
    // rounding: the same touching pose, and the same seating for two
    // friction vectors to 1e-9 of its motion. (Before the shape was centred
    // at the ball's foot on the axis, such a scene was refused: "the ball
    // does not touch its surface".)
    use kinrepro::solve::quasistatic::seat;
    use kinrepro::solve::{Load, SolverOptions};
    let opts = SolverOptions::default();
    for name in ["02_maxwell_pins_steel.toml", "03_maxwell_pins_sic.toml"] {
        let path = scene_path(name);
        let source = std::fs::read_to_string(&path).unwrap();
        let scene = Scene::parse(&source, &path.display().to_string()).unwrap();
        let base = Coupling::new(&scene).unwrap();
        for shift in [0.03, -0.03] {
            let mut moved = scene.clone();
            for s in &mut moved.surfaces {
                if let SurfaceGeometry::Cylinder { axis_point, direction, .. } = &mut s.geometry {
                    *axis_point += *direction * shift;
                }
            }
            let c = Coupling::new(&moved).unwrap_or_else(|e| panic!("{name} {shift}: {e}"));
            for mu in [[0.46, 0.53, 0.51, 0.47, 0.545, 0.455], [0.5; 6]] {
                let (la, lb) =
                    (Load::nominal(&scene).with_mu(&mu), Load::nominal(&moved).with_mu(&mu));
                let (a, b) =
                    (seat(&base, &la, &opts).unwrap().pose(), seat(&c, &lb, &opts).unwrap().pose());
                let motion = a.translation.norm();
                let dt = (a.translation - b.translation).norm();
                let dr = a.rotation.angle_to(&b.rotation) * base.length_scale();
                assert!(dt.max(dr) < 1e-9 * motion, "{name} {shift}: {dt:e} {dr:e} of {motion:e}");
            }
        }
    }
}

#[test]
fn friction_limit_is_scale_free_and_grows_with_groove_steepness() {
    let base = std::fs::read_to_string(scene_path("01_maxwell_vgroove_steel.toml")).unwrap();
    let limit = |src: &str| {
        let s = Scene::parse(src, "t.toml").unwrap();
        kinrepro::assembly::friction_limit::friction_limit(&Coupling::new(&s).unwrap(), &s.preload)
            .mu_limit
    };
    let l0 = limit(&base);
    // Scale-free: preload and size do not change a friction coefficient.
    let scaled = base
        .replace("force = 20.0", "force = 500.0")
        .replace("diameter = 0.080", "diameter = 0.300")
        .replace("ball_diameter = 0.010", "ball_diameter = 0.0375");
    assert!((limit(&scaled) - l0).abs() < 2e-4, "{} vs {l0}", limit(&scaled));
    // Steeper flanks (smaller opening angle) centre better.
    let steep = base.replace("opening_angle_deg = 90.0", "opening_angle_deg = 70.0");
    let flat = base.replace("opening_angle_deg = 90.0", "opening_angle_deg = 120.0");
    assert!(limit(&steep) > l0 && l0 > limit(&flat));
    assert!(l0 > 0.0 && l0 < 1.0);
}

/// Rank by singular values (a second method: the analysis decomposes A^T A).
fn svd_rank(a: &nalgebra::DMatrix<f64>) -> usize {
    let s = a.clone().svd(false, false).singular_values;
    let smax = s.max();
    s.iter().filter(|&&x| x > 1e-6 * smax).count()
}

/// The redundancy analysis against brute force: the number of redundant
/// constraints is m - rank (rank-nullity), and contact i takes part in a
/// self-stress exactly when removing its row leaves the rank unchanged.
#[test]
fn redundant_contacts_match_brute_force_rank_tests() {
    let (_, c01) =
        kinrepro::error::read_scene(&scene_path("01_maxwell_vgroove_steel.toml")).unwrap();
    let (_, c06) = kinrepro::error::read_scene(&scene_path("06_kelvin_steel.toml")).unwrap();
    let with = |base: &Coupling, extra: &[(usize, usize)]| {
        // (copy of contact, assigned to ball: the ball's sphere is its
        // moving surface)
        let mut c = base.clone();
        for &(k, ball) in extra {
            let mut e = c.contacts[k].clone();
            e.ball = ball;
            e.centre = c.balls[ball].centre;
            e.radius = c.balls[ball].radius;
            c.contacts.push(e);
        }
        c
    };
    let cases = [
        (with(&c01, &[(0, 0)]), vec![1, 7]),
        (with(&c01, &[(0, 0), (3, 1)]), vec![1, 4, 7, 8]),
        // A fourth surface on the trihedral ball: its normal passes through
        // the ball centre like the other three, so all four fight.
        (with(&c06, &[(3, 0)]), vec![1, 2, 3, 7]),
        (with(&c06, &[(5, 2), (0, 0), (1, 0)]), vec![1, 2, 6, 7, 8, 9]),
    ];
    for (c, expect) in cases {
        let a = constraint::constraint_matrix(&c);
        let m = a.nrows();
        let rank = svd_rank(&a);
        let brute: Vec<usize> =
            (0..m).filter(|&i| svd_rank(&a.clone().remove_row(i)) == rank).map(|i| i + 1).collect();
        assert_eq!(brute, expect, "brute force");
        let r = constraint::analyse(&c);
        assert_eq!(r.rank, rank);
        assert_eq!(r.redundant_constraints, m - rank);
        assert_eq!(r.redundant_contacts, brute);
        assert!(!r.exactly_constrained);
        assert!(r.describe().contains("over-constrained"), "{}", r.describe());
    }
}

/// Issue 12, case 8: the analysis of many surfaces is one compact sentence
/// (today: one sentence per self-stress state, each listing every contact,
/// so the text and the m x m eigen-decomposition behind it grow as m^2 and
/// m^3; 3000 surfaces took 24 s). Timing is in benches/check.rs.
#[test]
fn a_thousand_surfaces_are_described_in_one_sentence() {
    let (_, c01) =
        kinrepro::error::read_scene(&scene_path("01_maxwell_vgroove_steel.toml")).unwrap();
    let mut c = c01.clone();
    for _ in 0..994 {
        c.contacts.push(c01.contacts[0].clone());
    }
    let r = constraint::analyse(&c);
    assert_eq!((r.contacts, r.rank, r.redundant_constraints), (1000, 6, 994));
    let mut expect = vec![1];
    expect.extend(7..=1000);
    assert_eq!(r.redundant_contacts, expect);
    let text = r.describe();
    assert_eq!(
        text,
        "1000 contacts, rank 6; over-constrained, 994 redundant constraints: contacts 1, 7-1000 \
         fight each other"
    );
}

/// Line numbers stay exact deep in a large file (they are found by binary
/// search over the line starts).
#[test]
fn errors_deep_in_a_large_scene_name_the_right_line() {
    let text = kinrepro::scene::Scene::expand_text(
        &std::fs::read_to_string(scene_path("01_maxwell_vgroove_steel.toml")).unwrap(),
        "01.toml",
    )
    .unwrap();
    let i = text.find("[[surfaces]]").unwrap();
    let j = text[i + 1..].find("[[surfaces]]").unwrap() + i + 1;
    let mut big = text.clone();
    for _ in 0..2000 {
        big.push_str(&text[i..j]);
    }
    big.push_str(&text[i..j].replace("ball = 1", "ball = 9"));
    let err = Scene::parse(&big, "big.toml").unwrap_err().to_string();
    let line = big.lines().position(|l| l == "ball = 9").unwrap() + 1;
    assert!(
        err.starts_with(&format!("big.toml:{line}: surfaces[2007].ball: 9 names no moving ball")),
        "{err}"
    );
}

/// Scene 01 with grooves of a user material `zerodur` (Schott: E 90.3 GPa,
/// v 0.243) that replaces the built-in one, with or without an allowable
/// pressure.
fn zerodur_scene(allowable: &str) -> String {
    std::fs::read_to_string(scene_path("01_maxwell_vgroove_steel.toml"))
        .unwrap()
        .replace("groove_material = \"steel\"", "groove_material = \"zerodur\"")
        + &format!(
            "\n[[materials]]\nname = \"zerodur\"\noverride = true\nyoungs_modulus = 90.3e9\npoisson_ratio = 0.243\n{allowable}"
        )
}

/// Issue 12, case 7: a zerodur flat without `allowable_pressure` showed
/// SF 7.62 from steel alone, silently. The factor is still steel's (checked
/// against Johnson's p0 = (6 F E*^2 / (pi^3 R^2))^(1/3), eq. 4.24), and it
/// now names the material it leaves out; with an allowable for zerodur it
/// covers both bodies and names none.
#[test]
fn a_safety_factor_names_the_material_it_leaves_out() {
    use kinrepro::contact::stress::LeftOut;
    use kinrepro::solve::quasistatic::seat;
    use kinrepro::solve::{Load, SolverOptions};
    let e_star = 1.0 / ((1.0 - 0.09) / 210e9 + (1.0 - 0.243f64.powi(2)) / 90.3e9);
    let p0 = |f: f64| {
        (6.0 * f * e_star * e_star / (std::f64::consts::PI.powi(3) * 0.005f64.powi(2))).cbrt()
    };
    let scene = Scene::parse(&zerodur_scene(""), "z.toml").unwrap();
    let c = Coupling::new(&scene).unwrap();
    let load = Load::nominal(&scene).with_mu(&[0.5; 6]);
    let s = seat(&c, &load, &SolverOptions::default()).unwrap();
    for r in &s.contacts {
        let sf = 4.2e9 / p0(r.normal_force_n);
        assert!((r.pressure_safety_factor.unwrap() / sf - 1.0).abs() < 1e-9);
        assert_eq!(
            r.safety_factor_left_out,
            vec![LeftOut { material: "zerodur".into(), missing: "allowable_pressure" }]
        );
    }
    // With zerodur's own allowable (below steel's) the factor is zerodur's.
    let scene = Scene::parse(&zerodur_scene("allowable_pressure = 0.5e9\n"), "z.toml").unwrap();
    let c = Coupling::new(&scene).unwrap();
    let load = Load::nominal(&scene).with_mu(&[0.5; 6]);
    let s = seat(&c, &load, &SolverOptions::default()).unwrap();
    for r in &s.contacts {
        let sf = 0.5e9 / p0(r.normal_force_n);
        assert!((r.safety_factor.unwrap() / sf - 1.0).abs() < 1e-9);
        assert!(r.safety_factor_left_out.is_empty());
    }
    // Steel on steel: nothing is left out; ceramics grooves (scene 05,
    // silicon-carbide balls without an allowable) are.
    let (scene, c) =
        kinrepro::error::read_scene(&scene_path("01_maxwell_vgroove_steel.toml")).unwrap();
    let load = Load::nominal(&scene).with_mu(&[0.5; 6]);
    let s = seat(&c, &load, &SolverOptions::default()).unwrap();
    assert!(s.contacts.iter().all(|r| r.safety_factor_left_out.is_empty()));
    let (scene, c) = kinrepro::error::read_scene(&scene_path("05_maxwell_balls_sic.toml")).unwrap();
    let load = Load::nominal(&scene).with_mu(&[0.6; 6]);
    let s = seat(&c, &load, &SolverOptions::default()).unwrap();
    for r in &s.contacts {
        assert_eq!(r.safety_factor_left_out.len(), 1);
        assert_eq!(r.safety_factor_left_out[0].material, "silicon-carbide");
    }
}

/// `run` (table and JSON) and `check` say which material the safety factor
/// leaves out.
#[test]
fn run_and_check_print_the_left_out_material() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let path = dir.join("zerodur.toml");
    std::fs::write(&path, zerodur_scene("")).unwrap();
    let cli = |args: &[&str]| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_kinrepro"))
            .args(args)
            .arg(&path)
            .output()
            .unwrap();
        assert!(out.status.success(), "{}", String::from_utf8_lossy(&out.stderr));
        String::from_utf8(out.stdout).unwrap()
    };
    for cmd in ["run", "check"] {
        let text = cli(&[cmd]);
        assert!(
            text.contains(
                "NOTE: contacts 1, 2, 3, 4, 5, 6: SF_p and SF leave out `zerodur`, which has no \
                 `allowable_pressure`"
            ),
            "{cmd}: {text}"
        );
    }
    let json: serde_json::Value = serde_json::from_str(&cli(&["run", "--json"])).unwrap();
    for c in json["contacts"].as_array().unwrap() {
        assert_eq!(
            c["safety_factor_left_out"],
            serde_json::json!([{"material": "zerodur", "missing": "allowable_pressure"}])
        );
    }
}

/// The shear factor too: balls of a steel with only an allowable shear
/// stress on built-in steel grooves (pressure allowable only). Each factor
/// leaves out the body that lacks its allowable.
#[test]
fn shear_and_pressure_factors_each_name_what_they_leave_out() {
    use kinrepro::contact::stress::LeftOut;
    let text = std::fs::read_to_string(scene_path("01_maxwell_vgroove_steel.toml"))
        .unwrap()
        .replace("ball_material = \"steel\"", "ball_material = \"hard-steel\"")
        + "\n[[materials]]\nname = \"hard-steel\"\nyoungs_modulus = 210e9\npoisson_ratio = 0.3\nallowable_shear_stress = 1.0e9\n";
    let (scene, c) = kinrepro::error::parse_scene(&text, "h.toml").unwrap();
    let s = kinrepro::solve::quasistatic::seat(
        &c,
        &kinrepro::solve::Load::nominal(&scene).with_mu(&[0.5; 6]),
        &kinrepro::solve::SolverOptions::default(),
    )
    .unwrap();
    let expect = vec![
        LeftOut { material: "hard-steel".into(), missing: "allowable_pressure" },
        LeftOut { material: "steel".into(), missing: "allowable_shear_stress" },
    ];
    for r in &s.contacts {
        assert!(r.pressure_safety_factor.is_some() && r.shear_safety_factor.is_some());
        assert_eq!(r.safety_factor_left_out, expect);
    }
}

/// Significant digits of a decimal literal (`-0.0346410161513775`: 15).
fn significant_digits(literal: &str) -> usize {
    let digits: String = literal.chars().filter(char::is_ascii_digit).collect();
    digits.trim_start_matches('0').trim_end_matches('0').len()
}

#[test]
fn expand_writes_rounding_noise_as_zero_and_reloads_the_same_scene() {
    let tmp = tempfile::tempdir().unwrap();
    for name in PAPER_SCENES {
        let path = scene_path(name);
        let (ok, text, err) = common::kinrepro(&["expand", path.to_str().unwrap()]);
        assert!(ok, "{name}: {err}");
        // Every number of an array (one per line) has at most 15 digits: no
        // 2.4492935982947064e-18 for the x of ball 1 at azimuth 90 deg.
        for line in text.lines().map(str::trim) {
            if let Some(n) = line.strip_suffix(',').filter(|n| n.parse::<f64>().is_ok()) {
                assert!(significant_digits(n) <= 15, "{name}: {n}");
            }
        }
        let first = text.find("centre = [\n").unwrap() + "centre = [\n".len();
        assert_eq!(text[first..].lines().next().unwrap().trim(), "0.0,", "{name}");
        // Written to a file and loaded back: the same scene within 1e-12.
        let file = tmp.path().join(name);
        std::fs::write(&file, &text).unwrap();
        let back = kinrepro::error::read_scene(&file).unwrap().0;
        let mut scene = Scene::parse(&std::fs::read_to_string(&path).unwrap(), "").unwrap();
        scene.file = back.file.clone();
        common::assert_close_debug(&strip_lines(scene), &strip_lines(back), name);
    }
}
