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
//! Elliptical contact (the crossed sphere-pin contacts): the stresses on
//! the z axis are those of the Hertz pressure p = p0 sqrt(1 - x^2/a^2 - y^2/b^2)
//! superposed from Boussinesq's point-load field (Johnson 1985, eqs. 3.20-3.21;
//! Timoshenko & Goodier 1970, §138), with r the horizontal distance of the
//! load point, rho^2 = r^2 + z^2 and per unit load
//!
//! ```text
//! sigma_r     = [(1 - 2 nu) / ((rho + z) rho) - 3 z r^2 / rho^5] / (2 pi)
//! sigma_theta = -(1 - 2 nu) [1 / ((rho + z) rho) - z / rho^3] / (2 pi)
//! sigma_z     = -3 z^3 / (2 pi rho^5)
//! ```
//!
//! On the axis x, y and z are principal directions (quarter symmetry), and
//! tau = (max - min)/2 of the three. The quadrature (documented at
//! [`elliptical_axis_stresses`]) is maximised over depth by golden section;
//! it reproduces the circle's closed form above to 1e-9 and tends to the
//! line contact's 0.300 p0 at z = 0.786 b (independent of nu) as b/a -> 0.
//! For the steel pin contact (b/a = 0.436, nu = 0.3) it gives 0.325 p0 at
//! z = 0.654 b, 4.8 % above the circle's value. The depth is reported in
//! units of the minor semi-axis b.
//!
//! Safety factor: allowable / actual, for the peak pressure (allowable
//! pressure of the weaker material) and for the shear stress of each body
//! that has an allowable shear stress; the smallest of those that exist.
//! A factor that exists for one body of a pair but not the other (e.g. a
//! steel ball on a flat without `allowable_pressure`) covers that body only:
//! the other material is carried in `left_out`, so that every output can
//! say which material the factor does not cover.

use serde::Serialize;

use std::f64::consts::PI;

use super::ContactPair;
use super::hertz::HertzLaw;
use super::quadrature::{gauss_on, golden_max};
use crate::material::Material;

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
    let (z, t) = golden_max(f, (best - 0.01).max(1e-6), best + 0.01, 1e-12);
    (t, z)
}

/// Stresses [sigma_x, sigma_y, sigma_z] / p0 on the axis of an elliptical
/// Hertz contact (semi-axes a along x, b = k' a along y) at depth z = zeta b,
/// in a body of Poisson ratio nu (tension positive).
///
/// Quadrature of the Boussinesq field (module doc) over the ellipse, with
/// the load point at polar coordinates (r, theta) about the axis, the edge at
/// R(theta) = a b / sqrt(b^2 cos^2 theta + a^2 sin^2 theta) and r = R sin phi
/// (which removes the square-root edge of the pressure):
///
/// ```text
/// sigma = int_0^2pi dtheta R^2 int_0^pi/2 dphi sin phi cos^2 phi s(R sin phi, theta)
/// ```
///
/// Gauss-Legendre, 24 nodes per panel: theta on a quarter (the field is
/// symmetric in both axes) in geometric panels [0, t1], [t1, 3 t1], [3 t1, 9 t1]
/// ... with t1 = atan(b/a)/2 (R changes on the angular scale b/a near the
/// major axis); phi on [0, phi1] and [phi1, pi/2] with 48 nodes each, phi1
/// the angle where r = 4 z (the near field). Converged to 1e-8 for
/// 0.01 <= b/a <= 1 and 2e-6 at b/a = 0.002 (sigma_z against its closed form, tests/it/contact_laws.rs).
pub fn elliptical_axis_stresses(nu: f64, kp: f64, zeta: f64) -> [f64; 3] {
    let (a, b, z) = (1.0 / kp, 1.0, zeta);
    let mut s = [0.0; 3];
    let two_pi = 2.0 * PI;
    let mut panels = Vec::new();
    let mut lo = 0.0;
    // (t1 >= 1e-4: at most ~10 panels; past a/b ~ 5000 the rule is coarser.)
    let mut hi = (0.5 * kp.atan()).max(1e-4);
    while lo < 0.5 * PI {
        panels.push((lo, hi.min(0.5 * PI)));
        lo = hi;
        hi *= 3.0;
    }
    let thetas = panels.iter().flat_map(|&(l, h)| gauss_on(24, l, h));
    for (th, wt) in thetas {
        let (st, ct) = th.sin_cos();
        let r_edge = a * b / (b * b * ct * ct + a * a * st * st).sqrt();
        let (c2, s2) = (ct * ct, st * st);
        let phi1 = (4.0 * z / r_edge).min(1.0).asin();
        let mut inner = [0.0; 3];
        for (lo, hi) in [(0.0, phi1), (phi1, 0.5 * PI)] {
            if hi <= lo {
                continue;
            }
            for (phi, wp) in gauss_on(48, lo, hi) {
                let (sp, cp) = phi.sin_cos();
                let r = r_edge * sp;
                let rho2 = r * r + z * z;
                let rho = rho2.sqrt();
                let rho5 = rho2 * rho2 * rho;
                let q = 1.0 / ((rho + z) * rho);
                let sr = ((1.0 - 2.0 * nu) * q - 3.0 * z * r * r / rho5) / two_pi;
                let sth = -(1.0 - 2.0 * nu) * (q - z / (rho2 * rho)) / two_pi;
                let sz = -3.0 * z * z * z / (two_pi * rho5);
                let w = wp * sp * cp * cp;
                inner[0] += w * (sr * c2 + sth * s2);
                inner[1] += w * (sr * s2 + sth * c2);
                inner[2] += w * sz;
            }
        }
        for k in 0..3 {
            s[k] += 4.0 * r_edge * r_edge * wt * inner[k];
        }
    }
    // p0 = 1 (the load is 2/3 pi a b p0): the stresses above are per p0.
    s
}

