//! Settings of the percentile bootstrap (Efron & Tibshirani 1993, ch. 13)
//! and its type-7 quantile (Hyndman & Fan 1996: linear interpolation
//! between order statistics, R's default), used by the Sobol intervals
//! ([`crate::study::sensitivity::sobol`]), whose base rows are independent.
//! The percentile interval is not valid for a Latin hypercube (resampling
//! breaks the stratification): study tables use [`super::interval`].
//!
//! The resampling is deterministic: ChaCha8 keyed from the fixed
//! [`BOOTSTRAP_SEED`] (see the `rng` module), so the same data always give
//! the same interval.

use serde::{Deserialize, Serialize};

pub const BOOTSTRAP_SEED: u64 = 0x6b69_6e72_6570_726f; // "kinrepro"

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct BootstrapConfig {
    /// Number of resamples B (>= 2).
    pub resamples: usize,
    /// Coverage level in (0, 1), e.g. 0.90.
    pub level: f64,
    pub seed: u64,
}

/// Type-7 quantile of sorted, non-empty data, `p` in [0, 1].
pub fn quantile_sorted(sorted: &[f64], p: f64) -> f64 {
    let h = (sorted.len() - 1) as f64 * p;
    let lo = h.floor() as usize;
    let hi = (lo + 1).min(sorted.len() - 1);
    sorted[lo] + (h - lo as f64) * (sorted[hi] - sorted[lo])
}
