//! How each contact's static coefficient mu_s is drawn (`[friction]
//! distribution`): a study's design gives every contact a coordinate u in
//! [0, 1] (uniform, stratified by the Latin hypercube), and the contact's
//! mu_s is the quantile of its distribution at u (inverse-transform
//! sampling), so that every sampler keeps its properties on each contact's
//! marginal and the Sobol indices stay defined per contact input.
//!
//! - uniform: mu = mu0 + spread (2u - 1), rectangular in mu0 +- spread
//!   (the paper's);
//! - normal: mean mu0, standard deviation sd, truncated to [0, MU_MAX]
//!   (friction is not negative, and no scene takes mu above MU_MAX):
//!   mu = mu0 + sd Phi^-1(Phi(a) + u (Phi(b) - Phi(a))), a = -mu0/sd,
//!   b = (MU_MAX - mu0)/sd (the truncated normal's quantile; Johnson, Kotz
//!   & Balakrishnan, *Continuous Univariate Distributions* 1, 1994, §10.1);
//! - lognormal: mean mu0 and standard deviation sd of mu itself, so
//!   ln mu is normal with s^2 = ln(1 + sd^2/mu0^2) and m = ln mu0 - s^2/2
//!   (ibid., §14.3), truncated above MU_MAX: mu = exp(m + s Phi^-1(u Phi(c))),
//!   c = (ln MU_MAX - m)/s;
//! - empirical: the measured values v_(1) <= ... <= v_(n), each equally
//!   likely: mu = v_(floor(u n) + 1) (u = 1 gives v_(n)).
//!
//! The truncation moves the mean and standard deviation of a normal or
//! lognormal whose mass beyond the bounds is not negligible;
//! [`MuDistribution::truncated_mass`] states it.

use serde::{Deserialize, Serialize};
use statrs::distribution::{ContinuousCDF, Normal};

use super::resolve::MU_MAX;

/// A contact's mu_s distribution beyond its mu0 and spread (`Uniform`
/// uses those two alone).
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(tag = "kind", rename_all = "lowercase")]
pub enum MuDistribution {
    #[default]
    Uniform,
    /// Standard deviation of each contact, in contact order.
    Normal { sd: Vec<f64> },
    /// Standard deviation of each contact, in contact order.
    Lognormal { sd: Vec<f64> },
    /// The measured values, ascending, shared by every contact.
    Empirical { values: Vec<f64> },
}

/// The share of a distribution's mass its truncation may remove before
/// `check` and `study` warn (1 %: the mean and sd drawn then differ from
/// the stated ones by a few per cent).
pub const TRUNCATION_WARN: f64 = 0.01;

fn phi() -> Normal {
    Normal::new(0.0, 1.0).expect("the standard normal")
}

/// ln-space (m, s) of a lognormal of mean `mean` and standard deviation `sd`.
fn log_params(mean: f64, sd: f64) -> (f64, f64) {
    let s2 = (1.0 + (sd / mean).powi(2)).ln();
    (mean.ln() - 0.5 * s2, s2.sqrt())
}

impl MuDistribution {
    pub fn is_uniform(&self) -> bool {
        *self == MuDistribution::Uniform
    }

