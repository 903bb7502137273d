//! What the report reads: study JSON (`study --format json`, or a merged
//! study) and the scene files it names.
//!
//! The study JSON holds the statistics and every sample (records) but not
//! the scenes. The report reads each scene file again (by the path in the
//! JSON, as given to `study`, else relative to the JSON file's folder),
//! checks that it is the scene the study ran (the fingerprint's
//! `scene_content` hash; for a prediction, with the calibrated parameters
//! applied, [`super::prediction`]), and seats it once at nominal friction for the
//! drawing, the contact forces, stresses and stiffnesses. That seating is
//! deterministic; nothing random is re-run.

use std::path::{Path, PathBuf};

use super::HtmlError;
use super::prediction::PredictionInput;
use crate::assembly::Coupling;
use crate::scene::Scene;
use crate::study::StudyReport;
use crate::study::provenance::{
    FINGERPRINT_VERSION, Fingerprint, READABLE_SCHEMAS, SCHEMA_VERSION,
};

/// One scene of a study: its file text, the scene and its coupling.
#[derive(Debug, Clone)]
pub struct SceneInput {
    pub text: String,
    pub scene: Scene,
    pub coupling: Coupling,
}

/// One study: where it came from, its document, and one scene per variant
/// (in the order of `report.variants`).
#[derive(Debug, Clone)]
pub struct StudyInput {
    pub source: String,
    pub report: StudyReport,
    pub scenes: Vec<SceneInput>,
    /// The calibration and measured sigma of a prediction (empty for a study).
    pub prediction: PredictionInput,
}

/// The input of a scene and its coupling, its text read from `scene.file`.
pub fn scene_input(scene: Scene, coupling: Coupling) -> Result<SceneInput, HtmlError> {
    let text = crate::input::read_to_string(&scene.file).map_err(|e| HtmlError::Input {
        file: scene.file.clone(),
        reason: format!("cannot read the scene file: {e}"),
    })?;
    Ok(SceneInput { text, scene, coupling })
}

/// Read a study JSON file and the scenes it names.
pub fn load_study(path: &Path) -> Result<StudyInput, HtmlError> {
    let source = path.display().to_string();
    let input = |reason: String| HtmlError::Input { file: source.clone(), reason };
    let text = crate::input::read_to_string(path)
        .map_err(|e| input(format!("cannot read the file: {e}")))?;
    let report: StudyReport = serde_json::from_str(&text)
        .map_err(|e| input(format!("not a kinrepro study JSON: {e}")))?;
    if !READABLE_SCHEMAS.contains(&report.schema_version) {
        return Err(input(format!(
            "schema_version {} (this kinrepro reads schemas {} to {SCHEMA_VERSION}; rerun the study)",
            report.schema_version,
            READABLE_SCHEMAS.start()
        )));
    }
    if report.variants.is_empty() {
        return Err(input("no variants: nothing to report".into()));
    }
    crate::study::validate::check_document(&report).map_err(|e| input(e.to_string()))?;
    let prediction = PredictionInput::parse(&text)
        .map_err(|e| input(format!("not a kinrepro study or prediction JSON: {e}")))?;
    let dir = path.parent().unwrap_or(Path::new("."));
    let mut scenes = Vec::new();
    for v in &report.variants {
        if v.partial {
            return Err(input(format!(
                "{}: shard {} of a sharded study; merge the parts first (kinrepro merge)",
                v.scene, v.shard
            )));
        }
        let scene_path = locate(&v.scene, dir).map_err(|e| input(e.to_string()))?;
        let text = crate::input::read_to_string(&scene_path)
            .map_err(|e| input(format!("{}: cannot read: {e}", scene_path.display())))?;
        let mut scene = Scene::parse(&text, &v.scene)?;
        let mut coupling = Coupling::new(&scene)
            .map_err(|source| HtmlError::Assembly { file: v.scene.clone(), source })?;
        // A prediction ran the scene with the calibrated parameters.
        prediction.apply(&mut scene, &mut coupling);
        if v.fingerprint.fingerprint_version != FINGERPRINT_VERSION {
            return Err(input(format!(
                "{}: study fingerprint of version {} (this kinrepro writes version \
                 {FINGERPRINT_VERSION}, and checks a scene against its own): rerun the study",
                v.scene, v.fingerprint.fingerprint_version
            )));
        }
        let now = Fingerprint::scene_content(&scene, &v.design);
        if now != v.fingerprint.scene_content {
            let why = if prediction.calibration.is_some() {
                "with the calibrated parameters applied, it is not the scene the prediction ran: \
                 the scene file or the JSON's calibration block changed since `predict`; rerun predict"
            } else {
                "the scene file changed since the study ran; rerun the study"
            };
            return Err(input(format!(
                "{}: scene_content {} differs from the study's {}: {why}",
                scene_path.display(),
                now,
                v.fingerprint.scene_content
            )));
        }
        scenes.push(SceneInput { text, scene, coupling });
    }
    Ok(StudyInput { source, report, scenes, prediction })
}

/// The scene path as written, else relative to the JSON's folder, and
/// only inside the current folder or the JSON's folder (after resolving
/// `..` and symbolic links): a path written in a JSON is data, not a
/// licence to read any file the user can read. The error names the path,
/// never the content of a file.
fn locate(scene: &str, json_dir: &Path) -> Result<PathBuf, Unlocated> {
    let json_dir = if json_dir.as_os_str().is_empty() { Path::new(".") } else { json_dir };
    let roots: Vec<PathBuf> =
        [Path::new("."), json_dir].iter().filter_map(|d| d.canonicalize().ok()).collect();
    let p = PathBuf::from(scene);
    let mut outside = false;
    for candidate in [p.clone(), json_dir.join(&p)] {
        let Ok(real) = candidate.canonicalize() else {
            continue;
        };
        if !real.is_file() {
            continue;
        }
        if roots.iter().any(|r| real.starts_with(r)) {
            return Ok(candidate);
        }
        outside = true;
    }
    let scene = scene.to_string();
    Err(match outside {
        true => Unlocated::Outside(scene),
        false => Unlocated::NotFound(scene),
    })
}

/// Why a study's scene file was not read.
#[derive(Debug, thiserror::Error)]
enum Unlocated {
    #[error(
        "scene `{0}` is outside the folders a report reads scenes from (the current folder and the JSON's folder): refused; run `report` where the study ran, or copy the scene next to the JSON"
    )]
    Outside(String),
    #[error("scene `{0}` not found (neither from the current folder nor next to the JSON)")]
    NotFound(String),
}
