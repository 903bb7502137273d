//! Mindlin's tangential stiffness of a Hertz contact without slip, exact for
//! an ellipse, as a 2x2 stiffness aligned with the ellipse axes.
//!
//! Mindlin (1949); Johnson, *Contact Mechanics* (1985), §7.2: a tangential
//! force Q along an axis of the contact ellipse (semi-axes a >= b, k' = b/a,
//! m = 1 - k'^2) with the traction q = Q / (2 pi a b) (1 - x^2/a^2 - y^2/b^2)^(-1/2)
//! displaces the contact area rigidly. Superposing Cerruti's point-force
//! displacement u_x = Q/(2 pi G r) [(1 - nu) + nu cos^2 theta] over the ellipse
//! gives, per body, the compliance
//!
//! ```text
//! C = 1/(8 pi a b G) int_0^2pi R(theta) [(1 - nu) + nu cos^2 theta] dtheta     (along a)
//!   = K(m) / (2 pi a G) [(1 - nu) + nu (K - E)/(m K)]
//! C = K(m) / (2 pi a G) [1 - nu (K - E)/(m K)]                                 (along b)
//! ```
//!
//! (R(theta) the ellipse's radius in direction theta; the integrals
//! int R dtheta = 4 b K and int R cos^2 theta dtheta = 4 b (K - E)/m).
//! The pair's stiffness is 1 / (C_1 + C_2). For a circle (K = pi/2,
//! (K - E)/(m K) -> 1/2) both give k_t = 8 G* a with 1/G* = sum (2 - nu)/G.
//! The contact is stiffer across its minor axis: for the 5 mm steel ball on
//! the 2 mm steel pin (b/a = 0.436) k_minor = 1.08 and k_major = 1.008 times
//! the equal-area circle's 8 G* sqrt(a b), 7 % apart.

use nalgebra::{Matrix3, Vector3};
use std::f64::consts::PI;

use super::elliptic::EllipticIntegrals;
use crate::material::Material;

/// k_t / a along the major and the minor axis [N/m^2] for the materials of
/// a pair and the ellipse shape k' = b/a (1: circle), so that k_t = coef a.
pub fn mindlin_axis_coefficients(m1: &Material, m2: &Material, kp: f64) -> [f64; 2] {
    let ell = EllipticIntegrals::from_kp(kp.min(1.0));
    let s = ell.s_over_m; // (K - E) / (m K)
    let per_body = |m: &Material| {
        let (g, nu) = (m.shear_modulus(), m.poisson_ratio);
        let c = ell.k / (2.0 * PI * g);
        [c * ((1.0 - nu) + nu * s), c * (1.0 - nu * s)]
    };
    let (c1, c2) = (per_body(m1), per_body(m2));
    [1.0 / (c1[0] + c2[0]), 1.0 / (c1[1] + c2[1])]
}

/// The 3x3 tangential stiffness k_major e1 e1^T + k_minor e2 e2^T in the
/// tangent plane of the unit normal `n`, e1 the major axis (`major_axis`
/// projected into the plane; any direction for a circle), e2 = n x e1.
pub fn tangential_tensor(k: [f64; 2], n: &Vector3<f64>, major_axis: &Vector3<f64>) -> Matrix3<f64> {
    let proj = Matrix3::identity() - n * n.transpose();
    if k[0] == k[1] {
        return k[0] * proj;
    }
    let e1 = (proj * major_axis).normalize();
    let e2 = n.cross(&e1);
    k[0] * e1 * e1.transpose() + k[1] * e2 * e2.transpose()
}
