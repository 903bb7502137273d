//! Friction readings: which coefficient acts while a contact slides.
//!
//! Two laws (`[friction] law` in a scene, MODEL.md §2):
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
//! F_n): the slip increment gamma >= 0 of the increment gives v = gamma / dt,
//! and the sliding force must lie on the rate-dependent limit:
//! ```text
//! |F| = T - k gamma = mu(gamma / dt) F_n
//! g(gamma) = k gamma + F_n (mu_s - mu_d) exp(-beta gamma) - (T - mu_d F_n) = 0,  beta = c / dt
//! ```
//! g is convex in gamma, every root lies in [(T - mu_s F_n)/k, (T - mu_d F_n)/k],
//! and g >= 0 at the upper end. Newton from the upper end therefore
//! descends monotonically onto the largest root (Fourier's condition for a
//! convex function), which is the sliding branch: a contact that slides
//! goes on sliding while that root exists (as the switch law slides on at
//! mu_d); a sticking contact starts to slide when T > mu_s F_n = mu(0) F_n
//! (then g(0) < 0 and the root is unique). The limits are exact:
//! c = 0 gives mu = mu_s (the switch law with ratio 1); c -> infinity gives
//! exp(-beta gamma) = 0 for any slip, i.e. mu = mu_d and the switch law's
//! hysteresis (slide on while T > mu_d F_n).
//!
//! Derivatives of the sliding coefficient at the root, for the consistent
//! tangent (implicit function theorem on g, s = exp(-beta gamma)):
//! ```text
//! g_gamma = k - beta F_n (mu_s - mu_d) s > 0
//! dmu/dT = -beta (mu_s - mu_d) s / g_gamma,   dmu/dF_n = +beta (mu_s - mu_d) s mu / g_gamma,
//! dmu/dk = +beta (mu_s - mu_d) s gamma / g_gamma      (T, F_n, k as independent inputs)
//! ```

use serde::{Deserialize, Serialize};

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

/// The sliding coefficient of one return-mapping increment and its partial
/// derivatives with respect to the trial force magnitude T, the normal
/// force F_n and the tangential stiffness k (each the others held fixed).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sliding {
    pub mu: f64,
    /// Slip increment gamma [m] (0 for the switch law, which does not need it).
    pub slip: f64,
    pub d_mu_d_trial: f64,
    pub d_mu_d_fn: f64,
    pub d_mu_d_k: f64,
}

impl Sliding {
    /// A constant sliding coefficient (the switch law's mu_d).
    pub fn constant(mu: f64) -> Self {
        Sliding {
            mu,
            slip: 0.0,
            d_mu_d_trial: 0.0,
            d_mu_d_fn: 0.0,
            d_mu_d_k: 0.0,
        }
    }
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
}

/// Stick (`None`) or slide with the returned coefficient.
pub fn slide(x: &SlideInput) -> Option<Sliding> {
    match x.law {
        FrictionLaw::Switch => {
            let limit = if x.was_sliding { x.mu_d } else { x.mu_s } * x.normal_force;
            (x.trial > limit).then(|| Sliding::constant(x.mu_d))
        }
        FrictionLaw::Decay { coefficient } => decay_slide(x, coefficient),
    }
}

