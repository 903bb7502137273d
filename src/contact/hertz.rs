//! Hertz normal contact of two smooth, non-conforming elastic bodies, for
//! circular and elliptical contact areas.
//!
//! Sources: Hertz (1882); Johnson, *Contact Mechanics* (1985), §4.2
//! (circular, eqs. 4.22-4.24) and §4.3 (elliptical, eqs. 4.36-4.42).
//!
//! Circular (relative radius R, 1/R = 1/R1 + 1/R2):
//! ```text
//! a = (3 F R / (4 E*))^(1/3),  delta = a^2 / R,  p0 = 3 F / (2 pi a^2),
//! F = K delta^(3/2),  K = 4/3 E* sqrt(R)
//! ```
//! Elliptical (principal relative curvatures A <= B, A = 1/(2 Rx), B = 1/(2 Ry);
//! semi-axes a >= b, k' = b/a, m = 1 - k'^2, K(m), E(m) complete elliptic integrals):
//! ```text
//! B/A = ((a/b)^2 E - K) / (K - E)                          (fixes k')
//! a^3 = 3 F (K - E) / (2 pi E* m A),  b = k' a
//! delta = 3 F K / (2 pi a E*),  p0 = 3 F / (2 pi a b)
//! ```
//! Both give F = K_h delta^(3/2); the law stores K_h and the constant
//! c_a = a / F^(1/3), so evaluating it costs a few flops.

use super::elliptic::{EllipticIntegrals, solve_kp};
use crate::lane::{Lane, each_lane, splat};
use std::f64::consts::PI;

/// Hertz treats the bodies as half-spaces, which needs a contact small
/// against the radii: above this ratio of the major semi-axis to the
/// smaller relative radius of curvature ([`HertzLaw::conformity`]) the
/// contact is too conformal for Hertz and kinrepro warns.
pub const CONFORMITY_LIMIT: f64 = 0.1;

/// The Hertz force-approach law of one contact pair.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzLaw {
    /// Effective modulus E* [Pa].
    pub e_star: f64,
    /// Relative radii of curvature [Rx, Ry] with Rx <= Ry [m]; equal for a
    /// circular contact. Rx = 1/(2B), Ry = 1/(2A).
    pub radii: [f64; 2],
    /// Shape of the contact ellipse, b/a (1 for a circle).
    pub axis_ratio: f64,
    /// Hertz constant K_h in F = K_h delta^(3/2) [N/m^1.5].
    pub hertz_constant: f64,
    /// c_a = a / F^(1/3) [m/N^(1/3)].
    semi_axis_coef: f64,
}

impl HertzLaw {
    /// Circular contact with relative radius `r` (1/r = 1/R1 + 1/R2; a plane
    /// has 1/R2 = 0, a concave seat a negative curvature).
    pub fn circular(r: f64, e_star: f64) -> Self {
        HertzLaw {
            e_star,
            radii: [r, r],
            axis_ratio: 1.0,
            hertz_constant: 4.0 / 3.0 * e_star * r.sqrt(),
            semi_axis_coef: (3.0 * r / (4.0 * e_star)).cbrt(),
        }
    }

    /// Elliptical contact from the two principal relative radii of curvature
    /// `rx`, `ry` (any order; rx = ry gives the circular law exactly).
    pub fn elliptical(rx: f64, ry: f64, e_star: f64) -> Self {
        let (r_small, r_large) = if rx <= ry { (rx, ry) } else { (ry, rx) };
        if r_small == r_large {
            return Self::circular(r_small, e_star);
        }
        let curv_a = 0.5 / r_large; // smaller curvature, along the major axis a
        let curv_b = 0.5 / r_small;
        let ell = EllipticIntegrals::from_kp(solve_kp(curv_b / curv_a));
        // a^3 / F = 3 (K - E) / (2 pi E* m A) = 3 K (S/m) / (2 pi E* A)
        let coef = (3.0 * ell.k * ell.s_over_m / (2.0 * PI * e_star * curv_a)).cbrt();
        // delta = 3 F K / (2 pi a E*) = F^(2/3) 3 K / (2 pi c_a E*)  =>  K_h = (2 pi c_a E* / (3 K))^(3/2)
        let hertz_constant = (2.0 * PI * coef * e_star / (3.0 * ell.k)).powf(1.5);
        HertzLaw {
            e_star,
            radii: [r_small, r_large],
            axis_ratio: ell.kp,
            hertz_constant,
            semi_axis_coef: coef,
        }
    }

