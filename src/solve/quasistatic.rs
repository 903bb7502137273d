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

use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

use super::contact_layer::{ContactEval, evaluate};
use super::{ContactResult, Seating, SolveError, SolverOptions, frictions};
use crate::assembly::constraint::frictionless_preload_forces;
use crate::assembly::{BodyPose, Coupling};
use crate::contact::{Friction, SlipState, TangentialState};
use serde::Serialize;

/// Seat the coupling with static coefficients `mu_s` (contact order).
pub fn seat(
    coupling: &Coupling,
    mu_s: &[f64],
    opts: &SolverOptions,
) -> Result<Seating, SolveError> {
    let fr = frictions(coupling, mu_s)?;
    let solver = Solver::new(coupling, fr, *opts, Program::Seat);
    let n = coupling.contacts.len();
    let pose = coupling.touching_pose;
    let states: Vec<TangentialState> = (0..n)
        .map(|i| TangentialState::new(coupling.geometry(i, &pose).normal))
        .collect();
    let end = solver.run(pose, states)?;
    Ok(Seating {
        pose: end.pose,
        contacts: end.contacts,
        increments: end.increments,
        newton_iterations: end.newton_iterations,
    })
}

/// An extra load on the moving half after seating: a force of fixed
/// direction applied at a point of the moving half, and a moment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExternalLoad {
    /// Force [N] (world axes, direction fixed).
    pub force: Vector3<f64>,
    /// Point of application in the moving half, scene coordinates [m].
    pub point: Vector3<f64>,
    /// Moment [N m].
    pub moment: Vector3<f64>,
}

/// What ends the at-rest (sticking, closed) response of a contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum LoadEventKind {
    /// The normal force reaches 0: the contact opens.
    Separation,
    /// |F_t| reaches mu_s F_n: the contact starts to slip.
    Slip,
}

impl LoadEventKind {
    pub fn name(self) -> &'static str {
        match self {
            LoadEventKind::Separation => "separates",
            LoadEventKind::Slip => "starts to slip",
        }
    }
}

/// The first contact event along a load path.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LoadEvent {
    /// Contact, 1-based.
    pub contact: usize,
    pub kind: LoadEventKind,
    /// The event happens between these load factors: `previous` is the last
    /// solved factor without it, `factor` the first with it (or the factor
    /// beyond which no equilibrium exists).
    pub previous: f64,
    pub factor: f64,
}

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

/// Apply `load` x `factor` to the coupling seated at `start` with contact
/// states `states` (usually [`at_rest_states`] of a seating with the same
/// `mu_s`), holding the full preload. The load ramps from 0 in
/// `opts.increments` equal steps.
pub fn apply_load(
    coupling: &Coupling,
    mu_s: &[f64],
    start: &BodyPose,
    states: &[TangentialState],
    load: &ExternalLoad,
    factor: f64,
    opts: &SolverOptions,
) -> Result<LoadPath, SolveError> {
    let fr = frictions(coupling, mu_s)?;
    if states.len() != coupling.contacts.len() {
        return Err(SolveError::MuCount {
            expected: coupling.contacts.len(),
            got: states.len(),
        });
    }
    let solver = Solver::new(
        coupling,
        fr,
        *opts,
        Program::Load {
            load: *load,
            factor,
        },
    );
    let end = solver.run(*start, states.to_vec())?;
    Ok(LoadPath {
        factor: end.reached * factor,
        pose: end.pose,
        contacts: end.contacts,
        states: end.states,
        first_event: end.event,
        stopped: end.stopped,
        increments: end.increments,
        newton_iterations: end.newton_iterations,
    })
}

/// A force and the world point it acts at (moving with the body).
type PointForce = (Vector3<f64>, Vector3<f64>);

/// What the path follower ramps.
#[derive(Debug, Clone, Copy, PartialEq)]
enum Program {
    /// The preload from 0 (lambda = s^1.5) from the touching pose.
    Seat,
    /// Full preload plus s * factor * load.
    Load { load: ExternalLoad, factor: f64 },
}

