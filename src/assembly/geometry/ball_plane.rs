//! A ball against a plane (parry: a half-space, `contact_halfspace_support_map`).
//! Plane through p with unit normal m (pointing out of the solid):
//! ```text
//! gap = (c - p) . m - r,    n = m
//! ```

use nalgebra::Vector3;

use super::ContactGeometry;

#[inline(always)]
pub(super) fn contact(
    centre: &Vector3<f64>,
    radius: f64,
    point: &Vector3<f64>,
    normal: &Vector3<f64>,
) -> ContactGeometry {
    let gap = (centre - point).dot(normal) - radius;
    ContactGeometry::midway(centre, radius, gap, *normal)
}
