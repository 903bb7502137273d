//! The remaining time a progress bar shows: only once it means something.
//!
//! The first seatings of a study include the nominal seatings and the thread
//! start-up, so a rate taken over them extrapolates to hours for a job of
//! seconds. The estimate is shown after [`MIN_ELAPSED`] and [`MIN_SHARE`] of
//! the work, from the mean rate since the start: elapsed * (total - done) / done.

use std::time::Duration;

/// Time before any estimate is shown.
pub const MIN_ELAPSED: Duration = Duration::from_secs(3);

/// Share of the work done before any estimate is shown.
pub const MIN_SHARE: f64 = 0.05;

/// The remaining time after `done` of `total` steps in `elapsed`, or None
/// while it is not yet meaningful (too early, too little done, or finished).
pub fn remaining(elapsed: Duration, done: u64, total: u64) -> Option<Duration> {
    if elapsed < MIN_ELAPSED || done == 0 || done >= total {
        return None;
    }
    if (done as f64) < MIN_SHARE * total as f64 {
        return None;
    }
    Some(elapsed.mul_f64((total - done) as f64 / done as f64))
}
