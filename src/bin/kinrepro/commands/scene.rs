//! `kinrepro check` and `kinrepro expand`: scene validation.

use std::path::{Path, PathBuf};

use crate::error::{CliError, Context};

pub fn check(scenes: &[PathBuf]) -> Result<(), CliError> {
    let (mut failed, mut unseated) = (0, 0);
    for path in scenes {
        match kinrepro::error::read_coupling(path) {
            Ok(c) => {
                let verdict = kinrepro::study::verdict::cannot_seat(&c, &Default::default())?;
                unseated += usize::from(verdict.is_some());
                let note = kinrepro::report::coupling::check::seating_note(&c, verdict.as_deref());
                let summary = kinrepro::report::coupling::check::check_summary(&c);
                super::emit(&format!("{summary}{note}\n"))?
            }
            Err(e) => {
                eprintln!("error: {e}");
                failed += 1;
            }
        }
    }
    if failed > 0 {
        return Err(CliError::InvalidScenes {
            failed,
            total: scenes.len(),
        });
    }
    // A coupling that cannot seat is valid TOML but not a usable design: a
    // script that checks scenes before a batch run must see it fail.
    if unseated > 0 {
        return Err(CliError::UnseatableScenes {
            count: unseated,
            total: scenes.len(),
        });
    }
    Ok(())
}

pub fn expand(scene: &Path) -> Result<(), CliError> {
    let file = scene.display().to_string();
    let source = super::read_text(scene)?;
    let text = kinrepro::scene::Scene::expand_text(&source, &file)?;
    // The explicit form must assemble too.
    let explicit = kinrepro::scene::Scene::parse(&text, &file)?;
    kinrepro::assembly::Coupling::new(&explicit).context(&file)?;
    super::emit(&text)
}
