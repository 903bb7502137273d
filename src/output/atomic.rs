//! Safe writing of output files: each file is written under a temporary name
//! in its target folder and renamed over the target only when complete, so an
//! interrupted run or a full disk never leaves a truncated file in its place
//! (rename within one folder is atomic on POSIX file systems).
//!
//! Only a regular file is ever replaced. A symbolic link to a regular file is
//! replaced at its target (the link stays); a path that is a device, a FIFO
//! or a socket, or a link to one (`/dev/null`, `/dev/stdout`), is written
//! through (opened for writing, never renamed over) with `--force`, and
//! refused without it; a folder is refused.

use std::fs::File;
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};

use tempfile::NamedTempFile;

use super::temporaries::Registered;
use crate::param::Param;
use thiserror::Error;

/// A file could not be written; names the file and the reason.
#[derive(Debug, Error)]
pub enum WriteError {
    #[error("{path}: exists; not overwritten (pass {} to replace it)", Param::Force)]
    Exists { path: String },
    #[error(
        "{path}: is a {kind}, not a regular file; not written (pass {} to write into it)",
        Param::Force
    )]
    NotRegular { path: String, kind: &'static str },
    #[error("{path}: cannot write: {reason}")]
    Io { path: String, reason: String },
    #[error(
        "{path}: is an input of this command (read as {input}); not overwritten, even with {}",
        Param::Force
    )]
    IsInput { path: String, input: String },
}

impl WriteError {
    pub(crate) fn io(path: &Path, e: impl std::fmt::Display) -> Self {
        WriteError::Io { path: path.display().to_string(), reason: e.to_string() }
    }
}

/// Refuse an existing `path` unless `force`, and an input of the command
/// ([`super::inputs`]) always.
pub fn check_overwrite(path: &Path, force: bool) -> Result<(), WriteError> {
    if let Some(input) = super::inputs::input_at(path) {
        let (path, input) = (path.display().to_string(), input.display().to_string());
        return Err(WriteError::IsInput { path, input });
    }
    if !force && path.exists() {
        return Err(WriteError::Exists { path: path.display().to_string() });
    }
    Ok(())
}

/// Where the bytes of an output path go.
enum Destination {
    /// A temporary file renamed over this regular file (the link's target
    /// when the path is a symbolic link).
    Replace(PathBuf),
    /// A device, FIFO or socket (or a link to one), opened for writing.
    Through,
}

/// The kind of a path that is not a regular file, for the messages.
#[cfg(unix)]
fn special_kind(t: std::fs::FileType) -> &'static str {
    use std::os::unix::fs::FileTypeExt;
    if t.is_char_device() {
        "character device"
    } else if t.is_block_device() {
        "block device"
    } else if t.is_fifo() {
        "FIFO"
    } else if t.is_socket() {
        "socket"
    } else {
        "special file"
    }
}

#[cfg(not(unix))]
fn special_kind(_: std::fs::FileType) -> &'static str {
    "special file"
}

/// How `target` is written ([`Destination`]), or why it is refused.
fn destination(target: &Path, force: bool) -> Result<Destination, WriteError> {
    let path = || target.display().to_string();
    match std::fs::metadata(target) {
        // Not there (or a dangling link): a new file where the links lead.
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
            Ok(Destination::Replace(follow_links(target)?))
        }
        Err(e) => Err(WriteError::io(target, e)),
        Ok(m) if m.is_dir() => Err(WriteError::io(target, "is a folder")),
        Ok(m) if m.is_file() => {
            check_overwrite(target, force)?;
            let real = std::fs::canonicalize(target).map_err(|e| WriteError::io(target, e))?;
            Ok(Destination::Replace(real))
        }
        Ok(_) if force => Ok(Destination::Through),
        Ok(m) => Err(WriteError::NotRegular { path: path(), kind: special_kind(m.file_type()) }),
    }
}

/// The path a chain of symbolic links ends at (`target` itself if it is
/// not a link); refused after 40 links (the kernel's limit).
fn follow_links(target: &Path) -> Result<PathBuf, WriteError> {
    let mut p = target.to_path_buf();
    for _ in 0..40 {
        match std::fs::read_link(&p) {
            Ok(next) => {
                p = match p.parent() {
                    Some(dir) => dir.join(next),
                    None => next,
                };
            }
            Err(_) => return Ok(p),
        }
    }
    Err(WriteError::io(target, "too many levels of symbolic links"))
}

