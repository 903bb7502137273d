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

use rayon::prelude::*;

pub use super::inputs::{Input, Tolerances};
use super::options::Settings;
pub use super::paths::{LoadPath, PathTally, SeatingPaths};
use super::stats::SampleRecord;
use super::variant::Variant;
pub use super::variation::{START_CLEARANCE, Sample, StartBounds, Variation, lifted_clear};
use super::{DesignSpec, Shard, StudyError};
use crate::assembly::BodyPose;
use crate::scene::{EvaluationPoint, Scene};
use crate::solve::quasistatic::{SeatingSetup, Workspace, seat_and_cycle_in, seat_in, seat4_in};
use crate::solve::{Load, Method, PointPose, SeatedPose, SolveError};

/// What a run reports as it goes: `tick` once per finished sample, and
/// the path of every sample seating counted into `tally` where one is
/// given. A closure alone is a `Progress` without a tally.
#[derive(Clone, Copy)]
pub struct Progress<'a> {
    pub tick: &'a (dyn Fn() + Sync),
    pub tally: Option<&'a PathTally>,
}

impl<'a> Progress<'a> {
    /// `tick` per sample, the seating paths counted into `tally`.
    pub fn with_tally(tick: &'a (dyn Fn() + Sync), tally: &'a PathTally) -> Self {
        Progress { tick, tally: Some(tally) }
    }

    fn record(&self, seated: &SeatedPose) {
        if let Some(t) = self.tally {
            t.record(seated);
        }
    }
}

impl<'a, F: Fn() + Sync> From<&'a F> for Progress<'a> {
    fn from(tick: &'a F) -> Self {
        Progress { tick, tally: None }
    }
}

impl<'a> From<&'a (dyn Fn() + Sync + 'a)> for Progress<'a> {
    fn from(tick: &'a (dyn Fn() + Sync + 'a)) -> Self {
        Progress { tick, tally: None }
    }
}

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

/// What a failed sample drew its preload or tolerances within: the
/// `[variation]` keys behind it (a bound may reach beyond what the
/// coupling carries), or empty.
fn varied_note(scene: &crate::scene::Scene, var: &super::variation::Variation) -> Box<str> {
    let keys = scene.variation.keys(var.preload, var.tolerances);
    if keys.is_empty() {
        return "".into();
    }
    format!(
        "; preload or tolerances drawn within [variation] {}, whose bounds may reach beyond what \
         the coupling can carry",
        keys.join(", ")
    )
    .into()
}

