//! Quasi-static seating: the preload ramps from 0 to F_p; at each increment
//! Newton solves the six pose unknowns of the moving half so that the
//! preload and the contact forces balance (MODEL.md §3).
//!
//! - Load schedule: lambda = s^(3/2) with s in uniform steps, so that every
//!   increment adds about the same Hertz approach (delta ~ F^(2/3)).
//! - Predictor: the linearised frictionless solution, x(lambda) = s x_1,
//!   where W x_1 = -(f_i / K_i)^(2/3) - c_i f_i (W the constraint rows, f_i
//!   the frictionless contact forces at full preload, c_i the support
//!   compliances).
//! - Corrector: Newton on R(x) = sum_i [F_i; p_i x F_i] + [P; p_P x P] = 0
//!   with the consistent tangent of the contact layer plus the geometric
//!   terms of moving points; finite rotations (quaternions), contact points
//!   and normals from parry at the current pose. Converged when
//!   |R_F| < tol F_p and |R_M| < tol F_p L (L the coupling radius).
//! - Time: the path parameter s runs from 0 to 1 in `[preload] ramp_time`
//!   T (t = s T, so lambda = (t/T)^(3/2): a uniform rate of Hertz
//!   approach); an increment from s to s' lasts (s' - s) T, the time base
//!   of the slip velocity of the decay friction law (`contact::friction`).
//!   A load path after seating ramps its load in the same time T.
//! - Adaptivity: an increment is halved when Newton fails, and when a
//!   contact changes between stick and slip, until that change is located
//!   within 2^-max_splits of a nominal increment.
//!
//! The same path follower applies an external load after seating
//! ([`apply_load`]): it starts from the seated pose and the at-rest contact
//! states ([`at_rest_states`]), holds the full preload, and ramps an extra
//! wrench (a force at a point of the moving half and a moment) from 0 to a
//! load factor in equal increments, with the same Newton corrector and
//! halving. Instead of failing, it records the first contact that
//! separates (F_n reaches 0) or starts to slip (|F_t| reaches mu_s F_n) as
//! a [`LoadEvent`]; a separation that leaves no equilibrium (the coupling
//! lifts off) ends the path there.
//!
//! A seating first tries the uniform fast path ([`uniform`]): the same
//! increments without halving, closed-form contact geometry; where the
//! adaptive path would halve, it declines and the adaptive path runs
//! (`Seating::path` says which one served). [`seat_adaptive`] always takes
//! the adaptive path (today's algorithm, the reference of the fast one).

mod load;
mod path;
mod solver;
pub mod uniform;

pub use load::{ExternalLoad, LoadEvent, LoadEventKind, LoadPath, apply_load, at_rest_states};

use path::End;
use solver::{Program, Solver};

use super::{Seating, SeatingPath, SolveError, SolverOptions, frictions};
use crate::assembly::Coupling;
use crate::contact::{Friction, TangentialState};

/// Seat the coupling with static coefficients `mu_s` (contact order): the
/// uniform fast path where it serves, else the adaptive path; the same
/// answer either way (to rounding, [`uniform`]).
pub fn seat(
    coupling: &Coupling,
    mu_s: &[f64],
    opts: &SolverOptions,
) -> Result<Seating, SolveError> {
    let fr = frictions(coupling, mu_s)?;
    if let Some(end) = uniform::seat(coupling, &fr, opts) {
        return Ok(seating(end, SeatingPath::Uniform));
    }
    adaptive(coupling, fr, opts)
}

/// Seat by the adaptive path only (today's algorithm, parry's geometry):
/// the reference of the fast path in tests and benches.
pub fn seat_adaptive(
    coupling: &Coupling,
    mu_s: &[f64],
    opts: &SolverOptions,
) -> Result<Seating, SolveError> {
    adaptive(coupling, frictions(coupling, mu_s)?, opts)
}

fn adaptive(
    coupling: &Coupling,
    fr: Vec<Friction>,
    opts: &SolverOptions,
) -> Result<Seating, SolveError> {
    let solver = Solver::adaptive(coupling, fr, *opts, Program::Seat);
    let end = solver.run(coupling.touching_pose, virgin_states(&solver))?;
    let end = end.expect("the adaptive path never declines");
    Ok(seating(end, SeatingPath::Adaptive))
}

/// Zero tangential force at every contact, tangent to its normal at the
/// touching pose.
fn virgin_states(solver: &Solver) -> Vec<TangentialState> {
    let pose = solver.coupling.touching_pose;
    (0..solver.coupling.contacts.len())
        .map(|i| {
            let g = solver.geometry.geometry(solver.coupling, i, &pose);
            TangentialState::new(g.normal)
        })
        .collect()
}

fn seating(end: End, path: SeatingPath) -> Seating {
    Seating {
        pose: end.pose,
        contacts: end.contacts,
        increments: end.increments,
        newton_iterations: end.newton_iterations,
        path,
    }
}
