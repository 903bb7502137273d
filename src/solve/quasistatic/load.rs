//! A load applied after seating ([`apply_load`]): the at-rest contact
//! states and the path of the external wrench (its data types are in
//! `external`).

use nalgebra::{Vector3, Vector6};

use super::external::{ExternalLoad, LIFT_OFF_RATIO, LoadEvent, LoadEventKind};
use super::path::{Buffers, Walk};
use super::solver::{Program, Solver, contact_results};
use crate::assembly::{BodyPose, Coupling};
use crate::contact::{SlipState, TangentialState};
use crate::solve::contact_layer::ContactEval;
use crate::solve::{ContactResult, Load, Seating, SolveError, SolverOptions};

/// The end of a load path.
#[derive(Debug, Clone, PartialEq)]
pub struct LoadPath {
    /// Load factor reached (the requested one unless a separation ended the path).
    pub factor: f64,
    pub pose: BodyPose,
    pub contacts: Vec<ContactResult>,
    pub states: Vec<TangentialState>,
    pub first_event: Option<LoadEvent>,
    /// Why the path ended before the requested factor, after its first
    /// event (a slipping coupling that slides away or loses equilibrium).
    pub stopped: Option<SolveError>,
    pub increments: usize,
    pub newton_iterations: usize,
}

/// The at-rest contact states after a seating: each contact keeps its
/// tangential force, and static friction governs again (a contact that was
/// sliding sticks until |F_t| reaches mu_s F_n). A frictionless contact
/// stays sliding (it carries no tangential force). The Mindlin-Deresiewicz
/// law rebuilds its springs as a virgin loading to that force.
pub fn at_rest_states(seating: &Seating) -> Vec<TangentialState> {
    seating
        .contacts
        .iter()
        .map(|c| {
            let n = Vector3::from(c.normal);
            // The law's force is the one the moving body exerts: minus the reported one.
            let force = -Vector3::from(c.tangential_force);
            TangentialState {
                force,
                sliding: c.mu_static == 0.0,
                normal_force: c.normal_force_n,
                ..TangentialState::new(n)
            }
        })
        .collect()
}

/// Apply `external` x `factor` to the coupling seated under `seated` at
/// `start` with contact states `states` (usually [`at_rest_states`] of
/// that seating), holding its full preload with its friction
/// coefficients. The external load ramps from 0 in `opts.increments`
/// equal steps.
pub fn apply_load(
    coupling: &Coupling,
    seated: &Load,
    start: &BodyPose,
    states: &[TangentialState],
    external: &ExternalLoad,
    factor: f64,
    opts: &SolverOptions,
) -> Result<LoadPath, SolveError> {
    let fr = seated.frictions(coupling)?;
    if states.len() != coupling.contacts.len() {
        return Err(SolveError::MuCount { expected: coupling.contacts.len(), got: states.len() });
    }
    let program = Program::Load { load: *external, factor };
    let solver = Solver::new(coupling, &fr, &seated.preload, *opts, program, Vector6::zeros());
    let mut bufs = Buffers { states: states.to_vec(), ..Buffers::default() };
    let end = solver.run(*start, &mut bufs)?;
    Ok(LoadPath {
        factor: end.reached * factor,
        pose: end.pose,
        contacts: contact_results(coupling, &fr, &bufs.evals),
        states: bufs.states,
        first_event: end.event,
        stopped: end.stopped,
        increments: end.increments,
        newton_iterations: end.newton_iterations,
    })
}

impl Solver<'_> {
    /// The first contact event of a solved load increment: a separation
    /// (F_n <= 0) before a slip of a contact with friction.
    pub(super) fn first_event(&self, evals: &[ContactEval]) -> Option<(usize, LoadEventKind)> {
        if let Some(i) = evals.iter().position(|e| e.normal_force <= 0.0) {
            return Some((i + 1, LoadEventKind::Separation));
        }
        evals
            .iter()
            .zip(self.friction)
            .position(|(e, f)| f.mu_s > 0.0 && e.slip() == SlipState::Slip)
            .map(|i| (i + 1, LoadEventKind::Slip))
    }

    /// A load increment that cannot be solved even at the smallest step,
    /// right after a contact has lost nearly all its normal force, is a
    /// lift-off: the separating contact leaves the moving half without
    /// equilibrium (no friction holds it). The contact is the one whose
    /// normal force has fallen furthest, if below [`LIFT_OFF_RATIO`] of its
    /// seated value.
    pub(super) fn lift_off(
        &self,
        walk: &Walk,
        start_fn: &[f64],
        s_next: f64,
        factor: f64,
    ) -> Option<LoadEvent> {
        let (i, ratio) = walk
            .evals
            .iter()
            .zip(start_fn)
            .enumerate()
            .map(|(i, (e, f0))| (i, e.normal_force / f0.max(f64::MIN_POSITIVE)))
            .min_by(|a, b| a.1.total_cmp(&b.1))?;
        (ratio < LIFT_OFF_RATIO).then_some(LoadEvent {
            contact: i + 1,
            kind: LoadEventKind::Separation,
            previous: walk.s * factor,
            factor: s_next * factor,
        })
    }
}
