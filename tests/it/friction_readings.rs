//! The two friction readings (`[friction] law = "switch" | "decay"`) in both
//! solvers, against their exact limits: decay_coefficient = 0 is the switch
//! law with ratio 1 (mu = mu_s while sliding), a very large coefficient is
//! the switch law with the scene's ratio (mu = mu_d for any slip), each to
//! 1e-9 relative per Monte Carlo sample; a scaling law of the slip velocity
//! (v = slip / increment duration, duration proportional to ramp_time);
//! and the scene keys' errors.

use crate::common::load;

use kinrepro::assembly::Coupling;
use kinrepro::contact::FrictionLaw;
use kinrepro::scene::Scene;
use kinrepro::solve::dynamic::{self, DynamicOptions};
use kinrepro::solve::quasistatic::seat;
use kinrepro::solve::{Load, PointPose, Seating, SolverOptions, nominal_mu};
use nalgebra::Vector3;
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// A scene and its coupling.
type Model = (Scene, Coupling);

/// `n` Monte Carlo draws of the six mu_s, uniform in mu0 +- spread.
fn mc_samples((scene, c): &Model, n: usize, seed: u64) -> Vec<Vec<f64>> {
    let f = &scene.friction;
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    (0..n)
        .map(|_| {
            (0..c.contacts.len())
                .map(|_| f.mu_static + f.spread * (2.0 * rng.random::<f64>() - 1.0))
                .collect()
        })
        .collect()
}

/// The scene with its friction reading replaced, assembled again.
fn with_law((scene, _): &Model, law: FrictionLaw, ratio: f64) -> Model {
    let mut scene = scene.clone();
    scene.friction.law = law;
    scene.friction.dynamic_ratio = ratio;
    let c = Coupling::new(&scene).unwrap();
    (scene, c)
}

/// The evaluated pose [x, y, z, phi_x, phi_y] of every evaluation point,
/// relative to the seating at nominal friction (what a study's sigma is made of).
fn pose((scene, _): &Model, s: &Seating, nominal: &Seating) -> Vec<[f64; 5]> {
    scene
        .evaluation_points
        .iter()
        .map(|p| PointPose::between(&nominal.pose(), &s.pose(), &p.position).evaluated())
        .collect()
}

/// Largest difference of two pose lists, relative to the larger of the
/// sample's translation (or rotation) magnitudes, per evaluation point.
fn max_rel(a: &[[f64; 5]], b: &[[f64; 5]]) -> f64 {
    let mut worst: f64 = 0.0;
    for (pa, pb) in a.iter().zip(b) {
        for range in [0..3, 3..5] {
            let scale = range.clone().map(|k| pb[k].abs()).fold(0.0, f64::max);
            for k in range {
                worst = worst.max((pa[k] - pb[k]).abs() / scale);
            }
        }
    }
    worst
}

type Seat = dyn Fn(&Model, &[f64]) -> Seating;

/// Seat `n` MC samples of `scene` under two readings, return the worst
/// per-sample relative difference of the poses.
fn compare(
    scene: &str,
    n: usize,
    a: (FrictionLaw, f64),
    b: (FrictionLaw, f64),
    seat: &Seat,
) -> f64 {
    let base = load(scene);
    let (ca, cb) = (with_law(&base, a.0, a.1), with_law(&base, b.0, b.1));
    let mu0 = nominal_mu(&base.0);
    let (na, nb) = (seat(&ca, &mu0), seat(&cb, &mu0));
    let mut worst: f64 = 0.0;
    for mu in mc_samples(&base, n, 7) {
        let pa = pose(&ca, &seat(&ca, &mu), &na);
        let pb = pose(&cb, &seat(&cb, &mu), &nb);
        worst = worst.max(max_rel(&pa, &pb));
    }
    worst
}

/// Seated under the scene's preload with the static coefficients `mu`.
fn quasi_static((scene, c): &Model, mu: &[f64]) -> Seating {
    let load = Load::nominal(scene).with_mu(mu);
    seat(c, &load, &SolverOptions::default()).unwrap()
}

fn dynamic((scene, c): &Model, mu: &[f64]) -> Seating {
    let load = Load::nominal(scene).with_mu(mu);
    dynamic::seat(c, &load, &DynamicOptions::default()).unwrap()
}

const SCENES: [&str; 3] =
    ["01_maxwell_vgroove_steel.toml", "02_maxwell_pins_steel.toml", "06_kelvin_steel.toml"];

#[test]
fn quasi_static_decay_with_zero_coefficient_is_switch_with_ratio_one() {
    for scene in SCENES {
        let d = compare(
            scene,
            40,
            (FrictionLaw::Decay { coefficient: 0.0 }, 0.8),
            (FrictionLaw::Switch, 1.0),
            &quasi_static,
        );
        eprintln!("{scene}: worst relative difference {d:e}");
        assert!(d < 1e-9, "{scene}: {d:e}");
    }
}

#[test]
fn quasi_static_decay_with_large_coefficient_is_switch_with_the_ratio() {
    for scene in SCENES {
        let d = compare(
            scene,
            40,
            (FrictionLaw::Decay { coefficient: 1e15 }, 0.8),
            (FrictionLaw::Switch, 0.8),
            &quasi_static,
        );
        eprintln!("{scene}: worst relative difference {d:e}");
        assert!(d < 1e-9, "{scene}: {d:e}");
    }
}

