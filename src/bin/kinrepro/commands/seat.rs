//! `kinrepro run`: one seating.

use super::*;
use crate::args::*;
use crate::error::{CliError, Context};
use kinrepro::assembly::Coupling;
use kinrepro::solve::Seating;
use kinrepro::solve::dynamic::{DynamicOptions, StartPose, seat_traced};
use std::path::Path;

pub fn run(args: RunArgs) -> Result<(), CliError> {
    let RunArgs {
        scene,
        mu,
        increments,
        solver,
        trace,
        force,
        offset,
        tilt,
        json,
    } = args;
    let coupling = kinrepro::error::read_coupling(&scene)?;
    if solver == SolverKind::QuasiStatic && (trace.is_some() || offset.is_some() || tilt.is_some())
    {
        return Err(CliError::Usage(
            "--trace, --offset and --tilt need --solver dynamic".to_string(),
        ));
    }
    check_increments(increments)?;
    let opts = kinrepro::solve::SolverOptions {
        increments,
        ..Default::default()
    };
    let dyn_opts = DynamicOptions {
        start: StartPose {
            offset: vector3("offset", offset)?,
            tilt: vector3("tilt", tilt)?,
        },
        ..Default::default()
    };
    let nominal_mu = kinrepro::solve::nominal_mu(&coupling);
    let mu = mu.unwrap_or_else(|| nominal_mu.clone());
    let file = coupling.scene.file.clone();
    let seat = |m: &[f64]| {
        match solver {
            SolverKind::QuasiStatic => kinrepro::solve::quasistatic::seat(&coupling, m, &opts),
            SolverKind::Dynamic => kinrepro::solve::dynamic::seat(&coupling, m, &dyn_opts),
        }
        .context(&file)
    };
    let seating = match (&trace, solver) {
        (Some(path), SolverKind::Dynamic) => traced(&coupling, &mu, &dyn_opts, path, force)?,
        _ => seat(&mu)?,
    };
    let nominal = seat(&nominal_mu)?;
    let report = kinrepro::report::run::RunReport::new(
        &coupling,
        &mu,
        &seating,
        &nominal,
        match solver {
            SolverKind::QuasiStatic => "quasi-static",
            SolverKind::Dynamic => "dynamic",
        },
    );
    if json {
        print_json(&report)
    } else {
        emit(&report.table())
    }
}

/// A dynamic seating with its trace written to `path` (whole or not at
/// all; kept when the seating fails, and the error says so).
fn traced(
    coupling: &Coupling,
    mu: &[f64],
    dyn_opts: &DynamicOptions,
    path: &Path,
    force: bool,
) -> Result<Seating, CliError> {
    let file = &coupling.scene.file;
    let name = path.display().to_string();
    let mut trace_file =
        kinrepro::report::atomic::AtomicFile::create(path, force).context("--trace")?;
    let mut w = kinrepro::report::trace::TraceWriter::new(trace_file.writer(), coupling)
        .map_err(|e| CliError::file(&name, "", e))?;
    let mut io_err = None;
    let result = seat_traced(coupling, mu, dyn_opts, &mut |s| {
        if io_err.is_none() {
            io_err = w.write(s).err();
        }
    });
    if let Some(e) = io_err {
        return Err(CliError::file(&name, "writing the trace failed: ", e));
    }
    w.finish().map_err(|e| CliError::file(&name, "", e))?;
    trace_file.commit()?;
    result.map_err(|e| CliError::Traced {
        trace: name.clone(),
        source: Box::new(CliError::from(e).in_context(file)),
    })
}
