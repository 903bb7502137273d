//! `kinrepro run`: one seating.

use std::path::{Path, PathBuf};

use kinrepro::assembly::Coupling;
use kinrepro::contact::friction::{in_transition, transition_warning};
use kinrepro::report::seating::run::RunReport;
use kinrepro::scene::Scene;
use kinrepro::solve::dynamic::{DynamicOptions, StartPose, seat_traced};
use kinrepro::solve::{Load, Method, Seating, Solver};

use super::{emit, print_json, read_scene, vector3};
use crate::error::{Context, Error, Result, usage};
use crate::flags::RunArgs;

/// `kinrepro run`, its flags checked.
pub struct Run {
    scene: PathBuf,
    /// The static coefficients (None: the scene's nominal).
    mu: Option<Vec<f64>>,
    method: Method,
    start: StartPose,
    trace: Option<PathBuf>,
    force: bool,
    json: bool,
}

impl TryFrom<RunArgs> for Run {
    type Error = Error;

    fn try_from(a: RunArgs) -> Result<Run> {
        if a.solver == Solver::QuasiStatic
            && (a.trace.is_some() || a.offset.is_some() || a.tilt.is_some())
        {
            usage!("--trace, --offset and --tilt need --solver dynamic");
        }
        Ok(Run {
            start: StartPose {
                offset: vector3("offset", a.offset.as_deref())?,
                tilt: vector3("tilt", a.tilt.as_deref())?,
            },
            method: Method::new(a.solver, a.path.increments, a.path.path_tolerance)?,
            scene: a.scene,
            mu: a.mu,
            trace: a.trace,
            force: a.force,
            json: a.json,
        })
    }
}

pub fn run(r: Run) -> Result {
    let (scene, coupling) = read_scene(&r.scene)?;
    let file = scene.file.clone();
    // The nominal seating starts where the seating does.
    let nominal = Load { start: r.start, ..Load::nominal(&scene) };
    let load = match &r.mu {
        Some(mu) => nominal.with_mu(mu),
        None => nominal.clone(),
    };
    let seating = match (&r.trace, &r.method) {
        (Some(path), Method::Dynamic(d)) => traced((&scene, &coupling), &load, d, path, r.force)?,
        _ => r.method.seat(&coupling, &load).context(&file)?,
    };
    let nominal = r.method.seat(&coupling, &nominal).context(&file)?;
    let weakening = seating.seated.decay_cv.filter(|&cv| in_transition(cv));
    if let Some(cv) = weakening {
        eprintln!("warning: {file}: {}", transition_warning(cv));
    }
    let model = (&scene, &coupling);
    let report = RunReport::new(model, &load.mu, &seating, &nominal, r.method.name());
    if r.json { print_json(&report) } else { emit(&report.table()) }
}

/// A dynamic seating with its trace written to `path` (whole or not at
/// all; kept when the seating fails, and the error says so, but not when
/// a signal stopped it).
fn traced(
    (scene, coupling): (&Scene, &Coupling),
    load: &Load,
    opts: &DynamicOptions,
    path: &Path,
    force: bool,
) -> Result<Seating> {
    let name = path.display().to_string();
    let mut trace_file =
        kinrepro::output::atomic::AtomicFile::create(path, force).context("--trace")?;
    let mut w =
        kinrepro::report::seating::trace::TraceWriter::new(trace_file.writer(), scene, coupling)
            .context(&name)?;
    let mut io_err = None;
    let result = seat_traced(coupling, load, opts, &mut |s| {
        if io_err.is_none() {
            io_err = w.write(s).err();
        }
    });
    if let Some(e) = io_err {
        return Err(e).context(format!("{name}: writing the trace failed"));
    }
    w.finish().context(&name)?;
    // Renamed into place under the signal lock; not at all once a signal
    // asked to stop (the partial trace of a cancelled seating is dropped).
    crate::signals::commit(vec![trace_file])?;
    result.context(&scene.file).map_err(|e| Error::new(format!("{e} (trace written to {name})")))
}
