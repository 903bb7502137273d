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
//! Its direction: h = 1/2 x^T (C1 + R(theta) C2 R(theta)^T) x with
//! C_i = diag(k_i1, k_i2) in body 1's principal frame, so the larger
//! curvature lies at psi from body 1's first direction with
//! tan 2 psi = 2 c_12 / (c_11 - c_22), and the major axis at psi + 90 deg.

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

/// The relative curvature of a pair: h = A x^2 + B y^2, A <= B [1/m], and
/// the angle [rad] from body 1's first principal direction to x, the major
/// axis of the contact ellipse.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RelativeCurvature {
    pub a: f64,
    pub b: f64,
    pub major_angle: f64,
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
    /// Johnson's A and B (module docs) and the direction of the major axis.
    pub fn relative(&self) -> Result<RelativeCurvature, ContactError> {
        let k1 = [
            curvature("radii1", self.radii1[0])?,
            curvature("radii1", self.radii1[1])?,
        ];
        let k2 = [
            curvature("radii2", self.radii2[0])?,
            curvature("radii2", self.radii2[1])?,
        ];
        if !self.angle.is_finite() {
            return Err(ContactError::BadAngle(self.angle));
        }
        let (d1, d2) = (k1[0] - k1[1], k2[0] - k2[1]);
        let (s2, c2) = (2.0 * self.angle).sin_cos();
        let sum = 0.5 * (k1[0] + k1[1] + k2[0] + k2[1]);
        let diff = 0.5 * (d1 * d1 + d2 * d2 + 2.0 * d1 * d2 * c2).max(0.0).sqrt();
        let (a, b) = (0.5 * (sum - diff), 0.5 * (sum + diff));
        if a.is_nan() || a <= 0.0 {
            return Err(ContactError::NotPointContact { a, b });
        }
        // C1 + R C2 R^T in body 1's frame: c11 - c22 = d1 + d2 cos 2theta,
        // 2 c12 = d2 sin 2theta.
        let psi = 0.5 * (d2 * s2).atan2(d1 + d2 * c2);
        Ok(RelativeCurvature {
            a,
            b,
            major_angle: psi + 0.5 * std::f64::consts::PI,
        })
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pair(radii1: [f64; 2], radii2: [f64; 2], deg: f64) -> Result<RelativeCurvature, ContactError> {
        PairCurvature {
            radii1,
            radii2,
            angle: deg.to_radians(),
        }
        .relative()
    }

    #[test]
    fn the_checks_of_johnson_section_4_1() {
        let inf = f64::INFINITY;
        // Equal crossed cylinders at 90 degrees: a sphere of that radius on a flat.
        let r = pair([0.004, inf], [0.004, inf], 90.0).unwrap();
        assert!((r.a * 0.008 - 1.0).abs() < 1e-15 && (r.b * 0.008 - 1.0).abs() < 1e-15);
        // A ball r in a concave cylinder R_g: across r R_g/(R_g - r), along r.
        let (rb, rg) = (0.005, 0.0052);
        let [rx, ry] = pair([rb, rb], [-rg, inf], 0.0).unwrap().radii();
        assert!((ry / (rb * rg / (rg - rb)) - 1.0).abs() < 1e-12, "{ry}");
        assert!((rx / rb - 1.0).abs() < 1e-15);
        // A ball on a pin: the major axis lies along the pin (body 2's
        // infinite radius, 90 degrees from its first direction).
        let pin = pair([0.005, 0.005], [0.002, inf], 0.0).unwrap();
        assert!((pin.major_angle - 0.5 * std::f64::consts::PI).abs() < 1e-15);
        // Negative A: a ball larger than its seat; A = 0: a pin on a flat.
        for (r1, r2) in [([0.005; 2], [-0.004; 2]), ([0.005, inf], [inf, inf])] {
            let e = pair(r1, r2, 0.0).unwrap_err();
            assert!(matches!(e, ContactError::NotPointContact { .. }), "{e}");
        }
        assert!(pair([0.0, 1.0], [1.0, 1.0], 0.0).is_err());
    }
}
