//! Enhanced stochastic evolutionary (ESE) optimisation of a Latin hypercube
//! (Jin, Chen & Sudjianto 2005, J. Stat. Plan. Inference 134:268-287).
//!
//! Criterion: `phi_p = (sum_{i<j} d_ij^-p)^(1/p)` with `p = 50` (Morris & Mitchell 1995), a
//! smooth surrogate of maximin distance (Johnson, Moore & Ylvisaker 1990): for large `p`,
//! minimising `phi_p` maximises the smallest distance and then reduces the number of pairs at it.
//!
//! Algorithm (paper, Sec. 3): outer iterations of `M` inner steps. Inner step `i` works on column
//! `i mod d`: it draws `J` random swaps of two values in that column, takes the best, and accepts
//! it if `phi_new - phi_old <= T * u` with `u ~ U[0, 1)`. `J = min(C(n,2)/5, 50)` and
//! `M = min(2 C(n,2) d / J, 100)` as in the paper. After each outer iteration the threshold `T`
//! is adapted: if the best design improved, `T *= 0.8` when more than 10 % of moves were
//! accepted but not all of them improved the best, `T /= 0.8` when fewer than 10 % were accepted;
//! otherwise (exploration) `T /= 0.7` when fewer than 10 % were accepted and `T *= 0.9` when more
//! than 80 % were (the common one-flag simplification of the paper's warming/cooling switch).
//!
//! Implementation details (ours):
//! * Each swap changes only the distances of the two swapped rows: a candidate costs O(n).
//! * `T` is relative to the current `phi_p` (`phi_new <= phi_old (1 + T u)`, initially
//!   `T = 0.005`, the paper's `0.005 phi_0` scale); compared as
//!   `S_new <= S_old (1 + T u)^50` on `S = sum (r^2/d^2)^25` with `r = 1/n`, so only +, -, *, /
//!   and `sqrt` are used: results are bit-identical on every IEEE-754 platform. Squared
//!   distances are floored at `1e-10 r^2` so that `S` cannot overflow.
//! * The returned design is the best visited one ordered by (largest minimum distance, then
//!   smallest `phi_p`), starting from the random design, so the result is never worse in
//!   maximin distance than the start.
//!
//! Cost measured for d = 6, n = 25 with the defaults (30 outer iterations, J = 50, M = 72):
//! 11-18 ms per design in a release build on a shared 2-core machine, raising the mean
//! minimum distance over 20 seeds from 0.33 (random LHS) to 0.74 (`examples/lhs_cost.rs`).

use rand_chacha::ChaCha8Rng;

use super::super::error::{Result, StudyError};
use super::super::rng::{below, unit_f64};

/// Tuning of the ESE optimiser. Defaults follow Jin, Chen & Sudjianto (2005).
#[derive(Debug, Clone, PartialEq)]
pub struct EseParams {
    /// Number of outer iterations (threshold adaptations). 0 disables the optimisation.
    pub outer_iterations: usize,
    /// Upper bound of inner steps per outer iteration (`M`, paper: 100).
    pub max_inner: usize,
    /// Upper bound of candidate swaps per inner step (`J`, paper: 50).
    pub max_candidates: usize,
    /// Initial acceptance threshold relative to `phi_p` (paper: 0.005).
    pub initial_threshold: f64,
}

impl Default for EseParams {
    fn default() -> Self {
        EseParams {
            outer_iterations: 30,
            max_inner: 100,
            max_candidates: 50,
            initial_threshold: 0.005,
        }
    }
}

impl EseParams {
    pub(crate) fn validate(&self) -> Result<()> {
        if self.max_inner == 0 || self.max_candidates == 0 {
            return Err(StudyError::InvalidParameter(
                "ESE max_inner and max_candidates must be >= 1".into(),
            ));
        }
        if !(self.initial_threshold.is_finite() && self.initial_threshold >= 0.0) {
            return Err(StudyError::InvalidParameter(
                "ESE initial_threshold must be finite and >= 0".into(),
            ));
        }
        Ok(())
    }
}

const MAX_THRESHOLD: f64 = 1.0;
const MIN_THRESHOLD: f64 = 1e-9;

fn pow25(r: f64) -> f64 {
    let r2 = r * r;
    let r4 = r2 * r2;
    let r8 = r4 * r4;
    let r16 = r8 * r8;
    r16 * r8 * r
}

/// Distances and the `phi_p` sum of a row-major `n x d` design.
struct State {
    n: usize,
    d: usize,
    x: Vec<f64>,
    d2: Vec<f64>,
    t: Vec<f64>,
    s: f64,
    r2: f64,
}

impl State {
    fn new(x: Vec<f64>, n: usize, d: usize) -> Self {
        let r2 = 1.0 / (n as f64 * n as f64);
        let mut st = State { n, d, x, d2: vec![0.0; n * n], t: vec![0.0; n * n], s: 0.0, r2 };
        for i in 0..n {
            st.refresh_row(i);
        }
        st.s = st.full_sum();
        st
    }

