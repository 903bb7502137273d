//! One leg of a thermal path: the bodies' temperatures go from one cycle
//! point to the next (uniformly in the path parameter s) with the full
//! preload held. At each increment the coupling is placed at the trial
//! temperatures (`Coupling::at_temperatures`, the preload by
//! `assembly::thermal::preload_at`) and the contact layer takes the
//! bodies' expansion since the committed state into each contact's
//! tangential increment (`contact_layer::Expansion`); Newton, the halving
//! at Newton failures and at stick/slip changes of loaded contacts, and
//! the commit are the seating's (`super::path`).
//!
//! A snap: under the switch law a sticking contact breaks away when its
//! trial force exceeds mu_s F_n and then slides at mu_d F_n. Where the drop
//! of its force moves the half so far that its trial force at the new pose
//! falls below mu_s F_n again (every contact of a symmetric coupling
//! breaking away together), the increment has no solution in which the
//! contact is judged from its sticking state: Newton alternates between
//! the two. The increment is then solved again with the contacts that
//! break away at its predictor latched as sliding (judged against
//! mu_d F_n, as a contact that slid in the committed increment): they slide
//! at mu_d, and the half comes to rest where the dynamics of the breakaway
//! would bring it (the quasi-static path does not resolve the jump; it is
//! inside one increment of 2^-max_splits of the nominal).
//!
//! The first slip of a leg: the increment in which a sticking contact
//! first slides brackets it (to 2^-max_splits of a nominal increment);
//! inside it, the utilisation u = |F_t| / (mu_s F_n) of that contact,
//! extrapolated linearly from the last two committed states to u = 1,
//! places it (the sticking response is linear in the temperature to the
//! change of the contact stiffnesses with the normal force).

use std::collections::HashMap;
use std::sync::{Arc, RwLock};

use nalgebra::Vector6;

use super::path::Buffers;
use super::solver::{Loads, Program, Solver, Step, twist_between};
use crate::assembly::thermal::preload_at;
use crate::assembly::{BodyPose, Coupling};
use crate::contact::{Friction, SlipState, TangentialLaw, TangentialState};
use crate::scene::{Preload, Temperatures, ThermalBodies};
use crate::solve::contact_layer::Expansion;
use crate::solve::{SolveError, SolverOptions};

/// Most couplings [`Placements`] keeps (a cycle of two points on the
/// levels up to 2^7 increments per leg places about 500).
const MAX_PLACEMENTS: usize = 1024;

/// The coupling placed at each temperature a thermal path has visited
/// (`Coupling::at_temperatures`, which forms every contact's laws again),
/// kept for the paths that visit it again: every sample of a study
/// follows the same cycle on the same uniform increments, so each
/// placement is made once per study, not once per sample. Shared by the
/// study's threads; the coupling placed is the same whether it comes from
/// here or is made afresh, so results do not depend on the order in which
/// the samples fill it.
#[derive(Default)]
pub struct Placements {
    map: RwLock<HashMap<[u64; 2], Arc<Coupling>>>,
}

impl Placements {
    /// `base` at the temperatures `t`, placed once.
    pub fn get(&self, base: &Coupling, t: Temperatures) -> Result<Arc<Coupling>, SolveError> {
        let key = [t.moving.to_bits(), t.fixed.to_bits()];
        if let Some(c) = self.map.read().ok().and_then(|m| m.get(&key).cloned()) {
            return Ok(c);
        }
        let placed = Arc::new(base.at_temperatures(t)?);
        if let Ok(mut m) = self.map.write()
            && m.len() < MAX_PLACEMENTS
        {
            m.insert(key, placed.clone());
        }
        Ok(placed)
    }
}

/// What a leg runs on.
pub(super) struct Leg<'a> {
    /// The coupling at the seating temperature (with its expansion model).
    pub base: &'a Coupling,
    /// The placements of `base` visited so far.
    pub placements: &'a Placements,
    /// Whether to locate the first slip from the sticking solution (the
    /// `thermal` command; a study does not report it).
    pub locate_first_slip: bool,
    pub bodies: &'a ThermalBodies,
    pub friction: &'a [Friction],
    /// The preload at the seating temperature.
    pub preload: &'a Preload,
    pub opts: SolverOptions,
    /// The Newton tolerance of the sticking solution that locates the
    /// first slip (the seating's: `opts.tolerance` of a controlled leg is
    /// looser, and the contacts of a symmetric coupling reach their limit
    /// together, to round-off only at the seating's tolerance).
    pub sticking_tolerance: f64,
    pub from: Temperatures,
    pub to: Temperatures,
}