/// The end of a path.
struct End {
    pose: BodyPose,
    contacts: Vec<ContactResult>,
    states: Vec<TangentialState>,
    /// Path parameter s reached.
    reached: f64,
    event: Option<LoadEvent>,
    /// Why a load path ended before its factor (after its first event).
    stopped: Option<SolveError>,
    increments: usize,
    newton_iterations: usize,
}

struct Solver<'a> {
    coupling: &'a Coupling,
    friction: Vec<Friction>,
    opts: SolverOptions,
    program: Program,
    /// Force scale of the residual [N].
    force_scale: f64,
    /// Coupling radius, the length scale of moments [m].
    length: f64,
    /// Predictor twist per unit s.
    x1: Vector6<f64>,
    /// Slide-away bound on the translation [m].
    max_travel: f64,
    /// Duration of the whole path, s from 0 to 1 (`[preload] ramp_time`) [s].
    ramp_time: f64,
}

enum Step {
    Converged(BodyPose, Vec<ContactEval>, usize),
    Failed(f64),
}

impl<'a> Solver<'a> {
    fn new(
        coupling: &'a Coupling,
        friction: Vec<Friction>,
        opts: SolverOptions,
        program: Program,
    ) -> Self {
        let touching = coupling.touching_pose;
        let length = coupling.length_scale();
        let rows = coupling.constraint_rows(&touching);
        let w = Matrix6::from_fn(|r, c| rows[r][c]);
        let f = frictionless_preload_forces(coupling);
        let rhs = Vector6::from_fn(|i, _| -coupling.contacts[i].normal.approach(f[i].max(0.0)));
        let x1 = w.lu().solve(&rhs).unwrap_or_else(Vector6::zeros);
        let preload = coupling.scene.preload.force;
        let force_scale = match program {
            Program::Seat => preload,
            Program::Load { load, factor } => {
                let f = factor.abs();
                preload
                    .max(f * load.force.norm())
                    .max(f * load.moment.norm() / length)
            }
        };
        Solver {
            coupling,
            friction,
            opts,
            program,
            force_scale,
            length,
            x1,
            max_travel: coupling.slide_away_travel(),
            ramp_time: coupling.scene.preload.ramp_time,
        }
    }

    /// Preload factor and extra-load factor at path parameter s.
    fn loads_at(&self, s: f64) -> (f64, f64) {
        match self.program {
            Program::Seat => (s.powf(1.5), 0.0),
            Program::Load { factor, .. } => (1.0, s * factor),
        }
    }

