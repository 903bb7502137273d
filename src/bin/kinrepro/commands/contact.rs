//! `kinrepro contact`: one contact pair by hand, at a load or through a
//! load history.

use std::path::{Path, PathBuf};

use kinrepro::contact::history::{HistoryError, LoadStep, drive, parse_history_csv};
use kinrepro::contact::{
    ContactLaw, ContactPair, ContactShape, Friction, PairCurvature, TangentialLaw,
    TangentialSupport,
};
use kinrepro::material::Material;
use kinrepro::report::contact::validity::{HertzValidity, hertz_validity, radius_hint};
use kinrepro::report::contact::{HistoryProvenance, contact_table, history_csv};
use nalgebra::Vector3;

use super::{emit, number, print_json, read_text};
use crate::error::{Context, Error, Result, usage};
use crate::flags::ContactArgs;

/// `kinrepro contact`, its flags checked: the pair with its materials, and
/// the friction and file of `--history`.
pub struct Contact {
    pair: ContactPair,
    load: Option<f64>,
    history: Option<(PathBuf, Friction, TangentialLaw, TangentialSupport)>,
    json: bool,
}

impl TryFrom<ContactArgs> for Contact {
    type Error = Error;

    fn try_from(a: ContactArgs) -> Result<Contact> {
        if let (Some(shape), Some(r2)) = (a.shape, a.radius2)
            && !shape.needs_radius2()
        {
            usage!(
                "--radius2 {r2}: has no effect with --shape {}, whose fixed body has no radius (leave it out)",
                shape.name()
            );
        }
        let history = match a.history.clone() {
            None => None,
            Some(path) => {
                if let Some(load) = a.load {
                    usage!(
                        "--load {load}: has no effect with --history, whose normal loads are the P_N column of {} (leave it out)",
                        path.display()
                    );
                }
                let c = a.tangential_compliance;
                let across = a.tangential_compliance_across;
                for (flag, c) in [("", Some(c)), ("-across", across)] {
                    if let Some(c) = c
                        && !(c.is_finite() && c >= 0.0)
                    {
                        usage!("--tangential-compliance{flag} {c}: must be finite and >= 0 (m/N)");
                    }
                }
                let support = match across {
                    None => TangentialSupport::isotropic(c),
                    Some(across) => TangentialSupport { along: c, across, axis: Vector3::x() },
                };
                if !support.is_rigid() && a.tangential_law == TangentialLaw::MindlinDeresiewicz {
                    usage!(
                        "--tangential-compliance: the mindlin-deresiewicz law does not take a support compliance (use --tangential-law coulomb)"
                    );
                }
                Some((path, history_friction(&a)?, a.tangential_law, support))
            }
        };
        let pair = pair(&a)?;
        radius_hints(&a);
        Ok(Contact { pair, load: a.load, history, json: a.json })
    }
}

/// `--angle-deg` in radians: finite and within one turn each way (beyond
/// it the sine and cosine of a large number carry its rounding only).
fn angle_rad(deg: Option<f64>) -> Result<f64> {
    let deg = deg.unwrap_or(0.0);
    if !(deg.is_finite() && deg.abs() <= 360.0) {
        let shown = if deg.abs() < 1e6 { deg.to_string() } else { format!("{deg:e}") };
        usage!("--angle-deg {shown}: give an angle in [-360, 360] degrees");
    }
    Ok(deg.to_radians())
}

/// `--mu` and `--dynamic-ratio` of `--history`.
fn history_friction(a: &ContactArgs) -> Result<Friction> {
    let mu = a.mu.unwrap_or(f64::NAN);
    let max = kinrepro::scene::resolve::MU_MAX;
    if !(mu.is_finite() && mu > 0.0 && mu <= max) {
        usage!("--mu {mu}: the friction coefficient must lie in (0, {max}] (the scenes' bound)");
    }
    let ratio = a.dynamic_ratio;
    if !(ratio > 0.0 && ratio <= 1.0) {
        usage!("--dynamic-ratio {ratio}: must lie in (0, 1]");
    }
    Ok(Friction::switch(mu, ratio * mu))
}

