//! The result of a thermal path (`quasistatic::thermal`): after the
//! seating, the coupling follows the scene's temperature cycle with the
//! full preload held and every contact's tangential history kept
//! (docs/model.md, "Thermal drift").

use nalgebra::Vector3;
use serde::Serialize;

use crate::assembly::BodyPose;
use crate::scene::{Temperatures, ThermalBodies};
use crate::solve::PointPose;

/// The coupling at one point of the cycle.
#[derive(Debug, Clone, PartialEq)]
pub struct CyclePoint {
    /// The temperature changes of the two bodies from the seating
    /// temperature [K].
    pub temperatures: Temperatures,
    /// The moving half's pose (body frame: the scene as written, at the
    /// seating temperature), Richardson-extrapolated where the path is
    /// error-controlled.
    pub pose: BodyPose,
    /// Estimated discretisation error of the pose relative to the larger
    /// of the seating's motion and this leg's (summed over the legs so
    /// far); `None` on fixed increments.
    pub path_error: Option<f64>,
    /// The contacts (1-based) that slid on the way from the previous point
    /// (from the seated state for the first).
    pub slipping: Vec<usize>,
    /// Accepted increments and Newton iterations of the leg (all levels).
    pub increments: usize,
    pub newton_iterations: usize,
}

/// Where the first contact starts to slide on the cycle.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FirstSlip {
    /// Contact, 1-based.
    pub contact: usize,
    /// The temperature changes at which it slides [K].
    pub temperatures: Temperatures,
    /// The cycle point (1-based) the leg it slides on leads to.
    pub cycle_point: usize,
}

/// A thermal path: the seated pose it starts from and each cycle point.
#[derive(Debug, Clone, PartialEq)]
pub struct ThermalPath {
    /// The seated pose the path starts from (the finest level of a
    /// controlled seating, whose contact states it continues).
    pub start: BodyPose,
    pub points: Vec<CyclePoint>,
    pub first_slip: Option<FirstSlip>,
}

impl ThermalPath {
    /// The drift of the moving body's point `p` (scene coordinates) at
    /// cycle point `k` (0-based): its displacement from where it was
    /// seated, T_k E_k(p) - T_0 p (rigid motion of the moving half and the
    /// body's own expansion), and the rotation vector of R_k R_0^-1.
    pub fn drift(&self, bodies: &ThermalBodies, k: usize, p: &Vector3<f64>) -> PointPose {
        let point = &self.points[k];
        let expanded = bodies.moving.map(p, point.temperatures.moving);
        let d = point.pose.apply(&expanded) - self.start.apply(p);
        let phi = (point.pose.rotation * self.start.rotation.inverse()).scaled_axis();
        PointPose::from_components([d.x, d.y, d.z, phi.x, phi.y, phi.z])
    }
}
