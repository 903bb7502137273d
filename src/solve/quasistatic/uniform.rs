//! The fast path of the quasi-static seating: the nominal increments
//! s_k = k / N, k = 1..N, without halving, with closed-form contact
//! geometry instead of parry's query. It declines (returns `None`) at the
//! first point where the adaptive path would do anything else, and the
//! adaptive path ([`super::seat_adaptive`]) then seats from scratch.
//!
//! # Why it is the adaptive path's answer
//!
//! The adaptive path ([`super::path`]) starts with the nominal increment
//! h = 1/N. Its step size changes only at two decisions: it halves h when
//! Newton fails on an increment, or when a contact that carried load
//! changes between stick and slip (located to 2^-max_splits of h); and it
//! doubles h (capped at 1/N) after a quiet increment. When neither halving
//! fires on any increment, h stays 1/N, so the accepted increments are
//! exactly s_k = k/N (the same floating-point sums s + h), each started from
//! the same predictor (the frictionless x_1 for the first, the secant of the
//! last accepted increment after), corrected by the same Newton iteration
//! on the same residual with the same consistent tangent, and committed
//! with the same contact states. This path runs that very code
//! ([`Solver::run`] with `uniform` set) and gives up where a halving would
//! fire, or where the path would end in an error (the adaptive path then
//! reports it). So, increment by increment, both evaluate the same
//! functions at the same arguments; the one difference is the geometry:
//! the closed forms of `assembly::geometry` (gap and normal of a ball on a
//! plane, a cylinder or a sphere) instead of parry's query, which agree to
//! ~1e-17 m (`parry_contact_matches_closed_form`). Such a rounding
//! difference is amplified where a small quantity is a difference of
//! positions ~0.04 m: the gap (an approach of ~1e-6 m resolved to ~1e-11
//! relative). The tangential increment du = p - p_c no longer is one (it is
//! formed from the rotation and translation increments, `contact_layer::
//! Motion`); the adaptive path's floor against itself (a one-ulp change of
//! mu) is 1.5e-12 to 6e-12 of the seating's motion. Measured over 1000
//! friction vectors per bundled scene (tests/fast_path.rs): at most 6.2e-11
//! of the seating's motion (scene 01; 7e-12 on scenes 02-07), the
//! increments equal. The 1e-12 is below what two float evaluations
//! of this model with different geometry code agree to.
//!
//! The argument does not use the contact law: it holds for Coulomb and
//! Mindlin-Deresiewicz, the switch and the decay friction law, and any
//! support compliance, because the history integrals are the adaptive
//! path's own (same increments, same midpoint stiffness, same return
//! mapping). The decay law amplifies the rounding a further step (its slip
//! velocity is a difference of forces over an increment): measured 1.7e-10
//! of the motion there. The one way the answers could part is a stick/slip
//! decision or a Newton stop that lies within rounding of its threshold, so
//! that one path halves and the other does not; tests/fast_path.rs would
//! see it (none in 7000 seatings).
//!
//! # Why not a direct solve of the final equilibrium
//!
//! A one-shot solve of the all-sliding equilibrium (F_t = mu_d F_n along
//! the total slip) is not the adaptive path's answer: the Coulomb force of
//! an increment points along R F_old + K_t du, so the final force direction
//! carries the whole history of the slip direction, and the slip path of a
//! contact point is not straight (finite rotations, the contact point
//! wandering over the ball, the normal of a pin turning as the ball moves
//! round it, the support compliance adding c F ~ s^1.5 to the Hertz
//! approach ~ s). Measured (bench friction vector, 20 vs 1 increments):
//! scene 01 differs by 3e-7 relative in x, scene 02 by 2.5e-3, scene 06 by
//! 0.4; 20 vs 40 increments by 5e-9, 3e-5 and 1e-2. No solve with fewer
//! increments can match the 20-increment path to 1e-12, so the fast path
//! keeps its increments and saves on each one instead.

use super::SeatingSetup;
use super::path::{Buffers, End};
use super::solver::{Program, Solver};
use crate::contact::Friction;
use crate::solve::SolverOptions;
use crate::solve::contact_layer::GeometrySource;

/// The seating on the uniform path, or `None` where it declines; the
/// states and evaluations are left in `bufs`.
pub(super) fn seat(
    setup: &SeatingSetup,
    friction: &[Friction],
    opts: &SolverOptions,
    bufs: &mut Buffers,
) -> Option<End> {
    let coupling = setup.coupling;
    let mut solver = Solver::with_predictor(coupling, friction, *opts, Program::Seat, setup.x1);
    solver.geometry = GeometrySource::ClosedForm;
    solver.uniform = true;
    bufs.states.clone_from(&setup.virgin_closed_form);
    solver.run(coupling.touching_pose, bufs).ok().flatten()
}
