//! Variance-based sensitivity of a study's outputs to its inputs:
//! standardized regression coefficients (SRC).
//!
//! For one output y over n samples and d inputs x_j, fit the linear model
//! y = b_0 + sum_j b_j x_j by least squares (SVD, nalgebra) and report
//!
//! * SRC_j = b_j s(x_j) / s(y) (s: sample standard deviation),
//! * R^2 = 1 - SS_res / SS_tot, the share of Var(y) the linear model explains,
//! * the share of input j: S_j = R^2 (b_j s(x_j))^2 / sum_k (b_k s(x_k))^2.
//!
//! For independent inputs the variance of the linear model is
//! sum_k b_k^2 Var(x_k), so S_j is input j's part of the explained
//! variance, and for a linear response it is exactly the first-order
//! (Sobol) index; the S_j sum to R^2. The plain SRC_j^2 estimate the same
//! quantity but also carry the chance correlation between the sampled
//! columns (about 1/sqrt(n)), which makes their sum miss R^2 by several
//! per cent at a few hundred samples; the normalised form removes that.
//! Where R^2 is well below 1 the response is not linear in the inputs over
//! their range and the shares describe only its linear part (Saltelli et
//! al., "Global Sensitivity Analysis: The Primer", 2008, §1.2.5). The
//! regression needs n >= d + 2 samples; the sampling error of a share is
//! of the order of 1 / sqrt(n).

pub mod sobol;
pub mod sobol_run;

use nalgebra::{DMatrix, DVector};
use serde::{Deserialize, Serialize};

use super::error::{Result, StudyError};
use super::inputs::Input;

/// Below this R^2 the shares are flagged as describing only the linear part.
pub const R2_LINEAR: f64 = 0.9;

/// The linear regression of one output: its standardized regression
/// coefficients and variance shares.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Regression {
    /// SRC_j = b_j s(x_j) / s(y), one per input.
    pub src: Vec<f64>,
    /// S_j = R^2 SRC_j^2 / sum_k SRC_k^2: share of the output variance due
    /// to input j.
    pub share: Vec<f64>,
    /// Coefficient of determination of the linear fit.
    pub r_squared: f64,
}

/// Regression of output `y` (one value per sample) on inputs `x` (one row
/// per sample, d columns): the SRC and shares. Errors: fewer than d + 2
/// samples, non-finite values, an output or an input that does not vary.
pub fn regression(x: &[Vec<f64>], y: &[f64]) -> Result<Regression> {
    let n = y.len();
    let d = x.first().map_or(0, |r| r.len());
    if d == 0 {
        return Err(StudyError::ZeroDims);
    }
    if x.len() != n {
        return Err(StudyError::InvalidParameter(format!(
            "{} input rows for {n} outputs",
            x.len()
        )));
    }
    if n < d + 2 {
        return Err(StudyError::InvalidParameter(format!(
            "a regression on {d} inputs needs at least {} samples, got {n}",
            d + 2
        )));
    }
    if y.iter().chain(x.iter().flatten()).any(|v| !v.is_finite()) {
        return Err(StudyError::NonFinite { what: "sensitivity data".into() });
    }
    let standardize = |v: &[f64]| -> Option<Vec<f64>> {
        let m = v.iter().sum::<f64>() / n as f64;
        let s = (v.iter().map(|a| (a - m).powi(2)).sum::<f64>() / (n - 1) as f64).sqrt();
        (s > 0.0 && s.is_finite() && s > 1e-14 * m.abs())
            .then(|| v.iter().map(|a| (a - m) / s).collect())
    };
    let ys = standardize(y)
        .ok_or_else(|| StudyError::InvalidParameter("the output does not vary".into()))?;
    let mut cols = Vec::with_capacity(d);
    for j in 0..d {
        let c: Vec<f64> = x.iter().map(|r| r[j]).collect();
        cols.push(standardize(&c).ok_or_else(|| {
            StudyError::InvalidParameter(format!("input {} does not vary", j + 1))
        })?);
    }
    // Standardized columns have zero mean: no intercept column is needed.
    let a = DMatrix::from_fn(n, d, |i, j| cols[j][i]);
    let b = DVector::from_column_slice(&ys);
    let coef = a
        .clone()
        .svd(true, true)
        .solve(&b, 1e-12)
        .map_err(|e| StudyError::InvalidParameter(format!("regression failed: {e}")))?;
    let resid = &b - &a * &coef;
    let ss_tot = b.norm_squared();
    let r_squared = 1.0 - resid.norm_squared() / ss_tot;
    let explained: f64 = coef.iter().map(|c| c * c).sum();
    Ok(Regression {
        src: coef.iter().copied().collect(),
        share: coef.iter().map(|c| r_squared * c * c / explained).collect(),
        r_squared,
    })
}

/// Sensitivity of one DOF (one output column).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DofSensitivity {
    /// Output name (`point/dof`).
    pub output: String,
    /// Share S_j of the output variance per input (empty when `note` says why not).
    pub share: Vec<f64>,
    /// SRC_j per input (sign: direction of the effect).
    pub src: Vec<f64>,
    /// R^2 of the linear fit.
    pub r_squared: Option<f64>,
    /// Why the shares are missing or only indicative.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// Sensitivity of a block of outputs to a block of inputs.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SensitivityBlock {
    /// "reseating" or "interchangeability".
    pub kind: String,
    /// The inputs, in the order of the shares.
    pub inputs: Vec<Input>,
    /// One entry per output (the six DOFs of the first evaluation point).
    pub dofs: Vec<DofSensitivity>,
    /// First-order and total Sobol indices of the same outputs on the same
    /// inputs (absent for a sharded study, or before they are attached).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sobol: Option<sobol::SobolBlock>,
}

/// The SRC of the outputs `outputs` (column indices, with names) on the
/// inputs `inputs` (column indices of the design rows, with names), over
/// samples given as (design row, outputs).
pub fn block(
    kind: &str,
    inputs: &[(usize, Input)],
    outputs: &[(usize, String)],
    samples: &[(&[f64], &[f64])],
) -> SensitivityBlock {
    let x: Vec<Vec<f64>> =
        samples.iter().map(|(row, _)| inputs.iter().map(|(j, _)| row[*j]).collect()).collect();
    let dofs = outputs
        .iter()
        .map(|(k, name)| {
            let y: Vec<f64> = samples.iter().map(|(_, out)| out[*k]).collect();
            match regression(&x, &y) {
                Ok(s) => DofSensitivity {
                    output: name.clone(),
                    note: (s.r_squared < R2_LINEAR).then(|| {
                        format!(
                            "R^2 = {:.3} < {R2_LINEAR}: the response is not linear enough; the \
                             shares describe only its linear part",
                            s.r_squared
                        )
                    }),
                    share: s.share,
                    src: s.src,
                    r_squared: Some(s.r_squared),
                },
                Err(e) => DofSensitivity {
                    output: name.clone(),
                    share: Vec::new(),
                    src: Vec::new(),
                    r_squared: None,
                    note: Some(e.to_string()),
                },
            }
        })
        .collect();
    SensitivityBlock {
        kind: kind.to_string(),
        inputs: inputs.iter().map(|(_, i)| *i).collect(),
        dofs,
        sobol: None,
    }
}
