//! `kinrepro calibrate`: fit the friction spread of a scene to a measured
//! scatter and write the calibration file (docs/measurements.md).
//!
//! Steps: (1) the model covariance G per unit spread^2 from a Monte Carlo
//! study at the scene's spread (the reference); (2) the maximum-likelihood
//! spread under Sigma(s) = s^2 G + N (`likelihood`); (3) a second study at
//! that estimate with the same design rows, G taken from it, and the fit
//! repeated, so that the linear scaling is only used across the interval
//! and not from the reference to the estimate; the change of G between the
//! two studies is reported as `model.linearity`; (4) the goodness of fit.

use std::collections::BTreeMap;

use nalgebra::DMatrix;
use serde::{Deserialize, Serialize};

use super::error::CalibrateError;
use super::likelihood::{
    GOF_THRESHOLD, Observed, SpreadFit, fit_spread, goodness_of_fit, model_covariance,
    model_error_sd, sandwich_factor,
};
use super::measurement::{MeasuredData, Measurement};
use super::model::ModelStudy;
use super::units::{DOFS, si_unit};
use crate::assembly::Coupling;
use crate::report::provenance::{Fingerprint, VERSION, fnv1a64};
use crate::solve::Method;

/// Version of the calibration file's schema (docs/measurements.md).
pub const CALIBRATION_SCHEMA_VERSION: u32 = 1;

/// The parameters `--fit` may name.
pub const PARAMETERS: [&str; 4] = ["spread", "mu_static", "dynamic_ratio", "support_compliance"];

/// How to calibrate.
#[derive(Debug, Clone, PartialEq)]
pub struct CalibrateOptions {
    /// Parameters to fit (only "spread" is supported).
    pub fit: Vec<String>,
    /// Sensor noise per DOF [SI], overriding the file's `# noise:`.
    pub noise: [Option<f64>; 6],
    /// Evaluation point (overrides the file's `point` column).
    pub point: Option<String>,
    pub samples: usize,
    pub seed: u64,
    pub method: Method,
}

/// One fitted parameter.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Parameter {
    pub estimate: f64,
    pub low: f64,
    pub high: f64,
    pub level: f64,
    pub method: String,
    /// Sandwich factor k of the adjusted likelihood ratio (1: normal scatter).
    pub sandwich_factor: f64,
    /// Standard deviation of ln(estimate) due to the finite model study,
    /// added to the interval in quadrature on ln s.
    pub model_error: f64,
    /// The interval reached the end of the admissible range (0 or mu_static).
    pub low_at_bound: bool,
    pub high_at_bound: bool,
}

/// The goodness-of-fit block.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct GoodnessOfFitReport {
    pub statistic: Option<f64>,
    pub df: usize,
    pub p_value: Option<f64>,
    pub ok: bool,
    pub threshold: f64,
    pub test: String,
}

/// Measured against fitted sigma of one DOF [SI].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DofFit {
    pub dof: String,
    pub unit: String,
    pub cycles: usize,
    pub measured_sigma: f64,
    pub noise_sigma: f64,
    /// Model plus noise at the estimate: sqrt(Sigma_jj).
    pub fitted_sigma: f64,
    /// The coupling's own scatter at the estimate (no sensor noise).
    pub model_sigma: f64,
}

/// The model studies behind the fit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ModelInfo {
    pub solver: String,
    pub sampler: String,
    pub seed: u64,
    pub samples: usize,
    pub reference_spread: f64,
    /// Largest relative change over the six DOFs of sigma / spread between
    /// the reference study and the study at the estimate.
    pub linearity: f64,
}

/// The calibration file.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Calibration {
    pub schema_version: u32,
    pub kind: String,
    pub kinrepro_version: String,
    pub scene: String,
    pub scene_name: String,
    /// FNV-1a hash of the resolved scene without file, spread and study
    /// settings: `predict` recognises the calibrated design by it.
    pub scene_content: String,
    pub point: String,
    pub measured_file: String,
    /// `cycles` or `summary`.
    pub data: String,
    pub metadata: BTreeMap<String, String>,
    pub parameters: BTreeMap<String, Parameter>,
    /// The friction settings held at the scene's values.
    pub fixed: BTreeMap<String, f64>,
    pub goodness_of_fit: GoodnessOfFitReport,
    pub dofs: Vec<DofFit>,
    pub model: ModelInfo,
    pub fingerprint: Fingerprint,
}

/// Hash of a scene that ignores its file, spread and study defaults.
pub fn design_hash(coupling: &Coupling) -> String {
    let s = &coupling.scene;
    let mut f = s.friction;
    f.spread = 0.0;
    let text = format!(
        "{:?}{:?}{:?}{:?}{:?}{:?}{:?}",
        s.balls, s.surfaces, s.preload, f, s.evaluation_points, s.dynamics, s.variation
    );
    format!("{:016x}", fnv1a64(text.as_bytes()))
}

/// Check `--fit`: only `spread`.
pub fn check_fit(fit: &[String]) -> Result<(), CalibrateError> {
    for f in fit {
        if !PARAMETERS.contains(&f.as_str()) {
            return Err(CalibrateError::UnknownParameter(f.clone()));
        }
        if f != "spread" {
            return Err(CalibrateError::NotSupported(f.clone()));
        }
    }
    if fit.is_empty() {
        return Err(CalibrateError::UnknownParameter(String::new()));
    }
    Ok(())
}

