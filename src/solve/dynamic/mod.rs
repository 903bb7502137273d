//! Seating dynamics (MODEL.md §3, the design card): the moving half is a
//! rapier3d-f64 dynamic body ([`world`]), the fixed surfaces are parry
//! shapes, and the compliant contact layer ([`crate::solve::contact_layer`],
//! shared with the quasi-static solver) supplies every contact force,
//! plus the dashpots of [`forces`] that let the motion settle.
//!
//! Each time step n (length dt):
//! 1. read the pose x_n and velocity of the body from rapier;
//! 2. for each contact, parry gives gap, normal and point at x_n (rapier's
//!    own manifolds are one step stale and its rigid contact is off); the
//!    contact layer gives the Hertz force and the stick/slip tangential
//!    force from the tangential state committed at step n-1 and the
//!    displacement of the contact point since x_(n-1); the dashpots add
//!    damping;
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
//! Time step: dt = T_min / `steps_per_period`, T_min = 2 pi / omega_max the
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
//! Defaults ([`DynamicOptions::default`]) and why: 30 steps per shortest
//! period (omega_max dt = 0.21: stable, energy error ~0.4 % undamped);
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
pub mod world;

use nalgebra::{Matrix3, Vector3};
use rapier3d_f64::prelude::{PhysicsWorld, RigidBodyHandle};

use super::{ContactResult, Seating, SolveError, frictions};
use crate::assembly::constraint::friction_limit;
use crate::assembly::{BodyPose, Coupling};
use crate::contact::{Friction, SlipState, TangentialState};
pub use forces::{Damping, StepContact};
pub use frequency::Frequencies;
pub use mass::{MassModel, MassSource};
use world::{dvec, from_rapier, nvec};

/// Where the moving half starts (at rest).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StartPose {
    /// Translation from the touching pose [m] (z > 0: above the seat).
    pub offset: Vector3<f64>,
    /// Rotation vector about the scene origin, applied before the offset [rad].
    pub tilt: Vector3<f64>,
}

impl StartPose {
    /// The touching pose itself (the quasi-static start).
    pub fn touching() -> Self {
        StartPose {
            offset: Vector3::zeros(),
            tilt: Vector3::zeros(),
        }
    }
}

/// Settings of the dynamic solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DynamicOptions {
    pub start: StartPose,
    /// Time steps per period of the highest natural mode at full preload.
    pub steps_per_period: f64,
    /// Ramp duration in periods of the fundamental (lowest) mode; 0: step load.
    pub ramp_periods: f64,
    pub damping: Damping,
    /// Amplitude of motion below which the body counts as at rest [m].
    pub settle_displacement: f64,
    /// Force and moment residual at rest, relative to F_p and F_p L.
    pub settle_force: f64,
    /// Give up this many fundamental periods after the ramp.
    pub max_settle_periods: f64,
}

impl Default for DynamicOptions {
    fn default() -> Self {
        DynamicOptions {
            start: StartPose::touching(),
            steps_per_period: 30.0,
            ramp_periods: 40.0,
            damping: Damping {
                normal: 0.3,
                tangential: 1.0,
            },
            settle_displacement: 1e-14,
            settle_force: 1e-9,
            max_settle_periods: 2000.0,
        }
    }
}

impl DynamicOptions {
    fn check(&self) -> Result<(), SolveError> {
        let bad = |m: String| Err(SolveError::BadOption(m));
        let finite3 = |v: &Vector3<f64>| v.iter().all(|x| x.is_finite());
        if !finite3(&self.start.offset) || !finite3(&self.start.tilt) {
            return bad("the start offset and tilt must be finite numbers".into());
        }
        if self.start.tilt.norm() > 0.1 {
            return bad(format!(
                "tilt {:.3e} rad is too large: a seating start is tilted by at most 0.1 rad",
                self.start.tilt.norm()
            ));
        }
        if !(self.steps_per_period >= 20.0 && self.steps_per_period.is_finite()) {
            return bad(format!(
                "steps_per_period = {} must be at least 20 (explicit damping needs zeta omega dt < 1)",
                self.steps_per_period
            ));
        }
        if !(self.ramp_periods >= 0.0 && self.ramp_periods.is_finite()) {
            return bad(format!("ramp_periods = {} must be >= 0", self.ramp_periods));
        }
        for (name, z) in [
            ("normal", self.damping.normal),
            ("tangential", self.damping.tangential),
        ] {
            if !(0.0..=1.0).contains(&z) {
                return bad(format!(
                    "{name} damping ratio {z} must lie in [0, 1] (above 1 the explicit dashpot loses stability)"
                ));
            }
        }
        if !(self.settle_displacement > 0.0
            && self.settle_force > 0.0
            && self.max_settle_periods > 0.0)
        {
            return bad("settling thresholds and the time limit must be positive".into());
        }
        Ok(())
    }
}

