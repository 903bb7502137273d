//! Running a reproducibility study of one scene: draw the design, seat the
//! coupling once per sample (rayon across samples), and record the pose of
//! every evaluation point relative to the nominal-mu seating.
//!
//! The plan (`super::plan`) has checked the options and drawn up each
//! scene's design; a run takes its [`Settings`] and one [`Variant`].
//!
//! Inputs: the row u_i of the design on [0, 1]^d maps to the varied
//! quantities in order: with friction varied, mu_s,k = mu0 + spread
//! (2 u_ik - 1) for contact k (docs/model.md, rectangular distribution); with
//! the start varied (dynamic solver), an offset x, y in +-b_x, +-b_y, z in
//! [0, b_z] above the seat and a tilt in +-b_tilt per axis. A row depends only
//! on (sampler, n, seed, i), so shards of the sample range computed anywhere
//! merge into exactly one run.
//!
//! With `preload` varied, the preload point moves by (dx, dy) in +-b per
//! axis and its direction turns by the rotation vector (t_x, t_y, 0), each
//! component in +-b_tilt (so the angle from the nominal direction is at
//! most sqrt(2) b_tilt). With `tolerances` varied, each row also draws
//! manufacturing errors ([`Tolerances`]); the perturbed coupling is seated
//! at nominal friction and preload and reported separately
//! (interchangeability of coupling halves, outputs `interchange/...`).

pub use super::inputs::{Input, Tolerances};
use super::options::Settings;
pub use super::paths::{LoadPath, PathTally, SeatingPaths};
pub use super::progress::Progress;
pub use super::rows::evaluate_rows;
use super::stats::SampleRecord;
use super::variant::Variant;
pub use super::variation::{START_CLEARANCE, Sample, StartBounds, Variation, lifted_clear};
use super::{DesignSpec, Shard, StudyError};
use crate::scene::Scene;

/// The samples of one scene that this run (shard) computed.
#[derive(Debug, Clone, PartialEq)]
pub struct VariantRun {
    pub design: DesignSpec,
    pub shard: Shard,
    /// `point/component` for every evaluation point and component.
    pub output_names: Vec<String>,
    pub records: Vec<SampleRecord>,
    /// Why the coupling cannot seat ([`super::verdict::cannot_seat`]), if it cannot.
    pub cannot_seat: Option<String>,
}

/// Prefix of the interchangeability outputs (`interchange/<point>/<dof>`).
pub const INTERCHANGE_PREFIX: &str = "interchange/";
/// Prefix of the thermal drift outputs (`thermal/<k>/<point>/<dof>`, k the
/// 1-based cycle point).
pub const THERMAL_PREFIX: &str = "thermal/";

/// Names of the thermal drift outputs of a scene with `[thermal]`: per
/// cycle point (1-based), every evaluation point's six components of the
/// drift from the sample's own seated pose (`ThermalPath::drift`).
pub fn thermal_output_names(scene: &Scene) -> Vec<String> {
    let points = scene.thermal.as_ref().map_or(0, |t| t.cycle.len());
    (1..=points)
        .flat_map(|k| {
            output_names(scene).into_iter().map(move |n| format!("{THERMAL_PREFIX}{k}/{n}"))
        })
        .collect()
}

/// Names of the re-seating outputs: per evaluation point its six DOFs and
/// its directions ([`EvaluationPoint::output_names`](crate::scene::EvaluationPoint::output_names)).
pub fn output_names(scene: &Scene) -> Vec<String> {
    scene.evaluation_points.iter().flat_map(|p| p.output_names()).collect()
}

/// Names of all recorded outputs under `variation`: the re-seating outputs
/// (if friction, preload or start vary), then the thermal drift outputs
/// (re-seating of a scene with `[thermal]`), then the interchangeability
/// outputs (if tolerances vary).
pub fn recorded_output_names(scene: &Scene, variation: &Variation) -> Vec<String> {
    let mut v = Vec::new();
    if variation.reseating() {
        v.extend(output_names(scene));
        v.extend(thermal_output_names(scene));
    }
    if variation.tolerances {
        v.extend(output_names(scene).into_iter().map(|n| format!("{INTERCHANGE_PREFIX}{n}")));
    }
    v
}

/// Run this shard's samples of one scene, reporting to `progress`; the
/// records are kept (the plan bounded them: `StudyPlan::keeping_records`,
/// or a variant `StudyPlan::new` does not stream).
///
/// Per sample: with friction, preload or start varied, the nominal
/// coupling is seated with the sample's friction, preload and start, and
/// its pose recorded relative to the nominal seating (re-seating scatter);
/// with tolerances varied, the sample's perturbed coupling is also seated
/// at nominal friction and preload, and its pose recorded relative to the
/// same nominal seating (interchangeability, `interchange/...` outputs).
pub fn run_variant<'a>(
    s: &Settings,
    v: &Variant,
    progress: impl Into<Progress<'a>>,
) -> Result<VariantRun, StudyError> {
    let in_file = |e: StudyError| e.in_file(v.file());
    let rows = v.design.range(v.samples.clone()).map_err(in_file)?;
    let cannot_seat = super::verdict::cannot_seat(&v.scene, &v.coupling, &s.method)?;
    let records = evaluate_rows(s, v, v.samples.clone().zip(rows).collect(), progress)?;
    Ok(VariantRun {
        design: v.design,
        shard: s.shard,
        output_names: recorded_output_names(&v.scene, &s.variation),
        records,
        cannot_seat,
    })
}

/// Run this shard's samples in chunks of `chunk` rows (rayon within a
/// chunk), handing each chunk's records to `sink` in sample-index order:
/// bounded memory for any sample count, and results that do not depend on
/// the number of threads.
pub fn run_chunked<'a>(
    s: &Settings,
    v: &Variant,
    chunk: usize,
    progress: impl Into<Progress<'a>>,
    sink: &mut dyn FnMut(Vec<SampleRecord>) -> Result<(), StudyError>,
) -> Result<(), StudyError> {
    let progress = progress.into();
    let mut start = v.samples.start;
    while start < v.samples.end {
        let end = (start + chunk.max(1)).min(v.samples.end);
        let rows = v.design.range(start..end).map_err(|e| e.in_file(v.file()))?;
        sink(evaluate_rows(s, v, (start..end).zip(rows).collect(), progress)?)?;
        start = end;
    }
    Ok(())
}
