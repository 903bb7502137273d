//! Whether Hertz's numbers mean something for one contact pair at a load
//! (`kinrepro contact`): Hertz treats both bodies as elastic half-spaces,
//! which needs the contact small against the radii of curvature, the
//! relative ones (Johnson 1985, §4.1) and each body's own (a conformal seat
//! has a relative radius far larger than its ball, yet its contact cannot
//! grow past the ball). And a radius that looks like millimetres typed as
//! metres.

use crate::contact::hertz::CONFORMITY_LIMIT;
use crate::contact::{HertzLaw, PairCurvature};
use crate::report::contact::conformity_warning;
use crate::scene::plausible::{CANOE_RADIUS_MAX, ELEMENT_DIAMETER_MAX};

/// What Hertz's numbers are worth at one load.
#[derive(Debug, Clone, PartialEq)]
pub enum HertzValidity {
    /// The contact is small against every radius.
    Valid,
    /// Outside Hertz's assumptions: the numbers are only indicative (why).
    Indicative(String),
    /// The contact would be wider than a body: the numbers mean nothing (why).
    Meaningless(String),
}

/// The smallest radius of curvature of either body [m] (flat directions
/// left out), or `None` for two flats.
pub fn smallest_body_radius(c: &PairCurvature) -> Option<f64> {
    c.radii1.iter().chain(&c.radii2).map(|r| r.abs()).filter(|r| r.is_finite()).reduce(f64::min)
}

/// Hertz's validity at normal load `load` [N] (module doc): meaningless if
/// the major semi-axis a reaches the smallest body radius, indicative if a
/// exceeds [`CONFORMITY_LIMIT`] of the smaller relative radius or of the
/// smallest body radius.
pub fn hertz_validity(h: &HertzLaw, c: &PairCurvature, load: f64) -> HertzValidity {
    let a = h.semi_axes(load)[0];
    let Some(r) = smallest_body_radius(c) else {
        return HertzValidity::Valid;
    };
    if a >= r {
        return HertzValidity::Meaningless(format!(
            "the contact semi-axis a = {:.4e} m would reach the smallest body radius {:.4e} m: \
             a contact as wide as the body is outside Hertz's model and its numbers mean nothing \
             (is the load far too large, or a radius far too small?)",
            a, r
        ));
    }
    if let Some(w) = conformity_warning(h, load) {
        return HertzValidity::Indicative(w);
    }
    if a > CONFORMITY_LIMIT * r {
        return HertzValidity::Indicative(format!(
            "conformal contact: the semi-axis a = {:.4} mm is {:.1} % of the smallest body radius \
             {:.4} mm (limit {:.0} %); Hertz treats both bodies as half-spaces, which needs a \
             contact small against each body, so these numbers are only indicative",
            a * 1e3,
            100.0 * a / r,
            r * 1e3,
            100.0 * CONFORMITY_LIMIT
        ));
    }
    HertzValidity::Valid
}

/// A hint if radius `r` [m] of `flag` looks like millimetres: above the
/// largest plausible ball, pin or seat radius of a scene
/// ([`ELEMENT_DIAMETER_MAX`] / 2), or for a principal radius (`--radii1`,
/// `--radii2`, which also describe canoe patches) above [`CANOE_RADIUS_MAX`].
pub fn radius_hint(flag: &str, r: f64, principal: bool) -> Option<String> {
    let max = if principal { CANOE_RADIUS_MAX } else { ELEMENT_DIAMETER_MAX / 2.0 };
    (r.is_finite() && r.abs() > max).then(|| {
        format!(
            "{flag} {r}: a radius of {} m is implausibly large (limit {max} m): did you give \
             millimetres? the flags are in SI (m); {} mm is {} m",
            r.abs(),
            r,
            r * 1e-3
        )
    })
}
