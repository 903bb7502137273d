//! Calibration of the friction spread on measured re-seating scatter, and
//! prediction of other designs with the calibrated spread (issue 15; the
//! paper's remedy: "the variation of the coefficient of friction in the
//! model can be refined based on measurement results").
//!
//! * [`measurement`]: the measured-data formats (docs/measurements.md).
//! * [`model`]: the model covariance of one point from a Monte Carlo study.
//! * [`likelihood`]: Wishart / chi-square likelihood, the profile-likelihood
//!   interval of the spread, the goodness-of-fit test.
//! * [`fit`]: the calibration ([`Calibration`], the calibration file).
//! * [`predict`]: sigma of other scenes at the calibrated spread, with a
//!   prediction interval.

pub mod chi2;
pub mod error;
pub mod fit;
pub mod likelihood;
pub mod measurement;
pub mod model;
pub mod predict;
pub mod units;

pub use error::CalibrateError;
pub use fit::{CalibrateOptions, Calibration, calibrate};
pub use measurement::{MeasuredData, Measurement};
pub use model::ModelStudy;
pub use predict::{Prediction, predict};
