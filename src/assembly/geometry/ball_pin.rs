//! A ball against a pin, a cylinder of radius R about the axis a + t d
//! (d unit; parry: a capsule about a segment of the axis, whose side is
//! the cylinder, `contact_convex_polyhedron_ball`). The ball centre's
//! offset from the axis is v:
//! ```text
//! v = (c - a) - ((c - a) . d) d,    gap = |v| - R - r,    n = v / |v|
//! ```

use nalgebra::Vector3;

use super::{ContactGeometry, axis_offset};

#[inline(always)]
pub(super) fn contact(
    centre: &Vector3<f64>,
    radius: f64,
    axis_point: &Vector3<f64>,
    direction: &Vector3<f64>,
    pin_radius: f64,
) -> ContactGeometry {
    let v = axis_offset(centre, axis_point, direction);
    let d = v.norm();
    ContactGeometry::midway(centre, radius, d - pin_radius - radius, v / d)
}
