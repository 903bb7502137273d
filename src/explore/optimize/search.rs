//! The search of one combination of listed values: the penalised cost of
//! a candidate ([`Search`], argmin's cost function, which records every
//! candidate) and Nelder-Mead with restarts ([`restarted`]).

use std::sync::Mutex;

use argmin::core::{CostFunction, Executor, State};
use argmin::solver::neldermead::NelderMead;

use super::{COST_TOLERANCE, Candidate, OptimizeSpec, PENALTY, RESTARTS};
use crate::explore::SweptValue;
use crate::explore::design_report::DesignReport;
use crate::explore::goal::{Objective, Sense};
use crate::explore::run::SweepError;
use crate::study::StudyPlan;

/// The search's cost function: each call evaluates a candidate and
/// records it (numbered when the searches' histories are joined).
#[derive(Clone)]
pub(super) struct Search<'a> {
    pub(super) spec: &'a OptimizeSpec,
    pub(super) plan: &'a StudyPlan,
    /// The search's number (1-based, [`Candidate::search`]).
    pub(super) number: usize,
    /// The listed values of this combination, by field.
    pub(super) fixed: Vec<(usize, SweptValue)>,
    /// The searched fields' indices in `spec.sets`.
    pub(super) searched: Vec<usize>,
    pub(super) history: &'a Mutex<Vec<(Candidate, DesignReport)>>,
    pub(super) scale: &'a Mutex<Option<f64>>,
    pub(super) tick: &'a (dyn Fn() + Sync),
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
        // The friction limit only where a goal reads it (about 0.1 s).
        let checks = spec.goals.reads_friction_limit();
        let (fields, d) = spec.evaluate(self.plan, &self.values(u), checks, self.tick);
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
            evaluation: 0,
            search: self.number,
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

/// Nelder-Mead from `start` in the unit cube (simplex edge 0.25), then
/// restarted from the best point with half the edge while a restart
/// lowers the cost (at most [`RESTARTS`]): a simplex that collapsed on a
/// kink of the cost (a constraint's bound, a change of the contacts'
/// stick-slip pattern) starts afresh there. Why the last run stopped,
/// and after how many runs.
pub(super) fn restarted(
    search: &Search<'_>,
    start: &[f64],
    max_iterations: u64,
) -> Result<String, SweepError> {
    let d = start.len();
    let (mut start, mut edge, mut last) = (start.to_vec(), 0.25, f64::INFINITY);
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
            Some(r) => match restart {
                0 => format!("{} after 1 run", r.text()),
                k => format!("{} after {} runs", r.text(), k + 1),
            },
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