    fn run(&self, start: BodyPose, start_states: Vec<TangentialState>) -> Result<End, SolveError> {
        let seating = self.program == Program::Seat;
        let mut pose = start;
        let mut states = start_states;
        let nominal = 1.0 / self.opts.increments.max(1) as f64;
        let h_min = nominal / f64::powi(2.0, self.opts.max_splits as i32);
        let (mut s, mut h) = (0.0_f64, nominal);
        let mut evals: Vec<ContactEval> = if seating {
            Vec::new()
        } else {
            self.evaluate_all(&pose, &pose, &states, self.ramp_time)
        };
        let start_fn: Vec<f64> = evals.iter().map(|e| e.normal_force).collect();
        let (mut accepted, mut iterations) = (0, 0);
        let mut last_step: Option<(Vector6<f64>, f64)> = None;
        let mut event: Option<LoadEvent> = None;
        let factor = match self.program {
            Program::Seat => 1.0,
            Program::Load { factor, .. } => factor,
        };
        while s < 1.0 {
            let s_next = if s + h > 1.0 - 1e-12 { 1.0 } else { s + h };
            let (lambda, extra) = self.loads_at(s_next);
            // Secant predictor from the last accepted increment (the path is
            // nearly straight in s), the frictionless one at the start of a
            // seating, the start pose at the start of a load path.
            let dx = match last_step {
                Some((dx, ds)) => dx * ((s_next - s) / ds),
                None if seating => self.x1 * (s_next - s),
                None => Vector6::zeros(),
            };
            let predictor =
                pose.moved(&dx.fixed_rows::<3>(0).into(), &dx.fixed_rows::<3>(3).into());
            // The increment's duration on the ramp (t = s T_ramp): the time
            // base of the slip velocity of the decay friction law.
            let duration = (s_next - s) * self.ramp_time;
            match self.newton(&pose, &states, predictor, lambda, extra, duration) {
                Step::Failed(residual) => {
                    if h <= h_min * 1.5 {
                        if !seating
                            && let Some(e) = self.lift_off(&evals, &start_fn, s, s_next, factor)
                        {
                            // No equilibrium beyond a separating contact: the path ends.
                            return Ok(self.end(
                                pose,
                                &evals,
                                states,
                                s,
                                event.or(Some(e)),
                                accepted,
                                iterations,
                            ));
                        }
                        let err = self.failure(lambda.max(extra), residual, &pose, &start);
                        return self
                            .stop(err, pose, &evals, states, s, event, accepted, iterations);
                    }
                    h *= 0.5;
                }
                Step::Converged(new_pose, new_evals, its) => {
                    iterations += its;
                    // A change of a contact that carried load is located by
                    // halving; from zero load it is not: Hertz force, Mindlin
                    // stiffness and the Coulomb limit all scale with the same
                    // power of the approach along a proportional path, so a
                    // fresh contact sticks or slips from the first load on.
                    let changed = new_evals
                        .iter()
                        .zip(&states)
                        .enumerate()
                        .any(|(i, (e, st))| {
                            (e.slip() == SlipState::Slip) != st.sliding
                                && evals.get(i).is_some_and(|old| old.normal_force > 0.0)
                        });
                    if changed && h > h_min * 1.5 {
                        h *= 0.5;
                        continue;
                    }
                    if seating {
                        if let Some(i) = new_evals.iter().position(|e| e.normal_force <= 0.0) {
                            return Err(SolveError::ContactOpened {
                                contact: i + 1,
                                percent: 100.0 * lambda,
                            });
                        }
                    } else if event.is_none() {
                        event = self
                            .first_event(&new_evals)
                            .map(|(contact, kind)| LoadEvent {
                                contact,
                                kind,
                                previous: s * factor,
                                factor: s_next * factor,
                            });
                    }
                    let travel = (new_pose.translation - start.translation).norm();
                    if travel > self.max_travel {
                        let err = SolveError::SlidAway {
                            percent: 100.0 * lambda.max(extra),
                            displacement_m: travel,
                        };
                        return self
                            .stop(err, pose, &evals, states, s, event, accepted, iterations);
                    }
                    states = new_evals
                        .iter()
                        .map(|e| e.tangential.state.clone())
                        .collect();
                    last_step = Some((twist_between(&pose, &new_pose), s_next - s));
                    pose = new_pose;
                    evals = new_evals;
                    accepted += 1;
                    s = s_next;
                    if !changed {
                        h = (2.0 * h).min(nominal);
                    }
                }
            }
        }
        Ok(self.end(pose, &evals, states, s, event, accepted, iterations))
    }

    /// A path that cannot go on: after a load event it ends there (the
    /// event is the answer, the error says why it stopped); before one, the
    /// error is the result.
    #[allow(clippy::too_many_arguments)]
    fn stop(
        &self,
        err: SolveError,
        pose: BodyPose,
        evals: &[ContactEval],
        states: Vec<TangentialState>,
        reached: f64,
        event: Option<LoadEvent>,
        increments: usize,
        newton_iterations: usize,
    ) -> Result<End, SolveError> {
        if event.is_none() {
            return Err(err);
        }
        let mut end = self.end(
            pose,
            evals,
            states,
            reached,
            event,
            increments,
            newton_iterations,
        );
        end.stopped = Some(err);
        Ok(end)
    }

