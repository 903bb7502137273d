//! Renders the results: text tables with labelled units, CSV, JSON, SVG
//! plots and the HTML report. Every number comes from the library's result
//! types; nothing here computes physics, runs a study or runs in parallel.
//!
//! By subject: [`study`] (the study document's table, CSV, files and
//! plots), [`sweep`] (a sweep's table, CSV and charts), [`calibration`]
//! (calibrations and predictions), [`seating`] (one seating and its
//! trace), [`coupling`] (`check`, stiffness and load), [`contact`] (one
//! contact pair, the FE check of its law), [`materials`]. Shared formats:
//! [`table`] (one table type for text, CSV and HTML), [`html`] (the
//! self-contained HTML report), [`printable`] and [`progress`]. Files are
//! written through `crate::output`.

pub mod calibration;
pub mod contact;
pub mod coupling;
pub mod html;
pub mod materials;
pub mod optimize;
pub mod printable;
pub mod progress;
pub mod seating;
pub mod study;
pub mod sweep;
pub mod table;
pub mod thermal;
