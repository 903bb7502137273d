//! One function per verb; shared helpers for parsing and printing.

mod analysis;
pub mod calibrate;
mod contact;
mod fe;
pub mod report;
mod scene;
mod seat;
mod study;
pub mod sweep;

use kinrepro::study::StudyReport;

use crate::args::{Command, Format};
use crate::error::CliError;

pub fn dispatch(command: Command) -> Result<(), CliError> {
    match command {
        Command::Contact(a) => contact::contact(a),
        Command::Check(a) => scene::check(a),
        Command::Expand(a) => scene::expand(a),
        Command::Run(a) => seat::run(a),
        Command::Stiffness(a) => analysis::stiffness(a),
        Command::Load(a) => analysis::load(a),
        Command::Study(a) => study::study(a),
        Command::Merge(a) => study::merge(a),
        Command::Sweep(a) => sweep::sweep(a),
        Command::ValidateHertz(a) => fe::validate_hertz(a),
        Command::Report(a) => report::report(a),
        Command::Materials(a) => report::materials(a),
        Command::Calibrate(a) => calibrate::calibrate_cmd(a),
        Command::Predict(a) => calibrate::predict_cmd(a),
    }
}

pub fn print_study(report: &StudyReport, format: Format) -> Result<(), CliError> {
    match format {
        Format::Table => emit(&report.table()),
        Format::Csv => emit(&report.csv()),
        Format::Json => emit(&format!("{}\n", serde_json::to_string_pretty(report)?)),
    }
}

/// Write `text` to stdout. A closed pipe (`| head`) is not an error: the
/// reader has what it wanted, so the rest is dropped quietly as Unix tools
/// do; any other failure (a full disk) is one clear error.
pub fn emit(text: &str) -> Result<(), CliError> {
    use std::io::Write;
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(CliError::Stdout(e)),
    }
}

/// Most worker threads per core that `--jobs` may ask for.
pub const JOBS_PER_CORE: usize = 4;

/// Build the global thread pool for `--jobs`, capped at the number of
/// samples and at [`JOBS_PER_CORE`] per core (said on stderr when capped).
pub fn set_jobs(jobs: Option<usize>, samples: usize) -> Result<(), CliError> {
    let Some(asked) = jobs else { return Ok(()) };
    if asked == 0 {
        return Err(CliError::Usage(
            "--jobs 0: need at least 1 worker thread".into(),
        ));
    }
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let cap = (JOBS_PER_CORE * cores).min(samples.max(1));
    let j = asked.min(cap);
    if j < asked {
        eprintln!(
            "note: --jobs {asked} capped to {j} (at most {JOBS_PER_CORE} per core on {cores} core(s), and no more than the {samples} sample(s))"
        );
    }
    rayon::ThreadPoolBuilder::new()
        .num_threads(j)
        .build_global()
        .map_err(CliError::Jobs)
}

/// Documented range of `--increments`.
pub const INCREMENTS: std::ops::RangeInclusive<usize> = 1..=100_000;

/// `--increments` inside [`INCREMENTS`].
pub fn check_increments(n: usize) -> Result<(), CliError> {
    if INCREMENTS.contains(&n) {
        Ok(())
    } else {
        Err(CliError::Usage(format!(
            "--increments {n}: out of range, need {}..={} load increments",
            INCREMENTS.start(),
            INCREMENTS.end()
        )))
    }
}

pub fn vector3(name: &str, v: Option<Vec<f64>>) -> Result<nalgebra::Vector3<f64>, CliError> {
    match v {
        None => Ok(nalgebra::Vector3::zeros()),
        Some(v) if v.len() == 3 => Ok(nalgebra::Vector3::new(v[0], v[1], v[2])),
        Some(v) => Err(CliError::Usage(format!(
            "--{name} needs three comma-separated values, got {}",
            v.len()
        ))),
    }
}

/// A finite three-vector option (None -> zero).
pub fn finite3(name: &str, v: Option<Vec<f64>>) -> Result<nalgebra::Vector3<f64>, CliError> {
    let x = vector3(name, v)?;
    if x.iter().all(|c| c.is_finite()) {
        Ok(x)
    } else {
        Err(CliError::Usage(format!(
            "--{name} needs three finite numbers, got ({}, {}, {})",
            x.x, x.y, x.z
        )))
    }
}

pub fn print_json<T: serde::Serialize>(v: &T) -> Result<(), CliError> {
    emit(&format!("{}\n", serde_json::to_string_pretty(v)?))
}

/// The parts of a `merge` (study or sweep JSON), each read once: `what`
/// names the document in the error (`"study"`, `"sweep"`); `first` is the
/// first part's text if the caller has already read it.
pub fn read_json_parts<T: serde::de::DeserializeOwned>(
    parts: &[std::path::PathBuf],
    mut first: Option<String>,
    what: &str,
) -> Result<Vec<(String, T)>, CliError> {
    use crate::error::Context;
    parts
        .iter()
        .map(|p| {
            let text = match first.take() {
                Some(t) => t,
                None => std::fs::read_to_string(p)
                    .map_err(|e| CliError::file(p.display(), "cannot read: ", e))?,
            };
            let doc = serde_json::from_str::<T>(&text)
                .context(format!("{}: not a kinrepro {what} JSON", p.display()))?;
            Ok((p.display().to_string(), doc))
        })
        .collect()
}
