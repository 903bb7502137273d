//! Running a reproducibility study of one scene: draw the design, seat the
//! coupling once per sample (rayon across samples), and record the pose of
//! every evaluation point relative to the nominal-mu seating.
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

use super::StudyError;
pub use super::inputs::{Input, Tolerances};
pub use super::paths::{LoadPath, PathTally, SeatingPaths};
pub use super::run_error::RunError;
use super::stats::SampleRecord;
pub use super::variation::{START_CLEARANCE, Sample, StartBounds, Variation, lifted_clear};
use super::{DesignSpec, Sampler, Shard};
use crate::assembly::{BodyPose, Coupling};
use crate::dof::Dof;

use crate::solve::dynamic::StartPose;
use crate::solve::quasistatic::{SeatingSetup, Workspace, seat_in};
use crate::solve::{Method, PointPose, SeatedPose, SolveError, nominal_mu};

/// How to run a study; `None` takes the scene's study settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StudyOptions {
    pub sampler: Option<Sampler>,
    pub samples: Option<usize>,
    pub seed: Option<u64>,
    pub shard: Shard,
    pub method: Method,
    pub variation: Variation,
    /// Also compute the sensitivity (SRC) tables of the report.
    pub sensitivity: bool,
    /// LHS replicates (`--replicates`; None: [`crate::study::sampling::default_replicates`]).
    pub replicates: Option<usize>,
}

impl Default for StudyOptions {
    fn default() -> Self {
        StudyOptions {
            sampler: None,
            samples: None,
            seed: None,
            shard: Shard::whole(),
            method: Method::default(),
            variation: Variation::default(),
            sensitivity: false,
            replicates: None,
        }
    }
}

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
        Progress {
            tick,
            tally: Some(tally),
        }
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

/// The design a scene's study uses under `opts`.
pub fn design_for(coupling: &Coupling, opts: &StudyOptions) -> Result<DesignSpec, StudyError> {
    let st = &coupling.scene.study;
    let sampler = opts.sampler.unwrap_or(st.sampler.into());
    let n = match sampler {
        Sampler::Corners => None,
        _ => Some(opts.samples.unwrap_or(st.samples)),
    };
    let dims = opts.variation.inputs(coupling).len();
    let spec = DesignSpec::new(sampler, dims, n, opts.seed.unwrap_or(st.seed))?;
    replicated(spec, opts.replicates)
}

/// An LHS split into `replicates` (default: 5, or the largest divisor of n
/// in 2..=5) so that its interval of sigma is valid; other designs as they are.
fn replicated(spec: DesignSpec, replicates: Option<usize>) -> Result<DesignSpec, StudyError> {
    use crate::study::sampling::{DEFAULT_LHS_REPLICATES, default_replicates};
    match (spec.sampler, replicates) {
        (_, Some(r)) => spec.with_replicates(r),
        (Sampler::Lhs, None) => match default_replicates(spec.n) {
            Some(r) => spec.with_replicates(r),
            None => Err(StudyError::InvalidParameter(format!(
                "an LHS of {} samples cannot be split into 2 to {DEFAULT_LHS_REPLICATES} replicates of at least 2 points (needed for its interval of sigma): give {}, or --replicates 1 for a single LHS without an interval",
                spec.n,
                nearest_replicable(spec.n)
            ))),
        },
        _ => Ok(spec),
    }
}

/// The sample counts nearest to `n` (one below, one above) that the default
/// replicate rule splits, with their replicate counts, as `--samples` advice.
fn nearest_replicable(n: usize) -> String {
    use crate::study::sampling::default_replicates;
    let fits = |m: usize| default_replicates(m).map(|r| format!("--samples {m} ({r} replicates)"));
    let below = (1..n).rev().find_map(fits);
    let above = (n + 1..).find_map(fits);
    below
        .into_iter()
        .chain(above)
        .collect::<Vec<_>>()
        .join(" or ")
}

/// Prefix of the interchangeability outputs (`interchange/<point>/<dof>`).
pub const INTERCHANGE_PREFIX: &str = "interchange/";

/// Names of the re-seating outputs (`<point>/<dof>_<SI unit>`, [`Dof::si_key`]).
pub fn output_names(coupling: &Coupling) -> Vec<String> {
    coupling
        .scene
        .evaluation_points
        .iter()
        .flat_map(|p| Dof::ALL.map(|d| format!("{}/{}", p.name, d.si_key())))
        .collect()
}

