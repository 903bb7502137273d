//! The likelihood of the measured scatter given the model, the fit of the
//! friction spread and the goodness-of-fit test.
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
//! The estimate maximises l (its score is unbiased whatever the pose's
//! distribution, since E[S] = Sigma). The interval is the profile-likelihood
//! (Wilks) interval {s : k 2 (l_max - l(s)) <= chi^2_1(level)} with the
//! sandwich factor k = H / J of [`sandwich_factor`]: the Wishart and
//! chi-square laws hold for normal scatter, but the pose is a nearly linear
//! function of six *uniform* coefficients, lighter-tailed than normal, so its
//! sample covariance varies less than Wishart says (k > 1; without k the
//! 90 % interval covered 99 % in tests/calibration.rs). For a scalar
//! parameter k 2 (l_max - l) is asymptotically chi^2_1 under any
//! distribution with finite fourth moments (the adjusted likelihood ratio,
//! e.g. Chandler & Bate 2007, Biometrika 94, 167; White 1982).

use nalgebra::DMatrix;

use super::chi2::{CHI2_1_90, chi2_sf};

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

/// Log-likelihood of the observation at spread `s` (None: Sigma singular).
pub fn log_likelihood(obs: &Observed, g: &DMatrix<f64>, noise_var: &[f64], s: f64) -> Option<f64> {
    let sigma = model_covariance(g, noise_var, s);
    match obs {
        Observed::Covariance { s: sm, n } => {
            let (ln_det, inv) = ln_det_inverse(&sigma)?;
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

/// The fitted spread with its profile-likelihood interval.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SpreadFit {
    pub estimate: f64,
    pub low: f64,
    pub high: f64,
    pub level: f64,
    /// The interval reached the end of the searched range (0 or s_max).
    pub low_at_bound: bool,
    pub high_at_bound: bool,
    pub log_likelihood: f64,
    /// The sandwich factor k = H / J at the estimate.
    pub sandwich: f64,
    /// Standard deviation of ln(estimate) due to the model study (0 until
    /// [`model_error_sd`] is applied).
    pub model_error: f64,
}

/// Smallest spread searched, relative to `s_max`.
const S_MIN_REL: f64 = 1e-4;

/// Maximise l(s) over s in (0, s_max] and find the 90 % adjusted Wilks
/// interval, `sandwich(s_hat)` giving k. None if the model covariance is
/// singular everywhere.
pub fn fit_spread(
    obs: &Observed,
    g: &DMatrix<f64>,
    noise_var: &[f64],
    s_max: f64,
    sandwich: &dyn Fn(f64) -> f64,
) -> Option<SpreadFit> {
    let l = |t: f64| log_likelihood(obs, g, noise_var, t.exp()).unwrap_or(f64::NEG_INFINITY);
    let (t0, t1) = ((s_max * S_MIN_REL).ln(), s_max.ln());
    let steps = 240;
    let ts: Vec<f64> = (0..=steps)
        .map(|i| t0 + (t1 - t0) * i as f64 / steps as f64)
        .collect();
    let ls: Vec<f64> = ts.iter().map(|&t| l(t)).collect();
    let k = (0..ls.len()).max_by(|&a, &b| ls[a].total_cmp(&ls[b]))?;
    if !ls[k].is_finite() {
        return None;
    }
    // Golden-section search in the bracket around the best grid point.
    let (mut a, mut b) = (ts[k.saturating_sub(1)], ts[(k + 1).min(steps)]);
    let r = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..100 {
        let (c, d) = (b - r * (b - a), a + r * (b - a));
        if l(c) >= l(d) {
            b = d;
        } else {
            a = c;
        }
    }
    let t_hat = 0.5 * (a + b);
    let l_max = l(t_hat).max(ls[k]);
    let t_hat = if l(t_hat) >= ls[k] { t_hat } else { ts[k] };
    let factor = sandwich(t_hat.exp());
    let drop = |t: f64| factor * 2.0 * (l_max - l(t)) - CHI2_1_90;
    let (low, low_at_bound) = match ts[..=k].iter().rev().find(|&&t| drop(t) > 0.0) {
        Some(&t) => (bisect(&drop, t, t_hat).exp(), false),
        None => (0.0, true),
    };
    let (high, high_at_bound) = match ts[k..].iter().find(|&&t| drop(t) > 0.0) {
        Some(&t) => (bisect(&drop, t_hat, t).exp(), false),
        None => (s_max, true),
    };
    Some(SpreadFit {
        estimate: t_hat.exp(),
        low,
        high,
        level: 0.90,
        low_at_bound,
        high_at_bound,
        log_likelihood: l_max,
        sandwich: factor,
        model_error: 0.0,
    })
}

/// The sandwich factor k = H / J of the likelihood at spread `s`: H the
/// information the Wishart (chi-square) law assumes, J the true variance of
/// the score, from the fourth moments of the model's pose samples `x`
/// (rows of the measured DOFs at spread `s_model`, scaled by s / s_model)
/// plus independent normal noise N.
///
/// Cycles: the score is (n - 1)/2 tr(A (S - Sigma)), A = Sigma^-1 Sigma'
/// Sigma^-1, Sigma' = 2 s G, so k = 2 tr(A Sigma A Sigma) / Var(y' A y) with
/// Var(y' A y) = Var(x' A x) + 4 tr(A N A Sigma_x) + 2 tr(A N A N) for
/// y = x + e. Summary: the same with A = diag(Sigma'_jj / Sigma_jj^2),
/// weights n_j - 1, and H that of independent DOFs.
/// Normal scatter gives k = 1.
pub fn sandwich_factor(
    obs: &Observed,
    g: &DMatrix<f64>,
    noise_var: &[f64],
    s: f64,
    x: &[Vec<f64>],
    s_model: f64,
) -> f64 {
    let p = g.nrows();
    let sigma = model_covariance(g, noise_var, s);
    let d_sigma = g * (2.0 * s);
    let scale = s / s_model;
    let n = x.len() as f64;
    let mean: Vec<f64> = (0..p)
        .map(|j| x.iter().map(|r| r[j]).sum::<f64>() / n)
        .collect();
    let xs: Vec<Vec<f64>> = x
        .iter()
        .map(|r| (0..p).map(|j| (r[j] - mean[j]) * scale).collect())
        .collect();
    let k = match obs {
        Observed::Covariance { .. } => sandwich_cycles(g, noise_var, s, &sigma, &d_sigma, &xs),
        Observed::Sigmas { cycles, .. } => {
            sandwich_summary(cycles, noise_var, &sigma, &d_sigma, &xs)
        }
    };
    if k.is_finite() && k > 0.0 { k } else { 1.0 }
}

/// Sample variance (divisor n - 1).
fn variance(v: &[f64]) -> f64 {
    let m = v.iter().sum::<f64>() / v.len() as f64;
    v.iter().map(|a| (a - m).powi(2)).sum::<f64>() / (v.len() as f64 - 1.0)
}

/// k for a cycles file (see [`sandwich_factor`]); `xs` centred and scaled samples.
fn sandwich_cycles(
    g: &DMatrix<f64>,
    noise_var: &[f64],
    s: f64,
    sigma: &DMatrix<f64>,
    d_sigma: &DMatrix<f64>,
    xs: &[Vec<f64>],
) -> f64 {
    let Some((_, inv)) = ln_det_inverse(sigma) else {
        return 1.0;
    };
    let a = &inv * d_sigma * &inv;
    let nm = DMatrix::from_diagonal(&nalgebra::DVector::from_column_slice(noise_var));
    let sx = g * (s * s);
    let h = 2.0 * (&a * sigma * &a * sigma).trace();
    let q: Vec<f64> = xs
        .iter()
        .map(|r| {
            let v = nalgebra::DVector::from_column_slice(r);
            (v.transpose() * &a * &v)[(0, 0)]
        })
        .collect();
    let j =
        variance(&q) + 4.0 * (&a * &nm * &a * &sx).trace() + 2.0 * (&a * &nm * &a * &nm).trace();
    h / j
}

/// k for a summary file (see [`sandwich_factor`]).
fn sandwich_summary(
    cycles: &[usize],
    noise_var: &[f64],
    sigma: &DMatrix<f64>,
    d_sigma: &DMatrix<f64>,
    xs: &[Vec<f64>],
) -> f64 {
    let p = sigma.nrows();
    let n = xs.len() as f64;
    let w: Vec<f64> = cycles.iter().map(|c| *c as f64 - 1.0).collect();
    let a: Vec<f64> = (0..p)
        .map(|j| d_sigma[(j, j)] / sigma[(j, j)].powi(2))
        .collect();
    let h: f64 = (0..p)
        .map(|j| w[j] / 2.0 * (a[j] * sigma[(j, j)]).powi(2))
        .sum();
    let sq: Vec<Vec<f64>> = (0..p)
        .map(|j| xs.iter().map(|r| r[j] * r[j]).collect())
        .collect();
    let mut jv = 0.0;
    for u in 0..p {
        for v in 0..p {
            let (mu, mv) = (sq[u].iter().sum::<f64>() / n, sq[v].iter().sum::<f64>() / n);
            let mut c = sq[u]
                .iter()
                .zip(&sq[v])
                .map(|(a, b)| (a - mu) * (b - mv))
                .sum::<f64>()
                / (n - 1.0);
            if u == v {
                c += 4.0 * mu * noise_var[u] + 2.0 * noise_var[u] * noise_var[u];
            }
            jv += (w[u] * w[v]).sqrt() / 4.0 * a[u] * a[v] * c;
        }
    }
    h / jv
}

/// Standard deviation of ln s_hat due to the finite model study alone.
///
/// s_hat solves the score equation tr(A (S - s^2 G - N)) = 0 (A the score's
/// weight matrix: Sigma^-1 Sigma' Sigma^-1, or its diagonal form weighted by
/// n_j - 1 for a summary), so an error dC of the model covariance C = s_m^2 G
/// moves ln s_hat^2 by -tr(A dC) / tr(A C), and with C estimated from the
/// model's N pose samples x: Var(ln s_hat) = Var(x' A x) / (4 N tr(A C)^2).
pub fn model_error_sd(
    obs: &Observed,
    g: &DMatrix<f64>,
    noise_var: &[f64],
    s: f64,
    x: &[Vec<f64>],
) -> f64 {
    let p = g.nrows();
    let sigma = model_covariance(g, noise_var, s);
    let Some((_, inv)) = ln_det_inverse(&sigma) else {
        return 0.0;
    };
    let mut a = &inv * g * &inv;
    if let Observed::Sigmas { cycles, .. } = obs {
        a = DMatrix::from_fn(p, p, |i, j| {
            if i == j {
                (cycles[i] as f64 - 1.0) * g[(i, i)] / sigma[(i, i)].powi(2)
            } else {
                0.0
            }
        });
    }
    let n = x.len() as f64;
    let mean: Vec<f64> = (0..p)
        .map(|j| x.iter().map(|r| r[j]).sum::<f64>() / n)
        .collect();
    let q: Vec<f64> = x
        .iter()
        .map(|r| {
            let v = nalgebra::DVector::from_fn(p, |j, _| r[j] - mean[j]);
            (v.transpose() * &a * &v)[(0, 0)]
        })
        .collect();
    let qm = q.iter().sum::<f64>() / n;
    let var_q = q.iter().map(|v| (v - qm).powi(2)).sum::<f64>() / (n - 1.0);
    // tr(A C) is the mean of x' A x.
    let sd = (var_q / (4.0 * n * qm * qm)).sqrt();
    if sd.is_finite() { sd } else { 0.0 }
}

/// Root of `f` between `a` and `b` (opposite signs) by bisection.
fn bisect(f: &dyn Fn(f64) -> f64, mut a: f64, mut b: f64) -> f64 {
    let fa = f(a);
    for _ in 0..100 {
        let m = 0.5 * (a + b);
        if (f(m) > 0.0) == (fa > 0.0) {
            a = m;
        } else {
            b = m;
        }
    }
    0.5 * (a + b)
}

/// p below which the model is taken not to explain the data.
pub const GOF_THRESHOLD: f64 = 0.01;

/// Whether the fitted model can explain the measured covariance's shape.
#[derive(Debug, Clone, PartialEq)]
pub struct GoodnessOfFit {
    /// Bartlett-corrected likelihood-ratio statistic (None: not testable).
    pub statistic: Option<f64>,
    pub df: usize,
    pub p_value: Option<f64>,
    /// False when p < [`GOF_THRESHOLD`].
    pub ok: bool,
    pub test: String,
}

/// Likelihood-ratio test of the fitted model covariance `fitted` (one
/// fitted parameter) against the unrestricted covariance.
///
/// Cycles: -2 ln Lambda = (n - 1) [tr(F^-1 S) - ln det(F^-1 S) - p],
/// multiplied by Bartlett's factor 1 - (2p^2 + 3p - 1) / (6 (n - 1)(p + 1))
/// (Anderson 2003, §10.8, test of Sigma = Sigma_0), compared with chi^2 of
/// p(p + 1)/2 - 1 degrees of freedom. Summary: per DOF
/// (n_j - 1)(r_j - ln r_j - 1), r_j = sigma_j^2 / F_jj, each with the p = 1
/// factor 1 - 1/(3 (n_j - 1)), against chi^2 of p - 1.
pub fn goodness_of_fit(obs: &Observed, fitted: &DMatrix<f64>) -> GoodnessOfFit {
    goodness_of_fit_q(obs, fitted, 1)
}

/// [`goodness_of_fit`] of a model with `q` fitted parameters: the degrees
/// of freedom p(p + 1)/2 - q (cycles) or p - q (summary); none left: not
/// testable.
pub fn goodness_of_fit_q(obs: &Observed, fitted: &DMatrix<f64>, q: usize) -> GoodnessOfFit {
    let p = obs.dims();
    let (stat, df, test) = match obs {
        Observed::Covariance { s, n } => {
            let m = *n as f64 - 1.0;
            let pf = p as f64;
            let df = (p * (p + 1) / 2).saturating_sub(q);
            let name = "likelihood ratio vs the unrestricted covariance (Wishart), Bartlett-corrected, chi^2";
            let stat = match (ln_det_inverse(fitted), s.clone().cholesky()) {
                (Some((ld_f, inv)), Some(chs)) if *n > p => {
                    let ld_s = 2.0 * chs.l_dirty().diagonal().iter().map(|d| d.ln()).sum::<f64>();
                    let lr = m * ((inv * s).trace() - (ld_s - ld_f) - pf);
                    let rho = 1.0 - (2.0 * pf * pf + 3.0 * pf - 1.0) / (6.0 * m * (pf + 1.0));
                    Some(rho * lr)
                }
                _ => None,
            };
            (stat, df, name)
        }
        Observed::Sigmas { sigma, cycles } => {
            let mut lr = 0.0;
            for (j, (sj, nj)) in sigma.iter().zip(cycles).enumerate() {
                let m = *nj as f64 - 1.0;
                let r = sj * sj / fitted[(j, j)];
                lr += (1.0 - 1.0 / (3.0 * m)) * m * (r - r.ln() - 1.0);
            }
            let name = "likelihood ratio vs free sigma per DOF (chi-square, DOFs independent), Bartlett-corrected";
            (lr.is_finite().then_some(lr), p.saturating_sub(q), name)
        }
    };
    let p_value = match stat {
        Some(x) if df > 0 => Some(chi2_sf(x.max(0.0), df as f64)),
        _ => None,
    };
    let test = match (stat, df) {
        (_, 0) => "not testable: the fitted parameters leave no shape to test \
                   (as many parameters as measured variances)"
            .to_string(),
        (None, _) => format!("not testable: fewer cycles than measured DOFs + 1 ({test})"),
        _ => test.to_string(),
    };
    GoodnessOfFit {
        statistic: stat,
        df,
        p_value,
        ok: p_value.is_none_or(|pv| pv >= GOF_THRESHOLD),
        test,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};

    fn samples(n: usize, uniform: bool) -> Vec<Vec<f64>> {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
        (0..n)
            .map(|_| {
                let v = if uniform {
                    // Uniform on +-sqrt(3): unit variance.
                    3f64.sqrt() * (2.0 * rng.random::<f64>() - 1.0)
                } else {
                    let (u1, u2): (f64, f64) = (1.0 - rng.random::<f64>(), rng.random());
                    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
                };
                vec![v]
            })
            .collect()
    }

    #[test]
    fn one_dof_closed_forms() {
        // One DOF, no noise, unit G: the Wishart maximum is s^2 = S.
        let g = DMatrix::from_element(1, 1, 1.0);
        let obs = Observed::Covariance {
            s: DMatrix::from_element(1, 1, 0.09),
            n: 40,
        };
        let f = fit_spread(&obs, &g, &[0.0], 1.0, &|_| 1.0).unwrap();
        assert!((f.estimate - 0.3).abs() < 1e-9, "{}", f.estimate);
        // Its Wilks interval: 39 [ln(s^2/S) + S/s^2 - 1] = 2.7055 at both ends.
        for e in [f.low, f.high] {
            let r = 0.09 / (e * e);
            assert!((39.0 * (r - r.ln() - 1.0) - CHI2_1_90).abs() < 1e-6);
        }
        // Sandwich factor: normal scatter 1; uniform scatter 2 / Var(x^2) = 2 / 0.8 = 2.5.
        let normal = sandwich_factor(&obs, &g, &[0.0], 1.0, &samples(200_000, false), 1.0);
        let uniform = sandwich_factor(&obs, &g, &[0.0], 1.0, &samples(200_000, true), 1.0);
        assert!((normal - 1.0).abs() < 0.02, "{normal}");
        assert!((uniform - 2.5).abs() < 0.03, "{uniform}");
        // Model error of ln s from N normal samples: sqrt(1 / (2 N)).
        let sd = model_error_sd(&obs, &g, &[0.0], 1.0, &samples(20_000, false));
        assert!((sd / (1.0 / 40_000f64).sqrt() - 1.0).abs() < 0.03, "{sd}");
    }
}
