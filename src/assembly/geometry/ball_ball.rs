//! A ball against a fixed ball of radius R centred at s (a Kelvin seat's
//! spheres; parry: `contact_ball_ball`):
//! ```text
//! gap = |c - s| - R - r,    n = (c - s) / |c - s|
//! ```

use nalgebra::Vector3;

use crate::lane::{Lane, lift, splat};

use super::ContactGeometry;

#[inline(always)]
pub(super) fn contact<T: Lane>(
    centre: &Vector3<T>,
    radius: f64,
    fixed_centre: &Vector3<f64>,
    fixed_radius: f64,
) -> ContactGeometry<T> {
    let v = centre - lift(fixed_centre);
    let d = v.norm();
    ContactGeometry::midway(centre, radius, d - splat(fixed_radius) - splat(radius), v / d)
}
