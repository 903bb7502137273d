//! A coupling rendered: `kinrepro check`'s summary ([`check`]), the
//! stiffness and load reports ([`analysis`]) and the preload's text
//! ([`preload`]).

pub mod analysis;
pub mod check;
pub mod preload;