/// The end of a leg; its contact states and evaluations are in the
/// [`Buffers`] it ran in.
pub(super) struct LegEnd {
    pub pose: BodyPose,
    pub increments: usize,
    pub newton_iterations: usize,
    /// Which contacts slid on the leg.
    pub slid: Vec<bool>,
    /// The first slip of a sticking contact: s along the leg and the
    /// contact (0-based).
    pub first_slip: Option<(f64, usize)>,
}

/// u = |F_t| / (mu_s F_n) of a committed state (0 without friction or load).
fn utilisation(state: &TangentialState, f: &Friction) -> f64 {
    let limit = f.mu_s * state.normal_force;
    if limit > 0.0 { state.force.norm() / limit } else { 0.0 }
}

/// The utilisations of each contact's last two committed states and the
/// s of the earlier one.
struct Utilisation {
    now: Vec<f64>,
    prev: Vec<f64>,
    s_prev: f64,
}

impl Utilisation {
    fn new(states: &[TangentialState], friction: &[Friction]) -> Self {
        let now = states.iter().zip(friction).map(|(st, f)| utilisation(st, f)).collect();
        Utilisation { now, prev: vec![f64::NAN; states.len()], s_prev: f64::NAN }
    }

    /// After a commit at `s` (the states of the increment that ended there
    /// are `states`).
    fn advance(&mut self, states: &[TangentialState], friction: &[Friction], s: f64) {
        std::mem::swap(&mut self.prev, &mut self.now);
        for ((u, st), f) in self.now.iter_mut().zip(states).zip(friction) {
            *u = utilisation(st, f);
        }
        self.s_prev = s;
    }

    /// Where contact `i`'s utilisation reaches 1 inside `(s, s_next)`:
    /// extrapolated linearly from the last two committed states, or the
    /// middle of the increment without two.
    fn extrapolate(&self, i: usize, s: f64, s_next: f64) -> f64 {
        let (ua, up) = (self.now[i], self.prev[i]);
        if up.is_finite() && ua > up {
            (s + (1.0 - ua) * (s - self.s_prev) / (ua - up)).clamp(s, s_next)
        } else {
            0.5 * (s + s_next)
        }
    }
}

impl<'a> Leg<'a> {
    /// The leg on `n` nominal increments from `start`; the start states
    /// are `bufs.states` (at rest: sticking where there is friction).
    pub fn run(&self, n: usize, start: BodyPose, bufs: &mut Buffers) -> Result<LegEnd, SolveError> {
        let nominal = 1.0 / n.max(1) as f64;
        let h_min = nominal / f64::powi(2.0, self.opts.max_splits as i32);
        let contacts = bufs.states.len();
        let mut end = LegEnd {
            pose: start,
            increments: 0,
            newton_iterations: 0,
            slid: vec![false; contacts],
            first_slip: None,
        };
        let (mut h, mut s, mut committed) = (nominal, 0.0, self.from);
        let mut last_step: Option<(Vector6<f64>, f64)> = None;
        let mut u = Utilisation::new(&bufs.states, self.friction);
        while s < 1.0 {
            let s_next = if s + h > 1.0 - 1e-12 { 1.0 } else { s + h };
            let at = self.from.towards(self.to, s_next);
            let coupling = self.placements.get(self.base, at)?;
            let preload = preload_at(self.bodies, self.preload, at, &self.base.touching_pose);
            let solver = self.solver(&coupling, &preload, at, committed);
            let dx = last_step.map_or(Vector6::zeros(), |(dx, ds)| dx * ((s_next - s) / ds));
            let predictor =
                end.pose.moved(&dx.fixed_rows::<3>(0).into(), &dx.fixed_rows::<3>(3).into());
            let duration = (s_next - s) * solver.ramp_time;
            let loads = Loads { lambda: 1.0, extra: 0.0, duration, s: s_next };
            let can_halve = h > h_min * 1.5;
            let step = solver.newton(&end.pose, &bufs.states, predictor, &loads, &mut bufs.trial);
            let (new_pose, iterations) = match step {
                Step::Failed(_) if can_halve => {
                    h *= 0.5;
                    continue;
                }
                Step::Failed(residual) => {
                    let snap = self.snap(&solver, &end.pose, predictor, &loads, bufs);
                    let Some((pose, its)) = snap else {
                        return Err(SolveError::ThermalNotConverged {
                            moving_k: at.moving,
                            fixed_k: at.fixed,
                            residual,
                            splits: self.opts.max_splits,
                        });
                    };
                    (pose, its)
                }
                Step::Converged(pose, its) => (pose, its),
            };
            end.newton_iterations += iterations;
            self.check(&bufs.trial, &new_pose, &start, at, &solver)?;
            if end.first_slip.is_none() {
                end.first_slip = self.first_slip((s, s_next), committed, &end.pose, &u, bufs);
            }
            for i in 0..contacts {
                end.slid[i] |=
                    self.friction[i].mu_s > 0.0 && bufs.trial[i].slip() == SlipState::Slip;
            }
            // A contact that broke away stays on its sliding branch for the
            // rest of the leg (module docs: the latch).
            for ((st, e), &slid) in bufs.states.iter_mut().zip(bufs.trial.iter()).zip(&end.slid) {
                st.clone_from(&e.tangential.state);
                st.sliding |= slid;
            }
            std::mem::swap(&mut bufs.evals, &mut bufs.trial);
            u.advance(&bufs.states, self.friction, s);
            last_step = Some((twist_between(&end.pose, &new_pose), s_next - s));
            end.pose = new_pose;
            end.increments += 1;
            s = s_next;
            committed = at;
            h = (2.0 * h).min(nominal);
        }
        Ok(end)
    }

