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

use crate::lane::{Lane, lift, splat};

use super::{ContactGeometry, axis_offset};

#[inline(always)]
pub(super) fn contact<T: Lane>(
    centre: &Vector3<T>,
    radius: f64,
    axis_point: &Vector3<f64>,
    direction: &Vector3<f64>,
    groove_radius: f64,
) -> ContactGeometry<T> {
    let v = axis_offset(centre, &lift(axis_point), &lift(direction));
    let d = v.norm();
    ContactGeometry::midway(centre, radius, splat::<T>(groove_radius) - d - splat(radius), -v / d)
}