    /// The name as `[friction] distribution` spells it.
    pub fn name(&self) -> &'static str {
        match self {
            MuDistribution::Uniform => "uniform",
            MuDistribution::Normal { .. } => "normal",
            MuDistribution::Lognormal { .. } => "lognormal",
            MuDistribution::Empirical { .. } => "empirical",
        }
    }

    /// mu_s of contact `k` (nominal `mu0`, half-width `spread`) at the
    /// design coordinate `u` in [0, 1] (module docs).
    pub fn quantile(&self, k: usize, mu0: f64, spread: f64, u: f64) -> f64 {
        match self {
            MuDistribution::Uniform => mu0 + spread * (2.0 * u - 1.0),
            MuDistribution::Normal { sd } if sd[k] > 0.0 => {
                let (n, sd) = (phi(), sd[k]);
                let (lo, hi) = (n.cdf(-mu0 / sd), n.cdf((MU_MAX - mu0) / sd));
                let p = (lo + u * (hi - lo)).clamp(lo, hi);
                (mu0 + sd * n.inverse_cdf(p)).clamp(0.0, MU_MAX)
            }
            MuDistribution::Lognormal { sd } if sd[k] > 0.0 && mu0 > 0.0 => {
                let ((m, s), n) = (log_params(mu0, sd[k]), phi());
                let hi = n.cdf((MU_MAX.ln() - m) / s);
                (m + s * n.inverse_cdf(u * hi)).exp().min(MU_MAX)
            }
            MuDistribution::Normal { .. } | MuDistribution::Lognormal { .. } => mu0,
            MuDistribution::Empirical { values } => {
                let n = values.len();
                values[((u * n as f64) as usize).min(n - 1)]
            }
        }
    }

    /// The range a contact's mu_s is drawn from, for the checks that probe
    /// its ends (`check`'s friction limit, the cannot-seat probe): mu0 -+
    /// spread (uniform), the 0.1 % and 99.9 % quantiles (normal,
    /// lognormal), the least and largest value (empirical).
    pub fn range(&self, k: usize, mu0: f64, spread: f64) -> (f64, f64) {
        match self {
            MuDistribution::Uniform => (mu0 - spread, mu0 + spread),
            MuDistribution::Empirical { values } => (values[0], values[values.len() - 1]),
            _ => (self.quantile(k, mu0, spread, 0.001), self.quantile(k, mu0, spread, 0.999)),
        }
    }

    /// The probability mass of contact `k`'s normal or lognormal that the
    /// truncation to [0, MU_MAX] removes (0 for the others).
    pub fn truncated_mass(&self, k: usize, mu0: f64) -> f64 {
        let n = phi();
        match self {
            MuDistribution::Normal { sd } if sd[k] > 0.0 => {
                n.cdf(-mu0 / sd[k]) + (1.0 - n.cdf((MU_MAX - mu0) / sd[k]))
            }
            MuDistribution::Lognormal { sd } if sd[k] > 0.0 && mu0 > 0.0 => {
                let (m, s) = log_params(mu0, sd[k]);
                1.0 - n.cdf((MU_MAX.ln() - m) / s)
            }
            _ => 0.0,
        }
    }

    /// A warning where the truncation to [0, MU_MAX] removes more than
    /// [`TRUNCATION_WARN`] of a contact's distribution (from each contact's
    /// nominal `mu0s`): the coefficients drawn then no longer have the
    /// stated mean and sd. `None` below it.
    pub fn truncation_warning(&self, mu0s: &[f64]) -> Option<String> {
        let (name, sd) = match self {
            MuDistribution::Normal { sd } => ("normal", sd),
            MuDistribution::Lognormal { sd } => ("lognormal", sd),
            _ => return None,
        };
        let (k, most) = (0..sd.len())
            .map(|k| (k, self.truncated_mass(k, mu0s[k])))
            .fold((0, 0.0), |a, b| if b.1 > a.1 { b } else { a });
        (most > TRUNCATION_WARN).then(|| {
            format!(
                "the {name} distribution of contact {} (mean {}, sd {}) loses {:.1} % of its \
                 mass to the truncation to [0, {MU_MAX}]: the coefficients drawn do not have \
                 that mean and sd (their distribution is the truncated one); a smaller sd keeps \
                 the stated one",
                k + 1,
                mu0s[k],
                sd[k],
                100.0 * most
            )
        })
    }

    /// One phrase for the reports, e.g. `normal, mean 0.5, sd 0.05,
    /// truncated to [0, 2] (largest mass removed 1.2e-23)`, from each
    /// contact's nominal `mu0s` (in contact order).
    pub fn describe(&self, mu0s: &[f64]) -> String {
        let list = |v: &[f64]| {
            if v.iter().all(|x| *x == v[0]) {
                format!("{}", v[0])
            } else {
                format!("[{}]", v.iter().map(|x| x.to_string()).collect::<Vec<_>>().join(", "))
            }
        };
        let removed = |kind: &str| {
            let n = match self {
                MuDistribution::Normal { sd } | MuDistribution::Lognormal { sd } => sd.len(),
                _ => 0,
            };
            let most = (0..n).map(|k| self.truncated_mass(k, mu0s[k])).fold(0.0, f64::max);
            format!("{kind} (largest mass removed {most:.1e})")
        };
        match self {
            MuDistribution::Uniform => "uniform".into(),
            MuDistribution::Normal { sd } => format!(
                "normal, mean {}, sd {}, {}",
                list(mu0s),
                list(sd),
                removed(&format!("truncated to [0, {MU_MAX}]"))
            ),
            MuDistribution::Lognormal { sd } => format!(
                "lognormal, mean {}, sd {}, {}",
                list(mu0s),
                list(sd),
                removed(&format!("truncated above {MU_MAX}"))
            ),
            MuDistribution::Empirical { values } => {
                format!(
                    "empirical, {} values in [{}, {}], resampled",
                    values.len(),
                    values[0],
                    values[values.len() - 1]
                )
            }
        }
    }
}

