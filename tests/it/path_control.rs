//! Load-path error control (`SolverOptions::path_tolerance`,
//! `solve::quasistatic::control`): the controlled seating against an
//! independent reference, the limit of the fixed-step path (Richardson,
//! first order, of 2560 and 5120 uniform increments), on the pin (02) and
//! Kelvin (06) scenes; its `path_error` is conservative; the CLI flags and
//! the study's `load_path` block. Friction vectors are Monte Carlo draws
//! (mu_s uniform in mu0 +- spread per contact, ChaCha8 here, not the
//! study code's).

use crate::common;
use crate::common::{load, mc_frictions as frictions};

use kinrepro::assembly::{BodyPose, Coupling};
use kinrepro::scene::Scene;
use kinrepro::solve::quasistatic;
use kinrepro::solve::{DEFAULT_PATH_TOLERANCE, Load, Seating, SolveError, SolverOptions};
use nalgebra::Vector6;

/// A scene and its coupling.
type Model = (Scene, Coupling);

/// The coupling seated under the scene's preload with the static
/// coefficients `mu`.
fn seat((scene, c): &Model, mu: &[f64], opts: &SolverOptions) -> Result<Seating, SolveError> {
    quasistatic::seat(c, &Load::nominal(scene).with_mu(mu), opts)
}

/// The twist from `a` to `b` with its rotation times the coupling radius
/// L: the size measure of the controller (v the translation of the
/// reference point, w the rotation vector).
fn twist(c: &Coupling, a: &BodyPose, b: &BodyPose) -> Vector6<f64> {
    let dq = b.rotation * a.rotation.inverse();
    let w = dq.scaled_axis() * c.length_scale();
    let v = b.translation - dq * a.translation;
    Vector6::new(v.x, v.y, v.z, w.x, w.y, w.z)
}

/// The limit of the fixed-step path: x_5120 + (x_5120 - x_2560), the
/// first-order Richardson extrapolation of 2560 and 5120 uniform
/// increments (the fixed path converges to first order,
/// tests/it/seating_path.rs).
fn limit(m: &Model, mu: &[f64]) -> BodyPose {
    let c = &m.1;
    let a = seat(m, mu, &SolverOptions::fixed(2560)).unwrap().pose();
    let b = seat(m, mu, &SolverOptions::fixed(5120)).unwrap().pose();
    let d = twist(c, &a, &b);
    let l = c.length_scale();
    b.moved(&d.fixed_rows::<3>(0).into(), &(d.fixed_rows::<3>(3) / l))
}

/// (true error, estimate, increments) of the controlled seating at
/// `tolerance`, the error relative to the motion of the limit.
fn controlled(m: &Model, mu: &[f64], tolerance: f64) -> (f64, f64, usize) {
    against(m, mu, &limit(m, mu), tolerance)
}

/// [`controlled`] against a limit `reference` already computed.
fn against(m: &Model, mu: &[f64], reference: &BodyPose, tolerance: f64) -> (f64, f64, usize) {
    let c = &m.1;
    let opts = SolverOptions { path_tolerance: Some(tolerance), ..Default::default() };
    let s = seat(m, mu, &opts).unwrap().seated;
    let motion = twist(c, &c.touching_pose, reference).norm();
    let error = twist(c, reference, &s.pose).norm() / motion;
    (error, s.path_error.expect("a controlled seating"), s.increments)
}

/// The default tolerance holds on the pin and Kelvin scenes, a tighter one
/// too, and the fine fixed path (5120 increments) itself agrees with the
/// controlled seating within the tolerance.
#[test]
fn the_controlled_seating_meets_its_tolerance() {
    for name in ["02_maxwell_pins_steel.toml", "06_kelvin_steel.toml"] {
        let m = load(name);
        let c = &m.1;
        for mu in frictions(&m.0, c, 5, 26) {
            for tolerance in [DEFAULT_PATH_TOLERANCE, 1e-6] {
                let (error, estimate, n) = controlled(&m, &mu, tolerance);
                println!("{name} {tolerance:e}: error {error:.2e} estimate {estimate:.2e} ({n})");
                assert!(estimate <= tolerance, "{name} {mu:?}: {estimate:e}");
                assert!(error <= tolerance, "{name} {mu:?}: {error:e} > {tolerance:e}");
            }
            let fine = seat(&m, &mu, &SolverOptions::fixed(5120)).unwrap().pose();
            let s = seat(&m, &mu, &SolverOptions::default()).unwrap();
            let motion = twist(c, &c.touching_pose, &fine).norm();
            let d = twist(c, &fine, &s.pose()).norm() / motion;
            assert!(d <= DEFAULT_PATH_TOLERANCE, "{name} {mu:?}: {d:e} from 5120");
        }
    }
}