#[test]
fn dynamic_decay_limits_are_the_switch_readings() {
    let scene = "01_maxwell_vgroove_steel.toml";
    let zero = compare(
        scene,
        2,
        (FrictionLaw::Decay { coefficient: 0.0 }, 0.8),
        (FrictionLaw::Switch, 1.0),
        &dynamic,
    );
    eprintln!("dynamic: c = 0 {zero:e}");
    assert!(zero < 1e-9, "{zero:e}");
    let large = compare(
        scene,
        2,
        (FrictionLaw::Decay { coefficient: 1e15 }, 0.8),
        (FrictionLaw::Switch, 0.8),
        &dynamic,
    );
    eprintln!("dynamic: c = 1e15 {large:e}");
    assert!(large < 1e-9, "{large:e}");
}

#[test]
fn an_fe_codes_decay_coefficient_slides_at_mu_s_at_seating_speeds() {
    // The readings must differ (else the limits above test nothing), and an
    // FE code's usual decay coefficient (20 s/m) at seating slip speeds
    // (the grooves slip ~0.5 um during the 1 s ramp: c v ~ 1e-5) gives the
    // sliding coefficient mu_s (1 - 2e-6): reading B, switch with ratio 1.
    let base = load("01_maxwell_vgroove_steel.toml");
    let mu = &mc_samples(&base, 1, 3)[0];
    let pose_of = |law, ratio| {
        let c = with_law(&base, law, ratio);
        let nominal = quasi_static(&c, &nominal_mu(&c.0));
        pose(&c, &quasi_static(&c, mu), &nominal)
    };
    let a = pose_of(FrictionLaw::Switch, 0.8);
    let b = pose_of(FrictionLaw::Switch, 1.0);
    let fe = pose_of(FrictionLaw::Decay { coefficient: 20.0 }, 0.8);
    assert!(max_rel(&a, &b) > 0.05, "{a:?} {b:?}");
    assert!(max_rel(&fe, &b) < 1e-4, "{fe:?} {b:?}");
}

#[test]
fn slip_velocity_scales_with_the_ramp_time() {
    // mu depends on c v = c gamma / ((s' - s) T): halving c and the ramp time
    // together leaves every seating unchanged (to rounding), while halving c
    // alone changes it.
    let base = load("06_kelvin_steel.toml");
    let law = |c: f64| FrictionLaw::Decay { coefficient: c };
    let c1 = with_law(&base, law(4e6), 0.8);
    let mut c2 = with_law(&base, law(2e6), 0.8);
    c2.0.preload.ramp_time = 0.5;
    let c3 = with_law(&base, law(2e6), 0.8);
    for mu in mc_samples(&base, 5, 11) {
        let (p1, p2, p3) = (
            quasi_static(&c1, &mu).pose(),
            quasi_static(&c2, &mu).pose(),
            quasi_static(&c3, &mu).pose(),
        );
        let o = Vector3::zeros();
        let d12 = PointPose::between(&p1, &p2, &o);
        let d13 = PointPose::between(&p1, &p3, &o);
        let r = PointPose::between(&base.1.touching_pose, &p1, &o);
        let size = |d: &PointPose| d.x_m.abs().max(d.y_m.abs()).max(d.z_m.abs());
        assert!(size(&d12) < 1e-9 * r.z_m.abs(), "{d12:?}");
        assert!(size(&d13) > 1e-4 * r.z_m.abs(), "{d13:?}");
    }
}

fn scene_text(friction_extra: &str, preload_extra: &str) -> String {
    format!(
        "[coupling]\narrangement = \"maxwell\"\ndiameter = 0.08\nball_diameter = 0.01\n\
         ball_material = \"steel\"\ngroove = \"planes\"\ngroove_material = \"steel\"\n\
         [preload]\nforce = 20.0\n{preload_extra}\n[friction]\nmu_static = 0.5\n{friction_extra}\n"
    )
}

#[test]
fn friction_law_keys_are_read() {
    let s = Scene::parse(&scene_text("", ""), "t.toml").unwrap();
    assert_eq!(s.friction.law, FrictionLaw::Switch);
    assert_eq!(s.preload.ramp_time, 1.0);
    let s = Scene::parse(
        &scene_text("law = \"decay\"\ndecay_coefficient = 20.0", "ramp_time = 0.25"),
        "t.toml",
    )
    .unwrap();
    assert_eq!(s.friction.law, FrictionLaw::Decay { coefficient: 20.0 });
    assert_eq!(s.preload.ramp_time, 0.25);
}

#[test]
fn friction_law_keys_are_checked() {
    for (friction, preload, line, field) in [
        ("law = \"decay\"", "", 13, "friction.decay_coefficient"),
        ("law = \"decay\"\ndecay_coefficient = -1.0", "", 14, "friction.decay_coefficient"),
        ("decay_coefficient = 3.0", "", 13, "friction.decay_coefficient"),
        ("law = \"switch\"\ndecay_coefficient = 3.0", "", 14, "friction.decay_coefficient"),
        (
            "tangential_law = \"mindlin-deresiewicz\"\nlaw = \"decay\"\ndecay_coefficient = 1.0",
            "",
            14,
            "friction.law",
        ),
        ("", "ramp_time = 0.0", 10, "preload.ramp_time"),
        ("", "ramp_time = -2.0", 10, "preload.ramp_time"),
    ] {
        let e = Scene::parse(&scene_text(friction, preload), "t.toml").unwrap_err();
        assert_eq!(e.line, Some(line), "{e}");
        assert_eq!(e.field, field, "{e}");
        assert!(e.to_string().starts_with(&format!("t.toml:{line}: {field}: ")), "{e}");
    }
    let e = Scene::parse(&scene_text("law = \"sudden\"", ""), "t.toml").unwrap_err();
    assert_eq!(e.line, Some(13), "{e}");
    assert!(e.to_string().contains("sudden"), "{e}");
}
