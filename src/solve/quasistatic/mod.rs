//! Quasi-static seating: the preload ramps from 0 to F_p; at each increment
//! Newton solves the six pose unknowns of the moving half so that the
//! preload and the contact forces balance (docs/model.md).
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
//!   and normals at the current pose (`assembly::geometry`). Converged when
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
//! A seating that never halves takes the nominal increments s_k = k/N
//! (`Seating::path` is then [`SeatingPath::Uniform`], else
//! [`SeatingPath::Adaptive`]). Fewer increments, or a direct solve of the
//! final equilibrium, give another answer: the Coulomb force of an
//! increment points along R F_old + K_t du, so the final force carries the
//! history of the slip direction, which is not straight (finite rotations,
//! the contact point wandering over the ball, a pin's normal turning, the
//! support compliance).
//!
//! A study seats one coupling many times: [`SeatingSetup`] holds what
//! every seating of it computes first (the predictor x_1 of the nominal
//! preload, the virgin contact states), and a [`Workspace`] the buffers of
//! one seating;
//! [`seat_in`], the seat kernel, reuses both (one workspace per rayon
//! worker in a study), so that a seating allocates nothing once they have
//! grown (tests/alloc_free.rs), and returns the pose-level [`SeatedPose`]
//! (the per-contact report, [`Workspace::seating`], is built only on
//! request). [`seat`] is the one-seating convenience that builds both and
//! the report.

mod control;
mod cycle;
mod external;
mod jacobian;
#[cfg(test)]
mod lanes_testing;
mod load;
mod lu6;
mod newton_lanes;
mod path;
mod path_lanes;
mod seat_lanes;
mod solver;
mod thermal;

pub use control::FINEST;
pub use cycle::{seat_and_cycle, seat_and_cycle_in};
pub use external::{ExternalLoad, LIFT_OFF_RATIO, LoadEvent, LoadEventKind};
pub use load::{LoadPath, apply_load, at_rest_states};
pub use seat_lanes::{LANES_ARE_FAST, Lanes, seat4_in};

use path::Buffers;
use solver::contact_results;

use nalgebra::Vector6;

use super::{Load, SeatedPose, Seating, SeatingPath, SolveError, SolverOptions, frictions_into};
use crate::assembly::BodyPose;
use crate::assembly::Coupling;
use crate::contact::{Friction, TangentialState};
use crate::scene::Preload;

/// Seat the coupling under `load` (from the touching pose), with the
/// per-contact report: [`seat_in`] in a fresh workspace.
pub fn seat(coupling: &Coupling, load: &Load, opts: &SolverOptions) -> Result<Seating, SolveError> {
    let mut ws = Workspace::new();
    let seated = seat_in(&SeatingSetup::new(coupling, &load.preload), load, opts, &mut ws)?;
    Ok(ws.seating(coupling, seated))
}

/// What every seating of one coupling under one preload computes before
/// its first increment, computed once and shared (it is `Sync`) by the
/// seatings of a study: the frictionless predictor x_1 of that preload and
/// the virgin contact states (zero force, tangent to the normals at the
/// touching pose).
pub struct SeatingSetup<'a> {
    coupling: &'a Coupling,
    preload: Preload,
    x1: Vector6<f64>,
    /// Virgin states at the normals of the touching pose.
    virgin: Vec<TangentialState>,
    /// The coupling at the temperatures thermal paths have visited.
    placements: thermal::Placements,
}

impl<'a> SeatingSetup<'a> {
    pub fn new(coupling: &'a Coupling, preload: &Preload) -> Self {
        SeatingSetup {
            coupling,
            preload: preload.clone(),
            x1: solver::predictor(coupling, preload),
            virgin: virgin_states(coupling),
            placements: thermal::Placements::default(),
        }
    }

    pub fn coupling(&self) -> &'a Coupling {
        self.coupling
    }
}

/// The preload a seating ramps and its frictionless predictor x_1.
#[derive(Clone, Copy)]
pub(super) struct Ramp<'a> {
    pub preload: &'a Preload,
    pub x1: Vector6<f64>,
}

/// The buffers of a seating, reused from one seating to the next
/// ([`seat_in`]): the per-contact frictions, states and evaluations. After
/// a seating they hold its final contacts ([`Workspace::seating`]).
#[derive(Debug, Default)]
pub struct Workspace {
    friction: Vec<Friction>,
    bufs: Buffers,
    /// The pose the buffers' states belong to after a seating: its last
    /// level's (a controlled seating reports the Richardson pose instead),
    /// where a thermal path continues (`cycle`).
    rest_pose: BodyPose,
}

impl Workspace {
    pub fn new() -> Self {
        Self::default()
    }

    /// The full result of the last seating `seated` of `coupling` in this
    /// workspace, with the per-contact report (allocates it).
    pub fn seating(&self, coupling: &Coupling, seated: SeatedPose) -> Seating {
        Seating { seated, contacts: contact_results(coupling, &self.friction, &self.bufs.evals) }
    }
}

/// The seat kernel: seat `setup`'s coupling under `load` in the reused
/// buffers of `ws`, without the per-contact report (no allocation once
/// `ws` has served one seating of this coupling, whatever the load's
/// preload: a preload other than the setup's gets its predictor here,
/// without allocating).
pub fn seat_in(
    setup: &SeatingSetup,
    load: &Load,
    opts: &SolverOptions,
    ws: &mut Workspace,
) -> Result<SeatedPose, SolveError> {
    frictions_into(setup.coupling, &load.mu, &mut ws.friction)?;
    let ramp = Ramp {
        preload: &load.preload,
        x1: match load.preload == setup.preload {
            true => setup.x1,
            false => solver::predictor(setup.coupling, &load.preload),
        },
    };
    if let Some(tolerance) = opts.path_tolerance {
        return control::seat_controlled(setup, ramp, opts, tolerance, ws);
    }
    let end = control::level(setup, ramp, opts, opts.increments, ws)?;
    ws.rest_pose = end.pose;
    Ok(SeatedPose {
        pose: end.pose,
        increments: end.increments,
        newton_iterations: end.newton_iterations,
        path: path_of(end.halved),
        decay_cv: end.decay_cv,
        path_error: None,
        slid: end.slid,
    })
}

/// The path that served a quasi-static seating: adaptive where an
/// increment was halved, else uniform.
fn path_of(halved: bool) -> SeatingPath {
    if halved { SeatingPath::Adaptive } else { SeatingPath::Uniform }
}

/// Zero tangential force at every contact, tangent to its normal at the
/// touching pose.
fn virgin_states(coupling: &Coupling) -> Vec<TangentialState> {
    let pose = coupling.touching_pose;
    (0..coupling.contacts.len())
        .map(|i| TangentialState::new(coupling.geometry(i, &pose).normal))
        .collect()
}
