//! Which solver path served the seatings of a study, and how finely the
//! load path was followed: counted by the rayon workers as samples
//! finish, reported as `seating_paths` and `load_path` of a variant.

use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};

use serde::{Deserialize, Serialize};

use crate::contact::friction;
use crate::solve::{SeatedPose, SeatingPath};

/// How many sample seatings each solver path served (`seating_paths` of a
/// study variant's JSON): the quasi-static fast path (`uniform`), the
/// adaptive path where it declined (`adaptive`), the dynamic solver
/// (`dynamic`). A sample with tolerances varied seats twice; the nominal
/// seating is not counted.
#[derive(Debug, Clone, Copy, Default, PartialEq, Eq, Serialize, Deserialize)]
pub struct SeatingPaths {
    pub uniform: usize,
    pub adaptive: usize,
    pub dynamic: usize,
}

impl SeatingPaths {
    /// The counts of several runs (shards) added; `None` if any lacks them.
    pub fn total(parts: impl IntoIterator<Item = Option<SeatingPaths>>) -> Option<SeatingPaths> {
        parts.into_iter().try_fold(SeatingPaths::default(), |a, p| {
            p.map(|p| SeatingPaths {
                uniform: a.uniform + p.uniform,
                adaptive: a.adaptive + p.adaptive,
                dynamic: a.dynamic + p.dynamic,
            })
        })
    }
}

/// Sample seatings whose decay-law c v_slip lies in the transition
/// ([`friction::TRANSITION`]): not converged (stderr warning of a study).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Unconverged {
    pub seatings: usize,
    /// The largest c v_slip among them.
    pub max_cv: f64,
}

/// The load path of a variant's quasi-static sample seatings (`load_path`
/// of a study variant's JSON): the largest estimated path error and the
/// load increments taken. Integers and a maximum, so that the shards of a
/// study add to exactly the unsharded numbers ([`LoadPath::total`]).
#[derive(Debug, Clone, Copy, Default, PartialEq, Serialize, Deserialize)]
pub struct LoadPath {
    /// Quasi-static sample seatings counted.
    pub seatings: usize,
    /// The largest `path_error` of them (`None`: none was estimated, the
    /// fixed `--increments`).
    pub max_path_error: Option<f64>,
    /// Load increments of all of them, and the most one took.
    pub increments_total: u64,
    pub increments_max: usize,
    /// increments_total / seatings (0 without seatings).
    pub increments_mean: f64,
}

impl LoadPath {
    fn new(seatings: usize, max_path_error: Option<f64>, total: u64, max: usize) -> Self {
        LoadPath {
            seatings,
            max_path_error,
            increments_total: total,
            increments_max: max,
            increments_mean: if seatings == 0 { 0.0 } else { total as f64 / seatings as f64 },
        }
    }

    /// Several runs (shards) together: seatings and increments added, the
    /// larger maxima, the mean over all seatings; `None` if any lacks them.
    pub fn total(parts: impl IntoIterator<Item = Option<LoadPath>>) -> Option<LoadPath> {
        let sum = parts.into_iter().try_fold((0, None, 0, 0), |a, p| {
            p.map(|p| {
                let error = match (a.1, p.max_path_error) {
                    (Some(x), Some(y)) => Some(f64::max(x, y)),
                    (x, y) => x.or(y),
                };
                let max = a.3.max(p.increments_max);
                (a.0 + p.seatings, error, a.2 + p.increments_total, max)
            })
        })?;
        Some(LoadPath::new(sum.0, sum.1, sum.2, sum.3))
    }
}

/// [`SeatingPaths`], [`LoadPath`] and the [`Unconverged`] seatings counted
/// by the rayon workers of a run.
#[derive(Debug, Default)]
pub struct PathTally {
    paths: [AtomicUsize; 3],
    /// Quasi-static seatings, their increments and the most one took.
    seatings: AtomicUsize,
    increments: AtomicU64,
    increments_max: AtomicUsize,
    /// The bits of the largest path error + 1 (0: none estimated); the
    /// bits of non-negative f64 order as the numbers do.
    error_bits: AtomicU64,
    /// Seatings of the decay law in its transition, and the bits of their
    /// largest c v_slip.
    unconverged: AtomicUsize,
    cv_bits: AtomicU64,
}

impl PathTally {
    /// Count one sample seating: its path, a decay-law c v_slip in the
    /// transition, and for a quasi-static one its increments and path error.
    pub fn record(&self, seated: &SeatedPose) {
        if let Some(cv) = seated.decay_cv.filter(|&cv| friction::in_transition(cv)) {
            self.unconverged.fetch_add(1, Ordering::Relaxed);
            self.cv_bits.fetch_max(cv.to_bits(), Ordering::Relaxed);
        }
        let k = match seated.path {
            SeatingPath::Uniform => 0,
            SeatingPath::Adaptive => 1,
            SeatingPath::Dynamic => 2,
        };
        self.paths[k].fetch_add(1, Ordering::Relaxed);
        if k == 2 {
            return;
        }
        self.seatings.fetch_add(1, Ordering::Relaxed);
        let n = seated.increments;
        self.increments.fetch_add(n as u64, Ordering::Relaxed);
        self.increments_max.fetch_max(n, Ordering::Relaxed);
        if let Some(e) = seated.path_error {
            let bits = e.max(0.0).to_bits() + 1;
            self.error_bits.fetch_max(bits, Ordering::Relaxed);
        }
    }

    /// The load path of the quasi-static seatings counted (`None` if none).
    pub fn load_path(&self) -> Option<LoadPath> {
        let seatings = self.seatings.load(Ordering::Relaxed);
        let bits = self.error_bits.load(Ordering::Relaxed);
        let error = (bits > 0).then(|| f64::from_bits(bits - 1));
        let total = self.increments.load(Ordering::Relaxed);
        let max = self.increments_max.load(Ordering::Relaxed);
        (seatings > 0).then(|| LoadPath::new(seatings, error, total, max))
    }

    pub fn counts(&self) -> SeatingPaths {
        let n = |k: usize| self.paths[k].load(Ordering::Relaxed);
        SeatingPaths { uniform: n(0), adaptive: n(1), dynamic: n(2) }
    }

    /// The seatings counted in the transition, if any.
    pub fn unconverged(&self) -> Option<Unconverged> {
        let seatings = self.unconverged.load(Ordering::Relaxed);
        (seatings > 0).then(|| Unconverged {
            seatings,
            max_cv: f64::from_bits(self.cv_bits.load(Ordering::Relaxed)),
        })
    }
}
