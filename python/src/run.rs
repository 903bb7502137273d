//! Long runs off the GIL, stoppable by Ctrl-C.
//!
//! The work runs on a thread of its own (on the library's rayon pool, or a
//! pool of `jobs` threads) while the calling thread waits with the GIL
//! released and checks Python's signals every 50 ms. On Ctrl-C it asks the
//! library to stop (`kinrepro::cancel::request`, checked before every
//! seating and every time step of the dynamic solver, as for the CLI's
//! SIGINT), waits for the run to end (at most [`GRACE`]) and raises the
//! `KeyboardInterrupt`. The request is process-wide, as Ctrl-C is: it stops
//! every kinrepro run in flight, and any of them raises `KeyboardInterrupt`;
//! it is withdrawn when the last of them has ended, so the next call runs.

use std::panic::{AssertUnwindSafe, catch_unwind};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::mpsc;
use std::time::Duration;

use kinrepro::cancel;
use pyo3::exceptions::{PyKeyboardInterrupt, PyRuntimeError};
use pyo3::prelude::*;

/// Longest wait for a run to stop after Ctrl-C before raising anyway (the
/// run then ends on its own thread).
const GRACE: Duration = Duration::from_secs(5);

/// How often the waiting thread checks Python's signals.
const POLL: Duration = Duration::from_millis(50);

/// What a run returns: its value or the library's message.
pub type Outcome<T> = Result<T, Failure>;

/// A failed run: the library's message (any library error converts into
/// it with `?`).
#[derive(Debug)]
pub struct Failure(pub String);

impl<E: std::error::Error> From<E> for Failure {
    fn from(e: E) -> Self {
        Failure(e.to_string())
    }
}

/// Runs in flight in this process.
static IN_FLIGHT: AtomicUsize = AtomicUsize::new(0);

/// A run in flight; the last one to end withdraws a stop request.
struct InFlight;

impl InFlight {
    fn start() -> InFlight {
        IN_FLIGHT.fetch_add(1, Ordering::SeqCst);
        InFlight
    }
}

impl Drop for InFlight {
    fn drop(&mut self) {
        if IN_FLIGHT.fetch_sub(1, Ordering::SeqCst) == 1 {
            cancel::withdraw();
        }
    }
}

/// A run's end: its outcome (or panic), and whether a stop was requested
/// while it ran.
struct Ended<T> {
    outcome: std::thread::Result<Outcome<T>>,
    stopped: bool,
}

/// Run `work` off the GIL on `jobs` threads (None: the global pool, all
/// cores); Ctrl-C stops it with `KeyboardInterrupt`.
pub fn interruptible<T, F>(py: Python<'_>, jobs: Option<usize>, work: F) -> PyResult<T>
where
    T: Send + 'static,
    F: FnOnce() -> Outcome<T> + Send + 'static,
{
    if jobs == Some(0) {
        return Err(crate::err("jobs=0: need at least 1 worker thread"));
    }
    let pool = match jobs {
        None => None,
        Some(j) => {
            Some(rayon::ThreadPoolBuilder::new().num_threads(j).build().map_err(crate::err)?)
        }
    };
    let (tx, rx) = mpsc::channel();
    let in_flight = InFlight::start();
    std::thread::spawn(move || {
        let body = AssertUnwindSafe(|| match &pool {
            Some(p) => p.install(work),
            None => work(),
        });
        let outcome = catch_unwind(body);
        let stopped = cancel::requested();
        drop(in_flight);
        let _ = tx.send(Ended { outcome, stopped });
    });
    // The receiver crosses into the GIL-free closure and back (it is Send,
    // not Sync).
    let wait = |rx: mpsc::Receiver<Ended<T>>, t| py.detach(move || (rx.recv_timeout(t), rx));
    let mut rx = rx;
    loop {
        let (got, back) = wait(rx, POLL);
        rx = back;
        match got {
            Ok(ended) => return finish(ended),
            Err(mpsc::RecvTimeoutError::Timeout) => {
                if let Err(interrupt) = py.check_signals() {
                    cancel::request();
                    let _ = wait(rx, GRACE);
                    return Err(interrupt);
                }
            }
            Err(mpsc::RecvTimeoutError::Disconnected) => {
                return Err(PyRuntimeError::new_err("kinrepro: the worker thread died"));
            }
        }
    }
}

/// The run's value, its message as `KinreproError`, `KeyboardInterrupt`
/// if a stop was requested while it ran (by Ctrl-C during another call of
/// this process), or a panic as `RuntimeError`.
fn finish<T>(ended: Ended<T>) -> PyResult<T> {
    match ended.outcome {
        Ok(_) if ended.stopped => {
            Err(PyKeyboardInterrupt::new_err("kinrepro: run stopped by Ctrl-C"))
        }
        Ok(Ok(v)) => Ok(v),
        Ok(Err(Failure(message))) => Err(crate::err(message)),
        Err(payload) => Err(PyRuntimeError::new_err(panic_text(&payload))),
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
