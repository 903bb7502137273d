//! Real preloads (`[[preload.forces]]`, springs, `gravity`), each against
//! an independent value: statics of a rigid half (three forces with the
//! central force's resultant and moment), the Hertz closed form of scene
//! 01's settlement (the spring's effect), the linear stiffness analysis
//! (a moved force), m g (the weight), and the lines of bad input.

use crate::common;
use crate::common::{kinrepro, scene};

use kinrepro::analysis::stiffness::CouplingStiffness;
use kinrepro::assembly::Coupling;
use kinrepro::scene::Scene;
use kinrepro::solve::{Load, SolverOptions, quasistatic};
use kinrepro::study::runner::Variation;
use nalgebra::{Vector3, Vector6};

/// Scene 01 without its `[preload] force` line, so that `extra` (appended)
/// gives the preload.
fn scene01_without_force(extra: &str) -> String {
    let text = std::fs::read_to_string(scene("01_maxwell_vgroove_steel.toml")).unwrap();
    let kept: Vec<&str> = text.lines().filter(|l| !l.starts_with("force = 20.0")).collect();
    kept.join("\n") + "\n" + extra
}

/// Ball centres of scene 01: radius 40 mm, azimuths 90, 210, 330 degrees.
fn ball_centres() -> Vec<Vector3<f64>> {
    [90.0f64, 210.0, 330.0]
        .iter()
        .map(|a| Vector3::new(0.04 * a.to_radians().cos(), 0.04 * a.to_radians().sin(), 0.0))
        .collect()
}

/// One `[[preload.forces]]` entry along -z at `p`, with `more` lines.
fn force_entry(force: f64, p: &Vector3<f64>, more: &str) -> String {
    format!(
        "\n[[preload.forces]]\nforce = {force:?}\npoint = [{:?}, {:?}, {:?}]\ndirection = [0.0, 0.0, -1.0]\n{more}",
        p.x, p.y, p.z
    )
}

/// A third of the central 20 N at each ball centre (in the plane of the
/// centres, z = 0, like the central force at the origin: a force at
/// another height has another moment once the half turns).
fn three_forces(more: &str) -> String {
    ball_centres().iter().map(|c| force_entry(20.0 / 3.0, c, more)).collect()
}