/// The decay law's return mapping (module docs): the largest root of g.
fn decay_slide(x: &SlideInput, c: f64) -> Option<Sliding> {
    let (k, fn_, t) = (x.stiffness, x.normal_force, x.trial);
    if !x.was_sliding && t <= x.mu_s * fn_ {
        return None;
    }
    let a = fn_ * (x.mu_s - x.mu_d);
    let b = t - x.mu_d * fn_;
    if b <= 0.0 || k <= 0.0 {
        return None;
    }
    let beta = if x.duration > 0.0 {
        c / x.duration
    } else {
        f64::INFINITY
    };
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
    // No sliding root: the largest root vanished (g > 0 at its minimum) or lies at gamma <= 0.
    if gd <= 0.0 || gv > 1e-12 * b.max(a) || gamma.is_nan() || gamma <= 0.0 {
        return None;
    }
    let mu = x.mu_d + (x.mu_s - x.mu_d) * s;
    let w = beta * (x.mu_s - x.mu_d) * s / gd;
    let w = if w.is_finite() { w } else { 0.0 };
    Some(Sliding {
        mu,
        slip: gamma,
        d_mu_d_trial: -w,
        d_mu_d_fn: w * mu,
        d_mu_d_k: w * gamma,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn input(law: FrictionLaw, trial: f64, was_sliding: bool) -> SlideInput {
        SlideInput {
            mu_s: 0.5,
            mu_d: 0.4,
            law,
            duration: 0.05,
            trial,
            normal_force: 10.0,
            stiffness: 1e7,
            was_sliding,
        }
    }

    #[test]
    fn decay_root_lies_on_the_rate_dependent_limit() {
        // (1e7, 4.6): a sliding root below mu_s F_n (beta F_n (mu_s - mu_d) > k).
        // Independent check: the returned force T - k gamma equals mu(v) F_n
        // with v = gamma / dt evaluated from the closed-form law.
        for (c, trial) in [(1e3, 5.2), (1e5, 6.0), (1e7, 4.6), (0.0, 5.5)] {
            let x = input(FrictionLaw::Decay { coefficient: c }, trial, true);
            let s = slide(&x).expect("slides");
            let (mu_v, _) = decay_coefficient(0.5, 0.4, c, s.slip / 0.05);
            assert!((s.mu - mu_v).abs() < 1e-14);
            assert!(((trial - 1e7 * s.slip) / (mu_v * 10.0) - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn decay_derivatives_match_finite_differences() {
        let c = 3e4;
        let base = input(FrictionLaw::Decay { coefficient: c }, 5.3, true);
        let s0 = slide(&base).unwrap();
        let fd = |f: &dyn Fn(&mut SlideInput, f64), h: f64| {
            let (mut p, mut m) = (base, base);
            f(&mut p, h);
            f(&mut m, -h);
            (slide(&p).unwrap().mu - slide(&m).unwrap().mu) / (2.0 * h)
        };
        let d_t = fd(&|x, h| x.trial += h, 1e-6);
        let d_fn = fd(&|x, h| x.normal_force += h, 1e-6);
        let d_k = fd(&|x, h| x.stiffness += h, 1.0);
        assert!((d_t / s0.d_mu_d_trial - 1.0).abs() < 1e-5, "{d_t} {s0:?}");
        assert!((d_fn / s0.d_mu_d_fn - 1.0).abs() < 1e-5, "{d_fn} {s0:?}");
        assert!((d_k / s0.d_mu_d_k - 1.0).abs() < 1e-4, "{d_k} {s0:?}");
    }

    #[test]
    fn decay_limits_are_the_switch_law() {
        // c = 0: mu = mu_s whenever sliding, and a sliding contact sticks below mu_s F_n.
        let zero = FrictionLaw::Decay { coefficient: 0.0 };
        assert_eq!(slide(&input(zero, 5.5, false)).unwrap().mu, 0.5);
        assert!(slide(&input(zero, 4.9, true)).is_none());
        // c huge: mu = mu_d exactly, sliding on above mu_d F_n, as the switch law.
        let huge = FrictionLaw::Decay { coefficient: 1e30 };
        for (trial, sliding) in [(5.5, false), (4.5, true), (4.01, true)] {
            let d = slide(&input(huge, trial, sliding)).unwrap();
            let s = slide(&input(FrictionLaw::Switch, trial, sliding)).unwrap();
            assert_eq!(d.mu, s.mu);
        }
        assert!(slide(&input(huge, 3.99, true)).is_none());
        assert!(slide(&input(huge, 4.99, false)).is_none());
    }

    #[test]
    fn decay_branch_vanishes_when_the_limit_curve_is_steep() {
        // Sliding at T between mu_d F_n and mu_s F_n needs a slip root; with a
        // small k and a moderate beta it exists, with a tiny T above mu_d F_n
        // and a small beta it does not (g > 0 everywhere).
        let c = 1e2; // beta = 2e3 1/m: the decay spans ~0.5 mm of slip
        let x = input(FrictionLaw::Decay { coefficient: c }, 4.01, true);
        assert!(slide(&x).is_none());
    }
}