/// Names of all recorded outputs under `variation`: the re-seating outputs
/// (if friction, preload or start vary), then the interchangeability
/// outputs (if tolerances vary).
pub fn recorded_output_names(coupling: &Coupling, variation: &Variation) -> Vec<String> {
    let mut v = Vec::new();
    if variation.reseating() {
        v.extend(output_names(coupling));
    }
    if variation.tolerances {
        v.extend(
            output_names(coupling)
                .into_iter()
                .map(|n| format!("{INTERCHANGE_PREFIX}{n}")),
        );
    }
    v
}

/// Check that `opts` can run on this scene: something varies, a varied
/// start has the dynamic solver, and the scene gives bounds for a varied
/// preload or tolerances.
pub fn check_options(coupling: &Coupling, opts: &StudyOptions) -> Result<(), RunError> {
    let var = opts.variation;
    let err = |reason: &str| {
        Err(RunError::Options {
            file: coupling.scene.file.clone(),
            reason: reason.to_string(),
        })
    };
    if !var.reseating() && !var.tolerances {
        return err(
            "the study varies nothing: vary friction, preload, tolerances or the start pose",
        );
    }
    if var.start.is_some() && !matches!(opts.method, Method::Dynamic(_)) {
        return err("a varied start pose needs the dynamic solver (--solver dynamic)");
    }
    let bounds = coupling.scene.variation;
    if var.preload && !bounds.preload_varies() {
        return err(
            "--vary preload: the scene's [variation] table gives no preload bound \
             (preload_offset, preload_tilt)",
        );
    }
    if var.preload && !coupling.scene.preload.forces.iter().any(|f| f.varies()) {
        return err("--vary preload: the preload is only the weight, which is not varied");
    }
    if var.tolerances && !bounds.tolerances_vary() {
        return err(
            "--vary tolerances: the scene's [variation] table gives no tolerance \
             (ball_diameter, ball_position, surface_normal, surface_tilt, groove_position)",
        );
    }
    Ok(())
}

/// Run this shard's samples of one scene, reporting to `progress`.
///
/// Per sample: with friction, preload or start varied, the nominal
/// coupling is seated with the sample's friction, preload and start, and
/// its pose recorded relative to the nominal seating (re-seating scatter);
/// with tolerances varied, the sample's perturbed coupling is also seated
/// at nominal friction and preload, and its pose recorded relative to the
/// same nominal seating (interchangeability, `interchange/...` outputs).
pub fn run_variant<'a>(
    coupling: &Coupling,
    opts: &StudyOptions,
    progress: impl Into<Progress<'a>>,
) -> Result<VariantRun, RunError> {
    let (design, range) = shard_design(coupling, opts)?;
    // The records of this run are kept in memory (sweep points, calibration
    // and prediction studies, shards): bounded before anything is drawn.
    super::bounds::check(
        "seatings kept in memory",
        Some(range.len()),
        super::bounds::MAX_KEPT_SEATINGS,
    )
    .map_err(|source| RunError::Design {
        file: coupling.scene.file.clone(),
        source,
    })?;
    let rows = design
        .range(range.clone())
        .map_err(|source| design_error(coupling, source))?;
    let cannot_seat = super::verdict::cannot_seat(coupling, &opts.method)?;
    let records = evaluate_rows(coupling, opts, range.zip(rows).collect(), progress)?;
    Ok(VariantRun {
        design,
        shard: opts.shard,
        output_names: recorded_output_names(coupling, &opts.variation),
        records,
        cannot_seat,
    })
}

/// The checked options' design and this shard's sample range of it.
fn shard_design(
    coupling: &Coupling,
    opts: &StudyOptions,
) -> Result<(DesignSpec, std::ops::Range<usize>), RunError> {
    check_options(coupling, opts)?;
    let design = design_for(coupling, opts).map_err(|e| design_error(coupling, e))?;
    let range = opts
        .shard
        .range(design.n)
        .map_err(|e| design_error(coupling, e))?;
    Ok((design, range))
}

fn design_error(coupling: &Coupling, source: StudyError) -> RunError {
    RunError::Design {
        file: coupling.scene.file.clone(),
        source,
    }
}

/// Run this shard's samples in chunks of `chunk` rows (rayon within a
/// chunk), handing each chunk's records to `sink` in sample-index order:
/// bounded memory for any sample count, and results that do not depend on
/// the number of threads. Returns the design.
pub fn run_chunked<'a>(
    coupling: &Coupling,
    opts: &StudyOptions,
    chunk: usize,
    progress: impl Into<Progress<'a>>,
    sink: &mut dyn FnMut(Vec<SampleRecord>) -> Result<(), RunError>,
) -> Result<DesignSpec, RunError> {
    let progress = progress.into();
    let (design, range) = shard_design(coupling, opts)?;
    let design_err = |source| design_error(coupling, source);
    let mut start = range.start;
    while start < range.end {
        let end = (start + chunk.max(1)).min(range.end);
        let rows = design.range(start..end).map_err(design_err)?;
        sink(evaluate_rows(
            coupling,
            opts,
            (start..end).zip(rows).collect(),
            progress,
        )?)?;
        start = end;
    }
    Ok(design)
}

