//! One design point of a sweep: its scene text (the base scene with the
//! swept fields set), validated by the normal scene loader, and its
//! evaluation: the nominal seating's principal stiffnesses, smallest
//! pressure safety factor, friction limit and approach, then the
//! reproducibility study (`study::runner::run_variant`, the study's own
//! design and statistics).

use thiserror::Error;
use toml::Table;

use super::ExploreError;
use super::field::{SweptValue, set};
use super::values::Set;
use crate::analysis::stiffness::CouplingStiffness;
use crate::assembly::Coupling;
use crate::assembly::constraint::friction_limit;
use crate::scene::Scene;
use crate::solve::dynamic::StartPose;
use crate::solve::{PointPose, Seating, SolveError, nominal_mu};
use crate::study::runner::{RunError, StudyOptions, VariantRun, run_variant};

/// Why a valid design point could not be evaluated (its `failed:` status).
#[derive(Debug, Error)]
pub enum EvalError {
    /// The nominal seating (nominal friction `mu`, touching start) failed.
    #[error("the nominal seating (mu_s = {mu}): {source}")]
    NominalSeating {
        mu: f64,
        #[source]
        source: SolveError,
    },
    /// The stiffness of the nominal seating could not be formed.
    #[error(transparent)]
    Stiffness(SolveError),
    #[error("the seated stiffness matrix is not positive definite")]
    NotPositiveDefinite,
    /// The friction check or the reproducibility study failed.
    #[error(transparent)]
    Run(#[from] RunError),
}

/// What became of a design point.
#[derive(Debug, Clone, PartialEq)]
pub enum Outcome {
    /// Evaluated: the study ran.
    Ok,
    /// The scene of this point does not validate or assemble.
    Invalid(String),
    /// Friction does not move the seated pose: every contact sticks from
    /// the first load increment, the coupling does not centre.
    CannotSeat(String),
    /// A seating failed (the solver's reason).
    Failed(String),
}

impl Outcome {
    /// `ok`, or the reason it could not be evaluated (the JSON `status`).
    pub fn status(&self) -> String {
        match self {
            Outcome::Ok => "ok".to_string(),
            Outcome::Invalid(r) => format!("invalid: {r}"),
            Outcome::CannotSeat(r) => format!("cannot seat: {r}"),
            Outcome::Failed(r) => format!("failed: {r}"),
        }
    }
}

/// Results of the nominal seating (nominal friction and preload, touching
/// start) of a design point, SI units.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Nominal {
    /// Ascending principal translational stiffnesses at the first
    /// evaluation point [N/m] (`analysis::stiffness`, contacts at rest).
    pub translational_n_per_m: [f64; 3],
    /// Ascending principal rotational stiffnesses [N m/rad].
    pub rotational_nm_per_rad: [f64; 3],
    /// Smallest allowable / peak pressure over the contacts (None: no
    /// contact's materials give an allowable pressure).
    pub min_pressure_safety_factor: Option<f64>,
    /// Friction limit for seating (`assembly::constraint::friction_limit`,
    /// as `check` prints it; None: no limit below mu = 10).
    pub friction_limit: Option<f64>,
    /// friction_limit - (mu_static + spread): positive below the limit.
    pub friction_limit_margin: Option<f64>,
    /// Displacement of the first evaluation point along the preload
    /// direction from the touching pose to the nominal seating [m].
    pub approach_m: f64,
    /// Largest contact approach (Hertz plus support) [m].
    pub max_contact_approach_m: f64,
}

/// A design point's evaluation.
#[derive(Debug, Clone)]
pub struct Evaluation {
    pub outcome: Outcome,
    /// The assembled coupling (None if the scene is invalid).
    pub coupling: Option<Coupling>,
    pub nominal: Option<Nominal>,
    /// The study's samples (Some when `outcome` is `Ok`).
    pub run: Option<VariantRun>,
}

/// The scene text of a design point: `base` with each set field replaced.
pub fn point_text(
    base: &Table,
    sets: &[Set],
    values: &[SweptValue],
) -> Result<String, ExploreError> {
    let mut doc = base.clone();
    for (s, v) in sets.iter().zip(values) {
        set(&mut doc, &s.path, v)?;
    }
    toml::to_string(&doc).map_err(|e| ExploreError::Design(format!("cannot write the scene: {e}")))
}

