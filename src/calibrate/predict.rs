//! `kinrepro predict`: sigma of other designs at the calibrated friction
//! spread, with a prediction interval.
//!
//! Per scene three Monte Carlo studies with the same design rows (common
//! random numbers): at the estimate s_hat and at the ends s_lo, s_hi of the
//! spread's interval. The interval of sigma carries
//! * the parameter uncertainty: ln sigma(s_hat) - ln sigma(s_lo) below and
//!   ln sigma(s_hi) - ln sigma(s_hat) above (the studies at the ends, so no
//!   linearity is assumed), and
//! * the sampling error of the N-sample study at s_hat: Bonett's 90 %
//!   interval (Bonett 2006) on ln sigma,
//!
//! combined in quadrature on ln sigma (both taken as independent, roughly
//! normal on the log scale): low = sigma exp(-sqrt(h_p,lo^2 + h_s,lo^2)),
//! high = sigma exp(+sqrt(h_p,hi^2 + h_s,hi^2)). The prediction is the
//! coupling's own scatter (no sensor noise).

use super::error::CalibrateError;
use super::fit::{Calibration, DofFit, design_hash};
use super::model::{model_options, with_spread};
use crate::assembly::Coupling;
use crate::report::study::{Dofs, PointStats, VariantReport};
use crate::solve::Method;
use crate::study::runner::run_variant;

/// The interval method named in `sigma_interval_method`.
pub const PREDICTION_METHOD: &str = "calibrated prediction: profile-likelihood 90 % interval of the spread (studies at its ends, common random numbers) and Bonett's 90 % interval of the Monte Carlo study at the estimate, combined in quadrature on ln sigma";

/// One scene's prediction.
#[derive(Debug, Clone, PartialEq)]
pub struct Prediction {
    /// The study at the calibrated spread, its intervals replaced by the
    /// prediction intervals.
    pub variant: VariantReport,
    /// The measured DOFs when this scene is the calibrated design.
    pub measured: Option<(String, Vec<DofFit>)>,
}

/// Predict sigma of every evaluation point of `coupling` at the spread of `cal`.
pub fn predict(
    coupling: &Coupling,
    cal: &Calibration,
    samples: usize,
    seed: u64,
    method: Method,
) -> Result<Prediction, CalibrateError> {
    let sp = cal.spread();
    let file = coupling.scene.file.clone();
    let mu0 = coupling.scene.friction.mu_static;
    if sp.high > mu0 {
        return Err(CalibrateError::Model {
            file,
            reason: format!(
                "the calibrated spread's interval reaches {:.4}, above this scene's mu_static {mu0} (mu_s would go negative)",
                sp.high
            ),
        });
    }
    let opts = model_options(samples, seed, method);
    let study = |s: f64| -> Result<Vec<PointStats>, CalibrateError> {
        let c = with_spread(coupling, s);
        let run = run_variant(&c, &opts, &|| {})?;
        let v = VariantReport::new(&c, run, &opts).map_err(|source| CalibrateError::Study {
            file: file.clone(),
            source,
        })?;
        Ok(v.points)
    };
    let c = with_spread(coupling, sp.estimate);
    let run = run_variant(&c, &opts, &|| {})?;
    let mut variant =
        VariantReport::new(&c, run, &opts).map_err(|source| CalibrateError::Study {
            file: file.clone(),
            source,
        })?;
    let lo = if sp.low > 0.0 {
        Some(study(sp.low)?)
    } else {
        None
    };
    let hi = study(sp.high)?;
    for (k, p) in variant.points.iter_mut().enumerate() {
        let mid = p.sigma.values();
        let (Some(bl), Some(bh)) = (p.sigma_ci90_low, p.sigma_ci90_high) else {
            return Err(CalibrateError::Model {
                file,
                reason: "the Monte Carlo study at the estimate gave no interval of sigma".into(),
            });
        };
        let l = lo.as_ref().map(|v| v[k].sigma.values());
        let (low, high) = combine(mid, bl.values(), bh.values(), l, hi[k].sigma.values());
        p.sigma_ci90_low = Some(nm_dofs(low));
        p.sigma_ci90_high = Some(nm_dofs(high));
        p.sigma_interval_method = PREDICTION_METHOD.to_string();
    }
    // The per-sample records of the study at the estimate are left out (as
    // for a streamed study): `kinrepro study` at the calibrated spread gives them.
    variant.records.clear();
    let measured =
        (design_hash(coupling) == cal.scene_content).then(|| (cal.point.clone(), cal.dofs.clone()));
    Ok(Prediction { variant, measured })
}

/// The prediction interval per DOF: sigma `mid` at the estimate with its
/// Bonett interval [bl, bh], sigma at the spread's low end `lo` (None: the
/// interval reaches zero spread) and high end `hi`; the parameter and
/// sampling half-widths combined in quadrature on ln sigma.
fn combine(
    mid: [f64; 6],
    bl: [f64; 6],
    bh: [f64; 6],
    lo: Option<[f64; 6]>,
    hi: [f64; 6],
) -> ([f64; 6], [f64; 6]) {
    let mut low = [0.0; 6];
    let mut high = [0.0; 6];
    for j in 0..6 {
        if mid[j] <= 0.0 {
            continue;
        }
        let hs_lo = (mid[j] / bl[j]).ln();
        let hs_hi = (bh[j] / mid[j]).ln();
        let hp_hi = (hi[j] / mid[j]).ln().abs();
        high[j] = mid[j] * hp_hi.hypot(hs_hi).exp();
        low[j] = match lo {
            Some(l) if l[j] > 0.0 => mid[j] * (-(mid[j] / l[j]).ln().abs().hypot(hs_lo)).exp(),
            _ => 0.0,
        };
    }
    (low, high)
}

/// `Dofs` from values already in nm and nrad.
fn nm_dofs(v: [f64; 6]) -> Dofs {
    Dofs::from_si(v.map(|x| x * 1e-9))
}
