//! Long runs off the GIL, stoppable by Ctrl-C.
//!
//! The work runs on its own thread (and the library's rayon pool, or a pool
//! of `jobs` threads) while the calling thread waits with the GIL released
//! and checks Python's signals every 50 ms. On Ctrl-C the library's
//! progress tick (called once per seating) unwinds the run with a private
//! payload through `resume_unwind` (no panic message: the hook is not
//! called); rayon carries it to the worker thread, which catches it, so
//! the run stops after the seatings in flight. A run without a tick
//! (calibrate, predict) goes on to its end on its thread and its result is
//! dropped; Python gets its `KeyboardInterrupt` at once either way.

use std::panic::{AssertUnwindSafe, catch_unwind, resume_unwind};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::mpsc;
use std::time::Duration;

use pyo3::exceptions::PyRuntimeError;
use pyo3::prelude::*;

/// The payload that stops a run.
struct Cancelled;

/// What a run returns: its value or the library's message.
pub type Outcome<T> = Result<T, String>;

/// Run `work` (given the tick to pass to the library) off the GIL on
/// `jobs` threads (None: the global pool, all cores).
pub fn interruptible<T, F>(py: Python<'_>, jobs: Option<usize>, work: F) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce(&(dyn Fn() + Sync)) -> Outcome<T> + Send + 'static,
{
    if jobs == Some(0) {
        return Err(crate::err("jobs=0: need at least 1 worker thread"));
    }
    let pool = match jobs {
        None => None,
        Some(j) => Some(
            rayon::ThreadPoolBuilder::new()
                .num_threads(j)
                .build()
                .map_err(crate::err)?,
        ),
    };
    let stop = Arc::new(AtomicBool::new(false));
    let (tx, rx) = mpsc::channel();
    let flag = stop.clone();
    std::thread::spawn(move || {
        let tick = move || {
            if flag.load(Ordering::Relaxed) {
                resume_unwind(Box::new(Cancelled));
            }
        };
        let body = AssertUnwindSafe(|| match &pool {
            Some(p) => p.install(|| work(&tick)),
            None => work(&tick),
        });
        let _ = tx.send(catch_unwind(body));
    });
    let mut rx = rx;
    loop {
        // The receiver crosses into the GIL-free closure and back (it is
        // Send, not Sync).
        let (got, back) = py.detach(move || (rx.recv_timeout(Duration::from_millis(50)), rx));
        rx = back;
        match got {
            Ok(Ok(Ok(v))) => return Ok(v),
            Ok(Ok(Err(message))) => return Err(crate::err(message)),
            Ok(Err(payload)) if payload.is::<Cancelled>() => {
                // Only after a signal; check_signals below raised it already.
                return Err(PyRuntimeError::new_err("kinrepro: run cancelled"));
            }
            Ok(Err(payload)) => return Err(PyRuntimeError::new_err(panic_text(&payload))),
            Err(mpsc::RecvTimeoutError::Timeout) => {
                if let Err(e) = py.check_signals() {
                    stop.store(true, Ordering::Relaxed);
                    return Err(e);
                }
            }
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                return Err(PyRuntimeError::new_err("kinrepro: the worker thread died"));
            }
        }
    }
}

fn panic_text(payload: &Box<dyn std::any::Any + Send>) -> String {
    let m = payload
        .downcast_ref::<String>()
        .cloned()
        .or_else(|| payload.downcast_ref::<&str>().map(|s| s.to_string()))
        .unwrap_or_else(|| "unknown".into());
    format!("kinrepro panicked (a bug, please report it): {m}")
}