/// Seat the coupling once per `(index, design row)` (rayon across rows)
/// and record the outputs named by [`recorded_output_names`], relative to
/// the nominal seating (nominal friction and preload, touching start, same
/// solver). Any design over `opts.variation`'s inputs may be passed (a
/// study's design, or e.g. the matrices of a variance-based sensitivity
/// analysis). `progress` ticks once per finished row.
pub fn evaluate_rows<'a>(
    coupling: &Coupling,
    opts: &StudyOptions,
    rows: Vec<(usize, Vec<f64>)>,
    progress: impl Into<Progress<'a>>,
) -> Result<Vec<SampleRecord>, RunError> {
    let progress = progress.into();
    let file = coupling.scene.file.clone();
    let var = opts.variation;
    let seat_err = |index: usize, mu: &[f64], source| RunError::Seating {
        file: file.clone(),
        index,
        mu: mu.to_vec(),
        source,
    };
    let nominal_mu = nominal_mu(coupling);
    // The reference: nominal friction, from the touching pose, same solver.
    let nominal = opts
        .method
        .seat(coupling, &nominal_mu, &StartPose::touching())
        .map_err(|source| RunError::Nominal {
            file: file.clone(),
            mu: nominal_mu.clone(),
            source,
        })?;
    let points: Vec<_> = coupling
        .scene
        .evaluation_points
        .iter()
        .map(|p| p.position)
        .collect();
    // Every evaluation point's six components from the nominal seating to `pose`.
    let reference = nominal.pose;
    let relative = |pose: BodyPose| {
        let pose_of = move |p| PointPose::between(&reference, &pose, p).components();
        points.iter().flat_map(pose_of)
    };
    let setup = SeatingSetup::new(coupling);
    // One workspace per rayon job, reused by the samples it seats.
    rows.into_par_iter()
        .map_init(Workspace::new, |ws, (index, row)| {
            if crate::cancel::requested() {
                return Err(RunError::Cancelled);
            }
            let sample = var.sample(coupling, &row);
            let mut outputs: Vec<f64> = Vec::new();
            if var.reseating() {
                let s = match reseat(&setup, opts, &sample, ws) {
                    // A varied start that does not centre is counted: a record without outputs.
                    Err(SolveError::NotCentred { .. }) if var.start.is_some() => {
                        (progress.tick)();
                        return Ok(SampleRecord::not_centred(index, row));
                    }
                    s => s.map_err(|e| seat_err(index, &sample.mu, e))?,
                };
                progress.record(&s);
                outputs.extend(relative(s.pose));
            }
            if let Some(t) = &sample.tolerances {
                let perturbed = t.coupling(coupling).map_err(|source| RunError::Perturbed {
                    file: file.clone(),
                    index,
                    source,
                })?;
                let s = opts
                    .method
                    .seat(&perturbed, &nominal_mu, &StartPose::touching())
                    .map_err(|e| seat_err(index, &nominal_mu, e))?;
                progress.record(&s.seated_pose());
                outputs.extend(relative(s.pose));
            }
            (progress.tick)();
            Ok(SampleRecord {
                index,
                inputs: row,
                outputs,
            })
        })
        .collect::<Result<Vec<_>, RunError>>()
}

/// The re-seating of one sample: the nominal coupling with the sample's
/// friction, preload and start; quasi-static in the reused workspace `ws`
/// unless the preload varies (then the coupling differs from `setup`'s).
fn reseat(
    setup: &SeatingSetup,
    opts: &StudyOptions,
    sample: &Sample,
    ws: &mut Workspace,
) -> Result<SeatedPose, SolveError> {
    let seat = |c: &Coupling| {
        opts.method
            .seat(c, &sample.mu, &sample.start)
            .map(|s| s.seated_pose())
    };
    match opts.method {
        _ if opts.variation.preload => {
            let mut c = setup.coupling().clone();
            c.scene.preload = sample.preload.clone();
            seat(&c)
        }
        Method::QuasiStatic(o) => seat_in(setup, &sample.mu, &o, ws),
        Method::Dynamic(_) => seat(setup.coupling()),
    }
}
