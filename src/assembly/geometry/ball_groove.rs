//! A ball inside a concave cylinder, one flank of a gothic-arch groove: the
//! inside of a cylinder of radius R > r about the axis a + t d (d unit).
//! The ball centre's offset from the axis is v; the nearest wall point is
//! a + (foot) + R v/|v|, so
//! ```text
//! v = (c - a) - ((c - a) . d) d,    gap = R - |v| - r,    n = -v / |v|
//! ```
//! (n from the wall into the ball, towards the axis). parry has no hollow
//! cylinder; `tests/it/geometry.rs` checks this against the projection of the
//! ball centre onto the boundary of parry's solid `Cylinder` from inside.

use nalgebra::Vector3;

use super::{ContactGeometry, axis_offset};

#[inline(always)]
pub(super) fn contact(
    centre: &Vector3<f64>,
    radius: f64,
    axis_point: &Vector3<f64>,
    direction: &Vector3<f64>,
    groove_radius: f64,
) -> ContactGeometry {
    let v = axis_offset(centre, axis_point, direction);
    let d = v.norm();
    ContactGeometry::midway(centre, radius, groove_radius - d - radius, -v / d)
}
