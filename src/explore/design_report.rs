//! One design point's results in a sweep's or an optimisation's
//! document: its values, status, study statistics and nominal checks
//! ([`DesignReport`]), from its [`Evaluation`].

use std::collections::BTreeMap;

use serde::{Deserialize, Serialize};

use super::{Evaluation, Outcome, SweptValue};
use crate::study::PointStats;

/// One design point's results.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DesignReport {
    /// Row of the design, 0-based.
    pub index: usize,
    /// The swept fields by TOML path.
    pub values: BTreeMap<String, SweptValue>,
    /// `ok`, or why the point could not be evaluated (`invalid: ...`,
    /// `cannot seat: ...`, `failed: ...`).
    pub status: String,
    /// Why the point's fields do not go together (the scene loader's or
    /// the assembly's message); None for a valid point (one that loads
    /// and assembles, whether or not it could be evaluated).
    #[serde(default)]
    pub invalid_reason: Option<String>,
    /// On the Pareto front (null in one shard of several: the front needs
    /// every design, `merge` marks it).
    pub pareto: Option<bool>,
    /// Study statistics per evaluation point (nm, nrad), as a study's
    /// `points`; empty unless `status` is `ok`.
    pub points: Vec<PointStats>,
    /// Ascending principal translational stiffnesses at the first
    /// evaluation point, nominal seating [N/m].
    pub principal_stiffness_n_per_m: Option<[f64; 3]>,
    /// Ascending principal rotational stiffnesses [N m/rad].
    pub principal_rotational_stiffness_nm_per_rad: Option<[f64; 3]>,
    /// Smallest allowable / peak pressure over the contacts, nominal seating.
    pub min_pressure_safety_factor: Option<f64>,
    /// Friction limit for seating as `check` prints it (null: none below 10).
    pub friction_limit: Option<f64>,
    /// friction_limit - (mu_static + spread).
    pub friction_limit_margin: Option<f64>,
    /// Displacement of the first evaluation point along the preload
    /// direction, touching pose to nominal seating [m].
    pub nominal_approach_m: Option<f64>,
    /// Largest contact approach of the nominal seating [m].
    pub max_contact_approach_m: Option<f64>,
    /// The sweep's constraints this evaluated design breaks (or cannot be
    /// shown to meet), as written; such a design is not on the front.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub broken_constraints: Vec<String>,
}

/// The report of one evaluated design point: the study statistics by the
/// study's own machinery (its [`crate::study::VariantReport`]).
pub fn design_report(
    index: usize,
    values: BTreeMap<String, SweptValue>,
    e: Evaluation,
) -> DesignReport {
    let n = e.nominal;
    DesignReport {
        index,
        values,
        status: e.outcome.status(),
        invalid_reason: match &e.outcome {
            Outcome::Invalid(r) => Some(r.clone()),
            _ => None,
        },
        pareto: None,
        points: e.report.map(|r| r.points).unwrap_or_default(),
        principal_stiffness_n_per_m: n.map(|n| n.translational_n_per_m),
        principal_rotational_stiffness_nm_per_rad: n.map(|n| n.rotational_nm_per_rad),
        min_pressure_safety_factor: n.and_then(|n| n.min_pressure_safety_factor),
        friction_limit: n.and_then(|n| n.friction_limit),
        friction_limit_margin: n.and_then(|n| n.friction_limit_margin),
        nominal_approach_m: n.map(|n| n.approach_m),
        max_contact_approach_m: n.map(|n| n.max_contact_approach_m),
        broken_constraints: Vec::new(),
    }
}
