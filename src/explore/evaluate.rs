//! One design point of a sweep: its scene (the base scene's typed form
//! with the swept fields set), validated by the normal scene loader, and
//! its evaluation: the nominal seating's principal stiffnesses, smallest
//! pressure safety factor, friction limit and approach, then the
//! reproducibility study of the sweep's plan (its design and statistics).

use thiserror::Error;

use super::field::{SetError, SweptValue, set};
use super::values::Set;
use crate::analysis::stiffness::CouplingStiffness;
use crate::assembly::Coupling;
use crate::assembly::friction_limit::friction_limit;
use crate::scene::{Scene, SceneFile};
use crate::solve::{Load, PointPose, Seating, SolveError};
use crate::study::{StudyError, StudyPlan, Variant, VariantReport};

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
    Study(#[from] StudyError),
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
    /// Friction limit for seating (`assembly::friction_limit`,
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
    pub nominal: Option<Nominal>,
    /// The study's report (Some when `outcome` is `Ok`).
    pub report: Option<VariantReport>,
}

/// The scene of a design point: `base` with each set field set; a value
/// the field does not take is the point's invalid reason (`FIELD: reason`).
pub fn point_file(
    base: &SceneFile,
    sets: &[Set],
    values: &[SweptValue],
) -> Result<SceneFile, SetError> {
    let mut file = base.clone();
    for (s, v) in sets.iter().zip(values) {
        set(&mut file, &s.path, v).map_err(|reason| SetError { path: s.path.clone(), reason })?;
    }
    Ok(file)
}

/// Validate and evaluate one design point, its scene `point` (from
/// [`point_file`]) read from `source`; `label` names it in messages, and
/// its study is `base`'s design and samples in `plan`. Never fails: a bad
/// point is an [`Outcome`] other than `Ok`. `friction_limit`: compute the
/// friction limit for seating (about 0.1 s; an optimisation's candidates
/// skip it unless a goal reads it).
pub fn evaluate(
    point: Result<SceneFile, SetError>,
    source: &str,
    label: &str,
    plan: &StudyPlan,
    (base, friction_limit): (&Variant, bool),
    tick: &(dyn Fn() + Sync),
) -> Evaluation {
    let mut e = Evaluation { outcome: Outcome::Ok, nominal: None, report: None };
    // A stopped run (`cancel::request`) skips the points not yet begun.
    if crate::cancel::requested() {
        e.outcome = Outcome::Failed("stopped: a stop was requested".into());
        return e;
    }
    let point = point.map_err(|e| e.to_string());
    let scene = match point.and_then(|f| Scene::from_file(&f, label, source).map_err(invalid)) {
        Ok(s) => s,
        Err(reason) => {
            e.outcome = Outcome::Invalid(reason);
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
    let v = base.with_model(scene, coupling);
    e.outcome = match seat_and_study(&v, (plan, friction_limit), tick, &mut e) {
        Ok(o) => o,
        Err(reason) => Outcome::Failed(reason.to_string()),
    };
    e
}

/// A design point's invalid reason: the field and the scene loader's
/// reason (no line: the point has no text of its own).
fn invalid(err: crate::scene::SceneError) -> String {
    match err.field.is_empty() {
        true => err.reason,
        false => format!("{}: {}", err.field, err.reason),
    }
}

fn seat_and_study(
    v: &Variant,
    (plan, friction_limit): (&StudyPlan, bool),
    tick: &(dyn Fn() + Sync),
    e: &mut Evaluation,
) -> Result<Outcome, EvalError> {
    let load = Load::nominal(&v.scene);
    let seating = plan
        .method()
        .seat(&v.coupling, &load)
        .map_err(|source| EvalError::NominalSeating { mu: load.mu[0], source })?;
    e.nominal = Some(nominal(&v.scene, &v.coupling, (&seating, &load), friction_limit)?);
    if let Some(reason) = crate::study::verdict::cannot_seat(&v.scene, &v.coupling, plan.method())?
    {
        return Ok(Outcome::CannotSeat(reason));
    }
    let report = plan.kept(v, tick)?;
    if let Some(r) = &report.cannot_seat {
        return Ok(Outcome::CannotSeat(r.clone()));
    }
    e.report = Some(report);
    Ok(Outcome::Ok)
}

/// Stiffness, safety, friction limit (if `with_limit`) and approach of the
/// nominal seating.
fn nominal(
    scene: &Scene,
    c: &Coupling,
    (seating, load): (&Seating, &Load),
    with_limit: bool,
) -> Result<Nominal, EvalError> {
    let point = scene.evaluation_points[0].position;
    let k = CouplingStiffness::new(c, seating, load).map_err(EvalError::Stiffness)?;
    let at = seating.pose().apply(&point);
    let principal = k.principal_at(&at).ok_or(EvalError::NotPositiveDefinite)?;
    let limit = match with_limit {
        true => friction_limit(c, &load.preload).mu_limit,
        false => f64::NAN,
    };
    let f = &scene.friction;
    let limit = limit.is_finite().then_some(limit);
    let approach = PointPose::between(&c.touching_pose, &seating.pose(), &point);
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
        approach_m: d.dot(&scene.preload.resultant_direction()),
        max_contact_approach_m: seating
            .contacts
            .iter()
            .map(|r| r.approach_m)
            .fold(f64::NEG_INFINITY, f64::max),
    })
}
