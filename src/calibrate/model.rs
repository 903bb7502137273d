//! The model's covariance of one evaluation point's pose at a given
//! friction spread, from a Monte Carlo study (`study::runner::run_variant`)
//! of the scene with `[friction] spread` replaced.

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

/// The covariance of one point's six DOFs at one spread.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelStudy {
    pub spread: f64,
    pub samples: usize,
    pub seed: u64,
    /// Index of the evaluation point.
    pub point: usize,
    /// 6x6 covariance (divisor N - 1) of x, y, z, phi_x, phi_y, phi_z [SI].
    pub cov: DMatrix<f64>,
    /// The pose samples of the point (x, y, z, phi_x, phi_y, phi_z) [SI].
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

impl ModelStudy {
    /// Run the model study of point `point` at `spread`. The same seed
    /// draws the same design rows at every spread (common random numbers),
    /// so the ratio of two model studies carries little sampling noise.
    pub fn run(
        coupling: &Coupling,
        point: usize,
        spread: f64,
        samples: usize,
        seed: u64,
        method: Method,
    ) -> Result<Self, CalibrateError> {
        let c = with_spread(coupling, spread);
        let opts = model_options(samples, seed, method);
        let run = run_variant(&c, &opts, &|| {})?;
        let rows: Vec<[f64; 6]> = run
            .records
            .iter()
            .map(|r| std::array::from_fn(|j| r.outputs[6 * point + j]))
            .collect();
        Ok(ModelStudy {
            spread,
            samples,
            seed,
            point,
            cov: covariance(&rows),
            rows,
            fingerprint: Fingerprint::new(&c, &opts, &run.design),
        })
    }

    /// Covariance per unit spread^2 of the DOFs `dofs`: G = C / s^2.
    pub fn per_unit(&self, dofs: &[usize]) -> DMatrix<f64> {
        let s2 = self.spread * self.spread;
        DMatrix::from_fn(dofs.len(), dofs.len(), |a, b| {
            self.cov[(dofs[a], dofs[b])] / s2
        })
    }
}

impl ModelStudy {
    /// The pose samples of the DOFs `dofs`.
    pub fn samples_of(&self, dofs: &[usize]) -> Vec<Vec<f64>> {
        self.rows
            .iter()
            .map(|r| dofs.iter().map(|&d| r[d]).collect())
            .collect()
    }
}

/// Sample covariance (divisor n - 1) of rows of six values.
pub fn covariance(rows: &[[f64; 6]]) -> DMatrix<f64> {
    let n = rows.len() as f64;
    let mean: [f64; 6] = std::array::from_fn(|j| rows.iter().map(|r| r[j]).sum::<f64>() / n);
    let mut c = DMatrix::zeros(6, 6);
    for r in rows {
        for a in 0..6 {
            for b in 0..6 {
                c[(a, b)] += (r[a] - mean[a]) * (r[b] - mean[b]);
            }
        }
    }
    c / (n - 1.0)
}
