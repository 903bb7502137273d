//! The fast path of the quasi-static seating: the nominal increments
//! s_k = k / N, k = 1..N, without halving, with parry's contact arithmetic
//! written out (`assembly::parry_inline`) instead of parry's dispatched
//! query. It declines (returns `None`) at the first point where the
//! adaptive path would do anything else, and the adaptive path
//! ([`super::seat_adaptive`]) then seats from scratch.
//!
//! # Why it is the adaptive path's answer, bit for bit
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
//! reports it). The contact geometry is parry's: the same IEEE operations
//! in the same order as parry's query for a ball on a half-space, a
//! capsule (a pin) and a ball, so the same bits
//! (`tests/scenes.rs`, `parry_inline_is_parrys_query_bit_for_bit`, 21000
//! random cases); where parry would take a branch that is not written out
//! (a ball centre inside a pin, say), parry itself is asked. So, increment
//! by increment, both paths evaluate the same functions at the same
//! arguments and give the same bits: tests/fast_path.rs finds the pose of
//! the fast path equal to the adaptive path's in every component for 1000
//! friction vectors of every bundled scene (difference 0; the issue asks
//! for 1e-12 of the motion, and the adaptive path itself moves by 1.5e-12
//! to 7e-12 of its motion when every mu moves by one ulp).
//!
//! The argument does not use the contact law: it holds for Coulomb and
//! Mindlin-Deresiewicz, the switch and the decay friction law, and any
//! support compliance, because the history integrals are the adaptive
//! path's own (same increments, same midpoint stiffness, same return
//! mapping): measured 0 difference for Mindlin-Deresiewicz and the decay
//! law too. As both paths compute the same bits, a stick/slip decision or
//! a Newton stop cannot fall differently in the two.
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
    solver.geometry = GeometrySource::Inline;
    solver.uniform = true;
    bufs.states.clone_from(&setup.virgin);
    solver.run(coupling.touching_pose, bufs).ok().flatten()
}
