//! The flags, as clap parses them: one struct per verb ([`verbs`],
//! [`studies`]), the groups several verbs share ([`groups`], flattened
//! into each), and the library's enums parsed directly (`Solver`,
//! `Varied`, `Sampler`). Each command turns its struct into the one value
//! it runs (`crate::commands`); a flag's value is checked there or by the
//! library, never twice.

pub mod groups;
pub mod studies;
pub mod verbs;

use clap::{Parser, Subcommand};
use kinrepro::param::Param;

pub use groups::{Format, TextFormat};
pub use studies::{CalibrateArgs, OptimizeArgs, PredictArgs, StudyArgs, SweepArgs};
pub use verbs::*;

#[derive(Parser)]
#[command(name = "kinrepro", version, about = "Re-seating reproducibility of kinematic couplings")]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Subcommand)]
pub enum Command {
    /// Evaluate one contact pair (Hertz, Mindlin, tau_max) at a load, or drive
    /// it through a load history (--history).
    Contact(ContactArgs),
    /// Load and validate scenes; print contacts, constraint status and friction limit.
    Check(CheckArgs),
    /// Seat the coupling once and print pose and contact states.
    Run(RunArgs),
    /// Stiffness of the seated coupling: 6x6 matrix, compliance and principal
    /// stiffnesses at a point (contacts at rest: static friction sticks).
    Stiffness(StiffnessArgs),
    /// Apply a force (and moment) after seating, preload held: deflection,
    /// contact forces and the safe load envelope (first separation or slip).
    Load(LoadArgs),
    /// Thermal drift: seat the coupling, then follow its [thermal] temperature
    /// cycle: the drift of each evaluation point, the contacts that slide,
    /// the first slip and the residual.
    Thermal(ThermalArgs),
    /// Reproducibility study: seat each scene once per friction sample and
    /// report the scatter of the pose (Table 2 of the paper).
    Study(StudyArgs),
    /// Merge the JSON outputs of sharded studies (or sweeps, or optimisations) into the result of one run.
    Merge(MergeArgs),
    /// Sweep scene fields over a grid or an LHS: reproducibility, stiffness,
    /// safety and friction limit per design point, and the Pareto front.
    Sweep(SweepArgs),
    /// The best design within bounds: one objective (e.g. the smallest
    /// sigma at a point) under constraints (e.g. sf_p>=3, k_min>=2e8), by
    /// Nelder-Mead over the varied fields, every candidate's study on the
    /// same friction draws.
    Optimize(OptimizeArgs),
    /// Check the Hertz law of every distinct contact pair of the scenes with
    /// the mini FE solver, at the load the nominal seating reaches.
    ValidateHertz(ValidateHertzArgs),
    /// Print the explicit form of a scene (loads back to the same coupling).
    Expand(ExpandArgs),
    /// Write one self-contained HTML report of study JSON files.
    Report(ReportArgs),
    /// List the built-in materials with E, nu, density, allowable pressure and sources.
    Materials(MaterialsArgs),
    /// Fit the friction spread of a scene to a measured re-seating scatter
    /// (docs/measurements.md) and write a calibration file.
    Calibrate(CalibrateArgs),
    /// Predict sigma of other scenes with a calibrated friction spread, with
    /// a prediction interval.
    Predict(PredictArgs),
    /// Remove the temporary files a killed run left in folders
    /// (`.NAME.kinrepro-XXXXXX.tmp`, untouched for a minute).
    Clean(CleanArgs),
}

/// The message for a negative number given to an option that takes none
/// (clap reads `--samples -1` as an unknown flag `-1` and suggests
/// `-- -1`, which would make it a file name): the option, the value and
/// that the option takes no negative number. `None` for any
/// other error (clap's own message then).
pub fn negative_value(e: &clap::Error, args: &[String]) -> Option<String> {
    use clap::error::{ContextKind, ContextValue, ErrorKind};
    if e.kind() != ErrorKind::UnknownArgument {
        return None;
    }
    let Some(ContextValue::String(value)) = e.get(ContextKind::InvalidArg) else {
        return None;
    };
    value.parse::<f64>().ok().filter(|_| value.starts_with('-'))?;
    let at = args.iter().position(|a| a == value)?;
    let before = at.checked_sub(1).map(|i| args[i].as_str()).filter(|a| a.starts_with("--"));
    Some(match before {
        Some(flag) => format!(
            "{flag} {value}: {flag} takes no negative number (`kinrepro {} --help` gives its \
             range)",
            args.get(1).map_or("COMMAND", String::as_str)
        ),
        None => format!("{value}: a negative number where an option or a file was expected"),
    })
}

/// A library parameter as the command line writes it: its flag
/// (`--path-tolerance`), followed by its value where the message gives one.
pub fn spelling(param: Param, value: Option<&str>) -> String {
    let flag = match param {
        Param::Sets => "--set".to_string(),
        p => format!("--{}", p.name().replace('_', "-")),
    };
    match value {
        None => flag,
        Some(v) => format!("{flag} {v}"),
    }
}
