//! Contact forces of one time step: the compliant contact layer
//! ([`contact_layer::evaluate_at`]: Hertz normal force, Coulomb stick/slip with
//! history) plus the damping that lets the motion settle.
//!
//! Normal damping, the nonlinear viscoelastic law of Tsuji, Tanaka & Ishida
//! (1992, *Powder Technology* 71, 239-250), i.e. a dashpot whose
//! coefficient keeps the contact at damping ratio zeta_n at every load:
//! ```text
//! F_n = max(0, K delta^(3/2) + c_n d(delta)/dt),   c_n = 2 zeta_n sqrt(m_eff,n k_n),
//! k_n = 3/2 K delta^(1/2)   =>   c_n = 2 zeta_n sqrt(3/2 m_eff,n K) delta^(1/4)
//! ```
//! d(delta)/dt = -n . v_c (v_c the velocity of the ball centre; the gap is
//! the distance of the centre from the surface minus the radii, for planes,
//! pins and balls alike). The damping vanishes with delta (no jump at first
//! touch) and the clamp at zero forbids adhesion. m_eff,n is the body's
//! effective mass along n at the ball centre ([`MassModel::effective_mass`]).
//!
//! Tangential damping: while a contact sticks, a dashpot acts on the
//! tangential velocity v_t of the contact point, in parallel with the
//! Mindlin spring k_t of the contact law, critically damped at zeta_t:
//! ```text
//! F_t,body = -F_t,law - c_t v_t,   c_t = 2 zeta_t sqrt(m_eff,t k_t),
//! |F_t,body| <= mu_s F_n,Hertz  (scaled back onto the cone if the dashpot pushes it out)
//! ```
//! A sliding contact has no dashpot: it already dissipates at mu_d F_n.
//! The friction law sees the elastic (Hertz) normal force, not the damped
//! one. The dashpot is a numerical device to let the motion settle (real
//! steel contacts are far less damped); at first touch, where delta is
//! small, c_n d(delta)/dt exceeds K delta^(3/2) by far, and a friction
//! limit mu (F_Hertz + f_dashpot) would make the contacts stick where the
//! quasi-static seating slides (measured: deviations of several sigma).
//! The price: while loading, a sliding contact transmits the extra normal
//! force f_dashpot without friction, which lowers its friction-to-normal
//! ratio by f_dashpot / F_n, an error of first order in the loading rate
//! (it shrinks as the ramp slows; see the cross-check tests).
//!
//! Explicit stability: a dashpot integrated explicitly needs
//! c dt / m_eff < 2; with c = 2 zeta sqrt(k m_eff) this is
//! zeta omega dt < 1, which holds for every zeta <= 1 at the time steps of
//! [`super::DynamicOptions`] (omega dt <= 2 pi / 20).

use nalgebra::{Matrix3, Vector3};

use super::mass::MassModel;
use crate::assembly::{BodyPose, Coupling};
use crate::contact::{Friction, SlipState, TangentialState};
use crate::solve::contact_layer::{ContactEval, Motion as LayerMotion, evaluate_at};

/// The damping ratios of the contact dashpots.
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct Damping {
    /// zeta_n of the normal dashpot (0: none).
    pub normal: f64,
    /// zeta_t of the tangential dashpot of a sticking contact (0: none).
    pub tangential: f64,
}

/// One contact in one step: the layer's evaluation and the total force.
#[derive(Debug, Clone)]
pub struct StepContact {
    pub eval: ContactEval,
    /// Total force on the moving body, applied at `eval.geometry.point` [N].
    pub force: Vector3<f64>,
    /// Normal force including the dashpot, >= 0 [N].
    pub normal_force: f64,
    /// Magnitude of the tangential force including the dashpot [N].
    pub tangential_force: f64,
}

impl StepContact {
    /// An empty slot for [`contact_force`].
    pub fn empty() -> Self {
        StepContact {
            eval: ContactEval::empty(),
            force: Vector3::zeros(),
            normal_force: 0.0,
            tangential_force: 0.0,
        }
    }
}

/// Rigid-body state used by the damping: pose, centre of mass (world),
/// linear velocity of the centre of mass, angular velocity, world inverse inertia.
pub struct Motion<'a> {
    pub pose: &'a BodyPose,
    pub com: Vector3<f64>,
    pub linvel: Vector3<f64>,
    pub angvel: Vector3<f64>,
    pub inv_inertia: Matrix3<f64>,
    pub mass: &'a MassModel,
}

impl Motion<'_> {
    /// Velocity of the body point now at `p`.
    pub fn velocity_at(&self, p: &Vector3<f64>) -> Vector3<f64> {
        self.linvel + self.angvel.cross(&(p - self.com))
    }
}

/// Evaluate contact `i` at the current motion state (contact layer plus
/// dashpots), with `back` the motion from its pose to the committed one,
/// into the slot `out` (the simulation's buffer: nothing is
/// built and then moved). No consistent tangent is formed: an explicit
/// step reads forces only ([`evaluate_at`] forms them by the same
/// operations with or without it).
#[allow(clippy::too_many_arguments)]
pub fn contact_force(
    out: &mut StepContact,
    coupling: &Coupling,
    i: usize,
    motion: &Motion,
    back: &LayerMotion,
    committed: &TangentialState,
    friction: Friction,
    damping: Damping,
) {
    evaluate_at(&mut out.eval, coupling, i, motion.pose, back, committed, friction, false);
    let (force, normal_force, tangential_force) =
        damped(&out.eval, coupling, i, motion, friction, damping);
    out.force = force;
    out.normal_force = normal_force;
    out.tangential_force = tangential_force;
}

/// The total force on the body, the normal force and the tangential
/// force's magnitude of the evaluation `eval` with the dashpots (module docs).
fn damped(
    eval: &ContactEval,
    coupling: &Coupling,
    i: usize,
    motion: &Motion,
    friction: Friction,
    damping: Damping,
) -> (Vector3<f64>, f64, f64) {
    let fh = eval.normal_force;
    if fh <= 0.0 {
        return (Vector3::zeros(), 0.0, 0.0);
    }
    let n = eval.geometry.normal;
    let p = eval.geometry.point;
    // The moving centre of curvature on the contact normal (a pin's foot).
    let centre = p + n * coupling.contacts[i].radius;
    // Normal dashpot (Tsuji et al. 1992).
    let mut f_n = fh;
    if damping.normal > 0.0 {
        let m_eff = motion.mass.effective_mass(&motion.inv_inertia, &(centre - motion.com), &n);
        let c_n = 2.0 * damping.normal * (m_eff * eval.normal_stiffness).sqrt();
        let approach_rate = -n.dot(&motion.velocity_at(&centre));
        f_n = (fh + c_n * approach_rate).max(0.0);
    }
    // Tangential: the law's spring force, plus a dashpot while sticking.
    let mut tangential = -eval.tangential.force;
    if damping.tangential > 0.0 && eval.slip() == SlipState::Stick {
        let vp = motion.velocity_at(&p);
        let vt = vp - n * n.dot(&vp);
        let speed = vt.norm();
        if speed > 0.0 {
            let dir = vt / speed;
            let m_eff = motion.mass.effective_mass(&motion.inv_inertia, &(p - motion.com), &dir);
            let (kt, _) = coupling.contacts[i].law.tangential_stiffness(fh);
            let c_t = 2.0 * damping.tangential * (m_eff * kt).sqrt();
            tangential -= vt * c_t;
            let limit = friction.mu_s * fh;
            let norm = tangential.norm();
            if norm > limit {
                tangential *= limit / norm;
            }
        }
    }
    (n * f_n + tangential, f_n, tangential.norm())
}
