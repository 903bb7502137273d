//! The quasi-static seating's path: `seating_path` says whether the load
//! path took the nominal increments s_k = k/N (`uniform`) or halved an
//! increment (`adaptive`), and the nominal path is a discretisation of one
//! load path that converges as the increments are refined. Friction
//! vectors are Monte Carlo draws (mu_s uniform in mu0 +- spread per
//! contact, drawn here with ChaCha8, not by the study code).

use crate::common;
use crate::common::load;

use kinrepro::assembly::Coupling;
use kinrepro::contact::{FrictionLaw, TangentialLaw};
use kinrepro::scene::Scene;
use kinrepro::solve::quasistatic;
use kinrepro::solve::{Load, PointPose, Seating, SeatingPath, SolveError, SolverOptions};
use nalgebra::Vector3;

/// A scene and its coupling.
type Model = (Scene, Coupling);

/// The coupling seated under the scene's preload with the static
/// coefficients `mu`.
fn seat((scene, c): &Model, mu: &[f64], opts: &SolverOptions) -> Result<Seating, SolveError> {
    quasistatic::seat(c, &Load::nominal(scene).with_mu(mu), opts)
}

/// The scene edited by `edit`, assembled again.
fn edited((scene, _): &Model, edit: impl FnOnce(&mut Scene)) -> Model {
    let mut scene = scene.clone();
    edit(&mut scene);
    let c = Coupling::new(&scene).unwrap();
    (scene, c)
}

use crate::common::PAPER_SCENES as SCENES;

/// `samples` friction vectors of the scene's distribution (seed 16).
fn frictions((scene, c): &Model, samples: usize) -> Vec<Vec<f64>> {
    common::mc_frictions(scene, c, samples, 16)
}

/// Seat `c` at every friction vector: the seatings on the nominal
/// increments, checking each one's `path` against its increment count (the
/// nominal count exactly without halving; a halved increment covers less
/// of the path, so more increments).
fn uniform_share(c: &Model, samples: usize) -> (usize, usize) {
    let opts = SolverOptions::fixed(20);
    let mut uniform = 0;
    for mu in frictions(c, samples) {
        let s = seat(c, &mu, &opts).unwrap().seated;
        match s.path {
            SeatingPath::Uniform => {
                assert_eq!(s.increments, opts.increments, "{}: {mu:?}", c.0.file);
                uniform += 1;
            }
            SeatingPath::Adaptive => {
                assert!(s.increments > opts.increments, "{}: {mu:?}", c.0.file)
            }
            SeatingPath::Dynamic => panic!("a quasi-static seating"),
        }
    }
    (uniform, samples)
}

/// Every bundled scene with the Coulomb law takes the nominal increments
/// for (nearly) every friction vector, as do Mindlin-Deresiewicz partial
/// slip and the decay friction law on scene 01; the decay law on scene 05
/// with c = 3e6 s/m (SiC, c v_slip near 1: its sliding coefficient
/// switching near the static limit) halves for some, which then take more
/// increments.
#[test]
fn seating_path_says_whether_an_increment_was_halved() {
    for name in SCENES {
        let (uniform, n) = uniform_share(&load(name), 300);
        println!("{name}: nominal increments {uniform} / {n}");
        assert!(uniform >= 285, "{name}: nominal increments only {uniform} / {n}");
    }
    let base = load("01_maxwell_vgroove_steel.toml");
    let md = edited(&base, |s| s.friction.tangential_law = TangentialLaw::MindlinDeresiewicz);
    let decay = edited(&base, |s| s.friction.law = FrictionLaw::Decay { coefficient: 1e6 });
    for (label, c) in [("mindlin-deresiewicz", md), ("decay", decay)] {
        let (uniform, n) = uniform_share(&c, 40);
        println!("01 {label}: nominal increments {uniform} / {n}");
        assert!(uniform >= 38, "01 {label}: nominal increments only {uniform} / {n}");
    }
    let decay = edited(&load("05_maxwell_balls_sic.toml"), |s| {
        s.friction.law = FrictionLaw::Decay { coefficient: 3e6 }
    });
    let (uniform, n) = uniform_share(&decay, 60);
    println!("05 decay: nominal increments {uniform} / {n}");
    assert!(uniform < n, "05 decay: no seating halved");
}

