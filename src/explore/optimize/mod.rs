//! `kinrepro optimize`: the best design within bounds on one objective
//! under constraints ([`super::goal`]). The continuous fields (`--vary
//! FIELD=LOW:HIGH`, `log:LOW:HIGH` searched in the logarithm) are searched
//! by Nelder-Mead (argmin) in the unit cube of their ranges, from its
//! centre; fields given as a list (materials, keywords, numbers) are
//! enumerated outside the search, one search per combination. With
//! `starts` > 1 each combination is searched from further starting
//! points too (an optimised Latin hypercube of the box, seeded by the
//! study's seed): a multi-start for objectives with several local minima.
//! The searches (combination x start) are independent: a run may make a
//! shard of them (`shard`), and [`merge_optimizations`] joins the shards'
//! documents into the single run's.
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

mod merge;
mod outcome;
mod search;

use std::collections::BTreeMap;
use std::sync::Mutex;

use argmin::core::CostFunction;
use rayon::prelude::*;
use serde::{Deserialize, Serialize};

pub use merge::{OptimizeMergeError, merge_optimizations};
use outcome::{best, report};
use search::{Search, restarted};

use super::design_report::{DesignReport, design_report};
use super::goal::Goals;
use super::run::{SetRecord, SweepError};
use super::values::Levels;
use super::{ExploreError, Set, SweptValue, evaluate, point_file};
use crate::param::Param;
use crate::scene::SceneFile;
use crate::study::sampling::lhs::start_points;
use crate::study::{Shard, StudyPlan};

/// The weight of a normalised constraint violation (module docs).
pub const PENALTY: f64 = 1e3;

/// Most restarts of the search from its best point (module docs).
pub const RESTARTS: usize = 6;

/// Most searches per combination of listed values (`starts`).
pub const MAX_STARTS: usize = crate::study::sampling::lhs::MAX_LHS_SAMPLES;

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
    /// Searches per combination of listed values: from the centre of the
    /// box, then from `starts - 1` points of a Latin hypercube (>= 1).
    pub starts: usize,
    /// The searches this run makes (1/1: all).
    pub shard: Shard,
}

/// The inputs of an optimisation a merge checks beyond its flags.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct OptimizeFingerprint {
    /// FNV-1a 64 (hex) of the base scene text as read.
    pub scene_content: String,
    /// The study settings of every candidate (the base scene's).
    pub study: crate::study::provenance::Fingerprint,
}

/// One candidate the search evaluated.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Candidate {
    /// 1-based, in the order evaluated (the searches' histories joined in
    /// search order).
    pub evaluation: usize,
    /// The search that evaluated it, 1-based: combination c (0-based) and
    /// start k (0-based) make search c * starts + k + 1.
    pub search: usize,
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
    /// What every shard of one optimisation shares beyond the fields
    /// above: the scene as read and the study's settings.
    pub fingerprint: OptimizeFingerprint,
    #[serde(flatten)]
    pub goals: Goals,
    /// The search and the constraint rule, in words.
    pub method: String,
    /// Searches per combination of listed values.
    pub starts: usize,
    /// Searches of the whole optimisation (combinations x starts).
    pub searches: usize,
    /// The searches this document holds (`1/1`: all; see
    /// [`merge_optimizations`]).
    pub shard: Shard,
    /// Why each search of this document stopped, in search order.
    pub termination: Vec<String>,
    /// None: no candidate met every constraint.
    pub optimum: Option<Optimum>,
    pub history: Vec<Candidate>,
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
        Ok(OptimizeSpec {
            file: file.into(),
            text: text.into(),
            base,
            sets,
            goals,
            max_iterations,
            starts: 1,
            shard: Shard::whole(),
        })
    }

    /// The design point of `values` (one per field) evaluated with the
    /// study of `plan` (and the friction limit if `friction_limit`): its
    /// fields by path and its report.
    pub(crate) fn evaluate(
        &self,
        plan: &StudyPlan,
        values: &[SweptValue],
        friction_limit: bool,
        tick: &(dyn Fn() + Sync),
    ) -> (BTreeMap<String, SweptValue>, DesignReport) {
        let file = point_file(&self.base, &self.sets, values);
        let fields: BTreeMap<String, SweptValue> =
            self.sets.iter().map(|s| s.path.clone()).zip(values.iter().cloned()).collect();
        let label = format!("{} {:?}", self.file, fields);
        let e = evaluate(file, &self.text, &label, plan, (&plan.variants[0], friction_limit), tick);
        (fields.clone(), design_report(0, fields, e))
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
    let starts = starting_points(spec, plan, searched.len())?;
    let combinations = combinations(&spec.sets);
    let searches = combinations.len() * starts.len();
    let mine = spec.shard.range(searches)?;
    // The searches in parallel (rayon), their histories joined in search
    // order: the result depends neither on the number of threads nor on
    // the shards.
    let runs: Vec<(Vec<(Candidate, DesignReport)>, String)> = mine
        .into_par_iter()
        .map(|s| {
            let (history, scale) = (Mutex::new(Vec::new()), Mutex::new(None));
            let search = Search {
                spec,
                plan,
                number: s + 1,
                fixed: combinations[s / starts.len()].clone(),
                searched: searched.clone(),
                history: &history,
                scale: &scale,
                tick,
            };
            let reason = match searched.is_empty() {
                true => {
                    let _ = search.cost(&Vec::new());
                    "nothing to search: every field is a list".to_string()
                }
                false => restarted(&search, &starts[s % starts.len()], spec.max_iterations)?,
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
        history[i].1 = spec.evaluate(plan, &values, true, tick).1;
        history[i].1.index = i;
    }
    Ok(report(spec, plan, history, termination, (searches, starts.len())))
}

/// Where each search of a combination starts, in the unit cube of the
/// searched fields: its centre, then `spec.starts - 1` points of an
/// optimised Latin hypercube seeded by the study's seed (one start, the
/// centre's, when nothing is searched).
fn starting_points(
    spec: &OptimizeSpec,
    plan: &StudyPlan,
    d: usize,
) -> Result<Vec<Vec<f64>>, SweepError> {
    if spec.starts == 0 || spec.starts > MAX_STARTS {
        let at = Param::Starts.with(spec.starts);
        return Err(SweepError::Optimize(format!(
            "{at}: give 1 to {MAX_STARTS} searches per combination"
        )));
    }
    let mut points = vec![vec![0.5; d]];
    if d > 0 && spec.starts > 1 {
        let seed = plan.variants[0].design.seed;
        points.extend(start_points(d, spec.starts - 1, seed)?);
    }
    Ok(points)
}
