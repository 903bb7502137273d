//! The parameters a calibration may fit (`fit`), their admissible ranges,
//! and setting them in a model of the scene (a study [`Variant`]: its scene
//! and its coupling together).
//!
//! * `spread`: `[friction] spread`, the half-width of mu_s in mu0 +- spread,
//!   searched in (1e-4 s_max, s_max] with s_max = min(mu_static,
//!   MU_MAX - mu_static) (the scene's own rule, `scene::resolve::tables`).
//! * `sd`: `[friction] sd` of a normal or lognormal distribution, the same
//!   at every contact, searched in (1e-4 s_max, s_max] with s_max =
//!   min(mu_static, MU_MAX - mu_static) / 2: two standard deviations each
//!   side inside [0, MU_MAX], so that the truncation removes at most 2.3 %
//!   at each end and the scatter keeps scaling with sd.
//! * `mu_static`: `[friction] mu_static`, searched in [0.1, 0.8]: dry and
//!   boundary-lubricated metal and ceramic pairs (steel on steel dry about
//!   0.5-0.8, lubricated 0.1-0.2); and spread <= mu_static at every point.
//! * `dynamic_ratio`: `[friction] dynamic_ratio` = mu_d / mu_s, searched in
//!   [0.3, 1.0] (the scene allows (0, 1]; below 0.3 no published dry pair).
//! * `support_compliance`: the series normal compliance of every contact's
//!   support [m/N], searched in [0, 4 c_H] with c_H the largest Hertz
//!   compliance d delta / dF = 2 delta / (3 F) of the scene's contacts under
//!   the frictionless preload forces: a support (pin seat, glued ball)
//!   softer than four times the Hertz contact itself is a design fault, not
//!   a scatter to calibrate.

use std::collections::BTreeMap;

use super::error::CalibrateError;
use crate::assembly::Coupling;
use crate::assembly::constraint::frictionless_preload_forces;
use crate::contact::SeriesNormal;
use crate::scene::resolve::MU_MAX;
use crate::scene::{MuDistribution, Scene};
use crate::study::Variant;

/// The parameters `fit` may name, in the order they are fitted and reported.
pub const PARAMETERS: [&str; 5] =
    ["spread", "sd", "mu_static", "dynamic_ratio", "support_compliance"];

/// Searched range of `mu_static`.
pub const MU_STATIC_RANGE: (f64, f64) = (0.1, 0.8);
/// Searched range of `dynamic_ratio`.
pub const DYNAMIC_RATIO_RANGE: (f64, f64) = (0.3, 1.0);
/// Upper end of `support_compliance` in units of the largest Hertz compliance.
pub const SUPPORT_COMPLIANCE_HERTZ_MULTIPLE: f64 = 4.0;

#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub enum Param {
    Spread,
    Sd,
    MuStatic,
    DynamicRatio,
    SupportCompliance,
}

impl Param {
    /// All five, in the order of [`PARAMETERS`].
    pub const ALL: [Param; 5] =
        [Param::Spread, Param::Sd, Param::MuStatic, Param::DynamicRatio, Param::SupportCompliance];

    pub fn name(self) -> &'static str {
        PARAMETERS[self as usize]
    }

    /// The scale of the coefficients' distribution ([`Scene::mu_scale`]):
    /// the spread or the sd. The calibration's model scales the pose
    /// covariance with its square and searches it on a log scale.
    pub fn is_scale(self) -> bool {
        matches!(self, Param::Spread | Param::Sd)
    }

    /// The scale parameter of `scene`'s distribution: `sd` for a normal or
    /// lognormal one, else `spread`.
    pub fn scale_of(scene: &Scene) -> Param {
        match scene.mu_distribution {
            MuDistribution::Normal { .. } | MuDistribution::Lognormal { .. } => Param::Sd,
            _ => Param::Spread,
        }
    }

    /// Whether this parameter applies to `scene` (a scale parameter only
    /// to its own distribution).
    pub fn applies_to(self, scene: &Scene) -> bool {
        !self.is_scale() || self == Param::scale_of(scene)
    }

    /// The parameter of a `fit` name.
    pub fn from_name(name: &str) -> Option<Param> {
        Param::ALL.into_iter().find(|p| p.name() == name)
    }

    /// Its value in the model `v` (the compliance of the first contact).
    pub fn value(self, v: &Variant) -> f64 {
        let f = &v.scene.friction;
        match self {
            Param::Spread | Param::Sd => v.scene.mu_scale(),
            Param::MuStatic => f.mu_static,
            Param::DynamicRatio => f.dynamic_ratio,
            Param::SupportCompliance => {
                v.coupling.contacts.first().map_or(0.0, |c| c.normal.compliance)
            }
        }
    }

    /// The searched range [low, high] for the model `v`. The spread's
    /// upper end also depends on mu_static (see [`admissible`]).
    pub fn range(self, v: &Variant, fit_mu: bool) -> (f64, f64) {
        match self {
            Param::Spread | Param::Sd => {
                let mu = if fit_mu { MU_STATIC_RANGE.1 } else { v.scene.friction.mu_static };
                (0.0, mu.min(MU_MAX - mu) / self.sds_inside())
            }
            Param::MuStatic => MU_STATIC_RANGE,
            Param::DynamicRatio => DYNAMIC_RATIO_RANGE,
            Param::SupportCompliance => {
                (0.0, SUPPORT_COMPLIANCE_HERTZ_MULTIPLE * hertz_compliance(v))
            }
        }
    }

    /// Set this parameter to `x` in a scene and its coupling: in the
    /// scene and, where the coupling carries it (the dynamic ratio, the
    /// compliances), there.
    pub fn set(self, scene: &mut Scene, coupling: &mut Coupling, x: f64) {
        match self {
            Param::Spread | Param::Sd => scene.set_mu_scale(x),
            Param::MuStatic => scene.friction.mu_static = x,
            Param::DynamicRatio => {
                scene.friction.dynamic_ratio = x;
                coupling.friction.dynamic_ratio = x;
            }
            Param::SupportCompliance => {
                for s in &mut scene.surfaces {
                    s.support_compliance = x;
                }
                for c in &mut coupling.contacts {
                    c.normal = SeriesNormal::new(c.normal.hertz, x);
                }
            }
        }
    }
}

