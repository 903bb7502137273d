//! The design points of a sweep: the full grid of the `--set` values
//! (the last `--set` varying fastest), or a space-filling Latin hypercube
//! of N points over their ranges (`study::sampling`'s optimised LHS,
//! Jin et al. 2005 ESE, seeded).

use serde::{Deserialize, Serialize};

use super::ExploreError;
use super::field::SweptValue;
use super::values::Set;
use crate::param::Param;
use crate::scene::Scene;
use crate::study::{Sampler, sampling};

/// How the design points are chosen.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", tag = "kind")]
pub enum DesignKind {
    /// Every combination of the `--set` values.
    Grid,
    /// An optimised Latin hypercube of `points` points over the ranges
    /// (lists: each value equally often), seeded with `seed`.
    Lhs { points: usize, seed: u64 },
}

impl DesignKind {
    /// A grid (`points` None), or an LHS of `points` design points seeded
    /// like each point's study: `seed`, else the scene's `[study]` seed.
    pub fn new(points: Option<usize>, seed: Option<u64>, base: &Scene) -> DesignKind {
        match points {
            None => DesignKind::Grid,
            Some(points) => DesignKind::Lhs { points, seed: seed.unwrap_or(base.study.seed) },
        }
    }

    pub fn name(&self) -> &'static str {
        match self {
            DesignKind::Grid => "grid",
            DesignKind::Lhs { .. } => "lhs",
        }
    }
}

/// One design point: its index and the value of each `--set`, in order.
#[derive(Debug, Clone, PartialEq)]
pub struct DesignPoint {
    pub index: usize,
    pub values: Vec<SweptValue>,
}

/// Most design points of a sweep.
pub const MAX_DESIGN_POINTS: usize = 100_000;

/// The design points of `sets` under `kind`.
pub fn design_points(sets: &[Set], kind: DesignKind) -> Result<Vec<DesignPoint>, ExploreError> {
    if sets.is_empty() {
        return Err(ExploreError::Design(format!(
            "nothing to sweep: give at least one {}",
            Param::Sets.with("FIELD=VALUES")
        )));
    }
    for (i, a) in sets.iter().enumerate() {
        if sets[..i].iter().any(|b| b.path == a.path) {
            return Err(ExploreError::Design(format!(
                "{} is given twice",
                Param::Sets.with(&a.path)
            )));
        }
    }
    match kind {
        DesignKind::Grid => grid(sets),
        DesignKind::Lhs { points, seed } => lhs(sets, points, seed),
    }
}

fn grid(sets: &[Set]) -> Result<Vec<DesignPoint>, ExploreError> {
    if let Some(s) = sets.iter().find(|s| s.levels.is_empty()) {
        return Err(ExploreError::Design(format!(
            "{}: a grid needs a count (a:b:count) or a list",
            Param::Sets.with(format!("{}={}", s.path, s.spec))
        )));
    }
    let total = sets
        .iter()
        .try_fold(1usize, |acc, s| acc.checked_mul(s.levels.len()))
        .filter(|n| *n <= MAX_DESIGN_POINTS)
        .ok_or_else(|| {
            ExploreError::Design(format!("the grid has more than {MAX_DESIGN_POINTS} points"))
        })?;
    Ok((0..total)
        .map(|index| {
            let mut rest = index;
            let mut values = vec![SweptValue::Number(0.0); sets.len()];
            for (k, s) in sets.iter().enumerate().rev() {
                let n = s.levels.len();
                values[k] = s.levels.value(rest % n);
                rest /= n;
            }
            DesignPoint { index, values }
        })
        .collect())
}

fn lhs(sets: &[Set], points: usize, seed: u64) -> Result<Vec<DesignPoint>, ExploreError> {
    let rows = sampling::design(Sampler::Lhs, sets.len(), points, seed).map_err(|e| {
        ExploreError::Design(format!(
            "{} {}: {e}",
            Param::Design.with("lhs"),
            Param::Points.with(points)
        ))
    })?;
    Ok(rows
        .into_iter()
        .enumerate()
        .map(|(index, u)| DesignPoint {
            index,
            values: sets
                .iter()
                .zip(&u)
                .map(|(s, &u)| match s.interval {
                    Some(iv) => SweptValue::Number(iv.at(u)),
                    None => {
                        let n = s.levels.len();
                        s.levels.value(((u * n as f64) as usize).min(n - 1))
                    }
                })
                .collect(),
        })
        .collect())
}
