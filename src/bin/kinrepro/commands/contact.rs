//! `kinrepro contact`: one contact pair by hand, at a load or through a
//! load history.

use kinrepro::contact::ContactPair;
use kinrepro::contact::history::{HistoryError, LoadStep, drive, parse_history_csv};
use kinrepro::report::contact::{
    HistoryProvenance, conformity_warning, contact_table, history_csv,
};

use super::{emit, print_json, read_text};
use crate::error::CliError;
use crate::flags::high::{Checked, ContactInputs};
use crate::flags::low::ContactArgs;
use kinrepro::contact::{Friction, TangentialLaw};
use std::path::Path;

pub fn contact(o: Checked<ContactArgs, ContactInputs>) -> Result<(), CliError> {
    let Checked { args: a, opts } = o;
    if let (Some(path), Some(friction)) = (&a.history, opts.history_friction) {
        if let Some(load) = a.load {
            eprintln!(
                "warning: --load {load} is not used with --history: the normal loads come from the P_N column of {}",
                path.display()
            );
        }
        return history(&opts.pair, path, friction, a.tangential_law);
    }
    // Without --history the flags require --load.
    let load = a.load.unwrap_or(f64::NAN);
    let eval = opts.pair.evaluate(load)?;
    if let Some(warning) = conformity_warning(&opts.pair.law()?.hertz, load) {
        eprintln!("warning: {warning}");
    }
    if a.json {
        print_json(&eval)
    } else {
        emit(&contact_table(&eval))
    }
}

/// `--history`: drive the pair through the loads of `path`.
fn history(
    pair: &ContactPair,
    path: &Path,
    friction: Friction,
    tangential_law: TangentialLaw,
) -> Result<(), CliError> {
    let file = path.display().to_string();
    let rows = parse_history_csv(&read_text(path)?, &file)?;
    let loads: Vec<LoadStep> = rows.iter().map(|r| r.load).collect();
    let law = pair.law()?;
    // Hertz's half-space assumption is checked at the largest normal load.
    let peak = loads.iter().map(|l| l.normal_force).fold(0.0, f64::max);
    if let Some(warning) = conformity_warning(&law.hertz, peak) {
        eprintln!("warning: {warning}");
    }
    let steps = drive(&law, tangential_law, friction, &loads).map_err(|e| {
        let step = match &e {
            HistoryError::BadNormal { step, .. }
            | HistoryError::BadTangential { step, .. }
            | HistoryError::Slides { step, .. }
            | HistoryError::NoConvergence { step, .. } => *step,
        };
        CliError::from(e).in_context(format!("{file}:{}", rows[step - 1].line))
    })?;
    let prov = HistoryProvenance {
        shape: pair.shape.name(),
        curvature: pair.curvature,
        materials: (&pair.material1.name, &pair.material2.name),
        law: tangential_law.name(),
        mu_static: friction.mu_s,
        mu_dynamic: friction.mu_d,
        history_file: &file,
    };
    emit(&history_csv(&prov, &steps))
}