/// Seat the coupling once per `(index, design row)` (rayon across rows)
/// and record the outputs named by [`recorded_output_names`], relative to
/// the nominal seating (nominal friction and preload, touching start, same
/// solver). Any design over the settings' inputs may be passed (a study's
/// design, or e.g. the matrices of a variance-based sensitivity analysis).
/// `progress` ticks once per finished row.
pub fn evaluate_rows<'a>(
    s: &Settings,
    v: &Variant,
    rows: Vec<(usize, Vec<f64>)>,
    progress: impl Into<Progress<'a>>,
) -> Result<Vec<SampleRecord>, StudyError> {
    let progress = progress.into();
    let (scene, coupling) = (&v.scene, &v.coupling);
    let var = s.variation;
    let file = v.file();
    let varied = varied_note(scene, &var);
    let seat_err = |index: usize, mu: &[f64], source| {
        let varied = varied.clone();
        let source = Box::new(source);
        StudyError::Seating { index, mu: mu.to_vec(), varied, source }.in_file(file)
    };
    // The reference: nominal friction and preload, from the touching pose, same solver.
    let nominal_load = Load::nominal(scene);
    let nominal = s.method.seat(coupling, &nominal_load).map_err(|source| {
        StudyError::Nominal { mu: nominal_load.mu.clone(), source }.in_file(file)
    })?;
    let points = &scene.evaluation_points;
    // Every evaluation point's outputs from the nominal seating to `pose`.
    let reference = nominal.pose();
    let relative = |pose: BodyPose| {
        points
            .iter()
            .flat_map(move |p| p.outputs(PointPose::between(&reference, &pose, &p.position)))
    };
    let setup = SeatingSetup::new(coupling, &scene.preload);
    let thermal = coupling.thermal.as_ref();
    // One sample's record, its re-seating `lanes` if the lanes seated it.
    let record = |ws: &mut Workspace,
                  (index, row): &(usize, Vec<f64>),
                  sample: Sample,
                  lanes: Option<Result<SeatedPose, SolveError>>| {
        let (index, row) = (*index, row.clone());
        let mut outputs: Vec<f64> = Vec::new();
        if var.reseating() && thermal.is_some() {
            let (seated, drift) = reseat_and_cycle(&setup, &s.method, &sample.load, points, ws)
                .map_err(|e| seat_err(index, &sample.load.mu, e))?;
            progress.record(&seated);
            outputs.extend(relative(seated.pose));
            outputs.extend(drift);
        } else if var.reseating() {
            let seated = match lanes.unwrap_or_else(|| reseat(&setup, &s.method, &sample.load, ws))
            {
                // A varied start that does not centre is counted: a record without outputs.
                Err(SolveError::NotCentred { .. }) if var.start.is_some() => {
                    (progress.tick)();
                    return Ok(SampleRecord::not_centred(index, row));
                }
                r => r.map_err(|e| seat_err(index, &sample.load.mu, e))?,
            };
            progress.record(&seated);
            outputs.extend(relative(seated.pose));
        }
        if let Some(t) = &sample.tolerances {
            let perturbed = t.coupling(scene, coupling).map_err(|source| {
                let keys = scene.variation.keys(false, true).join(", ").into();
                StudyError::Perturbed { index, keys, source }.in_file(file)
            })?;
            let seated = s
                .method
                .seat(&perturbed, &nominal_load)
                .map_err(|e| seat_err(index, &nominal_load.mu, e))?
                .seated;
            progress.record(&seated);
            outputs.extend(relative(seated.pose));
        }
        (progress.tick)();
        Ok(SampleRecord { index, inputs: row, outputs })
    };
    // Quasi-static re-seatings without a thermal cycle go four at a time
    // in lanes (`seat4_in`: each the seating `seat_in` gives, so the
    // records are the same bits), in sample order.
    let four = match &s.method {
        Method::QuasiStatic(o) if s.lanes && var.reseating() && thermal.is_none() => Some(o),
        _ => None,
    };
    // One workspace per rayon job, reused by the samples it seats.
    let groups = rows
        .par_chunks(if four.is_some() { 4 } else { 1 })
        .map_init(Workspace::new, |ws, group| {
            if crate::cancel::requested() {
                return Err(StudyError::Cancelled);
            }
            let samples: Vec<Sample> =
                group.iter().map(|(_, row)| var.sample(scene, coupling, row)).collect();
            let mut lanes: Vec<Option<Result<SeatedPose, SolveError>>> = match (four, &samples[..])
            {
                (Some(o), [a, b, c, d]) => {
                    seat4_in(&setup, [&a.load, &b.load, &c.load, &d.load], o, ws)
                        .map(Some)
                        .into()
                }
                _ => samples.iter().map(|_| None).collect(),
            };
            let records = group.iter().zip(samples).zip(lanes.drain(..));
            records.map(|((r, sample), seated)| record(ws, r, sample, seated)).collect()
        })
        .collect::<Result<Vec<Vec<_>>, StudyError>>()?;
    Ok(groups.into_iter().flatten().collect())
}

/// The re-seating of one sample under `load` and its temperature cycle
/// (quasi-static only: the plan refuses the dynamic solver for a scene
/// with `[thermal]`): the seated pose and, per cycle point and evaluation
/// point, the outputs of the drift from that pose
/// ([`crate::solve::thermal::ThermalPath::drift`]).
fn reseat_and_cycle(
    setup: &SeatingSetup,
    method: &Method,
    load: &Load,
    points: &[EvaluationPoint],
    ws: &mut Workspace,
) -> Result<(SeatedPose, Vec<f64>), SolveError> {
    let Method::QuasiStatic(o) = method else {
        return Err(SolveError::ThermalNeedsQuasiStatic);
    };
    let coupling = setup.coupling();
    let bodies = coupling.thermal_bodies()?;
    let (seated, path) = seat_and_cycle_in(setup, load, o, ws)?;
    let drift = (0..path.points.len())
        .flat_map(|k| points.iter().map(move |p| (k, p)))
        .flat_map(|(k, p)| p.outputs(path.drift(bodies, k, &p.position)))
        .collect();
    Ok((seated, drift))
}

/// The re-seating of one sample under `load`: quasi-static by the seat
/// kernel in the reused workspace `ws` (whatever the sample's preload),
/// dynamic by a seating of its own.
fn reseat(
    setup: &SeatingSetup,
    method: &Method,
    load: &Load,
    ws: &mut Workspace,
) -> Result<SeatedPose, SolveError> {
    match method {
        Method::QuasiStatic(o) => seat_in(setup, load, o, ws),
        Method::Dynamic(_) => method.seat(setup.coupling(), load).map(|s| s.seated),
    }
}
