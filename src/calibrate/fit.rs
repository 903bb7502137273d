//! `kinrepro calibrate --fit`: the fit of one or several parameters (the
//! spread alone is the case of one parameter and a grid of no node
//! parameters) and its calibration file.
//!
//! Steps: (1) the model grid ([`super::grid`]) over the fitted parameters
//! other than the spread, at the scene's spread (or 0.1 mu0 if it is 0):
//! the reference; (2) the maximum-likelihood estimate ([`super::joint`]);
//! (3) with the spread fitted, the grid again at the estimated spread, and
//! the estimate again, so that sigma ∝ spread spans only the interval;
//! (4) a direct study at the estimate: the check of grid and linear law
//! (`model.grid.check`, with the region points of step 6 too), the change of sigma / spread from the reference
//! (`model.linearity`) and the pose samples for the information; (5) per
//! parameter the adjusted profile interval, widened in quadrature by the
//! model study's error (on ln s for the spread, linearly for the others);
//! (6) the region points for `predict`; (7) the goodness of fit with
//! p(p + 1)/2 - q degrees of freedom.

use std::collections::BTreeMap;

use nalgebra::{DMatrix, DVector};

use super::error::CalibrateError;
pub use super::file::{
    CalibrateOptions, Calibration, Correlation, DofFit, ModelInfo, Parameter, dof_fits, noise_of,
    observed, point_index, skeleton,
};
use super::grid::{GridInfo, ModelGrid};
use super::information::{Derived, information};
use super::joint::{End, JointModel, estimate, profile_end, ray_end};
use super::likelihood::{LEVEL, Observed, goodness_of_fit, wilks_threshold};
use super::measurement::Measurement;
use super::model::StudySpec;
use super::params::{Param, parse_fit, with_values};
use crate::assembly::Coupling;
use crate::param::Param as Arg;
use crate::scene::{MuDistribution, Scene};
use crate::study::stats::quantile::normal_quantile;
use crate::study::{StudyOptions, StudyPlan, Variant};

/// A calibration's friction model: independent coefficients, one
/// mu_static and one scale at every contact (the spread of a uniform
/// distribution, the sd of a normal or lognormal one); a scene with per
/// contact values, a correlation or empirical values is refused, saying
/// which (`fit` and `predict`).
pub(crate) fn one_friction_scale(scene: &Scene) -> Result<(), CalibrateError> {
    let refuse = |reason: String| Err(CalibrateError::Model { file: scene.file.clone(), reason });
    if scene.contact_friction.is_some() {
        return refuse(
            "[friction] gives mu_static or spread per contact; a calibration fits one \
             mu_static and one spread for every contact: give them as numbers"
                .to_string(),
        );
    }
    if scene.mu_correlation > 0.0 {
        return refuse(format!(
            "[friction] correlation = {}; a calibration fits the spread of independent \
             coefficients: leave correlation out",
            scene.mu_correlation
        ));
    }
    match &scene.mu_distribution {
        MuDistribution::Empirical { .. } => refuse(
            "[friction] distribution = \"empirical\": measured values have no parameter to \
             fit; give distribution = \"uniform\" (fits spread) or \"normal\" or \
             \"lognormal\" (fits sd)"
                .to_string(),
        ),
        MuDistribution::Normal { sd } | MuDistribution::Lognormal { sd }
            if sd.iter().any(|s| *s != sd[0]) =>
        {
            refuse(
                "[friction] sd differs between contacts; a calibration fits one sd for every \
                 contact: give sd as a number"
                    .to_string(),
            )
        }
        _ => Ok(()),
    }
}

/// The parameters `fit` names for `scene` (empty: the scale of its
/// friction distribution, `spread` or `sd`); a scale parameter of another
/// distribution is refused, naming the scene's.
fn fit_for(scene: &Scene, fit: &[String]) -> Result<Vec<Param>, CalibrateError> {
    let scale = Param::scale_of(scene);
    let params = if fit.is_empty() { vec![scale] } else { parse_fit(fit)? };
    match params.iter().find(|p| !p.applies_to(scene)) {
        Some(p) => Err(CalibrateError::Model {
            file: scene.file.clone(),
            reason: format!(
                "`{}` is the scale of another friction distribution: this scene's is {} \
                 ([friction] distribution), whose scale is `{}`: fit that ({})",
                p.name(),
                scene.mu_distribution.name(),
                scale.name(),
                Arg::Fit.with(scale.name())
            ),
        }),
        None => Ok(params),
    }
}

