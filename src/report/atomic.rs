//! Safe writing of output files: each file is written under a temporary name
//! in its target folder and renamed over the target only when complete, so an
//! interrupted run or a full disk never leaves a truncated file in its place
//! (rename within one folder is atomic on POSIX file systems).

use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use tempfile::NamedTempFile;
use thiserror::Error;

/// A file could not be written; names the file and the reason.
#[derive(Debug, Error)]
pub enum WriteError {
    #[error("{path}: exists; not overwritten (pass --force to replace it)")]
    Exists { path: String },
    #[error("{path}: cannot write: {reason}")]
    Io { path: String, reason: String },
}

impl WriteError {
    pub(crate) fn io(path: &Path, e: impl std::fmt::Display) -> Self {
        WriteError::Io {
            path: path.display().to_string(),
            reason: e.to_string(),
        }
    }
}

/// Refuse an existing `path` unless `force`.
pub fn check_overwrite(path: &Path, force: bool) -> Result<(), WriteError> {
    if !force && path.exists() {
        return Err(WriteError::Exists {
            path: path.display().to_string(),
        });
    }
    Ok(())
}

/// A file being written under a temporary name next to its target.
pub struct AtomicFile {
    target: PathBuf,
    writer: BufWriter<NamedTempFile>,
}

impl AtomicFile {
    /// Start writing `target` (refused if it exists and not `force`).
    pub fn create(target: &Path, force: bool) -> Result<Self, WriteError> {
        check_overwrite(target, force)?;
        let tmp = temp_next_to(target, "")?;
        Ok(AtomicFile {
            target: target.to_path_buf(),
            writer: BufWriter::new(tmp),
        })
    }

    /// The writer of the content.
    pub fn writer(&mut self) -> &mut impl Write {
        &mut self.writer
    }

    /// Flush, sync and rename over the target.
    pub fn commit(self) -> Result<(), WriteError> {
        let target = self.target;
        let tmp = self
            .writer
            .into_inner()
            .map_err(|e| WriteError::io(&target, e.error()))?;
        tmp.as_file()
            .sync_all()
            .map_err(|e| WriteError::io(&target, e))?;
        tmp.persist(&target)
            .map_err(|e| WriteError::io(&target, e.error))?;
        Ok(())
    }
}

impl Write for AtomicFile {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        self.writer.write(buf)
    }

    fn flush(&mut self) -> std::io::Result<()> {
        self.writer.flush()
    }
}

/// A new empty temporary file in `target`'s folder (`.name.XXXX.suffix`).
pub fn temp_next_to(target: &Path, suffix: &str) -> Result<NamedTempFile, WriteError> {
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let name = target
        .file_name()
        .map_or("kinrepro".into(), |n| n.to_string_lossy().into_owned());
    let prefix = format!(".{name}.");
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(suffix);
    // An ordinary file's mode (0666 less the umask), not the 0600 of a
    // private temporary file: the output is shared like any other file.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(std::fs::Permissions::from_mode(0o666));
    }
    builder
        .tempfile_in(dir)
        .map_err(|e| WriteError::io(target, e))
}

/// Write `text` to `target` whole or not at all.
pub fn write_file(target: &Path, text: &str, force: bool) -> Result<(), WriteError> {
    let mut f = AtomicFile::create(target, force)?;
    f.writer()
        .write_all(text.as_bytes())
        .map_err(|e| WriteError::io(target, e))?;
    f.commit()
}
