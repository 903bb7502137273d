//! The library's top-level error: each layer's error, with the file it
//! concerns, for the CLI to print before exiting non-zero.

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
    #[error("{0}")]
    Other(String),
}

/// Load, validate and assemble a scene file.
pub fn load_coupling(path: &Path) -> Result<Coupling, Error> {
    let scene = Scene::load(path)?;
    Coupling::new(&scene).map_err(|source| Error::Assembly {
        file: scene.file.clone(),
        source,
    })
}
