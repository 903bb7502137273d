//! The preload forces on the moving half at a pose and load factor, shared
//! by both solvers: each force of fixed direction d at a point p of the body,
//!
//! ```text
//! constant, weight:  F = lambda F_0 d
//! spring:            F = (lambda F_0 - k (p - p_0) . d) d
//! magnet:            F = lambda F(gap) d,  gap = gap_0 - (p - p_0) . d
//! ```
//!
//! with p_0 the point in the touching pose. The spring lies along d between
//! an anchor on the fixed half and p; its length in the touching pose is
//! free_length - F_0 / k, so it gives F_0 there at full load, and it
//! lengthens by (p - p_0) . d as the half moves, losing k times that. The
//! load path ramps its compression (lambda F_0 / k: the anchor driven in,
//! as a screw tightening the spring), so every force reaches its full
//! value together at lambda = 1. A magnet pulls along d towards its
//! keeper on the fixed half, gap_0 away in the touching pose; moving its
//! point along d closes the gap, and its table's force F(gap)
//! (`scene::magnet`) is ramped whole (the keeper brought up). Its
//! stiffness is -lambda dF/dgap d d^T: positive along d where the pull
//! grows as the gap closes (a magnet destabilises what it holds).

use nalgebra::{Matrix3, Vector3};

use crate::assembly::{BodyPose, Coupling};
use crate::lane::{Lane, lift, splat};
use crate::scene::{ForceLaw, Preload};

/// One preload force at a pose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Applied<T: Lane = f64> {
    /// Force on the moving half [N].
    pub force: Vector3<T>,
    /// Its point in the world [m].
    pub point: Vector3<T>,
    /// d(force)/d(displacement of the point): -k d d^T for a spring,
    /// -lambda dF/dgap d d^T for a magnet (None for a constant force).
    pub stiffness: Option<Matrix3<T>>,
}

/// Every force of `preload` on `coupling`'s moving half at `pose` and load
/// factor `lambda`, in scene order (module docs).
pub fn applied<'a, T: Lane>(
    coupling: &'a Coupling,
    preload: &'a Preload,
    pose: &'a BodyPose<T>,
    lambda: f64,
) -> impl Iterator<Item = Applied<T>> + 'a {
    preload.forces.iter().map(move |f| {
        let point = pose.apply(&lift(&f.point));
        let direction = lift::<T, 3, 1>(&f.direction);
        let stretch = || {
            let rest = lift::<T, 3, 1>(&coupling.touching_pose.apply(&f.point));
            (point - rest).dot(&direction)
        };
        let dd = || lift::<T, 3, 3>(&(f.direction * f.direction.transpose()));
        match &f.law {
            ForceLaw::Spring { stiffness: k, .. } => Applied {
                force: direction * (splat::<T>(f.force * lambda) - splat::<T>(*k) * stretch()),
                point,
                stiffness: Some(dd() * splat::<T>(-k)),
            },
            ForceLaw::Magnet(m) => {
                // The magnet's force table lane by lane (f64's own interpolation).
                let gap = splat::<T>(m.gap) - stretch();
                let (mut force, mut slope) = (T::zero(), T::zero());
                for i in 0..T::LANES {
                    let (f, s) = m.force(gap.extract(i));
                    force.replace(i, f);
                    slope.replace(i, s);
                }
                Applied {
                    force: direction * (force * splat(lambda)),
                    point,
                    stiffness: Some(dd() * (splat::<T>(-lambda) * slope)),
                }
            }
            ForceLaw::Constant | ForceLaw::Weight => {
                Applied { force: direction * splat::<T>(f.force * lambda), point, stiffness: None }
            }
        }
    })
}
