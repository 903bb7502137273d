//! The command line's error: every library error by type (`#[from]`), the
//! command line's own argument checks, and the few failures that belong to
//! the CLI itself (stdout, the thread pool, reading an input file).
//!
//! Rules, so that the enum stays easy to extend:
//! - A library error gets a `#[from]` variant whose message is the library's
//!   own (`"{0}"`); add one per new library error type.
//! - Where a command adds where it happened (the scene file, an option), it
//!   wraps the error with [`Context::context`] (`"{context}: {error}"`),
//!   never by formatting it into a string.
//! - [`CliError::Usage`] is only for checks of the arguments themselves (a
//!   value out of range, options that do not go together); it is not a
//!   catch-all for failures of the library.

use std::fmt::Display;

use kinrepro::assembly::AssemblyError;
use kinrepro::calibrate::CalibrateError;
use kinrepro::contact::ContactError;
use kinrepro::contact::history::{HistoryCsvError, HistoryError};
use kinrepro::explore::ExploreError;
use kinrepro::explore::{SweepError, SweepMergeError};
use kinrepro::fe::FeError;
use kinrepro::material::MaterialError;
use kinrepro::report::coupling::analysis::ReportError;
use kinrepro::output::atomic::WriteError;
use kinrepro::report::calibration::plot::PlotError as CalibrationPlotError;
use kinrepro::report::html::HtmlError;
use kinrepro::report::sweep::plot::SweepPlotError;
use kinrepro::scene::SceneError;
use kinrepro::solve::SolveError;
use kinrepro::study::merge::MergeError;
use kinrepro::study::runner::RunError;
use kinrepro::study::{StudyError, StudyRunError};
use thiserror::Error;

#[derive(Debug, Error)]
pub enum CliError {
    /// An argument out of range, or options that do not go together.
    #[error("{0}")]
    Usage(String),
    #[error("{0}")]
    Read(#[from] kinrepro::error::Error),
    #[error("{0}")]
    Scene(#[from] SceneError),
    #[error("{0}")]
    Assembly(#[from] AssemblyError),
    #[error("{0}")]
    Material(#[from] MaterialError),
    #[error("{0}")]
    Contact(#[from] ContactError),
    #[error("{0}")]
    History(#[from] HistoryError),
    #[error("{0}")]
    HistoryCsv(#[from] HistoryCsvError),
    #[error("{0}")]
    Solve(#[from] SolveError),
    #[error("{0}")]
    Fe(#[from] FeError),
    #[error("{0}")]
    Study(#[from] StudyError),
    #[error("{0}")]
    Run(#[from] RunError),
    #[error("{0}")]
    StudyRun(#[from] StudyRunError),
    #[error("{0}")]
    Report(#[from] ReportError),
    #[error("{0}")]
    Write(#[from] WriteError),
    #[error("merge: {0}")]
    Merge(#[from] MergeError),
    #[error("{0}")]
    Html(#[from] HtmlError),
    #[error("{0}")]
    Calibrate(#[from] CalibrateError),
    #[error("{0}")]
    CalibrationPlot(#[from] CalibrationPlotError),
    #[error("{0}")]
    Explore(#[from] ExploreError),
    #[error("{0}")]
    Sweep(#[from] SweepError),
    #[error("merge: {0}")]
    SweepMerge(#[from] SweepMergeError),
    #[error("{0}")]
    SweepPlot(#[from] SweepPlotError),
    #[error("{0}")]
    Json(#[from] serde_json::Error),
    #[error("{0}")]
    Progress(#[from] indicatif::style::TemplateError),
    /// An input or output file of the command line itself.
    #[error("{path}: {what}{source}")]
    File {
        path: String,
        /// What was being done, with its trailing ": " (or empty).
        what: &'static str,
        #[source]
        source: std::io::Error,
    },
    /// A run stopped by SIGINT or SIGTERM (`crate::signals`).
    #[error("interrupted")]
    Interrupted,
    #[error("stdout: cannot write the results: {0}")]
    Stdout(#[source] std::io::Error),
    #[error("--jobs: {0}")]
    Jobs(#[from] rayon::ThreadPoolBuildError),
    #[error("{failed} of {total} scenes are invalid")]
    InvalidScenes { failed: usize, total: usize },
    #[error("{count} of {total} scenes cannot seat (CANNOT SEAT above)")]
    UnseatableScenes { count: usize, total: usize },
    #[error("cannot seat: {0} (pass --allow-unseated to accept this result)")]
    CannotSeat(String),
    /// A failed seating whose trace file was still written.
    #[error("{source} (trace written to {trace})")]
    Traced {
        trace: String,
        #[source]
        source: Box<CliError>,
    },
    /// Any of the above, with where it happened: `"{context}: {source}"`.
    #[error("{context}: {source}")]
    In {
        context: String,
        #[source]
        source: Box<CliError>,
    },
}

impl CliError {
    /// This error, with where it happened: `"{context}: {self}"`.
    pub fn in_context(self, context: impl Display) -> Self {
        CliError::In {
            context: context.to_string(),
            source: Box::new(self),
        }
    }

    /// An input or output file that could not be handled (`what`: e.g.
    /// `"cannot read: "`, or `""` for the bare I/O message).
    pub fn file(path: impl Display, what: &'static str, source: std::io::Error) -> Self {
        CliError::File {
            path: path.to_string(),
            what,
            source,
        }
    }
}

/// Say where an error happened: `result.context(file)?`.
pub trait Context<T> {
    fn context(self, context: impl Display) -> Result<T, CliError>;
}

impl<T, E: Into<CliError>> Context<T> for Result<T, E> {
    fn context(self, context: impl Display) -> Result<T, CliError> {
        self.map_err(|e| e.into().in_context(context))
    }
}
