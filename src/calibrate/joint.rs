//! The likelihood of the fitted parameters theta (any of the spread s and
//! mu_static, dynamic_ratio, support_compliance, phi; the spread alone is
//! the case of one parameter and no phi): Sigma(theta) = s^2 G(phi) + N
//! with G(phi) from the model grid ([`super::grid`]) and the Wishart /
//! chi-square likelihood of [`super::likelihood::log_likelihood`].
//!
//! * Estimate: the maximum of l over the searched box (a coarse grid, then
//!   Nelder-Mead), with spread <= mu_static.
//! * Interval of each parameter: the profile likelihood l_p(v) = max of l
//!   over the other parameters at theta_a = v, and the adjusted Wilks
//!   interval {v : k_a 2 (l_max - l_p(v)) <= chi^2_1(0.90)}. For a scalar
//!   parameter of interest among nuisance parameters the adjusted profile
//!   likelihood ratio k_a 2 (l_max - l_p) is asymptotically chi^2_1 with
//!   k_a = (H^-1)_aa / (H^-1 J H^-1)_aa (Chandler & Bate 2007, Biometrika 94,
//!   167, §3), H the information the Wishart law assumes and J the true
//!   variance of the score (from the pose samples' fourth moments, see
//!   [`super::information`]); for one parameter k = H / J.
//! * Where the profile stays below the threshold up to an end of the range,
//!   the interval ends there and is flagged: the data do not determine it.

use nalgebra::DMatrix;

use super::grid::ModelGrid;
use super::likelihood::{Observed, log_likelihood, model_covariance, wilks_threshold};
use super::params::{Param, admissible};
use crate::contact::quadrature::golden_max;

/// Lower end of the searched spread relative to its upper end (the spread
/// is searched on a log scale, from S_MIN_REL s_max to s_max).
pub const S_MIN_REL: f64 = 1e-4;

/// The likelihood of theta for one observation.
pub struct JointModel<'a> {
    pub obs: &'a Observed,
    pub grid: &'a ModelGrid,
    /// The fitted parameters (sorted: the spread first if fitted).
    pub params: Vec<Param>,
    /// Searched range per fitted parameter.
    pub ranges: Vec<(f64, f64)>,
    /// The scale parameter of the scene's distribution (spread or sd).
    pub scale: Param,
    /// The scale and mu_static where they are not fitted.
    pub spread_fixed: f64,
    pub mu_fixed: f64,
    pub noise_var: Vec<f64>,
}

impl<'a> JointModel<'a> {
    /// The model of `params` (sorted) on `grid` for the scene `v`: the
    /// searched ranges from [`Param::range`], the spread and mu_static from
    /// the scene where they are not fitted.
    pub fn new(
        obs: &'a Observed,
        grid: &'a ModelGrid,
        params: &[Param],
        v: &crate::study::Variant,
        noise_var: &[f64],
    ) -> Self {
        let fit_mu = params.contains(&Param::MuStatic);
        let f = &v.scene.friction;
        JointModel {
            obs,
            grid,
            params: params.to_vec(),
            ranges: params.iter().map(|p| p.range(v, fit_mu)).collect(),
            scale: Param::scale_of(&v.scene),
            spread_fixed: v.scene.mu_scale(),
            mu_fixed: f.mu_static,
            noise_var: noise_var.to_vec(),
        }
    }

    fn index(&self, p: Param) -> Option<usize> {
        self.params.iter().position(|q| *q == p)
    }

    /// Sigma(theta); None where theta is not admissible.
    pub fn sigma(&self, theta: &[f64]) -> Option<DMatrix<f64>> {
        let s = self.spread(theta);
        let mu = self.index(Param::MuStatic).map_or(self.mu_fixed, |i| theta[i]);
        if !admissible(self.scale, s, mu) {
            return None;
        }
        Some(model_covariance(&self.grid.at(&self.phi(theta)), &self.noise_var, s))
    }

    /// The spread at theta (fitted or fixed).
    pub fn spread(&self, theta: &[f64]) -> f64 {
        (self.index(self.scale)).map_or(self.spread_fixed, |i| theta[i])
    }

    /// The values of the grid parameters phi in theta.
    pub fn phi(&self, theta: &[f64]) -> Vec<f64> {
        self.grid
            .params
            .iter()
            .map(|p| theta[self.index(*p).expect("grid parameters are fitted")])
            .collect()
    }

    /// l(theta), -inf where not admissible or singular.
    pub fn log_likelihood(&self, theta: &[f64]) -> f64 {
        let l = self.sigma(theta).and_then(|sg| log_likelihood(self.obs, &sg));
        l.unwrap_or(f64::NEG_INFINITY)
    }

