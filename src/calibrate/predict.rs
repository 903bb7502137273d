//! `kinrepro predict`: sigma of other designs at the calibrated
//! parameters, with a prediction interval.
//!
//! Per scene Monte Carlo studies with the same design rows (common random
//! numbers): at the estimate theta_hat and at each point of the
//! calibration's `region` (per parameter the ends of its interval, the
//! other parameters at their profile maximum; for several parameters also
//! the ends of the principal axes of the joint region; see `fit`; a
//! schema-1 file: the ends s_lo, s_hi of the spread's interval). The
//! interval of sigma carries
//! * the parameter uncertainty: the range of sigma over those points,
//!   ln sigma(theta_hat) - ln min below and ln max - ln sigma(theta_hat)
//!   above (studies at the points, so no linearity is assumed; the range
//!   over the joint region's boundary points approximates the profile
//!   likelihood interval of sigma itself, {sigma(theta) : k 2 (l_max -
//!   l(theta)) <= chi^2_1(0.90)}, from inside), and
//! * the sampling error of the N-sample study at theta_hat: Bonett's 90 %
//!   interval (Bonett 2006) on ln sigma,
//!
//! combined in quadrature on ln sigma (both taken as independent, roughly
//! normal on the log scale): low = sigma exp(-sqrt(h_p,lo^2 + h_s,lo^2)),
//! high = sigma exp(+sqrt(h_p,hi^2 + h_s,hi^2)). A region point at zero
//! spread gives low = 0. The prediction is the coupling's own scatter (no
//! sensor noise). The calibrated mu_static, dynamic_ratio and absolute
//! support_compliance [m/N] are applied to the other design as they are.

use std::collections::BTreeMap;

use super::error::CalibrateError;
use super::file::{Calibration, DofFit, design_hash};
use super::params::{Param, admissible, apply_named};
use crate::assembly::Coupling;
use crate::scene::Scene;
use crate::solve::Solver;
use crate::study::runner::run_variant;
use crate::study::{Dofs, PointStats, StudyOptions, StudyPlan, Variant, VariantReport};

/// The interval method named in `sigma_interval_method`.
pub const PREDICTION_METHOD: &str = "calibrated prediction: range of sigma over the calibration's 90 % profile-likelihood parameter region (studies at its points, common random numbers) and Bonett's 90 % interval of the Monte Carlo study at the estimate, combined in quadrature on ln sigma";

/// One scene's prediction.
#[derive(Debug, Clone, PartialEq)]
pub struct Prediction {
    /// The study at the calibrated spread, its intervals replaced by the
    /// prediction intervals.
    pub variant: VariantReport,
    /// The measured DOFs when this scene is the calibrated design.
    pub measured: Option<(String, Vec<DofFit>)>,
}

/// The scene with the calibrated `values` set (names of [`super::params::PARAMETERS`]; other names are ignored).
pub fn with_parameters(v: &Variant, values: &BTreeMap<String, f64>) -> Variant {
    let mut out = v.clone();
    apply_named(&mut out.scene, &mut out.coupling, values);
    out
}

