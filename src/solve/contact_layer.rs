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
//! On a thermal path both bodies also expand between the committed state
//! and the trial one ([`Expansion`]): the fixed surface's material point
//! now at p was at p_f = o_f + rho_f (p - o_f) and the moving one at
//! p_m = T_c (o_m + rho_m (T^-1 p - o_m)), rho each body's stretch at the
//! committed temperature over its stretch at the trial one; the increment
//! of the law is the relative displacement du = p_f - p_m, which is the
//! rigid du above plus eps_f (p - o_f) - eps_m R_c (T^-1 p - o_m),
//! eps = rho - 1 (`Motion::displacement`).
//!
//! Mindlin's stiffness follows the normal load (K_t ~ a ~ F_n^(1/3)), so an
//! increment integrates dF_t = K_t(a) du with du taken to grow with the
//! Hertz approach (du ~ d(a^2)) inside the increment: K_t at
//! a_eff = (2/3)(a0^2 + a0 a1 + a1^2)/(a0 + a1), a0 at the committed normal
//! force and a1 at the trial one (`ContactLaw::increment_semi_axis`; exact
//! along a proportional path, second order otherwise). K_t is
//! Mindlin's 2x2 elliptical stiffness in the tangent plane, its major axis
//! the contact's (`assembly::Contact::major_axis`: along the pin for a
//! sphere-cylinder contact, across the groove for a sphere-groove one)
//! projected into the plane (`contact::mindlin`).

use nalgebra::{Matrix3, Vector3};

use crate::assembly::{BodyPose, ContactGeometry, Coupling};
use crate::contact::hertz::load_root;
use crate::contact::{Friction, SlipState, TangentialInput, TangentialResponse, TangentialState};
use crate::lane::{Lane, lift, splat};
use crate::scene::{Temperatures, ThermalBodies};

/// One contact evaluated at a trial pose.
#[derive(Debug, Clone)]
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
    /// Whether `stiffness` (and the tangential response's derivatives) are
    /// this evaluation's ([`evaluate_into`] without the tangent
    /// leaves them as they were).
    pub tangent: bool,
    /// The committed force's cube root this slot last formed ([`CommittedRoot`]).
    pub committed_root: CommittedRoot,
}

/// The cube root F_c^(1/3) of a committed normal force F_c
/// (`contact::hertz::load_root`), kept with the exact bits of the F_c it
/// was formed from: the evaluations of one increment share the committed
/// state, so a slot forms the cube root of its a0 = a(F_c) once per
/// increment instead of at every evaluation, and a different F_c (the
/// next increment, another seating) is never answered from the memo. The
/// root is the law-free part of a0 = c_a F_c^(1/3), so a slot reused for
/// another coupling's contact answers right.
#[derive(Debug, Clone, Copy)]
pub struct CommittedRoot {
    force_bits: u64,
    root: f64,
}

impl CommittedRoot {
    /// A memo that holds nothing (NaN bits: no force is looked up as them,
    /// and a NaN force is formed anew each time).
    pub const EMPTY: CommittedRoot = CommittedRoot { force_bits: f64::NAN.to_bits(), root: 0.0 };

    /// F_c^(1/3) of `committed_fn`, from the memo if it holds that force.
    #[inline]
    pub fn of(&mut self, committed_fn: f64) -> f64 {
        let bits = committed_fn.to_bits();
        if bits != self.force_bits || committed_fn.is_nan() {
            *self = CommittedRoot { force_bits: bits, root: load_root(committed_fn) };
        }
        self.root
    }
}

impl ContactEval {
    /// A slot for [`evaluate_into`]: an open contact at `geometry`
    /// (no tangent formed yet).
    pub fn open(geometry: ContactGeometry) -> Self {
        ContactEval {
            geometry,
            approach: -geometry.gap,
            normal_force: 0.0,
            normal_stiffness: 0.0,
            tangential: TangentialResponse::open(geometry.normal),
            force: Vector3::zeros(),
            stiffness: Matrix3::zeros(),
            tangent: false,
            committed_root: CommittedRoot::EMPTY,
        }
    }

    /// An empty slot (open, zero geometry) for the solvers' buffers.
    pub fn empty() -> Self {
        Self::open(ContactGeometry::default())
    }

    pub fn slip(&self) -> SlipState {
        self.tangential.slip
    }
}

