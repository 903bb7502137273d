//! Contact stresses of a Hertz contact: the peak pressure p0 and the maximum
//! (subsurface) shear stress, checked against the materials' allowables.
//!
//! Circular contact (Johnson, *Contact Mechanics*, 1985, eq. 3.45): on the
//! axis of symmetry, with zeta = z/a,
//!
//! ```text
//! sigma_r/p0 = -(1 + nu) (1 - zeta atan(1/zeta)) + 1 / (2 (1 + zeta^2))
//! sigma_z/p0 = -1 / (1 + zeta^2)
//! tau/p0     = |sigma_z - sigma_r| / 2         (the principal shear stress)
//! ```
//!
//! maximised over zeta (golden section to 1e-12; the maximum lies on the
//! axis): tau_max = 0.31 p0 at z = 0.48 a for nu = 0.3, as Johnson quotes.
//! It depends on the Poisson ratio of the body, so each of the two bodies
//! gets its own value.
//!
//! Elliptical contact (the crossed sphere-pin contacts): tau_max/p0 lies
//! between the circle's value and the line contact's 0.300 (at z = 0.786 b,
//! independent of nu; Johnson 1985, ch. 4). kinrepro uses
//! the larger of the two, an upper bound whose error is at most
//! |circle - 0.300| / max(circle, 0.300) (3.2 % for nu = 0.3); the depth is
//! not reported for an ellipse.
//!
//! Safety factor: allowable / actual, for the peak pressure (allowable
//! pressure of the weaker material) and for the shear stress of each body
//! that has an allowable shear stress; the smallest of those that exist.
//! A factor that exists for one body of a pair but not the other (e.g. a
//! steel ball on a flat without `allowable_pressure`) covers that body only:
//! the other material is carried in `left_out`, so that every output can
//! say which material the factor does not cover.

use serde::Serialize;

use super::ContactPair;
use super::hertz::HertzLaw;
use crate::material::Material;

/// tau_max / p0 of a line contact (plane strain), independent of nu.
pub const LINE_CONTACT_SHEAR_RATIO: f64 = 0.300;

/// tau/p0 on the axis of a circular Hertz contact at depth zeta = z/a.
pub fn circular_axis_shear(nu: f64, zeta: f64) -> f64 {
    let q = 1.0 + zeta * zeta;
    let sigma_r = -(1.0 + nu) * (1.0 - zeta * (1.0 / zeta).atan()) + 0.5 / q;
    let sigma_z = -1.0 / q;
    0.5 * (sigma_z - sigma_r).abs()
}

/// The maximum shear stress under a circular Hertz contact: (tau_max/p0, z/a).
pub fn circular_max_shear(nu: f64) -> (f64, f64) {
    // The axis shear rises from (1 - 2 nu)/4 at the surface to one maximum
    // and decays; bracket it on a coarse grid, then golden section.
    let f = |z: f64| circular_axis_shear(nu, z);
    let best = (1..=300)
        .map(|k| {
            let z = k as f64 * 0.01;
            (z, f(z))
        })
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map_or(0.5, |(z, _)| z);
    let (mut lo, mut hi) = ((best - 0.01).max(1e-6), best + 0.01);
    let g = 0.5 * (5f64.sqrt() - 1.0);
    while hi - lo > 1e-12 {
        let x1 = hi - g * (hi - lo);
        let x2 = lo + g * (hi - lo);
        if f(x1) < f(x2) {
            lo = x1;
        } else {
            hi = x2;
        }
    }
    let z = 0.5 * (lo + hi);
    (f(z), z)
}

/// tau_max/p0 used for a contact of axis ratio b/a (1 = circle) in a body of
/// Poisson ratio nu (module doc), and whether it is exact.
pub fn max_shear_ratio(nu: f64, axis_ratio: f64) -> (f64, bool) {
    let (circle, _) = circular_max_shear(nu);
    if axis_ratio >= 1.0 - 1e-12 {
        (circle, true)
    } else {
        (circle.max(LINE_CONTACT_SHEAR_RATIO), false)
    }
}

/// A material that a safety factor of its pair had to leave out: the other
/// body has the allowable, this one has not, so the factor is the other
/// body's alone.
#[derive(Debug, Clone, PartialEq, Eq, Serialize)]
pub struct LeftOut {
    pub material: String,
    /// The key it lacks: `allowable_pressure` (SF_p) or
    /// `allowable_shear_stress` (SF_tau).
    pub missing: &'static str,
}

