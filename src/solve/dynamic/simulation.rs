//! The dynamic seating, step by step (the scheme of the module docs of
//! [`super`]).

use nalgebra::{Matrix3, Vector3};
use rapier3d_f64::prelude::{PhysicsWorld, RigidBodyHandle};

use super::forces::{self, StepContact};
use super::frequency::{self, Frequencies};
use super::mass::MassModel;
use super::options::DynamicOptions;
use super::trace::{Energy, TraceContact, TraceSample, TraceState};
use super::world::{self, dvec, from_rapier, nvec};
use crate::assembly::{BodyPose, Coupling};
use crate::contact::friction;
use crate::contact::{Friction, SlipState, TangentialState};
use crate::scene::Preload;
use crate::solve::contact_layer::Motion as LayerMotion;
use crate::solve::preload_forces::{Applied, applied};
use crate::solve::{Load, SolveError};

/// Settling status of the last step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Status {
    pub(super) kinetic: f64,
    max_speed: f64,
    pub(super) residual: f64,
}

/// A dynamic seating in progress: step it yourself (tests, studies of the
/// motion) or let [`seat`] run it to rest.
pub struct Simulation<'a> {
    coupling: &'a Coupling,
    pub(super) friction: Vec<Friction>,
    preload: &'a Preload,
    opts: DynamicOptions,
    mass: MassModel,
    pub(super) freq: Frequencies,
    world: PhysicsWorld,
    body: RigidBodyHandle,
    dt: f64,
    pub(super) ramp_time: f64,
    pub(super) steps: usize,
    committed_pose: BodyPose,
    states: Vec<TangentialState>,
    /// Slip path of each contact so far [m] (committed slip velocity times dt).
    slip_path: Vec<f64>,
    /// Pose x_n at which the last step evaluated its forces, and those forces.
    pub(super) pose: BodyPose,
    pub(super) contacts: Vec<StepContact>,
    /// The slots the next step evaluates its contacts into (the last
    /// step's but one: no evaluation is allocated per step).
    spare: Vec<StepContact>,
    /// The preload forces of the last step (a buffer reused every step).
    preload_forces: Vec<Applied>,
    /// The velocity (linear, angular) at the start of the last step, for
    /// the synchronized kinetic energy of [`Simulation::energy`].
    velocity: (Vector3<f64>, Vector3<f64>),
    pub(super) status: Status,
    /// Work of the preload up to t_n (the state of the last step) and up
    /// to t_(n+1) [J].
    work_at_state: f64,
    work: f64,
    length: f64,
    pub(super) max_travel: f64,
}