    /// theta of the unit coordinates u (the spread on a log scale).
    pub fn theta(&self, u: &[f64]) -> Vec<f64> {
        self.params
            .iter()
            .zip(&self.ranges)
            .zip(u)
            .map(|((p, &(a, b)), &u)| match p {
                p if p.is_scale() => {
                    let (t0, t1) = ((b * S_MIN_REL).ln(), b.ln());
                    (t0 + u * (t1 - t0)).exp()
                }
                _ => a + u * (b - a),
            })
            .collect()
    }

    /// The unit coordinate of parameter `a` at value `v`.
    pub fn unit(&self, a: usize, v: f64) -> f64 {
        let (lo, hi) = self.ranges[a];
        match self.params[a] {
            p if p.is_scale() => {
                let (t0, t1) = ((hi * S_MIN_REL).ln(), hi.ln());
                ((v.max(hi * S_MIN_REL).ln() - t0) / (t1 - t0)).clamp(0.0, 1.0)
            }
            _ => ((v - lo) / (hi - lo)).clamp(0.0, 1.0),
        }
    }

    /// l at the unit coordinates u.
    pub fn l_unit(&self, u: &[f64]) -> f64 {
        self.log_likelihood(&self.theta(u))
    }
}

/// Maximise `f` over the unit box in the coordinates where `free` is true
/// (the others stay at `start`), by Nelder-Mead with coordinates clamped to
/// [0, 1] (Nelder & Mead 1965; reflection 1, expansion 2, contraction and
/// shrink 1/2); one free coordinate by golden section. Returns the point
/// and its value.
pub fn maximise(f: &dyn Fn(&[f64]) -> f64, start: &[f64], free: &[bool]) -> (Vec<f64>, f64) {
    let idx: Vec<usize> = (0..start.len()).filter(|&i| free[i]).collect();
    let n = idx.len();
    let point = |y: &[f64]| -> Vec<f64> {
        let mut x = start.to_vec();
        for (k, &i) in idx.iter().enumerate() {
            x[i] = y[k].clamp(0.0, 1.0);
        }
        x
    };
    let value = |y: &[f64]| f(&point(y));
    if n == 0 {
        return (start.to_vec(), f(start));
    }
    if n == 1 {
        // One coordinate: golden section on the start's neighbourhood (the
        // simplex's first step), to 1e-12 in u.
        let y0 = start[idx[0]];
        let (lo, hi) = ((y0 - 0.1).max(0.0), (y0 + 0.1).min(1.0));
        let (y, v) = golden_max(|y| value(&[y]), lo, hi, 1e-12);
        return (point(&[y]), v);
    }
    let y0: Vec<f64> = idx.iter().map(|&i| start[i]).collect();
    let mut simplex: Vec<(Vec<f64>, f64)> = vec![(y0.clone(), value(&y0))];
    for k in 0..n {
        let mut y = y0.clone();
        y[k] = if y[k] > 0.5 { y[k] - 0.1 } else { y[k] + 0.1 };
        simplex.push((y.clone(), value(&y)));
    }
    for _ in 0..600 {
        simplex.sort_by(|a, b| b.1.total_cmp(&a.1));
        let (best, worst) = (simplex[0].1, simplex[n].1);
        let size = (1..=n)
            .map(|j| (0..n).map(|k| (simplex[j].0[k] - simplex[0].0[k]).abs()).fold(0.0, f64::max))
            .fold(0.0, f64::max);
        if size < 1e-10 || (best.is_finite() && (best - worst).abs() < 1e-12 && size < 1e-6) {
            break;
        }
        let centroid: Vec<f64> =
            (0..n).map(|k| simplex[..n].iter().map(|s| s.0[k]).sum::<f64>() / n as f64).collect();
        let along = |t: f64| -> Vec<f64> {
            (0..n)
                .map(|k| (centroid[k] + t * (simplex[n].0[k] - centroid[k])).clamp(0.0, 1.0))
                .collect()
        };
        let r = along(-1.0);
        let fr = value(&r);
        if fr > simplex[0].1 {
            let e = along(-2.0);
            let fe = value(&e);
            simplex[n] = if fe > fr { (e, fe) } else { (r, fr) };
        } else if fr > simplex[n - 1].1 {
            simplex[n] = (r, fr);
        } else {
            let c = along(0.5);
            let fc = value(&c);
            if fc > simplex[n].1 {
                simplex[n] = (c, fc);
            } else {
                let b = simplex[0].0.clone();
                for s in simplex.iter_mut().skip(1) {
                    let y: Vec<f64> = (0..n).map(|k| 0.5 * (b[k] + s.0[k])).collect();
                    *s = (y.clone(), value(&y));
                }
            }
        }
    }
    simplex.sort_by(|a, b| b.1.total_cmp(&a.1));
    (point(&simplex[0].0), simplex[0].1)
}

/// Points per parameter of the starting grid, by number of parameters.
const START_POINTS: [usize; 5] = [1, 33, 13, 7, 5];

