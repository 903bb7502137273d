//! Seating dynamics (docs/model.md, "Seating dynamics"): the moving half is a
//! rapier3d-f64 dynamic body ([`world`]), the fixed surfaces are parry
//! shapes (colliders that touch nothing), and the compliant contact layer
//! ([`crate::solve::contact_layer`], shared with the quasi-static solver)
//! supplies every contact force, plus the dashpots of [`forces`] that let
//! the motion settle.
//!
//! Each time step n (length dt):
//! 1. read the pose x_n and velocity of the body from rapier;
//! 2. for each contact, `assembly::geometry` gives gap, normal and point
//!    at x_n (rapier's own manifolds are one step stale and its rigid
//!    contact is off); the contact layer gives the Hertz force and the
//!    stick/slip tangential force from the tangential state committed at
//!    step n-1 and the displacement of the contact point since x_(n-1);
//!    the dashpots add damping;
//! 3. the preload F(t) = lambda(t) F_p acts at its body point;
//! 4. the forces are set as user forces (reset first: rapier keeps them
//!    across steps), the tangential states and x_n are committed, and
//!    rapier advances one step: v_(n+1) = v_n + dt M^-1 F_n,
//!    x_(n+1) = x_n + dt v_(n+1) (symplectic Euler, see [`world`]).
//!
//! Friction: the decay law (`contact::friction`) sees the actual slip
//! velocity, the slip of a step over dt (of the last step while sliding). The seating here is far faster
//! than a real one (T_r below, not `[preload] ramp_time`), so with a finite
//! decay_coefficient its slip speeds, and with them mu, differ from the
//! quasi-static solver's; the two limits (coefficient 0 or very large) do not
//! depend on the speed.
//!
//! Load: lambda(t) = (t / T_r)^(3/2) for t < T_r, then 1 (the quasi-static
//! solver's schedule lambda = s^(3/2) with s = t / T_r, i.e. a uniform rate
//! of Hertz approach). T_r = `ramp_periods` periods of the fundamental mode.
//! With `ramp_periods = 0` the full preload acts from t = 0 (a step load).
//!
//! Time step: dt = T_min / `steps_per_period` (`arrival_steps_per_period`
//! for an offset or tilted start), T_min = 2 pi / omega_max the
//! period of the highest natural mode of the seated coupling at full preload
//! ([`frequency`]). Symplectic Euler is stable for omega dt < 2 and its
//! energy error is of order (omega dt)^2 (Hairer et al. 2006, §IX.8).
//!
//! Settled (checked once the ramp is over): the kinetic energy is below
//! 1/2 m (omega_min s)^2 and every ball centre and contact point moves
//! slower than omega_min s (s = `settle_displacement`: the amplitude of any
//! motion left is below s), and the net force and moment of preload and
//! contact-layer forces are below `settle_force` F_p and `settle_force`
//! F_p L. The pose at that step is the result. A contact left open then
//! means the coupling did not centre ([`SolveError::NotCentred`]).
//!
//! Defaults ([`DynamicOptions::default`]) and why: 20 steps per shortest
//! period from the touching pose (omega_max dt = 0.31: stable, zeta omega
//! dt < 1 for the explicit dashpots, energy error ~1 % undamped). There
//! the step does not set the result, the ramp does: on scenes 01, 06 and
//! 07 (ten friction vectors each) 20 steps per period move every pose by
//! at most 0.01 % of sigma from 30 steps, while halving the ramp moves it
//! by up to 3.8 % (docs/benchmarks.md, 2026-11-29). A half that arrives
//! moving strikes its seat, and the impacts load the contacts beyond the
//! preload (shorter periods): 30 steps per period for it, as before. Its
//! final pose still moves with the step: scene 01, five arrivals that
//! centre (mu = 0.2 and 0.5, offsets of 10-70 um, tilts of 0.1-0.3 mrad),
//! up to 7 nm between 30 and 120 steps per period, up to 20 nm at 20;
//! ramp of 40 fundamental periods with a smoothstep in time (the rate of
//! load vanishes at the end, so the body creeps into its final pose);
//! zeta_n = 0.3, zeta_t = 1. The dashpot carries part of the load without
//! friction while the contacts are loaded (see [`forces`]), which gives a
//! difference to the quasi-static pose of first order in the loading rate
//! and in zeta_n: measured on scene 06 (Kelvin), lateral difference 34 %
//! of sigma at 10 periods and zeta_n = 1, 10 % at 40 periods, 3 % at 40
//! periods and zeta_n = 0.3. What remains at 40 periods is mostly the
//! quasi-static solver's own increment error for the sticking Kelvin flat
//! (against 320 quasi-static increments: ~1 %).
//!
//! Initial conditions ([`StartPose`]): at rest, at the touching pose (the
//! quasi-static case) or moved from it by a tilt phi (rotation vector about
//! the scene origin) and then an offset, so that the balls land on their
//! surfaces during the motion.

