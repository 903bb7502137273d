//! A ball against a pin, a cylinder of radius R about the axis a + t d
//! (d unit; parry: a capsule about a segment of the axis, whose side is
//! the cylinder, `contact_convex_polyhedron_ball`). The ball centre's
//! offset from the axis is v:
//! ```text
//! v = (c - a) - ((c - a) . d) d,    gap = |v| - R - r,    n = v / |v|
//! ```

use nalgebra::Vector3;

use crate::lane::{Lane, lift, splat};

use super::{ContactGeometry, axis_offset};

#[inline(always)]
pub(super) fn contact<T: Lane>(
    centre: &Vector3<T>,
    radius: f64,
    axis_point: &Vector3<f64>,
    direction: &Vector3<f64>,
    pin_radius: f64,
) -> ContactGeometry<T> {
    let v = axis_offset(centre, &lift(axis_point), &lift(direction));
    let d = v.norm();
    ContactGeometry::midway(centre, radius, d - splat(pin_radius) - splat(radius), v / d)
}
