//! The path follower ([`Solver::run`]): increments in the path
//! parameter s, halved on Newton failure and on a stick/slip change of a
//! loaded contact, doubled back to the nominal size after a quiet one
//! (module docs of [`super`]). A seating under load-path error control
//! (`SolverOptions::path_tolerance`) takes its increments uniform in
//! t = sqrt(s) instead, s = t^2 (`super::control`). The contact states and evaluations live in
//! the caller's [`Buffers`] (reused from seating to seating, no allocation
//! once they have grown to the coupling's contact count); the path's end
//! leaves the committed ones there.

use nalgebra::Vector6;

use super::external::LoadEvent;
use super::solver::{Loads, Program, Solver, Step, twist_between};
use crate::assembly::BodyPose;
use crate::contact::friction;
use crate::contact::{SlipState, TangentialState};
use crate::solve::SolveError;
use crate::solve::contact_layer::ContactEval;

/// The buffers of a path: the committed states (the start states on
/// entry, the final ones on return), the committed evaluations, and the
/// trial evaluations of the increment being solved.
#[derive(Debug, Default)]
pub(super) struct Buffers {
    pub states: Vec<TangentialState>,
    pub evals: Vec<ContactEval>,
    pub trial: Vec<ContactEval>,
    /// Each contact's slip summed over the path [m] (slip velocity times
    /// increment duration): the decay law's v_slip ([`End::decay_cv`]).
    pub slip_path: Vec<f64>,
}

/// The end of a path; its contact states and evaluations are in the
/// [`Buffers`] the path ran in.
pub(super) struct End {
    pub pose: BodyPose,
    /// Path parameter s reached.
    pub reached: f64,
    pub event: Option<LoadEvent>,
    /// Why a load path ended before its factor (after its first event).
    pub stopped: Option<SolveError>,
    pub increments: usize,
    pub newton_iterations: usize,
    /// Whether an increment was halved (else the path took the nominal
    /// increments s_k = k/N).
    pub halved: bool,
    /// Whether a contact slid in an accepted increment.
    pub slid: bool,
    /// The decay law's c v_slip of the path (`friction::seating_cv`).
    pub decay_cv: Option<f64>,
}

/// The committed state of a path between increments.
pub(super) struct Walk<'w> {
    pub pose: BodyPose,
    pub states: &'w mut Vec<TangentialState>,
    /// The contacts at `pose` where `committed` (a seating's slots hold
    /// the last seating's contacts before its first increment: they are
    /// kept, not cleared, so that no slot is made anew).
    pub evals: &'w mut Vec<ContactEval>,
    /// Whether `evals` hold the contacts at `pose`.
    pub committed: bool,
    /// Each contact's slip so far [m] ([`Buffers::slip_path`]).
    pub slip_path: &'w mut Vec<f64>,
    /// Path parameter reached.
    pub s: f64,
    pub event: Option<LoadEvent>,
    /// Accepted increments and Newton iterations so far.
    pub accepted: usize,
    pub iterations: usize,
    pub halved: bool,
    /// Whether a contact slid in an accepted increment so far.
    pub slid: bool,
}

impl<'w> Walk<'w> {
    /// A path at `pose` with nothing accepted yet.
    fn at(
        pose: BodyPose,
        states: &'w mut Vec<TangentialState>,
        evals: &'w mut Vec<ContactEval>,
        slip_path: &'w mut Vec<f64>,
    ) -> Self {
        Walk {
            pose,
            states,
            evals,
            committed: false,
            slip_path,
            s: 0.0,
            event: None,
            accepted: 0,
            iterations: 0,
            halved: false,
            slid: false,
        }
    }
}

/// What stays fixed along a path.
struct Context {
    start: BodyPose,
    /// Normal forces at the start of a load path.
    start_fn: Vec<f64>,
    /// Load factor of a load path (1 for a seating).
    factor: f64,
    seating: bool,
}

/// An increment's verdict.
enum Verdict {
    /// Accepted, with whether a contact changed between stick and slip.
    Accept(bool),
    /// Halve the increment and try again.
    Halve,
    /// The path ends here.
    Stop(SolveError),
}

