//! One seating rendered: `kinrepro run`'s table and JSON ([`run`]) and the
//! dynamic solver's time history ([`trace`]).

pub mod run;
pub mod trace;
