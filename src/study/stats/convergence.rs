//! Convergence of sigma with the number of samples: sigma of the first k samples, k = 2..=n.
//!
//! Computed in one pass with Welford's (1962) update of [`Moments`], which is numerically stable;
//! the value at k = n may differ in the last bits from the two-pass sigma of [`super::Summary`].
//!
//! For Latin hypercube designs, a prefix of the design (its first k rows) is **not** itself a
//! Latin hypercube: its k points do not fill k strata per dimension, so the curve shows how
//! sigma settles, not what a k-sample LHS study would give. For Monte Carlo, prefixes are
//! genuine k-sample studies.

use serde::{Deserialize, Serialize};

use super::super::error::Result;
use super::check_values;
use super::moments::Moments;

/// Sigma of the first `k` samples.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct ConvergencePoint {
    pub k: usize,
    pub sigma: f64,
}

/// Sigma of every prefix of `values` with at least 2 samples (n - 1 points).
pub fn sigma_convergence(values: &[f64]) -> Result<Vec<ConvergencePoint>> {
    check_values(values)?;
    let mut m = Moments::new();
    Ok((values.iter().enumerate())
        .filter_map(|(i, &v)| {
            m.push(v);
            (i >= 1).then(|| ConvergencePoint { k: i + 1, sigma: m.sigma() })
        })
        .collect())
}