/// The friction of a scene or a study in words: `mu_s = 0.5 +- 0.05` and
/// `uniform` (given by the caller: `check` writes `(uniform)`), or one
/// contact's pair after another where lists are given, or the
/// distribution ([`MuDistribution::describe`]) with each contact's mu0;
/// then the correlation within each ball, if any.
pub fn describe_friction(
    (mu_static, spread): (f64, f64),
    contact_friction: Option<&[[f64; 2]]>,
    (distribution, correlation): (&MuDistribution, f64),
    uniform: &str,
) -> String {
    let text = describe_marginals((mu_static, spread), contact_friction, distribution, uniform);
    if correlation > 0.0 {
        format!(
            "{text}, correlation {correlation} between the contacts of each ball (Gaussian copula)"
        )
    } else {
        text
    }
}

fn describe_marginals(
    (mu_static, spread): (f64, f64),
    contact_friction: Option<&[[f64; 2]]>,
    distribution: &MuDistribution,
    uniform: &str,
) -> String {
    match (contact_friction, distribution) {
        (None, MuDistribution::Uniform) => format!("mu_s = {mu_static} +- {spread} {uniform}"),
        (Some(c), MuDistribution::Uniform) => {
            let each: Vec<String> = c.iter().map(|[m, d]| format!("{m} +- {d}")).collect();
            format!("mu_s per contact = [{}] {uniform}", each.join(", "))
        }
        (c, d) => {
            let n = match d {
                MuDistribution::Normal { sd } | MuDistribution::Lognormal { sd } => sd.len(),
                _ => c.map_or(1, |c| c.len()),
            };
            let mu0s: Vec<f64> = match c {
                Some(c) => c.iter().map(|p| p[0]).collect(),
                None => vec![mu_static; n],
            };
            format!("mu_s {}", d.describe(&mu0s))
        }
    }
}

/// The design coordinates `u` of the contacts (in contact order; `ball[k]`
/// the ball of contact k) made dependent between the contacts of each
/// ball by a Gaussian copula of correlation `rho` in [0, 1]: z = Phi^-1(u),
/// z' = L z over each ball's contacts with L L^T the equicorrelation
/// matrix (1 on the diagonal, rho elsewhere; its Cholesky factor, column j
/// of a row left 0 where L_jj = 0, as at rho = 1), and u' = Phi(z')
/// (Nelsen, *An Introduction to Copulas*, 2006, §2.3 and §5.3). Each z'_k is
/// standard normal, so each u'_k stays uniform and each contact keeps its
/// distribution. The first contact of each ball keeps its own coordinate
/// (and its Latin-hypercube stratum); the others mix theirs with it, and
/// at rho = 1 take the first one's exactly. `rho = 0` leaves `u` as it is.
pub fn correlate(u: &mut [f64], ball: &[usize], rho: f64) {
    if rho == 0.0 {
        return;
    }
    if rho == 1.0 {
        for k in 1..u.len() {
            if ball[k] == ball[k - 1] {
                u[k] = u[k - 1];
            }
        }
        return;
    }
    let n = phi();
    let mut start = 0;
    while start < u.len() {
        let end = start + ball[start..].iter().take_while(|&&b| b == ball[start]).count();
        let m = end - start;
        // Cholesky factor of the m x m equicorrelation matrix (0 < rho < 1:
        // positive definite).
        let mut l = vec![vec![0.0; m]; m];
        for i in 0..m {
            for j in 0..=i {
                let target = if i == j { 1.0 } else { rho };
                let dot: f64 = (0..j).map(|k| l[i][k] * l[j][k]).sum();
                l[i][j] = if i == j {
                    (target - dot).max(0.0).sqrt()
                } else if l[j][j] > 0.0 {
                    (target - dot) / l[j][j]
                } else {
                    0.0
                };
            }
        }
        // Coordinates of 0 or 1 (infinite z) moved inside by one ulp.
        let z: Vec<f64> = u[start..end]
            .iter()
            .map(|&x| n.inverse_cdf(x.clamp(f64::EPSILON, 1.0 - f64::EPSILON)))
            .collect();
        for i in 1..m {
            let zi: f64 = (0..=i).map(|k| l[i][k] * z[k]).sum();
            u[start + i] = n.cdf(zi);
        }
        start = end;
    }
}

impl super::file::Distribution {
    /// The keyword as a scene file spells it.
    pub fn name(self) -> &'static str {
        match self {
            super::file::Distribution::Uniform => "uniform",
            super::file::Distribution::Normal => "normal",
            super::file::Distribution::Lognormal => "lognormal",
            super::file::Distribution::Empirical => "empirical",
        }
    }
}