/// Evaluate contact `i` of `coupling` at `pose`, from the committed pose
/// and tangential state, with the tangent: [`evaluate_into`] into a fresh
/// slot, for callers that evaluate one contact at a time (the dynamic
/// solver, the stiffness of a seated coupling).
pub fn evaluate(
    coupling: &Coupling,
    i: usize,
    pose: &BodyPose,
    committed_pose: &BodyPose,
    committed: &TangentialState,
    friction: Friction,
) -> ContactEval {
    let mut out = ContactEval::empty();
    let back = Motion::between(pose, committed_pose);
    evaluate_at(&mut out, coupling, i, pose, &back, committed, friction, true);
    out
}

/// Contact `i` at `pose` into the slot `out` ([`evaluate_into`], with the
/// tangent if `tangent`), `back` the motion from `pose` to the committed
/// pose: for callers that evaluate one contact at a time into their own
/// buffers (the dynamic solver's step, which forms `back` once for all
/// contacts and reads no tangent).
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn evaluate_at(
    out: &mut ContactEval,
    coupling: &Coupling,
    i: usize,
    pose: &BodyPose,
    back: &Motion,
    committed: &TangentialState,
    friction: Friction,
    tangent: bool,
) {
    let g = coupling.geometry(i, pose);
    let moved = Moved { du: back.displacement(&g.point), committed, friction };
    let normal = NormalPart::new(coupling, i, &g, committed, &mut out.committed_root);
    out.geometry = g;
    evaluate_into(out, coupling, i, &moved, &normal, tangent);
}

/// The rigid motion that takes the moving half from a trial pose T back to
/// the committed pose T_c, p_c = T_c T^-1 p, written as p_c - p = D p + b
/// with D = R(dq) - I, dq = q_c q^-1, and b = (t_c - t) - D t. For the unit
/// quaternion dq = (w, v), R(dq) - I = 2 w [v]x + 2 [v]x^2 (Rodrigues), so
/// D is formed without the cancellation of R - I: the small displacement
/// du = p - p_c = -(D p + b) of the contact law keeps the full relative
/// precision of the rotation and the translation increments.
#[derive(Debug, Clone, Copy)]
pub struct Motion<T: Lane = f64> {
    d: Matrix3<T>,
    b: Vector3<T>,
    /// The bodies' expansion over the increment (a thermal path's).
    thermal: Option<ThermalMotion<T>>,
}

/// The expansion terms of [`Motion::displacement`] (module docs):
/// eps_f (p - o_f) - eps_m (Q (p - t) - R_c o_m), Q = R_c R^T.
#[derive(Debug, Clone, Copy)]
struct ThermalMotion<T: Lane> {
    eps_f: T,
    o_f: Vector3<T>,
    eps_m: T,
    q: Matrix3<T>,
    t: Vector3<T>,
    rc_om: Vector3<T>,
}

/// How the two bodies expand between a trial state and the committed one
/// of a thermal path's increment: eps = (1 + alpha dT_c) / (1 + alpha dT)
/// - 1 of each body (dT_c its committed temperature change, dT the trial
///   one), and its origin.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Expansion {
    pub moving: f64,
    pub moving_origin: Vector3<f64>,
    pub fixed: f64,
    pub fixed_origin: Vector3<f64>,
}

impl Expansion {
    /// From the trial temperature changes `trial` back to `committed`.
    pub fn between(bodies: &ThermalBodies, trial: Temperatures, committed: Temperatures) -> Self {
        let eps = |alpha: f64, t: f64, c: f64| alpha * (c - t) / (1.0 + alpha * t);
        Expansion {
            moving: eps(bodies.moving.thermal_expansion, trial.moving, committed.moving),
            moving_origin: bodies.moving.origin,
            fixed: eps(bodies.fixed.thermal_expansion, trial.fixed, committed.fixed),
            fixed_origin: bodies.fixed.origin,
        }
    }
}

