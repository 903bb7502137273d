//! Load-path error control of a seating (`SolverOptions::path_tolerance`).
//!
//! The path follower is first order in its increment: the friction force
//! of an increment points along R F_old + K_t du (a backward-Euler step of
//! the slip-direction history), so a seating on N increments differs from
//! the limit of the path by about C / N. The increment's K_t integrates
//! Mindlin's stiffness exactly along a proportional path
//! (`ContactLaw::increment_semi_axis`), which leaves the turning of the
//! slip directions and the contact geometry. A controlled seating takes
//! its increments uniform in t = sqrt(s) (lambda = t^3, approach ~ t^2,
//! k_t ~ t: smooth in t), where the error of the seated pose x_N behaves
//! as C_1 h with h = 1/N: it halves per doubling of N on every bundled
//! scene.
//!
//! The controller seats on N = 3, 6, 12, ... graded increments, each
//! level from the touching pose, and after every level N >= 6 forms
//!
//! ```text
//! d   = x_N - x_{N/2}                  (a twist: `twist_between`)
//! x*  = x_N + d                        (Richardson, first order)
//! err = |d|_L / |x_N - x_0|_L + M tol_Newton
//! ```
//!
//! where |(v, w)|_L = sqrt(|v|^2 + L^2 |w|^2) is the size of a twist with
//! its rotation scaled by the coupling radius L (v the translation of the
//! moving half's reference point), x_0 the touching pose, M the
//! increments of level N and tol_Newton the Newton tolerance (each
//! increment's equilibrium is solved to a residual of tol_Newton F_p, a
//! pose error of about tol_Newton of the motion, and these add along the
//! history). It stops at the first level with err <= tolerance (or at
//! [`FINEST`] increments) and reports x* with `path_error` = err.
//!
//! err estimates the error of x_N (with x_N = x + C_1 h + C_2 h^2,
//! d = -(C_1 h + 3 C_2 h^2)); x* removes the first-order part, so err
//! bounds the error left. Measured against the limit of the fixed path
//! (first-order Richardson of 2560 and 5120 uniform increments,
//! tests/it/path_control.rs) the true error is below err for 200 of 200
//! friction vectors of scene 06 and 199 of 200 of scene 02 (the exception
//! 3.0e-9 against 1.6e-9, at the Newton floor). A contact that changes between stick
//! and slip is located by halving inside every level (`path`), to
//! 2^-max_splits of its increment. On every bundled scene the first pair,
//! 3 + 6 increments, meets the default tolerance.

use nalgebra::Vector6;

use super::path::End;
use super::solver::{Program, Solver, twist_between};
use super::{Ramp, SeatingSetup, Workspace};
use crate::solve::{SeatedPose, SolveError, SolverOptions};

/// The coarsest level's graded increments.
const FIRST: usize = 3;
/// The finest level (3 x 2^11): a seating stops here even above its
/// tolerance (its `path_error` says so).
pub const FINEST: usize = 6144;

/// One seating on `n` increments (graded where `opts` control the path),
/// from the touching pose and the virgin states; its contacts stay in `ws`.
pub(super) fn level(
    setup: &SeatingSetup,
    ramp: Ramp,
    opts: &SolverOptions,
    n: usize,
    ws: &mut Workspace,
) -> Result<End, SolveError> {
    let c = setup.coupling;
    let opts = SolverOptions { increments: n, ..*opts };
    let solver = Solver::new(c, &ws.friction, ramp.preload, opts, Program::Seat, ramp.x1);
    ws.bufs.states.clone_from(&setup.virgin);
    solver.run(c.touching_pose, &mut ws.bufs)
}

/// |(v, w)|_L of the twist `t` (module docs).
pub(super) fn size(t: &Vector6<f64>, length: f64) -> f64 {
    let v = t.fixed_rows::<3>(0).norm();
    let w = t.fixed_rows::<3>(3).norm();
    v.hypot(length * w)
}

/// Seat to `tolerance` (module docs); `ws.friction` holds the frictions.
pub(super) fn seat_controlled(
    setup: &SeatingSetup,
    ramp: Ramp,
    opts: &SolverOptions,
    tolerance: f64,
    ws: &mut Workspace,
) -> Result<SeatedPose, SolveError> {
    let c = setup.coupling;
    let length = c.length_scale();
    let mut n = FIRST;
    let first = level(setup, ramp, opts, n, ws)?;
    let mut coarse = first.pose;
    let (mut increments, mut iterations, mut halved) =
        (first.increments, first.newton_iterations, first.halved);
    loop {
        n *= 2;
        let fine = level(setup, ramp, opts, n, ws)?;
        increments += fine.increments;
        iterations += fine.newton_iterations;
        halved |= fine.halved;
        // d = x_N - x_{N/2}, which x* = x_N + d adds (module docs).
        let d = twist_between(&coarse, &fine.pose);
        let motion = size(&twist_between(&c.touching_pose, &fine.pose), length);
        let change = size(&d, length);
        let floor = fine.increments as f64 * opts.tolerance;
        let error = if motion > 0.0 { change / motion } else { 0.0 } + floor;
        if error <= tolerance || n >= FINEST {
            ws.rest_pose = fine.pose;
            return Ok(SeatedPose {
                pose: fine.pose.moved(&d.fixed_rows::<3>(0).into(), &d.fixed_rows::<3>(3).into()),
                increments,
                newton_iterations: iterations,
                path: super::path_of(halved),
                path_error: Some(error),
                decay_cv: fine.decay_cv,
                slid: fine.slid,
            });
        }
        coarse = fine.pose;
    }
}
