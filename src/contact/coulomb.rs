//! The history-dependent Coulomb stick/slip law: return mapping with its
//! consistent tangent, over Mindlin's elastic stiffness.
//!
//! Elastic stiffness: Mindlin's exact 2x2 tangential stiffness of the contact
//! ellipse (`contact::mindlin`), as the 3x3 tensor
//! K_t = k_major e1 e1^T + k_minor e2 e2^T in the tangent plane (e1 the major
//! axis; K_t = 8 G* a (I - n n^T) for a circle).
//!
//! Coulomb return mapping (Simo & Hughes, *Computational Inelasticity*,
//! 1998, §2.2 applied to the tangential force; Wriggers, *Computational
//! Contact Mechanics*, 2006, §5.2):
//! ```text
//! F_trial = R F_old + K_t du_t           (R rotates the old force into the new tangent plane)
//! stick  if |F_trial| <= mu F_n,   mu = mu_s (was sticking) or mu_d (was sliding)
//! slip   otherwise: F = the point of |F| = mu_d F_n closest to F_trial in the
//!        complementary-energy norm of K_t (mu_d F_n F_trial/|F_trial| for a circle)
//! ```
//! The change from mu_s to mu_d is sudden, as in the paper's FE model
//! (`law = "switch"`); `law = "decay"` makes the sliding coefficient depend
//! on the slip velocity of the increment ([`super::friction`]).
//!
//! Sign convention: `du` is the tangential displacement of the moving body
//! relative to the fixed surface at the contact, and the law's force is the
//! tangential force along it that the moving body exerts on the fixed
//! surface (a spring stretched by du). The friction force on the moving
//! body is its negative.
//!
//! The law's arithmetic ([`coulomb`]) is written over lanes (one contact of
//! several seatings: lane i is bit for bit the f64 law of lane i's inputs,
//! a lane that sticks and one that slips in the same call included);
//! [`update`] is its f64 form on the shared tangential types.

use nalgebra::{Matrix3, Vector3};
use simba::simd::SimdValue;

use super::friction::{FrictionLaw, SlideLanes, Sliding, slide_lanes};
use super::mindlin::{PrincipalStiffness, RadialReturn};
use super::tangential_types::{SlipState, TangentialInput, TangentialResponse, TangentialState};
use crate::lane::{Both, Lane, Mask, branch, splat};

/// Coulomb return mapping into `out`, with its consistent tangent if
/// `tangent` (else `out`'s derivatives are left as they were; the force and
/// state are formed by the same operations either way): [`coulomb`] of
/// the committed state `old` and the increment `input`.
#[inline(always)]
pub fn update(
    old: &TangentialState,
    input: &TangentialInput,
    tangent: bool,
    out: &mut TangentialResponse,
) {
    let fr = input.friction;
    let x = CoulombInput {
        old_force: old.force,
        was_sliding: old.sliding,
        previous_velocity: old.slip_velocity,
        normal: input.normal,
        du: input.du,
        normal_force: input.normal_force,
        stiffness: input.stiffness,
        principal: input.principal,
        d_stiffness_d_fn: input.d_stiffness_d_fn,
        mu_s: fr.mu_s,
        mu_d: fr.mu_d,
        law: fr.law,
        duration: fr.duration,
    };
    let (y, tangents) = coulomb(&x, tangent);
    if let Some((d_du, d_fn)) = tangents {
        (out.d_force_d_du, out.d_force_d_fn) = (d_du, d_fn);
    }
    out.force = y.force;
    out.state.assign_from(old, y.force, y.sliding, y.slip_velocity);
    out.slip = if y.sliding { SlipState::Slip } else { SlipState::Stick };
}

/// What the Coulomb law reads of one contact (per lane over lanes): the
/// committed state (its force rotated into the new tangent plane), the
/// increment, Mindlin's stiffness and the friction.
#[derive(Debug, Clone, Copy)]
pub struct CoulombInput<T: Lane> {
    pub old_force: Vector3<T>,
    pub was_sliding: Mask<T>,
    pub previous_velocity: T,
    pub normal: Vector3<T>,
    pub du: Vector3<T>,
    pub normal_force: T,
    pub stiffness: Matrix3<T>,
    pub principal: PrincipalStiffness<T>,
    pub d_stiffness_d_fn: Matrix3<T>,
    pub mu_s: T,
    pub mu_d: T,
    /// The friction law and the increment's duration [s] (every lane's).
    pub law: FrictionLaw,
    pub duration: f64,
}

/// The Coulomb law's force, whether it slides, and its slip velocity.
#[derive(Debug, Clone, Copy)]
pub struct CoulombOutput<T: Lane> {
    pub force: Vector3<T>,
    pub sliding: Mask<T>,
    pub slip_velocity: T,
}

