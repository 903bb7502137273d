//! The Hertz reference of the FE validation: kinrepro's own contact law
//! ([`crate::contact::HertzLaw`]), the law under test, behind the small
//! interface the FE runner uses.

use crate::contact::HertzLaw;
use crate::fe::FeError;

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HertzSolution {
    /// Contact semi-axes `[along x, along y]` (m).
    pub semi_axes: [f64; 2],
    /// Approach of distant points (m).
    pub approach: f64,
    /// Peak (central) pressure (Pa).
    pub peak_pressure: f64,
}

/// Hertz contact for the gap profile h = x^2/(2 rx) + y^2/(2 ry), effective
/// modulus `e_star` (Pa) and normal load `load` (N).
pub fn hertz(rx: f64, ry: f64, e_star: f64, load: f64) -> Result<HertzSolution, FeError> {
    for (name, v) in [("rx", rx), ("ry", ry), ("e_star", e_star), ("load", load)] {
        if !(v.is_finite() && v > 0.0) {
            return Err(FeError::InvalidInput(format!(
                "{name} must be finite and positive, got {v}"
            )));
        }
    }
    let law = HertzLaw::elliptical(rx, ry, e_star);
    // The major semi-axis lies along the larger radius.
    let [a, b] = law.semi_axes(load);
    let semi_axes = if ry >= rx { [b, a] } else { [a, b] };
    Ok(HertzSolution {
        semi_axes,
        approach: law.approach(load),
        peak_pressure: law.max_pressure(load),
    })
}
