//! The information matrices of the joint likelihood ([`super::joint`]) at
//! the estimate: the sandwich factor of each parameter's profile interval,
//! the model study's sampling error of each estimate, and the correlation
//! of the estimates.

use nalgebra::{DMatrix, DVector};

use super::joint::{JointModel, S_MIN_REL};
use super::likelihood::Observed;
use super::model::covariance;

/// The information matrices at theta: H (what the Wishart / chi-square law
/// assumes), J (the true variance of the score, with the pose's fourth
/// moments from the samples `x` of the measured DOFs at theta plus normal
/// sensor noise N), and M (the variance of the score due to the model
/// study's own N_x samples).
///
/// The score of parameter a is tr(W_a (S - Sigma)) with W_a =
/// (n - 1)/2 Sigma^-1 Sigma_a Sigma^-1 (cycles) or diag((n_j - 1)/2
/// Sigma_a,jj / Sigma_jj^2) (summary), Sigma_a = dSigma/dtheta_a. Then
/// H_ab = tr(W_a Sigma_b); cycles: J_ab = Cov(y' W_a y, y' W_b y) / (n - 1)
/// with y = x + e, Cov(y'Ay, y'By) = Cov(x'Ax, x'Bx) + 4 tr(A N B Sigma_x) +
/// 2 tr(A N B N); summary: J_ab = sum_uv W_a,u W_b,v Cov(y_u^2, y_v^2) /
/// sqrt((n_u - 1)(n_v - 1)); M_ab = Cov(x'W_a x, x'W_b x) / N_x (cycles),
/// sum_uv W_a,u W_b,v Cov(x_u^2, x_v^2) / N_x (summary). Normal scatter
/// gives J = H.
pub struct Information {
    pub h: DMatrix<f64>,
    pub j: DMatrix<f64>,
    pub m: DMatrix<f64>,
}

/// dSigma/dtheta_a by central differences (one-sided at a range end).
pub fn d_sigma(m: &JointModel, theta: &[f64]) -> Option<Vec<DMatrix<f64>>> {
    (0..theta.len())
        .map(|a| {
            let (lo, hi) = m.ranges[a];
            let h = match m.params[a] {
                p if p.is_scale() => 1e-4 * theta[a].max(hi * S_MIN_REL),
                _ => 1e-4 * (hi - lo),
            };
            let at = |d: f64| {
                let mut t = theta.to_vec();
                t[a] += d;
                let inside = t[a] >= lo && t[a] <= hi;
                inside.then(|| m.sigma(&t)).flatten()
            };
            match (at(h), at(-h)) {
                (Some(p), Some(n)) => Some((p - n) / (2.0 * h)),
                (Some(p), None) => Some((p - m.sigma(theta)?) / h),
                (None, Some(n)) => Some((m.sigma(theta)? - n) / h),
                (None, None) => None,
            }
        })
        .collect()
}

