//! Bounds on the run sizes a user controls (samples, the Sobol base size),
//! derived from what one machine can do. A seating of a three-contact
//! coupling costs about 21 us of one core (the quasi-static solver, scene 01).
//!
//! - A run that keeps its records (a Latin hypercube or small Monte Carlo
//!   design, a shard, the Saltelli matrices of `--sensitivity`) holds each
//!   seating's inputs and outputs as f64: with a few inputs and one
//!   evaluation point about 200 bytes. [`MAX_KEPT_SEATINGS`] = 2^24
//!   (16.8 M) records are about 3.4 GB and 6 core-minutes of scene 01.
//! - A streamed Monte Carlo study keeps only moments, so its memory is
//!   bounded whatever its size; its time and its per-sample CSV are not:
//!   [`MAX_STREAMED_SAMPLES`] = 10^8 samples are about 35 core-minutes and a
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

/// Typical cost of one seating on one core [s], rounded up: a quasi-static
/// seating of a three-contact coupling on the controlled path of 9
/// increments, 50 us (measured 21 us for scene 01, 38 us for scene 02 and
/// 20 us for scene 06 in 20 000-sample one-job studies), or
/// [`SECONDS_PER_INCREMENT`] per increment where fixed increments
/// (`--increments N`) cost more; a dynamic one 4 ms (measured 1.6 to 2.2
/// ms from the touching pose, 2.3 to 3.2 ms arriving off-centre, scenes 01
/// and 06). Measured on the development machine; a run's progress line
/// gives the measured rate.
pub fn seating_seconds(method: &crate::solve::Method) -> f64 {
    match method {
        crate::solve::Method::QuasiStatic(o) if o.path_tolerance.is_none() => {
            (o.increments as f64 * SECONDS_PER_INCREMENT).max(50e-6)
        }
        crate::solve::Method::QuasiStatic(_) => 50e-6,
        crate::solve::Method::Dynamic(_) => 4e-3,
    }
}

/// One fixed load increment of a scene-01 seating on one core [s]:
/// `run --increments 100000` takes 0.18 s.
pub const SECONDS_PER_INCREMENT: f64 = 1.8e-6;

/// Runs estimated above this many seconds say so before they start.
pub const ANNOUNCE_ABOVE_S: f64 = 60.0;

/// The estimate of a run of `seatings` on `threads` threads, if it is
/// above [`ANNOUNCE_ABOVE_S`]: one line for the terminal.
pub fn estimate_note(
    seatings: usize,
    method: &crate::solve::Method,
    threads: usize,
) -> Option<String> {
    let per = seating_seconds(method);
    let s = seatings as f64 * per / threads.max(1) as f64;
    (s > ANNOUNCE_ABOVE_S).then(|| {
        format!(
            "note: {seatings} seatings, estimated about {:.0} min on {} thread(s) \
             (about {:.0} us per seating on one core; Ctrl-C stops the run and removes \
             its temporary files)",
            s / 60.0,
            threads.max(1),
            per * 1e6
        )
    })
}
