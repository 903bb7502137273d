//! The library's top-level error: reading and assembling a scene, with the
//! file it concerns, for a front end to print. Each layer below has its own
//! typed error.

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

/// Read a scene file, validate it and assemble its coupling.
pub fn read_scene(path: &Path) -> Result<(Scene, Coupling), Error> {
    assembled(Scene::load(path)?)
}

/// Validate scene text and assemble its coupling; `file` names it.
pub fn parse_scene(text: &str, file: &str) -> Result<(Scene, Coupling), Error> {
    assembled(Scene::parse(text, file)?)
}

/// A validated scene with its coupling.
fn assembled(scene: Scene) -> Result<(Scene, Coupling), Error> {
    match Coupling::new(&scene) {
        Ok(c) => Ok((scene, c)),
        Err(source) => Err(Error::Assembly { file: scene.file, source }),
    }
}