/// Index of the evaluation point `name` (None: the first).
pub fn point_index(
    coupling: &Coupling,
    name: Option<&str>,
    file: &str,
) -> Result<usize, CalibrateError> {
    let pts = &coupling.scene.evaluation_points;
    match name {
        None => Ok(0),
        Some(n) => pts
            .iter()
            .position(|p| p.name == n)
            .ok_or_else(|| CalibrateError::Point {
                file: file.to_string(),
                point: n.to_string(),
                have: pts
                    .iter()
                    .map(|p| format!("`{}`", p.name))
                    .collect::<Vec<_>>()
                    .join(", "),
            }),
    }
}

/// The observation in the measurement's DOF order.
pub fn observed(m: &Measurement) -> Observed {
    match &m.data {
        MeasuredData::Cycles(rows) => Observed::Covariance {
            s: m.covariance().unwrap_or_else(|| DMatrix::zeros(0, 0)),
            n: rows.len(),
        },
        MeasuredData::Summary { sigma, cycles } => Observed::Sigmas {
            sigma: sigma.clone(),
            cycles: cycles.clone(),
        },
    }
}

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

/// Calibrate the scene's friction spread on measurement `m`.
pub fn calibrate(
    coupling: &Coupling,
    m: &Measurement,
    opts: &CalibrateOptions,
) -> Result<Calibration, CalibrateError> {
    check_fit(&opts.fit)?;
    let point_name = opts.point.as_deref().or(m.point.as_deref());
    let point = point_index(coupling, point_name, &m.file)?;
    let noise: Vec<f64> = m
        .dofs
        .iter()
        .map(|&d| opts.noise[d].or(m.noise[d]).unwrap_or(0.0))
        .collect();
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
    let linearity = linearity(&reference, &at_estimate);
    let dofs = dof_fits(m, &noise, &fitted, &g, fit.estimate);
    let parameter = parameter(&fit);
    Ok(Calibration {
        schema_version: CALIBRATION_SCHEMA_VERSION,
        kind: "calibration".into(),
        kinrepro_version: VERSION.into(),
        scene: coupling.scene.file.clone(),
        scene_name: coupling.scene.name.clone(),
        scene_content: design_hash(coupling),
        point: coupling.scene.evaluation_points[point].name.clone(),
        measured_file: m.file.clone(),
        data: match m.data {
            MeasuredData::Cycles(_) => "cycles",
            MeasuredData::Summary { .. } => "summary",
        }
        .into(),
        metadata: m.metadata.iter().cloned().collect(),
        parameters: BTreeMap::from([("spread".to_string(), parameter)]),
        fixed: BTreeMap::from([
            ("mu_static".to_string(), f.mu_static),
            ("dynamic_ratio".to_string(), f.dynamic_ratio),
        ]),
        goodness_of_fit: GoodnessOfFitReport {
            statistic: gof.statistic,
            df: gof.df,
            p_value: gof.p_value,
            ok: gof.ok,
            threshold: GOF_THRESHOLD,
            test: gof.test,
        },
        dofs,
        model: ModelInfo {
            solver: opts.method.name().into(),
            sampler: "mc".into(),
            seed: opts.seed,
            samples: opts.samples,
            reference_spread: s_ref,
            linearity,
        },
        fingerprint: at_estimate.fingerprint,
    })
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

/// Measured against fitted sigma per measured DOF.
fn dof_fits(
    m: &Measurement,
    noise: &[f64],
    fitted: &DMatrix<f64>,
    g: &DMatrix<f64>,
    estimate: f64,
) -> Vec<DofFit> {
    let measured = m.sigma();
    let cycles = m.cycles();
    m.dofs
        .iter()
        .enumerate()
        .map(|(j, &d)| DofFit {
            dof: DOFS[d].into(),
            unit: si_unit(d).into(),
            cycles: cycles[j],
            measured_sigma: measured[j],
            noise_sigma: noise[j],
            fitted_sigma: fitted[(j, j)].sqrt(),
            model_sigma: estimate * g[(j, j)].sqrt(),
        })
        .collect()
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
    }
}

impl Calibration {
    /// Parse a calibration file's text.
    pub fn parse(text: &str, file: &str) -> Result<Self, CalibrateError> {
        let bad = |reason: String| CalibrateError::Calibration {
            file: file.into(),
            reason,
        };
        let c: Calibration = serde_json::from_str(text).map_err(|e| bad(e.to_string()))?;
        if c.kind != "calibration" || c.schema_version != CALIBRATION_SCHEMA_VERSION {
            return Err(bad(format!(
                "kind `{}` schema {} (need kind `calibration`, schema {CALIBRATION_SCHEMA_VERSION})",
                c.kind, c.schema_version
            )));
        }
        if !c.parameters.contains_key("spread") {
            return Err(bad("no `spread` in `parameters`".into()));
        }
        Ok(c)
    }

    /// The calibrated spread.
    pub fn spread(&self) -> &Parameter {
        &self.parameters["spread"]
    }
}
