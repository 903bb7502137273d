//! The library's top-level error: reading and assembling a scene file, with
//! the file it concerns, for the CLI to print before exiting non-zero. Each
//! layer below has its own typed error; the CLI's `CliError` wraps them all.

use std::path::Path;

use thiserror::Error;

use crate::assembly::{AssemblyError, Coupling};
use crate::scene::{Scene, SceneError};

#[derive(Debug, Error)]
pub enum Error {
    #[error("{0}")]
    Scene(#[from] SceneError),
    #[error("{file}: {source}")]
    Assembly {
        file: String,
        #[source]
        source: AssemblyError,
    },
}

/// Read a scene file, validate it and assemble the coupling.
pub fn read_coupling(path: &Path) -> Result<Coupling, Error> {
    let scene = Scene::load(path)?;
    Coupling::new(&scene).map_err(|source| Error::Assembly {
        file: scene.file.clone(),
        source,
    })
}
