//! Human-facing text: tables with labelled units. Every number comes from
//! the library's result types; nothing here computes physics.

pub mod analysis;
pub mod check;
pub mod contact;
pub mod run;
pub mod safety;
pub mod sensitivity;
pub mod study;
pub mod trace;
pub mod validate_hertz;
