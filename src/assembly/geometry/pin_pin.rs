//! A moving pin against a fixed pin (crossed pins): cylinders of radii r
//! about the line a1 + t d1 (moving) and R about a2 + s d2 (fixed), d1, d2
//! unit and not parallel. With m = d1 x d2 and w = a1 - a2 the distance
//! of the two axes along their common normal is s = w . m / |m|, and
//! (parry: two capsules about segments of the axes, `contact_capsule_capsule`)
//! ```text
//! gap = |s| - R - r,    n = sign(s) m / |m|  (from the fixed pin to the moving one)
//! ```
//! The foot of the common normal on the fixed axis is a2 + t2 d2 with
//! t2 = w . (m x d1) / |m|^2, and the moving axis' foot lies |s| further
//! along n.

use nalgebra::Vector3;

use crate::lane::{Lane, lift, splat};

use super::ContactGeometry;

#[inline]
pub(super) fn contact<T: Lane>(
    axis_point: &Vector3<T>,
    direction: &Vector3<T>,
    radius: f64,
    fixed_point: &Vector3<f64>,
    fixed_direction: &Vector3<f64>,
    fixed_radius: f64,
) -> ContactGeometry<T> {
    let (fixed_point, fixed_direction) = (lift(fixed_point), lift(fixed_direction));
    let m = direction.cross(&fixed_direction);
    let m2 = m.norm_squared();
    let w = axis_point - fixed_point;
    let s = w.dot(&m) / m2.simd_sqrt();
    let n = m * (s.simd_signum() / m2.simd_sqrt());
    let t2 = w.dot(&m.cross(direction)) / m2;
    let fixed_foot = fixed_point + fixed_direction * t2;
    let moving_foot = fixed_foot + n * s.simd_abs();
    let gap = s.simd_abs() - splat(fixed_radius) - splat(radius);
    ContactGeometry::midway(&moving_foot, radius, gap, n)
}