pub mod forces;
pub mod frequency;
pub mod mass;
pub mod options;
pub mod simulation;
pub mod trace;
pub mod world;

use super::{ContactResult, Load, SeatedPose, Seating, SolveError};
use crate::assembly::Coupling;
use crate::assembly::friction_limit::friction_limit;
pub use forces::{Damping, StepContact};
pub use frequency::Frequencies;
pub use mass::{MassModel, MassSource};
pub use options::{DynamicOptions, StartPose};
pub use simulation::Simulation;
pub use trace::{Energy, TraceContact, TraceSample, TraceState};

/// Seat the coupling dynamically under `load`, from its start pose.
pub fn seat(
    coupling: &Coupling,
    load: &Load,
    opts: &DynamicOptions,
) -> Result<Seating, SolveError> {
    seat_with(coupling, load, opts, None)
}

/// Most time steps of one dynamic seating: 10^7, about a minute and a
/// half at some 8 us per step (a default seating takes a few thousand).
pub const MAX_STEPS: usize = 10_000_000;

/// [`seat`], calling `trace` after every step with the state at the start of it.
pub fn seat_traced(
    coupling: &Coupling,
    load: &Load,
    opts: &DynamicOptions,
    trace: &mut dyn FnMut(&TraceSample),
) -> Result<Seating, SolveError> {
    seat_with(coupling, load, opts, Some(trace))
}

/// [`seat`], with the trace sample of every step given to `trace` if
/// there is one (a seating without it builds none).
fn seat_with(
    coupling: &Coupling,
    load: &Load,
    opts: &DynamicOptions,
    mut trace: Option<&mut dyn FnMut(&TraceSample)>,
) -> Result<Seating, SolveError> {
    let mut sim = Simulation::new(coupling, load, opts)?;
    let max_time = sim.ramp_time + opts.max_settle_periods * sim.freq.longest_period();
    check_steps(&sim, max_time)?;
    loop {
        if crate::cancel::requested() {
            return Err(SolveError::Cancelled);
        }
        sim.step()?;
        if let Some(trace) = trace.as_mut() {
            trace(&sim.sample());
        }
        let travel = (sim.pose.translation - coupling.touching_pose.translation).norm();
        if travel > sim.max_travel {
            return Err(SolveError::SlidAway {
                percent: 100.0 * sim.load_fraction(sim.time_of_state()),
                displacement_m: travel,
            });
        }
        if sim.time_of_state() >= sim.ramp_time && sim.settled() {
            break;
        }
        if sim.time_of_state() > max_time {
            return Err(SolveError::NotSettled {
                time_s: sim.time_of_state(),
                steps: sim.steps,
                kinetic_j: sim.status.kinetic,
                residual: sim.status.residual,
            });
        }
    }
    let open: Vec<usize> = sim
        .contacts
        .iter()
        .enumerate()
        .filter(|(_, c)| c.eval.normal_force <= 0.0)
        .map(|(i, _)| i)
        .collect();
    if !open.is_empty() {
        let limit = friction_limit(coupling, &load.preload);
        return Err(SolveError::NotCentred {
            open: open.iter().map(|i| (i + 1).to_string()).collect::<Vec<_>>().join(", "),
            gap_m: open
                .iter()
                .map(|&i| sim.contacts[i].eval.geometry.gap)
                .fold(f64::NEG_INFINITY, f64::max),
            mu_max: load.mu.iter().copied().fold(0.0, f64::max),
            mu_limit: limit.mu_limit,
            critical_contact: limit.critical_contact,
        });
    }
    Ok(Seating {
        seated: SeatedPose {
            pose: sim.pose,
            increments: sim.steps,
            newton_iterations: 0,
            path: crate::solve::SeatingPath::Dynamic,
            decay_cv: sim.decay_cv(),
            path_error: None,
            slid: sim.slid(),
        },
        contacts: sim
            .contacts
            .iter()
            .enumerate()
            .map(|(i, c)| ContactResult::from_eval(coupling, i, &c.eval, sim.friction[i]))
            .collect(),
    })
}

/// Refuse a seating whose step count up to `max_time` is above [`MAX_STEPS`].
fn check_steps(sim: &Simulation, max_time: f64) -> Result<(), SolveError> {
    // The longest seating the time step allows: refused above the bound
    // rather than run for hours (a tiny [dynamics] mass or inertia makes
    // the shortest period, and so dt, tiny against the longest one).
    let steps = max_time / sim.dt();
    if steps.is_nan() || steps > MAX_STEPS as f64 {
        return Err(SolveError::BadOption(format!(
            "the seating may take {steps:.3e} time steps (dt = {dt:.3e} s, up to {max_time:.3e} s), \
             above the bound of {MAX_STEPS}: the shortest and longest natural periods are too far \
             apart; check [dynamics] mass and inertia (a tiny moment of inertia)",
            dt = sim.dt(),
        )));
    }
    Ok(())
}
