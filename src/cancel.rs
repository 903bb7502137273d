//! A process-wide request to stop the run in progress (set by the CLI on
//! SIGINT or SIGTERM, by the Python package on Ctrl-C). The study loops
//! check it before each seating, a sweep before each design point and the
//! dynamic solver before each time step, and return an error: the run
//! unwinds normally, so every temporary output file is deleted by its
//! destructor and nothing half-written is renamed over a result.

use std::sync::atomic::{AtomicBool, Ordering};

static REQUESTED: AtomicBool = AtomicBool::new(false);

/// Ask the run in progress to stop (async-signal-safe: one atomic store).
pub fn request() {
    REQUESTED.store(true, Ordering::SeqCst);
}

/// Whether a stop was asked for.
pub fn requested() -> bool {
    REQUESTED.load(Ordering::Relaxed)
}

/// Withdraw the request once the runs it stopped have ended: a host that
/// outlives its runs (the Python package, after Ctrl-C) can run again.
pub fn withdraw() {
    REQUESTED.store(false, Ordering::SeqCst);
}