/// Whether `v` is a value parameter `name` can have in any scene (the
/// scene's own rules, `scene::resolve::tables`): a spread and mu_static
/// within [0, MU_MAX] (spread <= mu_static and mu_static + spread <= MU_MAX
/// give spread <= MU_MAX / 2), a dynamic ratio in (0, 1] (mu_d never
/// exceeds mu_s), a finite support compliance >= 0. `Err` says the range.
pub fn physical(name: &str, v: f64) -> Result<(), OutOfRange> {
    let (ok, range) = match Param::from_name(name) {
        Some(p @ (Param::Spread | Param::Sd)) => {
            let top = MU_MAX / 2.0 / p.sds_inside();
            ((0.0..=top).contains(&v), format!("[0, {top}]"))
        }
        Some(Param::MuStatic) => ((0.0..=MU_MAX).contains(&v), format!("[0, {MU_MAX}]")),
        Some(Param::DynamicRatio) => (v > 0.0 && v <= 1.0, "(0, 1]".into()),
        Some(Param::SupportCompliance) | None => (v.is_finite() && v >= 0.0, "[0, inf) m/N".into()),
    };
    if ok { Ok(()) } else { Err(OutOfRange { value: v, range }) }
}

/// A parameter value outside the range any scene allows.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("{value} is outside {range}")]
pub struct OutOfRange {
    pub value: f64,
    pub range: String,
}

impl Param {
    /// How many of its scales the distribution keeps each side of mu0
    /// inside [0, MU_MAX]: the spread 1 (all of a uniform's range), the sd 2.
    pub fn sds_inside(self) -> f64 {
        if self == Param::Sd { 2.0 } else { 1.0 }
    }
}

/// Whether scale `s` of parameter `scale` (the spread, or the sd) and
/// mu_static `mu` keep mu0 +- s (mu0 +- 2 sd) in [0, MU_MAX].
pub fn admissible(scale: Param, s: f64, mu: f64) -> bool {
    let reach = scale.sds_inside() * s;
    s >= 0.0 && reach <= mu && mu + reach <= MU_MAX
}

/// The model `v` with the parameters `params` set to `values`.
pub fn with_values(v: &Variant, params: &[Param], values: &[f64]) -> Variant {
    let mut out = v.clone();
    for (p, x) in params.iter().zip(values) {
        p.set(&mut out.scene, &mut out.coupling, *x);
    }
    out
}

/// Set the parameters named in `values` (unknown names are left out) in a
/// scene and its coupling.
pub fn apply_named(scene: &mut Scene, coupling: &mut Coupling, values: &BTreeMap<String, f64>) {
    for (name, x) in values {
        if let Some(p) = Param::from_name(name) {
            p.set(scene, coupling, *x);
        }
    }
}

/// The largest Hertz compliance d delta / dF = 2 delta / (3 F) of the
/// contacts at their frictionless preload forces F [m/N] (Hertz:
/// delta = (F / K)^(2/3)).
pub fn hertz_compliance(v: &Variant) -> f64 {
    frictionless_preload_forces(&v.coupling, &v.scene.preload)
        .iter()
        .zip(&v.coupling.contacts)
        .filter(|(f, _)| **f > 0.0)
        .map(|(f, c)| 2.0 * c.normal.hertz.approach(*f) / (3.0 * f))
        .fold(0.0, f64::max)
}

/// Parse `fit`: a non-empty list of known, distinct names, returned in
/// the order of [`PARAMETERS`].
pub fn parse_fit(fit: &[String]) -> Result<Vec<Param>, CalibrateError> {
    if fit.is_empty() || fit.iter().all(|f| f.is_empty()) {
        return Err(CalibrateError::EmptyFit);
    }
    let mut out = Vec::new();
    for f in fit {
        if f.is_empty() {
            return Err(CalibrateError::EmptyFit);
        }
        let p = Param::from_name(f).ok_or_else(|| CalibrateError::UnknownParameter(f.clone()))?;
        if out.contains(&p) {
            return Err(CalibrateError::DuplicateParameter(f.clone()));
        }
        out.push(p);
    }
    out.sort();
    Ok(out)
}
