//! Calibration of the friction spread on measured re-seating scatter, and
//! prediction of other designs with the calibrated spread (issue 15; the
//! paper's remedy: "the variation of the coefficient of friction in the
//! model can be refined based on measurement results").
//!
//! * [`measurement`]: the measured-data formats (docs/measurements.md).
//! * [`model`]: the model covariance of one point from a Monte Carlo study.
//! * [`likelihood`]: Wishart / chi-square likelihood, the profile-likelihood
//!   interval of the spread, the goodness-of-fit test.
//! * [`fit`]: the calibration ([`Calibration`], the calibration file); the
//!   spread alone.
//! * [`params`]: the parameters `--fit` may name and their searched ranges.
//! * [`grid`], [`joint`], [`information`], [`joint_fit`]: several parameters
//!   (the model covariance on a common-random-number grid, the joint
//!   profile likelihood, its sandwich factors and model error).
//! * [`predict`]: sigma of other scenes at the calibrated parameters, with a
//!   prediction interval.

pub mod chi2;
pub mod error;
pub mod file;
pub mod fit;
pub mod grid;
pub mod information;
pub mod joint;
pub mod joint_fit;
pub mod likelihood;
pub mod measurement;
pub mod model;
pub mod params;
pub mod predict;
pub mod units;

pub use error::CalibrateError;
pub use fit::{CalibrateOptions, Calibration, calibrate};
pub use measurement::{MeasuredData, Measurement};
pub use model::ModelStudy;
pub use predict::{Prediction, predict};
