//! `kinrepro optimize`: the best design within bounds on one objective
//! under constraints ([`super::goal`]). The continuous fields (`--vary
//! FIELD=LOW:HIGH`, `log:LOW:HIGH` searched in the logarithm) are searched
//! by Nelder-Mead (argmin) in the unit cube of their ranges, from its
//! centre; fields given as a list (materials, keywords, numbers) are
//! enumerated outside the search, one search per combination.
//!
//! Every candidate's study is the base scene's plan: the same sampler,
//! seed and samples, so the same friction draws (common random numbers):
//! sigma is then a smooth function of the design, and two candidates
//! differ by their design, not by their draws.
//!
//! Constraints by an exact (L1) penalty: the search minimises
//! s f / |f_0| + P sum_i max(0, -m_i) / max(|b_i|, tiny) + P |u - clamp(u)|^2
//! (s = +1 for min, -1 for max; f_0 the objective at the first candidate;
//! m_i the margin of constraint i, b_i its bound; P = [`PENALTY`], larger
//! than any Lagrange multiplier of the normalised problem this tool meets,
//! so the penalised minimum is the constrained one (Nocedal and Wright,
//! "Numerical Optimization", 2006, thm. 17.3)). A candidate that cannot be
//! evaluated costs [`PENALTY`] squared. The optimum reported is the best
//! feasible candidate evaluated (feasible first), whatever the search's
//! last simplex.

use std::collections::BTreeMap;
use std::sync::Mutex;

use argmin::core::{CostFunction, Executor, State};
use argmin::solver::neldermead::NelderMead;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

use super::design_report::{DesignReport, design_report};
use super::goal::{Goals, Objective, Output, Sense};
use super::run::{SetRecord, SweepError};
use super::values::Levels;
use super::{ExploreError, Set, SweptValue, evaluate, point_file};
use crate::param::Param;
use crate::scene::SceneFile;
use crate::study::StudyPlan;
use crate::study::provenance::{SCHEMA_VERSION, VERSION, produced_by};

/// The weight of a normalised constraint violation (module docs).
pub const PENALTY: f64 = 1e3;

/// Most restarts of the search from its best point (module docs).
pub const RESTARTS: usize = 6;

/// Default cap on the search's iterations per combination of listed values.
pub const MAX_ITERATIONS: u64 = 200;

/// The spread of the simplex's costs at which a search stops (normalised
/// cost, module docs).
pub const COST_TOLERANCE: f64 = 1e-7;

/// An optimisation as asked for.
#[derive(Debug, Clone)]
pub struct OptimizeSpec {
    pub file: String,
    pub text: String,
    pub base: SceneFile,
    /// Ranges (searched) and lists (enumerated).
    pub sets: Vec<Set>,
    pub goals: Goals,
    pub max_iterations: u64,
}

/// One candidate the search evaluated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Candidate {
    /// 1-based, in the order evaluated.
    pub evaluation: usize,
    pub fields: BTreeMap<String, SweptValue>,
    /// The objective's value (SI), None if the design gave none.
    pub objective: Option<f64>,
    /// Each constraint's margin in its unit (>= 0: met), in order.
    pub margins: Vec<Option<f64>>,
    pub feasible: bool,
    /// The penalised cost the search minimised.
    pub cost: f64,
    /// `ok` or why the design was not evaluated.
    pub status: String,
}

/// The optimum: its fields, its full study and checks, and its margins.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Optimum {
    pub evaluation: usize,
    pub fields: BTreeMap<String, SweptValue>,
    pub objective: f64,
    /// Each constraint's margin at the optimum (its unit, >= 0).
    pub constraint_margins: Vec<Margin>,
    /// The optimum's study statistics and nominal checks.
    pub design: DesignReport,
    /// The statistical error of the objective at the optimum, in words.
    pub statistical_error: String,
}

/// How far a design is inside one constraint.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Margin {
    /// The constraint as written (`sf_p>=3`).
    pub constraint: String,
    /// bound - value for `<=`, value - bound for `>=` (the output's SI unit).
    pub margin: f64,
}

