//! Friction readings: which coefficient acts while a contact slides.
//!
//! Two laws (`[friction] law` in a scene, docs/model.md):
//! - **switch** (the paper's written set-up): static mu_s while sticking, a
//!   sudden switch to mu_d = dynamic_ratio * mu_s once the contact slides.
//! - **decay** (the exponential law of FE codes: ANSYS's FACT/DC, LS-DYNA's
//!   FS/FD/DC, COMSOL's exponential dynamic Coulomb):
//!   ```text
//!   mu(v) = mu_d + (mu_s - mu_d) exp(-c v),   c = decay_coefficient [s/m]
//!   ```
//!   with v the slip velocity. In ANSYS's terms mu = MU (1 + (FACT - 1)
//!   exp(-DC v)), so MU = mu_d, FACT = mu_s / mu_d, DC = c.
//!
//! Return mapping with the decay law (one increment of duration dt, trial
//! force magnitude T = |F_old + k du|, tangential stiffness k, normal force
//! F_n, slip increment gamma >= 0, slip velocity v = gamma / dt):
//!
//! - A contact that slid in the last increment slides on with the
//!   coefficient of the last increment's slip velocity v_prev (explicit in
//!   the velocity): mu = mu(v_prev), sliding while T > mu F_n, slip
//!   gamma = (T - mu F_n)/k. Within the increment the law is then the plain
//!   Coulomb map |F| = min(T, mu F_n), continuous in T. (Solved implicitly,
//!   a velocity-weakening coefficient has a fold: below some T its sliding
//!   branch vanishes and |F| jumps up to T, and since beta = c/dt grows as
//!   an increment is halved, the quasi-static path may then have no
//!   solution: measured, scene 02 at c = 2e6 s/m.) The lag is one increment.
//! - A contact that starts to slide (it stuck, and T > mu_s F_n = mu(0) F_n)
//!   has no previous velocity: its slip is solved implicitly,
//!   ```text
//!   |F| = T - k gamma = mu(gamma / dt) F_n
//!   g(gamma) = k gamma + F_n (mu_s - mu_d) exp(-beta gamma) - (T - mu_d F_n) = 0,  beta = c / dt
//!   ```
//!   g is convex in gamma with g(0) < 0, its root lies in
//!   [(T - mu_s F_n)/k, (T - mu_d F_n)/k] and g >= 0 at the upper end, so
//!   Newton from the upper end descends monotonically onto it (Fourier's
//!   condition for a convex function).
//!
//! The limits are exact: c = 0 gives mu = mu_s (the switch law with ratio
//! 1); c -> infinity gives exp(-c v) = 0 for any slip, i.e. mu = mu_d from
//! the first sliding increment on and the switch law's hysteresis (slide on
//! while T > mu_d F_n).
//!
//! Derivatives of the onset coefficient at the root, for the consistent
//! tangent (implicit function theorem on g, s = exp(-beta gamma)):
//! ```text
//! g_gamma = k - beta F_n (mu_s - mu_d) s > 0
//! dmu/dT = -beta (mu_s - mu_d) s / g_gamma,   dmu/dF_n = +beta (mu_s - mu_d) s mu / g_gamma,
//! dmu/dk = +beta (mu_s - mu_d) s gamma / g_gamma      (T, F_n, k as independent inputs)
//! ```
//! With the lagged velocity mu is constant within the increment.

use serde::{Deserialize, Serialize};
use simba::simd::SimdValue;

use crate::lane::{Lane, Mask};

/// Which coefficient acts while a contact slides.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case", tag = "law")]
pub enum FrictionLaw {
    /// Sudden switch from mu_s to mu_d = ratio * mu_s (the paper's text).
    #[default]
    Switch,
    /// mu(v) = mu_d + (mu_s - mu_d) exp(-coefficient * v) [coefficient in s/m].
    Decay { coefficient: f64 },
}

impl FrictionLaw {
    /// The name as in scene files.
    pub fn name(&self) -> &'static str {
        match self {
            FrictionLaw::Switch => "switch",
            FrictionLaw::Decay { .. } => "decay",
        }
    }
}

/// mu(v) = mu_d + (mu_s - mu_d) exp(-c v) and dmu/dv, for v >= 0.
pub fn decay_coefficient(mu_s: f64, mu_d: f64, c: f64, v: f64) -> (f64, f64) {
    let s = (-c * v).exp();
    (mu_d + (mu_s - mu_d) * s, -c * (mu_s - mu_d) * s)
}

