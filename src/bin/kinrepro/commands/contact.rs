//! `kinrepro contact`: one contact pair by hand, at a load or through a
//! load history.

use kinrepro::contact::ContactPair;
use kinrepro::contact::history::{HistoryError, LoadStep, drive, parse_history_csv};
use kinrepro::report::contact::{HistoryProvenance, contact_table, history_csv};
use kinrepro::report::contact::validity::{HertzValidity, hertz_validity, radius_hint};

use super::{emit, number, print_json, read_text};
use crate::error::CliError;
use crate::flags::high::{Checked, ContactInputs};
use crate::flags::low::ContactArgs;
use kinrepro::contact::{Friction, TangentialLaw};
use std::path::Path;

pub fn contact(o: Checked<ContactArgs, ContactInputs>) -> Result<(), CliError> {
    let Checked { args: a, opts } = o;
    radius_hints(&a);
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
    validity(&opts.pair, load).map_err(|e| e.in_context(format!("--load {}", number(load))))?;
    if a.json {
        print_json(&eval)
    } else {
        emit(&contact_table(&eval))
    }
}

/// Hertz's validity at `load`: a warning where the numbers are only
/// indicative, an error where they mean nothing.
fn validity(pair: &ContactPair, load: f64) -> Result<(), CliError> {
    match hertz_validity(&pair.law()?.hertz, &pair.curvature, load) {
        HertzValidity::Valid => Ok(()),
        HertzValidity::Indicative(w) => {
            eprintln!("warning: {w}");
            Ok(())
        }
        HertzValidity::Meaningless(why) => Err(CliError::Usage(why)),
    }
}

/// A warning for each radius flag that looks like millimetres.
fn radius_hints(a: &ContactArgs) {
    let single = [("--radius1", a.radius1), ("--radius2", a.radius2)];
    let single = single.into_iter().filter_map(|(f, r)| Some((f, r?, false)));
    let radii = [("--radii1", &a.radii1), ("--radii2", &a.radii2)];
    let principal = radii
        .into_iter()
        .flat_map(|(f, r)| r.iter().flatten().map(move |x| (f, *x, true)));
    for (flag, r, principal) in single.chain(principal) {
        if let Some(hint) = radius_hint(flag, r, principal) {
            eprintln!("warning: {hint}");
        }
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
    validity(pair, peak).map_err(|e| e.in_context(format!("{file}: P_N {}", number(peak))))?;
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