    /// Normal force F = K_h delta^(3/2) for delta > 0, else 0 (no tension).
    pub fn force(&self, approach: f64) -> f64 {
        if approach > 0.0 { self.hertz_constant * approach * approach.sqrt() } else { 0.0 }
    }

    /// Normal stiffness dF/ddelta = 3/2 K_h delta^(1/2) (0 when open).
    pub fn stiffness(&self, approach: f64) -> f64 {
        if approach > 0.0 { 1.5 * self.hertz_constant * approach.sqrt() } else { 0.0 }
    }

    /// Approach delta = (F / K_h)^(2/3) for a load F >= 0.
    pub fn approach(&self, load: f64) -> f64 {
        (load.max(0.0) / self.hertz_constant).powf(2.0 / 3.0)
    }

    /// Semi-axes [a, b], a >= b, for a load F.
    pub fn semi_axes(&self, load: f64) -> [f64; 2] {
        let a = self.semi_axis_coef * load.max(0.0).cbrt();
        [a, a * self.axis_ratio]
    }

    /// The major semi-axis a = c_a F^(1/3) of [`Self::semi_axes`] by the
    /// cube root [`cbrt`] (within one ulp of libm's, a fifth of its
    /// instructions): the contact layer's K_t (a0 once per increment; a1
    /// from the Hertz law's own root, `SeriesNormal::force_stiffness_and_root`,
    /// where the contact has no support compliance).
    #[inline]
    pub fn major_semi_axis_fast(&self, load: f64) -> f64 {
        self.major_semi_axis_of_root(load_root(load))
    }

    /// [`Self::major_semi_axis_fast`] from the load's cube root
    /// [`load_root`] already formed.
    #[inline]
    pub fn major_semi_axis_of_root<T: Lane>(&self, root: T) -> T {
        splat::<T>(self.semi_axis_coef) * root
    }

    /// The major semi-axis a at load F over the smaller relative radius of
    /// curvature Rx: small for a Hertz contact, above [`CONFORMITY_LIMIT`]
    /// too conformal.
    pub fn conformity(&self, load: f64) -> f64 {
        self.semi_axes(load)[0] / self.radii[0]
    }

    /// Peak pressure p0 = 3 F / (2 pi a b).
    pub fn max_pressure(&self, load: f64) -> f64 {
        if load <= 0.0 {
            return 0.0;
        }
        let [a, b] = self.semi_axes(load);
        3.0 * load / (2.0 * PI * a * b)
    }
}

/// F^(1/3) of a load F ([`cbrt`]; zero for F <= 0), the law-free part of
/// [`HertzLaw::major_semi_axis_fast`].
#[inline]
pub fn load_root(load: f64) -> f64 {
    cbrt(load.max(0.0))
}

/// [`load_root`] of each lane.
#[inline]
pub fn load_roots<T: Lane>(load: T) -> T {
    each_lane(&load, load_root)
}

/// The cube root of x to within one ulp of libm's (measured over 2e6
/// values from 1e-60 to 1e60), about a fifth of its instructions: the
/// contact layer's a(F) = c_a F^(1/3) ([`HertzLaw::major_semi_axis_fast`]:
/// at the committed force once per increment, at the trial one where a
/// support compliance is in series; elsewhere libm's, whose bits the
/// dynamic solver's time step depends on). A
/// bit-level start (the exponent divided by 3; within 3 %) and three
/// Halley steps y <- y + y (x - y^3) / (2 y^3 + x) (cubic convergence:
/// 3e-2, 1e-5, 1e-16). Zero, subnormal, negative and non-finite x go to
/// libm.
pub fn cbrt(x: f64) -> f64 {
    if !(f64::MIN_POSITIVE..f64::INFINITY).contains(&x) {
        return x.cbrt();
    }
    let mut y = f64::from_bits(x.to_bits() / 3 + 0x2A9F_7893_782D_A1CE);
    for _ in 0..3 {
        let y3 = y * y * y;
        y += y * (x - y3) / (2.0 * y3 + x);
    }
    y
}
