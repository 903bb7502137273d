//! Complete elliptic integrals by the arithmetic-geometric mean, the
//! ellipticity of a Hertz contact, and the Hamrock-Brewe approximation kept
//! as a cross-check.
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
        EllipticIntegrals {
            kp,
            m,
            k,
            e: k * (1.0 - s),
            s_over_m,
        }
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

/// Hamrock & Brewe (1983) curve fits, for cross-checking only
/// (J. Lubrication Technol. 105:171-177; stated accuracy a few percent).
/// `rx` < `ry` are the relative radii of curvature (r = 1/(2 * curvature)).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HamrockBrewe {
    /// Larger semi-axis a [m] (along y, the direction of the larger radius).
    pub a: f64,
    /// Smaller semi-axis b [m].
    pub b: f64,
    /// Approach delta [m].
    pub approach: f64,
}

/// Hamrock-Brewe approximation for load `f`, effective modulus `e_star`.
///
/// ```text
/// kappa = 1.0339 (Ry/Rx)^0.6360,  Eps = 1.0003 + 0.5968 Rx/Ry,
/// Fi = 1.5277 + 0.6023 ln(Ry/Rx), 1/R = 1/Rx + 1/Ry, E' = 2 E*,
/// a = (6 kappa^2 Eps f R / (pi E'))^(1/3),  b = (6 Eps f R / (pi kappa E'))^(1/3),
/// delta = Fi (9/(2 Eps R) (f / (pi kappa E'))^2)^(1/3)
/// ```
pub fn hamrock_brewe(rx: f64, ry: f64, e_star: f64, f: f64) -> HamrockBrewe {
    let (rx, ry) = if rx <= ry { (rx, ry) } else { (ry, rx) };
    let alpha = ry / rx;
    let kappa = 1.0339 * alpha.powf(0.6360);
    let eps = 1.0003 + 0.5968 / alpha;
    let fi = 1.5277 + 0.6023 * alpha.ln();
    let r = 1.0 / (1.0 / rx + 1.0 / ry);
    let ep = 2.0 * e_star;
    HamrockBrewe {
        a: (6.0 * kappa * kappa * eps * f * r / (PI * ep)).cbrt(),
        b: (6.0 * eps * f * r / (PI * kappa * ep)).cbrt(),
        approach: fi * (9.0 / (2.0 * eps * r) * (f / (PI * kappa * ep)).powi(2)).cbrt(),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agm_matches_tabulated_values() {
        // Abramowitz & Stegun table 17.1, m = 0.5: K = 1.8540746773013719,
        // E = 1.3506438810476755.
        let i = EllipticIntegrals::from_kp(0.5_f64.sqrt());
        assert!((i.k - 1.854_074_677_301_371_9).abs() < 4e-16);
        assert!((i.e - 1.350_643_881_047_675_5).abs() < 4e-16);
        // m = 0: K = E = pi/2.
        let c = EllipticIntegrals::from_kp(1.0);
        assert_eq!(c.k, PI / 2.0);
        assert_eq!(c.e, PI / 2.0);
        // Legendre relation E K' + E' K - K K' = pi/2 at m = 0.3.
        let m: f64 = 0.3;
        let i = EllipticIntegrals::from_kp((1.0 - m).sqrt());
        let j = EllipticIntegrals::from_kp(m.sqrt());
        let legendre = i.e * j.k + j.e * i.k - i.k * j.k;
        assert!((legendre - PI / 2.0).abs() < 1e-15, "{legendre}");
    }

    #[test]
    fn ellipticity_solve_inverts_the_ratio() {
        for kp in [0.999_999, 0.9, 0.5, 0.1, 0.01] {
            let r = EllipticIntegrals::from_kp(kp).curvature_ratio();
            let back = solve_kp(r);
            assert!((back / kp - 1.0).abs() < 1e-12, "{kp} -> {r} -> {back}");
        }
        assert_eq!(solve_kp(1.0), 1.0);
    }
}