/// The decay law's transition, c v_slip "of order 1" (docs/model.md,
/// "Velocity weakening"): here taken as within two decades of 1. v_slip is
/// a seating's characteristic slip speed, a contact's slip path over the
/// duration of the preload ramp. Below the band mu stays within 1 % of
/// (mu_s - mu_d) of mu_s (1 - exp(-0.01)); above it the slowest slip of a
/// seating, about a decade below its mean, still has exp(-c v) below
/// exp(-10) = 5e-5, i.e. mu = mu_d. Inside, the coefficient falls as the
/// slip speeds up and sliding is unstable: measured with the dynamic solver
/// on scene 01, c v = 1.4 changes a sample's pose by a factor 2 between 30
/// and 120 steps per period, c v = 15 by up to 10 %, c v = 160 by 0.1 %.
pub const TRANSITION: [f64; 2] = [1e-2, 1e2];

/// Whether `cv` = c v_slip lies in [`TRANSITION`] (results not converged).
pub fn in_transition(cv: f64) -> bool {
    (TRANSITION[0]..=TRANSITION[1]).contains(&cv)
}

/// The warning for a seating whose c v_slip `cv` lies in [`TRANSITION`].
pub fn transition_warning(cv: f64) -> String {
    format!(
        "decay law in its transition: c v_slip = {cv:.3e} lies in [{}, {}] (decay_coefficient \
         times a contact's slip over the ramp duration): the sliding is velocity-weakening and \
         the result is not converged (docs/model.md, \"Velocity weakening\")",
        TRANSITION[0], TRANSITION[1]
    )
}

/// The decay law's c v_slip of a seating: per decay-law contact, its
/// coefficient c times v_slip = slip path / `time` (the contact's slip
/// summed over the seating [m], over the preload ramp's duration [s]); of
/// these, the one [`deepest`] inside [`TRANSITION`]. `None` without a
/// decay-law contact that slid. Both solvers report it
/// (`crate::solve::Seating::decay_cv`).
pub fn seating_cv(friction: &[super::Friction], slip_path: &[f64], time: f64) -> Option<f64> {
    let cv = friction.iter().zip(slip_path).filter_map(|(f, path)| match f.law {
        FrictionLaw::Decay { coefficient } => Some(coefficient * path / time),
        FrictionLaw::Switch => None,
    });
    deepest(cv)
}

/// Of several c v_slip values (one per contact that slid), the one deepest
/// inside [`TRANSITION`], nearest 1 on a log scale; `None` if none is positive.
pub fn deepest(cv: impl IntoIterator<Item = f64>) -> Option<f64> {
    cv.into_iter().filter(|&x| x > 0.0).min_by(|a, b| a.ln().abs().total_cmp(&b.ln().abs()))
}

/// The sliding coefficient of one return-mapping increment and its partial
/// derivatives with respect to the trial force magnitude T, the normal
/// force F_n and the tangential stiffness k (each the others held fixed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sliding<T: Lane = f64> {
    pub mu: T,
    /// Slip increment gamma [m] (0 for the switch law, which does not need it).
    pub slip: T,
    pub d_mu_d_trial: T,
    pub d_mu_d_fn: T,
    pub d_mu_d_k: T,
}

impl<T: Lane> Sliding<T> {
    /// A constant sliding coefficient (the switch law's mu_d).
    pub fn constant(mu: T) -> Self {
        let zero = T::zero();
        Sliding { mu, slip: zero, d_mu_d_trial: zero, d_mu_d_fn: zero, d_mu_d_k: zero }
    }

    /// Whether mu is constant (no derivative): the switch law, a sliding
    /// contact of the decay law.
    #[inline]
    pub fn constant_mask(&self) -> Mask<T> {
        let zero = T::zero();
        self.d_mu_d_trial.simd_eq(zero) & self.d_mu_d_fn.simd_eq(zero) & self.d_mu_d_k.simd_eq(zero)
    }
}

