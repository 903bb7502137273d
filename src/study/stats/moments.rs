//! Streaming moments of one output quantity: count, mean, central sums of
//! powers 2-4, min and max, updated one value at a time in bounded memory.
//!
//! One-pass update (Welford 1962 for M2; Terriberry 2007 / Pébay 2008,
//! eqs. 1.5-1.7, for M3 and M4), with delta = x - mean_old, n the new count:
//! ```text
//! mean += delta / n
//! M4 += delta^4 (n-1)(n^2-3n+3)/n^3 + 6 delta^2 M2/n^2 - 4 delta M3/n
//! M3 += delta^3 (n-1)(n-2)/n^2 - 3 delta M2/n
//! M2 += delta^2 (n-1)/n
//! ```
//! and the pairwise combination of two accumulators (Chan, Golub & LeVeque
//! 1979; Pébay 2008, eqs. 2.1-2.3). The sample variance is M2 / (n - 1);
//! the fourth standardised moment is n M4 / M2^2.
//!
//! Pushing values in a fixed order gives a fixed result: a study that
//! streams its samples pushes them in sample-index order, so the result does
//! not depend on the number of threads.

use serde::{Deserialize, Serialize};

/// Running moments of one quantity.
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Moments {
    pub n: u64,
    pub mean: f64,
    /// Sum of (x - mean)^2.
    pub m2: f64,
    /// Sum of (x - mean)^3.
    pub m3: f64,
    /// Sum of (x - mean)^4.
    pub m4: f64,
    pub min: f64,
    pub max: f64,
}

impl Default for Moments {
    fn default() -> Self {
        Moments {
            n: 0,
            mean: 0.0,
            m2: 0.0,
            m3: 0.0,
            m4: 0.0,
            min: f64::INFINITY,
            max: f64::NEG_INFINITY,
        }
    }
}

impl Moments {
    /// No values yet.
    pub fn new() -> Self {
        Self::default()
    }

    pub fn push(&mut self, x: f64) {
        let n0 = self.n as f64;
        self.n += 1;
        let n = self.n as f64;
        let delta = x - self.mean;
        let dn = delta / n;
        let dn2 = dn * dn;
        let term1 = delta * dn * n0;
        self.mean += dn;
        self.m4 += term1 * dn2 * (n * n - 3.0 * n + 3.0) + 6.0 * dn2 * self.m2 - 4.0 * dn * self.m3;
        self.m3 += term1 * dn * (n - 2.0) - 3.0 * dn * self.m2;
        self.m2 += term1;
        self.min = self.min.min(x);
        self.max = self.max.max(x);
    }

    /// Combine with the moments of another set of values.
    pub fn merge(&mut self, other: &Moments) {
        if other.n == 0 {
            return;
        }
        if self.n == 0 {
            *self = *other;
            return;
        }
        let (na, nb) = (self.n as f64, other.n as f64);
        let n = na + nb;
        let delta = other.mean - self.mean;
        let d2 = delta * delta;
        let m2 = self.m2 + other.m2 + d2 * na * nb / n;
        let m3 = self.m3
            + other.m3
            + d2 * delta * na * nb * (na - nb) / (n * n)
            + 3.0 * delta * (na * other.m2 - nb * self.m2) / n;
        let m4 = self.m4
            + other.m4
            + d2 * d2 * na * nb * (na * na - na * nb + nb * nb) / (n * n * n)
            + 6.0 * d2 * (na * na * other.m2 + nb * nb * self.m2) / (n * n)
            + 4.0 * delta * (na * other.m3 - nb * self.m3) / n;
        self.mean += delta * nb / n;
        self.n += other.n;
        self.m2 = m2;
        self.m3 = m3;
        self.m4 = m4;
        self.min = self.min.min(other.min);
        self.max = self.max.max(other.max);
    }

    /// Sample variance (divisor n - 1); NaN for fewer than 2 values.
    pub fn variance(&self) -> f64 {
        if self.n < 2 {
            return f64::NAN;
        }
        self.m2 / (self.n as f64 - 1.0)
    }

    /// Sample standard deviation (divisor n - 1); NaN for fewer than 2 values.
    pub fn sigma(&self) -> f64 {
        self.variance().sqrt()
    }

    /// Fourth standardised moment n M4 / M2^2 (3 for a normal
    /// distribution, 1.8 for a uniform one); NaN without spread.
    pub fn kurtosis(&self) -> f64 {
        self.n as f64 * self.m4 / (self.m2 * self.m2)
    }
}
