//! A thermal path through the load's temperature cycle after the seating
//! (docs/model.md, "Thermal drift"): leg by leg (`super::thermal`), from
//! the seated state with every contact's tangential history. The coupling
//! is at rest at the seated state and at every cycle point (the
//! temperature dwells there): a contact that slid sticks until |F_t|
//! reaches mu_s F_n again, as after `at_rest_states`.
//!
//! Error control (`[thermal] path_tolerance`, [`Load::thermal_tolerance`]):
//! each leg runs on n = 2, 4, 8, ... uniform increments from the same
//! start until the estimated error of its end pose,
//!
//! ```text
//! err = |x_n - x_{n/2}|_L / max(|x_seated - x_0|_L, |x_n - x_start|_L) + M tol_Newton
//! ```
//!
//! is within the tolerance (|.|_L and M as the seating's,
//! `super::control`); the leg reports x_n and the next leg continues from
//! it with its states. A leg's error carries into the legs after it, so a
//! cycle point's `path_error` is the sum of its own and the earlier legs'
//! estimates. The legs converge at first order or faster in 1/n (first
//! order while the friction forces still turn towards their slip, faster
//! once they have turned), so |x_n - x_{n/2}| bounds the error of x_n;
//! a first-order Richardson step would overshoot where the order is
//! higher, and none is taken. On fixed increments (no path tolerance)
//! every leg takes the nominal increments once, without an estimate.
//!
//! Where the levels start: the first leg at n = 4, the later ones at
//! n = 2. In the first leg every contact breaks away from its seated
//! state and its force turns from the seating direction into the
//! direction of the thermal slip, which the return map follows at first
//! order in the increment; a level of 2 increments is not accepted there
//! (the bundled aluminium-on-Invar scene: |x_4 - x_2| = 3.8e-3 of the
//! motion, |x_8 - x_4| = 6.5e-4). A later leg reverses or continues that
//! slip along the same line, a proportional path the return map follows
//! exactly, and 2 + 4 increments meet the tolerance. Only the work
//! depends on the start; every level is checked the same way.
//!
//! Newton tolerance of a controlled leg: tol_Newton = [`NEWTON_SHARE`]
//! times the thermal path tolerance (or the seating's Newton tolerance if
//! that is looser). Each increment's equilibrium is solved to a residual
//! of tol_Newton F_p, a pose error of about tol_Newton of the motion, and
//! these add along the leg: the term M tol_Newton of `err` above (M the
//! leg's increments) stays below 1/30 of the tolerance up to 32
//! increments, and is reported in `path_error`.

use super::control::size;
use super::path::Buffers;
use super::solver::twist_between;
use super::thermal::{Leg, LegEnd};
use super::{FINEST, SeatingSetup, Workspace, seat_in};
use crate::assembly::{BodyPose, Coupling};
use crate::contact::{Friction, TangentialState};
use crate::scene::Temperatures;
use crate::solve::thermal::{CyclePoint, FirstSlip, ThermalPath};
use crate::solve::{Load, SeatedPose, Seating, SolveError, SolverOptions};

/// The first level of a controlled leg after the first (module docs).
const FIRST: usize = 2;

/// The first level of the first leg of a path (module docs).
const FIRST_OF_PATH: usize = 4;

/// The Newton tolerance of a controlled leg as a share of the thermal path
/// tolerance (module docs).
pub const NEWTON_SHARE: f64 = 1e-3;

/// Seat `coupling` under `load` and follow `load.cycle`, with the
/// seating's per-contact report: [`seat_and_cycle_in`] in a fresh workspace.
pub fn seat_and_cycle(
    coupling: &Coupling,
    load: &Load,
    opts: &SolverOptions,
) -> Result<(Seating, ThermalPath), SolveError> {
    coupling.thermal_bodies()?;
    let mut ws = Workspace::new();
    let setup = SeatingSetup::new(coupling, &load.preload);
    let seated = seat_in(&setup, load, opts, &mut ws)?;
    let seating = ws.seating(coupling, seated);
    let path = cycle_after(&setup, load, opts, true, &mut ws)?;
    Ok((seating, path))
}

/// The study kernel: seat `setup`'s coupling under `load` in `ws`
/// ([`seat_in`]) and follow `load.cycle` from that seating, with the
/// couplings placed at the cycle's temperatures kept in `setup` for the
/// next sample; the first slip is not located (a study does not report
/// it).
pub fn seat_and_cycle_in(
    setup: &SeatingSetup,
    load: &Load,
    opts: &SolverOptions,
    ws: &mut Workspace,
) -> Result<(SeatedPose, ThermalPath), SolveError> {
    let seated = seat_in(setup, load, opts, ws)?;
    let path = cycle_after(setup, load, opts, false, ws)?;
    Ok((seated, path))
}