/// The pair of `--shape` with its radii, or of `--radii1` and `--radii2`;
/// one that is not a point contact is refused, in words.
fn pair(a: &ContactArgs) -> Result<ContactPair> {
    let material1 = Material::builtin(&a.material1).context("--material1")?;
    let material2 = Material::builtin(&a.material2).context("--material2")?;
    let pair = match (a.shape, &a.radii1, &a.radii2) {
        (Some(shape), _, _) => {
            let r1 = a.radius1.unwrap_or(f64::NAN);
            ContactPair::from_shape(shape, r1, a.radius2, material1, material2)?
        }
        (None, Some(r1), Some(r2)) => ContactPair {
            shape: ContactShape::General,
            curvature: PairCurvature {
                radii1: principal_radii("--radii1", r1)?,
                radii2: principal_radii("--radii2", r2)?,
                angle: angle_rad(a.angle_deg)?,
            },
            material1,
            material2,
        },
        _ => usage!("give --shape with --radius1, or --radii1 with --radii2"),
    };
    pair.law()?;
    Ok(pair)
}

/// The two principal radii RX,RY [m] of `--radii1` or `--radii2`.
fn principal_radii(flag: &str, v: &[f64]) -> Result<[f64; 2]> {
    match v {
        [x, y] => Ok([*x, *y]),
        _ => usage!(
            "{flag} needs two comma-separated principal radii RX,RY [m] (inf: flat, negative: concave), got {} value(s)",
            v.len()
        ),
    }
}

pub fn contact(c: Contact) -> Result {
    if let Some((path, friction, law, compliance)) = &c.history {
        return history(&c.pair, path, *friction, (*law, *compliance));
    }
    // Without --history the flags require --load.
    let load = c.load.unwrap_or(f64::NAN);
    let eval = c.pair.evaluate(load)?;
    validity(&c.pair, load).context(format!("--load {}", number(load)))?;
    if c.json { print_json(&eval) } else { emit(&contact_table(&eval)) }
}

/// Hertz's validity at `load`: a warning where the numbers are only
/// indicative, an error where they mean nothing.
fn validity(pair: &ContactPair, load: f64) -> Result {
    match hertz_validity(&pair.law()?.hertz, &pair.curvature, load) {
        HertzValidity::Valid => Ok(()),
        HertzValidity::Indicative(w) => {
            eprintln!("warning: {w}");
            Ok(())
        }
        HertzValidity::Meaningless(why) => Err(Error::new(why)),
    }
}

/// A warning for each radius flag that looks like millimetres.
fn radius_hints(a: &ContactArgs) {
    let single = [("--radius1", a.radius1), ("--radius2", a.radius2)];
    let single = single.into_iter().filter_map(|(f, r)| Some((f, r?, false)));
    let radii = [("--radii1", &a.radii1), ("--radii2", &a.radii2)];
    let principal =
        radii.into_iter().flat_map(|(f, r)| r.iter().flatten().map(move |x| (f, *x, true)));
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
    (tangential_law, support): (TangentialLaw, TangentialSupport),
) -> Result {
    let file = path.display().to_string();
    let rows = parse_history_csv(&read_text(path)?, &file)?;
    let loads: Vec<LoadStep> = rows.iter().map(|r| r.load).collect();
    let law = ContactLaw { tangential_support: support, ..pair.law()? };
    // Hertz's half-space assumption is checked at the largest normal load.
    let peak = loads.iter().map(|l| l.normal_force).fold(0.0, f64::max);
    validity(pair, peak).context(format!("{file}: P_N {}", number(peak)))?;
    let steps = drive(&law, tangential_law, friction, &loads).map_err(|e| {
        let step = match &e {
            HistoryError::BadNormal { step, .. }
            | HistoryError::BadTangential { step, .. }
            | HistoryError::Slides { step, .. }
            | HistoryError::NoConvergence { step, .. } => *step,
        };
        Error::new(format!("{file}:{}: {e}", rows[step - 1].line))
    })?;
    let prov = HistoryProvenance {
        shape: pair.shape.name(),
        curvature: pair.curvature,
        materials: (&pair.material1.name, &pair.material2.name),
        law: tangential_law.name(),
        mu_static: friction.mu_s,
        mu_dynamic: friction.mu_d,
        history_file: &file,
        tangential_support: support,
        command: "contact --history",
    };
    emit(&history_csv(&prov, &steps))
}
