//! A sweep rendered: its table and CSV ([`text`]), its design charts
//! ([`plot`], with the Pareto chart in [`pareto`]) and the design points
//! not evaluated ([`status`]).

pub mod pareto;
pub mod plot;
pub mod status;
pub mod text;
