//! One function per verb, taking its checked options (`crate::flags`):
//! call the library and print. Shared helpers for printing and the thread pool.

mod analysis;
mod calibrate;
mod contact;
mod fe;
mod report;
mod scene;
mod seat;
mod study;
mod sweep;

use std::path::{Path, PathBuf};

use kinrepro::study::StudyReport;

use crate::error::{CliError, Context};
use crate::flags::high::{self, checked};
use crate::flags::low::{Command, Format};

/// Check the flags of `command` (`crate::flags::high`), then run it.
pub fn dispatch(command: Command) -> Result<(), CliError> {
    match command {
        Command::Contact(a) => contact::contact(checked(a, high::contact)?),
        Command::Check(a) => scene::check(&a.scenes),
        Command::Expand(a) => scene::expand(&a.scene),
        Command::Run(a) => seat::run(checked(a, high::run)?),
        Command::Stiffness(a) => analysis::stiffness(checked(a, high::stiffness)?),
        Command::Load(a) => analysis::load(checked(a, high::load)?),
        Command::Study(a) => study::study(checked(a, high::study)?),
        Command::Merge(a) => study::merge(a),
        Command::Sweep(a) => sweep::sweep(checked(a, high::sweep)?),
        Command::ValidateHertz(a) => fe::validate_hertz(checked(a, high::validate_hertz)?),
        Command::Report(a) => report::report(a),
        Command::Materials(a) => report::materials(a.format),
        Command::Calibrate(a) => calibrate::calibrate(checked(a, high::calibrate)?),
        Command::Predict(a) => calibrate::predict(checked(a, high::predict)?.args),
    }
}

pub fn print_study(report: &StudyReport, format: Format) -> Result<(), CliError> {
    match format {
        Format::Table => emit(&report.table()),
        Format::Csv => emit(&report.csv()),
        Format::Json => print_json(report),
    }
}

/// Write `text` to stdout. A closed pipe (`| head`) is not an error: the
/// reader has what it wanted, so the rest is dropped quietly as Unix tools
/// do; any other failure (a full disk) is one clear error.
pub fn emit(text: &str) -> Result<(), CliError> {
    use std::io::Write;
    // Control characters from the user's names are escaped (line breaks kept).
    let text = kinrepro::report::printable::printable_lines(text);
    let mut out = std::io::stdout().lock();
    match out.write_all(text.as_bytes()).and_then(|()| out.flush()) {
        Ok(()) => Ok(()),
        Err(e) if e.kind() == std::io::ErrorKind::BrokenPipe => Ok(()),
        Err(e) => Err(CliError::Stdout(e)),
    }
}

/// Most worker threads per core that `--jobs` may ask for.
pub const JOBS_PER_CORE: usize = 4;

/// Build the global thread pool for `--jobs` (at least 1, checked by the
/// flags), capped at the number of samples and at [`JOBS_PER_CORE`] per
/// core (said on stderr when capped).
pub fn set_jobs(jobs: Option<usize>, samples: usize) -> Result<(), CliError> {
    let Some(asked) = jobs else { return Ok(()) };
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

/// The progress bar of `total` seatings by `method` (on a terminal only),
/// after the run's estimate if it is above a minute (on stderr, terminal
/// or not: `study::bounds::estimate_note`).
pub fn progress(
    total: usize,
    method: &kinrepro::solve::Method,
) -> Result<indicatif::ProgressBar, CliError> {
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
    .with_key(
        "remaining",
        |s: &indicatif::ProgressState, w: &mut dyn std::fmt::Write| {
            let left =
                kinrepro::report::progress::remaining(s.elapsed(), s.pos(), s.len().unwrap_or(0));
            if let Some(left) = left {
                let _ = write!(w, " (about {} left)", indicatif::HumanDuration(left));
            }
        },
    );
    b.set_style(style);
    Ok(b)
}

pub use kinrepro::scene::plausible::as_typed as number;

pub fn print_json<T: serde::Serialize>(v: &T) -> Result<(), CliError> {
    emit(&format!("{}\n", serde_json::to_string_pretty(v)?))
}

/// The text of an input file.
pub fn read_text(path: &Path) -> Result<String, CliError> {
    kinrepro::input::read_to_string(path)
        .map_err(|e| CliError::file(path.display(), "cannot read the file: ", e))
}

/// The parts of a `merge` (study or sweep JSON), each read once: `what`
/// names the document in the error (`"study"`, `"sweep"`); `first` is the
/// first part's text, already read.
pub fn read_json_parts<T: serde::de::DeserializeOwned>(
    parts: &[PathBuf],
    first: String,
    what: &str,
) -> Result<Vec<(String, T)>, CliError> {
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