    /// The path follower of one increment of the leg to the temperatures
    /// `at` from the committed ones, on `coupling` placed at `at`.
    fn solver<'s>(
        &self,
        coupling: &'s Coupling,
        preload: &'s Preload,
        at: Temperatures,
        committed: Temperatures,
    ) -> Solver<'s>
    where
        'a: 's,
    {
        let mut solver = Solver::new(
            coupling,
            self.friction,
            preload,
            self.opts,
            Program::Hold,
            Vector6::zeros(),
        );
        solver.expansion = Some(Expansion::between(self.bodies, at, committed));
        solver
    }

    /// The first slip in the increment `(s, s_next)` just solved (its
    /// evaluations in `bufs.trial`, the committed states in `bufs.states`),
    /// if a sticking contact breaks away in it: from the sticking solution
    /// where every contact stuck before and the law sticks linearly (and
    /// the first slip is asked for), else extrapolated from the
    /// utilisations `u`.
    fn first_slip(
        &self,
        (s, s_next): (f64, f64),
        committed: Temperatures,
        pose: &BodyPose,
        u: &Utilisation,
        bufs: &mut Buffers,
    ) -> Option<(f64, usize)> {
        let breaks = |i: usize| {
            let (e, st) = (&bufs.trial[i], &bufs.states[i]);
            self.friction[i].mu_s > 0.0 && e.slip() == SlipState::Slip && !st.sliding
        };
        let first = (0..bufs.states.len())
            .filter(|&i| breaks(i))
            .map(|i| (u.extrapolate(i, s, s_next), i))
            .min_by(|a, b| a.0.total_cmp(&b.0))?;
        let all_stuck = bufs.states.iter().all(|st| !st.sliding);
        if self.locate_first_slip && all_stuck && self.sticks_linearly() {
            return self.first_slip_sticking((s, s_next), committed, pose, bufs).or(Some(first));
        }
        Some(first)
    }

    /// The increment again with the contacts that break away at its
    /// `predictor` latched as sliding (module docs: a snap); its pose and
    /// Newton iterations if it converges (the evaluations in `bufs.trial`).
    fn snap(
        &self,
        solver: &Solver,
        committed: &BodyPose,
        predictor: BodyPose,
        loads: &Loads,
        bufs: &mut Buffers,
    ) -> Option<(BodyPose, usize)> {
        let trial = &mut bufs.trial;
        solver.evaluate_all(&predictor, committed, &bufs.states, loads.duration, false, trial);
        let mut latched = bufs.states.clone();
        let mut any = false;
        for ((st, e), f) in latched.iter_mut().zip(trial.iter()).zip(self.friction) {
            if !st.sliding && f.mu_s > 0.0 && e.slip() == SlipState::Slip {
                st.sliding = true;
                any = true;
            }
        }
        if !any {
            return None;
        }
        match solver.newton(committed, &latched, predictor, loads, trial) {
            Step::Converged(pose, its) => Some((pose, its)),
            Step::Failed(_) => None,
        }
    }

    /// Whether a sticking contact's force is linear in the temperature
    /// (to the change of its stiffness with the normal force): the Coulomb
    /// law's single spring. Mindlin-Deresiewicz slips partially from the
    /// first increment.
    fn sticks_linearly(&self) -> bool {
        self.base.friction.tangential == TangentialLaw::Coulomb
    }

    /// The first slip inside the increment `(s, s_next)` of a leg at whose
    /// start every contact sticks (`bufs.states`, at `committed` and
    /// `pose`), from the sticking solution: the increment solved with
    /// every contact held (mu infinite) gives each contact's force F and
    /// normal force N at the end, linear in s between the committed state
    /// and that end (Coulomb's spring), and the contact slides first where
    /// |F(s)| = mu_s N(s) (the smaller root of that quadratic). The end is
    /// then moved to the root and solved again, twice, which removes the
    /// change of the stiffnesses with the normal force. `None` if the
    /// sticking solution does not converge or nothing reaches its limit.
    fn first_slip_sticking(
        &self,
        (s, s_next): (f64, f64),
        committed: Temperatures,
        pose: &BodyPose,
        bufs: &mut Buffers,
    ) -> Option<(f64, usize)> {
        let held: Vec<Friction> = self
            .friction
            .iter()
            .map(|f| {
                if f.mu_s > 0.0 {
                    Friction { mu_s: f64::INFINITY, mu_d: f64::INFINITY, ..*f }
                } else {
                    *f
                }
            })
            .collect();
        let mut trial = bufs.trial.clone();
        let (mut end, mut found) = (s_next, None);
        for _ in 0..3 {
            let at = self.from.towards(self.to, end);
            let coupling = self.base.at_temperatures(at).ok()?;
            let preload = preload_at(self.bodies, self.preload, at, &self.base.touching_pose);
            let opts = SolverOptions { tolerance: self.sticking_tolerance, ..self.opts };
            let mut solver =
                Solver::new(&coupling, &held, &preload, opts, Program::Hold, Vector6::zeros());
            solver.expansion = Some(Expansion::between(self.bodies, at, committed));
            let loads =
                Loads { lambda: 1.0, extra: 0.0, duration: (end - s) * solver.ramp_time, s: end };
            let Step::Converged(..) = solver.newton(pose, &bufs.states, *pose, &loads, &mut trial)
            else {
                return found;
            };
            let reach = (s_next - s) / (end - s);
            let root = (0..trial.len())
                .filter(|&i| self.friction[i].mu_s > 0.0)
                .filter_map(|i| {
                    let st = &bufs.states[i];
                    let e = &trial[i];
                    limit_crossing(
                        (&st.force, st.normal_force),
                        (&e.tangential.force, e.normal_force),
                        self.friction[i].mu_s,
                    )
                    .filter(|&t| t <= reach)
                    .map(|t| (s + t * (end - s), i))
                })
                .min_by(|a, b| a.0.total_cmp(&b.0));
            let Some(root) = root else { return found };
            found = Some(root);
            if (root.0 - end).abs() <= 1e-9 * (s_next - s) {
                break;
            }
            end = root.0;
        }
        found
    }

    /// An accepted increment must leave every contact closed and the
    /// moving half near where it started.
    fn check(
        &self,
        trial: &[crate::solve::contact_layer::ContactEval],
        pose: &BodyPose,
        start: &BodyPose,
        at: Temperatures,
        solver: &Solver,
    ) -> Result<(), SolveError> {
        if let Some(i) = trial.iter().position(|e| e.normal_force <= 0.0) {
            return Err(SolveError::ThermalContactOpened {
                contact: i + 1,
                moving_k: at.moving,
                fixed_k: at.fixed,
            });
        }
        let travel = (pose.translation - start.translation).norm();
        if travel > solver.max_travel {
            return Err(SolveError::ThermalSlidAway {
                moving_k: at.moving,
                fixed_k: at.fixed,
                displacement_m: travel,
            });
        }
        Ok(())
    }
}