/// The cycle from the seating `ws` holds (its last level's pose and states).
fn cycle_after(
    setup: &SeatingSetup,
    load: &Load,
    opts: &SolverOptions,
    locate_first_slip: bool,
    ws: &mut Workspace,
) -> Result<ThermalPath, SolveError> {
    let coupling = setup.coupling();
    let bodies = coupling.thermal_bodies()?;
    let start = ws.rest_pose;
    let (friction, bufs) = (&ws.friction, &mut ws.bufs);
    let length = coupling.length_scale();
    let seat_motion = size(&twist_between(&coupling.touching_pose, &start), length);
    let (mut pose, mut from, mut carried) = (start, Temperatures::ZERO, 0.0);
    let mut points = Vec::with_capacity(load.cycle.len());
    let mut first_slip = None;
    let mut saved = Vec::new();
    for (k, &to) in load.cycle.iter().enumerate() {
        let leg = Leg {
            base: coupling,
            placements: &setup.placements,
            locate_first_slip,
            bodies,
            friction,
            preload: &load.preload,
            opts: leg_options(opts, load),
            sticking_tolerance: opts.tolerance,
            from,
            to,
        };
        at_rest(&mut bufs.states, friction);
        let reached = match opts.path_tolerance {
            None => Reached::fixed(leg.run(opts.increments, pose, bufs)?),
            Some(_) => {
                let scale = Scale { seat_motion, length, tolerance: load.thermal_tolerance };
                let first = if k == 0 { FIRST_OF_PATH } else { FIRST };
                controlled(&leg, first, pose, &scale, &mut carried, bufs, &mut saved)?
            }
        };
        let end = &reached.end;
        first_slip = first_slip.or(end.first_slip.map(|(s, contact)| FirstSlip {
            contact: contact + 1,
            temperatures: from.towards(to, s),
            cycle_point: k + 1,
        }));
        points.push(CyclePoint {
            temperatures: to,
            pose: reached.pose,
            path_error: reached.path_error,
            slipping: (0..end.slid.len()).filter(|&i| end.slid[i]).map(|i| i + 1).collect(),
            increments: reached.increments,
            newton_iterations: reached.newton_iterations,
        });
        pose = end.pose;
        from = to;
    }
    Ok(ThermalPath { start, points, first_slip })
}

/// The solver options of a leg: under error control, the Newton
/// tolerance `NEWTON_SHARE` times the thermal path tolerance (module
/// docs), or the seating's if that is looser; on fixed increments the
/// seating's options.
fn leg_options(opts: &SolverOptions, load: &Load) -> SolverOptions {
    match opts.path_tolerance {
        Some(_) => SolverOptions {
            tolerance: opts.tolerance.max(NEWTON_SHARE * load.thermal_tolerance),
            ..*opts
        },
        None => *opts,
    }
}

/// The seated states at rest: a contact with friction sticks (static
/// friction governs again, at zero slip velocity); one without stays
/// sliding. Each keeps its force and history.
fn at_rest(states: &mut [TangentialState], friction: &[Friction]) {
    for (st, f) in states.iter_mut().zip(friction) {
        st.sliding = f.mu_s == 0.0;
        st.slip_velocity = 0.0;
    }
}

/// One leg as reported: the end the next leg continues from, the
/// reported pose and its error, the work of all its levels.
struct Reached {
    end: LegEnd,
    pose: BodyPose,
    path_error: Option<f64>,
    increments: usize,
    newton_iterations: usize,
}

impl Reached {
    /// A leg on fixed increments: its end as it is.
    fn fixed(end: LegEnd) -> Self {
        Reached {
            pose: end.pose,
            path_error: None,
            increments: end.increments,
            newton_iterations: end.newton_iterations,
            end,
        }
    }
}

/// What a controlled leg's error is measured against (module docs).
struct Scale {
    seat_motion: f64,
    length: f64,
    tolerance: f64,
}

/// A leg under error control from `start`, its levels from `first`
/// increments (module docs); the states at its start are `bufs.states`
/// (kept in `saved` for each level), the earlier legs' error `carried`
/// (this leg's is added).
fn controlled(
    leg: &Leg,
    first: usize,
    start: BodyPose,
    scale: &Scale,
    carried: &mut f64,
    bufs: &mut Buffers,
    saved: &mut Vec<TangentialState>,
) -> Result<Reached, SolveError> {
    saved.clone_from(&bufs.states);
    let mut n = first;
    let mut coarse = leg.run(n, start, bufs)?;
    let (mut increments, mut iterations) = (coarse.increments, coarse.newton_iterations);
    loop {
        n *= 2;
        bufs.states.clone_from(saved);
        let fine = leg.run(n, start, bufs)?;
        increments += fine.increments;
        iterations += fine.newton_iterations;
        let d = twist_between(&coarse.pose, &fine.pose);
        let motion = size(&twist_between(&start, &fine.pose), scale.length);
        let reference = scale.seat_motion.max(motion);
        let change = if reference > 0.0 { size(&d, scale.length) / reference } else { 0.0 };
        let floor = fine.increments as f64 * leg.opts.tolerance;
        if change + floor <= scale.tolerance || n >= FINEST {
            *carried += change;
            return Ok(Reached {
                pose: fine.pose,
                path_error: Some(*carried + floor),
                increments,
                newton_iterations: iterations,
                end: fine,
            });
        }
        coarse = fine;
    }
}
