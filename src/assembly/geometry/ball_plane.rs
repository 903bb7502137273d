//! A ball against a plane (parry: a half-space, `contact_halfspace_support_map`).
//! Plane through p with unit normal m (pointing out of the solid):
//! ```text
//! gap = (c - p) . m - r,    n = m
//! ```

use nalgebra::Vector3;

use crate::lane::{Lane, lift, splat};

use super::ContactGeometry;

#[inline(always)]
pub(super) fn contact<T: Lane>(
    centre: &Vector3<T>,
    radius: f64,
    point: &Vector3<f64>,
    normal: &Vector3<f64>,
) -> ContactGeometry<T> {
    let normal = lift(normal);
    let gap = (centre - lift(point)).dot(&normal) - splat(radius);
    ContactGeometry::midway(centre, radius, gap, normal)
}