/// Seat the coupling dynamically with static coefficients `mu_s` (contact order).
pub fn seat(
    coupling: &Coupling,
    mu_s: &[f64],
    opts: &DynamicOptions,
) -> Result<Seating, SolveError> {
    seat_traced(coupling, mu_s, opts, &mut |_| {})
}

/// [`seat`], calling `trace` after every step with the state at the start of it.
pub fn seat_traced(
    coupling: &Coupling,
    mu_s: &[f64],
    opts: &DynamicOptions,
    trace: &mut dyn FnMut(&TraceSample),
) -> Result<Seating, SolveError> {
    let mut sim = Simulation::new(coupling, mu_s, opts)?;
    let max_time = sim.ramp_time + opts.max_settle_periods * sim.freq.longest_period();
    loop {
        sim.step()?;
        trace(&sim.sample());
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
        let limit = friction_limit(coupling);
        return Err(SolveError::NotCentred {
            open: open
                .iter()
                .map(|i| (i + 1).to_string())
                .collect::<Vec<_>>()
                .join(", "),
            gap_m: open
                .iter()
                .map(|&i| sim.contacts[i].eval.geometry.gap)
                .fold(f64::NEG_INFINITY, f64::max),
            mu_max: mu_s.iter().copied().fold(0.0, f64::max),
            mu_limit: limit.mu_limit,
            critical_contact: limit.critical_contact,
        });
    }
    Ok(Seating {
        pose: sim.pose,
        contacts: sim
            .contacts
            .iter()
            .enumerate()
            .map(|(i, c)| ContactResult::from_eval(coupling, i, &c.eval, sim.friction[i]))
            .collect(),
        increments: sim.steps,
        newton_iterations: 0,
        path: crate::solve::SeatingPath::Dynamic,
    })
}

/// Contact state in a trace.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TraceState {
    Open,
    Stick,
    Slip,
}

impl TraceState {
    pub fn name(self) -> &'static str {
        match self {
            TraceState::Open => "open",
            TraceState::Stick => "stick",
            TraceState::Slip => "slip",
        }
    }
}

/// One contact in a trace sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TraceContact {
    /// Normal force including the dashpot [N].
    pub normal_force: f64,
    /// Tangential force magnitude including the dashpot [N].
    pub tangential_force: f64,
    /// Hertz approach, negative when open [m].
    pub approach: f64,
    pub state: TraceState,
}

/// The state at the start of one time step.
#[derive(Debug, Clone, PartialEq)]
pub struct TraceSample {
    pub time: f64,
    pub load_fraction: f64,
    pub pose: BodyPose,
    pub kinetic_energy: f64,
    pub contacts: Vec<TraceContact>,
}

/// Energy at the start of the last step (time t_n), in J.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Energy {
    /// 1/2 m v^2 + 1/2 w.I w with the velocity of step n-1 -> n (rapier's).
    pub kinetic: f64,
    /// The same with the velocity interpolated to t_n, (v_(n-1/2) + v_(n+1/2)) / 2:
    /// symplectic Euler is the leapfrog scheme with velocities at half steps,
    /// so this is the kinetic energy that belongs to the position x_n.
    pub kinetic_synchronized: f64,
    /// Hertz potential sum 2/5 K delta^(5/2) (the integral of K delta^(3/2)).
    pub hertz: f64,
    /// Work done by the preload on the body since t = 0 (sum F_k . dx_k).
    pub preload_work: f64,
}

impl Energy {
    /// Total energy kinetic + Hertz - preload work (constant for a
    /// conservative system; uses the synchronized kinetic energy).
    pub fn total(&self) -> f64 {
        self.kinetic_synchronized + self.hertz - self.preload_work
    }

    /// The same with rapier's unsynchronized velocity.
    pub fn total_unsynchronized(&self) -> f64 {
        self.kinetic + self.hertz - self.preload_work
    }
}

/// Settling status of the last step.
#[derive(Debug, Clone, Copy, PartialEq)]
struct Status {
    kinetic: f64,
    max_speed: f64,
    residual: f64,
}

/// A dynamic seating in progress: step it yourself (tests, studies of the
/// motion) or let [`seat`] run it to rest.
pub struct Simulation<'a> {
    coupling: &'a Coupling,
    friction: Vec<Friction>,
    opts: DynamicOptions,
    mass: MassModel,
    freq: Frequencies,
    world: PhysicsWorld,
    body: RigidBodyHandle,
    dt: f64,
    ramp_time: f64,
    /// Steps taken.
    steps: usize,
    committed_pose: BodyPose,
    states: Vec<TangentialState>,
    /// Pose x_n at which the last step evaluated its forces, and those forces.
    pose: BodyPose,
    contacts: Vec<StepContact>,
    energy: Energy,
    status: Status,
    work: f64,
    length: f64,
    max_travel: f64,
}

