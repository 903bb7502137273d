//! A ball against a fixed ball of radius R centred at s (a Kelvin seat's
//! spheres; parry: `contact_ball_ball`):
//! ```text
//! gap = |c - s| - R - r,    n = (c - s) / |c - s|
//! ```

use nalgebra::Vector3;

use super::ContactGeometry;

#[inline(always)]
pub(super) fn contact(
    centre: &Vector3<f64>,
    radius: f64,
    fixed_centre: &Vector3<f64>,
    fixed_radius: f64,
) -> ContactGeometry {
    let v = centre - fixed_centre;
    let d = v.norm();
    ContactGeometry::midway(centre, radius, d - fixed_radius - radius, v / d)
}
