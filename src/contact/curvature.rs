//! General contact geometry: the relative curvature of two bodies that
//! touch at a point, each given by its principal radii of curvature there
//! (positive convex, negative concave, infinite flat) and the angle theta
//! between the two bodies' first principal directions.
//!
//! The gap between the surfaces near the contact is h = A x^2 + B y^2 in
//! the principal axes of h, with (Johnson, *Contact Mechanics*, 1985, §4.1,
//! eq. 4.2), k_ij = 1/R_ij,
//!
//! ```text
//! A + B = 1/2 (k11 + k12 + k21 + k22)
//! B - A = 1/2 sqrt((k11 - k12)^2 + (k21 - k22)^2 + 2 (k11 - k12)(k21 - k22) cos 2 theta)
//! ```
//!
//! A point contact needs A > 0 (A = 0: the bodies touch along a line; A < 0:
//! a concave surface is curved more tightly than the convex one it holds).
//! The elliptical Hertz law ([`super::HertzLaw::elliptical`]) follows from
//! the relative radii Rx = 1/(2B) <= Ry = 1/(2A); the major axis of the
//! contact ellipse lies along x, the direction of the smaller curvature A.

use super::ContactError;

/// Two touching bodies by their principal radii of curvature [m] (positive
/// convex, negative concave, infinite flat) and the angle [rad] from body 1's
/// first principal direction (that of `radii1[0]`) to body 2's.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PairCurvature {
    pub radii1: [f64; 2],
    pub radii2: [f64; 2],
    pub angle: f64,
}

/// The relative curvature of a pair: h = A x^2 + B y^2, A <= B [1/m].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RelativeCurvature {
    pub a: f64,
    pub b: f64,
}

impl RelativeCurvature {
    /// The relative radii of curvature [Rx, Ry] = [1/(2B), 1/(2A)], Rx <= Ry.
    pub fn radii(&self) -> [f64; 2] {
        [0.5 / self.b, 0.5 / self.a]
    }
}

/// The curvature 1/R of a principal radius R (0 for an infinite one);
/// a zero or NaN radius is an error naming `field`.
fn curvature(field: &'static str, r: f64) -> Result<f64, ContactError> {
    if r.is_nan() || r == 0.0 {
        return Err(ContactError::BadPrincipalRadius { field, value: r });
    }
    Ok(1.0 / r)
}

impl PairCurvature {
    /// Johnson's A and B (module docs); A <= 0 is not a point contact.
    pub fn relative(&self) -> Result<RelativeCurvature, ContactError> {
        let k1 = [curvature("radii1", self.radii1[0])?, curvature("radii1", self.radii1[1])?];
        let k2 = [curvature("radii2", self.radii2[0])?, curvature("radii2", self.radii2[1])?];
        if !self.angle.is_finite() {
            return Err(ContactError::BadAngle(self.angle));
        }
        let (d1, d2) = (k1[0] - k1[1], k2[0] - k2[1]);
        let sum = 0.5 * (k1[0] + k1[1] + k2[0] + k2[1]);
        let cross = 2.0 * d1 * d2 * (2.0 * self.angle).cos();
        let diff = 0.5 * (d1 * d1 + d2 * d2 + cross).max(0.0).sqrt();
        let (a, b) = (0.5 * (sum - diff), 0.5 * (sum + diff));
        if a.is_nan() || a <= 0.0 {
            return Err(ContactError::NotPointContact { a, b });
        }
        Ok(RelativeCurvature { a, b })
    }
}
