//! The preload forces on the moving half at a pose and load factor, shared
//! by both solvers: each force of fixed direction d at a point p of the body,
//!
//! ```text
//! constant, weight:  F = lambda F_0 d
//! spring:            F = (lambda F_0 - k (p - p_0) . d) d
//! ```
//!
//! with p_0 the point in the touching pose. The spring lies along d between
//! an anchor on the fixed half and p; its length in the touching pose is
//! free_length - F_0 / k, so it gives F_0 there at full load, and it
//! lengthens by (p - p_0) . d as the half moves, losing k times that. The
//! load path ramps its compression (lambda F_0 / k: the anchor driven in,
//! as a screw tightening the spring), so every force reaches its full
//! value together at lambda = 1.

use nalgebra::{Matrix3, Vector3};

use crate::assembly::{BodyPose, Coupling};
use crate::scene::Preload;

/// One preload force at a pose.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Applied {
    /// Force on the moving half [N].
    pub force: Vector3<f64>,
    /// Its point in the world [m].
    pub point: Vector3<f64>,
    /// d(force)/d(displacement of the point): -k d d^T (zero unless a spring).
    pub stiffness: Option<Matrix3<f64>>,
}

/// Every force of `preload` on `coupling`'s moving half at `pose` and load
/// factor `lambda`, in scene order (module docs).
pub fn applied<'a>(
    coupling: &'a Coupling,
    preload: &'a Preload,
    pose: &'a BodyPose,
    lambda: f64,
) -> impl Iterator<Item = Applied> + 'a {
    preload.forces.iter().map(move |f| {
        let point = pose.apply(&f.point);
        let k = f.stiffness();
        if k > 0.0 {
            let stretch = (point - coupling.touching_pose.apply(&f.point)).dot(&f.direction);
            Applied {
                force: f.direction * (f.force * lambda - k * stretch),
                point,
                stiffness: Some(f.direction * f.direction.transpose() * -k),
            }
        } else {
            Applied { force: f.direction * (f.force * lambda), point, stiffness: None }
        }
    })
}
