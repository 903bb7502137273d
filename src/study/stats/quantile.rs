//! Quantiles of the standard normal and Student t distributions (the `statrs` crate), with the
//! probability checked here instead of a panic inside the crate.

use statrs::distribution::{ContinuousCDF, Normal, StudentsT};

use super::super::error::{Result, StudyError};

/// Quantile `z_p` of the standard normal distribution, `0 < p < 1`.
pub fn normal_quantile(p: f64) -> Result<f64> {
    if !(p > 0.0 && p < 1.0) {
        return Err(StudyError::InvalidParameter(format!(
            "normal quantile: probability {p} not in (0, 1)"
        )));
    }
    Ok(Normal::standard().inverse_cdf(p))
}

/// Quantile `t_{p, nu}` of Student's t, `0 < p < 1`, `nu >= 1`.
pub fn student_t_quantile(p: f64, nu: usize) -> Result<f64> {
    let t = StudentsT::new(0.0, 1.0, nu as f64).ok();
    match t {
        Some(t) if p > 0.0 && p < 1.0 => Ok(t.inverse_cdf(p)),
        _ => Err(StudyError::InvalidParameter(format!(
            "t quantile: need 0 < p < 1 and nu >= 1 (p = {p}, nu = {nu})"
        ))),
    }
}