impl<T: Lane> Motion<T> {
    /// The motion from `pose` back to `committed` (per lane for lanes).
    pub fn between(pose: &BodyPose<T>, committed: &BodyPose<T>) -> Self {
        let dq = committed.rotation * pose.rotation.inverse();
        let (w, v) = (dq.w, dq.imag());
        // [v]x^2 = v v^T - |v|^2 I, entry by entry (no 3x3 products; the
        // diagonal -(v_j^2 + v_k^2) without cancellation).
        let (xx, yy, zz) = (v.x * v.x, v.y * v.y, v.z * v.z);
        let (two, minus_two) = (splat::<T>(2.0), splat::<T>(-2.0));
        let d = Matrix3::new(
            minus_two * (yy + zz),
            two * (v.x * v.y - w * v.z),
            two * (v.x * v.z + w * v.y),
            two * (v.y * v.x + w * v.z),
            minus_two * (xx + zz),
            two * (v.y * v.z - w * v.x),
            two * (v.z * v.x - w * v.y),
            two * (v.z * v.y + w * v.x),
            minus_two * (xx + yy),
        );
        let b = (committed.translation - pose.translation) - d * pose.translation;
        Motion { d, b, thermal: None }
    }

    /// The motion from `pose` back to `committed` with the bodies'
    /// `expansion` over the increment (module docs).
    pub fn expanding(pose: &BodyPose<T>, committed: &BodyPose<T>, expansion: &Expansion) -> Self {
        let rigid = Motion::between(pose, committed);
        let thermal = ThermalMotion {
            eps_f: splat(expansion.fixed),
            o_f: lift(&expansion.fixed_origin),
            eps_m: splat(expansion.moving),
            q: Matrix3::identity() + rigid.d,
            t: pose.translation,
            rc_om: committed.rotation * lift(&expansion.moving_origin),
        };
        Motion { thermal: Some(thermal), ..rigid }
    }

    /// du = p_f - p_m of the material points now at `p` (module docs).
    pub fn displacement(&self, p: &Vector3<T>) -> Vector3<T> {
        let rigid = -(self.d * p + self.b);
        match &self.thermal {
            None => rigid,
            Some(e) => rigid + (p - e.o_f) * e.eps_f - (e.q * (p - e.t) - e.rc_om) * e.eps_m,
        }
    }
}

/// The arguments of an evaluation besides the contact geometry at the
/// trial pose (which the slot holds, [`evaluate_into`]): tangential
/// increment du = p - p_c of the contact point ([`Motion`]), committed
/// state and friction.
#[derive(Debug, Clone, Copy)]
pub struct Moved<'s> {
    pub du: Vector3<f64>,
    pub committed: &'s TangentialState,
    pub friction: Friction,
}

/// The normal part of one contact's evaluation: approach, Hertz (with the
/// support compliance) force and stiffness, and the increment's effective
/// semi-axis for K_t with its relative derivative d(ln a_eff)/dF_n
/// (`ContactLaw::increment_semi_axis`): a1 = a(F_n) from the Hertz law's
/// square root (`SeriesNormal::force_stiffness_and_root`: F^(1/3) =
/// K^(1/3) delta^(1/2)), a0 = a(F_c) from the slot's [`CommittedRoot`]. It
/// holds the evaluation's long chains of dependent operations (square
/// root, and a cube root where a support compliance is in series);
/// [`Solver::evaluate_all`] forms it for every contact before the rest of
/// any, so that the processor overlaps the contacts' chains.
///
/// [`Solver::evaluate_all`]: crate::solve::quasistatic
#[derive(Debug, Clone, Copy, Default)]
pub struct NormalPart<T: Lane = f64> {
    pub approach: T,
    pub normal_force: T,
    pub normal_stiffness: T,
    /// d(ln a_eff)/dF_n [1/N].
    pub dlog: T,
    /// The increment's effective semi-axis a_eff [m].
    pub a_eff: T,
}

impl NormalPart {
    /// Contact `i` of `coupling` at geometry `g`, from the committed state
    /// (its force's cube root through the slot's `memo`).
    #[inline(always)]
    pub fn new(
        coupling: &Coupling,
        i: usize,
        g: &ContactGeometry,
        committed: &TangentialState,
        memo: &mut CommittedRoot,
    ) -> Self {
        Self::of_root(coupling, i, g, || memo.of(committed.normal_force))
    }
}

impl<T: Lane> NormalPart<T> {
    /// [`NormalPart::new`] with the committed force's cube root from
    /// `committed_root` (per lane for lanes).
    #[inline(always)]
    pub fn of_root(
        coupling: &Coupling,
        i: usize,
        g: &ContactGeometry<T>,
        committed_root: impl FnOnce() -> T,
    ) -> Self {
        let contact = &coupling.contacts[i];
        let approach = -g.gap;
        // Hertz in series with the support compliance (`contact::series`).
        let (fn_, kn, root) = contact.normal.force_stiffness_and_root(approach);
        let hertz = &contact.law.hertz;
        let a0 = hertz.major_semi_axis_of_root(committed_root());
        let a1 = hertz.major_semi_axis_of_root(root);
        let (a_eff, dlog) = contact.law.increment_semi_axis_of(a0, a1, fn_);
        NormalPart { approach, normal_force: fn_, normal_stiffness: kn, dlog, a_eff }
    }
}

