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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn normal_quantiles_match_tables() {
        // Abramowitz & Stegun Table 26.5 / R's qnorm.
        for (p, z) in [
            (0.95, 1.644_853_626_951_472_2),
            (0.975, 1.959_963_984_540_054),
            (0.5, 0.0),
            (1e-10, -6.361_340_902_404_056),
        ] {
            let got = normal_quantile(p).unwrap();
            assert!((got - z).abs() < 1e-14 * z.abs().max(1.0), "{p}: {got}");
        }
        assert!(normal_quantile(1.0).is_err());
    }

    #[test]
    fn t_quantiles_match_tables() {
        // R: qt(0.95, c(1, 2, 4, 9, 30)); qt(0.975, 4) (checked with mpmath, 30 digits).
        for (p, nu, t) in [
            (0.95, 1, 6.313_751_514_675_041),
            (0.95, 2, 2.919_985_580_353_725),
            (0.95, 4, 2.131_846_786_326_649),
            (0.95, 9, 1.833_112_932_653_634),
            (0.95, 30, 1.697_260_886_593_957),
            (0.975, 4, 2.776_445_105_197_793),
        ] {
            let got = student_t_quantile(p, nu).unwrap();
            assert!((got - t).abs() < 1e-10 * t, "nu {nu}: {got} vs {t}");
            assert!((student_t_quantile(1.0 - p, nu).unwrap() + t).abs() < 1e-10 * t);
        }
        assert!(student_t_quantile(0.95, 0).is_err());
    }
}
