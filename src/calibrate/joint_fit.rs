//! `kinrepro calibrate --fit` with parameters besides (or instead of) the
//! spread: the joint fit of [`super::joint`] on the model grid of
//! [`super::grid`], and its calibration file.
//!
//! Steps: (1) the grid at the scene's spread (or 0.1 mu0 if it is 0);
//! (2) the joint maximum-likelihood estimate; (3) with the spread fitted,
//! the grid again at the estimated spread, and the estimate again, so that
//! sigma ∝ spread spans only the interval; (4) a direct study at the
//! estimate: the check of grid and linear law (`model.grid.check`) and the
//! pose samples for the information; (5) per parameter the adjusted profile
//! interval, widened in quadrature by the model study's error (on ln s for
//! the spread, linearly for the others); (6) the region points for
//! `predict`; (7) the goodness of fit with p(p + 1)/2 - q degrees of freedom.

use std::collections::BTreeMap;

use nalgebra::{DMatrix, DVector};

use super::error::CalibrateError;
use super::file::{
    CalibrateOptions, Calibration, Correlation, ModelInfo, Parameter, dof_fits, noise_of, observed,
    skeleton,
};
use super::grid::{GridInfo, ModelGrid, StudySpec};
use super::information::{Derived, information};
use super::joint::{End, JointModel, estimate, profile_end, ray_end};
use super::likelihood::{Observed, goodness_of_fit_q};
use super::measurement::Measurement;
use super::params::{Param, with_values};
use crate::assembly::Coupling;

/// The two-sided 90 % normal quantile.
const Z_90: f64 = 1.644_853_626_951_472_2;

/// Calibrate the parameters `params` (sorted, not the spread alone).
pub fn calibrate_joint(
    coupling: &Coupling,
    m: &Measurement,
    opts: &CalibrateOptions,
    params: &[Param],
    point: usize,
) -> Result<Calibration, CalibrateError> {
    let f = coupling.scene.friction;
    let fit_spread = params.contains(&Param::Spread);
    if !fit_spread && f.spread == 0.0 {
        return Err(CalibrateError::Model {
            file: m.file.clone(),
            reason: "the scene's friction spread is 0, so the model has no scatter: \
                     fit the spread too (--fit spread,...)"
                .into(),
        });
    }
    let noise = noise_of(m, opts);
    let noise_var: Vec<f64> = noise.iter().map(|v| v * v).collect();
    let obs = observed(m);
    let spec = StudySpec {
        coupling,
        point,
        dofs: &m.dofs,
        samples: opts.samples,
        seed: opts.seed,
        method: opts.method,
    };
    let s_ref = if f.spread > 0.0 {
        f.spread
    } else {
        0.1 * f.mu_static
    };
    let grid = two_pass_grid(&spec, &obs, params, &noise_var, s_ref)?;
    let jm = JointModel::new(&obs, &grid, params, coupling, &noise_var);
    let (u_hat, l_max) = estimate(&jm);
    if !l_max.is_finite() {
        return Err(singular(m));
    }
    let theta = jm.theta(&u_hat);
    let at_estimate = spec.run(&with_values(coupling, params, &theta))?;
    let fit = fit_at(&jm, &u_hat, l_max, &at_estimate.samples_of(&m.dofs));
    let fitted = jm.sigma(&theta).ok_or_else(|| singular(m))?;
    let s_hat = fitted_spread(params, &theta, f.spread);
    let g_hat = (&fitted - DMatrix::from_diagonal(&DVector::from_column_slice(&noise_var)))
        / (s_hat * s_hat);
    let gof = goodness_of_fit_q(&obs, &fitted, params.len());
    let check = grid_check(&g_hat, &at_estimate.per_unit(&m.dofs));
    let info = model_info(opts, s_ref, &grid, check);
    let mut cal = skeleton(
        coupling,
        m,
        point,
        gof,
        info,
        at_estimate.fingerprint.clone(),
    );
    cal.dofs = dof_fits(m, &noise, &fitted, &g_hat, s_hat);
    cal.parameters = params
        .iter()
        .map(|p| p.name().to_string())
        .zip(fit.parameters)
        .collect();
    let named = |t: &Vec<f64>| params.iter().map(|p| p.name().to_string()).zip(t.clone());
    cal.region = fit.region.iter().map(|t| named(t).collect()).collect();
    cal.correlation = fit.correlation;
    cal.fixed = fixed(coupling, params);
    Ok(cal)
}

