//! Complete elliptic integrals by the arithmetic-geometric mean and the
//! ellipticity of a Hertz contact (Hamrock & Brewe's curve fits, a
//! cross-check, are in tests/it/contact_laws.rs).
//!
//! Notation: a >= b are the semi-axes of the contact ellipse, k' = b/a,
//! m = e^2 = 1 - k'^2 the parameter, K(m) and E(m) the complete elliptic
//! integrals of the first and second kind.

use std::f64::consts::PI;

/// K(m), E(m) and the AGM sum S(m), computed from k' = sqrt(1 - m).
///
/// Arithmetic-geometric mean (Abramowitz & Stegun 17.6): a0 = 1, b0 = k',
/// c0 = sqrt(m); a(n+1) = (an + bn)/2, b(n+1) = sqrt(an bn),
/// c(n+1) = (an - bn)/2. Then
///
/// ```text
/// K = pi / (2 a_N),   S = sum_n 2^(n-1) c_n^2,   E = K (1 - S)
/// ```
///
/// S is accumulated from positive terms only, so K - E = K S and
/// E/(1-m) - K = K (m - S)/k'^2 keep full relative precision even for a
/// nearly circular contact, where subtracting E from K would cancel.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EllipticIntegrals {
    /// Complementary modulus k' = b/a.
    pub kp: f64,
    /// Parameter m = e^2 = 1 - k'^2.
    pub m: f64,
    /// K(m), first kind.
    pub k: f64,
    /// E(m), second kind.
    pub e: f64,
    /// S(m) / m: finite as m -> 0 (limit 1/2).
    pub s_over_m: f64,
}

impl EllipticIntegrals {
    /// Evaluate for a complementary modulus 0 < k' <= 1.
    pub fn from_kp(kp: f64) -> Self {
        debug_assert!(kp > 0.0 && kp <= 1.0);
        let m = (1.0 - kp) * (1.0 + kp);
        // Start at n = 1: a1 = (1 + k')/2, b1 = sqrt(k'), c1 = (1 - k')/2,
        // c1^2/m = (1 - k')/(4 (1 + k')). Then c(n+1) = c_n^2 / (4 a(n+1)),
        // so S/m = 1/2 + sum_{n>=1} 2^(n-1) c_n^2/m is summed without subtraction.
        let (mut a, mut b) = (0.5 * (1.0 + kp), kp.sqrt());
        let mut c = 0.5 * (1.0 - kp);
        let mut c2_over_m = (1.0 - kp) / (4.0 * (1.0 + kp));
        let mut s_over_m = 0.5;
        let mut pow = 1.0;
        for _ in 0..64 {
            s_over_m += pow * c2_over_m;
            if c <= 1e-3 * f64::EPSILON * a {
                break;
            }
            let a_next = 0.5 * (a + b);
            b = (a * b).sqrt();
            a = a_next;
            let ratio = c / (4.0 * a);
            c *= ratio;
            c2_over_m *= ratio * ratio;
            pow *= 2.0;
        }
        let k = PI / (2.0 * a);
        let s = s_over_m * m;
        EllipticIntegrals { kp, m, k, e: k * (1.0 - s), s_over_m }
    }

    /// Ratio of the principal relative curvatures B/A (>= 1) that produces a
    /// contact ellipse with this k' (Johnson 1985, eqs. 3.59-3.60 / 4.39):
    ///
    /// ```text
    /// B/A = ((a/b)^2 E - K) / (K - E) = (1 - S/m) / (k'^2 S/m)
    /// ```
    pub fn curvature_ratio(&self) -> f64 {
        (1.0 - self.s_over_m) / (self.kp * self.kp * self.s_over_m)
    }
}

/// Solve the ellipse shape k' = b/a from the curvature ratio B/A >= 1.
///
/// The ratio falls monotonically from infinity to 1 as k' goes from 0 to 1;
/// bisection on ln k' is run to the last bit, so k' is exact to f64 precision.
pub fn solve_kp(curvature_ratio: f64) -> f64 {
    if curvature_ratio <= 1.0 {
        return 1.0;
    }
    // Bracket: k' = 1 gives ratio 1; shrink the lower end until ratio exceeds target.
    let mut lo = 0.5_f64;
    while EllipticIntegrals::from_kp(lo).curvature_ratio() < curvature_ratio {
        lo *= 0.5;
        if lo < 1e-300 {
            return lo;
        }
    }
    // ratio(lo) >= target > ratio(hi): geometric bisection to adjacent floats.
    let mut hi = 1.0_f64;
    for _ in 0..4096 {
        let mid = (lo * hi).sqrt();
        if mid <= lo || mid >= hi {
            break;
        }
        if EllipticIntegrals::from_kp(mid).curvature_ratio() >= curvature_ratio {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}
