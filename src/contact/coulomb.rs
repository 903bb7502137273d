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

use nalgebra::{Matrix3, Vector3};

use super::friction::{FrictionLaw, SlideInput, Sliding};
use super::mindlin::{PrincipalStiffness, RadialReturn};
use super::tangential_types::{SlipState, TangentialInput, TangentialResponse, TangentialState};

/// Coulomb return mapping into `out`, with its consistent tangent if
/// `tangent` (else `out`'s derivatives are left as they were; the force and
/// state are formed by the same operations either way); the sliding
/// coefficient comes from the friction law ([`super::friction::slide`]:
/// the sudden switch, or the decay law). The increment is `input.du`
/// without its normal part. The decay law's slip increment uses the
/// stiffness along the trial force, k = t^T K_t t (t = F_trial/|F_trial|):
/// exact for a circular contact, the stiffness of the load direction for
/// an elliptical one.
///
/// A circular contact (`input.principal` without axes, K_t = k (I - n n^T))
/// uses K_t's closed forms ([`Circle`]) instead of the 3x3 tensor; an
/// elliptical one projects in its principal axes
/// ([`PrincipalStiffness::project`]).
#[inline]
pub fn update(
    old: &TangentialState,
    input: &TangentialInput,
    tangent: bool,
    out: &mut TangentialResponse,
) {
    let n = input.normal;
    let du = &(input.du - n * n.dot(&input.du));
    let fr = input.friction;
    let circle = Circle::of(&input.principal);
    let trial = old.force
        + match circle {
            Some(c) => c.times(du),
            None => input.stiffness * du,
        };
    let norm = trial.norm();
    // The switch law reads no stiffness (`friction::slide`).
    let k_along = match (fr.law, circle) {
        (FrictionLaw::Switch, _) => 0.0,
        (FrictionLaw::Decay { .. }, Some(c)) => c.along(norm),
        (FrictionLaw::Decay { .. }, None) => {
            let t = if norm > 0.0 { trial / norm } else { trial };
            t.dot(&(input.stiffness * t))
        }
    };
    let sliding = super::friction::slide(&SlideInput {
        mu_s: fr.mu_s,
        mu_d: fr.mu_d,
        law: fr.law,
        duration: fr.duration,
        trial: norm,
        normal_force: input.normal_force,
        stiffness: k_along,
        was_sliding: old.sliding,
        previous_velocity: old.slip_velocity,
    });
    let Some(s) = sliding else {
        out.force = trial;
        out.state.assign_from(old, trial, false, 0.0);
        out.slip = SlipState::Stick;
        if tangent {
            out.d_force_d_du = input.stiffness;
            out.d_force_d_fn = match circle {
                Some(_) => du * Circle::d_k_d_fn(input),
                None => input.d_stiffness_d_fn * du,
            };
        }
        return;
    };
    let limit = s.mu * input.normal_force;
    let force = match circle {
        Some(c) => {
            let r = RadialReturn::new(&input.normal, &trial, limit);
            if tangent {
                c.slide_tangent(&r, du, input, &s, out);
            }
            r.force()
        }
        None => {
            let (force, d_trial, d_limit) = input.principal.project(&input.normal, &trial, limit);
            if tangent {
                slide_tangent(&trial, du, input, &s, &d_trial, &d_limit, out);
            }
            force
        }
    };
    out.force = force;
    out.state.assign_from(old, force, true, s.slip / input.friction.duration);
    out.slip = SlipState::Slip;
}

/// The elastic stiffness of a circular contact, K_t = k (I - n n^T)
/// (Mindlin's k_major = k_minor, [`PrincipalStiffness`] without axes), by
/// its one value k. The closed forms below are exact mathematically
/// because every vector the law applies K_t to lies in the tangent plane
/// (n . v = 0, so (I - n n^T) v = v): the increment du (its normal part
/// removed by [`update`]), the old force (rotated
/// into the plane) and so the trial force and its direction t.
#[derive(Debug, Clone, Copy)]
struct Circle {
    k: f64,
}

