//! `kinrepro clean DIR...`: remove the temporaries a killed run left
//! (library: `output::temporaries::remove_stale`).

use std::path::PathBuf;
use std::time::Duration;

use crate::error::{Error, Result};

/// A temporary untouched for this long belongs to no live run: a run
/// writes its own as it goes, and renames or deletes it at its end.
const IDLE: Duration = Duration::from_secs(60);

pub fn clean(dirs: &[PathBuf]) -> Result {
    for dir in dirs {
        let (removed, kept) = kinrepro::output::temporaries::remove_stale(dir, IDLE)
            .map_err(|e| Error::new(format!("{}: cannot clean: {e}", dir.display())))?;
        for p in &removed {
            println!("removed {}", p.display());
        }
        for p in &kept {
            eprintln!(
                "kept {}: modified within the last {} s, a run may still be writing it",
                p.display(),
                IDLE.as_secs()
            );
        }
        if removed.is_empty() && kept.is_empty() {
            println!("{}: no temporary files of kinrepro", dir.display());
        }
    }
    Ok(())
}