/// The Coulomb law (module docs), with its tangent (dF/d(du), dF/dF_n)
/// if `tangent`. The sliding coefficient
/// comes from the friction law ([`super::friction::slide`]: the sudden
/// switch, or the decay law). The increment is `du` without its normal
/// part. The decay law's slip increment uses the stiffness along the
/// trial force, k = t^T K_t t (t = F_trial/|F_trial|): exact for a
/// circular contact, the stiffness of the load direction for an
/// elliptical one.
///
/// A circular contact (`principal` without axes, K_t = k (I - n n^T))
/// uses K_t's closed forms ([`Circle`]) instead of the 3x3 tensor; an
/// elliptical one projects in its principal axes
/// ([`PrincipalStiffness::project`]).
#[inline(always)]
pub fn coulomb<T: Lane>(
    x: &CoulombInput<T>,
    tangent: bool,
) -> (CoulombOutput<T>, Option<Tangent<T>>) {
    let n = x.normal;
    let du = &(x.du - n * n.dot(&x.du));
    let circle = Circle::of(&x.principal);
    let trial = x.old_force
        + match circle {
            Some(c) => c.times(du),
            None => x.stiffness * du,
        };
    let norm = trial.norm();
    // The switch law reads no stiffness (`friction::slide`).
    let positive = norm.simd_gt(T::zero());
    let k_along = match (x.law, circle) {
        (FrictionLaw::Switch, _) => T::zero(),
        (FrictionLaw::Decay { .. }, Some(c)) => c.k.select(positive, T::zero()),
        (FrictionLaw::Decay { .. }, None) => {
            let t = (trial / norm).select(positive, trial);
            t.dot(&(x.stiffness * t))
        }
    };
    let (slides, s) = slide_lanes(&SlideLanes {
        mu_s: x.mu_s,
        mu_d: x.mu_d,
        law: x.law,
        duration: x.duration,
        trial: norm,
        normal_force: x.normal_force,
        stiffness: k_along,
        was_sliding: x.was_sliding,
        previous_velocity: x.previous_velocity,
    });
    let limit = s.mu * x.normal_force;
    let slip_velocity = s.slip / splat::<T>(x.duration);
    if !tangent {
        let slip = |_| match circle {
            Some(_) => RadialReturn::new(&n, &trial, limit).force(),
            None => x.principal.project(&n, &trial, limit).0,
        };
        let force = branch::<T, _>(slides, slip, |_| trial);
        let slip_velocity = slip_velocity.select(slides, T::zero());
        return (CoulombOutput { force, sliding: slides, slip_velocity }, None);
    }
    let stick = |_| {
        let d_fn = match circle {
            Some(_) => du * Circle::d_k_d_fn(&x.d_stiffness_d_fn),
            None => x.d_stiffness_d_fn * du,
        };
        Both(trial, Both(x.stiffness, d_fn))
    };
    let slip = |_| {
        let (force, (d_du, d_fn)) = match circle {
            Some(c) => {
                let r = RadialReturn::new(&n, &trial, limit);
                (r.force(), c.slide_tangent(&r, du, x, &s))
            }
            None => {
                let (force, d_trial, d_limit) = x.principal.project(&n, &trial, limit);
                (force, slide_tangent(&trial, du, x, &s, &d_trial, &d_limit))
            }
        };
        Both(force, Both(d_du, d_fn))
    };
    let Both(force, Both(d_du, d_fn)) = branch::<T, _>(slides, slip, stick);
    let slip_velocity = slip_velocity.select(slides, T::zero());
    (CoulombOutput { force, sliding: slides, slip_velocity }, Some((d_du, d_fn)))
}

/// The tangent of the law: dF/d(du) and dF/dF_n.
pub type Tangent<T> = (Matrix3<T>, Vector3<T>);

/// The elastic stiffness of a circular contact, K_t = k (I - n n^T)
/// (Mindlin's k_major = k_minor, [`PrincipalStiffness`] without axes), by
/// its one value k. The closed forms below are exact mathematically
/// because every vector the law applies K_t to lies in the tangent plane
/// (n . v = 0, so (I - n n^T) v = v): the increment du (its normal part
/// removed by [`coulomb`]), the old force (rotated
/// into the plane) and so the trial force and its direction t.
#[derive(Debug, Clone, Copy)]
struct Circle<T: Lane> {
    k: T,
}

impl<T: Lane> Circle<T> {
    #[inline]
    fn of(p: &PrincipalStiffness<T>) -> Option<Self> {
        p.axes.is_none().then_some(Circle { k: p.k[0] })
    }

    /// K_t v = k v for v in the tangent plane.
    #[inline]
    fn times(self, v: &Vector3<T>) -> Vector3<T> {
        v * self.k
    }

