//! Errors of the calibration module: bad measurement files, bad options,
//! and model studies that could not run.

use thiserror::Error;

use super::units::UnitError;
use crate::param::{Param, ParamError};
use crate::study::StudyError;

/// A calibration or prediction could not be made.
#[derive(Debug, Error)]
pub enum CalibrateError {
    /// A bad value or header in a measurement file.
    #[error("{file}: line {line}, column {column}: {reason}")]
    Parse {
        file: String,
        line: usize,
        /// 1-based column number and header name, e.g. "2 (x_nm)".
        column: String,
        reason: String,
    },
    /// A measurement file that is wrong as a whole (too few cycles, no DOF).
    #[error("{file}: line {line}: {reason}")]
    File { file: String, line: usize, reason: String },
    /// Bad measured numbers given as an array (`Measurement::from_cycles`).
    #[error("{origin}: {reason}")]
    Array { origin: String, reason: String },
    #[error("{file}: cannot read: {reason}")]
    Read { file: String, reason: String },
    /// A bad `noise` entry (or `# noise:` metadata).
    #[error("{origin}: {reason}")]
    Noise { origin: String, reason: UnitError },
    /// A parameter name `fit` does not know.
    #[error(
        "{}: unknown parameter (known: spread, mu_static, dynamic_ratio, support_compliance)",
        Param::Fit.with(.0)
    )]
    UnknownParameter(String),
    /// A parameter named twice in `fit`.
    #[error("{}: named twice", Param::Fit.with(.0))]
    DuplicateParameter(String),
    /// An empty `fit` list or an empty name in it.
    #[error(
        "{}: empty parameter name (give a comma-separated list of spread, mu_static, \
         dynamic_ratio, support_compliance)",
        Param::Fit
    )]
    EmptyFit,
    /// An option out of range (the model samples, ...).
    #[error(transparent)]
    Param(#[from] ParamError),
    /// The measured evaluation point is not in the scene.
    #[error("{file}: evaluation point `{point}` is not in the scene (it has: {have})")]
    Point { file: String, point: String, have: String },
    /// The model cannot be compared with the data (singular covariance, ...).
    #[error("{file}: {reason}")]
    Model { file: String, reason: String },
    /// A bad calibration file (`predict --calibration`).
    #[error("{file}: not a kinrepro calibration file: {reason}")]
    Calibration { file: String, reason: String },
    /// A calibrated point (estimates or a region point) that does not apply
    /// to the predicted scene: names the calibration file and the point.
    #[error("{calibration}: {at} applied to {scene}: {reason}")]
    Applied { calibration: String, at: String, scene: String, reason: String },
    /// A coupling that cannot seat ([`crate::study::verdict::cannot_seat`]):
    /// its scatter is not a prediction.
    #[error("{file}: cannot seat: {reason}")]
    CannotSeat { file: String, reason: String },
    /// A model study could not be planned or run (its message names the scene).
    #[error(transparent)]
    Study(#[from] StudyError),
}
