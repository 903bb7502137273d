//! The model studies of a calibration: Monte Carlo studies of the scene
//! with fitted parameters replaced (one study plan, its variant of the
//! scene with the parameters set: `super::params`), giving the pose
//! samples of one evaluation point and their covariance.

use nalgebra::DMatrix;

use super::error::CalibrateError;
use crate::param::{Param, ParamError};
use crate::study::provenance::Fingerprint;
use crate::study::runner::run_variant;
use crate::study::{StudyPlan, Variant};

/// Samples of the model studies (`model_samples`): the relative standard
/// error of a model variance, sqrt(2 / (N - 1)) = 3.2 % at 2000, is small
/// against that of a 50-cycle measurement (20 %).
pub const MODEL_SAMPLES: usize = 2000;

/// Seed of the model studies (`seed`); a synthetic measurement must use another.
pub const MODEL_SEED: u64 = 15_015;

/// Fewest samples of a model study (`model_samples` of a calibration,
/// `samples` of a prediction).
pub const MIN_MODEL_SAMPLES: usize = 100;

/// A model study's sample count `n`, given as `param`: at least
/// [`MIN_MODEL_SAMPLES`].
pub fn check_model_samples(param: Param, n: usize) -> Result<usize, ParamError> {
    if n < MIN_MODEL_SAMPLES {
        return Err(ParamError::new(
            param,
            format!("{}: need at least {MIN_MODEL_SAMPLES} samples", param.with(n)),
        ));
    }
    Ok(n)
}

/// What every model study of a calibration shares: the plan of the
/// scene's Monte Carlo study (`plan.variants[0]`, the scene as given).
#[derive(Debug, Clone, Copy)]
pub struct StudySpec<'a> {
    pub plan: &'a StudyPlan,
    /// Index of the measured evaluation point.
    pub point: usize,
    pub dofs: &'a [usize],
}

/// The pose samples of one point at one spread.
#[derive(Debug, Clone, PartialEq)]
pub struct ModelStudy {
    pub spread: f64,
    /// The pose samples of the point (the six DOFs of [`crate::dof::Dof::ALL`]) [SI].
    pub rows: Vec<[f64; 6]>,
    pub fingerprint: Fingerprint,
}

impl StudySpec<'_> {
    /// The scene as given.
    pub fn base(&self) -> &Variant {
        &self.plan.variants[0]
    }

    /// The model study of `v` (the scene with parameters set) at its own
    /// spread. The same seed draws the same design rows at every spread
    /// and node (common random numbers), so the ratio of two model studies
    /// carries little sampling noise.
    pub fn run(&self, v: &Variant) -> Result<ModelStudy, CalibrateError> {
        let s = &self.plan.settings;
        let run = run_variant(s, v, &|| {})?;
        let spread = v.scene.mu_scale();
        if let Some(reason) = run.cannot_seat {
            return Err(CalibrateError::CannotSeat {
                file: v.file().to_string(),
                reason: format!("{reason} (model study at spread {spread})"),
            });
        }
        let point = self.point;
        Ok(ModelStudy {
            spread,
            rows: (run.records.iter())
                .map(|r| std::array::from_fn(|j| r.outputs[6 * point + j]))
                .collect(),
            fingerprint: Fingerprint::new(&v.scene, s, &run.design),
        })
    }
}

impl ModelStudy {
    pub fn samples_of(&self, dofs: &[usize]) -> Vec<Vec<f64>> {
        self.rows.iter().map(|r| dofs.iter().map(|&d| r[d]).collect()).collect()
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
    let mean: Vec<f64> =
        (0..p).map(|j| rows.iter().map(|r| r.as_ref()[j]).sum::<f64>() / n).collect();
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
