//! `kinrepro merge` of sweep parts: the shards of one sweep (equal
//! fingerprints, every shard once, each holding its design points) into
//! exactly the single run's document, Pareto marks set on the whole.

use thiserror::Error;

use super::run::SweepReport;
use crate::study::Shard;
use crate::study::merge::{MergeError, check_shards};

/// Sweep parts that do not merge.
#[derive(Debug, Error)]
pub enum SweepMergeError {
    #[error("{part}: not a part of the sweep of {first}: {field} differs")]
    Different { part: String, first: String, field: String },
    #[error(transparent)]
    Shards(#[from] MergeError),
    #[error("{part}: shard {shard} should hold design points {expected:?}")]
    Rows { part: String, shard: Shard, expected: std::ops::Range<usize> },
}

/// Merge the parts of a sharded sweep into exactly the single run's document.
pub fn merge_sweeps(parts: Vec<(String, SweepReport)>) -> Result<SweepReport, SweepMergeError> {
    let shards: Vec<(&str, Shard)> = parts.iter().map(|(f, p)| (f.as_str(), p.shard)).collect();
    let n = parts.first().map_or(0, |(_, p)| p.design_points);
    check_shards(&shards, n, ("design points", 0))?;
    let (first_name, first) = &parts[0];
    let fp = serde_json::to_value(&first.fingerprint).unwrap_or_default();
    for (name, p) in &parts {
        let other = serde_json::to_value(&p.fingerprint).unwrap_or_default();
        if let Some(field) = first_difference(&fp, &other, "fingerprint") {
            return Err(SweepMergeError::Different {
                part: name.clone(),
                first: first_name.clone(),
                field,
            });
        }
        let expected = p.shard.range(p.design_points).unwrap_or(0..0);
        if !p.designs.iter().map(|d| d.index).eq(expected.clone()) {
            return Err(SweepMergeError::Rows { part: name.clone(), shard: p.shard, expected });
        }
    }
    let mut parts: Vec<SweepReport> = parts.into_iter().map(|(_, p)| p).collect();
    parts.sort_by_key(|p| p.shard.index);
    let mut merged = parts[0].clone();
    merged.designs = parts.into_iter().flat_map(|p| p.designs).collect();
    merged.shard = Shard::whole();
    merged.mark_pareto();
    Ok(merged)
}

/// The dotted path of the first field where two JSON values differ.
pub(crate) fn first_difference(
    a: &serde_json::Value,
    b: &serde_json::Value,
    at: &str,
) -> Option<String> {
    use serde_json::Value::Object;
    match (a, b) {
        (Object(x), Object(y)) => x
            .iter()
            .find_map(|(k, v)| match y.get(k) {
                Some(w) => first_difference(v, w, &format!("{at}.{k}")),
                None => Some(format!("{at}.{k}")),
            })
            .or_else(|| y.keys().find(|k| !x.contains_key(*k)).map(|k| format!("{at}.{k}"))),
        _ if a == b => None,
        _ => Some(format!("{at} ({a} vs {b})")),
    }
}
