//! `kinrepro calibrate`: fit the friction spread of a scene alone to a measured
//! scatter (several parameters: `joint_fit`) and build the calibration file.
//!
//! Steps: (1) the model covariance G per unit spread^2 from a Monte Carlo
//! study at the scene's spread (the reference); (2) the maximum-likelihood
//! spread under Sigma(s) = s^2 G + N (`likelihood`); (3) a second study at
//! that estimate with the same design rows, G taken from it, and the fit
//! repeated, so that the linear scaling is only used across the interval
//! and not from the reference to the estimate; the change of G between the
//! two studies is reported as `model.linearity`; (4) the goodness of fit.

use std::collections::BTreeMap;

use super::error::CalibrateError;
pub use super::file::{
    CALIBRATION_SCHEMA_VERSION, CalibrateOptions, Calibration, Correlation, DofFit,
    GoodnessOfFitReport, ModelInfo, PARAMETERS, Parameter, READABLE_SCHEMA_VERSIONS, design_hash,
    dof_fits, noise_of, observed, point_index, skeleton,
};
use super::likelihood::{
    SpreadFit, fit_spread, goodness_of_fit, model_covariance, model_error_sd, sandwich_factor,
};
use super::measurement::Measurement;
use super::model::ModelStudy;
use super::params::{Param, parse_fit};
use crate::assembly::Coupling;

/// Fit with the model covariance of `model`; an error if the model
/// covariance plus noise is singular.
pub fn fit_with(
    m: &Measurement,
    model: &ModelStudy,
    noise_var: &[f64],
    s_max: f64,
) -> Result<SpreadFit, CalibrateError> {
    let obs = observed(m);
    let g = model.per_unit(&m.dofs);
    let x = model.samples_of(&m.dofs);
    let k = |s: f64| sandwich_factor(&obs, &g, noise_var, s, &x, model.spread);
    let mut fit =
        fit_spread(&obs, &g, noise_var, s_max, &k).ok_or_else(|| CalibrateError::Model {
            file: m.file.clone(),
            reason: "the model covariance of the measured DOFs plus the sensor noise is singular: \
                 give the sensor noise of every measured DOF (--noise)"
                .into(),
        })?;
    // Carry the model study's own sampling error: widen in quadrature on ln s.
    fit.model_error = model_error_sd(&obs, &g, noise_var, fit.estimate, &x);
    let h = Z_90 * fit.model_error;
    if !fit.low_at_bound {
        fit.low = fit.estimate * (-(fit.estimate / fit.low).ln().hypot(h)).exp();
    }
    if !fit.high_at_bound {
        fit.high = (fit.estimate * (fit.high / fit.estimate).ln().hypot(h).exp()).min(s_max);
    }
    Ok(fit)
}

/// The two-sided 90 % normal quantile, 1.6449.
const Z_90: f64 = 1.644_853_626_951_472_2;

/// Calibrate the parameters `opts.fit` of the scene on measurement `m`:
/// the spread alone here, several in [`super::joint_fit`].
pub fn calibrate(
    coupling: &Coupling,
    m: &Measurement,
    opts: &CalibrateOptions,
) -> Result<Calibration, CalibrateError> {
    let params = parse_fit(&opts.fit)?;
    let point_name = opts.point.as_deref().or(m.point.as_deref());
    let point = point_index(coupling, point_name, &m.file)?;
    if params != [Param::Spread] {
        return super::joint_fit::calibrate_joint(coupling, m, opts, &params, point);
    }
    let noise = noise_of(m, opts);
    let noise_var: Vec<f64> = noise.iter().map(|v| v * v).collect();
    let f = &coupling.scene.friction;
    let s_max = f.mu_static;
    let s_ref = if f.spread > 0.0 {
        f.spread
    } else {
        0.1 * f.mu_static
    };
    let run = |s| ModelStudy::run(coupling, point, s, opts.samples, opts.seed, opts.method);
    let reference = run(s_ref)?;
    let first = fit_with(m, &reference, &noise_var, s_max)?;
    let at_estimate = run(first.estimate)?;
    let fit = fit_with(m, &at_estimate, &noise_var, s_max)?;
    let g = at_estimate.per_unit(&m.dofs);
    let fitted = model_covariance(&g, &noise_var, fit.estimate);
    let gof = goodness_of_fit(&observed(m), &fitted);
    let model = ModelInfo {
        solver: opts.method.name().into(),
        sampler: "mc".into(),
        seed: opts.seed,
        samples: opts.samples,
        reference_spread: s_ref,
        linearity: linearity(&reference, &at_estimate),
        grid: None,
    };
    let mut cal = skeleton(coupling, m, point, gof, model, at_estimate.fingerprint);
    cal.dofs = dof_fits(m, &noise, &fitted, &g, fit.estimate);
    let mut parameter = parameter(&fit);
    parameter.range = Some([0.0, s_max]);
    cal.region = [(fit.low > 0.0).then_some(fit.low), Some(fit.high)]
        .into_iter()
        .flatten()
        .map(|v| BTreeMap::from([("spread".to_string(), v)]))
        .collect();
    cal.parameters = BTreeMap::from([("spread".to_string(), parameter)]);
    cal.correlation = Some(Correlation {
        parameters: vec!["spread".into()],
        matrix: vec![vec![1.0]],
    });
    cal.fixed = BTreeMap::from([
        ("mu_static".to_string(), f.mu_static),
        ("dynamic_ratio".to_string(), f.dynamic_ratio),
        (
            "support_compliance".to_string(),
            Param::SupportCompliance.value(coupling),
        ),
    ]);
    Ok(cal)
}

/// Largest relative change of sigma / spread over the six DOFs between two model studies.
fn linearity(a: &ModelStudy, b: &ModelStudy) -> f64 {
    (0..6)
        .map(|j| {
            let x = a.cov[(j, j)].sqrt() / a.spread;
            let y = b.cov[(j, j)].sqrt() / b.spread;
            if x > 0.0 { (y / x - 1.0).abs() } else { 0.0 }
        })
        .fold(0.0, f64::max)
}

/// The spread's entry of `parameters`.
fn parameter(fit: &SpreadFit) -> Parameter {
    Parameter {
        estimate: fit.estimate,
        low: fit.low,
        high: fit.high,
        level: fit.level,
        method: "adjusted profile likelihood (k 2 (l_max - l) <= chi^2_1(0.90) = 2.7055, \
                 k the sandwich factor), widened in quadrature on ln s by the model study's \
                 sampling error"
            .into(),
        sandwich_factor: fit.sandwich,
        model_error: fit.model_error,
        low_at_bound: fit.low_at_bound,
        high_at_bound: fit.high_at_bound,
        range: None,
        determined: !fit.low_at_bound && !fit.high_at_bound,
    }
}
