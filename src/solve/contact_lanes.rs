//! The contact layer over lanes: one contact of several seatings at once,
//! one seating per lane ([`crate::lane`]), for the Coulomb law. It is the
//! composition of [`super::contact_layer::evaluate_into`] for that law,
//! from the same functions: the geometry at each lane's pose
//! (`Coupling::geometry`), the normal part (`NormalPart::of_root`), the
//! increment's tangential stiffness
//! (`ContactLaw::increment_stiffness_lanes`), the committed force turned
//! into the new tangent plane (`Rotation`), the law
//! (`contact::coulomb::coulomb`) and the contact's force and stiffness
//! (`contact_layer::contact_stiffness`, which the f64 layer calls too), so that lane i is
//! bit for bit the f64 evaluation of lane i's seating (tests/it/lanes.rs).
//!
//! What the lanes do not follow, [`evaluate_lanes`] answers with `None`
//! (that set of seatings is then seated one by one): the
//! Mindlin-Deresiewicz law (its spring rows), an anisotropic support
//! compliance, and lanes that differ in the form of K_t (circle or
//! ellipse: the contact's, but an elliptical contact unloaded before and
//! after the increment has k = 0, a circle, in the lanes where it is open).

use nalgebra::{Matrix3, Vector3};
use simba::simd::{SimdBool, SimdValue};

use crate::assembly::{ContactGeometry, Coupling};
use crate::contact::coulomb::{CoulombInput, coulomb};
use crate::contact::tangential_types::Rotation;
use crate::contact::{Friction, FrictionLaw, TangentialLaw, TangentialState};
use crate::lane::{Lane, Mask, gather};
use crate::solve::contact_layer::{NormalPart, contact_stiffness};

/// The committed tangential state of one contact, per lane: the
/// [`TangentialState`] of the Coulomb law.
#[derive(Debug, Clone, Copy)]
pub struct LaneState<T: Lane> {
    pub normal: Vector3<T>,
    pub force: Vector3<T>,
    pub sliding: Mask<T>,
    pub normal_force: T,
    pub slip_velocity: T,
}

impl<T: Lane> LaneState<T> {
    /// Lane i holds `states[i]` (one state per lane).
    pub fn from_states(states: &[&TangentialState]) -> Self {
        LaneState {
            normal: gather(states.iter().map(|s| s.normal)),
            force: gather(states.iter().map(|s| s.force)),
            sliding: gather(states.iter().map(|s| s.sliding)),
            normal_force: gather(states.iter().map(|s| s.normal_force)),
            slip_velocity: gather(states.iter().map(|s| s.slip_velocity)),
        }
    }

    /// Lane i's state.
    pub fn lane(&self, i: usize) -> TangentialState {
        TangentialState {
            normal: self.normal.map(|x| x.extract(i)),
            force: self.force.map(|x| x.extract(i)),
            sliding: self.sliding.extract(i),
            row: None,
            normal_force: self.normal_force.extract(i),
            slip_velocity: self.slip_velocity.extract(i),
        }
    }
}

/// The friction of one contact, per lane (the law and the increment's
/// duration [s] are every lane's).
#[derive(Debug, Clone, Copy)]
pub struct LaneFriction<T: Lane> {
    pub mu_s: T,
    pub mu_d: T,
    pub law: FrictionLaw,
    pub duration: f64,
}

impl<T: Lane> LaneFriction<T> {
    /// Lane i holds `frictions[i]` (the law and the duration are the
    /// first's: a coupling's contacts share their law, an increment its
    /// duration).
    pub fn from_frictions(frictions: &[&Friction]) -> Self {
        LaneFriction {
            mu_s: gather(frictions.iter().map(|f| f.mu_s)),
            mu_d: gather(frictions.iter().map(|f| f.mu_d)),
            law: frictions[0].law,
            duration: frictions[0].duration,
        }
    }
}

/// One contact evaluated in lanes: [`super::contact_layer::ContactEval`]
/// of the Coulomb law, per lane.
#[derive(Debug, Clone, Copy)]
pub struct LaneContact<T: Lane> {
    pub geometry: ContactGeometry<T>,
    pub approach: T,
    pub normal_force: T,
    pub normal_stiffness: T,
    /// The trial tangential state (its force the law's).
    pub state: LaneState<T>,
    /// The contact's force on the fixed surface and its stiffness dF/du
    /// (zero without the tangent).
    pub force: Vector3<T>,
    pub stiffness: Matrix3<T>,
}

/// Contact `i` of `coupling` in lanes at geometry `g`, displaced by `du`
/// from the `committed` state (whose normal force's cube root is
/// `committed_root`), with the tangent if `tangent`; `None` where the
/// lanes cannot follow (module docs).
#[allow(clippy::too_many_arguments)]
#[inline]
pub fn evaluate_lanes<T: Lane>(
    coupling: &Coupling,
    i: usize,
    g: ContactGeometry<T>,
    du: Vector3<T>,
    committed: &LaneState<T>,
    committed_root: T,
    friction: &LaneFriction<T>,
    tangent: bool,
) -> Option<LaneContact<T>> {
    if coupling.friction.tangential != TangentialLaw::Coulomb {
        return None;
    }
    let contact = &coupling.contacts[i];
    let np = NormalPart::of_root(coupling, i, &g, || committed_root);
    let (principal, kt, dkt) = contact.law.increment_stiffness_lanes(
        np.a_eff,
        np.dlog,
        &g.normal,
        &contact.major_axis,
        tangent,
    )?;
    // The committed force turned into the new tangent plane
    // (`TangentialState::rotated_to`: kept where the normal is the same).
    let (m, n) = (committed.normal, g.normal);
    let same = m.x.simd_eq(n.x) & m.y.simd_eq(n.y) & m.z.simd_eq(n.z);
    let turned = Rotation::between(&m, &n).apply(&committed.force);
    let old_force = if same.all() { committed.force } else { committed.force.select(same, turned) };
    let x = CoulombInput {
        old_force,
        was_sliding: committed.sliding,
        previous_velocity: committed.slip_velocity,
        normal: n,
        du,
        normal_force: np.normal_force,
        stiffness: kt,
        principal,
        d_stiffness_d_fn: dkt,
        mu_s: friction.mu_s,
        mu_d: friction.mu_d,
        law: friction.law,
        duration: friction.duration,
    };
    let (y, tangents) = coulomb(&x, tangent);
    // An open contact (F_n <= 0) carries no friction and keeps no history
    // (`TangentialState::update`).
    let open = np.normal_force.simd_le(T::zero());
    let zero = Vector3::zeros();
    let ft = zero.select(open, y.force);
    let stiffness = match tangents {
        Some((d_du, d_fn)) => {
            let d_du = Matrix3::zeros().select(open, d_du);
            contact_stiffness(&n, np.normal_stiffness, &d_du, &zero.select(open, d_fn))
        }
        None => Matrix3::zeros(),
    };
    let state = LaneState {
        normal: n,
        force: ft,
        sliding: y.sliding & !open,
        normal_force: np.normal_force,
        slip_velocity: T::zero().select(open, y.slip_velocity),
    };
    Some(LaneContact {
        geometry: g,
        approach: np.approach,
        normal_force: np.normal_force,
        normal_stiffness: np.normal_stiffness,
        state,
        force: n * np.normal_force - ft,
        stiffness,
    })
}