/// Calibrate the parameters `opts.fit` of `scene` (assembled as
/// `coupling`) on measurement `m`.
pub fn calibrate(
    scene: &Scene,
    coupling: &Coupling,
    m: &Measurement,
    opts: &CalibrateOptions,
) -> Result<Calibration, CalibrateError> {
    one_friction_scale(scene)?;
    let params = fit_for(scene, &opts.fit)?;
    let point_name = opts.point.as_deref().or(m.point.as_deref());
    let point = point_index(scene, point_name, &m.file)?;
    let f = scene.friction;
    let scale = Param::scale_of(scene);
    let fit_scale = params.iter().any(|p| p.is_scale());
    if !fit_scale && scene.mu_scale() == 0.0 {
        return Err(CalibrateError::Model {
            file: m.file.clone(),
            reason: format!(
                "the scene's friction {0} is 0, so the model has no scatter: fit the {0} too ({1})",
                scale.name(),
                Arg::Fit.with(format!("{},...", scale.name()))
            ),
        });
    }
    let noise = noise_of(m, opts);
    let noise_var: Vec<f64> = noise.iter().map(|v| v * v).collect();
    let obs = observed(m);
    let models = StudyOptions::monte_carlo(opts.samples, opts.seed, opts.solver);
    let plan = StudyPlan::keeping_records(vec![(scene.clone(), coupling.clone())], &models)?;
    let spec = StudySpec { plan: &plan, point, dofs: &m.dofs };
    let base: &Variant = spec.base();
    let s_ref = if scene.mu_scale() > 0.0 { scene.mu_scale() } else { 0.1 * f.mu_static };
    let (reference, grid) = two_pass_grid(&spec, &obs, &params, &noise_var, s_ref)?;
    let grid = grid.as_ref().unwrap_or(&reference);
    let jm = JointModel::new(&obs, grid, &params, base, &noise_var);
    let (u_hat, l_max) = estimate(&jm);
    if !l_max.is_finite() {
        return Err(singular(m));
    }
    let theta = jm.theta(&u_hat);
    let at_estimate = spec.run(&with_values(base, &params, &theta))?;
    let fit = fit_at(&jm, &u_hat, l_max, &at_estimate.samples_of(&m.dofs));
    let fitted = jm.sigma(&theta).ok_or_else(|| singular(m))?;
    let s_hat = jm.spread(&theta);
    let g_hat = per_unit_model(&fitted, &noise_var, s_hat);
    let gof = goodness_of_fit(&obs, &fitted, params.len());
    let direct = at_estimate.per_unit(&m.dofs);
    let phi_hat = jm.phi(&theta);
    let linearity = sigma_difference(&reference.at(&phi_hat), &direct);
    let mut check = sigma_difference(&g_hat, &direct);
    if !grid.params.is_empty() {
        check = check.max(region_check(&spec, &jm, &params, &fit.region, &noise_var)?);
    }
    let info = model_info(&spec, s_ref, grid, linearity, check);
    let mut cal = skeleton(scene, m, point, gof, info, at_estimate.fingerprint.clone());
    cal.dofs = dof_fits(m, &noise, &fitted, &g_hat, s_hat);
    let names = || params.iter().map(|p| p.name().to_string());
    cal.region = fit.region.iter().map(|t| names().zip(t.clone()).collect()).collect();
    cal.parameters = names().zip(fit.parameters).collect();
    cal.correlation = fit.correlation;
    cal.fixed = fixed(base, &params);
    Ok(cal)
}

/// The model grid over the fitted parameters other than the spread at
/// `s_ref` (the reference), and with the spread fitted the grid again at
/// the first estimate of the spread.
fn two_pass_grid(
    spec: &StudySpec,
    obs: &Observed,
    params: &[Param],
    noise_var: &[f64],
    s_ref: f64,
) -> Result<(ModelGrid, Option<ModelGrid>), CalibrateError> {
    let grid_params: Vec<Param> = params.iter().copied().filter(|p| !p.is_scale()).collect();
    let fit_mu = params.contains(&Param::MuStatic);
    let ranges: Vec<(f64, f64)> =
        grid_params.iter().map(|p| p.range(spec.base(), fit_mu)).collect();
    let reference = ModelGrid::build(spec, &grid_params, &ranges, s_ref)?;
    if !params.iter().any(|p| p.is_scale()) {
        return Ok((reference, None));
    }
    let jm = JointModel::new(obs, &reference, params, spec.base(), noise_var);
    let s1 = jm.theta(&estimate(&jm).0)[0];
    let grid = ModelGrid::build(spec, &grid_params, &ranges, s1)?;
    Ok((reference, Some(grid)))
}