    /// c of dK_t/dF_n = c (I - n n^T): K_t = k(F_n) (I - n n^T) with n
    /// independent of F_n, and trace(I - n n^T) = 3 - |n|^2 = 2, so
    /// c = trace(dK_t/dF_n) / 2 (then dK_t/dF_n v = c v in the plane).
    #[inline]
    fn d_k_d_fn(dk: &Matrix3<T>) -> T {
        splat::<T>(0.5) * (dk[(0, 0)] + dk[(1, 1)] + dk[(2, 2)])
    }

    /// [`slide_tangent`] for a circular contact, from the radial return
    /// `r` (L = mu F_n, T = |F_trial|, t in the plane, so that
    /// dF/dF_trial = (L/T) (I - n n^T - t t^T) =: (L/T) Q and dF/dL = t).
    /// With Q (I - n n^T) = Q, t^T (I - n n^T) = t^T, Q du = du - t (t . du)
    /// and dK_t/dF_n = c (I - n n^T):
    /// ```text
    /// dF/d(du) = (L/T) k Q + F_n (dmu/dT) k t t^T
    /// dF/dF_n  = (mu + F_n dmu/dF_n) t + (L/T) c (du - t (t . du))
    /// dmu/dF_n = dmu/dT c (t . du) + dmu/dF_n|_T,k + dmu/dk c
    /// ```
    /// Returns (dF/d(du), dF/dF_n).
    #[inline]
    fn slide_tangent(
        self,
        r: &RadialReturn<T>,
        du: &Vector3<T>,
        x: &CoulombInput<T>,
        s: &Sliding<T>,
    ) -> (Matrix3<T>, Vector3<T>) {
        let (f_n, t, k) = (x.normal_force, r.t, self.k);
        let c = Self::d_k_d_fn(&x.d_stiffness_d_fn);
        let t_du = t.dot(du);
        let in_plane = (du - t * t_du) * (r.ratio * c);
        let d_du = r.scaled_plane(&x.normal, r.ratio * k);
        // A constant coefficient (the switch law, a sliding decay contact).
        let Both(d_du, d_fn) = branch::<T, _>(
            s.constant_mask(),
            |_| Both(d_du, t * s.mu + in_plane),
            |_| {
                let dmu_dfn = s.d_mu_d_trial * c * t_du + s.d_mu_d_fn + s.d_mu_d_k * c;
                let d_du = d_du + (t * (f_n * s.d_mu_d_trial * k)) * t.transpose();
                Both(d_du, t * (s.mu + f_n * dmu_dfn) + in_plane)
            },
        );
        (d_du, d_fn)
    }
}

/// The tangent of gross sliding. The force F is the point on the circle
/// |F| = mu F_n closest to F_trial in the complementary-energy norm of K
/// ([`PrincipalStiffness::project`]; the radial return
/// F = mu F_n F_trial/|F_trial| for a circular contact), so that the
/// friction force opposes the slip also for an elliptical K; mu from the
/// friction law (`s`; constant mu_d for the switch law); `d_trial` and
/// `d_limit` are the projection's dF/dF_trial and dF/dL. Tangent, with
/// T = |F_trial|, t = F_trial/T and L = mu F_n the limit:
/// dF/d(du) = (dF/dF_trial) K + (dF/dL) F_n (dmu/dT) t^T K,
/// dF/dF_n = (dF/dL) (mu + F_n dmu/dF_n) + (dF/dF_trial) (dK/dF_n) du,
/// dmu/dF_n total through T (dT/dF_n = t . K' du), F_n and k (dk/dF_n = t^T K' t).
/// Returns (dF/d(du), dF/dF_n).
#[inline]
fn slide_tangent<T: Lane>(
    trial: &Vector3<T>,
    du: &Vector3<T>,
    x: &CoulombInput<T>,
    s: &Sliding<T>,
    d_trial: &Matrix3<T>,
    d_limit: &Vector3<T>,
) -> (Matrix3<T>, Vector3<T>) {
    let f_n = x.normal_force;
    let (k, dk) = (&x.stiffness, &x.d_stiffness_d_fn);
    let (mu, d_trial, d_limit) = (s.mu, *d_trial, *d_limit);
    let dk_du = dk * du;
    let Both(d_du, d_fn) = branch::<T, _>(
        s.constant_mask(),
        // A constant coefficient (the switch law, a sliding decay contact).
        |_| Both(d_trial * k, d_limit * mu + d_trial * dk_du),
        |_| {
            let t = trial.normalize();
            let dmu_dfn =
                s.d_mu_d_trial * t.dot(&dk_du) + s.d_mu_d_fn + s.d_mu_d_k * t.dot(&(dk * t));
            let dt_ddu = k.transpose() * t; // dT/d(du) as a column
            Both(
                d_trial * k + (d_limit * (f_n * s.d_mu_d_trial)) * dt_ddu.transpose(),
                d_limit * (mu + f_n * dmu_dfn) + d_trial * dk_du,
            )
        },
    );
    (d_du, d_fn)
}
