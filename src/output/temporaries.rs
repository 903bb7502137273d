//! The temporary files of atomic writes ([`super::atomic`]) that exist now,
//! so that an exit that does not unwind (a second signal, or the grace
//! period after the first running out: `bin/kinrepro/signals.rs`) can
//! delete them first. A normal exit or an unwinding run deletes each by its
//! destructor and unregisters it; a committed one is renamed, then
//! unregistered (deleting its old name afterwards finds nothing).

use std::path::{Path, PathBuf};
use std::sync::{Mutex, MutexGuard};

static LIVE: Mutex<Vec<PathBuf>> = Mutex::new(Vec::new());

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
