//! A sweep rendered: its table and CSV ([`text`]), its design charts
//! ([`plot`], with the Pareto chart in [`pareto`]) and the design points
//! not evaluated ([`status`]).

pub mod pareto;
pub mod plot;
pub mod status;
pub mod text;

use crate::output::atomic::WriteError;

/// A chart could not be drawn or written.
#[derive(Debug, thiserror::Error)]
pub enum SweepPlotError {
    #[error("sweep chart: {0}")]
    Draw(String),
    #[error(transparent)]
    Write(#[from] WriteError),
}
