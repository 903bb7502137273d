//! Boussinesq (1885) point load on an elastic half-space, used as the far-field
//! displacement boundary condition of the truncated block.
//!
//! Johnson, *Contact Mechanics* (1985), eq. (3.21a,b): for a normal point load `P`
//! at the origin of the half-space `ζ ≥ 0` (`ζ` depth below the surface),
//! `ρ = sqrt(r² + ζ²)`, `G = E / (2(1+ν))`:
//!
//! * `u_r = P/(4πG) [ r ζ/ρ³ - (1-2ν) r/(ρ(ρ+ζ)) ]`
//! * `u_ζ = P/(4πG) [ ζ²/ρ³ + 2(1-ν)/ρ ]`
//!
//! On the surface `u_ζ = P(1-ν²)/(π E r)`. Displacements vanish at infinity, which
//! is the datum of the Hertz approach.

/// Displacement `[u_x, u_y, u_z]` in mesh coordinates (`z` up, surface `z = 0`,
/// body `z ≤ 0`) at point `x` due to a downward load `p` at the origin. Returns
/// `None` at the load point.
pub fn displacement(p: f64, e: f64, nu: f64, x: [f64; 3]) -> Option<[f64; 3]> {
    let r = x[0].hypot(x[1]);
    let zeta = -x[2];
    let rho = r.hypot(zeta);
    if rho.is_nan() || rho <= 0.0 {
        return None;
    }
    let g = e / (2.0 * (1.0 + nu));
    let c = p / (4.0 * std::f64::consts::PI * g);
    // u_r / r (finite as r -> 0 below the surface)
    let ur_over_r = c * (zeta / rho.powi(3) - (1.0 - 2.0 * nu) / (rho * (rho + zeta)));
    let uz_down = c * (zeta * zeta / rho.powi(3) + 2.0 * (1.0 - nu) / rho);
    Some([ur_over_r * x[0], ur_over_r * x[1], -uz_down])
}

#[cfg(test)]
mod tests {
    use super::*;
    use approx::assert_relative_eq;
    use std::f64::consts::PI;

    #[test]
    fn surface_deflection_closed_form() {
        let (p, e, nu) = (10.0, 200e9, 0.3);
        let r = 1e-3;
        let u = displacement(p, e, nu, [r * 0.6, r * 0.8, 0.0]).unwrap();
        assert_relative_eq!(
            -u[2],
            p * (1.0 - nu * nu) / (PI * e * r),
            max_relative = 1e-12
        );
        // surface radial displacement: -(1-2ν)(1+ν) P /(2π E r)
        let ur = u[0].hypot(u[1]);
        assert_relative_eq!(
            ur,
            (1.0 - 2.0 * nu) * (1.0 + nu) * p / (2.0 * PI * e * r),
            max_relative = 1e-12
        );
        assert!(displacement(p, e, nu, [0.0; 3]).is_none());
    }

    /// The field satisfies Navier's equation `(λ+G) ∇(∇·u) + G ∇²u = 0`;
    /// checked by finite differences at an interior point.
    #[test]
    fn satisfies_navier_equation() {
        let (e, nu) = (1.0, 0.3);
        let g = e / (2.0 * (1.0 + nu));
        let lam = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
        let x0 = [0.7, -0.4, -0.9];
        let h = 1e-3;
        let u = |x: [f64; 3]| displacement(1.0, e, nu, x).unwrap();
        let shift = |x: [f64; 3], d: usize, s: f64| {
            let mut y = x;
            y[d] += s;
            y
        };
        // second derivatives ∂²u_i/∂x_j∂x_k by central differences
        let d2 = |i: usize, j: usize, k: usize| {
            (u(shift(shift(x0, j, h), k, h))[i]
                - u(shift(shift(x0, j, h), k, -h))[i]
                - u(shift(shift(x0, j, -h), k, h))[i]
                + u(shift(shift(x0, j, -h), k, -h))[i])
                / (4.0 * h * h)
        };
        for i in 0..3 {
            let grad_div: f64 = (0..3).map(|j| d2(j, j, i)).sum();
            let lap: f64 = (0..3).map(|j| d2(i, j, j)).sum();
            let res = (lam + g) * grad_div + g * lap;
            assert!(res.abs() < 1e-5, "component {i}: {res}");
        }
    }
}