impl Circle {
    #[inline]
    fn of(p: &PrincipalStiffness) -> Option<Self> {
        p.axes.is_none().then_some(Circle { k: p.k[0] })
    }

    /// K_t v = k v for v in the tangent plane.
    #[inline]
    fn times(self, v: &Vector3<f64>) -> Vector3<f64> {
        v * self.k
    }

    /// t^T K_t t = k (1 - (n . t)^2) = k for the unit direction t of a
    /// nonzero in-plane trial force of length `norm` (0 for a zero one,
    /// whose t is the zero vector).
    #[inline]
    fn along(self, norm: f64) -> f64 {
        if norm > 0.0 { self.k } else { 0.0 }
    }

    /// c of dK_t/dF_n = c (I - n n^T): K_t = k(F_n) (I - n n^T) with n
    /// independent of F_n, and trace(I - n n^T) = 3 - |n|^2 = 2, so
    /// c = trace(dK_t/dF_n) / 2 (then dK_t/dF_n v = c v in the plane).
    #[inline]
    fn d_k_d_fn(input: &TangentialInput) -> f64 {
        let dk = &input.d_stiffness_d_fn;
        0.5 * (dk[(0, 0)] + dk[(1, 1)] + dk[(2, 2)])
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
    #[inline]
    fn slide_tangent(
        self,
        r: &RadialReturn,
        du: &Vector3<f64>,
        input: &TangentialInput,
        s: &Sliding,
        out: &mut TangentialResponse,
    ) {
        let (f_n, t, k) = (input.normal_force, r.t, self.k);
        let c = Self::d_k_d_fn(input);
        let t_du = t.dot(du);
        let in_plane = (du - t * t_du) * (r.ratio * c);
        out.d_force_d_du = r.scaled_plane(&input.normal, r.ratio * k);
        if s.d_mu_d_trial == 0.0 && s.d_mu_d_fn == 0.0 && s.d_mu_d_k == 0.0 {
            // A constant coefficient (the switch law, a sliding decay contact).
            out.d_force_d_fn = s.mu * t + in_plane;
        } else {
            let dmu_dfn = s.d_mu_d_trial * c * t_du + s.d_mu_d_fn + s.d_mu_d_k * c;
            out.d_force_d_du += (t * (f_n * s.d_mu_d_trial * k)) * t.transpose();
            out.d_force_d_fn = (s.mu + f_n * dmu_dfn) * t + in_plane;
        }
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
#[inline]
fn slide_tangent(
    trial: &Vector3<f64>,
    du: &Vector3<f64>,
    input: &TangentialInput,
    s: &Sliding,
    d_trial: &Matrix3<f64>,
    d_limit: &Vector3<f64>,
    out: &mut TangentialResponse,
) {
    let f_n = input.normal_force;
    let (k, dk) = (&input.stiffness, &input.d_stiffness_d_fn);
    let (mu, d_trial, d_limit) = (s.mu, *d_trial, *d_limit);
    let dk_du = dk * du;
    let (d_force_d_du, d_force_d_fn) =
        if s.d_mu_d_trial == 0.0 && s.d_mu_d_fn == 0.0 && s.d_mu_d_k == 0.0 {
            // A constant coefficient (the switch law, a sliding decay contact).
            (d_trial * k, mu * d_limit + d_trial * dk_du)
        } else {
            let t = trial.normalize();
            let dmu_dfn =
                s.d_mu_d_trial * t.dot(&dk_du) + s.d_mu_d_fn + s.d_mu_d_k * t.dot(&(dk * t));
            let dt_ddu = k.transpose() * t; // dT/d(du) as a column
            (
                d_trial * k + (d_limit * (f_n * s.d_mu_d_trial)) * dt_ddu.transpose(),
                (mu + f_n * dmu_dfn) * d_limit + d_trial * dk_du,
            )
        };
    out.d_force_d_du = d_force_d_du;
    out.d_force_d_fn = d_force_d_fn;
}
