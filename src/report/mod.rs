//! Renders the results: text tables with labelled units, CSV, JSON, SVG
//! plots and the HTML report. Every number comes from the library's result
//! types; nothing here computes physics, runs a study or runs in parallel.

pub mod analysis;
pub mod atomic;
pub mod calibration;
pub mod calibration_plot;
pub mod check;
pub mod contact;
pub mod contact_validity;
pub mod html;
pub mod materials;
pub mod plot;
pub mod preload;
pub mod printable;
pub mod progress;
pub mod run;
pub mod safety;
pub mod sensitivity;
pub mod study_files;
pub mod study_table;
pub mod study_text;
pub mod sweep_pareto;
pub mod sweep_plot;
pub mod sweep_status;
pub mod sweep_text;
pub mod table;
pub mod temporaries;
pub mod trace;
pub mod validate_hertz;
