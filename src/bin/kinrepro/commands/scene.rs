//! `kinrepro check` and `kinrepro expand`: scene validation.

use std::path::{Path, PathBuf};

use kinrepro::report::coupling::check::{check_summary, seating_note};

use super::{emit, read_text};
use crate::error::{Context, Error, Result};

pub fn check(scenes: &[PathBuf]) -> Result {
    let (mut failed, mut unseated) = (0, 0);
    for path in scenes {
        match kinrepro::error::read_scene(path) {
            Ok((s, c)) => {
                let verdict = kinrepro::study::verdict::cannot_seat(&s, &c, &Default::default())?;
                unseated += usize::from(verdict.is_some());
                let note = seating_note(&s, &c, verdict.as_deref());
                emit(&format!("{}{note}\n", check_summary(&s, &c)))?
            }
            Err(e) => {
                eprintln!("error: {e}");
                failed += 1;
            }
        }
    }
    let total = scenes.len();
    if failed > 0 {
        return Err(Error::new(format!("{failed} of {total} scenes are invalid")));
    }
    // A coupling that cannot seat is valid TOML but not a usable design: a
    // script that checks scenes before a batch run must see it fail.
    if unseated > 0 {
        return Err(Error::new(format!(
            "{unseated} of {total} scenes cannot seat (CANNOT SEAT above)"
        )));
    }
    Ok(())
}

pub fn expand(scene: &Path) -> Result {
    let file = scene.display().to_string();
    let source = read_text(scene)?;
    let text = kinrepro::scene::Scene::expand_text(&source, &file)?;
    // The explicit form must assemble too.
    let explicit = kinrepro::scene::Scene::parse(&text, &file)?;
    kinrepro::assembly::Coupling::new(&explicit).context(&file)?;
    emit(&text)
}