/// tau/p0 = (max - min)/2 of the principal stresses on the axis of an
/// elliptical contact at depth z = zeta b.
pub fn elliptical_axis_shear(nu: f64, kp: f64, zeta: f64) -> f64 {
    let s = elliptical_axis_stresses(nu, kp, zeta);
    let max = s[0].max(s[1]).max(s[2]);
    let min = s[0].min(s[1]).min(s[2]);
    0.5 * (max - min)
}

/// The maximum subsurface shear stress of a Hertz contact of axis ratio
/// b/a (1 = circle) in a body of Poisson ratio nu: (tau_max/p0, z/b). Exact
/// for the circle (closed form), a converged quadrature for an ellipse.
pub fn max_shear_ratio(nu: f64, axis_ratio: f64) -> (f64, f64) {
    if axis_ratio >= 1.0 - 1e-12 {
        return circular_max_shear(nu);
    }
    // A coupling repeats the same pair: remember results per (nu, b/a).
    thread_local! {
        static DONE: std::cell::RefCell<std::collections::HashMap<(u64, u64), (f64, f64)>> =
            Default::default();
    }
    let key = (nu.to_bits(), axis_ratio.to_bits());
    if let Some(r) = DONE.with(|d| d.borrow().get(&key).copied()) {
        return r;
    }
    let r = elliptical_max_shear(nu, axis_ratio);
    DONE.with(|d| d.borrow_mut().insert(key, r));
    r
}

/// The search of [`max_shear_ratio`] for an ellipse.
fn elliptical_max_shear(nu: f64, axis_ratio: f64) -> (f64, f64) {
    let f = |z: f64| elliptical_axis_shear(nu, axis_ratio, z);
    // For nu >= 0.25 the maximum lies between the circle's 0.48 b and the
    // line's 0.786 b; for small nu and long ellipses the (sigma_x, sigma_z)
    // pair can peak nearer the surface ((1 - 2 nu)/2 at z = 0 for a line).
    let best = (1..=30)
        .map(|k| k as f64 * 0.05)
        .map(|z| (z, f(z)))
        .max_by(|a, b| a.1.total_cmp(&b.1))
        .map_or(0.6, |(z, _)| z);
    let (z, t) = golden_max(f, best - 0.05, best + 0.05, 1e-7);
    (t, z)
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
    /// Its depth below the surface [m] (in the body with the larger tau).
    pub max_shear_depth_m: Option<f64>,
    /// Allowable pressure / p0 (weaker material), if an allowable is known.
    pub pressure_safety_factor: Option<f64>,
    /// Smallest allowable shear / tau_max over the bodies with an allowable.
    pub shear_safety_factor: Option<f64>,
    /// The smaller of the two factors that exist.
    pub safety_factor: Option<f64>,
    /// Materials a factor that exists had to leave out (no allowable given).
    pub left_out: Vec<LeftOut>,
}

/// tau_max/p0 of the two bodies of a pair and the depth z/b of the maximum,
/// fixed by the Poisson ratios and the ellipse shape: computed once per pair
/// (an ellipse takes ~40 quadratures of the axis stresses, a few ms).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ShearRatios {
    pub ratio: [f64; 2],
    /// z/b of the maximum in each body (b the minor semi-axis).
    pub depth_rel: [f64; 2],
}

impl ShearRatios {
    pub fn new(pair: &ContactPair, hertz: &HertzLaw) -> Self {
        let nu = [pair.material1.poisson_ratio, pair.material2.poisson_ratio];
        let r = nu.map(|n| max_shear_ratio(n, hertz.axis_ratio));
        ShearRatios { ratio: [r[0].0, r[1].0], depth_rel: [r[0].1, r[1].1] }
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
    let depth = if load > 0.0 {
        // Report the depth in the body with the larger tau.
        let k = if shear[0] >= shear[1] { 0 } else { 1 };
        Some(ratios.depth_rel[k] * hertz.semi_axes(load)[1])
    } else {
        None
    };
    let safety = |allow: f64, actual: f64| {
        if actual > 0.0 { allow / actual } else { f64::INFINITY }
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
            (pressure && m.allowable_pressure.is_none(), "allowable_pressure"),
            (shear && m.allowable_shear_stress.is_none(), "allowable_shear_stress"),
        ];
        for (_, missing) in lacks.into_iter().filter(|(lacks, _)| *lacks) {
            let entry = LeftOut { material: m.name.clone(), missing };
            if !out.contains(&entry) {
                out.push(entry);
            }
        }
    }
    out
}
