//! Descriptive statistics of the output quantities of a study.
//!
//! Per output quantity over the samples: n, mean, min, max, the standard deviation, the
//! 3-sigma value and band, and a 90 % interval of sigma by a method valid for the design
//! ([`SigmaMethod`], [`interval`]): Bonett's kurtosis-adjusted interval for Monte Carlo, the
//! replicate t interval for a replicated LHS, none for corners or a single LHS. Sigma is the
//! sample standard deviation (divisor n - 1), except for a replicated LHS, where it is the
//! unbiased replicated estimate of [`interval::sigma_replicated`].
//!
//! Mean and variance use the corrected two-pass algorithm (Chan, Golub & LeVeque 1983, eq. 1.7):
//! `mean = sum(x)/n`, `var = (sum((x-mean)^2) - (sum(x-mean))^2/n) / (n-1)`, which is accurate
//! even when the spread is tiny compared with the mean. Fewer than 2 values or any NaN/infinity
//! is an error, never a NaN result.
//!
//! Shards are merged at the level of per-sample records ([`records`]): the statistics of a
//! merged study are recomputed from the records sorted by sample index, so they are those of a
//! single run.

pub mod bootstrap;
pub mod convergence;
pub mod interval;
pub mod moments;
pub mod quantile;
pub mod records;

use serde::{Deserialize, Serialize};

use super::error::{Result, StudyError};
use super::sampling::{DesignSpec, Sampler};
pub use bootstrap::{BOOTSTRAP_SEED, BootstrapConfig};
pub use convergence::{ConvergencePoint, sigma_convergence};
pub use interval::{Interval, sigma_interval_from_moments, sigma_interval_iid, sigma_replicated};
pub use moments::Moments;
pub use records::{MergedStudy, SampleRecord, ShardFile, merge, verify_inputs};

/// How the interval of sigma is computed: chosen from the design that produced the samples.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SigmaMethod {
    /// Independent samples (Monte Carlo): Bonett (2006).
    Iid,
    /// A replicated LHS of this many replicates (rows in replicate order).
    Replicated(usize),
    /// No valid interval: a corner design (deterministic).
    Corners,
    /// No valid interval: a single (unreplicated) LHS.
    SingleLhs,
    /// No valid interval: an LHS some of whose seatings did not centre (its
    /// strata and replicates are incomplete).
    IncompleteLhs,
}

impl SigmaMethod {
    /// The method valid for `design`.
    pub fn for_design(design: &DesignSpec) -> Self {
        Self::for_sampler(design.sampler, design.replicates)
    }

    /// The method valid for `sampler` run in `replicates` replicates.
    pub fn for_sampler(sampler: Sampler, replicates: usize) -> Self {
        match (sampler, replicates) {
            (Sampler::MonteCarlo, _) => SigmaMethod::Iid,
            (Sampler::Corners, _) => SigmaMethod::Corners,
            (Sampler::Lhs, r) if r >= 2 => SigmaMethod::Replicated(r),
            (Sampler::Lhs, _) => SigmaMethod::SingleLhs,
        }
    }

    /// The point estimate of sigma in words, for the headers of the reports.
    pub fn estimate(&self) -> String {
        match self {
            SigmaMethod::Replicated(r) => format!(
                "replicated LHS: the unbiased estimate over its {r} replicates (within-replicate variance plus the spread of the replicate means); its interval, a t on {} df, varies in width from study to study: on average it is narrower than Monte Carlo's at the same sample count, as the LHS lowers the scatter of sigma, but a single one can be wider",
                r - 1
            ),
            SigmaMethod::Iid => "Monte Carlo: divisor n-1".to_string(),
            SigmaMethod::Corners => "corner design: divisor n-1".to_string(),
            SigmaMethod::SingleLhs => "single LHS: divisor n-1".to_string(),
            SigmaMethod::IncompleteLhs => {
                "LHS with seatings that did not centre: divisor n-1 over those that did".to_string()
            }
        }
    }

    /// The method in words, as written into every output (`sigma_interval_method`).
    pub fn describe(&self) -> String {
        match self {
            SigmaMethod::Iid => interval::METHOD_BONETT.to_string(),
            SigmaMethod::Replicated(r) => {
                format!(
                    "{} ({r} replicates, {} df)",
                    interval::METHOD_REPLICATED_LHS,
                    r - 1
                )
            }
            SigmaMethod::Corners => interval::METHOD_NONE_CORNERS.to_string(),
            SigmaMethod::SingleLhs => {
                "none (single LHS: resampling breaks its strata; use 2 or more replicates)".to_string()
            }
            SigmaMethod::IncompleteLhs => {
                "none (seatings that did not centre leave the LHS strata incomplete; a Monte Carlo design gives an interval)".to_string()
            }
        }
    }
}

