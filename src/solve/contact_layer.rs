//! The compliant contact layer shared by both solvers: for one contact, the
//! pose of the moving half and the committed tangential history give the
//! Hertz normal force, the stick/slip tangential force and their tangent.
//!
//! Kinematics: the ball's material point now at the contact point p had, at
//! the committed pose, the position p_c = T_c T^-1 p; its displacement
//! du = p - p_c is the tangential increment of the contact law (the fixed
//! surface does not move). The force on the moving body is
//! F = F_n n - F_t (F_t the law's force, see `contact::tangential`), applied
//! at p.
//!
//! Mindlin's stiffness follows the normal load (k_t ~ F_n^(1/3)), so an
//! increment integrates dF_t = k_t(F_n) du with k_t at the mean normal force
//! of the increment, (F_n,committed + F_n)/2 (midpoint rule: second order in
//! the increment, where k_t at the end force would be first order).

use nalgebra::{Matrix3, Vector3};

use crate::assembly::{BodyPose, ContactGeometry, Coupling};
use crate::contact::{Friction, SlipState, TangentialInput, TangentialResponse, TangentialState};

/// One contact evaluated at a trial pose.
#[derive(Debug, Clone, Copy)]
pub struct ContactEval {
    pub geometry: ContactGeometry,
    /// Approach delta = -gap [m] (negative: open).
    pub approach: f64,
    pub normal_force: f64,
    /// dF_n / d delta [N/m].
    pub normal_stiffness: f64,
    pub tangential: TangentialResponse,
    /// Total contact force on the moving body [N].
    pub force: Vector3<f64>,
    /// d(force)/d(displacement of the contact point) [N/m].
    pub stiffness: Matrix3<f64>,
}

impl ContactEval {
    pub fn slip(&self) -> SlipState {
        self.tangential.slip
    }
}

/// Evaluate contact `i` of `coupling` at `pose`, from the committed pose
/// and tangential state.
pub fn evaluate(
    coupling: &Coupling,
    i: usize,
    pose: &BodyPose,
    committed_pose: &BodyPose,
    committed: &TangentialState,
    friction: Friction,
) -> ContactEval {
    let contact = &coupling.contacts[i];
    let g = coupling.geometry(i, pose);
    let approach = -g.gap;
    let hertz = &contact.law.hertz;
    // Hertz in series with the support compliance (`contact::series`).
    let (fn_, kn) = contact.normal.force_and_stiffness(approach);
    let body_point = pose.rotation.inverse() * (g.point - pose.translation);
    let du = g.point - committed_pose.apply(&body_point);
    let f_mid = 0.5 * (committed.normal_force + fn_);
    let (kt, dkt_mid) = contact.law.tangential_stiffness(f_mid);
    let dkt = 0.5 * dkt_mid;
    // Cattaneo-Mindlin's secant branch uses the current contact radius.
    let [a, b] = hertz.semi_axes(fn_);
    let input = TangentialInput {
        normal: g.normal,
        du,
        normal_force: fn_,
        stiffness: kt,
        d_stiffness_d_fn: dkt,
        contact_radius: (a * b).sqrt(),
        g_star: contact.law.g_star,
        friction,
    };
    let mut tangential = committed.update(coupling.scene.friction.tangential_law, &input);
    tangential.state.normal_force = fn_;
    let n = g.normal;
    // d(approach) = -n . dp, so d(F_n n) = -k_n n n^T dp and
    // d(F_t) = T dp + (dF_t/dF_n)(-k_n n^T dp); the force on the body is F_n n - F_t.
    let d_fn = -kn * n.transpose();
    let stiffness = n * d_fn - (tangential.d_force_d_du + tangential.d_force_d_fn * d_fn);
    ContactEval {
        geometry: g,
        approach,
        normal_force: fn_,
        normal_stiffness: kn,
        force: n * fn_ - tangential.force,
        tangential,
        stiffness,
    }
}
