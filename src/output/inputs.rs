//! The files the running command has read, so that no output of the same
//! command replaces one of them, `--force` or not (`report in.json --out
//! in.json`, `study S.toml --html S.toml`): the output would destroy the
//! input it was made from. Kept only where [`track`] was called (the
//! command-line program, once per process); a Python session reads and
//! writes over many calls and keeps nothing here.
//!
//! A file is known by its identity (`same_file::Handle`: device and inode
//! on Unix), so a symbolic link, a hard link or another spelling of an
//! input's path is that input too.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};
use std::sync::{Mutex, MutexGuard};

use same_file::Handle;

static TRACK: AtomicBool = AtomicBool::new(false);

static READ: Mutex<Vec<(PathBuf, Handle)>> = Mutex::new(Vec::new());

fn read() -> MutexGuard<'static, Vec<(PathBuf, Handle)>> {
    READ.lock().unwrap_or_else(|e| e.into_inner())
}

/// Keep the regular files read from now on in this process.
pub fn track() {
    TRACK.store(true, Ordering::SeqCst);
}

/// Note the regular file `file`, opened at `path`, as read, if tracking
/// (a pipe or a device is not replaced by an output anyway, and the
/// caller registers regular files only). Its identity comes from the open
/// file itself, so it is the file that was read.
pub fn register(path: &Path, file: &std::fs::File) {
    if !TRACK.load(Ordering::SeqCst) {
        return;
    }
    if let Ok(h) = file.try_clone().and_then(Handle::from_file) {
        let mut r = read();
        if !r.iter().any(|(_, known)| *known == h) {
            r.push((path.to_path_buf(), h));
        }
    }
}

/// The path under which the input that `target` is was read, if it is one.
pub fn input_at(target: &Path) -> Option<PathBuf> {
    if !TRACK.load(Ordering::SeqCst) {
        return None;
    }
    let h = Handle::from_path(target).ok()?;
    read().iter().find(|(_, known)| *known == h).map(|(p, _)| p.clone())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn an_input_is_known_by_any_path_to_it_and_nothing_else_is() {
        let dir = tempfile::tempdir().unwrap();
        let (a, b) = (dir.path().join("a.toml"), dir.path().join("b.toml"));
        std::fs::write(&a, "x").unwrap();
        std::fs::write(&b, "x").unwrap();
        track();
        register(&a, &std::fs::File::open(&a).unwrap());
        let link = dir.path().join("link");
        std::os::unix::fs::symlink(&a, &link).unwrap();
        let other_spelling = dir.path().join(".").join("a.toml");
        assert_eq!(input_at(&link).as_deref(), Some(a.as_path()));
        assert_eq!(input_at(&other_spelling).as_deref(), Some(a.as_path()));
        assert_eq!(input_at(&b), None);
        assert_eq!(input_at(&dir.path().join("missing")), None);
    }
}
