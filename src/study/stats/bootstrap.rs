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
pub(crate) fn quantile_sorted(sorted: &[f64], p: f64) -> f64 {
    let h = (sorted.len() - 1) as f64 * p;
    let lo = h.floor() as usize;
    let hi = (lo + 1).min(sorted.len() - 1);
    sorted[lo] + (h - lo as f64) * (sorted[hi] - sorted[lo])
}

#[cfg(test)]
mod tests {
    use super::quantile_sorted;

    #[test]
    fn type7_quantiles_match_r() {
        // R: quantile(c(1,2,3,4,10), c(0.05, 0.5, 0.95)) -> 1.2 3.0 8.8
        let x = [1.0, 2.0, 3.0, 4.0, 10.0];
        assert!((quantile_sorted(&x, 0.05) - 1.2).abs() < 1e-12);
        assert_eq!(quantile_sorted(&x, 0.5), 3.0);
        assert!((quantile_sorted(&x, 0.95) - 8.8).abs() < 1e-12);
    }
}