/// The optimisation's document (`kinrepro optimize --json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct OptimizeReport {
    pub schema_version: u32,
    pub kinrepro_version: String,
    /// Always `optimize`.
    pub document: String,
    pub solver: String,
    pub sampler: crate::study::Sampler,
    pub seed: u64,
    pub samples: usize,
    pub scene: String,
    pub name: String,
    pub vary: Vec<SetRecord>,
    #[serde(flatten)]
    pub goals: Goals,
    /// The search and the constraint rule, in words.
    pub method: String,
    /// Why each search stopped (one per combination of listed values).
    pub termination: Vec<String>,
    /// None: no candidate met every constraint.
    pub optimum: Option<Optimum>,
    pub history: Vec<Candidate>,
}

/// The search's cost function: each call evaluates a candidate (or
/// returns its cost from the history) and records it.
#[derive(Clone)]
struct Search<'a> {
    spec: &'a OptimizeSpec,
    plan: &'a StudyPlan,
    /// The listed values of this combination, by field.
    fixed: Vec<(usize, SweptValue)>,
    /// The searched fields' indices in `spec.sets`.
    searched: Vec<usize>,
    history: &'a Mutex<Vec<(Candidate, DesignReport)>>,
    scale: &'a Mutex<Option<f64>>,
    /// Compute the friction limit (a goal reads `friction_margin`).
    friction_limit: bool,
    tick: &'a (dyn Fn() + Sync),
}

impl Search<'_> {
    /// The design point of unit coordinates `u` (clamped into the box).
    fn values(&self, u: &[f64]) -> Vec<SweptValue> {
        let mut values: Vec<SweptValue> = vec![SweptValue::Number(f64::NAN); self.spec.sets.len()];
        for (k, v) in &self.fixed {
            values[*k] = v.clone();
        }
        for (&k, &x) in self.searched.iter().zip(u) {
            let interval = self.spec.sets[k].interval.expect("a searched field has a range");
            values[k] = SweptValue::Number(interval.at(x.clamp(0.0, 1.0)));
        }
        values
    }

    /// Evaluate `u`: the candidate and its design report.
    fn candidate(&self, u: &[f64]) -> (Candidate, DesignReport) {
        let spec = self.spec;
        let values = self.values(u);
        let file = point_file(&spec.base, &spec.sets, &values);
        let fields: BTreeMap<String, SweptValue> =
            spec.sets.iter().map(|s| s.path.clone()).zip(values.iter().cloned()).collect();
        let label = format!("{} {:?}", spec.file, fields);
        let base = (&self.plan.variants[0], self.friction_limit);
        let e = evaluate(file, &spec.text, &label, self.plan, base, self.tick);
        let evaluation = self.history.lock().map_or(0, |h| h.len()) + 1;
        let d = design_report(evaluation - 1, fields.clone(), e);
        let objective = self.objective().output.value(&d);
        let margins: Vec<Option<f64>> =
            spec.goals.constraints.iter().map(|c| c.margin(&d)).collect();
        let feasible = d.status == "ok" && margins.iter().all(|m| m.is_some_and(|m| m >= 0.0));
        let outside: f64 = u.iter().map(|x| (x - x.clamp(0.0, 1.0)).powi(2)).sum();
        let cost = match (objective, d.status == "ok") {
            (Some(f), true) => {
                let scale = *self.scale.lock().expect("scale").get_or_insert(f.abs().max(1e-300));
                let sign = if self.objective().sense == Sense::Min { 1.0 } else { -1.0 };
                let violation: f64 = (spec.goals.constraints.iter().zip(&margins))
                    .map(|(c, m)| m.map_or(1.0, |m| (-m).max(0.0) / c.bound.abs().max(1e-300)))
                    .sum();
                sign * f / scale + PENALTY * (violation + outside)
            }
            _ => PENALTY * PENALTY * (1.0 + outside),
        };
        let c = Candidate {
            evaluation,
            fields,
            objective,
            margins,
            feasible,
            cost,
            status: d.status.clone(),
        };
        (c, d)
    }

    fn objective(&self) -> &Objective {
        &self.spec.goals.objectives[0]
    }
}

impl CostFunction for Search<'_> {
    type Param = Vec<f64>;
    type Output = f64;

    fn cost(&self, u: &Vec<f64>) -> Result<f64, argmin::core::Error> {
        if crate::cancel::requested() {
            return Err(argmin::core::Error::msg("stopped: a stop was requested"));
        }
        let (c, d) = self.candidate(u);
        let cost = c.cost;
        self.history.lock().map_err(|_| argmin::core::Error::msg("history"))?.push((c, d));
        Ok(cost)
    }
}

