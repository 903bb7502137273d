//! Calibration of the friction spread (issue 15): recovery of a known
//! spread from synthetic measurements (coverage of the 90 % interval over
//! repetitions), transfer of the calibration to other designs against
//! direct studies, and a misfit that no spread can produce.
//!
//! Synthetic measurements are drawn here, independently of the
//! calibration code: mu_s,k = mu0 + spread (2u - 1) with u from a ChaCha
//! stream of the test's own seed, one seating per cycle, plus Gaussian
//! sensor noise (Box-Muller), written as a measurement CSV and parsed.

mod common;

use kinrepro::assembly::Coupling;
use kinrepro::calibrate::fit::{CalibrateOptions, fit_with};
use kinrepro::calibrate::model::{MODEL_SAMPLES, MODEL_SEED, model_options, with_spread};
use kinrepro::calibrate::{Measurement, ModelStudy, calibrate, predict};
use kinrepro::solve::Method;
use kinrepro::study::runner::{evaluate_rows, run_variant};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

const TRUE_SPREAD: f64 = 0.08;
/// Sensor noise: 1 nm on translations, 20 nrad on rotations.
const NOISE: [f64; 6] = [1e-9, 1e-9, 1e-9, 20e-9, 20e-9, 20e-9];

/// `cycles` re-seatings of point 0 at `spread`, with sensor noise [SI].
fn synthetic(c: &Coupling, spread: f64, cycles: usize, rng: &mut ChaCha8Rng) -> Vec<[f64; 6]> {
    let c = with_spread(c, spread);
    let dims = c.contacts.len();
    let rows: Vec<(usize, Vec<f64>)> = (0..cycles)
        .map(|i| (i, (0..dims).map(|_| rng.random::<f64>()).collect()))
        .collect();
    let opts = model_options(cycles, 1, Method::default());
    let recs = evaluate_rows(&c, &opts, rows, &|| {}).unwrap();
    recs.iter()
        .map(|r| std::array::from_fn(|j| r.outputs[j] + NOISE[j] * gaussian(rng)))
        .collect()
}

/// Standard normal by Box-Muller.
fn gaussian(rng: &mut ChaCha8Rng) -> f64 {
    let u1: f64 = 1.0 - rng.random::<f64>();
    let u2: f64 = rng.random::<f64>();
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

/// The cycles as a measurement file (nm, nrad), with the noise as metadata.
fn csv(rows: &[[f64; 6]]) -> String {
    let mut s = String::from(
        "# rig: synthetic\n# noise: x=1nm, y=1nm, z=1nm, phi_x=20nrad, phi_y=20nrad, phi_z=20nrad\n",
    );
    s.push_str("x_nm,y_nm,z_nm,phi_x_nrad,phi_y_nrad,phi_z_nrad\n");
    for r in rows {
        let cells: Vec<String> = r.iter().map(|v| format!("{:.6}", v * 1e9)).collect();
        s.push_str(&cells.join(","));
        s.push('\n');
    }
    s
}

fn noise_var() -> Vec<f64> {
    NOISE.iter().map(|v| v * v).collect()
}

#[test]
fn recovery_coverage_of_the_spread_interval() {
    let c = common::load("02_maxwell_pins_steel.toml");
    // One model study at the scene's own spread (0.05), scaled by s^2:
    // the linear law the calibration relies on, used here over 0.05 -> 0.08.
    let model = ModelStudy::run(&c, 0, 0.05, MODEL_SAMPLES, MODEL_SEED, Method::default()).unwrap();
    let mut rng = ChaCha8Rng::seed_from_u64(2026);
    let reps = 120;
    let (mut covered, mut abs_err, mut bias) = (0, 0.0, 0.0);
    for _ in 0..reps {
        let rows = synthetic(&c, TRUE_SPREAD, 50, &mut rng);
        let m = Measurement::parse(&csv(&rows), "synthetic.csv").unwrap();
        let f = fit_with(&m, &model, &noise_var(), 0.5).unwrap();
        assert!(f.low < f.estimate && f.estimate < f.high);
        covered += usize::from(f.low <= TRUE_SPREAD && TRUE_SPREAD <= f.high);
        abs_err += (f.estimate / TRUE_SPREAD - 1.0).abs() / reps as f64;
        bias += (f.estimate / TRUE_SPREAD - 1.0) / reps as f64;
    }
    let coverage = covered as f64 / reps as f64;
    eprintln!("coverage {coverage:.3}, mean |error| {abs_err:.4}, mean error {bias:.4}");
    assert!((0.80..=0.97).contains(&coverage), "coverage {coverage}");
    assert!(abs_err < 0.05, "mean absolute relative error {abs_err}");
}
