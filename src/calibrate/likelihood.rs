//! The likelihood of the measured scatter given the model, and the
//! goodness-of-fit test.
//!
//! Model: with every contact sliding, the pose deviation is nearly linear in
//! the deviations of the static coefficients, mu_k = mu0 + spread u_k, so
//! the model covariance of the measured DOFs is Sigma(s) = s^2 G with G the
//! covariance per unit spread^2 (from a study, `model`). The rig adds
//! independent sensor noise N = diag(noise^2):
//! Sigma(s) = s^2 G + N.
//!
//! * Cycles file (n cycles, sample covariance S, divisor n - 1):
//!   (n - 1) S ~ Wishart_p(Sigma, n - 1) (Anderson 2003, §7.2), so up to a
//!   constant l(s) = -(n - 1)/2 [ln det Sigma(s) + tr(Sigma(s)^-1 S)].
//! * Summary file (sigma_j over n_j cycles, DOFs taken as independent):
//!   (n_j - 1) sigma_j^2 / Sigma_jj ~ chi^2_{n_j - 1}, so
//!   l(s) = -sum_j (n_j - 1)/2 [ln Sigma_jj(s) + sigma_j^2 / Sigma_jj(s)].
//!
//! The fit ([`super::fit`]) maximises l over the fitted parameters and
//! takes the adjusted profile-likelihood interval of each; this file holds
//! the likelihood itself and the goodness-of-fit test.

use nalgebra::DMatrix;
use statrs::distribution::{ChiSquared, ContinuousCDF};

/// The level of every calibrated interval.
pub const LEVEL: f64 = 0.90;

/// chi^2_1(LEVEL) = 2.7055: the threshold of Wilks' profile-likelihood
/// interval, {theta_a : k_a 2 (l_max - l_p) <= this}.
pub fn wilks_threshold() -> f64 {
    ChiSquared::new(1.0).expect("one degree of freedom").inverse_cdf(LEVEL)
}

/// What was measured, in the model's DOF order (SI).
#[derive(Debug, Clone, PartialEq)]
pub enum Observed {
    /// Sample covariance S (divisor n - 1) of n cycles.
    Covariance { s: DMatrix<f64>, n: usize },
    /// Sample sigma per DOF with its number of cycles.
    Sigmas { sigma: Vec<f64>, cycles: Vec<usize> },
}

impl Observed {
    /// Number of measured DOFs.
    pub fn dims(&self) -> usize {
        match self {
            Observed::Covariance { s, .. } => s.nrows(),
            Observed::Sigmas { sigma, .. } => sigma.len(),
        }
    }
}

/// Sigma(s) = s^2 G + diag(noise_var).
pub fn model_covariance(g: &DMatrix<f64>, noise_var: &[f64], s: f64) -> DMatrix<f64> {
    let mut m = g * (s * s);
    for (j, v) in noise_var.iter().enumerate() {
        m[(j, j)] += v;
    }
    m
}

/// ln det and inverse of a symmetric positive definite matrix (None if not).
fn ln_det_inverse(m: &DMatrix<f64>) -> Option<(f64, DMatrix<f64>)> {
    let ch = m.clone().cholesky()?;
    let ln_det = 2.0 * ch.l_dirty().diagonal().iter().map(|d| d.ln()).sum::<f64>();
    Some((ln_det, ch.inverse()))
}

/// Log-likelihood of the observation under the covariance `sigma` (None:
/// singular).
pub fn log_likelihood(obs: &Observed, sigma: &DMatrix<f64>) -> Option<f64> {
    match obs {
        Observed::Covariance { s: sm, n } => {
            let (ln_det, inv) = ln_det_inverse(sigma)?;
            let tr = (inv * sm).trace();
            Some(-0.5 * (*n as f64 - 1.0) * (ln_det + tr))
        }
        Observed::Sigmas { sigma: sd, cycles } => {
            let mut l = 0.0;
            for (j, (sj, nj)) in sd.iter().zip(cycles).enumerate() {
                let v = sigma[(j, j)];
                if v <= 0.0 || !v.is_finite() {
                    return None;
                }
                l -= 0.5 * (*nj as f64 - 1.0) * (v.ln() + sj * sj / v);
            }
            Some(l)
        }
    }
}