/// The open output: a temporary file to rename, or the special file itself.
enum Sink {
    /// The temporary, the regular file it is renamed over, and the
    /// temporary's entry in the registry of the hard exit.
    Temp(BufWriter<NamedTempFile>, PathBuf, Registered),
    Through(BufWriter<File>),
}

/// A file being written under a temporary name next to its target, or
/// straight into a device, FIFO or socket ([`Destination`]).
pub struct AtomicFile {
    target: PathBuf,
    sink: Sink,
}

impl AtomicFile {
    /// Start writing `target` (refused if it exists and not `force`).
    pub fn create(target: &Path, force: bool) -> Result<Self, WriteError> {
        let sink = match destination(target, force)? {
            Destination::Replace(real) => {
                super::temporaries::note_stale(&real);
                let tmp = temp_next_to(&real)?;
                let reg = Registered::new(tmp.path());
                Sink::Temp(BufWriter::new(tmp), real, reg)
            }
            Destination::Through => {
                let f = std::fs::OpenOptions::new()
                    .write(true)
                    .open(target)
                    .map_err(|e| WriteError::io(target, e))?;
                Sink::Through(BufWriter::new(f))
            }
        };
        Ok(AtomicFile { target: target.to_path_buf(), sink })
    }

    /// The path given for the file.
    pub fn target(&self) -> &Path {
        &self.target
    }

    /// The writer of the content.
    pub fn writer(&mut self) -> &mut impl Write {
        self
    }

    /// Flush, sync and rename over the target (flush only when written
    /// through a special file).
    pub fn commit(self) -> Result<(), WriteError> {
        let target = self.target;
        let (w, real, _reg) = match self.sink {
            Sink::Through(mut w) => return w.flush().map_err(|e| WriteError::io(&target, e)),
            Sink::Temp(w, real, reg) => (w, real, reg),
        };
        let tmp = w.into_inner().map_err(|e| WriteError::io(&target, e.error()))?;
        tmp.as_file().sync_all().map_err(|e| WriteError::io(&target, e))?;
        tmp.persist(&real).map_err(|e| WriteError::io(&target, e.error))?;
        Ok(())
    }
}

/// Commit every file of `files` (each written whole), in order; returns
/// their paths. Call it once all are written, so that an interruption
/// before it leaves every target as it was.
pub fn commit_all(files: Vec<AtomicFile>) -> Result<Vec<String>, WriteError> {
    files
        .into_iter()
        .map(|f| {
            let path = f.target().display().to_string();
            f.commit().map(|()| path)
        })
        .collect()
}

impl Write for AtomicFile {
    fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
        match &mut self.sink {
            Sink::Temp(w, ..) => w.write(buf),
            Sink::Through(w) => w.write(buf),
        }
    }

    fn flush(&mut self) -> std::io::Result<()> {
        match &mut self.sink {
            Sink::Temp(w, ..) => w.flush(),
            Sink::Through(w) => w.flush(),
        }
    }
}
/// A new empty temporary file in `target`'s folder,
/// `.NAME.kinrepro-XXXXXX.tmp` ([`super::temporaries::MARK`], `SUFFIX`).
pub fn temp_next_to(target: &Path) -> Result<NamedTempFile, WriteError> {
    let dir = match target.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let name = target.file_name().map_or("kinrepro".into(), |n| n.to_string_lossy().into_owned());
    let prefix = format!(".{name}{}", super::temporaries::MARK);
    let mut builder = tempfile::Builder::new();
    builder.prefix(&prefix).suffix(super::temporaries::SUFFIX);
    // An ordinary file's mode (0666 less the umask), not the 0600 of a
    // private temporary file: the output is shared like any other file.
    #[cfg(unix)]
    {
        use std::os::unix::fs::PermissionsExt;
        builder.permissions(std::fs::Permissions::from_mode(0o666));
    }
    builder.tempfile_in(dir).map_err(|e| WriteError::io(target, e))
}

/// Write `text` to `target` whole or not at all.
pub fn write_file(target: &Path, text: &str, force: bool) -> Result<(), WriteError> {
    let mut f = AtomicFile::create(target, force)?;
    f.writer().write_all(text.as_bytes()).map_err(|e| WriteError::io(target, e))?;
    f.commit()
}