/// The combinations of the listed fields' values (one empty combination
/// without lists).
fn combinations(sets: &[Set]) -> Vec<Vec<(usize, SweptValue)>> {
    let mut out: Vec<Vec<(usize, SweptValue)>> = vec![Vec::new()];
    for (k, s) in sets.iter().enumerate().filter(|(_, s)| s.interval.is_none()) {
        out = out
            .into_iter()
            .flat_map(|c| {
                (0..s.levels.len()).map(move |i| {
                    let mut c = c.clone();
                    c.push((k, s.levels.value(i)));
                    c
                })
            })
            .collect();
    }
    out
}

impl OptimizeSpec {
    /// Parse `FIELD=LOW:HIGH` (searched) or `FIELD=A,B,...` (enumerated)
    /// for each varied field against the base scene.
    pub fn new(
        file: &str,
        text: &str,
        vary: &[String],
        goals: Goals,
        max_iterations: u64,
    ) -> Result<Self, ExploreError> {
        let base = SceneFile::parse(text, file)?;
        if base.coupling.is_none() {
            return Err(ExploreError::NotHighLevel { file: file.to_string() });
        }
        let mut sets = Vec::new();
        for a in vary {
            let mut s = Set::parse(a, &base).map_err(|e| match e {
                ExploreError::Values { path, spec, reason } => {
                    ExploreError::Vary { path, spec, reason: reason.to_string() }
                }
                ExploreError::Field { path, reason } => {
                    let spec = a.split_once('=').map_or("", |(_, v)| v).trim().to_string();
                    ExploreError::Vary { path, spec, reason: reason.to_string() }
                }
                ExploreError::SetSyntax { arg } => ExploreError::Vary {
                    path: arg,
                    spec: String::new(),
                    reason: "expected FIELD=LOW:HIGH or FIELD=A,B,...".to_string(),
                },
                e => e,
            })?;
            if sets.iter().any(|o: &Set| o.path == s.path) {
                let reason = "the field is varied twice".to_string();
                return Err(ExploreError::Vary { path: s.path, spec: s.spec, reason });
            }
            // A range's count (a grid's) has no meaning here.
            if s.interval.is_some() {
                s.levels = Levels::Numbers(Vec::new());
            }
            sets.push(s);
        }
        Ok(OptimizeSpec { file: file.into(), text: text.into(), base, sets, goals, max_iterations })
    }

    /// The fields varied, by path.
    pub fn paths(&self) -> Vec<String> {
        self.sets.iter().map(|s| s.path.clone()).collect()
    }
}

/// Run the optimisation of `spec`, every candidate's study by `plan`
/// (from [`super::run::study_plan`]).
pub fn optimize(
    spec: &OptimizeSpec,
    plan: &StudyPlan,
    tick: &(dyn Fn() + Sync),
) -> Result<OptimizeReport, SweepError> {
    if spec.max_iterations == 0 {
        let at = Param::MaxIterations.with(0);
        return Err(SweepError::Optimize(format!("{at}: the search needs at least 1 iteration")));
    }
    let n = spec.goals.objectives.len();
    if n != 1 {
        return Err(SweepError::Optimize(format!(
            "an optimisation takes exactly one objective (given or from the scene's [goals]), got {n}"
        )));
    }
    let searched: Vec<usize> =
        (0..spec.sets.len()).filter(|&k| spec.sets[k].interval.is_some()).collect();
    // One search per combination of listed values, the combinations in
    // parallel (rayon), their histories joined in combination order: the
    // result does not depend on the number of threads.
    let runs: Vec<(Vec<(Candidate, DesignReport)>, String)> = combinations(&spec.sets)
        .into_par_iter()
        .map(|fixed| {
            let (history, scale) = (Mutex::new(Vec::new()), Mutex::new(None));
            let search = Search {
                spec,
                plan,
                fixed,
                searched: searched.clone(),
                history: &history,
                scale: &scale,
                friction_limit: spec.goals.reads_friction_limit(),
                tick,
            };
            let reason = match searched.is_empty() {
                true => {
                    let _ = search.cost(&Vec::new());
                    "nothing to search: every field is a list".to_string()
                }
                false => restarted(&search, searched.len(), spec.max_iterations)?,
            };
            let h = history.into_inner().map_err(|_| SweepError::Optimize("history".into()))?;
            Ok((h, reason))
        })
        .collect::<Result<_, SweepError>>()?;
    let mut termination = Vec::new();
    let mut history: Vec<(Candidate, DesignReport)> = Vec::new();
    for (h, reason) in runs {
        history.extend(h);
        termination.push(reason);
    }
    for (i, (c, d)) in history.iter_mut().enumerate() {
        (c.evaluation, d.index) = (i + 1, i);
    }
    // The optimum's nominal checks in full (the candidates skipped the
    // friction limit unless a goal read it).
    if let Some(i) = best(&history, &spec.goals.objectives[0]) {
        let values: Vec<SweptValue> =
            spec.sets.iter().map(|s| history[i].0.fields[&s.path].clone()).collect();
        let file = point_file(&spec.base, &spec.sets, &values);
        let label = format!("{} {:?}", spec.file, history[i].0.fields);
        let e = evaluate(file, &spec.text, &label, plan, (&plan.variants[0], true), tick);
        history[i].1 = design_report(i, history[i].0.fields.clone(), e);
    }
    Ok(report(spec, plan, history, termination))
}