/// The `model` block: the grid if there are grid parameters.
fn model_info(
    spec: &StudySpec,
    s_ref: f64,
    grid: &ModelGrid,
    linearity: f64,
    check: f64,
) -> ModelInfo {
    let design = spec.base().design;
    ModelInfo {
        solver: spec.plan.method().name().into(),
        sampler: "mc".into(),
        seed: design.seed,
        samples: design.n,
        scale: Param::scale_of(&spec.base().scene).name().into(),
        reference_spread: s_ref,
        linearity,
        grid: (!grid.params.is_empty()).then(|| GridInfo {
            parameters: grid.params.iter().map(|p| p.name().to_string()).collect(),
            nodes: grid.nodes.clone(),
            spread: grid.spread,
            check,
        }),
    }
}

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
    let derived = information(jm, &theta, x).map_or(Derived::unadjusted(q), |i| i.derived());
    let (parameters, ends) = intervals(jm, u_hat, l_max, &derived);
    JointFit {
        region: region(jm, u_hat, l_max, &derived, &ends, &parameters),
        parameters,
        correlation: derived.covariance.as_ref().map(|v| correlation(&jm.params, v)),
    }
}

fn singular(m: &Measurement) -> CalibrateError {
    CalibrateError::Model {
        file: m.file.clone(),
        reason: "the model covariance of the measured DOFs plus the sensor noise is singular \
                 everywhere in the searched range: give the sensor noise of every measured DOF ("
            .to_string()
            + &format!("{})", Arg::Noise),
    }
}

/// The model covariance per unit spread^2, (Sigma - N) / s^2, of the
/// model's Sigma (noise N on the diagonal) at spread `s`.
fn per_unit_model(sigma: &DMatrix<f64>, noise_var: &[f64], s: f64) -> DMatrix<f64> {
    (sigma - DMatrix::from_diagonal(&DVector::from_column_slice(noise_var))) / (s * s)
}

/// The grid's check at the region points: the largest relative sigma
/// difference between the interpolated grid (scaled by s^2) and a direct
/// study at each point. The intervals are read off the grid, so where the
/// model changes regime between nodes (a contact that begins to stick as
/// mu_static rises) this shows how far the grid strays there, not only at
/// the estimate.
fn region_check(
    spec: &StudySpec,
    jm: &JointModel,
    params: &[Param],
    region: &[Vec<f64>],
    noise_var: &[f64],
) -> Result<f64, CalibrateError> {
    let mut worst = 0.0f64;
    for theta in region {
        let Some(sigma) = jm.sigma(theta) else {
            continue;
        };
        let model = per_unit_model(&sigma, noise_var, jm.spread(theta));
        let direct = spec.run(&with_values(spec.base(), params, theta))?;
        worst = worst.max(sigma_difference(&model, &direct.per_unit(spec.dofs)));
    }
    Ok(worst)
}

