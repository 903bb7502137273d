//! Splitting the sample indices 0..n into contiguous, balanced shards.
//!
//! Shards are **1-based**, as `--shard i/N` with `1 <= i <= N` (a Slurm job array submitted with
//! `--array=1-N` hands `$SLURM_ARRAY_TASK_ID` straight through). Shard `i` gets
//! `floor(n / N)` samples, plus one if `i <= n % N`, in index order; a shard may be empty
//! when `N > n`.

use std::fmt;
use std::ops::Range;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

use super::super::error::{Result, StudyError};

/// One shard `index` of `count` (1-based).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub struct Shard {
    pub index: usize,
    pub count: usize,
}

impl Shard {
    /// Validated shard.
    pub fn new(index: usize, count: usize) -> Result<Self> {
        if index == 0 || index > count {
            return Err(StudyError::InvalidShard { index, count });
        }
        Ok(Shard { index, count })
    }

    /// The whole study as a single shard, 1/1.
    pub fn whole() -> Self {
        Shard { index: 1, count: 1 }
    }

    /// The sample indices of this shard in a design of `n` samples.
    pub fn range(&self, n: usize) -> Result<Range<usize>> {
        shard_range(n, self.index, self.count)
    }
}

impl fmt::Display for Shard {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}/{}", self.index, self.count)
    }
}

impl FromStr for Shard {
    type Err = StudyError;

    /// Parses `INDEX/COUNT`, e.g. `3/8`.
    fn from_str(s: &str) -> Result<Self> {
        let err = || StudyError::ShardParse(s.to_owned());
        let (i, c) = s.trim().split_once('/').ok_or_else(err)?;
        let index = i.trim().parse().map_err(|_| err())?;
        let count = c.trim().parse().map_err(|_| err())?;
        Shard::new(index, count)
    }
}

/// Contiguous, balanced range of sample indices of shard `shard_index` (1-based) of `shard_count`.
///
/// The ranges of shards 1..=count are disjoint, in order, and cover 0..n; their lengths differ
/// by at most one.
pub fn shard_range(n: usize, shard_index: usize, shard_count: usize) -> Result<Range<usize>> {
    if shard_index == 0 || shard_index > shard_count {
        return Err(StudyError::InvalidShard { index: shard_index, count: shard_count });
    }
    let j = shard_index - 1;
    let base = n / shard_count;
    let rem = n % shard_count;
    let start = j * base + j.min(rem);
    let len = base + usize::from(j < rem);
    Ok(start..start + len)
}
