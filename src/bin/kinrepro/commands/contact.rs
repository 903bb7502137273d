//! `kinrepro contact`: one contact pair by hand, at a load or through a
//! load history.

use std::path::Path;

use kinrepro::contact::history::{HistoryError, LoadStep, drive, parse_history_csv};
use kinrepro::contact::{ContactPair, ContactShape, Friction, PairCurvature};
use kinrepro::material::Material;
use kinrepro::report::contact::{
    HistoryProvenance, conformity_warning, contact_table, history_csv,
};

use super::emit;
use crate::args::*;
use crate::error::{CliError, Context};

pub fn contact(args: ContactArgs) -> Result<(), CliError> {
    let pair = pair(&args)?;
    let eval = pair.evaluate(args.load)?;
    if let Some(warning) = conformity_warning(&eval) {
        eprintln!("warning: {warning}");
    }
    if let Some(path) = &args.history {
        return history(&args, &pair, path);
    }
    if args.json {
        let text = serde_json::to_string_pretty(&eval)?;
        emit(&format!("{text}\n"))
    } else {
        emit(&contact_table(&eval))
    }
}

/// The pair of `--shape` with `--radius1/--radius2`, or of the principal
/// radii `--radii1/--radii2` and `--angle-deg`.
fn pair(args: &ContactArgs) -> Result<ContactPair, CliError> {
    let material1 = Material::builtin(&args.material1).context("--material1")?;
    let material2 = Material::builtin(&args.material2).context("--material2")?;
    let (Some(r1), Some(r2)) = (&args.radii1, &args.radii2) else {
        let shape = args.shape.unwrap_or(ContactShape::SpherePlane);
        let r1 = args.radius1.unwrap_or(f64::NAN);
        return Ok(ContactPair::from_shape(
            shape,
            r1,
            args.radius2,
            material1,
            material2,
        )?);
    };
    let two = |flag: &str, v: &[f64]| match v {
        [x, y] => Ok([*x, *y]),
        _ => Err(CliError::Usage(format!(
            "{flag} needs two comma-separated principal radii RX,RY [m], got {}",
            v.len()
        ))),
    };
    Ok(ContactPair {
        shape: ContactShape::General,
        curvature: PairCurvature {
            radii1: two("--radii1", r1)?,
            radii2: two("--radii2", r2)?,
            angle: args.angle_deg.unwrap_or(0.0).to_radians(),
        },
        material1,
        material2,
    })
}

fn history(args: &ContactArgs, pair: &ContactPair, path: &Path) -> Result<(), CliError> {
    let mu = args.mu.unwrap_or(f64::NAN);
    if !(mu.is_finite() && mu > 0.0) {
        return Err(CliError::Usage(format!(
            "--mu {mu}: the friction coefficient must be positive and finite"
        )));
    }
    let ratio = args.dynamic_ratio;
    if !(ratio > 0.0 && ratio <= 1.0) {
        return Err(CliError::Usage(format!(
            "--dynamic-ratio {ratio}: must lie in (0, 1]"
        )));
    }
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| CliError::file(&file, "", e))?;
    let rows = parse_history_csv(&text, &file)?;
    let loads: Vec<LoadStep> = rows.iter().map(|r| r.load).collect();
    let friction = Friction::switch(mu, ratio * mu);
    let law = pair.law()?;
    let steps = drive(&law, args.tangential_law, friction, &loads).map_err(|e| {
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
        materials: (&args.material1, &args.material2),
        law: args.tangential_law.name(),
        mu_static: friction.mu_s,
        mu_dynamic: friction.mu_d,
        history_file: &file,
    };
    emit(&history_csv(&prov, &steps))
}
