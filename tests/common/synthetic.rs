//! Synthetic measurements for the calibration tests, drawn independently
//! of the calibration code: mu_s,k = mu0 + spread (2u - 1) with u from a
//! ChaCha stream of the test's own seed (not the model's), one seating per
//! cycle, plus Gaussian sensor noise (Box-Muller).

use kinrepro::calibrate::fit::CalibrateOptions;
use kinrepro::calibrate::model::{MODEL_SAMPLES, MODEL_SEED};
use kinrepro::solve::Solver;
use kinrepro::study::runner::evaluate_rows;
use kinrepro::study::{StudyOptions, Variant};
use rand::Rng;
use rand_chacha::ChaCha8Rng;

/// Sensor noise: 1 nm on translations, 20 nrad on rotations.
pub const NOISE: [f64; 6] = [1e-9, 1e-9, 1e-9, 20e-9, 20e-9, 20e-9];

/// `cycles` re-seatings of point 0 of `v` (its own friction), with noise [SI].
pub fn synthetic(v: &Variant, cycles: usize, rng: &mut ChaCha8Rng) -> Vec<[f64; 6]> {
    let dims = v.coupling.contacts.len();
    let rows: Vec<(usize, Vec<f64>)> =
        (0..cycles).map(|i| (i, (0..dims).map(|_| rng.random::<f64>()).collect())).collect();
    let settings = StudyOptions::monte_carlo(cycles, 1, Solver::QuasiStatic).settings().unwrap();
    let recs = evaluate_rows(&settings, v, rows, &|| {}).unwrap();
    recs.iter().map(|r| std::array::from_fn(|j| r.outputs[j] + NOISE[j] * gaussian(rng))).collect()
}

pub fn gaussian(rng: &mut ChaCha8Rng) -> f64 {
    let u1: f64 = 1.0 - rng.random::<f64>();
    let u2: f64 = rng.random::<f64>();
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

pub fn csv(rows: &[[f64; 6]]) -> String {
    let mut s = String::from(
        "# noise: x=1nm, y=1nm, z=1nm, phi_x=20nrad, phi_y=20nrad, phi_z=20nrad\n\
         x_nm,y_nm,z_nm,phi_x_nrad,phi_y_nrad,phi_z_nrad\n",
    );
    for r in rows {
        let cells: Vec<String> = r.iter().map(|v| format!("{:.6}", v * 1e9)).collect();
        s += &cells.join(",");
        s.push('\n');
    }
    s
}

pub fn noise_var() -> Vec<f64> {
    NOISE.iter().map(|v| v * v).collect()
}

/// Calibration options fitting `fit`, with the model's defaults.
pub fn calibrate_options(fit: &[&str]) -> CalibrateOptions {
    CalibrateOptions {
        fit: fit.iter().map(|s| s.to_string()).collect(),
        noise: [None; 6],
        point: None,
        samples: MODEL_SAMPLES,
        seed: MODEL_SEED,
        solver: Solver::QuasiStatic,
    }
}