/// The stress state of one contact at a normal load, and its safety factors.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContactStress {
    pub max_pressure_pa: f64,
    /// Maximum shear stress [Pa] in the ball (body 1) and the fixed element (body 2).
    pub max_shear_stress_pa: [f64; 2],
    /// Its depth below the surface [m] (circular contacts only).
    pub max_shear_depth_m: Option<f64>,
    /// Whether tau_max is exact (circle) or the elliptical upper bound.
    pub shear_exact: bool,
    /// Allowable pressure / p0 (weaker material), if an allowable is known.
    pub pressure_safety_factor: Option<f64>,
    /// Smallest allowable shear / tau_max over the bodies with an allowable.
    pub shear_safety_factor: Option<f64>,
    /// The smaller of the two factors that exist.
    pub safety_factor: Option<f64>,
    /// Materials a factor that exists had to leave out (no allowable given).
    pub left_out: Vec<LeftOut>,
}

/// tau_max/p0 of the two bodies of a pair and the depth z/a of the maximum,
/// fixed by the Poisson ratios and the ellipse shape: computed once per pair
/// (it takes a few hundred evaluations of the axis stresses).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShearRatios {
    pub ratio: [f64; 2],
    /// z/a of the maximum in each body (circular contacts).
    pub depth_rel: [f64; 2],
    /// Exact (circle) or the elliptical upper bound.
    pub exact: bool,
}

impl ShearRatios {
    pub fn new(pair: &ContactPair, hertz: &HertzLaw) -> Self {
        let nu = [pair.material1.poisson_ratio, pair.material2.poisson_ratio];
        let r = nu.map(|n| max_shear_ratio(n, hertz.axis_ratio));
        ShearRatios {
            ratio: [r[0].0, r[1].0],
            depth_rel: nu.map(|n| circular_max_shear(n).1),
            exact: r[0].1 && r[1].1,
        }
    }
}

/// Contact stresses of `pair` (with its Hertz law and shear ratios) at normal
/// load `load`.
pub fn contact_stress(
    pair: &ContactPair,
    hertz: &HertzLaw,
    ratios: &ShearRatios,
    load: f64,
) -> ContactStress {
    let p0 = hertz.max_pressure(load);
    let materials: [&Material; 2] = [&pair.material1, &pair.material2];
    let shear = ratios.ratio.map(|r| r * p0);
    let exact = ratios.exact;
    let depth = if exact && load > 0.0 {
        // Report the depth in the body with the larger tau.
        let k = if shear[0] >= shear[1] { 0 } else { 1 };
        Some(ratios.depth_rel[k] * hertz.semi_axes(load)[0])
    } else {
        None
    };
    let safety = |allow: f64, actual: f64| {
        if actual > 0.0 {
            allow / actual
        } else {
            f64::INFINITY
        }
    };
    let pressure_sf = materials
        .iter()
        .filter_map(|m| m.allowable_pressure)
        .map(|a| safety(a, p0))
        .reduce(f64::min);
    let shear_sf = materials
        .iter()
        .zip(shear)
        .filter_map(|(m, t)| m.allowable_shear_stress.map(|a| safety(a, t)))
        .reduce(f64::min);
    let left_out = left_out(materials, pressure_sf.is_some(), shear_sf.is_some());
    let safety_factor = match (pressure_sf, shear_sf) {
        (Some(a), Some(b)) => Some(a.min(b)),
        (a, b) => a.or(b),
    };
    ContactStress {
        max_pressure_pa: p0,
        max_shear_stress_pa: shear,
        max_shear_depth_m: depth,
        shear_exact: exact,
        pressure_safety_factor: pressure_sf,
        shear_safety_factor: shear_sf,
        safety_factor,
        left_out,
    }
}

/// The bodies without an allowable for a factor that exists (from the
/// other body's allowable).
fn left_out(materials: [&Material; 2], pressure: bool, shear: bool) -> Vec<LeftOut> {
    let mut out = Vec::new();
    for m in materials {
        let lacks = [
            (
                pressure && m.allowable_pressure.is_none(),
                "allowable_pressure",
            ),
            (
                shear && m.allowable_shear_stress.is_none(),
                "allowable_shear_stress",
            ),
        ];
        for (_, missing) in lacks.into_iter().filter(|(lacks, _)| *lacks) {
            let entry = LeftOut {
                material: m.name.clone(),
                missing,
            };
            if !out.contains(&entry) {
                out.push(entry);
            }
        }
    }
    out
}