/// Predict sigma of every evaluation point of `scene` (assembled as
/// `coupling`) at the parameters of `cal`, read from `cal_file` (errors at
/// a calibrated point name that file and the point: `parameters`
/// estimates or `region[i]`), by Monte Carlo studies of `samples` samples
/// seeded `seed`, seated by `solver`.
pub fn predict(
    scene: &Scene,
    coupling: &Coupling,
    cal: &Calibration,
    cal_file: &str,
    (samples, seed, solver): (usize, u64, Solver),
) -> Result<Prediction, CalibrateError> {
    let file = scene.file.clone();
    super::fit::one_friction_scale(scene)?;
    let options = StudyOptions::monte_carlo(samples, seed, solver);
    let plan = StudyPlan::keeping_records(vec![(scene.clone(), coupling.clone())], &options)?;
    let estimate = with_parameters(&plan.variants[0], &cal.estimates());
    let region: Vec<Variant> =
        cal.region_points().iter().map(|v| with_parameters(&estimate, v)).collect();
    let at = |k: Option<usize>| match k {
        None => "the `parameters` estimates".to_string(),
        Some(i) if cal.region.is_empty() => format!("the `parameters.spread` interval end {i}"),
        Some(i) => format!("`region[{i}]`"),
    };
    let applied = |k: Option<usize>, reason: String| CalibrateError::Applied {
        calibration: cal_file.to_string(),
        at: at(k),
        scene: file.clone(),
        reason,
    };
    let points = std::iter::once((None, &estimate))
        .chain(region.iter().enumerate().map(|(i, c)| (Some(i), c)));
    for (k, v) in points {
        inadmissible(v).map_or(Ok(()), |r| Err(applied(k, r)))?;
    }
    let s = &plan.settings;
    let report = |v: &Variant, k: Option<usize>| -> Result<VariantReport, CalibrateError> {
        let run = run_variant(s, v, &|| {}).map_err(|e| applied(k, e.to_string()))?;
        if let Some(reason) = run.cannot_seat {
            return Err(applied(k, format!("cannot seat: {reason}")));
        }
        let mut r = VariantReport::new(s, v, run).map_err(|e| e.in_file(&file))?;
        r.assessment = Some(crate::study::assessment::Assessment::new(&v.scene, &v.coupling));
        Ok(r)
    };
    let mut variant = report(&estimate, None)?;
    // A point at zero spread has no scatter (sigma 0): no study needed.
    let others: Vec<Option<Vec<PointStats>>> = region
        .iter()
        .enumerate()
        .map(|(i, c)| {
            (c.scene.mu_scale() > 0.0).then(|| report(c, Some(i)).map(|v| v.points)).transpose()
        })
        .collect::<Result<_, _>>()?;
    for (k, p) in variant.points.iter_mut().enumerate() {
        let mid = p.sigma.values();
        let (Some(bl), Some(bh)) = (p.sigma_ci90_low, p.sigma_ci90_high) else {
            return Err(CalibrateError::Model {
                file,
                reason: "the Monte Carlo study at the estimate gave no interval of sigma".into(),
            });
        };
        let at: Vec<[f64; 6]> =
            others.iter().map(|o| o.as_ref().map_or([0.0; 6], |v| v[k].sigma.values())).collect();
        let (low, high) = combine(mid, bl.values(), bh.values(), &at);
        p.sigma_ci90_low = Some(nm_dofs(low));
        p.sigma_ci90_high = Some(nm_dofs(high));
        p.sigma_interval_method = PREDICTION_METHOD.to_string();
    }
    // The per-sample records of the study at the estimate are left out (as
    // for a streamed study): `kinrepro study` at the calibrated values gives them.
    variant.records.clear();
    let measured =
        (design_hash(scene) == cal.scene_content).then(|| (cal.point.clone(), cal.dofs.clone()));
    Ok(Prediction { variant, measured })
}

/// Why the friction of `c` (a scene at calibrated values) is no scene's:
/// mu_s = mu_static +- spread (mu_static +- 2 sd) leaves [0, MU_MAX].
fn inadmissible(v: &Variant) -> Option<String> {
    let f = &v.scene.friction;
    let scale = Param::scale_of(&v.scene);
    let s = v.scene.mu_scale();
    let reach = if scale == Param::Sd { "2 sd" } else { "spread" };
    (!admissible(scale, s, f.mu_static)).then(|| {
        format!(
            "{} {s} with mu_static {}: mu_static +- {reach} would leave [0, {}]",
            scale.name(),
            f.mu_static,
            crate::scene::resolve::MU_MAX
        )
    })
}

/// The prediction interval per DOF: sigma `mid` at the estimate with its
/// Bonett interval [bl, bh], and sigma at the region points `at` (0: a
/// point at zero spread); the parameter half-widths ln(mid / min) and
/// ln(max / mid) and the sampling half-widths combined in quadrature on
/// ln sigma.
fn combine(mid: [f64; 6], bl: [f64; 6], bh: [f64; 6], at: &[[f64; 6]]) -> ([f64; 6], [f64; 6]) {
    let mut low = [0.0; 6];
    let mut high = [0.0; 6];
    for j in 0..6 {
        if mid[j] <= 0.0 {
            continue;
        }
        let min = at.iter().map(|a| a[j]).fold(mid[j], f64::min);
        let max = at.iter().map(|a| a[j]).fold(mid[j], f64::max);
        let hs_lo = (mid[j] / bl[j]).ln();
        let hs_hi = (bh[j] / mid[j]).ln();
        high[j] = mid[j] * (max / mid[j]).ln().hypot(hs_hi).exp();
        low[j] = if min > 0.0 { mid[j] * (-(mid[j] / min).ln().hypot(hs_lo)).exp() } else { 0.0 };
    }
    (low, high)
}

/// `Dofs` from values already in nm and nrad.
fn nm_dofs(v: [f64; 6]) -> Dofs {
    Dofs::from_si(v.map(|x| x * 1e-9))
}
