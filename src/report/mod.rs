//! Human-facing text: tables with labelled units. Every number comes from
//! the library's result types; nothing here computes physics.

pub mod analysis;
pub mod atomic;
pub mod calibration;
pub mod calibration_plot;
pub mod check;
pub mod contact;
pub mod html;
pub mod materials;
pub mod merge;
pub mod provenance;
pub mod run;
pub mod safety;
pub mod sensitivity;
pub mod study;
pub mod study_checks;
pub mod study_files;
pub mod study_record;
pub mod study_stats;
pub mod study_stream;
pub mod study_table;
pub mod study_text;
pub mod sweep;
pub mod sweep_plot;
pub mod sweep_text;
pub mod trace;
pub mod validate_hertz;
