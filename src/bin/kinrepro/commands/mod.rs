//! One module per verb family: each turns its flags into the one value it
//! runs (checking what the library does not), calls the library and
//! prints. Shared helpers for printing, files, flags and the thread pool.

mod analysis;
mod calibrate;
mod clean;
mod contact;
mod fe;
mod optimize;
mod report;
mod scene;
mod seat;
mod study;
mod sweep;
mod thermal;

use std::path::{Path, PathBuf};

use kinrepro::assembly::Coupling;
use kinrepro::scene::Scene;
use nalgebra::Vector3;

use crate::error::{Context, Error, Result, usage};
use crate::flags::{Command, Format};

/// Run `command`.
pub fn dispatch(command: Command) -> Result {
    match command {
        Command::Contact(a) => contact::contact(a.try_into()?),
        Command::Check(a) => scene::check(&a.scenes),
        Command::Expand(a) => scene::expand(&a.scene),
        Command::Run(a) => seat::run(a.try_into()?),
        Command::Stiffness(a) => analysis::stiffness(a.try_into()?),
        Command::Load(a) => analysis::load(a.try_into()?),
        Command::Thermal(a) => thermal::thermal(a.try_into()?),
        Command::Study(a) => study::study(a.try_into()?),
        Command::Merge(a) => study::merge(a),
        Command::Sweep(a) => sweep::sweep(a.try_into()?),
        Command::Optimize(a) => optimize::optimize(a),
        Command::ValidateHertz(a) => fe::validate_hertz(a.try_into()?),
        Command::Report(a) => report::report(a),
        Command::Materials(a) => report::materials(a.format),
        Command::Calibrate(a) => calibrate::calibrate(a.try_into()?),
        Command::Predict(a) => calibrate::predict(a.try_into()?),
        Command::Clean(a) => clean::clean(&a.dirs),
    }
}

/// Read a scene file, validate it and assemble its coupling.
pub fn read_scene(path: &Path) -> Result<(Scene, Coupling)> {
    Ok(kinrepro::error::read_scene(path)?)
}

/// Write `text` to stdout. A closed pipe (`| head`) is not an error: the
/// reader has what it wanted, so the rest is dropped quietly as Unix tools
/// do; any other failure (a full disk) is one clear error.
pub fn emit(text: &str) -> Result {
    use std::io::Write;
    // Control characters from the user's names are escaped (line breaks kept).
    let text = kinrepro::report::printable::printable_lines(text);
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(Error::new(format!("stdout: cannot write the results: {e}"))),
    }
}

/// Print a table, CSV or JSON in `format`.
pub fn print_as<T: serde::Serialize>(
    format: Format,
    value: &T,
    table: impl FnOnce() -> String,
    csv: impl FnOnce() -> String,
) -> Result {
    match format {
        Format::Table => emit(&table()),
        Format::Csv => emit(&csv()),
        Format::Json => print_json(value),
    }
}

pub fn print_json<T: serde::Serialize>(v: &T) -> Result {
    emit(&format!("{}\n", serde_json::to_string_pretty(v)?))
}

/// Most worker threads per core that `--jobs` may ask for.
pub const JOBS_PER_CORE: usize = 4;

/// `--jobs`: at least one worker thread (capped when the pool is built).
pub fn check_jobs(jobs: Option<usize>) -> Result {
    match jobs {
        Some(0) => usage!("--jobs 0: need at least 1 worker thread"),
        _ => Ok(()),
    }
}

/// Build the global thread pool for `--jobs` (checked: at least 1), capped
/// at the number of samples and at [`JOBS_PER_CORE`] per core (said on
/// stderr when capped).
pub fn set_jobs(jobs: Option<usize>, samples: usize) -> Result {
    let Some(asked) = jobs else { return Ok(()) };
    let cores = std::thread::available_parallelism().map_or(1, |n| n.get());
    let cap = (JOBS_PER_CORE * cores).min(samples.max(1));
    let j = asked.min(cap);
    if j < asked {
        eprintln!(
            "note: --jobs {asked} capped to {j} (at most {JOBS_PER_CORE} per core on {cores} core(s), and no more than the {samples} sample(s))"
        );
    }
    rayon::ThreadPoolBuilder::new().num_threads(j).build_global().context("--jobs")
}

/// The progress bar of `total` seatings by `method` (on a terminal only),
/// after the run's estimate if it is above a minute (on stderr, terminal
/// or not: `study::bounds::estimate_note`).
pub fn progress(total: usize, method: &kinrepro::solve::Method) -> Result<indicatif::ProgressBar> {
    let threads = rayon::current_num_threads();
    if let Some(note) = kinrepro::study::bounds::estimate_note(total, method, threads) {
        eprintln!("{note}");
    }
    if !std::io::IsTerminal::is_terminal(&std::io::stderr()) {
        return Ok(indicatif::ProgressBar::hidden());
    }
    let b = indicatif::ProgressBar::new(total as u64);
    let style = indicatif::ProgressStyle::with_template(
        "{elapsed_precise} [{bar:40}] {pos}/{len} seatings{remaining}",
    )?
    .with_key("remaining", |s: &indicatif::ProgressState, w: &mut dyn std::fmt::Write| {
        let left =
            kinrepro::report::progress::remaining(s.elapsed(), s.pos(), s.len().unwrap_or(0));
        if let Some(left) = left {
            let _ = write!(w, " (about {} left)", indicatif::HumanDuration(left));
        }
    });
    b.set_style(style);
    Ok(b)
}

pub use kinrepro::scene::plausible::as_typed as number;

/// The text of an input file.
pub fn read_text(path: &Path) -> Result<String> {
    kinrepro::input::read_to_string(path)
        .context(format!("{}: cannot read the file", path.display()))
}

/// Three comma-separated values of `--{flag}` (None: zero).
pub fn vector3(flag: &str, v: Option<&[f64]>) -> Result<Vector3<f64>> {
    match v {
        None => Ok(Vector3::zeros()),
        Some(&[x, y, z]) => Ok(Vector3::new(x, y, z)),
        Some(v) => usage!("--{flag} needs three comma-separated values, got {}", v.len()),
    }
}

/// Three finite values of `--{flag}` (None: zero).
pub fn finite3(flag: &str, v: Option<&[f64]>) -> Result<Vector3<f64>> {
    let x = vector3(flag, v)?;
    if !x.iter().all(|c| c.is_finite()) {
        usage!("--{flag} needs three finite numbers, got ({}, {}, {})", x.x, x.y, x.z);
    }
    Ok(x)
}

/// `--force` without any of the output files it would replace.
pub fn force_needs_output(force: bool, outputs: [&Option<PathBuf>; 2]) -> Result {
    if force && outputs.iter().all(|o| o.is_none()) {
        usage!(
            "--force: has no effect without --out or --html (it only allows replacing existing output files)"
        );
    }
    Ok(())
}

/// The parts of a `merge` (study or sweep JSON), each read once: `what`
/// names the document in the error (`"study"`, `"sweep"`); `first` is the
/// first part's text, already read.
pub fn read_json_parts<T: serde::de::DeserializeOwned>(
    parts: &[PathBuf],
    first: String,
    what: &str,
) -> Result<Vec<(String, T)>> {
    let mut first = Some(first);
    parts
        .iter()
        .map(|p| {
            let text = first.take().map_or_else(|| read_text(p), Ok)?;
            let doc = serde_json::from_str::<T>(&text)
                .context(format!("{}: not a kinrepro {what} JSON", p.display()))?;
            Ok((p.display().to_string(), doc))
        })
        .collect()
}