/// The information matrices at theta (see [`Information`]); `x` the pose
/// samples (measured DOFs) of a model study at theta.
pub fn information(m: &JointModel, theta: &[f64], x: &[Vec<f64>]) -> Option<Information> {
    let sigma = m.sigma(theta)?;
    let ds = d_sigma(m, theta)?;
    let p = sigma.nrows();
    let inv = sigma.clone().cholesky()?.inverse();
    let w: Vec<DMatrix<f64>> = match m.obs {
        Observed::Covariance { n, .. } => {
            ds.iter().map(|d| &inv * d * &inv * (0.5 * (*n as f64 - 1.0))).collect()
        }
        Observed::Sigmas { cycles, .. } => ds
            .iter()
            .map(|d| {
                DMatrix::from_fn(p, p, |i, j| {
                    if i == j {
                        0.5 * (cycles[i] as f64 - 1.0) * d[(i, i)] / sigma[(i, i)].powi(2)
                    } else {
                        0.0
                    }
                })
            })
            .collect(),
    };
    let q = w.len();
    let h = DMatrix::from_fn(q, q, |a, b| (&w[a] * &ds[b]).trace());
    let xs = centred(x);
    let nx = xs.len() as f64;
    let nv = DMatrix::from_diagonal(&DVector::from_column_slice(&m.noise_var));
    let (j, mm) = match m.obs {
        Observed::Covariance { n, .. } => {
            // Per sample the quadratic forms x' W_a x of every parameter.
            let forms: Vec<Vec<f64>> = xs
                .iter()
                .map(|r| {
                    let v = DVector::from_column_slice(r);
                    w.iter().map(|wa| (v.transpose() * wa * &v)[(0, 0)]).collect()
                })
                .collect();
            let sx = covariance(&xs);
            let c = covariance(&forms);
            let noise = DMatrix::from_fn(q, q, |a, b| {
                4.0 * (&w[a] * &nv * &w[b] * &sx).trace()
                    + 2.0 * (&w[a] * &nv * &w[b] * &nv).trace()
            });
            ((&c + noise) / (*n as f64 - 1.0), c / nx)
        }
        Observed::Sigmas { cycles, .. } => {
            let sq: Vec<Vec<f64>> = xs.iter().map(|r| r.iter().map(|v| v * v).collect()).collect();
            let c = covariance(&sq);
            let mean = |u: usize| sq.iter().map(|r| r[u]).sum::<f64>() / nx;
            let cy = DMatrix::from_fn(p, p, |u, v| {
                let extra = if u == v {
                    4.0 * mean(u) * m.noise_var[u] + 2.0 * m.noise_var[u].powi(2)
                } else {
                    0.0
                };
                (c[(u, v)] + extra) / ((cycles[u] as f64 - 1.0) * (cycles[v] as f64 - 1.0)).sqrt()
            });
            let pair = |mat: &DMatrix<f64>, a: usize, b: usize| {
                (0..p)
                    .flat_map(|u| (0..p).map(move |v| (u, v)))
                    .map(|(u, v)| w[a][(u, u)] * w[b][(v, v)] * mat[(u, v)])
                    .sum::<f64>()
            };
            (
                DMatrix::from_fn(q, q, |a, b| pair(&cy, a, b)),
                DMatrix::from_fn(q, q, |a, b| pair(&c, a, b) / nx),
            )
        }
    };
    Some(Information { h, j, m: mm })
}

/// Rows minus their mean.
fn centred(x: &[Vec<f64>]) -> Vec<Vec<f64>> {
    let n = x.len() as f64;
    let p = x.first().map_or(0, Vec::len);
    let mean: Vec<f64> = (0..p).map(|j| x.iter().map(|r| r[j]).sum::<f64>() / n).collect();
    x.iter().map(|r| (0..p).map(|j| r[j] - mean[j]).collect()).collect()
}

/// What the information gives per parameter: the sandwich factor k_a, the
/// standard deviation of the estimate due to the model study, and the
/// correlation of the estimates (from H^-1 J H^-1).
#[derive(Debug, Clone, PartialEq)]
pub struct Derived {
    pub k: Vec<f64>,
    pub model_sd: Vec<f64>,
    pub covariance: Option<DMatrix<f64>>,
}

impl Derived {
    /// Without the information: k = 1 (the unadjusted, wider interval), no
    /// model error, no correlation.
    pub fn unadjusted(q: usize) -> Self {
        Derived { k: vec![1.0; q], model_sd: vec![0.0; q], covariance: None }
    }
}

impl Information {
    /// k_a = (H^-1)_aa / V_aa with V = H^-1 J H^-1 (H singular:
    /// [`Derived::unadjusted`]); model sd_a = sqrt((H^-1 M H^-1)_aa).
    pub fn derived(&self) -> Derived {
        let q = self.h.nrows();
        let Some(hi) = self.h.clone().try_inverse() else {
            return Derived::unadjusted(q);
        };
        let v = &hi * &self.j * &hi;
        let vm = &hi * &self.m * &hi;
        let k = (0..q)
            .map(|a| {
                let r = hi[(a, a)] / v[(a, a)];
                if r.is_finite() && r > 0.0 { r } else { 1.0 }
            })
            .collect();
        let model_sd = (0..q)
            .map(|a| {
                let s = vm[(a, a)].max(0.0).sqrt();
                if s.is_finite() { s } else { 0.0 }
            })
            .collect();
        Derived { k, model_sd, covariance: Some(v) }
    }
}