/// [`slide`] over lanes: the lanes that slide, and their coefficient
/// (lanes that stick hold any value). The switch law in lanes; the decay
/// law lane by lane through [`slide`] (its Newton iteration has no form
/// over lanes here).
#[inline]
pub fn slide_lanes<T: Lane>(x: &SlideLanes<T>) -> (Mask<T>, Sliding<T>) {
    match x.law {
        FrictionLaw::Switch => {
            let limit = x.mu_d.select(x.was_sliding, x.mu_s) * x.normal_force;
            (x.trial.simd_gt(limit), Sliding::constant(x.mu_d))
        }
        FrictionLaw::Decay { .. } => {
            let mut slides = Mask::<T>::splat(false);
            let mut s = Sliding::constant(T::zero());
            for i in 0..T::LANES {
                let one = SlideInput {
                    mu_s: x.mu_s.extract(i),
                    mu_d: x.mu_d.extract(i),
                    law: x.law,
                    duration: x.duration,
                    trial: x.trial.extract(i),
                    normal_force: x.normal_force.extract(i),
                    stiffness: x.stiffness.extract(i),
                    was_sliding: x.was_sliding.extract(i),
                    previous_velocity: x.previous_velocity.extract(i),
                };
                let slid = slide(&one);
                slides.replace(i, slid.is_some());
                if let Some(v) = slid {
                    s.mu.replace(i, v.mu);
                    s.slip.replace(i, v.slip);
                    s.d_mu_d_trial.replace(i, v.d_mu_d_trial);
                    s.d_mu_d_fn.replace(i, v.d_mu_d_fn);
                    s.d_mu_d_k.replace(i, v.d_mu_d_k);
                }
            }
            (slides, s)
        }
    }
}

/// [`SlideInput`] over lanes (the law and the increment's duration are
/// every lane's).
#[derive(Debug, Clone, Copy)]
pub struct SlideLanes<T: Lane> {
    pub mu_s: T,
    pub mu_d: T,
    pub law: FrictionLaw,
    pub duration: f64,
    pub trial: T,
    pub normal_force: T,
    pub stiffness: T,
    pub was_sliding: Mask<T>,
    pub previous_velocity: T,
}

/// The inputs of one sliding decision.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlideInput {
    pub mu_s: f64,
    pub mu_d: f64,
    pub law: FrictionLaw,
    /// Duration of the increment [s] (slip velocity = slip / duration).
    pub duration: f64,
    /// |trial force| [N], normal force [N], tangential stiffness [N/m].
    pub trial: f64,
    pub normal_force: f64,
    pub stiffness: f64,
    /// Whether the contact was sliding at the end of the last increment.
    pub was_sliding: bool,
    /// Slip velocity of the last increment [m/s] (0 if it stuck).
    pub previous_velocity: f64,
}

/// Stick (`None`) or slide with the returned coefficient.
#[inline]
pub fn slide(x: &SlideInput) -> Option<Sliding> {
    match x.law {
        FrictionLaw::Switch => {
            let limit = if x.was_sliding { x.mu_d } else { x.mu_s } * x.normal_force;
            (x.trial > limit).then(|| Sliding::constant(x.mu_d))
        }
        FrictionLaw::Decay { coefficient } => decay_slide(x, coefficient),
    }
}

/// The decay law's return mapping (module docs).
fn decay_slide(x: &SlideInput, c: f64) -> Option<Sliding> {
    let (k, f_n, t) = (x.stiffness, x.normal_force, x.trial);
    if x.was_sliding {
        let (mu, _) = decay_coefficient(x.mu_s, x.mu_d, c, x.previous_velocity);
        return (t > mu * f_n && k > 0.0)
            .then(|| Sliding { slip: (t - mu * f_n) / k, ..Sliding::constant(mu) });
    }
    if t <= x.mu_s * f_n {
        return None;
    }
    let a = f_n * (x.mu_s - x.mu_d);
    let b = t - x.mu_d * f_n;
    if b <= 0.0 || k <= 0.0 {
        return None;
    }
    let beta = if x.duration > 0.0 { c / x.duration } else { f64::INFINITY };
    // g(gamma) and g'(gamma); beta gamma is never inf * 0 since gamma > 0 here.
    let g = |gamma: f64| {
        let s = if a == 0.0 { 0.0 } else { (-beta * gamma).exp() };
        (k * gamma + a * s - b, k - beta * a * s, s)
    };
    let mut gamma = b / k;
    let (mut gv, mut gd, mut s) = g(gamma);
    for _ in 0..200 {
        if gv <= 0.0 || gd <= 0.0 {
            break;
        }
        let next = gamma - gv / gd;
        if next.is_nan() || next <= 0.0 || next >= gamma {
            break;
        }
        gamma = next;
        (gv, gd, s) = g(gamma);
    }
    // A root exists (g(0) < 0 <= g(b/k)); reject only a failed iteration.
    if gd <= 0.0 || gv > 1e-12 * b.max(a) || gamma.is_nan() || gamma <= 0.0 {
        return None;
    }
    let mu = x.mu_d + (x.mu_s - x.mu_d) * s;
    let w = beta * (x.mu_s - x.mu_d) * s / gd;
    let w = if w.is_finite() { w } else { 0.0 };
    Some(Sliding { mu, slip: gamma, d_mu_d_trial: -w, d_mu_d_fn: w * mu, d_mu_d_k: w * gamma })
}