/// The estimate is conservative: the true error is below `path_error` for
/// at least 95 % of 200 friction vectors per scene (at the default
/// tolerance and at 1e-6, where the levels differ).
#[test]
fn the_path_error_is_conservative() {
    let tolerances = [DEFAULT_PATH_TOLERANCE, 1e-6];
    for name in ["02_maxwell_pins_steel.toml", "06_kelvin_steel.toml"] {
        let m = load(name);
        let (mut below, mut worst) = ([0; 2], [(0.0f64, 0.0, 0.0); 2]);
        for mu in &frictions(&m.0, &m.1, 200, 7) {
            // One reference per friction vector serves both tolerances.
            let reference = limit(&m, mu);
            for (k, &tolerance) in tolerances.iter().enumerate() {
                let (error, estimate, _) = against(&m, mu, &reference, tolerance);
                below[k] += usize::from(error <= estimate);
                if error / estimate > worst[k].0 {
                    worst[k] = (error / estimate, error, estimate);
                }
            }
        }
        for (k, tolerance) in tolerances.iter().enumerate() {
            let (below, worst) = (below[k], worst[k]);
            println!(
                "{name} {tolerance:e}: {below} / 200 below, worst error / estimate {:.2} ({:.1e} / {:.1e})",
                worst.0, worst.1, worst.2
            );
            assert!(below >= 190, "{name} {tolerance:e}: only {below} / 200");
        }
    }
}

/// The same for the Mindlin-Deresiewicz law on scene 01 (the issue's
/// case: its path_error once said 8e-7 while z stayed 1.6e-5 from the
/// converged value): the true error, against the limit of fixed paths of
/// 320 and 640 increments (the law is exact along each proportional
/// increment, so these are converged far below the estimate), is below
/// `path_error` for at least 95 % of 200 friction vectors.
#[test]
fn the_path_error_is_conservative_for_mindlin_deresiewicz() {
    let (scene, _) = load("01_maxwell_vgroove_steel.toml");
    let text = std::fs::read_to_string(&scene.file)
        .unwrap()
        .replace("tangential_law = \"coulomb\"", "tangential_law = \"mindlin-deresiewicz\"");
    let scene = Scene::parse(&text, "md01.toml").unwrap();
    let coupling = Coupling::new(&scene).unwrap();
    let m = (scene, coupling);
    let c = &m.1;
    let (mut below, mut worst) = (0, 0.0f64);
    for mu in &frictions(&m.0, c, 200, 7) {
        let a = seat(&m, mu, &SolverOptions::fixed(320)).unwrap().pose();
        let b = seat(&m, mu, &SolverOptions::fixed(640)).unwrap().pose();
        let d = twist(c, &a, &b);
        let reference =
            b.moved(&d.fixed_rows::<3>(0).into(), &(d.fixed_rows::<3>(3) / c.length_scale()));
        let s = seat(&m, mu, &SolverOptions::default()).unwrap().seated;
        let motion = twist(c, &c.touching_pose, &reference).norm();
        let error = twist(c, &reference, &s.pose).norm() / motion;
        let estimate = s.path_error.expect("a controlled seating");
        below += usize::from(error <= estimate);
        worst = worst.max(error / estimate);
    }
    println!(
        "mindlin-deresiewicz, scene 01: {below} / 200 below, worst error / estimate {worst:.2}"
    );
    assert!(below >= 190, "only {below} / 200");
}