/// The model grid over the fitted parameters other than the spread: at
/// `s_ref`, and with the spread fitted again at its first estimate.
fn two_pass_grid(
    spec: &StudySpec,
    obs: &Observed,
    params: &[Param],
    noise_var: &[f64],
    s_ref: f64,
) -> Result<ModelGrid, CalibrateError> {
    let grid_params: Vec<Param> = params
        .iter()
        .copied()
        .filter(|p| *p != Param::Spread)
        .collect();
    let fit_mu = params.contains(&Param::MuStatic);
    let ranges: Vec<(f64, f64)> = grid_params
        .iter()
        .map(|p| p.range(spec.coupling, fit_mu))
        .collect();
    let grid = ModelGrid::build(spec, &grid_params, &ranges, s_ref)?;
    if !params.contains(&Param::Spread) {
        return Ok(grid);
    }
    let jm = JointModel::new(obs, &grid, params, spec.coupling, noise_var);
    let s1 = jm.theta(&estimate(&jm).0)[0];
    ModelGrid::build(spec, &grid_params, &ranges, s1)
}

/// The `model` block of a joint calibration.
fn model_info(opts: &CalibrateOptions, s_ref: f64, grid: &ModelGrid, check: f64) -> ModelInfo {
    ModelInfo {
        solver: opts.method.name().into(),
        sampler: "mc".into(),
        seed: opts.seed,
        samples: opts.samples,
        reference_spread: s_ref,
        linearity: check,
        grid: Some(GridInfo {
            parameters: grid.params.iter().map(|p| p.name().to_string()).collect(),
            nodes: grid.nodes.clone(),
            spread: grid.spread,
            check,
        }),
    }
}

/// The joint fit at the estimate.
#[derive(Debug, Clone, PartialEq)]
pub struct JointFit {
    /// Per fitted parameter (in the model's order): estimate and interval.
    pub parameters: Vec<Parameter>,
    /// The region points (parameter values in the model's order).
    pub region: Vec<Vec<f64>>,
    pub correlation: Option<Correlation>,
}

/// Intervals, correlation and region points at the estimate `u_hat` (unit
/// coordinates, l_max its log-likelihood), `x` the pose samples of the
/// measured DOFs from a model study at the estimate.
pub fn fit_at(jm: &JointModel, u_hat: &[f64], l_max: f64, x: &[Vec<f64>]) -> JointFit {
    let q = jm.params.len();
    let theta = jm.theta(u_hat);
    let derived = information(jm, &theta, x).map_or(
        Derived {
            k: vec![1.0; q],
            model_sd: vec![0.0; q],
            covariance: None,
        },
        |i| i.derived(),
    );
    let (parameters, ends) = intervals(jm, u_hat, l_max, &derived);
    JointFit {
        parameters,
        region: region(jm, u_hat, l_max, &derived, &ends),
        correlation: derived
            .covariance
            .as_ref()
            .map(|v| correlation(&jm.params, v)),
    }
}

fn singular(m: &Measurement) -> CalibrateError {
    CalibrateError::Model {
        file: m.file.clone(),
        reason: "the model covariance of the measured DOFs plus the sensor noise is singular \
                 everywhere in the searched range: give the sensor noise of every measured DOF (--noise)"
            .into(),
    }
}

fn fitted_spread(params: &[Param], theta: &[f64], fixed: f64) -> f64 {
    params
        .iter()
        .position(|p| *p == Param::Spread)
        .map_or(fixed, |i| theta[i])
}

/// Largest relative difference of sigma between the grid's G at the
/// estimate and the direct study's G (both per unit spread^2).
fn grid_check(g_grid: &DMatrix<f64>, g_direct: &DMatrix<f64>) -> f64 {
    (0..g_grid.nrows())
        .map(|j| {
            let (a, b) = (g_grid[(j, j)].sqrt(), g_direct[(j, j)].sqrt());
            if b > 0.0 { (a / b - 1.0).abs() } else { 0.0 }
        })
        .fold(0.0, f64::max)
}

