//! The model studies of a calibration: Monte Carlo studies
//! (`study::runner::run_variant`) of the scene with fitted parameters
//! replaced, giving the pose samples of one evaluation point and their
//! covariance.

use nalgebra::DMatrix;

use super::error::CalibrateError;
use crate::assembly::Coupling;
use crate::solve::Method;
use crate::study::Sampler;
use crate::study::provenance::Fingerprint;
use crate::study::runner::{StudyOptions, run_variant};

/// Samples of the model studies (`--model-samples`): the relative standard
/// error of a model variance, sqrt(2 / (N - 1)) = 3.2 % at 2000, is small
/// against that of a 50-cycle measurement (20 %).
pub const MODEL_SAMPLES: usize = 2000;

/// Seed of the model studies (`--seed`); a synthetic measurement must use another.
pub const MODEL_SEED: u64 = 15_015;

/// Fewest samples of a model study (`--model-samples`, `predict --samples`).
pub const MIN_MODEL_SAMPLES: usize = 100;

/// A model study's sample count `n` given by `flag`: at least
/// [`MIN_MODEL_SAMPLES`].
pub fn check_model_samples(flag: &str, n: usize) -> Result<usize, String> {
    if n < MIN_MODEL_SAMPLES {
        return Err(format!(
            "{flag} {n}: need at least {MIN_MODEL_SAMPLES} samples"
        ));
    }
    Ok(n)
}

/// What every model study of a calibration shares.
#[derive(Debug, Clone, Copy)]
pub struct StudySpec<'a> {
    pub coupling: &'a Coupling,
    /// Index of the measured evaluation point.
    pub point: usize,
    pub dofs: &'a [usize],
    pub samples: usize,
    pub seed: u64,
    pub method: Method,
}

/// The pose samples of one point at one spread.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelStudy {
    pub spread: f64,
    /// The pose samples of the point (the six DOFs of [`crate::dof::Dof::ALL`]) [SI].
    pub rows: Vec<[f64; 6]>,
    pub fingerprint: Fingerprint,
}

/// The scene with its friction spread replaced by `spread`.
pub fn with_spread(coupling: &Coupling, spread: f64) -> Coupling {
    let mut c = coupling.clone();
    c.scene.friction.spread = spread;
    c
}

/// Study options of a model study: plain Monte Carlo (an unbiased sample
/// covariance; Bonett's interval for sigma), friction varied.
pub fn model_options(samples: usize, seed: u64, method: Method) -> StudyOptions {
    StudyOptions {
        sampler: Some(Sampler::MonteCarlo),
        samples: Some(samples),
        seed: Some(seed),
        method,
        ..StudyOptions::default()
    }
}

impl StudySpec<'_> {
    /// The model study of `c` (a variant of the scene) at its own spread.
    /// The same seed draws the same design rows at every spread and node
    /// (common random numbers), so the ratio of two model studies carries
    /// little sampling noise.
    pub fn run(&self, c: &Coupling) -> Result<ModelStudy, CalibrateError> {
        let opts = model_options(self.samples, self.seed, self.method);
        let run = run_variant(c, &opts, &|| {})?;
        if let Some(reason) = run.cannot_seat {
            return Err(CalibrateError::CannotSeat {
                file: c.scene.file.clone(),
                reason: format!(
                    "{reason} (model study at spread {})",
                    c.scene.friction.spread
                ),
            });
        }
        let point = self.point;
        Ok(ModelStudy {
            spread: c.scene.friction.spread,
            rows: (run.records.iter())
                .map(|r| std::array::from_fn(|j| r.outputs[6 * point + j]))
                .collect(),
            fingerprint: Fingerprint::new(c, &opts, &run.design),
        })
    }
}

impl ModelStudy {
    pub fn samples_of(&self, dofs: &[usize]) -> Vec<Vec<f64>> {
        self.rows
            .iter()
            .map(|r| dofs.iter().map(|&d| r[d]).collect())
            .collect()
    }

    /// Covariance per unit spread^2 of the DOFs `dofs`: G = C / s^2.
    pub fn per_unit(&self, dofs: &[usize]) -> DMatrix<f64> {
        covariance(&self.samples_of(dofs)) / (self.spread * self.spread)
    }
}

/// Sample covariance matrix (divisor n - 1) of rows of equal length (the
/// columns are the variables).
pub fn covariance<R: AsRef<[f64]>>(rows: &[R]) -> DMatrix<f64> {
    let n = rows.len() as f64;
    let p = rows.first().map_or(0, |r| r.as_ref().len());
    let mean: Vec<f64> = (0..p)
        .map(|j| rows.iter().map(|r| r.as_ref()[j]).sum::<f64>() / n)
        .collect();
    let mut c = DMatrix::zeros(p, p);
    for r in rows {
        let r = r.as_ref();
        for a in 0..p {
            for b in 0..p {
                c[(a, b)] += (r[a] - mean[a]) * (r[b] - mean[b]);
            }
        }
    }
    c / (n - 1.0)
}