/// Accept an increment lasting `duration` [s]: the trial evaluations and
/// states become the committed ones, and each contact's slip velocity times
/// `duration` adds to its slip path. Returns the increment's twist and its
/// length in s.
fn commit(
    w: &mut Walk,
    trial: &mut Vec<ContactEval>,
    new_pose: BodyPose,
    (s_next, duration): (f64, f64),
) -> (Vector6<f64>, f64) {
    for ((st, e), path) in w.states.iter_mut().zip(trial.iter()).zip(w.slip_path.iter_mut()) {
        st.clone_from(&e.tangential.state);
        *path += st.slip_velocity * duration;
        w.slid |= st.sliding;
    }
    let step = (twist_between(&w.pose, &new_pose), s_next - w.s);
    w.pose = new_pose;
    std::mem::swap(w.evals, trial);
    w.committed = true;
    w.accepted += 1;
    w.s = s_next;
    step
}

/// Whether a contact that carried load changed between stick and slip. A
/// change is located by halving; from zero load it is not: Hertz force,
/// Mindlin stiffness and the Coulomb limit all scale with the same power of
/// the approach along a proportional path, so a fresh contact sticks or
/// slips from the first load on.
fn stick_slip_changed(w: &Walk, trial: &[ContactEval]) -> bool {
    trial.iter().zip(w.states.iter()).enumerate().any(|(i, (e, st))| {
        (e.slip() == SlipState::Slip) != st.sliding
            && w.committed
            && w.evals.get(i).is_some_and(|old| old.normal_force > 0.0)
    })
}

