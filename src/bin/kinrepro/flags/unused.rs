//! Flags that would have no effect where they are given: each is an error
//! naming the flag and what it needs, so that a run never silently ignores
//! what the user asked for. Rules that clap expresses (`requires`) are on
//! the flags themselves ([`super::low`]); these are the ones that depend on
//! a flag's value or on one of several other flags. (`--increments` and
//! `--path-tolerance` with the dynamic solver, or together, are refused by the library's
//! `kinrepro::study::request::method`, for the Python package too.)

use std::path::PathBuf;

use super::low::ContactArgs;
use super::low_study::{StudyArgs, SweepArgs};
use crate::error::CliError;

fn usage(message: impl Into<String>) -> CliError {
    CliError::Usage(message.into())
}

/// `contact --radius2` with a shape that has no second radius (a plane).
pub fn contact(a: &ContactArgs) -> Result<(), CliError> {
    match (a.shape, a.radius2) {
        (Some(shape), Some(r2)) if !shape.needs_radius2() => Err(usage(format!(
            "--radius2 {r2}: has no effect with --shape {}, whose fixed body has no radius (leave it out)",
            shape.name()
        ))),
        _ => Ok(()),
    }
}

/// `--force` without any of the output files it would replace.
fn force(force: bool, outputs: [&Option<PathBuf>; 2]) -> Result<(), CliError> {
    if force && outputs.iter().all(|o| o.is_none()) {
        return Err(usage(
            "--force: has no effect without --out or --html (it only allows replacing existing output files)",
        ));
    }
    Ok(())
}

pub fn study(a: &StudyArgs) -> Result<(), CliError> {
    force(a.force, [&a.out, &a.html])
}

pub fn sweep(a: &SweepArgs) -> Result<(), CliError> {
    force(a.force, [&a.out, &a.html])
}