/// The smallest t > 0 at which |F_0 + t (F_1 - F_0)| = mu (N_0 + t (N_1 - N_0))
/// for a contact inside its limit at t = 0: the root of
/// a t^2 + 2 b t + c = 0 with a = |dF|^2 - mu^2 dN^2,
/// b = F_0 . dF - mu^2 N_0 dN, c = |F_0|^2 - mu^2 N_0^2 < 0.
fn limit_crossing(
    (f0, n0): (&nalgebra::Vector3<f64>, f64),
    (f1, n1): (&nalgebra::Vector3<f64>, f64),
    mu: f64,
) -> Option<f64> {
    let (df, dn) = (f1 - f0, n1 - n0);
    let m2 = mu * mu;
    let a = df.norm_squared() - m2 * dn * dn;
    let b = f0.dot(&df) - m2 * n0 * dn;
    let c = f0.norm_squared() - m2 * n0 * n0;
    if c >= 0.0 {
        return None;
    }
    // c < 0: one positive root where a > 0; where a <= 0 one only if b > 0
    // and the discriminant is non-negative (the smaller positive root).
    let disc = b * b - a * c;
    if disc < 0.0 {
        return None;
    }
    // The positive root, written without cancellation: t = -c / (b + sqrt(disc)).
    let q = b + disc.sqrt();
    (q > 0.0).then(|| -c / q).filter(|t| t.is_finite())
}
