//! Helpers shared by the integration tests.

#![allow(dead_code)]

pub mod synthetic;

use std::path::{Path, PathBuf};
use std::process::Command;

/// Run the kinrepro binary: (success, stdout, stderr).
pub fn kinrepro(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_kinrepro")).args(args).output().unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// The seven bundled variants of the paper, in its order.
pub const PAPER_SCENES: [&str; 7] = [
    "01_maxwell_vgroove_steel.toml",
    "02_maxwell_pins_steel.toml",
    "03_maxwell_pins_sic.toml",
    "04_maxwell_balls_steel.toml",
    "05_maxwell_balls_sic.toml",
    "06_kelvin_steel.toml",
    "07_kelvin_sic.toml",
];

/// Path of a bundled scene.
pub fn scene(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(name)
}

/// The worked 50-cycle measurement of scene 02 (docs/calibration/).
pub fn worked_measurement() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/calibration/measured_02.csv")
}

/// `samples` Monte Carlo friction vectors of the scene's distribution:
/// mu_s uniform in mu0 +- spread per contact, drawn here with ChaCha8
/// seeded by `seed` (not by the study code).
pub fn mc_frictions(
    s: &kinrepro::scene::Scene,
    c: &kinrepro::assembly::Coupling,
    samples: usize,
    seed: u64,
) -> Vec<Vec<f64>> {
    use rand::{Rng, SeedableRng};
    let f = &s.friction;
    let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(seed);
    (0..samples)
        .map(|_| {
            (0..c.contacts.len())
                .map(|_| f.mu_static + f.spread * rng.random_range(-1.0..1.0))
                .collect()
        })
        .collect()
}

/// Load and assemble a bundled scene: the scene and its coupling.
pub fn load(name: &str) -> (kinrepro::scene::Scene, kinrepro::assembly::Coupling) {
    kinrepro::error::read_scene(&scene(name)).unwrap()
}

/// Load and assemble a bundled scene and plan a friction-varied Monte
/// Carlo study of it (`samples` samples seeded `seed`, quasi-static): its
/// variant is the scene as given, the model of a calibration.
pub fn model_plan(name: &str, samples: usize, seed: u64) -> kinrepro::study::StudyPlan {
    use kinrepro::study::{StudyOptions, StudyPlan};
    let opts = StudyOptions::monte_carlo(samples, seed, kinrepro::solve::Solver::QuasiStatic);
    StudyPlan::new(vec![load(name)], &opts).unwrap()
}

/// Steel (E = 210 GPa, nu = 0.3) on steel: E* = E / (2 (1 - nu^2)) (Hertz; Johnson 1985, eq. 4.22).
pub const E_STAR_STEEL: f64 = 210e9 / (2.0 * (1.0 - 0.3 * 0.3));

/// Hertz sphere on a sphere or plane (Johnson 1985, §4.2): contact radius
/// a = (3 F R / (4 E*))^(1/3) and approach delta = a^2 / R.
pub fn hertz_circle(force: f64, radius: f64, e_star: f64) -> (f64, f64) {
    let a = (3.0 * force * radius / (4.0 * e_star)).cbrt();
    (a, a * a / radius)
}

/// Ball centres and contact normals (into the ball) of the symmetric Maxwell
/// coupling of scene 01, from docs/model.md's axes and contact numbering and not from kinrepro: balls at
/// azimuths 90, 210, 330 deg on the 40 mm circle, contacts 2k-1 and 2k with
/// normals +-sin(alpha) s + cos(alpha) e_z, s = e_z x e_r (alpha = 45 deg for
/// the 90-degree groove).
pub fn maxwell_contacts(alpha: f64) -> Vec<(nalgebra::Vector3<f64>, nalgebra::Vector3<f64>)> {
    use nalgebra::Vector3;
    let mut out = Vec::new();
    for az in [90.0f64, 210.0, 330.0] {
        let er = Vector3::new(az.to_radians().cos(), az.to_radians().sin(), 0.0);
        let s = Vector3::z().cross(&er);
        for sign in [1.0, -1.0] {
            out.push((er * 0.040, s * (sign * alpha.sin()) + Vector3::z() * alpha.cos()));
        }
    }
    out
}

/// The numbers of a value's Debug text and the text between them.
fn debug_numbers(text: &str) -> (Vec<String>, Vec<f64>) {
    let (mut words, mut numbers, mut word) = (Vec::new(), Vec::new(), String::new());
    let mut chars = text.char_indices().peekable();
    while let Some((i, c)) = chars.next() {
        let starts = c.is_ascii_digit()
            || (c == '-' && text[i + 1..].starts_with(|d: char| d.is_ascii_digit()));
        if !starts || word.ends_with(|w: char| w.is_alphanumeric() || w == '_') {
            word.push(c);
            continue;
        }
        let mut end = i + c.len_utf8();
        while let Some(&(j, d)) = chars.peek() {
            let exp_sign = (d == '-' || d == '+') && text[..j].ends_with('e');
            if !(d.is_ascii_digit() || d == '.' || d == 'e' || exp_sign) {
                break;
            }
            end = j + d.len_utf8();
            chars.next();
        }
        numbers.push(text[i..end].parse().unwrap());
        words.push(std::mem::take(&mut word));
    }
    words.push(word);
    (words, numbers)
}

/// Two values (scenes) equal in structure, each number within 1e-12
/// relative; below 1e-16 in absolute value (a length in m or a unit
/// normal's component) a number counts as zero (rounding noise).
pub fn assert_close_debug<T: std::fmt::Debug>(a: &T, b: &T, what: &str) {
    let (wa, na) = debug_numbers(&format!("{a:?}"));
    let (wb, nb) = debug_numbers(&format!("{b:?}"));
    assert_eq!(wa, wb, "{what}: the structure differs");
    for (k, (x, y)) in na.iter().zip(&nb).enumerate() {
        let tol = 1e-12 * x.abs().max(y.abs()) + 1e-16;
        assert!((x - y).abs() <= tol, "{what}: number {k}: {x} vs {y}");
    }
}

/// Plan a study of `models` (each a scene and its coupling) under `opts`.
pub fn plan(
    models: Vec<(kinrepro::scene::Scene, kinrepro::assembly::Coupling)>,
    opts: &kinrepro::study::StudyOptions,
) -> kinrepro::study::StudyPlan {
    kinrepro::study::StudyPlan::new(models, opts).unwrap()
}

/// Run the first scene of `plan` and report it (the records kept).
pub fn report(plan: &kinrepro::study::StudyPlan) -> kinrepro::study::VariantReport {
    use kinrepro::study::runner::run_variant;
    let (s, v) = (&plan.settings, &plan.variants[0]);
    kinrepro::study::VariantReport::new(s, v, run_variant(s, v, &|| {}).unwrap()).unwrap()
}

/// Scene text `text` is refused at the line of its first `KEY =` (KEY the
/// last part of `field`, e.g. `friction.sd`), naming `field` and saying
/// `says`.
#[allow(dead_code)]
pub fn refused_at_key(text: &str, field: &str, says: &str) {
    let key = field.rsplit('.').next().unwrap();
    let line = text.lines().position(|l| l.starts_with(&format!("{key} ="))).unwrap() + 1;
    let err = kinrepro::scene::Scene::parse(text, "bad.toml").unwrap_err().to_string();
    assert!(
        err.starts_with(&format!("bad.toml:{line}: {field}: ")) && err.contains(says),
        "{field}: {err}"
    );
}