impl<'a> Simulation<'a> {
    /// Set up the world at the start pose, at rest.
    pub fn new(
        coupling: &'a Coupling,
        mu_s: &[f64],
        opts: &DynamicOptions,
    ) -> Result<Self, SolveError> {
        opts.check()?;
        let friction = frictions(coupling, mu_s)?;
        let mass = MassModel::of(coupling);
        let freq = frequency::seated_frequencies(coupling, &mass).ok_or_else(|| {
            SolveError::BadOption(
                "the seated coupling has no positive natural frequencies (a contact unloaded \
                 by the preload, or singular mass properties)"
                    .into(),
            )
        })?;
        let touching = coupling.touching_pose;
        let start = touching.moved(&opts.start.offset, &opts.start.tilt);
        let n = coupling.contacts.len();
        let mut states = Vec::with_capacity(n);
        for i in 0..n {
            let g = coupling.geometry(i, &start);
            if g.gap < 0.0 && (opts.start.offset.norm() > 0.0 || opts.start.tilt.norm() > 0.0) {
                return Err(SolveError::StartOverlaps {
                    contact: i + 1,
                    overlap_m: -g.gap,
                });
            }
            states.push(TangentialState::new(g.normal));
        }
        let dt = freq.shortest_period() / opts.steps_per_period;
        let (world, body) = world::build(coupling, &mass, &start, dt);
        let length = coupling.length_scale();
        let max_travel = coupling.slide_away_travel()
            + opts.start.offset.norm()
            + opts.start.tilt.norm() * 2.0 * length;
        Ok(Simulation {
            coupling,
            friction,
            opts: *opts,
            mass,
            freq,
            world,
            body,
            dt,
            ramp_time: opts.ramp_periods * freq.longest_period(),
            steps: 0,
            committed_pose: start,
            states,
            pose: start,
            contacts: Vec::new(),
            energy: Energy {
                kinetic: 0.0,
                kinetic_synchronized: 0.0,
                hertz: 0.0,
                preload_work: 0.0,
            },
            status: Status {
                kinetic: 0.0,
                max_speed: 0.0,
                residual: f64::INFINITY,
            },
            work: 0.0,
            length,
            max_travel,
        })
    }

    /// Time step [s].
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Duration of the preload ramp [s].
    pub fn ramp_time(&self) -> f64 {
        self.ramp_time
    }

    pub fn frequencies(&self) -> Frequencies {
        self.freq
    }

    pub fn mass(&self) -> &MassModel {
        &self.mass
    }

    /// Steps taken so far.
    pub fn steps(&self) -> usize {
        self.steps
    }

    /// Time t_n of the state of the last step (its start) [s].
    pub fn time_of_state(&self) -> f64 {
        self.steps.saturating_sub(1) as f64 * self.dt
    }

    /// Pose x_n at the start of the last step.
    pub fn pose(&self) -> &BodyPose {
        &self.pose
    }

    /// Contacts of the last step, evaluated at x_n.
    pub fn contacts(&self) -> &[StepContact] {
        &self.contacts
    }

    /// Energy at t_n (see [`Energy`]).
    pub fn energy(&self) -> Energy {
        self.energy
    }

    /// Preload fraction lambda(t).
    pub fn load_fraction(&self, t: f64) -> f64 {
        if t >= self.ramp_time {
            1.0
        } else {
            let tau = t / self.ramp_time;
            let s = tau * tau * (3.0 - 2.0 * tau);
            s.powf(1.5)
        }
    }

    fn kinetic(&self, v: &Vector3<f64>, w: &Vector3<f64>, rot: &Matrix3<f64>) -> f64 {
        let iw = rot * self.mass.inertia * rot.transpose();
        0.5 * self.mass.mass * v.norm_squared() + 0.5 * w.dot(&(iw * w))
    }

