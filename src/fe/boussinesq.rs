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