/// Validate and evaluate one design point; `label` names it in messages.
/// Never fails: a bad point is an [`Outcome`] other than `Ok`.
pub fn evaluate(
    text: &str,
    label: &str,
    opts: &StudyOptions,
    tick: &(dyn Fn() + Sync),
) -> Evaluation {
    let mut e = Evaluation {
        outcome: Outcome::Ok,
        coupling: None,
        nominal: None,
        run: None,
    };
    // A stopped run (`cancel::request`) skips the points not yet begun.
    if crate::cancel::requested() {
        e.outcome = Outcome::Failed("stopped: a stop was requested".into());
        return e;
    }
    let scene = match Scene::parse(text, label) {
        Ok(s) => s,
        Err(err) => {
            // Line numbers would point into the generated text: name the
            // field only (for a parser error, the key on the error's line).
            let field = match (err.field.is_empty(), err.line) {
                (true, Some(line)) => field_at(text, line).unwrap_or_default(),
                _ => err.field,
            };
            e.outcome = Outcome::Invalid(if field.is_empty() {
                err.reason
            } else {
                format!("{field}: {}", err.reason)
            });
            return e;
        }
    };
    let coupling = match Coupling::new(&scene) {
        Ok(c) => c,
        Err(err) => {
            e.outcome = Outcome::Invalid(err.to_string());
            return e;
        }
    };
    e.outcome = match seat_and_study(&coupling, opts, tick, &mut e) {
        Ok(o) => o,
        Err(reason) => Outcome::Failed(reason.to_string()),
    };
    e.coupling = Some(coupling);
    e
}

/// The dotted path (`table.key`) of the `key = value` at 1-based `line`
/// of a TOML text, its table from the last header above it.
fn field_at(text: &str, line: usize) -> Option<String> {
    let lines: Vec<&str> = text.lines().take(line).collect();
    let key = lines.last()?.split_once('=')?.0.trim();
    let table = lines
        .iter()
        .rev()
        .find_map(|l| l.trim().strip_prefix('['))
        .map(|h| h.trim_matches(|c| c == '[' || c == ']').trim())?;
    Some(format!("{table}.{key}"))
}

fn seat_and_study(
    c: &Coupling,
    opts: &StudyOptions,
    tick: &(dyn Fn() + Sync),
    e: &mut Evaluation,
) -> Result<Outcome, EvalError> {
    let mu = nominal_mu(c);
    let seating = opts
        .method
        .seat(c, &mu, &StartPose::touching())
        .map_err(|source| EvalError::NominalSeating { mu: mu[0], source })?;
    e.nominal = Some(nominal(c, &seating, &mu)?);
    if let Some(reason) = crate::study::verdict::cannot_seat(c, &opts.method)? {
        return Ok(Outcome::CannotSeat(reason));
    }
    e.run = Some(run_variant(c, opts, tick)?);
    Ok(Outcome::Ok)
}

/// Stiffness, safety, friction limit and approach of the nominal seating.
fn nominal(c: &Coupling, seating: &Seating, mu: &[f64]) -> Result<Nominal, EvalError> {
    let point = c.scene.evaluation_points[0].position;
    let k = CouplingStiffness::new(c, seating, mu).map_err(EvalError::Stiffness)?;
    let at = seating.pose.apply(&point);
    let principal = k.principal_at(&at).ok_or(EvalError::NotPositiveDefinite)?;
    let limit = friction_limit(c).mu_limit;
    let f = &c.scene.friction;
    let limit = limit.is_finite().then_some(limit);
    let approach = PointPose::between(&c.touching_pose, &seating.pose, &point);
    let d = nalgebra::Vector3::new(approach.x_m, approach.y_m, approach.z_m);
    Ok(Nominal {
        translational_n_per_m: principal.translational.map(|(k, _)| k),
        rotational_nm_per_rad: principal.rotational.map(|(k, _)| k),
        min_pressure_safety_factor: seating
            .contacts
            .iter()
            .filter_map(|r| r.pressure_safety_factor)
            .reduce(f64::min),
        friction_limit: limit,
        friction_limit_margin: limit.map(|l| l - (f.mu_static + f.spread)),
        approach_m: d.dot(&c.scene.preload.resultant_direction()),
        max_contact_approach_m: seating
            .contacts
            .iter()
            .map(|r| r.approach_m)
            .fold(f64::NEG_INFINITY, f64::max),
    })
}