impl Solver<'_> {
    /// Follow the path from `start`; the start states are `bufs.states`.
    pub(super) fn run(&self, start: BodyPose, bufs: &mut Buffers) -> Result<End, SolveError> {
        let seating = self.program == Program::Seat;
        let nominal = 1.0 / self.opts.increments.max(1) as f64;
        let h_min = nominal / f64::powi(2.0, self.opts.max_splits as i32);
        bufs.slip_path.clear();
        bufs.slip_path.resize(bufs.states.len(), 0.0);
        let trial = &mut bufs.trial;
        let mut w = Walk::at(start, &mut bufs.states, &mut bufs.evals, &mut bufs.slip_path);
        if !seating {
            self.evaluate_all(&start, &start, w.states, self.ramp_time, true, w.evals);
            w.committed = true;
        }
        let ctx = Context {
            start,
            start_fn: match seating {
                true => Vec::new(),
                false => w.evals.iter().map(|e| e.normal_force).collect(),
            },
            factor: match self.program {
                Program::Seat | Program::Hold => 1.0,
                Program::Load { factor, .. } => factor,
            },
            seating,
        };
        let graded = seating && self.opts.path_tolerance.is_some();
        let mut h = nominal;
        // The increments are uniform in t: t = s, or t = sqrt(s) graded.
        let mut t = 0.0;
        let mut last_step: Option<(Vector6<f64>, f64)> = None;
        while w.s < 1.0 {
            let t_next = if t + h > 1.0 - 1e-12 { 1.0 } else { t + h };
            let s_next = if graded { t_next * t_next } else { t_next };
            let (predictor, loads) = self.increment(&w, last_step, s_next, seating);
            let can_halve = h > h_min * 1.5;
            let step = self.newton(&w.pose, w.states, predictor, &loads, trial);
            let verdict = match step {
                Step::Failed(_) if can_halve => Verdict::Halve,
                Step::Failed(residual) => {
                    let load = loads.lambda.max(loads.extra);
                    return self.dead_end(&ctx, w, s_next, load, residual);
                }
                Step::Converged(new_pose, its) => {
                    w.iterations += its;
                    let changed = stick_slip_changed(&w, trial);
                    if changed && can_halve {
                        Verdict::Halve
                    } else {
                        self.judge(&ctx, &mut w, &new_pose, trial, &loads)
                            .unwrap_or(Verdict::Accept(changed))
                    }
                }
            };
            match verdict {
                Verdict::Halve => {
                    h *= 0.5;
                    w.halved = true;
                }
                Verdict::Stop(err) => return self.stop(err, w),
                Verdict::Accept(changed) => {
                    let Step::Converged(new_pose, _) = step else {
                        unreachable!("only a converged increment is accepted")
                    };
                    let span = (s_next, loads.duration);
                    last_step = Some(commit(&mut w, trial, new_pose, span));
                    t = t_next;
                    if !changed {
                        h = (2.0 * h).min(nominal);
                    }
                }
            }
        }
        Ok(self.end(w))
    }

    /// The predictor and the loads of the increment from `w.s` to `s_next`.
    /// Secant predictor from the last accepted increment (the path is
    /// nearly straight in s), the frictionless one at the start of a
    /// seating, the start pose at the start of a load path. The increment
    /// lasts (s_next - s) T_ramp (t = s T_ramp): the time base of the slip
    /// velocity of the decay friction law.
    fn increment(
        &self,
        w: &Walk,
        last_step: Option<(Vector6<f64>, f64)>,
        s_next: f64,
        seating: bool,
    ) -> (BodyPose, Loads) {
        let (lambda, extra) = self.loads_at(s_next);
        let dx = match last_step {
            Some((dx, ds)) => dx * ((s_next - w.s) / ds),
            None if seating => self.x1 * (s_next - w.s),
            None => Vector6::zeros(),
        };
        let predictor = w.pose.moved(&dx.fixed_rows::<3>(0).into(), &dx.fixed_rows::<3>(3).into());
        let loads = Loads { lambda, extra, duration: (s_next - w.s) * self.ramp_time, s: s_next };
        (predictor, loads)
    }

    /// A converged increment that needs no halving: `Some(Stop)` if the
    /// path ends with it (a contact opened during a seating, or the coupling
    /// slid away), `None` to accept it; records a load path's first event.
    fn judge(
        &self,
        ctx: &Context,
        w: &mut Walk,
        new_pose: &BodyPose,
        trial: &[ContactEval],
        loads: &Loads,
    ) -> Option<Verdict> {
        if ctx.seating {
            if let Some(i) = trial.iter().position(|e| e.normal_force <= 0.0) {
                return Some(Verdict::Stop(SolveError::ContactOpened {
                    contact: i + 1,
                    percent: 100.0 * loads.lambda,
                }));
            }
        } else if w.event.is_none() {
            w.event = self.first_event(trial).map(|(contact, kind)| LoadEvent {
                contact,
                kind,
                previous: w.s * ctx.factor,
                factor: loads.s * ctx.factor,
            });
        }
        let travel = (new_pose.translation - ctx.start.translation).norm();
        if travel > self.max_travel {
            return Some(Verdict::Stop(if ctx.seating {
                SolveError::SlidAway { percent: 100.0 * loads.lambda, displacement_m: travel }
            } else {
                SolveError::LoadSlidAway { percent: 100.0 * loads.s, displacement_m: travel }
            }));
        }
        None
    }

    /// An increment that fails at the smallest step: a load path ends at a
    /// lift-off (no equilibrium beyond a separating contact), otherwise the
    /// path cannot go on.
    fn dead_end(
        &self,
        ctx: &Context,
        mut w: Walk,
        s_next: f64,
        load: f64,
        residual: f64,
    ) -> Result<End, SolveError> {
        if !ctx.seating
            && let Some(e) = self.lift_off(&w, &ctx.start_fn, s_next, ctx.factor)
        {
            w.event = w.event.or(Some(e));
            return Ok(self.end(w));
        }
        let at = if ctx.seating { load } else { s_next };
        let err = self.failure(at, residual, &w.pose, &ctx.start);
        self.stop(err, w)
    }

    /// A path that cannot go on: after a load event it ends there (the
    /// event is the answer, the error says why it stopped); before one, the
    /// error is the result.
    fn stop(&self, err: SolveError, w: Walk) -> Result<End, SolveError> {
        if w.event.is_none() {
            return Err(err);
        }
        let mut end = self.end(w);
        end.stopped = Some(err);
        Ok(end)
    }

    fn end(&self, w: Walk) -> End {
        End {
            pose: w.pose,
            reached: w.s,
            event: w.event,
            stopped: None,
            increments: w.accepted,
            newton_iterations: w.iterations,
            halved: w.halved,
            slid: w.slid,
            decay_cv: friction::seating_cv(self.friction, w.slip_path, self.ramp_time),
        }
    }
}