/// Write `text` as a scene file in the temporary directory.
fn write(name: &str, text: &str) -> String {
    let path = std::env::temp_dir().join(format!("kinrepro_preloads_{name}.toml"));
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

/// Every sigma of `kinrepro study FILE --sampler mc --samples 50 --format json`.
fn study_sigmas(file: &str) -> Vec<f64> {
    let args = ["study", file, "--sampler", "mc", "--samples", "50", "--format", "json"];
    let (ok, out, err) = kinrepro(&args);
    assert!(ok, "{err}");
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    let mut v = Vec::new();
    for p in doc["variants"][0]["points"].as_array().unwrap() {
        for (_, s) in p["sigma"].as_object().unwrap() {
            v.push(s.as_f64().unwrap());
        }
    }
    assert!(!v.is_empty() && v.iter().all(|s| *s > 0.0), "{v:?}");
    v
}

fn max_relative(a: &[f64], b: &[f64]) -> f64 {
    assert_eq!(a.len(), b.len());
    a.iter().zip(b).map(|(x, y)| (x / y - 1.0).abs()).fold(0.0, f64::max)
}

fn coupling(text: &str) -> (Scene, Coupling) {
    kinrepro::error::parse_scene(text, "preloads.toml").unwrap()
}

#[test]
fn three_forces_above_the_balls_give_the_central_preloads_sigma() {
    // Parallel forces F/3 at the ball centres (which sum to zero) have the
    // resultant F and, about any point of the half, the moment of F at the
    // centre: on a rigid half the same load at every pose.
    let central = scene("01_maxwell_vgroove_steel.toml").display().to_string();
    let three = write("three", &scene01_without_force(&three_forces("")));
    let (a, b) = (study_sigmas(&central), study_sigmas(&three));
    let d = max_relative(&b, &a);
    assert!(d < 1e-9, "largest relative sigma difference {d:e}");
}

#[test]
fn spring_preloads_change_sigma_by_less_than_their_stiffness_share() {
    let k = 2.0e4; // each spring [N/m]
    let spring = format!("stiffness = {k:?}\nfree_length = 0.02\n");
    let sprung = write("sprung", &scene01_without_force(&three_forces(&spring)));
    let central = scene("01_maxwell_vgroove_steel.toml").display().to_string();
    let (a, b) = (study_sigmas(&central), study_sigmas(&sprung));
    // Scene 01 by hand (tests/it/quasistatic.rs): six 45-degree contacts share
    // F = 20 N, each f = F / (6 cos 45), Hertz K = 4/3 E* sqrt(R), approach
    // delta = (f/K)^(2/3), the half settles z = delta / cos 45; each contact's
    // k_n = 3/2 K delta^(1/2), the vertical stiffness K_z = 6 k_n cos^2 45.
    let cos_a = 45f64.to_radians().cos();
    let f = 20.0 / (6.0 * cos_a);
    let e_star = 210e9 / (2.0 * (1.0 - 0.09));
    let kh = 4.0 / 3.0 * e_star * 5e-3f64.sqrt();
    let delta = (f / kh).powf(2.0 / 3.0);
    let kz = 6.0 * 1.5 * kh * delta.sqrt() * cos_a * cos_a;
    // The springs lose 3 k z of the preload at the seat and add 3 k to K_z:
    // to first order the scatter changes by these relative amounts.
    let lost = 3.0 * k * (delta / cos_a) / 20.0;
    let stiffer = 3.0 * k / kz;
    let d = max_relative(&b, &a);
    println!(
        "springs of {k} N/m: preload lost at the seat {lost:.3e}, stiffness share {stiffer:.3e}; \
         largest relative sigma change {d:.3e}"
    );
    assert!(d > 1e-6, "the springs must change sigma: {d:e}");
    assert!(d < 3.0 * (lost + stiffer), "{d:e} vs {lost:e} + {stiffer:e}");
}

#[test]
fn a_force_moved_sideways_turns_the_half_as_the_linear_stiffness_predicts() {
    // Frictionless, so that the seating is path independent and the linear
    // analysis (analysis::stiffness, the `load` command's K) applies.
    let frictionless = |forces: &str| {
        let t = scene01_without_force(forces);
        coupling(
            &t.replace("mu_static = 0.5", "mu_static = 0.0")
                .replace("spread = 0.05", "spread = 0.0"),
        )
    };
    let centres = ball_centres();
    let f = 20.0 / 3.0;
    let e = 2.0e-4; // force 1 moved along x [m]
    let moved: String = centres
        .iter()
        .enumerate()
        .map(|(i, c)| force_entry(f, &(c + Vector3::x() * if i == 0 { e } else { 0.0 }), ""))
        .collect();
    let base: String = centres.iter().map(|c| force_entry(f, c, "")).collect();
    let ((scene_a, ca), (scene_b, cb)) = (frictionless(&base), frictionless(&moved));
    let opts = SolverOptions::default();
    let (la, lb) =
        (Load::nominal(&scene_a).with_mu(&[0.0; 6]), Load::nominal(&scene_b).with_mu(&[0.0; 6]));
    let sa = quasistatic::seat(&ca, &la, &opts).unwrap();
    let sb = quasistatic::seat(&cb, &lb, &opts).unwrap();
    // The added load: a pure moment (e x) x (-f z) = e f y.
    let moment = (Vector3::x() * e).cross(&Vector3::new(0.0, 0.0, -f));
    let q = sa.pose().apply(&Vector3::zeros());
    let c = CouplingStiffness::new(&ca, &sa, &la).unwrap();
    let predicted =
        c.compliance_at(&q).unwrap() * Vector6::new(0.0, 0.0, 0.0, moment.x, moment.y, moment.z);
    let u = sb.pose().apply(&Vector3::zeros()) - q;
    let phi = (sb.pose().rotation * sa.pose().rotation.inverse()).scaled_axis();
    let (pu, pphi) =
        (predicted.fixed_rows::<3>(0).into_owned(), predicted.fixed_rows::<3>(3).into_owned());
    println!("rotation {phi:?} predicted {pphi:?}; translation {u:?} predicted {pu:?}");
    assert!(pphi.norm() > 1e-9, "the moment must turn the half: {pphi:?}");
    // Linear theory: errors of the order of the contact force change
    // (e f / (R F) ~ 2e-3) and the left-out geometric stiffness (~1e-4).
    assert!((phi - pphi).norm() < 1e-2 * pphi.norm(), "{phi:?} vs {pphi:?}");
    assert!((u - pu).norm() < 1e-2 * (pu.norm() + 0.04 * pphi.norm()), "{u:?} vs {pu:?}");
}

#[test]
fn gravity_alone_equals_a_single_force_m_g_at_the_centre_of_mass() {
    let (m, com) = (2.0, [1.0e-3, -2.0e-3, 0.01]);
    let weight = scene01_without_force("").replace(
        "[preload]\n",
        &format!("[preload]\ngravity = true\nmass = {m:?}\ncentre_of_mass = {com:?}\n"),
    );
    let single = scene01_without_force("").replace(
        "[preload]\n",
        &format!(
            "[preload]\nforce = {:?}\npoint = {com:?}\ndirection = [0.0, 0.0, -1.0]\n",
            m * 9.80665
        ),
    );
    let a = study_sigmas(&write("weight", &weight));
    let b = study_sigmas(&write("weight_as_force", &single));
    let d = max_relative(&a, &b);
    assert!(d < 1e-9, "{d:e}");
    // The mass may come from [dynamics] instead.
    let dynamics = scene01_without_force(&format!(
        "\n[dynamics]\nmass = {m:?}\ninertia = [0.01, 0.01, 0.02]\ncentre_of_mass = {com:?}\n"
    ))
    .replace("[preload]\n", "[preload]\ngravity = true\n");
    let p = Scene::parse(&dynamics, "d.toml").unwrap().preload;
    let w = Scene::parse(&weight, "w.toml").unwrap().preload;
    assert_eq!(p, w);
    assert!((w.scale() - m * 9.80665).abs() < 1e-12 * m * 9.80665);
}

/// The error of `text` names `file:line: field`, the line that holds `marker`.
fn assert_error_at(text: &str, marker: &str, field: &str) {
    let line = text.lines().position(|l| l.contains(marker)).unwrap() + 1;
    let err = Scene::parse(text, "bad.toml").unwrap_err().to_string();
    assert!(err.starts_with(&format!("bad.toml:{line}: {field}: ")), "{err}");
}

#[test]
fn bad_preloads_are_refused_naming_the_field_and_line() {
    let zero = force_entry(5.0, &Vector3::new(0.0, 0.0, 0.01), "")
        .replace("[0.0, 0.0, -1.0]", "[0.0, 0.0, 0.0]");
    let text = scene01_without_force(&(three_forces("") + &zero));
    assert_error_at(&text, "direction = [0.0, 0.0, 0.0]", "preload.forces[4].direction");
    let text = scene01_without_force(&three_forces("stiffness = -1.0e3\nfree_length = 0.02\n"));
    assert_error_at(&text, "stiffness = -1", "preload.forces[1].stiffness");
    let text = scene01_without_force(&three_forces("stiffness = 1.0e3\n"));
    assert_error_at(&text, "stiffness = 1", "preload.forces[1].stiffness");
    // 6.67 N from a 1 N/mm spring needs more than 6.67 mm of free length.
    let text = scene01_without_force(&three_forces("stiffness = 1.0e3\nfree_length = 0.005\n"));
    assert_error_at(&text, "free_length", "preload.forces[1].free_length");
    let text = scene01_without_force("").replace("[preload]\n", "[preload]\ngravity = true\n");
    assert_error_at(&text, "gravity = true", "preload.gravity");
    let text = std::fs::read_to_string(scene("01_maxwell_vgroove_steel.toml")).unwrap()
        + &three_forces("");
    assert_error_at(&text, "force = 20.0", "preload.force");
    let err = Scene::parse(&scene01_without_force(""), "bad.toml").unwrap_err().to_string();
    assert!(err.contains("preload.force: missing"), "{err}");
}

#[test]
fn expand_prints_the_forces_and_loads_back_to_the_same_preload() {
    let text = scene01_without_force(&three_forces("stiffness = 1.0e4\nfree_length = 0.02\n"))
        .replace("[preload]\n", "[preload]\ngravity = true\nmass = 1.5\n");
    let expanded = Scene::expand_text(&text, "s.toml").unwrap();
    assert_eq!(expanded.matches("[[preload.forces]]").count(), 3, "{expanded}");
    let a = Scene::parse(&text, "s.toml").unwrap().preload;
    let b = Scene::parse(&expanded, "s.toml").unwrap().preload;
    // `expand` writes 15 significant digits: equal within 1e-12 relative.
    common::assert_close_debug(&a, &b, "expanded preload");
    assert_eq!(a.forces.len(), 4, "three springs and the weight");
}

#[test]
fn vary_preload_moves_and_tilts_each_force_but_not_the_weight() {
    let text = scene01_without_force(&three_forces(""))
        .replace("[preload]\n", "[preload]\ngravity = true\nmass = 1.0\n")
        + "\n[variation]\npreload_offset = [1.0e-3, 2.0e-3]\npreload_tilt = 0.01\n";
    let (scene, c) = coupling(&text);
    let var = Variation { friction: false, preload: true, ..Default::default() };
    let names: Vec<String> = var.inputs(&scene).iter().map(|i| i.name()).collect();
    let per = ["x_m", "y_m", "tilt_x_rad", "tilt_y_rad"];
    let expect: Vec<String> = ["preload_", "preload_2_", "preload_3_"]
        .iter()
        .flat_map(|p| per.iter().map(move |s| format!("{p}{s}")))
        .collect();
    assert_eq!(names, expect);
    // Force 2's x offset at its upper bound, everything else at the middle.
    let mut row = vec![0.5; 12];
    row[4] = 1.0;
    let s = var.sample(&scene, &c, &row);
    let nominal = &scene.preload.forces;
    for (i, (f, n)) in s.load.preload.forces.iter().zip(nominal).enumerate() {
        let shift = if i == 1 { Vector3::new(1.0e-3, 0.0, 0.0) } else { Vector3::zeros() };
        assert!((f.point - n.point - shift).norm() < 1e-15, "force {}", i + 1);
        assert!((f.direction - n.direction).norm() < 1e-15);
    }
}

/// Scene 01's 20 N central force plus the weight of a 0.5 kg half under
/// `gravity` (a TOML value), its centre of mass 10 mm above the centre.
fn with_gravity(gravity: &str) -> String {
    scene01_without_force("").replace(
        "[preload]\n",
        &format!(
            "[preload]\nforce = 20.0\ngravity = {gravity}\nmass = 0.5\ncentre_of_mass = [0.0, 0.0, 0.01]\n"
        ),
    )
}

#[test]
fn a_gravity_vector_along_minus_z_is_gravity_true() {
    let (a, b) = (with_gravity("true"), with_gravity("[0.0, 0.0, -9.80665]"));
    let (pa, pb) = (Scene::parse(&a, "a.toml").unwrap(), Scene::parse(&b, "b.toml").unwrap());
    assert_eq!(pa.preload, pb.preload);
    let d = max_relative(&study_sigmas(&write("g_true", &a)), &study_sigmas(&write("g_vec", &b)));
    assert!(d <= 1e-12, "{d:e}");
    // `expand` writes the vector back and it loads to the same preload.
    let expanded = Scene::expand_text(&b, "b.toml").unwrap();
    common::assert_close_debug(
        &pb.preload,
        &Scene::parse(&expanded, "e.toml").unwrap().preload,
        "expanded",
    );
}

/// Gravity along x on the Maxwell coupling, frictionless: the six contact
/// forces are statically determinate, N_i from the 6x6 equilibrium of the
/// seated contact normals and points (solved here) against the preload
/// and the sideways weight; `run --mu 0,...` gives the same.
#[test]
fn sideways_gravity_is_carried_by_the_contacts_as_statics_says() {
    let g = [4.0, 0.0, -9.0];
    let file = write("g_side", &with_gravity(&format!("[{:?}, {:?}, {:?}]", g[0], g[1], g[2])));
    let (ok, out, err) = kinrepro(&["run", &file, "--mu", "0,0,0,0,0,0", "--json"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let vec3 = |x: &serde_json::Value| {
        Vector3::new(x[0].as_f64().unwrap(), x[1].as_f64().unwrap(), x[2].as_f64().unwrap())
    };
    // External loads at the seated pose: 20 N down at the centre, m g at
    // the centre of mass (both carried by the half, which moved by u).
    let pose = &v["pose"];
    let u = Vector3::new(
        pose["x_m"].as_f64().unwrap(),
        pose["y_m"].as_f64().unwrap(),
        pose["z_m"].as_f64().unwrap(),
    );
    let weight = Vector3::from(g) * 0.5;
    let (f, m) = (
        Vector3::new(0.0, 0.0, -20.0) + weight,
        u.cross(&Vector3::new(0.0, 0.0, -20.0)) + (u + Vector3::new(0.0, 0.0, 0.01)).cross(&weight),
    );
    let contacts = v["contacts"].as_array().unwrap();
    let mut a = nalgebra::Matrix6::zeros();
    for (i, c) in contacts.iter().enumerate() {
        let (n, p) = (vec3(&c["normal"]), vec3(&c["point_m"]));
        a.fixed_view_mut::<3, 1>(0, i).copy_from(&n);
        a.fixed_view_mut::<3, 1>(3, i).copy_from(&p.cross(&n));
    }
    let rhs = -Vector6::new(f.x, f.y, f.z, m.x, m.y, m.z);
    let normal = a.lu().solve(&rhs).unwrap();
    for (i, c) in contacts.iter().enumerate() {
        let got = c["normal_force_n"].as_f64().unwrap();
        assert!(
            (got - normal[i]).abs() <= 1e-6 * 20.0,
            "contact {}: {got} vs {}",
            i + 1,
            normal[i]
        );
    }
    // The sideways weight loads the contacts unevenly.
    let spread = normal.max() - normal.min();
    assert!(spread > 0.5, "{normal:?}");
}

#[test]
fn bad_gravity_is_refused_naming_the_field_and_line() {
    for (g, says) in [
        ("[0.0, 0.0, 0.0]", "no direction"),
        ("[0.0, 0.0, -9806.65]", "mm/s^2"),
        ("1.0", "expected true, false or a gravity vector"),
        ("[0.0, -9.8]", "3 numbers"),
        ("[0.0, \"down\", -9.8]", "number"),
    ] {
        let text = with_gravity(g);
        let line = text.lines().position(|l| l.starts_with("gravity = ")).unwrap() + 1;
        let err = Scene::parse(&text, "bad.toml").unwrap_err().to_string();
        assert!(err.starts_with(&format!("bad.toml:{line}: preload.gravity: ")), "{g}: {err}");
        assert!(err.contains(says), "{g}: {err}");
    }
    let large = format!("allow_large_values = true\n{}", with_gravity("[0.0, 0.0, -9806.65]"));
    assert!(Scene::parse(&large, "ok.toml").is_ok());
    let off = with_gravity("false").replace("mass = 0.5\ncentre_of_mass = [0.0, 0.0, 0.01]\n", "");
    assert_eq!(Scene::parse(&off, "off.toml").unwrap().preload.forces.len(), 1);
}

/// Scene 01 with its preload as one `[[preload.forces]]` entry at the
/// centre along -z: a magnet with `gap` and `table` (TOML).
fn with_magnet(gap: &str, table: &str) -> String {
    scene01_without_force(&format!(
        "\n[[preload.forces]]\npoint = [0.0, 0.0, 0.0]\ndirection = [0.0, 0.0, -1.0]\ngap = {gap}\nforce_table = {table}\n"
    ))
}

#[test]
fn a_magnet_with_a_constant_table_is_a_constant_force() {
    let magnet = with_magnet("0.5e-3", "[[0.0, 20.0], [1.0e-3, 20.0], [2.0e-3, 20.0]]");
    let constant = std::fs::read_to_string(scene("01_maxwell_vgroove_steel.toml")).unwrap();
    let d = max_relative(
        &study_sigmas(&write("magnet_const", &magnet)),
        &study_sigmas(&write("magnet_as_force", &constant)),
    );
    assert!(d <= 1e-12, "{d:e}");
}

/// A magnet whose pull falls linearly with the gap (two table points: the
/// monotone interpolant is the line): at the seated pose the contacts
/// carry the table's force at the seated gap, gap_0 + the settlement.
#[test]
fn a_falling_magnet_pulls_with_the_tables_force_at_the_seated_gap() {
    let (g0, f0, g1, f1) = (0.0, 30.0, 2.0e-3, 10.0);
    let gap = 0.5e-3;
    let text = with_magnet(&format!("{gap:?}"), &format!("[[{g0:?}, {f0:?}], [{g1:?}, {f1:?}]]"));
    let (ok, out, err) = kinrepro(&["run", &write("magnet_line", &text), "--json"]);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let dz = v["pose"]["z_m"].as_f64().unwrap();
    assert!(dz < 0.0, "the half settles: {dz}");
    // Moving along d = -z by -dz closes the gap by -dz.
    let seated_gap = gap + dz;
    let expected = f0 + (f1 - f0) * (seated_gap - g0) / (g1 - g0);
    let carried: f64 = v["contacts"]
        .as_array()
        .unwrap()
        .iter()
        .map(|c| {
            let n = c["normal"][2].as_f64().unwrap() * c["normal_force_n"].as_f64().unwrap();
            n + c["tangential_force"][2].as_f64().unwrap()
        })
        .sum();
    assert!((carried / expected - 1.0).abs() < 1e-9, "{carried} N vs {expected} N");
    // `expand` writes the magnet back.
    let expanded = Scene::expand_text(&text, "m.toml").unwrap();
    let (a, b) =
        (Scene::parse(&text, "m.toml").unwrap(), Scene::parse(&expanded, "e.toml").unwrap());
    common::assert_close_debug(&a.preload, &b.preload, "expanded magnet");
    // It pulls harder than at the touching gap (10 N/mm over ~0.6 um).
    let touching = f0 + (f1 - f0) * (gap - g0) / (g1 - g0);
    assert!(carried > touching, "{carried} vs {touching}");
}

/// The monotone interpolant (Fritsch & Carlson): between two table points
/// the force stays between their values, and the slope the solvers use is
/// the derivative of the force (central differences).
#[test]
fn the_magnet_table_is_interpolated_monotonically_with_its_slope() {
    use kinrepro::scene::preload::MagnetLaw;
    let table = vec![[0.0, 40.0], [0.2e-3, 31.0], [0.5e-3, 30.5], [1.0e-3, 12.0], [3.0e-3, 2.0]];
    let law = MagnetLaw::new(0.3e-3, table.clone());
    for w in table.windows(2) {
        for k in 1..50 {
            let g = w[0][0] + (w[1][0] - w[0][0]) * k as f64 / 50.0;
            let (f, slope) = law.force(g);
            assert!(f <= w[0][1] + 1e-12 && f >= w[1][1] - 1e-12, "{g}: {f} outside {w:?}");
            let h = 1e-9;
            let fd = (law.force(g + h).0 - law.force(g - h).0) / (2.0 * h);
            assert!((slope - fd).abs() <= 1e-5 * slope.abs().max(1e3), "{g}: {slope} vs {fd}");
            assert!(slope <= 0.0, "{g}: {slope}");
        }
    }
    for w in &table {
        assert_eq!(law.force(w[0]).0, w[1]);
    }
}

#[test]
fn bad_magnets_are_refused_naming_the_field_and_line() {
    let cases = [
        ("0.5e-3", "[[0.0, 20.0]]", "force_table", "at least two rows"),
        ("0.5e-3", "[[0.0, 20.0], [0.0, 10.0]]", "force_table[2]", "increasing gap"),
        ("0.5e-3", "[[0.0, 20.0], [1.0e-3, -1.0]]", "force_table[2]", "negative"),
        ("5.0e-3", "[[0.0, 20.0], [1.0e-3, 10.0]]", "gap", "outside"),
        ("0.5e-3", "[[0.0, 20.0], [1.0e-3]]", "force_table[2]", "2 numbers"),
        ("0.5e-3", "[[0.0, 0.0], [1.0e-3, 0.0]]", "gap", "must pull"),
    ];
    for (gap, table, field, says) in cases {
        let text = with_magnet(gap, table);
        let marker = if field == "gap" { "gap = " } else { "force_table = " };
        let line = text.lines().position(|l| l.starts_with(marker)).unwrap() + 1;
        let err = Scene::parse(&text, "bad.toml").unwrap_err().to_string();
        let want = format!("bad.toml:{line}: preload.forces[1].{field}: ");
        assert!(err.starts_with(&want) && err.contains(says), "{table}: {err}");
    }
    let text = with_magnet("0.5e-3", "[[0.0, 20.0], [1.0e-3, 10.0]]").replace("gap = 0.5e-3\n", "");
    let err = Scene::parse(&text, "bad.toml").unwrap_err().to_string();
    assert!(err.contains("force_table") && err.contains("gap is missing"), "{err}");
    let text = with_magnet("0.5e-3", "[[0.0, 20.0], [1.0e-3, 10.0]]") + "force = 5.0\n";
    let err = Scene::parse(&text, "bad.toml").unwrap_err().to_string();
    assert!(err.contains("preload.forces[1].force") && err.contains("drop force"), "{err}");
}

/// Preload geometry in millimetres or pointing away from the seat is
/// refused where it is written: a spring's point 40 m out, a centre of
/// mass 15 m away, forces whose resultant lifts the half.
#[test]
fn preload_geometry_errors_name_the_field_and_line() {
    let far = scene01_without_force(&force_entry(20.0, &Vector3::new(0.0, 40.0, 0.0), ""));
    assert_error_at(&far, "point = [0.0, 40.0", "preload.forces[1].point");
    let com = with_gravity("true").replace("[0.0, 0.0, 0.01]", "[0.0, 0.0, 15.0]");
    assert_error_at(&com, "centre_of_mass", "preload.centre_of_mass");
    // 20 N down at the balls, 30 N up at the centre: the last lifts.
    let up =
        force_entry(30.0, &Vector3::zeros(), "").replace("[0.0, 0.0, -1.0]", "[0.0, 0.0, 1.0]");
    let lift = scene01_without_force(&(three_forces("") + &up));
    assert_error_at(&lift, "direction = [0.0, 0.0, 1.0]", "preload.forces[4].direction");
    let err = Scene::parse(&lift, "bad.toml").unwrap_err().to_string();
    assert!(err.contains("does not press the moving half"), "{err}");
    let allowed = format!("allow_large_values = true\n{com}");
    assert!(Scene::parse(&allowed, "ok.toml").is_ok());
}