/// The maximum-likelihood estimate in unit coordinates and l_max.
pub fn estimate(m: &JointModel) -> (Vec<f64>, f64) {
    let q = m.params.len();
    let k = START_POINTS[q.min(4)];
    let mut best = (vec![0.5; q], f64::NEG_INFINITY);
    for flat in 0..k.pow(q as u32) {
        let mut r = flat;
        let u: Vec<f64> = (0..q)
            .map(|_| {
                let i = r % k;
                r /= k;
                (i as f64 + 0.5) / k as f64
            })
            .collect();
        let l = m.l_unit(&u);
        if l > best.1 {
            best = (u, l);
        }
    }
    let all = vec![true; q];
    maximise(&|u| m.l_unit(u), &best.0, &all)
}

/// The profile of parameter `a` at unit value `v`: the others maximised,
/// from `warm` (and from `u_hat`), returning the arg max and l_p.
pub fn profile(m: &JointModel, a: usize, v: f64, warm: &[f64], u_hat: &[f64]) -> (Vec<f64>, f64) {
    let free: Vec<bool> = (0..m.params.len()).map(|i| i != a).collect();
    let f = |u: &[f64]| m.l_unit(u);
    let mut best = (warm.to_vec(), f64::NEG_INFINITY);
    for s in [warm, u_hat] {
        let mut start = s.to_vec();
        start[a] = v;
        let r = maximise(&f, &start, &free);
        if r.1 > best.1 {
            best = r;
        }
    }
    best
}

/// One end of a profile interval in unit coordinates.
#[derive(Debug, Clone, PartialEq)]
pub struct End {
    /// The unit value of the parameter at the end.
    pub u: f64,
    /// The whole point (the others at their profile maximum).
    pub point: Vec<f64>,
    /// No crossing inside the range: the end is the range end.
    pub at_bound: bool,
}

/// Steps from the estimate to a range end, and bisections of the step
/// where the boundary of a region is crossed.
const BOUNDARY_STEPS: usize = 40;
const BISECTIONS: usize = 30;

/// Where a walk from `start` (inside a region, with its state) to `end`
/// first leaves the region: `inside(v, state)` is the state at v (a warm
/// start for the next point) or None outside. The crossing is located by
/// bisection of the step; returns the last value inside, its state, and
/// whether the walk reached `end` without leaving.
fn boundary<S>(start: (f64, S), end: f64, inside: impl Fn(f64, &S) -> Option<S>) -> (f64, S, bool) {
    let mut last = start;
    let span = end - last.0;
    let from = last.0;
    for i in 1..=BOUNDARY_STEPS {
        let v = from + span * i as f64 / BOUNDARY_STEPS as f64;
        match inside(v, &last.1) {
            Some(state) => last = (v, state),
            None => {
                let mut out = v;
                for _ in 0..BISECTIONS {
                    let mid = 0.5 * (last.0 + out);
                    match inside(mid, &last.1) {
                        Some(state) => last = (mid, state),
                        None => out = mid,
                    }
                }
                return (last.0, last.1, false);
            }
        }
    }
    (last.0, last.1, true)
}

/// The end of the adjusted profile interval of parameter `a` towards
/// `dir` (-1: low, +1: high): k 2 (l_max - l_p) = chi^2_1(0.90).
pub fn profile_end(m: &JointModel, a: usize, k: f64, u_hat: &[f64], l_max: f64, dir: f64) -> End {
    let threshold = wilks_threshold();
    let target = if dir < 0.0 { 0.0 } else { 1.0 };
    let (u, mut point, at_bound) = boundary((u_hat[a], u_hat.to_vec()), target, |v, warm| {
        let (pt, l) = profile(m, a, v, warm, u_hat);
        (k * 2.0 * (l_max - l) <= threshold).then_some(pt)
    });
    if at_bound {
        point[a] = target;
    }
    End { u, point, at_bound }
}

/// The point where the ray u_hat + t e (t > 0) leaves the adjusted
/// likelihood region k 2 (l_max - l) <= chi^2_1(0.90), or the unit box.
pub fn ray_end(m: &JointModel, u_hat: &[f64], e: &[f64], k: f64, l_max: f64) -> Vec<f64> {
    let t_max = u_hat
        .iter()
        .zip(e)
        .map(|(&u, &d)| {
            if d > 0.0 {
                (1.0 - u) / d
            } else if d < 0.0 {
                -u / d
            } else {
                f64::INFINITY
            }
        })
        .fold(f64::INFINITY, f64::min);
    let at = |t: f64| -> Vec<f64> {
        u_hat.iter().zip(e).map(|(u, d)| (u + t * d).clamp(0.0, 1.0)).collect()
    };
    let threshold = wilks_threshold();
    let (t, _, _) = boundary((0.0, ()), t_max, |t, _| {
        (k * 2.0 * (l_max - m.l_unit(&at(t))) <= threshold).then_some(())
    });
    at(t)
}
