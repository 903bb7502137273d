//! The error of running one scene's study ([`super::runner`]): the design,
//! the options, a perturbed coupling, the nominal seating, the probe
//! seatings of [`super::verdict`] or one sample's seating.

use thiserror::Error;

use super::StudyError;
use crate::assembly::AssemblyError;
use crate::solve::SolveError;

/// A study could not be run.
#[derive(Debug, Error)]
pub enum RunError {
    /// A stop was asked for ([`crate::cancel`]).
    #[error("interrupted")]
    Cancelled,
    #[error("{file}: {source}")]
    Design {
        file: String,
        #[source]
        source: StudyError,
    },
    #[error("{file}: {reason}")]
    Options { file: String, reason: String },
    #[error(
        "{file}: sample {index}: the coupling perturbed by the drawn tolerances does not \
         assemble: {source}"
    )]
    Perturbed {
        file: String,
        index: usize,
        #[source]
        source: AssemblyError,
    },
    #[error(
        "{file}: the nominal seating (the reference of every sample; mu_s = {mu:?}, touching start) failed: {source}"
    )]
    Nominal {
        file: String,
        mu: Vec<f64>,
        #[source]
        source: SolveError,
    },
    #[error(
        "{file}: the seating at mu_s = {mu:?} (touching start) that tells whether friction \
         moves the pose failed: {source}"
    )]
    FrictionProbe {
        file: String,
        mu: Vec<f64>,
        #[source]
        source: SolveError,
    },
    #[error("{file}: sample {index} (mu_s = {mu:?}): {source}")]
    Seating {
        file: String,
        index: usize,
        mu: Vec<f64>,
        #[source]
        source: SolveError,
    },
}