    /// Advance one time step (module docs).
    pub fn step(&mut self) -> Result<(), SolveError> {
        let c = self.coupling;
        let t = self.steps as f64 * self.dt;
        let lambda = self.load_fraction(t);
        let rb = &self.world.bodies[self.body];
        let pose = from_rapier(rb.position());
        let com = nvec(rb.center_of_mass());
        let linvel = nvec(rb.linvel());
        let angvel = nvec(rb.angvel());
        let rot = pose.rotation.to_rotation_matrix().into_inner();
        let motion = forces::Motion {
            pose: &pose,
            com,
            linvel,
            angvel,
            inv_inertia: self.mass.world_inverse_inertia(&pose.rotation),
            mass: &self.mass,
        };
        let contacts: Vec<StepContact> = (0..c.contacts.len())
            .map(|i| {
                forces::contact_force(
                    c,
                    i,
                    &motion,
                    &self.committed_pose,
                    &self.states[i],
                    self.friction[i].during(self.dt),
                    self.opts.damping,
                )
            })
            .collect();
        let p = &c.scene.preload;
        let fp = p.direction * (p.force * lambda);
        let pp = pose.apply(&p.point);
        // Residual of the contact-layer forces (no dashpots) and the preload.
        let mut rf = fp;
        let mut rm = pp.cross(&fp);
        let mut max_speed: f64 = 0.0;
        let mut hertz = 0.0;
        for (i, sc) in contacts.iter().enumerate() {
            let e = &sc.eval;
            rf += e.force;
            rm += e.geometry.point.cross(&e.force);
            let centre = pose.apply(&c.balls[c.contacts[i].ball].centre);
            max_speed = max_speed
                .max(motion.velocity_at(&centre).norm())
                .max(motion.velocity_at(&e.geometry.point).norm());
            hertz += c.contacts[i].normal.energy(e.approach);
        }
        let residual = (rf.norm() / p.force).max(rm.norm() / (p.force * self.length));
        let kinetic_before = self.kinetic(&linvel, &angvel, &rot);
        // Apply: user forces persist in rapier, so reset them first.
        let rb = &mut self.world.bodies[self.body];
        rb.reset_forces(false);
        rb.reset_torques(false);
        for sc in &contacts {
            rb.add_force_at_point(dvec(&sc.force), dvec(&sc.eval.geometry.point), false);
        }
        rb.add_force_at_point(dvec(&fp), dvec(&pp), false);
        // Commit the tangential history and the pose of this step.
        for (st, sc) in self.states.iter_mut().zip(&contacts) {
            *st = sc.eval.tangential.state.clone();
        }
        self.committed_pose = pose;
        self.world.step();
        let rb = &self.world.bodies[self.body];
        let new_pose = from_rapier(rb.position());
        let (v1, w1) = (nvec(rb.linvel()), nvec(rb.angvel()));
        let finite = new_pose.translation.iter().all(|x| x.is_finite())
            && new_pose.rotation.coords.iter().all(|x| x.is_finite())
            && v1.iter().chain(w1.iter()).all(|x| x.is_finite());
        if !finite || !residual.is_finite() {
            return Err(SolveError::NonFinite {
                time_s: t,
                step: self.steps,
            });
        }
        self.energy = Energy {
            kinetic: kinetic_before,
            kinetic_synchronized: self.kinetic(
                &((linvel + v1) * 0.5),
                &((angvel + w1) * 0.5),
                &rot,
            ),
            hertz,
            preload_work: self.work,
        };
        self.work += fp.dot(&(new_pose.apply(&p.point) - pp));
        self.status = Status {
            kinetic: kinetic_before,
            max_speed,
            residual,
        };
        self.pose = pose;
        self.contacts = contacts;
        self.steps += 1;
        Ok(())
    }

    /// Whether the state of the last step is at rest (module docs).
    pub fn settled(&self) -> bool {
        let v_tol = self.freq.omega_min * self.opts.settle_displacement;
        self.status.max_speed <= v_tol
            && self.status.kinetic <= 0.5 * self.mass.mass * v_tol * v_tol
            && self.status.residual <= self.opts.settle_force
    }

    /// The trace sample of the last step.
    pub fn sample(&self) -> TraceSample {
        let t = self.time_of_state();
        TraceSample {
            time: t,
            load_fraction: self.load_fraction(t),
            pose: self.pose,
            kinetic_energy: self.status.kinetic,
            contacts: self
                .contacts
                .iter()
                .map(|sc| TraceContact {
                    normal_force: sc.normal_force,
                    tangential_force: sc.tangential_force,
                    approach: sc.eval.approach,
                    state: if sc.eval.normal_force <= 0.0 {
                        TraceState::Open
                    } else if sc.eval.slip() == SlipState::Slip {
                        TraceState::Slip
                    } else {
                        TraceState::Stick
                    },
                })
                .collect(),
        }
    }

    /// Number of contact pairs rapier's narrow phase holds (0: its rigid
    /// contact is off for every coupling pair).
    pub fn rapier_contact_pairs(&self) -> usize {
        self.world.narrow_phase.contact_pairs().count()
    }
}
