//! Calibration of the friction spread on measured re-seating scatter, and
//! prediction of other designs with the calibrated spread (the paper's
//! remedy: "the variation of the coefficient of friction in the
//! model can be refined based on measurement results").
//!
//! * [`measurement`]: the measured-data formats (docs/measurements.md);
//!   [`measured_array`]: the same cycles given as numbers in SI.
//! * [`model`]: the model covariance of one point from a Monte Carlo study.
//! * [`params`]: the parameters `--fit` may name and their searched ranges.
//! * [`grid`]: the model covariance on a common-random-number grid over the
//!   fitted parameters other than the spread (one study for the spread alone).
//! * [`likelihood`]: the Wishart / chi-square likelihood and the
//!   goodness-of-fit test.
//! * [`joint`], [`information`]: the likelihood of the fitted parameters,
//!   its estimate and profile intervals; the sandwich factors and the model
//!   study's error.
//! * [`fit`]: the calibration of one or several parameters ([`Calibration`],
//!   the calibration file of [`file`]).
//! * [`predict`]: sigma of other scenes at the calibrated parameters, with a
//!   prediction interval.

pub mod error;
pub mod file;
pub mod fit;
pub mod grid;
pub mod information;
pub mod joint;
pub mod likelihood;
pub mod measured_array;
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