/// The pose of the origin relative to the touching pose, rotations times
/// the coupling radius (the displacement they cause at the balls).
fn motion((_, c): &Model, s: &Seating) -> [f64; 6] {
    let v = PointPose::between(&c.touching_pose, &s.pose(), &Vector3::zeros()).components();
    let l = c.length_scale();
    [v[0], v[1], v[2], v[3] * l, v[4] * l, v[5] * l]
}

/// The nominal path is a discretisation of one load path: with N, 2N, 4N
/// and 8N increments (N = 20) the differences between successive poses
/// fall by a factor of 1.6 to 3.5 at each doubling (first order or better),
/// so the 20-increment pose is within about twice its difference from 40
/// increments of the converged path. Scenes where that difference is above
/// the Newton tolerance (scene 01 slides straight and sits at 1e-10 of
/// its motion for every N): pins (02), balls (04), Kelvin (06).
#[test]
fn the_nominal_path_converges_as_the_increments_are_refined() {
    for name in [SCENES[1], SCENES[3], SCENES[5]] {
        let c = load(name);
        for mu in frictions(&c, 3) {
            let poses: Vec<[f64; 6]> = [20, 40, 80, 160]
                .iter()
                .map(|&increments| {
                    let opts = SolverOptions::fixed(increments);
                    let s = seat(&c, &mu, &opts).unwrap();
                    assert_eq!(s.seated.path, SeatingPath::Uniform, "{name} {increments}");
                    motion(&c, &s)
                })
                .collect();
            let size = poses[3].iter().fold(0.0f64, |m, v| m.max(v.abs()));
            let d: Vec<f64> = poses
                .windows(2)
                .map(|w| (0..6).map(|k| (w[0][k] - w[1][k]).abs()).fold(0.0, f64::max) / size)
                .collect();
            println!("{name}: differences at each doubling {d:?}");
            assert!(d[0] > 1e-9, "{name}: {d:?} at the Newton tolerance");
            for k in 0..2 {
                let ratio = d[k] / d[k + 1];
                assert!((1.6..3.5).contains(&ratio), "{name} {mu:?}: {d:?}");
            }
        }
    }
}

/// `run --json` names the path: the nominal increments for a bundled
/// scene at its nominal friction, the dynamic solver as such.
#[test]
fn run_json_says_which_path_seated() {
    let scene = common::scene("01_maxwell_vgroove_steel.toml");
    let scene = scene.to_str().unwrap();
    for (extra, expected) in [(None, "uniform"), (Some("dynamic"), "dynamic")] {
        let mut args = vec!["run", scene, "--json"];
        if let Some(solver) = extra {
            args.extend(["--solver", solver]);
        }
        let (ok, out, err) = common::kinrepro(&args);
        assert!(ok, "{err}");
        let v: serde_json::Value = serde_json::from_str(&out).unwrap();
        assert_eq!(v["seating_path"], expected, "{args:?}");
        // And what produced it.
        assert_eq!(v["kinrepro_version"], env!("CARGO_PKG_VERSION"), "{args:?}");
        assert_eq!(v["schema_version"], 3, "{args:?}");
    }
}

/// `seating_paths` of a study variant counts every sample seating once:
/// the counts add up to the samples (twice the samples with tolerances
/// varied, where each sample also seats the perturbed coupling), the
/// quasi-static study uses no dynamic seating, and the nominal increments
/// serve (they serve every sample of scene 01 above).
#[test]
fn study_json_counts_the_seating_paths() {
    let s01 = common::scene("01_maxwell_vgroove_steel.toml");
    let tol = common::scene("tolerances_maxwell_vgroove.toml");
    let cases = [
        (vec![s01.to_str().unwrap(), "--samples", "30"], 30),
        (vec![tol.to_str().unwrap(), "--samples", "12", "--vary", "friction,tolerances"], 24),
    ];
    for (args, seatings) in cases {
        let mut a = vec!["study"];
        a.extend(args);
        a.extend(["--format", "json"]);
        let (ok, out, err) = common::kinrepro(&a);
        assert!(ok, "{err}");
        let json: serde_json::Value = serde_json::from_str(&out).unwrap();
        let p = &json["variants"][0]["seating_paths"];
        let count = |k: &str| p[k].as_u64().unwrap();
        assert_eq!(count("uniform") + count("adaptive"), seatings, "{p}");
        assert_eq!(count("dynamic"), 0, "{p}");
        assert!(count("uniform") > 0, "{p}");
    }
}
