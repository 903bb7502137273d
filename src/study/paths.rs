//! Which solver path served the seatings of a study: counted by the rayon
//! workers as samples finish, reported as `seating_paths` of a variant.

use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};

use serde::{Deserialize, Serialize};

use crate::contact::friction;
use crate::solve::{Seating, SeatingPath};

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

/// [`SeatingPaths`] counted by the rayon workers of a run, and the
/// [`Unconverged`] seatings: their count and largest c v_slip (the bits of
/// a non-negative f64 order as the numbers do).
#[derive(Debug, Default)]
pub struct PathTally([AtomicUsize; 3], AtomicUsize, AtomicU64);

impl PathTally {
    /// Count the path of `seating` and pass it on.
    pub fn count(&self, seating: Seating) -> Seating {
        self.record(seating.path, seating.decay_cv);
        seating
    }

    /// Count one seating served by `path` with the decay law's `decay_cv`.
    pub fn record(&self, path: SeatingPath, decay_cv: Option<f64>) {
        if let Some(cv) = decay_cv.filter(|&cv| friction::in_transition(cv)) {
            self.1.fetch_add(1, Ordering::Relaxed);
            self.2.fetch_max(cv.to_bits(), Ordering::Relaxed);
        }
        let k = match path {
            SeatingPath::Uniform => 0,
            SeatingPath::Adaptive => 1,
            SeatingPath::Dynamic => 2,
        };
        self.0[k].fetch_add(1, Ordering::Relaxed);
    }

    pub fn counts(&self) -> SeatingPaths {
        let n = |k: usize| self.0[k].load(Ordering::Relaxed);
        SeatingPaths {
            uniform: n(0),
            adaptive: n(1),
            dynamic: n(2),
        }
    }

    /// The seatings counted in the transition, if any.
    pub fn unconverged(&self) -> Option<Unconverged> {
        let seatings = self.1.load(Ordering::Relaxed);
        (seatings > 0).then(|| Unconverged {
            seatings,
            max_cv: f64::from_bits(self.2.load(Ordering::Relaxed)),
        })
    }
}
