//! Bounds on the run sizes a user controls (samples, the Sobol base size),
//! derived from what one machine can do. A seating of a three-contact
//! coupling costs about 50 us of one core (the quasi-static solver, scene 01).
//!
//! - A run that keeps its records (a Latin hypercube or small Monte Carlo
//!   design, a shard, the Saltelli matrices of `--sensitivity`) holds each
//!   seating's inputs and outputs as f64: with a few inputs and one
//!   evaluation point about 200 bytes. [`MAX_KEPT_SEATINGS`] = 2^24
//!   (16.8 M) records are about 3.4 GB and 14 core-minutes.
//! - A streamed Monte Carlo study keeps only moments, so its memory is
//!   bounded whatever its size; its time and its per-sample CSV are not:
//!   [`MAX_STREAMED_SAMPLES`] = 10^8 samples are about 80 core-minutes and a
//!   CSV of about 20 GB.

use super::error::StudyError;

/// Most seatings whose records one run keeps in memory.
pub const MAX_KEPT_SEATINGS: usize = 1 << 24;

/// Most samples of one streamed Monte Carlo study.
pub const MAX_STREAMED_SAMPLES: usize = 100_000_000;

/// `count` (what it counts: `what`) against `max`.
pub fn check(what: &'static str, count: Option<usize>, max: usize) -> Result<usize, StudyError> {
    match count {
        Some(n) if n <= max => Ok(n),
        n => Err(StudyError::AboveBound {
            what,
            count: n.map_or("more than 2^64".into(), |n| n.to_string()),
            max,
        }),
    }
}
