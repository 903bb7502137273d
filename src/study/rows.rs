//! Seating a study's rows: each design row's sample seated (rayon across
//! rows) and its outputs recorded relative to the nominal seating
//! ([`evaluate_rows`]). Quasi-static re-seatings without
//! a thermal cycle go four at a time in SIMD lanes
//! ([`seat4_in`]: each lane the seating [`seat_in`] gives, bit for bit),
//! in sample order, so that neither the lanes nor the number of jobs
//! change a record.

use rayon::prelude::*;

use super::StudyError;
use super::options::Settings;
use super::progress::Progress;
use super::stats::SampleRecord;
use super::variant::Variant;
use super::variation::{Sample, Variation};
use crate::assembly::BodyPose;
use crate::scene::{EvaluationPoint, Scene};
use crate::solve::quasistatic::{SeatingSetup, Workspace, seat_and_cycle_in, seat_in, seat4_in};
use crate::solve::{Load, Method, PointPose, SeatedPose, SolveError, SolverOptions};

/// Seat the coupling once per `(index, design row)` (rayon across rows)
/// and record the outputs named by
/// [`recorded_output_names`](super::runner::recorded_output_names),
/// relative to the nominal seating (nominal friction and preload,
/// touching start, same solver). Any design over the settings' inputs may
/// be passed (a study's design, or e.g. the matrices of a variance-based
/// sensitivity analysis). `progress` ticks once per finished row.
pub fn evaluate_rows<'a>(
    s: &Settings,
    v: &Variant,
    rows: Vec<(usize, Vec<f64>)>,
    progress: impl Into<Progress<'a>>,
) -> Result<Vec<SampleRecord>, StudyError> {
    let (scene, coupling) = (&v.scene, &v.coupling);
    // The reference: nominal friction and preload, from the touching pose, same solver.
    let nominal_load = Load::nominal(scene);
    let nominal = s.method.seat(coupling, &nominal_load).map_err(|source| {
        StudyError::Nominal { mu: nominal_load.mu.clone(), source }.in_file(v.file())
    })?;
    let r = Rows {
        s,
        v,
        setup: SeatingSetup::new(coupling, &scene.preload),
        reference: nominal.pose(),
        nominal_load,
        varied: varied_note(scene, &s.variation),
        progress: progress.into(),
    };
    let four = r.four();
    // One workspace per rayon job, reused by the samples it seats.
    let sets = rows
        .par_chunks(if four.is_some() { 4 } else { 1 })
        .map_init(Workspace::new, |ws, set| {
            if crate::cancel::requested() {
                return Err(StudyError::Cancelled);
            }
            let samples: Vec<Sample> =
                set.iter().map(|(_, row)| s.variation.sample(scene, coupling, row)).collect();
            let lanes: Vec<Option<Result<SeatedPose, SolveError>>> = match (four, &samples[..]) {
                (Some(o), [a, b, c, d]) => {
                    let loads = [&a.load, &b.load, &c.load, &d.load];
                    seat4_in(&r.setup, loads, o, ws).map(Some).into()
                }
                _ => samples.iter().map(|_| None).collect(),
            };
            let records = set.iter().zip(samples).zip(lanes);
            records.map(|((row, sample), seated)| r.record(ws, row, sample, seated)).collect()
        })
        .collect::<Result<Vec<Vec<_>>, StudyError>>()?;
    Ok(sets.into_iter().flatten().collect())
}

/// What every row of [`evaluate_rows`] shares.
struct Rows<'a> {
    s: &'a Settings,
    v: &'a Variant,
    setup: SeatingSetup<'a>,
    /// The nominal seating's pose and load.
    reference: BodyPose,
    nominal_load: Load,
    /// [`varied_note`] of the scene.
    varied: Box<str>,
    progress: Progress<'a>,
}

impl Rows<'_> {
    /// The solver options, if the re-seatings go four at a time in lanes:
    /// quasi-static, lanes asked for, re-seating without a thermal cycle.
    fn four(&self) -> Option<&SolverOptions> {
        let var = &self.s.variation;
        match &self.s.method {
            Method::QuasiStatic(o)
                if self.s.lanes && var.reseating() && self.v.coupling.thermal.is_none() =>
            {
                Some(o)
            }
            _ => None,
        }
    }

    /// Every evaluation point's outputs from the nominal seating to `pose`.
    fn relative(&self, pose: BodyPose) -> impl Iterator<Item = f64> + '_ {
        let reference = self.reference;
        self.v
            .scene
            .evaluation_points
            .iter()
            .flat_map(move |p| p.outputs(PointPose::between(&reference, &pose, &p.position)))
    }

    /// A failed seating of row `index` under `mu`.
    fn seat_err(&self, index: usize, mu: &[f64], source: SolveError) -> StudyError {
        let (varied, source) = (self.varied.clone(), Box::new(source));
        StudyError::Seating { index, mu: mu.to_vec(), varied, source }.in_file(self.v.file())
    }

    /// One row's record; `lanes` is its re-seating if the lanes seated it.
    fn record(
        &self,
        ws: &mut Workspace,
        (index, row): &(usize, Vec<f64>),
        sample: Sample,
        lanes: Option<Result<SeatedPose, SolveError>>,
    ) -> Result<SampleRecord, StudyError> {
        let (index, row) = (*index, row.clone());
        let (s, var, points) = (self.s, &self.s.variation, &self.v.scene.evaluation_points);
        let mut outputs: Vec<f64> = Vec::new();
        if var.reseating() && self.v.coupling.thermal.is_some() {
            let (seated, drift) =
                reseat_and_cycle(&self.setup, &s.method, &sample.load, points, ws)
                    .map_err(|e| self.seat_err(index, &sample.load.mu, e))?;
            self.progress.record(&seated);
            outputs.extend(self.relative(seated.pose));
            outputs.extend(drift);
        } else if var.reseating() {
            let seated = lanes.unwrap_or_else(|| reseat(&self.setup, &s.method, &sample.load, ws));
            let seated = match seated {
                // A varied start that does not centre is counted: a record without outputs.
                Err(SolveError::NotCentred { .. }) if var.start.is_some() => {
                    (self.progress.tick)();
                    return Ok(SampleRecord::not_centred(index, row));
                }
                r => r.map_err(|e| self.seat_err(index, &sample.load.mu, e))?,
            };
            self.progress.record(&seated);
            outputs.extend(self.relative(seated.pose));
        }
        if let Some(t) = &sample.tolerances {
            let seated = self.interchanged(index, t)?;
            self.progress.record(&seated);
            outputs.extend(self.relative(seated.pose));
        }
        (self.progress.tick)();
        Ok(SampleRecord { index, inputs: row, outputs })
    }

    /// Row `index`'s perturbed coupling seated at nominal friction and
    /// preload (interchangeability).
    fn interchanged(
        &self,
        index: usize,
        t: &super::inputs::Tolerances,
    ) -> Result<SeatedPose, StudyError> {
        let (scene, load) = (&self.v.scene, &self.nominal_load);
        let perturbed = t.coupling(scene, &self.v.coupling).map_err(|source| {
            let keys = scene.variation.keys(false, true).join(", ").into();
            StudyError::Perturbed { index, keys, source }.in_file(self.v.file())
        })?;
        let seated = self.s.method.seat(&perturbed, load);
        Ok(seated.map_err(|e| self.seat_err(index, &load.mu, e))?.seated)
    }
}

/// What a failed sample drew its preload or tolerances within: the
/// `[variation]` keys behind it (a bound may reach beyond what the
/// coupling carries), or empty.
fn varied_note(scene: &Scene, var: &Variation) -> Box<str> {
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
