//! A finished optimisation: its best feasible candidate, its document,
//! and the statistical error of the optimum's sampled objective and
//! constraints.

use super::{COST_TOLERANCE, PENALTY};
use super::{Candidate, Margin, OptimizeFingerprint, OptimizeReport, OptimizeSpec, Optimum};
use crate::explore::design_report::DesignReport;
use crate::explore::goal::{Goals, Objective, Output, Sense, direction_matches};
use crate::explore::run::SetRecord;
use crate::study::StudyPlan;
use crate::study::provenance::{Fingerprint, SCHEMA_VERSION, VERSION, fnv1a64, produced_by};

/// The best feasible candidate of `history` on `objective` (the first
/// of equals), if any is feasible.
pub(super) fn best(history: &[(Candidate, DesignReport)], objective: &Objective) -> Option<usize> {
    let better = |a: f64, b: f64| if objective.sense == Sense::Min { a < b } else { a > b };
    let mut best: Option<(usize, f64)> = None;
    for (i, (c, _)) in history.iter().enumerate() {
        let Some(f) = c.objective.filter(|_| c.feasible) else { continue };
        if best.is_none_or(|(_, b)| better(f, b)) {
            best = Some((i, f));
        }
    }
    best.map(|(i, _)| i)
}

/// The document of a finished optimisation.
pub(super) fn report(
    spec: &OptimizeSpec,
    plan: &StudyPlan,
    history: Vec<(Candidate, DesignReport)>,
    termination: Vec<String>,
    (searches, starts): (usize, usize),
) -> OptimizeReport {
    let objective = &spec.goals.objectives[0];
    let optimum = best(&history, objective).map(|i| &history[i]).map(|(c, d)| Optimum {
        evaluation: c.evaluation,
        fields: c.fields.clone(),
        objective: c.objective.unwrap_or(f64::NAN),
        constraint_margins: (spec.goals.constraints.iter().zip(&c.margins))
            .map(|(k, m)| Margin { constraint: k.name(), margin: m.unwrap_or(f64::NAN) })
            .collect(),
        design: d.clone(),
        statistical_error: statistical_error(&spec.goals, d),
    });
    let base = &plan.variants[0];
    OptimizeReport {
        schema_version: SCHEMA_VERSION,
        kinrepro_version: VERSION.to_string(),
        document: "optimize".to_string(),
        solver: plan.method().name().to_string(),
        sampler: base.design.sampler,
        seed: base.design.seed,
        samples: base.design.n,
        scene: spec.file.clone(),
        name: base.scene.name.clone(),
        vary: spec
            .sets
            .iter()
            .map(|s| SetRecord { field: s.path.clone(), values: s.spec.clone(), kind: s.kind })
            .collect(),
        fingerprint: OptimizeFingerprint {
            scene_content: format!("{:016x}", fnv1a64(spec.text.as_bytes())),
            study: Fingerprint::new(&base.scene, &plan.settings, &base.design),
        },
        goals: spec.goals.clone(),
        method: format!(
            "Nelder-Mead (argmin) in the unit cube of the ranges from its centre{}, stopping when \
             the simplex's costs spread less than {COST_TOLERANCE:e} or after {} iterations, \
             restarted from its best point while that helps; listed fields enumerated, each \
             combination searched alike; constraints by an exact L1 penalty of weight \
             {PENALTY} on violations relative to their bounds; the optimum is the best feasible \
             candidate evaluated; every candidate's study uses the same friction draws (common \
             random numbers)",
            match starts {
                1 => String::new(),
                2 => " and from 1 point of a Latin hypercube".to_string(),
                n => format!(" and from {} points of a Latin hypercube", n - 1),
            },
            spec.max_iterations
        ),
        starts,
        searches,
        shard: spec.shard,
        termination,
        optimum,
        history: history.into_iter().map(|(c, _)| c).collect(),
    }
}

/// The statistical error at the optimum: for the objective and every
/// constraint that reads a sigma, its value and the 90 % interval of the
/// design's method, and what common random numbers do and do not remove.
fn statistical_error(goals: &Goals, d: &DesignReport) -> String {
    let outputs = goals.objectives.iter().map(|o| &o.output);
    let sampled: Vec<String> = outputs
        .chain(goals.constraints.iter().map(|c| &c.output))
        .filter_map(|o| sampled_interval(o, d).map(|t| format!("{} = {t}", o.name())))
        .collect();
    if sampled.is_empty() {
        return "no objective or constraint reads a sampled quantity: the optimum has no \
                sampling error"
            .to_string();
    }
    format!(
        "{}; the optimum is that of these friction draws: common random numbers make the \
         comparison between candidates sharper than these intervals, not the values themselves",
        sampled.join("; ")
    )
}

/// `value (standard error s / sqrt(n))` of a mean drift output at `d`:
/// the drift's sigma s at the cycle point the output reads, over n
/// samples (the standard error of a mean of independent draws; a Latin
/// hypercube's is smaller).
fn mean_error(o: &Output, d: &DesignReport, point: &str) -> Option<String> {
    let value = o.value(d)?;
    let p = d.points.iter().find(|p| p.name == point)?;
    // The cycle point whose |mean| the output is: the last, or the largest.
    let unit = if o.unit() == "rad" { 3 } else { 0 };
    let largest = p
        .thermal
        .iter()
        .map(|c| c.drift.sigma.values()[unit..unit + 3].iter().cloned().fold(0.0, f64::max))
        .fold(0.0, f64::max);
    let n = p.n.max(1) as f64;
    Some(format!(
        "{value:.4e} (standard error of the mean at most {:.4e}: the largest drift sigma over the cycle / sqrt({}) for independent draws; a Latin hypercube's is smaller)",
        largest / crate::dof::NANO / n.sqrt(),
        p.n
    ))
}

/// `value [low, high] (method, n)` of a sigma or 3-sigma output at `d`
/// (SI), None for another output.
fn sampled_interval(o: &Output, d: &DesignReport) -> Option<String> {
    let (point, measure, factor) = match o {
        Output::Sigma { point, measure } => (point, measure, 1.0),
        Output::Pm3sigma { point, measure } => (point, measure, 3.0),
        Output::Drift { point, .. } | Output::Residual { point, .. } => {
            return mean_error(o, d, point);
        }
        _ => return None,
    };
    let value = o.value(d)?;
    let p = d.points.iter().find(|p| &p.name == point)?;
    let interval = if let Some(dof) = crate::dof::Dof::from_name(measure) {
        let (l, h) = p.sigma_ci90_low.zip(p.sigma_ci90_high)?;
        Some([l.si()[dof.index()], h.si()[dof.index()]])
    } else {
        let s = (p.directions.iter())
            .find(|s| direction_matches(measure, &s.name, s.kind == "about"))?;
        s.interval().map(|[l, h]| [l / crate::dof::NANO, h / crate::dof::NANO])
    };
    Some(match interval {
        Some([l, h]) => format!(
            "{value:.4e} [{:.4e}, {:.4e}] ({}, n = {})",
            factor * l,
            factor * h,
            p.sigma_interval_method,
            p.n
        ),
        None => format!("{value:.4e} (no interval: {})", p.sigma_interval_method),
    })
}

impl OptimizeReport {
    /// The line naming what produced this document.
    pub fn produced_by(&self) -> String {
        format!(
            "{}, optimisation of {}, shard {}",
            produced_by(
                &self.solver,
                &self.sampler.to_string(),
                &self.seed.to_string(),
                &self.samples.to_string(),
                "friction"
            ),
            self.scene,
            self.shard
        )
    }
}