impl<'a> Simulation<'a> {
    /// Set up the world at the load's start pose, at rest.
    pub fn new(
        coupling: &'a Coupling,
        load: &'a Load,
        opts: &DynamicOptions,
    ) -> Result<Self, SolveError> {
        load.start.check()?;
        opts.check()?;
        let friction = load.frictions(coupling)?;
        let mass = MassModel::of(coupling);
        let freq =
            frequency::seated_frequencies(coupling, &load.preload, &mass).ok_or_else(|| {
                SolveError::BadOption(
                    "the seated coupling has no positive natural frequencies (a contact unloaded \
                 by the preload, or singular mass properties)"
                        .into(),
                )
            })?;
        let touching = coupling.touching_pose;
        let start = touching.moved(&load.start.offset, &load.start.tilt);
        let n = coupling.contacts.len();
        let mut states = Vec::with_capacity(n);
        for i in 0..n {
            let g = coupling.geometry(i, &start);
            if g.gap < 0.0 && load.start.is_offset() {
                return Err(SolveError::StartOverlaps { contact: i + 1, overlap_m: -g.gap });
            }
            states.push(TangentialState::new(g.normal));
        }
        let dt = freq.shortest_period() / opts.steps_per_period_from(&load.start);
        let (world, body) = world::build(coupling, &mass, &start);
        let length = coupling.length_scale();
        let max_travel = coupling.slide_away_travel()
            + load.start.offset.norm()
            + load.start.tilt.norm() * 2.0 * length;
        Ok(Simulation {
            coupling,
            friction,
            preload: &load.preload,
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
            slip_path: vec![0.0; n],
            pose: start,
            contacts: Vec::new(),
            spare: Vec::new(),
            preload_forces: Vec::new(),
            velocity: (Vector3::zeros(), Vector3::zeros()),
            status: Status { kinetic: 0.0, max_speed: 0.0, residual: f64::INFINITY },
            work_at_state: 0.0,
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

    /// Energy at t_n (see [`Energy`]), formed on request (a seating reads
    /// none): the kinetic energy with the velocities before and after the
    /// last step, the Hertz energy of its contacts.
    pub fn energy(&self) -> Energy {
        let rb = &self.world.bodies[self.body];
        let (v0, w0) = self.velocity;
        let (v1, w1) = (nvec(rb.linvel()), nvec(rb.angvel()));
        let rot = self.pose.rotation.to_rotation_matrix().into_inner();
        let hertz = (self.contacts.iter().zip(&self.coupling.contacts))
            .fold(0.0, |e, (sc, c)| e + c.normal.energy(sc.eval.approach));
        Energy {
            kinetic: self.status.kinetic,
            kinetic_synchronized: self.kinetic(&((v0 + v1) * 0.5), &((w0 + w1) * 0.5), &rot),
            hertz,
            preload_work: self.work_at_state,
        }
    }

    /// Preload fraction lambda(t).
    pub fn load_fraction(&self, t: f64) -> f64 {
        if t >= self.ramp_time {
            1.0
        } else {
            let tau = t / self.ramp_time;
            let s = tau * tau * (3.0 - 2.0 * tau);
            // s^1.5 as s sqrt(s): one square root instead of pow.
            s * s.sqrt()
        }
    }

    fn kinetic(&self, v: &Vector3<f64>, w: &Vector3<f64>, rot: &Matrix3<f64>) -> f64 {
        let iw = rot * self.mass.inertia * rot.transpose();
        0.5 * self.mass.mass * v.norm_squared() + 0.5 * w.dot(&(iw * w))
    }

    /// Advance one time step (module docs): evaluate the contacts at x_n,
    /// the residual of the contact-layer forces and the preload, apply the
    /// forces and commit, then let rapier integrate the body ([`world::integrate`]).
    pub fn step(&mut self) -> Result<(), SolveError> {
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
        let mut contacts = std::mem::take(&mut self.spare);
        self.contact_forces(&motion, &mut contacts);
        let mut preload = std::mem::take(&mut self.preload_forces);
        preload.clear();
        preload.extend(applied(self.coupling, self.preload, &pose, lambda));
        let (residual, max_speed) = self.balance(&motion, &contacts, &preload);
        let kinetic_before = self.kinetic(&linvel, &angvel, &rot);
        self.apply_and_commit(&contacts, &preload, pose);
        world::integrate(&mut self.world.bodies[self.body], self.dt);
        let rb = &self.world.bodies[self.body];
        let new_pose = from_rapier(rb.position());
        let (v1, w1) = (nvec(rb.linvel()), nvec(rb.angvel()));
        let finite = new_pose.translation.iter().all(|x| x.is_finite())
            && new_pose.rotation.coords.iter().all(|x| x.is_finite())
            && v1.iter().chain(w1.iter()).all(|x| x.is_finite());
        if !finite || !residual.is_finite() {
            return Err(SolveError::NonFinite { time_s: t, step: self.steps });
        }
        self.velocity = (linvel, angvel);
        self.work_at_state = self.work;
        let points = self.preload.forces.iter().map(|f| f.point);
        for (a, point) in preload.iter().zip(points) {
            self.work += a.force.dot(&(new_pose.apply(&point) - a.point));
        }
        self.status = Status { kinetic: kinetic_before, max_speed, residual };
        self.pose = pose;
        self.spare = std::mem::replace(&mut self.contacts, contacts);
        self.preload_forces = preload;
        self.steps += 1;
        Ok(())
    }

    /// Every contact's force at the pose of `motion` (contact layer and
    /// dashpots) into `out`, one slot per contact.
    fn contact_forces(&self, motion: &forces::Motion, out: &mut Vec<StepContact>) {
        let c = self.coupling;
        out.resize_with(c.contacts.len(), StepContact::empty);
        let back = LayerMotion::between(motion.pose, &self.committed_pose);
        for (i, slot) in out.iter_mut().enumerate() {
            forces::contact_force(
                slot,
                c,
                i,
                motion,
                &back,
                &self.states[i],
                self.friction[i].during(self.dt),
                self.opts.damping,
            );
        }
    }

    /// Residual of the contact-layer forces (no dashpots) and the preload
    /// forces, relative to F_p and F_p L (F_p the preload's scale); the
    /// largest speed of a ball centre or contact point.
    fn balance(
        &self,
        motion: &forces::Motion,
        contacts: &[StepContact],
        preload: &[Applied],
    ) -> (f64, f64) {
        let c = self.coupling;
        let scale = self.preload.scale();
        let (mut rf, mut rm) = (Vector3::zeros(), Vector3::zeros());
        for a in preload {
            rf += a.force;
            rm += a.point.cross(&a.force);
        }
        let mut max_speed: f64 = 0.0;
        for (i, sc) in contacts.iter().enumerate() {
            let e = &sc.eval;
            rf += e.force;
            rm += e.geometry.point.cross(&e.force);
            let centre = motion.pose.apply(&c.contacts[i].centre);
            max_speed = max_speed
                .max(motion.velocity_at(&centre).norm())
                .max(motion.velocity_at(&e.geometry.point).norm());
        }
        let residual = (rf.norm() / scale).max(rm.norm() / (scale * self.length));
        (residual, max_speed)
    }

    /// Set the contact forces and the preload as rapier user forces (they
    /// persist in rapier, so reset first), and commit the tangential
    /// history and the pose of this step.
    fn apply_and_commit(&mut self, contacts: &[StepContact], preload: &[Applied], pose: BodyPose) {
        let rb = &mut self.world.bodies[self.body];
        rb.reset_forces(false);
        rb.reset_torques(false);
        for sc in contacts {
            rb.add_force_at_point(dvec(&sc.force), dvec(&sc.eval.geometry.point), false);
        }
        for a in preload {
            rb.add_force_at_point(dvec(&a.force), dvec(&a.point), false);
        }
        for ((st, sc), path) in self.states.iter_mut().zip(contacts).zip(&mut self.slip_path) {
            *st = sc.eval.tangential.state.clone();
            *path += st.slip_velocity * self.dt;
        }
        self.committed_pose = pose;
    }

    /// The decay law's c v_slip so far ([`crate::solve::Seating::decay_cv`]):
    /// v_slip of a contact is its slip path over the ramp duration (over
    /// the time so far for a step load).
    pub fn decay_cv(&self) -> Option<f64> {
        let time = if self.ramp_time > 0.0 { self.ramp_time } else { self.time_of_state() };
        friction::seating_cv(&self.friction, &self.slip_path, time)
    }

    /// Whether a contact has slipped so far (its slip path is not zero).
    pub fn slid(&self) -> bool {
        self.slip_path.iter().any(|p| *p > 0.0)
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
}
