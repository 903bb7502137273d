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
//! A study seats one coupling many times: [`SeatingSetup`] holds what
//! every seating of it computes first (the predictor x_1, the virgin
//! contact states), and [`seat_prepared`] reuses it with the same bits.
//! A [`Workspace`] holds the buffers of one seating; [`seat_in`] reuses
//! them (one workspace per rayon worker in a study), so that a seating
//! allocates nothing once they have grown (tests/alloc_free.rs), and
//! returns the pose-level [`SeatedPose`] (the per-contact report,
//! [`Workspace::seating`], is built only on request).

mod external;
mod load;
mod lu6;
mod path;
mod solver;
pub mod uniform;

pub use external::{ExternalLoad, LoadEvent, LoadEventKind};
pub use load::{LoadPath, apply_load, at_rest_states};

use path::{Buffers, End};
use solver::{Program, Solver, contact_results};

use nalgebra::Vector6;

use super::{SeatedPose, Seating, SeatingPath, SolveError, SolverOptions, frictions_into};
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
    seat_prepared(&SeatingSetup::new(coupling), mu_s, opts)
}

/// What every seating of one coupling computes before its first
/// increment, computed once and shared (it is `Sync`) by the seatings of a
/// study: the frictionless predictor x_1 and the virgin contact states
/// (zero force, tangent to the normals at the touching pose), the same for
/// both paths (their geometries give the same bits). [`seat_prepared`] with
/// it gives the bits of [`seat`].
pub struct SeatingSetup<'a> {
    coupling: &'a Coupling,
    x1: Vector6<f64>,
    /// Virgin states at parry's normals of the touching pose.
    virgin: Vec<TangentialState>,
}

impl<'a> SeatingSetup<'a> {
    pub fn new(coupling: &'a Coupling) -> Self {
        SeatingSetup {
            coupling,
            x1: solver::predictor(coupling),
            virgin: virgin_states(coupling),
        }
    }

    pub fn coupling(&self) -> &'a Coupling {
        self.coupling
    }
}

/// The buffers of a seating, reused from one seating to the next
/// ([`seat_in`]): the per-contact frictions, states and evaluations. After
/// a seating they hold its final contacts ([`Workspace::seating`]).
#[derive(Debug, Default)]
pub struct Workspace {
    friction: Vec<Friction>,
    bufs: Buffers,
}

impl Workspace {
    pub fn new() -> Self {
        Self::default()
    }

    /// The full result of the last seating `seated` of `coupling` in this
    /// workspace, with the per-contact report (allocates it).
    pub fn seating(&self, coupling: &Coupling, seated: SeatedPose) -> Seating {
        Seating {
            pose: seated.pose,
            contacts: contact_results(coupling, &self.friction, &self.bufs.evals),
            increments: seated.increments,
            newton_iterations: seated.newton_iterations,
            path: seated.path,
        }
    }
}

/// [`seat`] of `setup`'s coupling.
pub fn seat_prepared(
    setup: &SeatingSetup,
    mu_s: &[f64],
    opts: &SolverOptions,
) -> Result<Seating, SolveError> {
    let mut ws = Workspace::new();
    let seated = seat_in(setup, mu_s, opts, &mut ws)?;
    Ok(ws.seating(setup.coupling, seated))
}

/// [`seat_prepared`] in the reused buffers of `ws`, without the
/// per-contact report: the same pose, increments and path, and no
/// allocation once `ws` has served one seating of this coupling.
pub fn seat_in(
    setup: &SeatingSetup,
    mu_s: &[f64],
    opts: &SolverOptions,
    ws: &mut Workspace,
) -> Result<SeatedPose, SolveError> {
    frictions_into(setup.coupling, mu_s, &mut ws.friction)?;
    if let Some(end) = uniform::seat(setup, &ws.friction, opts, &mut ws.bufs) {
        return Ok(seated(end, SeatingPath::Uniform));
    }
    adaptive(setup, &ws.friction, opts, &mut ws.bufs)
}

/// Seat by the adaptive path only (today's algorithm, parry's geometry):
/// the reference of the fast path in tests and benches.
pub fn seat_adaptive(
    coupling: &Coupling,
    mu_s: &[f64],
    opts: &SolverOptions,
) -> Result<Seating, SolveError> {
    let setup = SeatingSetup::new(coupling);
    let mut ws = Workspace::new();
    frictions_into(coupling, mu_s, &mut ws.friction)?;
    let seated = adaptive(&setup, &ws.friction, opts, &mut ws.bufs)?;
    Ok(ws.seating(coupling, seated))
}

fn adaptive(
    setup: &SeatingSetup,
    fr: &[Friction],
    opts: &SolverOptions,
    bufs: &mut Buffers,
) -> Result<SeatedPose, SolveError> {
    let c = setup.coupling;
    let solver = Solver::with_predictor(c, fr, *opts, Program::Seat, setup.x1);
    bufs.states.clone_from(&setup.virgin);
    let end = solver.run(c.touching_pose, bufs)?;
    let end = end.expect("the adaptive path never declines");
    Ok(seated(end, SeatingPath::Adaptive))
}

/// Zero tangential force at every contact, tangent to its normal at the
/// touching pose (parry's geometry).
fn virgin_states(coupling: &Coupling) -> Vec<TangentialState> {
    let pose = coupling.touching_pose;
    (0..coupling.contacts.len())
        .map(|i| TangentialState::new(coupling.geometry(i, &pose).normal))
        .collect()
}

fn seated(end: End, path: SeatingPath) -> SeatedPose {
    SeatedPose {
        pose: end.pose,
        increments: end.increments,
        newton_iterations: end.newton_iterations,
        path,
    }
}