/// Nelder-Mead from the centre of the unit cube (simplex edge 0.25), then
/// restarted from the best point with half the edge while a restart
/// lowers the cost (at most [`RESTARTS`]): a simplex that collapsed on a
/// kink of the cost (a constraint's bound, a change of the contacts'
/// stick-slip pattern) starts afresh there. Why the last search stopped.
fn restarted(search: &Search<'_>, d: usize, max_iterations: u64) -> Result<String, SweepError> {
    let (mut start, mut edge, mut last) = (vec![0.5; d], 0.25, f64::INFINITY);
    let mut reason = String::new();
    for restart in 0..=RESTARTS {
        let simplex: Vec<Vec<f64>> = std::iter::once(start.clone())
            .chain((0..d).map(|i| {
                let mut v = start.clone();
                v[i] += if v[i] + edge <= 1.0 { edge } else { -edge };
                v
            }))
            .collect();
        let solver = NelderMead::new(simplex)
            .with_sd_tolerance(COST_TOLERANCE)
            .map_err(|e| SweepError::Optimize(e.to_string()))?;
        let res = Executor::new(search.clone(), solver)
            .configure(|s| s.max_iters(max_iterations))
            .run()
            .map_err(|e| SweepError::Optimize(e.to_string()))?;
        let state = res.state();
        reason = match state.get_termination_reason() {
            Some(r) => format!("{} (search {})", r.text(), restart + 1),
            None => "running".to_string(),
        };
        let cost = state.get_best_cost();
        let Some(best) = state.get_best_param() else { break };
        if cost >= last - 1e-9 * last.abs() {
            break;
        }
        (start, edge, last) = (best.iter().map(|x| x.clamp(0.0, 1.0)).collect(), edge / 2.0, cost);
    }
    Ok(reason)
}

/// The best feasible candidate of `history` on `objective` (the first
/// of equals), if any is feasible.
fn best(history: &[(Candidate, DesignReport)], objective: &Objective) -> Option<usize> {
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
fn report(
    spec: &OptimizeSpec,
    plan: &StudyPlan,
    history: Vec<(Candidate, DesignReport)>,
    termination: Vec<String>,
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
        goals: spec.goals.clone(),
        method: format!(
            "Nelder-Mead (argmin) in the unit cube of the ranges from its centre, stopping when the \
             simplex's costs spread less than {COST_TOLERANCE:e} or after {} iterations; listed \
             fields enumerated, one search each; constraints by an exact L1 penalty of weight \
             {PENALTY} on violations relative to their bounds; the optimum is the best feasible \
             candidate evaluated; every candidate's study uses the same friction draws (common \
             random numbers)",
            spec.max_iterations
        ),
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
        let s = p.directions.iter().find(|s| s.name == *measure || s.label() == *measure)?;
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
            "{}, optimisation of {}",
            produced_by(
                &self.solver,
                &self.sampler.to_string(),
                &self.seed.to_string(),
                &self.samples.to_string(),
                "friction"
            ),
            self.scene
        )
    }
}
