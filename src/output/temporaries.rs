//! The temporary files of atomic writes ([`super::atomic`]) that exist now,
//! so that an exit that does not unwind (a second signal, or the grace
//! period after the first running out: `bin/kinrepro/signals.rs`) can
//! delete them first. A normal exit or an unwinding run deletes each by its
//! destructor and unregisters it; a committed one is renamed, then
//! unregistered (deleting its old name afterwards finds nothing).
//!
//! A run killed outright (SIGKILL, a power cut) deletes nothing. Its
//! temporaries keep their names (`.NAME.kinrepro-XXXXXX.tmp` next to the
//! output NAME: [`MARK`], [`SUFFIX`]), so that a later run writing NAME
//! finds those modified before it started ([`note_stale`], reported by
//! [`stale`]) and `kinrepro clean DIR` removes them ([`remove_stale`]).

use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard, OnceLock};
use std::time::{Duration, SystemTime};

static LIVE: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// What every temporary's name carries after its output's name.
pub const MARK: &str = ".kinrepro-";
/// The end of every temporary's name.
pub const SUFFIX: &str = ".tmp";

static STARTED: OnceLock<SystemTime> = OnceLock::new();
static STALE: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

/// When this run started: fixed by the first call (the command line
/// calls it first thing; a library user at its first output).
pub fn run_started() -> SystemTime {
    *STARTED.get_or_init(SystemTime::now)
}

/// Whether `name` is a temporary's of this program (module docs).
pub fn is_temporary(name: &str) -> bool {
    name.starts_with('.') && name.ends_with(SUFFIX) && name.contains(MARK)
}

/// Note the temporaries of output `target` (same folder, `.NAME` +
/// [`MARK`]) last modified before this run started: left by a run that
/// did not end (a live run writing the same output started later, or is
/// the one that wrote them, so is older than this one only if it started
/// first).
pub fn note_stale(target: &Path) {
    let started = run_started();
    let (Some(name), Some(dir)) = (target.file_name(), target.parent()) else {
        return;
    };
    let dir = if dir.as_os_str().is_empty() { Path::new(".") } else { dir };
    let prefix = format!(".{}{MARK}", name.to_string_lossy());
    let Ok(entries) = std::fs::read_dir(dir) else {
        return;
    };
    let mut stale = STALE.lock().unwrap_or_else(|e| e.into_inner());
    for e in entries.flatten() {
        let n = e.file_name().to_string_lossy().into_owned();
        let old = e.metadata().and_then(|m| m.modified()).is_ok_and(|t| t < started);
        if n.starts_with(&prefix) && is_temporary(&n) && old && !stale.contains(&e.path()) {
            stale.push(e.path());
        }
    }
}

/// The stale temporaries noted so far ([`note_stale`]), once each.
pub fn stale() -> Vec<PathBuf> {
    std::mem::take(&mut *STALE.lock().unwrap_or_else(|e| e.into_inner()))
}

/// Remove this program's temporaries in `dir` that nothing has modified
/// for `idle` (a live run writes its own as it goes, and renames or
/// deletes it at its end); returns (removed, kept as possibly in use).
pub fn remove_stale(dir: &Path, idle: Duration) -> std::io::Result<(Vec<PathBuf>, Vec<PathBuf>)> {
    let now = SystemTime::now();
    let (mut removed, mut kept) = (Vec::new(), Vec::new());
    for e in std::fs::read_dir(dir)? {
        let e = e?;
        if !e.file_type()?.is_file() || !is_temporary(&e.file_name().to_string_lossy()) {
            continue;
        }
        let modified = e.metadata()?.modified()?;
        if now.duration_since(modified).unwrap_or_default() >= idle {
            std::fs::remove_file(e.path())?;
            removed.push(e.path());
        } else {
            kept.push(e.path());
        }
    }
    removed.sort();
    kept.sort();
    Ok((removed, kept))
}

/// The registry, usable after a panic elsewhere (a poisoned lock).
fn live() -> MutexGuard<'static, Vec<PathBuf>> {
    LIVE.lock().unwrap_or_else(|e| e.into_inner())
}

/// A temporary file's entry in the registry, removed when dropped.
#[derive(Debug)]
pub struct Registered(PathBuf);

impl Registered {
    pub fn new(path: &Path) -> Self {
        live().push(path.to_path_buf());
        Registered(path.to_path_buf())
    }
}

impl Drop for Registered {
    fn drop(&mut self) {
        let mut l = live();
        if let Some(i) = l.iter().position(|p| *p == self.0) {
            l.swap_remove(i);
        }
    }
}

/// Delete every registered temporary (best effort: one already gone is
/// skipped) and empty the registry; for an exit that does not unwind.
pub fn remove_all() {
    for p in live().drain(..) {
        let _ = std::fs::remove_file(p);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn remove_all_deletes_what_is_registered_and_nothing_else() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join(".a.tmp"), dir.path().join("b"));
        std::fs::write(&a, "partial").unwrap();
        std::fs::write(&b, "kept").unwrap();
        let reg = Registered::new(&a);
        let gone = Registered::new(&dir.path().join(".never-created"));
        drop(gone);
        remove_all();
        assert!(!a.exists() && b.exists());
        // Dropping an entry already removed by remove_all is harmless.
        drop(reg);
    }
}