/// Contact `i` evaluated into the slot `out` (the solvers' buffers,
/// reused across iterations: no evaluation is built and then moved), from
/// its [`NormalPart`] and the geometry at the trial pose, which the caller
/// has written into `out.geometry`. With `tangent` false the tangent (`stiffness`,
/// dK_t/dF_n and the law's derivatives) is not formed: `out.tangent` says
/// whether `out.stiffness` belongs to this evaluation. Everything else is
/// formed by the same operations either way, so a Newton iterate that
/// converges, whose tangent nobody reads, skips it.
#[inline]
pub fn evaluate_into(
    out: &mut ContactEval,
    coupling: &Coupling,
    i: usize,
    moved: &Moved,
    normal: &NormalPart,
    tangent: bool,
) {
    let g = out.geometry;
    let Moved { du, committed, friction } = *moved;
    let contact = &coupling.contacts[i];
    let NormalPart { approach, normal_force: fn_, normal_stiffness: kn, dlog, a_eff } = *normal;
    let major_axis = contact.major_axis;
    let law = &contact.law;
    let (principal, kt, dkt) =
        law.increment_stiffness(a_eff, dlog, &g.normal, &major_axis, tangent);
    let tangential_law = coupling.friction.tangential;
    let (contact_radius, mindlin_shape) =
        law.mindlin_deresiewicz_inputs(tangential_law, fn_, &g.normal, &major_axis);
    let input = TangentialInput {
        normal: g.normal,
        du,
        normal_force: fn_,
        stiffness: kt,
        principal,
        d_stiffness_d_fn: dkt,
        contact_radius,
        g_star: law.g_star,
        mindlin_shape,
        friction,
    };
    let tangential = &mut out.tangential;
    committed.update(tangential_law, &input, tangent, tangential);
    tangential.state.normal_force = fn_;
    let n = g.normal;
    // d(approach) = -n . dp, so d(F_n n) = -k_n n n^T dp and
    // d(F_t) = T dp + (dF_t/dF_n)(-k_n n^T dp); the force on the body is F_n n - F_t:
    // K = -k_n (n - dF_t/dF_n) n^T - T.
    if tangent {
        let (d_du, d_fn) = (&tangential.d_force_d_du, &tangential.d_force_d_fn);
        out.stiffness = contact_stiffness(&n, kn, d_du, d_fn);
    }
    out.tangent = tangent;
    out.force = n * fn_ - tangential.force;
    out.approach = approach;
    out.normal_force = fn_;
    out.normal_stiffness = kn;
}

/// A contact's stiffness dF/du = (dF_t/dF_n - n) (k_n n)^T - dF_t/d(du)
/// (F = n F_n - F_t its force on the fixed surface), from the normal
/// stiffness k_n and the tangential law's tangent.
#[inline(always)]
pub fn contact_stiffness<T: Lane>(
    n: &Vector3<T>,
    normal_stiffness: T,
    d_du: &Matrix3<T>,
    d_fn: &Vector3<T>,
) -> Matrix3<T> {
    (d_fn - n) * (n * normal_stiffness).transpose() - d_du
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The memo answers exactly what forming the root anew gives, for any
    /// sequence of committed forces: repeats (an increment's evaluations),
    /// changes (the next increment), zero of both signs, a negative force
    /// (an open contact), NaN, and a force of the same value after others.
    #[test]
    fn committed_root_answers_what_a_root_formed_anew_gives() {
        let forces =
            [3.7, 3.7, 3.7, 12.5, 0.0, -0.0, -2.0, f64::NAN, f64::NAN, 1e-300, 3.7, 12.5, 12.5];
        let mut memo = CommittedRoot::EMPTY;
        for f in forces {
            let got = memo.of(f);
            let anew = load_root(f);
            assert!(got.to_bits() == anew.to_bits() || (got.is_nan() && anew.is_nan()), "{f}");
        }
        let mut fresh = CommittedRoot::EMPTY;
        assert_eq!(fresh.of(8.0), 2.0);
    }
}