    #[allow(clippy::too_many_arguments)]
    fn end(
        &self,
        pose: BodyPose,
        evals: &[ContactEval],
        states: Vec<TangentialState>,
        reached: f64,
        event: Option<LoadEvent>,
        increments: usize,
        newton_iterations: usize,
    ) -> End {
        End {
            pose,
            contacts: evals
                .iter()
                .enumerate()
                .map(|(i, e)| self.result(i, e))
                .collect(),
            states,
            reached,
            event,
            stopped: None,
            increments,
            newton_iterations,
        }
    }

    /// The first contact event of a solved load increment: a separation
    /// (F_n <= 0) before a slip of a contact with friction.
    fn first_event(&self, evals: &[ContactEval]) -> Option<(usize, LoadEventKind)> {
        if let Some(i) = evals.iter().position(|e| e.normal_force <= 0.0) {
            return Some((i + 1, LoadEventKind::Separation));
        }
        evals
            .iter()
            .zip(&self.friction)
            .position(|(e, f)| f.mu_s > 0.0 && e.slip() == SlipState::Slip)
            .map(|i| (i + 1, LoadEventKind::Slip))
    }

    /// A load increment that cannot be solved even at the smallest step,
    /// right after a contact has lost nearly all its normal force, is a
    /// lift-off: the separating contact leaves the moving half without
    /// equilibrium (no friction holds it). The contact is the one whose
    /// normal force has fallen furthest, if below 5 % of its seated value.
    fn lift_off(
        &self,
        evals: &[ContactEval],
        start_fn: &[f64],
        s: f64,
        s_next: f64,
        factor: f64,
    ) -> Option<LoadEvent> {
        let (i, ratio) = evals
            .iter()
            .zip(start_fn)
            .enumerate()
            .map(|(i, (e, f0))| (i, e.normal_force / f0.max(f64::MIN_POSITIVE)))
            .min_by(|a, b| a.1.total_cmp(&b.1))?;
        (ratio < 0.05).then_some(LoadEvent {
            contact: i + 1,
            kind: LoadEventKind::Separation,
            previous: s * factor,
            factor: s_next * factor,
        })
    }

    fn failure(&self, lambda: f64, residual: f64, pose: &BodyPose, start: &BodyPose) -> SolveError {
        let travel = (pose.translation - start.translation).norm();
        if travel > 0.5 * self.max_travel {
            SolveError::SlidAway {
                percent: 100.0 * lambda,
                displacement_m: travel,
            }
        } else {
            SolveError::NotConverged {
                percent: 100.0 * lambda,
                residual,
                splits: self.opts.max_splits,
            }
        }
    }

    fn evaluate_all(
        &self,
        pose: &BodyPose,
        committed_pose: &BodyPose,
        states: &[TangentialState],
        duration: f64,
    ) -> Vec<ContactEval> {
        (0..self.coupling.contacts.len())
            .map(|i| {
                evaluate(
                    self.coupling,
                    i,
                    pose,
                    committed_pose,
                    &states[i],
                    self.friction[i].during(duration),
                )
            })
            .collect()
    }

    /// Net force and moment on the moving half, and the preload force and point.
    fn residual(
        &self,
        pose: &BodyPose,
        evals: &[ContactEval],
        lambda: f64,
        extra: f64,
    ) -> (Vector6<f64>, [PointForce; 2]) {
        let p = &self.coupling.scene.preload;
        let fp = p.direction * (p.force * lambda);
        let pp = pose.apply(&p.point);
        let mut r = Vector6::zeros();
        let mut add = |f: &Vector3<f64>, at: &Vector3<f64>| {
            let m = at.cross(f);
            r += Vector6::new(f.x, f.y, f.z, m.x, m.y, m.z);
        };
        add(&fp, &pp);
        for e in evals {
            add(&e.force, &e.geometry.point);
        }
        let mut loads = [(fp, pp), (Vector3::zeros(), pp)];
        if let Program::Load { load, .. } = self.program {
            let fe = load.force * extra;
            let pe = pose.apply(&load.point);
            add(&fe, &pe);
            let me = load.moment * extra;
            r += Vector6::new(0.0, 0.0, 0.0, me.x, me.y, me.z);
            loads[1] = (fe, pe);
        }
        (r, loads)
    }