    fn term(&self, d2: f64) -> f64 {
        pow25(self.r2 / d2.max(self.r2 * 1e-10))
    }

    fn pair_d2(&self, i: usize, j: usize) -> f64 {
        let (xi, xj) = (&self.x[i * self.d..][..self.d], &self.x[j * self.d..][..self.d]);
        xi.iter().zip(xj).map(|(a, b)| (a - b) * (a - b)).sum()
    }

    /// Recomputes distances and terms of row `i` exactly from the coordinates.
    fn refresh_row(&mut self, i: usize) {
        for j in 0..self.n {
            if j != i {
                let d2 = self.pair_d2(i, j);
                let t = self.term(d2);
                self.d2[i * self.n + j] = d2;
                self.d2[j * self.n + i] = d2;
                self.t[i * self.n + j] = t;
                self.t[j * self.n + i] = t;
            }
        }
    }

    fn full_sum(&self) -> f64 {
        let mut s = 0.0;
        for i in 0..self.n {
            for j in i + 1..self.n {
                s += self.t[i * self.n + j];
            }
        }
        s
    }

    fn min_d2(&self) -> f64 {
        let mut m = f64::INFINITY;
        for i in 0..self.n {
            for j in i + 1..self.n {
                m = m.min(self.d2[i * self.n + j]);
            }
        }
        m
    }

    /// Change of the `phi_p` sum if values of rows `a` and `b` in column `k` were swapped.
    fn delta(&self, k: usize, a: usize, b: usize) -> f64 {
        let (n, d) = (self.n, self.d);
        let (xa, xb) = (self.x[a * d + k], self.x[b * d + k]);
        let mut delta = 0.0;
        for j in 0..n {
            if j == a || j == b {
                continue;
            }
            let xj = self.x[j * d + k];
            let (da, db) = ((xa - xj) * (xa - xj), (xb - xj) * (xb - xj));
            let na = self.d2[a * n + j] - da + db;
            let nb = self.d2[b * n + j] - db + da;
            delta += self.term(na) + self.term(nb) - self.t[a * n + j] - self.t[b * n + j];
        }
        delta
    }

    fn apply(&mut self, k: usize, a: usize, b: usize, delta: f64) {
        self.x.swap(a * self.d + k, b * self.d + k);
        self.refresh_row(a);
        self.refresh_row(b);
        self.s += delta;
    }
}

/// Runs ESE on the row-major `n x d` design `x` (n >= 2, d >= 2) and returns the best design.
pub(crate) fn optimise(
    x: Vec<f64>,
    n: usize,
    d: usize,
    rng: &mut ChaCha8Rng,
    params: &EseParams,
) -> Vec<f64> {
    let mut st = State::new(x, n, d);
    let pairs = n * (n - 1) / 2;
    let j_cand = pairs.div_ceil(5).clamp(1, params.max_candidates);
    let m_inner = (2 * pairs * d).div_ceil(j_cand).clamp(1, params.max_inner);

    let mut threshold = params.initial_threshold.clamp(0.0, MAX_THRESHOLD);
    let mut best_s = st.s;
    let mut record = (st.min_d2(), st.s, st.x.clone());

    for _ in 0..params.outer_iterations {
        let best_before = best_s;
        let (mut n_acc, mut n_imp) = (0usize, 0usize);
        for inner in 0..m_inner {
            let k = inner % d;
            let mut cand = (0, 0, f64::INFINITY);
            for _ in 0..j_cand {
                let a = below(rng, n);
                let mut b = below(rng, n - 1);
                if b >= a {
                    b += 1;
                }
                let delta = st.delta(k, a, b);
                if delta < cand.2 {
                    cand = (a, b, delta);
                }
            }
            let (a, b, delta) = cand;
            let s_new = st.s + delta;
            let factor = 1.0 + threshold * unit_f64(rng);
            let f2 = factor * factor;
            let f50 = pow25(f2);
            if s_new <= st.s * f50 {
                st.apply(k, a, b, delta);
                n_acc += 1;
                if st.s < best_s {
                    best_s = st.s;
                    n_imp += 1;
                    let m = st.min_d2();
                    if m > record.0 || (m == record.0 && st.s < record.1) {
                        record = (m, st.s, st.x.clone());
                    }
                }
            }
        }
        // Remove the drift of the incremental sum.
        st.s = st.full_sum();

        let acc = n_acc as f64 / m_inner as f64;
        if best_s < best_before {
            if acc > 0.1 && n_imp < n_acc {
                threshold *= 0.8;
            } else if !(acc > 0.1 && n_imp == n_acc) {
                threshold /= 0.8;
            }
        } else if acc < 0.1 {
            threshold /= 0.7;
        } else if acc > 0.8 {
            threshold *= 0.9;
        }
        threshold = threshold.clamp(MIN_THRESHOLD, MAX_THRESHOLD);
    }
    record.2
}
