//! SIGINT, SIGTERM, SIGHUP (a closed terminal or ssh session), SIGQUIT,
//! SIGUSR1 and SIGUSR2 ([`HANDLED`], `signal-hook`): the first asks the
//! library to stop ([`kinrepro::cancel`]); the run unwinds, its temporary
//! files are deleted by their destructors, and the process exits 128 + the
//! signal (130, 143, 129, 131, 138, 140).
//! A command that does not check the request (a single long FE solve) is
//! stopped after [`GRACE`], as is any run at a second signal, but never in
//! the middle of [`commit`]: a folder of outputs is renamed whole or not at
//! all. That exit does not unwind: it deletes the registered temporaries
//! ([`kinrepro::output::temporaries`]) first.

use std::sync::Mutex;
use std::sync::atomic::{AtomicI32, Ordering};
use std::time::Duration;

use kinrepro::output::atomic::{AtomicFile, commit_all};
use signal_hook::consts::{SIGHUP, SIGINT, SIGQUIT, SIGTERM, SIGUSR1, SIGUSR2};
use signal_hook::iterator::Signals;

use crate::error::Error;

/// Time a run has to unwind after the first signal.
pub const GRACE: Duration = Duration::from_secs(3);

/// The first signal received (0: none).
static RECEIVED: AtomicI32 = AtomicI32::new(0);

/// Held while output files are renamed into place.
static COMMITTING: Mutex<()> = Mutex::new(());

/// The signals that stop a run as SIGTERM does, with their names. Each of
/// the others would end the process without unwinding (SIGQUIT with a
/// core dump) and leave its temporaries behind.
const HANDLED: [(i32, &str); 6] = [
    (SIGINT, "SIGINT"),
    (SIGTERM, "SIGTERM"),
    (SIGHUP, "SIGHUP"),
    (SIGQUIT, "SIGQUIT"),
    (SIGUSR1, "SIGUSR1"),
    (SIGUSR2, "SIGUSR2"),
];

/// Handle the signals of [`HANDLED`] on a thread of their own.
pub fn install() -> Result<(), Error> {
    let mut signals = Signals::new(HANDLED.map(|(sig, _)| sig))
        .map_err(|e| Error::new(format!("cannot handle signals: {e}")))?;
    std::thread::spawn(move || {
        for sig in signals.forever() {
            if RECEIVED.compare_exchange(0, sig, Ordering::SeqCst, Ordering::SeqCst).is_err() {
                stop(sig);
            }
            kinrepro::cancel::request();
            std::thread::spawn(move || {
                std::thread::sleep(GRACE);
                stop(sig);
            });
        }
    });
    Ok(())
}

/// Exit now with 128 + `sig` (after any commit in progress), deleting the
/// temporaries no destructor will delete.
fn stop(sig: i32) -> ! {
    let _hold = COMMITTING.lock();
    kinrepro::output::temporaries::remove_all();
    // Not `eprintln!`: it panics when stderr is closed (its reader gone),
    // which would end this thread before the exit and leave a run blocked
    // (opening a FIFO without a reader) running for ever.
    crate::say(&format!("kinrepro: {}: stopped", name(sig)));
    std::process::exit(128 + sig)
}

fn name(sig: i32) -> &'static str {
    HANDLED.iter().find(|(s, _)| *s == sig).map_or("signal", |(_, n)| n)
}

/// The exit code and message of a run stopped by a signal, if one came.
pub fn received() -> Option<(u8, String)> {
    match RECEIVED.load(Ordering::SeqCst) {
        0 => None,
        sig => Some((
            (128 + sig) as u8,
            format!("{}: interrupted; no output file replaced by a partial one", name(sig)),
        )),
    }
}

/// Rename `files` into place, all of them, or none once a stop was asked
/// for; returns their paths.
pub fn commit(files: Vec<AtomicFile>) -> Result<Vec<String>, Error> {
    let _hold = COMMITTING.lock();
    if kinrepro::cancel::requested() {
        return Err(Error::new("interrupted"));
    }
    Ok(commit_all(files)?)
}
