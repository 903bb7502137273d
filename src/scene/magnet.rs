//! A magnet's pull against the gap to its keeper: a table of (gap, force)
//! interpolated by the monotone piecewise-cubic Hermite interpolant of
//! Fritsch & Carlson (SIAM J. Numer. Anal. 17 (1980) 238-246), so that a
//! force that falls with the gap between the tabulated points falls
//! between them too (no overshoot), with a continuous slope dF/dgap for
//! the solvers' Jacobian. Outside the table the end value holds (slope
//! zero); the scene loader refuses a touching gap outside it.
//!
//! Slopes (Fritsch & Carlson's steps 1-5): the secants
//! delta_k = (F_k+1 - F_k) / (g_k+1 - g_k); at interior points
//! m_k = (delta_k-1 + delta_k) / 2, zero where the secants differ in sign
//! or one is zero; m_0 = delta_0 and m_n = delta_n-1; then where
//! alpha = m_k / delta_k and beta = m_k+1 / delta_k have
//! alpha^2 + beta^2 > 9, both are scaled by tau = 3 / sqrt(alpha^2 + beta^2).

use serde::Serialize;

/// A magnet's force law (module docs).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MagnetLaw {
    /// Gap between the magnet and its keeper in the touching pose [m].
    pub gap: f64,
    /// (gap [m], force [N]) by strictly increasing gap.
    pub table: Vec<[f64; 2]>,
    /// The Hermite slopes at the table's points [N/m] (module docs).
    #[serde(skip)]
    slopes: Vec<f64>,
}

impl MagnetLaw {
    /// The law of `table` (at least two points, strictly increasing gaps,
    /// finite values: the scene loader checks them) at the touching gap
    /// `gap`.
    pub fn new(gap: f64, table: Vec<[f64; 2]>) -> Self {
        let slopes = monotone_slopes(&table);
        MagnetLaw { gap, table, slopes }
    }

    /// The same law at another touching gap.
    pub fn at_gap(&self, gap: f64) -> Self {
        MagnetLaw { gap, ..self.clone() }
    }

    /// The force [N] and its slope dF/dgap [N/m] at `gap` [m].
    pub fn force(&self, gap: f64) -> (f64, f64) {
        let t = &self.table;
        let (first, last) = (t[0], t[t.len() - 1]);
        if gap <= first[0] {
            return (first[1], 0.0);
        }
        if gap >= last[0] {
            return (last[1], 0.0);
        }
        let k = t.partition_point(|p| p[0] <= gap) - 1;
        let (g0, f0, g1, f1) = (t[k][0], t[k][1], t[k + 1][0], t[k + 1][1]);
        let h = g1 - g0;
        let s = (gap - g0) / h;
        let (m0, m1) = (self.slopes[k], self.slopes[k + 1]);
        // Cubic Hermite basis on [0, 1] and its derivative.
        let (s2, s3) = (s * s, s * s * s);
        let (h00, h10, h01, h11) =
            (2.0 * s3 - 3.0 * s2 + 1.0, s3 - 2.0 * s2 + s, -2.0 * s3 + 3.0 * s2, s3 - s2);
        let (d00, d10, d01, d11) =
            (6.0 * s2 - 6.0 * s, 3.0 * s2 - 4.0 * s + 1.0, -6.0 * s2 + 6.0 * s, 3.0 * s2 - 2.0 * s);
        let force = h00 * f0 + h10 * h * m0 + h01 * f1 + h11 * h * m1;
        let slope = (d00 * f0 + d01 * f1) / h + d10 * m0 + d11 * m1;
        (force, slope)
    }
}

/// Fritsch & Carlson's slopes (module docs).
fn monotone_slopes(t: &[[f64; 2]]) -> Vec<f64> {
    let n = t.len();
    let delta: Vec<f64> = t.windows(2).map(|w| (w[1][1] - w[0][1]) / (w[1][0] - w[0][0])).collect();
    let mut m = vec![0.0; n];
    m[0] = delta[0];
    m[n - 1] = delta[n - 2];
    for k in 1..n - 1 {
        let (a, b) = (delta[k - 1], delta[k]);
        m[k] = if a * b > 0.0 { 0.5 * (a + b) } else { 0.0 };
    }
    for k in 0..n - 1 {
        if delta[k] == 0.0 {
            m[k] = 0.0;
            m[k + 1] = 0.0;
            continue;
        }
        let (alpha, beta) = (m[k] / delta[k], m[k + 1] / delta[k]);
        let r = alpha.hypot(beta);
        if r > 3.0 {
            let tau = 3.0 / r;
            m[k] = tau * alpha * delta[k];
            m[k + 1] = tau * beta * delta[k];
        }
    }
    m
}