/// p below which the model is taken not to explain the data.
pub const GOF_THRESHOLD: f64 = 0.01;

/// Whether the fitted model can explain the measured covariance's shape
/// (the `goodness_of_fit` block of the calibration file).
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct GoodnessOfFit {
    /// Bartlett-corrected likelihood-ratio statistic (None: not testable).
    pub statistic: Option<f64>,
    pub df: usize,
    pub p_value: Option<f64>,
    /// False when p < `threshold` ([`GOF_THRESHOLD`]).
    pub ok: bool,
    pub threshold: f64,
    pub test: String,
}

/// Likelihood-ratio test of the fitted model covariance `fitted` (`q`
/// fitted parameters) against the unrestricted covariance.
///
/// Cycles: -2 ln Lambda = (n - 1) [tr(F^-1 S) - ln det(F^-1 S) - p],
/// multiplied by Bartlett's factor 1 - (2p^2 + 3p - 1) / (6 (n - 1)(p + 1))
/// (Anderson 2003, §10.8, test of Sigma = Sigma_0), compared with chi^2 of
/// p(p + 1)/2 - 1 degrees of freedom (one parameter). Summary: per DOF
/// (n_j - 1)(r_j - ln r_j - 1), r_j = sigma_j^2 / F_jj, each with the p = 1
/// factor 1 - 1/(3 (n_j - 1)), against chi^2 of p - 1. With q parameters
/// the degrees of freedom are p(p + 1)/2 - q (cycles) or p - q (summary);
/// none left: not testable.
pub fn goodness_of_fit(obs: &Observed, fitted: &DMatrix<f64>, q: usize) -> GoodnessOfFit {
    let p = obs.dims();
    // `why`: the reason the statistic cannot be formed, if it cannot.
    let (stat, df, test, why) = match obs {
        Observed::Covariance { s, n } => {
            let m = *n as f64 - 1.0;
            let pf = p as f64;
            let df = (p * (p + 1) / 2).saturating_sub(q);
            let name = "likelihood ratio vs the unrestricted covariance (Wishart), Bartlett-corrected, chi^2";
            let (stat, why) = match (ln_det_inverse(fitted), s.clone().cholesky()) {
                _ if *n <= p => (None, "fewer cycles than measured DOFs + 1"),
                (None, _) => (None, "the fitted model covariance is singular"),
                (_, None) => (
                    None,
                    "the measured covariance is singular (a DOF without scatter, or DOFs \
                     that move together exactly)",
                ),
                (Some((ld_f, inv)), Some(chs)) => {
                    let ld_s = 2.0 * chs.l_dirty().diagonal().iter().map(|d| d.ln()).sum::<f64>();
                    let lr = m * ((inv * s).trace() - (ld_s - ld_f) - pf);
                    let rho = 1.0 - (2.0 * pf * pf + 3.0 * pf - 1.0) / (6.0 * m * (pf + 1.0));
                    (Some(rho * lr), "")
                }
            };
            (stat, df, name, why)
        }
        Observed::Sigmas { sigma, cycles } => {
            let mut lr = 0.0;
            for (j, (sj, nj)) in sigma.iter().zip(cycles).enumerate() {
                let m = *nj as f64 - 1.0;
                let r = sj * sj / fitted[(j, j)];
                lr += (1.0 - 1.0 / (3.0 * m)) * m * (r - r.ln() - 1.0);
            }
            let name = "likelihood ratio vs free sigma per DOF (chi-square, DOFs independent), Bartlett-corrected";
            let why = "a measured or fitted sigma is zero";
            (lr.is_finite().then_some(lr), p.saturating_sub(q), name, why)
        }
    };
    let p_value = match stat {
        Some(x) if df > 0 => ChiSquared::new(df as f64).ok().map(|c| c.sf(x.max(0.0))),
        _ => None,
    };
    let test = match (stat, df) {
        (_, 0) => "not testable: the fitted parameters leave no shape to test \
                   (as many parameters as measured variances)"
            .to_string(),
        (None, _) => format!("not testable: {why} ({test})"),
        _ => test.to_string(),
    };
    GoodnessOfFit {
        statistic: stat,
        df,
        p_value,
        ok: p_value.is_none_or(|pv| pv >= GOF_THRESHOLD),
        threshold: GOF_THRESHOLD,
        test,
    }
}
