//! `kinrepro merge` of an optimisation's shards: the documents of
//! `optimize --shard I/N` (equal but for their searches, every shard
//! once) joined into exactly the single run's document. The searches are
//! independent, so the single run's history is the shards' histories in
//! search order, and its optimum the best of the shards' optima (the first
//! of equals), each already re-checked in full by its shard.

use std::ops::Range;

use thiserror::Error;

use super::OptimizeReport;
use crate::explore::goal::Sense;
use crate::explore::merge::first_difference;
use crate::study::Shard;
use crate::study::merge::{MergeError, check_shards};

/// Optimisation parts that do not merge.
#[derive(Debug, Error)]
pub enum OptimizeMergeError {
    #[error("{part}: not a part of the optimisation of {first}: {field} differs")]
    Different { part: String, first: String, field: String },
    #[error(transparent)]
    Shards(#[from] MergeError),
    #[error("{part}: shard {shard} should hold searches {expected:?} (1-based), {found}")]
    Searches { part: String, shard: Shard, expected: Range<usize>, found: String },
}

/// The fields every part of one optimisation shares: the document less
/// its shard's own (shard, termination, optimum, history).
fn common(p: &OptimizeReport) -> serde_json::Value {
    let mut v = serde_json::to_value(p).unwrap_or_default();
    if let Some(o) = v.as_object_mut() {
        for k in ["shard", "termination", "optimum", "history"] {
            o.remove(k);
        }
    }
    v
}

/// Whether `p` holds exactly the searches of its shard: one termination
/// each, and candidates only of them, in search order.
fn holds_its_searches(name: &str, p: &OptimizeReport) -> Result<(), OptimizeMergeError> {
    let range = p.shard.range(p.searches).unwrap_or(0..0);
    let expected = range.start + 1..range.end + 1;
    let found = if p.termination.len() != range.len() {
        Some(format!("has {} search terminations", p.termination.len()))
    } else if let Some(c) = p.history.iter().find(|c| !expected.contains(&c.search)) {
        Some(format!("holds candidate {} of search {}", c.evaluation, c.search))
    } else if !p.history.windows(2).all(|w| w[0].search <= w[1].search) {
        Some("its candidates are not in search order".to_string())
    } else {
        None
    };
    match found {
        None => Ok(()),
        Some(found) => {
            Err(OptimizeMergeError::Searches { part: name.into(), shard: p.shard, expected, found })
        }
    }
}

/// Merge the parts of a sharded optimisation into exactly the single
/// run's document.
pub fn merge_optimizations(
    parts: Vec<(String, OptimizeReport)>,
) -> Result<OptimizeReport, OptimizeMergeError> {
    let shards: Vec<(&str, Shard)> = parts.iter().map(|(f, p)| (f.as_str(), p.shard)).collect();
    let n = parts.first().map_or(0, |(_, p)| p.searches);
    check_shards(&shards, n, ("searches", 1))?;
    let (first_name, first) = &parts[0];
    let key = common(first);
    for (name, p) in &parts {
        if let Some(field) = first_difference(&key, &common(p), "document") {
            let (part, first) = (name.clone(), first_name.clone());
            return Err(OptimizeMergeError::Different { part, first, field });
        }
        holds_its_searches(name, p)?;
    }
    let mut parts: Vec<OptimizeReport> = parts.into_iter().map(|(_, p)| p).collect();
    parts.sort_by_key(|p| p.shard.index);
    let min = parts[0].goals.objectives.first().is_none_or(|o| o.sense == Sense::Min);
    let mut merged = parts[0].clone();
    (merged.shard, merged.termination, merged.history) = (Shard::whole(), Vec::new(), Vec::new());
    merged.optimum = None;
    for p in parts {
        let offset = merged.history.len();
        if let Some(mut o) = p.optimum {
            let better = merged.optimum.as_ref().is_none_or(|b| match min {
                true => o.objective < b.objective,
                false => o.objective > b.objective,
            });
            if better {
                o.evaluation += offset;
                o.design.index = o.evaluation - 1;
                merged.optimum = Some(o);
            }
        }
        merged.termination.extend(p.termination);
        for mut c in p.history {
            c.evaluation += offset;
            merged.history.push(c);
        }
    }
    Ok(merged)
}
