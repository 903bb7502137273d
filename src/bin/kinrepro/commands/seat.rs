//! `kinrepro run`: one seating.

use std::path::Path;

use kinrepro::assembly::Coupling;
use kinrepro::contact::friction::{in_transition, transition_warning};
use kinrepro::report::seating::run::RunReport;
use kinrepro::solve::dynamic::{DynamicOptions, seat_traced};
use kinrepro::solve::{Method, Seating};

use super::*;
use crate::error::{CliError, Context};
use crate::flags::high::Checked;
use crate::flags::low::RunArgs;

pub fn run(o: Checked<RunArgs, Method>) -> Result<(), CliError> {
    let Checked {
        args: a,
        opts: method,
    } = o;
    let coupling = kinrepro::error::read_coupling(&a.scene)?;
    let nominal_mu = kinrepro::solve::nominal_mu(&coupling);
    let mu = a.mu.unwrap_or_else(|| nominal_mu.clone());
    let file = coupling.scene.file.clone();
    let seat = |m: &[f64]| {
        match &method {
            Method::QuasiStatic(q) => kinrepro::solve::quasistatic::seat(&coupling, m, q),
            Method::Dynamic(d) => kinrepro::solve::dynamic::seat(&coupling, m, d),
        }
        .context(&file)
    };
    let seating = match (&a.trace, &method) {
        (Some(path), Method::Dynamic(d)) => traced(&coupling, &mu, d, path, a.force)?,
        _ => seat(&mu)?,
    };
    let nominal = seat(&nominal_mu)?;
    let weakening = seating.decay_cv.filter(|&cv| in_transition(cv));
    if let Some(cv) = weakening {
        eprintln!("warning: {file}: {}", transition_warning(cv));
    }
    let report = RunReport::new(&coupling, &mu, &seating, &nominal, method.name());
    if a.json {
        print_json(&report)
    } else {
        emit(&report.table())
    }
}

/// A dynamic seating with its trace written to `path` (whole or not at
/// all; kept when the seating fails, and the error says so, but not when
/// a signal stopped it).
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
        kinrepro::output::atomic::AtomicFile::create(path, force).context("--trace")?;
    let mut w = kinrepro::report::seating::trace::TraceWriter::new(trace_file.writer(), coupling)
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
    // Renamed into place under the signal lock; not at all once a signal
    // asked to stop (the partial trace of a cancelled seating is dropped).
    crate::signals::commit(vec![trace_file])?;
    result.map_err(|e| CliError::Traced {
        trace: name.clone(),
        source: Box::new(CliError::from(e).in_context(file)),
    })
}