    fn relative(&self, r: &Vector6<f64>) -> f64 {
        let fp = self.force_scale;
        let rf = r.fixed_rows::<3>(0).norm() / fp;
        let rm = r.fixed_rows::<3>(3).norm() / (fp * self.length);
        rf.max(rm)
    }

    fn newton(
        &self,
        committed_pose: &BodyPose,
        states: &[TangentialState],
        start: BodyPose,
        lambda: f64,
        extra: f64,
        duration: f64,
    ) -> Step {
        let mut pose = start;
        let mut last = f64::INFINITY;
        for it in 0..self.opts.max_newton {
            let evals = self.evaluate_all(&pose, committed_pose, states, duration);
            let (r, loads) = self.residual(&pose, &evals, lambda, extra);
            let rel = self.relative(&r);
            if !rel.is_finite() {
                return Step::Failed(rel);
            }
            if rel < self.opts.tolerance {
                return Step::Converged(pose, evals, it + 1);
            }
            last = rel;
            let j = self.jacobian(&evals, &loads);
            let Some(dx) = j.lu().solve(&(-r)) else {
                return Step::Failed(rel);
            };
            if !dx.iter().all(|v| v.is_finite()) || dx.fixed_rows::<3>(0).norm() > self.max_travel {
                return Step::Failed(rel);
            }
            pose = pose.moved(&dx.fixed_rows::<3>(0).into(), &dx.fixed_rows::<3>(3).into());
        }
        Step::Failed(last)
    }

    /// dR/d(v, w) for a twist about the world origin: contact stiffness K_i
    /// mapped through dp = v - [p]x w, plus the moments of forces whose
    /// points move with the body.
    fn jacobian(&self, evals: &[ContactEval], loads: &[PointForce]) -> Matrix6<f64> {
        let mut j = Matrix6::zeros();
        let mut add_point_force =
            |k: &Matrix3<f64>, f: &Vector3<f64>, p: &Vector3<f64>, moving: &Vector3<f64>| {
                let px = p.cross_matrix();
                let mx = moving.cross_matrix();
                let fx = f.cross_matrix();
                // force rows: K dp;  moment rows: p x (K dp) + dp_moving x f
                let kp = k * (-px);
                j.fixed_view_mut::<3, 3>(0, 0).add_assign(k);
                j.fixed_view_mut::<3, 3>(0, 3).add_assign(&kp);
                j.fixed_view_mut::<3, 3>(3, 0).add_assign(&(px * k - fx));
                j.fixed_view_mut::<3, 3>(3, 3)
                    .add_assign(&(px * kp + fx * mx));
            };
        for (i, e) in evals.iter().enumerate() {
            let centre = e.geometry.point
                + e.geometry.normal * self.coupling.balls[self.coupling.contacts[i].ball].radius;
            add_point_force(&e.stiffness, &e.force, &e.geometry.point, &centre);
        }
        for (f, p) in loads {
            add_point_force(&Matrix3::zeros(), f, p, p);
        }
        j
    }

    fn result(&self, i: usize, e: &ContactEval) -> ContactResult {
        ContactResult::from_eval(self.coupling, i, e, self.friction[i])
    }
}

/// The twist (v, w) with `from.moved(v, w) == to`.
fn twist_between(from: &BodyPose, to: &BodyPose) -> Vector6<f64> {
    let dq = to.rotation * from.rotation.inverse();
    let w = dq.scaled_axis();
    let v = to.translation - dq * from.translation;
    Vector6::new(v.x, v.y, v.z, w.x, w.y, w.z)
}

use std::ops::AddAssign;