/// Statistics of one output quantity.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Summary {
    /// Number of samples.
    pub n: usize,
    pub mean: f64,
    pub min: f64,
    pub max: f64,
    /// Standard deviation: divisor n - 1, or the replicated-LHS estimate.
    pub sigma: f64,
    /// 3 * sigma.
    pub three_sigma: f64,
    /// mean - 3 sigma.
    pub lower_3sigma: f64,
    /// mean + 3 sigma.
    pub upper_3sigma: f64,
    /// Interval of sigma (None where the design admits none).
    pub sigma_interval: Option<Interval>,
    /// How `sigma` and its interval were computed ([`SigmaMethod::describe`]).
    pub sigma_interval_method: String,
}

/// Mean and sample standard deviation (corrected two-pass). Needs n >= 2 finite values.
pub fn mean_sigma(values: &[f64]) -> Result<(f64, f64)> {
    check_values(values)?;
    Ok(mean_sigma_unchecked(values))
}

pub(crate) fn check_values(values: &[f64]) -> Result<()> {
    if values.len() < 2 {
        return Err(StudyError::TooFewSamples { n: values.len() });
    }
    if values.iter().any(|v| !v.is_finite()) {
        return Err(StudyError::NonFinite { what: "sample values".into() });
    }
    Ok(())
}

/// Corrected two-pass mean and standard deviation; caller checked n >= 2 and finiteness.
pub(crate) fn mean_sigma_unchecked(values: &[f64]) -> (f64, f64) {
    let n = values.len() as f64;
    let mean = values.iter().sum::<f64>() / n;
    let (mut ss, mut comp) = (0.0, 0.0);
    for &v in values {
        let dv = v - mean;
        ss += dv * dv;
        comp += dv;
    }
    // Clamp rounding below zero, but keep a NaN (overflow) visible: f64::max
    // would turn it into 0 (sigma = 0 from a part holding 1e308).
    let var = (ss - comp * comp / n) / (n - 1.0);
    let var = if var < 0.0 { 0.0 } else { var };
    (mean, var.sqrt())
}

/// Full summary of one quantity (values in design order), with the interval of `method`.
pub fn summarize(values: &[f64], method: SigmaMethod) -> Result<Summary> {
    let (mean, sigma) = mean_sigma(values)?;
    let min = values.iter().copied().fold(f64::INFINITY, f64::min);
    let max = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    let summary =
        |sigma, interval, how| summary(values.len(), mean, sigma, [min, max], interval, how);
    if method == SigmaMethod::Iid && values.len() < 3 {
        return summary(sigma, None, "none (fewer than 3 samples)".into());
    }
    let (sigma, sigma_interval) = match method {
        SigmaMethod::Iid => (sigma, Some(sigma_interval_iid(values, interval::LEVEL)?)),
        SigmaMethod::Replicated(r) => {
            let (s, i) = sigma_replicated(values, r, interval::LEVEL)?;
            (s, Some(i))
        }
        SigmaMethod::Corners | SigmaMethod::SingleLhs | SigmaMethod::IncompleteLhs => (sigma, None),
    };
    summary(sigma, sigma_interval, method.describe())
}

/// Summary of one quantity from its streamed moments (independent samples): sigma with
/// divisor n - 1 and Bonett's interval from the moments ([`sigma_interval_from_moments`]).
pub fn summarize_moments(m: &Moments) -> Result<Summary> {
    let (n, sigma, how) = (m.n as usize, m.sigma(), SigmaMethod::Iid.describe());
    let s = summary(n, m.mean, sigma, [m.min, m.max], None, how)?;
    Ok(Summary { sigma_interval: Some(sigma_interval_from_moments(m, interval::LEVEL)?), ..s })
}

fn summary(
    n: usize,
    mean: f64,
    sigma: f64,
    [min, max]: [f64; 2],
    sigma_interval: Option<Interval>,
    sigma_interval_method: String,
) -> Result<Summary> {
    if !(mean.is_finite() && sigma.is_finite()) {
        return Err(StudyError::NonFinite { what: "mean or sigma (overflow)".into() });
    }
    Ok(Summary {
        n,
        mean,
        min,
        max,
        sigma,
        three_sigma: 3.0 * sigma,
        lower_3sigma: mean - 3.0 * sigma,
        upper_3sigma: mean + 3.0 * sigma,
        sigma_interval,
        sigma_interval_method,
    })
}

/// One [`Summary`] per output quantity (column `j` of every record's `outputs`), taking the
/// records in the given order (sort them by index first; [`merge`] does).
pub fn summarize_outputs(records: &[SampleRecord], method: SigmaMethod) -> Result<Vec<Summary>> {
    let width = records.first().map_or(0, |r| r.outputs.len());
    if records.len() < 2 {
        return Err(StudyError::TooFewSamples { n: records.len() });
    }
    if let Some(r) = records.iter().find(|r| r.outputs.len() != width) {
        return Err(StudyError::RecordShape {
            index: r.index,
            what: format!("{} outputs, expected {width}", r.outputs.len()),
        });
    }
    (0..width)
        .map(|j| {
            let column: Vec<f64> = records.iter().map(|r| r.outputs[j]).collect();
            summarize(&column, method)
        })
        .collect()
}