/// Largest relative difference of sigma between two model covariances per
/// unit spread^2 (`b` the direct study's).
fn sigma_difference(a: &DMatrix<f64>, b: &DMatrix<f64>) -> f64 {
    (0..a.nrows())
        .map(|j| {
            let (x, y) = (a[(j, j)].sqrt(), b[(j, j)].sqrt());
            if y > 0.0 { (x / y - 1.0).abs() } else { 0.0 }
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
    // The two-sided normal quantile of the level (1.645 at 90 %).
    let z = normal_quantile(0.5 + 0.5 * LEVEL).expect("level in (0, 1)");
    let mut ends = Vec::new();
    let mut out = Vec::new();
    for (a, p) in jm.params.iter().enumerate() {
        let lo = profile_end(jm, a, d.k[a], u_hat, l_max, -1.0);
        let hi = profile_end(jm, a, d.k[a], u_hat, l_max, 1.0);
        let (r0, r1) = jm.ranges[a];
        let spread = p.is_scale();
        let value = |e: &End| {
            if spread && e.at_bound && e.u == 0.0 { 0.0 } else { jm.theta(&e.point)[a] }
        };
        let est = theta[a];
        // The model error widens the interval in quadrature: on ln s for
        // the spread (its model_error is the sd of ln s), linearly otherwise.
        let f = |x: f64| if spread { x.ln() } else { x };
        let f_inv = |x: f64| if spread { x.exp() } else { x };
        let model_error = d.model_sd[a] / if spread { est } else { 1.0 };
        let widen = |end: &End, dir: f64| {
            let v = value(end);
            let h = (f(v) - f(est)).abs().hypot(z * model_error);
            if end.at_bound { v } else { f_inv(f(est) + dir * h) }
        };
        let (low, high) = (widen(&lo, -1.0).max(r0), widen(&hi, 1.0).min(r1));
        // Widening by the model error may also reach a range end.
        let low_at = lo.at_bound || low <= r0;
        let high_at = hi.at_bound || high >= r1;
        out.push(Parameter {
            estimate: est,
            low,
            high,
            level: LEVEL,
            method: method_text(*p, jm),
            sandwich_factor: d.k[a],
            model_error,
            low_at_bound: low_at,
            high_at_bound: high_at,
            range: Some([r0, r1]),
            determined: !low_at && !high_at,
        });
        ends.push((lo, hi));
    }
    (out, ends)
}

/// How parameter `p`'s interval was found.
fn method_text(p: Param, jm: &JointModel) -> String {
    let chi2 = wilks_threshold();
    let rule = if jm.params.len() > 1 {
        format!(
            "the other fitted parameters maximised at each point; k 2 (l_max - l_p) <= \
             chi^2_1(0.90) = {chi2:.4}, k the sandwich factor of this parameter"
        )
    } else {
        format!("k 2 (l_max - l) <= chi^2_1(0.90) = {chi2:.4}, k the sandwich factor")
    };
    let scale = if p.is_scale() { "on ln s" } else { "linearly" };
    let grid = if jm.grid.params.is_empty() {
        ""
    } else {
        "; model covariance interpolated on a common-random-number grid"
    };
    format!(
        "adjusted profile likelihood ({rule}), widened in quadrature {scale} by the model \
         study's sampling error{grid}"
    )
}

/// The region points: each profile end (the other parameters at their
/// profile maximum, the parameter itself at its interval's end, so that the
/// model error's widening is carried) and, for several parameters, both
/// ends of each principal axis of the sandwich covariance (in unit
/// coordinates) where they leave the region min_a k_a 2 (l_max - l) <=
/// chi^2_1(0.90) or the searched box. For one parameter that axis is the
/// parameter itself, whose ends are the interval's.
fn region(
    jm: &JointModel,
    u_hat: &[f64],
    l_max: f64,
    d: &Derived,
    ends: &[(End, End)],
    parameters: &[Parameter],
) -> Vec<Vec<f64>> {
    let mut pts: Vec<Vec<f64>> = Vec::new();
    for (a, ((lo, hi), p)) in ends.iter().zip(parameters).enumerate() {
        for (e, v) in [(lo, p.low), (hi, p.high)] {
            let mut t = jm.theta(&e.point);
            t[a] = v;
            pts.push(t);
        }
    }
    let k = d.k.iter().copied().fold(f64::INFINITY, f64::min);
    let Some(v) = d.covariance.as_ref().filter(|_| jm.params.len() > 1) else {
        return pts;
    };
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
            pts.push(jm.theta(&ray_end(jm, u_hat, &e, k, l_max)));
            pts.push(jm.theta(&ray_end(jm, u_hat, &neg, k, l_max)));
        }
    }
    pts
}

fn correlation(params: &[Param], v: &DMatrix<f64>) -> Correlation {
    let q = params.len();
    Correlation {
        parameters: params.iter().map(|p| p.name().to_string()).collect(),
        matrix: (0..q)
            .map(|a| (0..q).map(|b| v[(a, b)] / (v[(a, a)] * v[(b, b)]).sqrt()).collect())
            .collect(),
    }
}

/// The parameters not fitted, at the scene's values.
fn fixed(v: &Variant, params: &[Param]) -> BTreeMap<String, f64> {
    Param::ALL
        .into_iter()
        .filter(|p| !params.contains(p) && p.applies_to(&v.scene))
        .map(|p| (p.name().to_string(), p.value(v)))
        .collect()
}