/// Where every contact slides along a straight path (scene 01) the
/// controlled seating takes its first two levels only: fewer increments
/// than the fixed default of 20, and the same pose as 5120 fixed
/// increments within the Newton floor.
#[test]
fn a_straight_slide_takes_few_increments() {
    let m = load("01_maxwell_vgroove_steel.toml");
    let c = &m.1;
    for mu in frictions(&m.0, c, 20, 3) {
        let s = seat(&m, &mu, &SolverOptions::default()).unwrap().seated;
        assert!(s.increments < 20, "{mu:?}: {} increments", s.increments);
        let fine = seat(&m, &mu, &SolverOptions::fixed(5120)).unwrap().pose();
        let motion = twist(c, &c.touching_pose, &fine).norm();
        let d = twist(c, &fine, &s.pose).norm() / motion;
        assert!(d < 1e-8, "{mu:?}: {d:e}");
        // A fixed-step seating does not estimate its error.
        let fixed = seat(&m, &mu, &SolverOptions::fixed(20)).unwrap();
        assert_eq!(fixed.seated.path_error, None);
    }
}

/// `--path-tolerance`: range and exclusion checked with a clear error,
/// `run --json` reports `path_error` and the increments, and a study's
/// `load_path` block merges from shards to the unsharded numbers.
#[test]
fn cli_path_tolerance_and_load_path() {
    let scene = common::scene("06_kelvin_steel.toml");
    let scene = scene.to_str().unwrap();
    for bad in ["0", "1", "nan", "-1e-5"] {
        let (ok, _, err) = common::kinrepro(&["run", scene, "--path-tolerance", bad]);
        assert!(!ok && err.contains("--path-tolerance"), "{bad}: {err}");
    }
    let (ok, _, err) =
        common::kinrepro(&["study", scene, "--increments", "40", "--path-tolerance", "1e-6"]);
    assert!(!ok && err.contains("exclude each other"), "{err}");
    let json = |args: &[&str]| -> serde_json::Value {
        let (ok, out, err) = common::kinrepro(args);
        assert!(ok, "{args:?}: {err}");
        serde_json::from_str(&out).unwrap()
    };
    let run = json(&["run", scene, "--json", "--path-tolerance", "1e-6"]);
    let e = run["path_error"].as_f64().unwrap();
    assert!(e > 0.0 && e <= 1e-6, "{e}");
    // Levels of 3, 6, 12, ... increments (no halving on scene 06): at
    // least the first two, 3 (2^k - 1) in all.
    let n = run["increments"].as_u64().unwrap();
    assert!(n >= 9 && n % 3 == 0 && (n / 3 + 1).is_power_of_two(), "{n}");
    let fixed = json(&["run", scene, "--json", "--increments", "20"]);
    assert!(fixed["path_error"].is_null());
    assert_eq!(fixed["increments"], 20);

    let dir = tempfile::tempdir().unwrap();
    let study = ["study", scene, "--sampler", "mc", "--samples", "30", "--format", "json"];
    let whole = json(&study);
    let mut parts = Vec::new();
    for i in 1..=3 {
        let shard = format!("{i}/3");
        let mut args = study.to_vec();
        args.extend(["--shard", &shard]);
        let path = dir.path().join(format!("part{i}.json"));
        std::fs::write(&path, json(&args).to_string()).unwrap();
        parts.push(path.to_str().unwrap().to_string());
    }
    let mut args = vec!["merge", "--format", "json"];
    args.extend(parts.iter().map(String::as_str));
    let merged = json(&args);
    let (w, m) = (&whole["variants"][0]["load_path"], &merged["variants"][0]["load_path"]);
    assert_eq!(w, m, "merge of shards");
    assert_eq!(w["seatings"], 30);
    let max_error = w["max_path_error"].as_f64().unwrap();
    assert!(max_error > 0.0 && max_error <= DEFAULT_PATH_TOLERANCE);
    let total = w["increments_total"].as_u64().unwrap() as f64;
    assert!((w["increments_mean"].as_f64().unwrap() - total / 30.0).abs() <= 1e-12 * total);
}