/// The profile interval of every parameter, widened by the model error,
/// and the profile ends (low, high) per parameter.
fn intervals(
    jm: &JointModel,
    u_hat: &[f64],
    l_max: f64,
    d: &Derived,
) -> (Vec<Parameter>, Vec<(End, End)>) {
    let theta = jm.theta(u_hat);
    let mut ends = Vec::new();
    let mut out = Vec::new();
    for (a, p) in jm.params.iter().enumerate() {
        let lo = profile_end(jm, a, d.k[a], u_hat, l_max, -1.0);
        let hi = profile_end(jm, a, d.k[a], u_hat, l_max, 1.0);
        let (r0, r1) = jm.ranges[a];
        let value = |e: &End| {
            if *p == Param::Spread && e.at_bound && e.u == 0.0 {
                0.0
            } else {
                jm.theta(&e.point)[a]
            }
        };
        let (mut low, mut high) = (value(&lo), value(&hi));
        let est = theta[a];
        let h = Z_90 * d.model_sd[a];
        if *p == Param::Spread {
            let hl = h / est;
            if !lo.at_bound {
                low = est * (-(est / low).ln().hypot(hl)).exp();
            }
            if !hi.at_bound {
                high = (est * (high / est).ln().hypot(hl).exp()).min(r1);
            }
        } else {
            if !lo.at_bound {
                low = (est - (est - low).hypot(h)).max(r0);
            }
            if !hi.at_bound {
                high = (est + (high - est).hypot(h)).min(r1);
            }
        }
        // Widening by the model error may also reach a range end.
        let low_at = lo.at_bound || (*p != Param::Spread && low <= r0);
        let high_at = hi.at_bound || high >= r1;
        out.push(Parameter {
            estimate: est,
            low,
            high,
            level: 0.90,
            method: method_text(*p),
            sandwich_factor: d.k[a],
            model_error: if *p == Param::Spread {
                d.model_sd[a] / est
            } else {
                d.model_sd[a]
            },
            low_at_bound: low_at,
            high_at_bound: high_at,
            range: Some([if *p == Param::Spread { 0.0 } else { r0 }, r1]),
            determined: !low_at && !high_at,
        });
        ends.push((lo, hi));
    }
    (out, ends)
}

fn method_text(p: Param) -> String {
    let scale = if p == Param::Spread {
        "on ln s"
    } else {
        "linearly"
    };
    format!(
        "adjusted profile likelihood (the other fitted parameters maximised at each point; \
         k 2 (l_max - l_p) <= chi^2_1(0.90) = 2.7055, k the sandwich factor of this parameter), \
         widened in quadrature {scale} by the model study's sampling error; model covariance \
         interpolated on a common-random-number grid"
    )
}

/// The region points: each profile end (the other parameters at their
/// profile maximum) and both ends of each principal axis of the sandwich
/// covariance (in unit coordinates) where they leave the region
/// min_a k_a 2 (l_max - l) <= chi^2_1(0.90) or the searched box.
fn region(
    jm: &JointModel,
    u_hat: &[f64],
    l_max: f64,
    d: &Derived,
    ends: &[(End, End)],
) -> Vec<Vec<f64>> {
    let mut pts: Vec<Vec<f64>> = ends
        .iter()
        .flat_map(|(lo, hi)| [lo.point.clone(), hi.point.clone()])
        .collect();
    let k = d.k.iter().copied().fold(f64::INFINITY, f64::min);
    if let Some(v) = &d.covariance {
        let theta = jm.theta(u_hat);
        // du/dtheta per parameter (the spread on a log scale).
        let jac: Vec<f64> = (0..theta.len())
            .map(|a| {
                let h = 1e-6 * jm.ranges[a].1;
                (jm.unit(a, theta[a] + h) - jm.unit(a, theta[a] - h)) / (2.0 * h)
            })
            .collect();
        let vu = DMatrix::from_fn(v.nrows(), v.ncols(), |a, b| jac[a] * v[(a, b)] * jac[b]);
        let eig = vu.symmetric_eigen();
        for c in 0..eig.eigenvectors.ncols() {
            let e: Vec<f64> = eig.eigenvectors.column(c).iter().copied().collect();
            if e.iter().all(|x| x.is_finite()) {
                let neg: Vec<f64> = e.iter().map(|x| -x).collect();
                pts.push(ray_end(jm, u_hat, &e, k, l_max));
                pts.push(ray_end(jm, u_hat, &neg, k, l_max));
            }
        }
    }
    pts.iter().map(|u| jm.theta(u)).collect()
}

fn correlation(params: &[Param], v: &DMatrix<f64>) -> Correlation {
    let q = params.len();
    Correlation {
        parameters: params.iter().map(|p| p.name().to_string()).collect(),
        matrix: (0..q)
            .map(|a| {
                (0..q)
                    .map(|b| v[(a, b)] / (v[(a, a)] * v[(b, b)]).sqrt())
                    .collect()
            })
            .collect(),
    }
}

/// The parameters not fitted, at the scene's values.
fn fixed(coupling: &Coupling, params: &[Param]) -> BTreeMap<String, f64> {
    [
        Param::Spread,
        Param::MuStatic,
        Param::DynamicRatio,
        Param::SupportCompliance,
    ]
    .into_iter()
    .filter(|p| !params.contains(p))
    .map(|p| (p.name().to_string(), p.value(coupling)))
    .collect()
}
