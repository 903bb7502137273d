//! The Newton corrector of the path follower: residual, consistent
//! Jacobian and the iteration of one increment (module docs of
//! [`super`]). Allocation-free: the contact evaluations go into a buffer
//! the caller owns, the 6x6 system lives and is solved on the stack
//! (`lu6`).
//!
//! Convergence: the relative residual below `tolerance`, or, where the
//! residual cannot get there in f64 (it stalls: less than a tenfold drop in
//! an iteration), the Newton correction below the resolution of the pose
//! itself: |dv| + L |dw| <= 64 eps L (L the coupling radius). Contact forces come from approaches delta of about a
//! micrometre computed as differences of positions of size L, so their
//! rounding is about eps L / delta of the contact force; for a coupling of
//! a metre or more that is above 1e-10 of the preload, and without this
//! floor Newton would stall and the increment be halved until it fails.
//!
//! Lazy tangent: the consistent tangent of the contacts (K_t, the return
//! map's derivative, the dF_t/dF_n terms: `ContactEval::stiffness`) is
//! read by the Jacobian only: not by the residual, the convergence test,
//! the commit, the predictor, the stick/slip decisions and halving of the
//! path, nor the reported contacts. So an evaluation forms it only when a
//! Jacobian will follow: eagerly where the iterate is expected to fail the
//! test (the predictor, and a correction from a relative residual r above
//! sqrt(tolerance): Newton's quadratic convergence gives about C r^2, C of
//! order 1-10 here, so a step from r = 1e-4 lands near 1e-7), and else
//! only once the iterate has failed it, by evaluating the same pose again
//! with the tangent (measured: 0 to 4 % of the corrected iterates of
//! scenes 01, 02, 06). Forces and states are formed by the same operations
//! with or without the tangent, so the seating does not depend on the
//! rule; it only decides where the tangent work is spent.

use nalgebra::{Matrix3, Matrix6, UnitQuaternion, Vector3, Vector6};

use super::external::ExternalLoad;
use super::jacobian::{add_contact, add_fixed_force};
use super::lu6::solve6;
use crate::assembly::constraint::frictionless_forces;
use crate::assembly::{BodyPose, ContactGeometry, Coupling};
use crate::contact::{Friction, TangentialState};
use crate::lane::{Lane, Mask, branch, each_lane, splat};
use crate::scene::Preload;
use crate::solve::contact_layer::{
    ContactEval, Expansion, Motion, Moved, NormalPart, evaluate_into,
};
use crate::solve::preload_forces::applied;
use crate::solve::{ContactResult, SolveError, SolverOptions};

/// Contacts evaluated together by [`Solver::evaluate_all`] (a kinematic
/// coupling has six).
const GROUP: usize = 8;

/// A force and the world point it acts at (moving with the body).
type PointForce = (Vector3<f64>, Vector3<f64>);

/// What the path follower ramps.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Program {
    /// The preload from 0 (lambda = s^1.5) from the touching pose.
    Seat,
    /// Full preload plus s * factor * load.
    Load { load: ExternalLoad, factor: f64 },
    /// The full preload held while the bodies' temperatures change (a
    /// thermal path, `super::thermal`).
    Hold,
}

/// The loads of one increment: preload factor, extra-load factor, and the
/// increment's duration [s] (the decay friction law's time base).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) struct Loads {
    pub lambda: f64,
    pub extra: f64,
    pub duration: f64,
    /// The path parameter at the end of the increment.
    pub s: f64,
}

/// The outcome of Newton on one increment; the evaluations of a converged
/// increment are in the caller's buffer.
pub(super) enum Step {
    /// Converged pose and the iterations it took.
    Converged(BodyPose, usize),
    /// Failed, with the last relative residual.
    Failed(f64),
}

pub(super) struct Solver<'a> {
    pub coupling: &'a Coupling,
    pub friction: &'a [Friction],
    /// The preload the path ramps (a seating) or holds (a load path).
    pub preload: &'a Preload,
    pub opts: SolverOptions,
    pub program: Program,
    /// Force scale of the residual [N].
    pub(super) force_scale: f64,
    /// Coupling radius, the length scale of moments [m].
    pub(super) length: f64,
    /// Predictor twist per unit s.
    pub x1: Vector6<f64>,
    /// Slide-away bound on the translation [m].
    pub max_travel: f64,
    /// Duration of the whole path, s from 0 to 1 (`[preload] ramp_time`) [s].
    pub ramp_time: f64,
    /// The bodies' expansion over the increment being solved (a thermal
    /// path's; `None`: the bodies keep their size).
    pub expansion: Option<Expansion>,
}

impl<'a> Solver<'a> {
    /// The path follower of `program`, with the seating predictor x_1
    /// ([`predictor`]; a load path, which starts from its start pose, reads
    /// none).
    pub fn new(
        coupling: &'a Coupling,
        friction: &'a [Friction],
        preload: &'a Preload,
        opts: SolverOptions,
        program: Program,
        x1: Vector6<f64>,
    ) -> Self {
        let length = coupling.length_scale();
        let scale = preload.scale();
        let force_scale = match program {
            Program::Seat | Program::Hold => scale,
            Program::Load { load, factor } => {
                let f = factor.abs();
                scale.max(f * load.force.norm()).max(f * load.moment.norm() / length)
            }
        };
        Solver {
            coupling,
            friction,
            preload,
            opts,
            program,
            force_scale,
            length,
            x1,
            max_travel: coupling.slide_away_travel(),
            ramp_time: preload.ramp_time,
            expansion: None,
        }
    }

    /// Preload factor and extra-load factor at path parameter s.
    pub fn loads_at(&self, s: f64) -> (f64, f64) {
        match self.program {
            // s^1.5 as s sqrt(s): one square root instead of pow.
            Program::Seat => (s * s.sqrt(), 0.0),
            Program::Load { factor, .. } => (1.0, s * factor),
            Program::Hold => (1.0, 0.0),
        }
    }

    /// Why a path failed at `lambda`: the preload factor of a seating, the
    /// fraction of the applied load of a load path.
    pub fn failure(
        &self,
        lambda: f64,
        residual: f64,
        pose: &BodyPose,
        start: &BodyPose,
    ) -> SolveError {
        let travel = (pose.translation - start.translation).norm();
        let percent = 100.0 * lambda;
        let splits = self.opts.max_splits;
        let slid = travel > 0.5 * self.max_travel;
        match (&self.program, slid) {
            (Program::Seat, true) => SolveError::SlidAway { percent, displacement_m: travel },
            (Program::Seat, false) => SolveError::NotConverged { percent, residual, splits },
            (Program::Load { .. } | Program::Hold, true) => {
                SolveError::LoadSlidAway { percent, displacement_m: travel }
            }
            (Program::Load { .. } | Program::Hold, false) => {
                SolveError::LoadNotConverged { percent, residual, splits }
            }
        }
    }

    /// Every contact at `pose` into `out`, one slot per contact (the slots
    /// are made once, then written in place), with the tangent if `tangent`
    /// ([`evaluate_into`]).
    pub fn evaluate_all(
        &self,
        pose: &BodyPose,
        committed_pose: &BodyPose,
        states: &[TangentialState],
        duration: f64,
        tangent: bool,
        out: &mut Vec<ContactEval>,
    ) {
        if out.len() != states.len() {
            out.resize_with(states.len(), ContactEval::empty);
        }
        let motion = match &self.expansion {
            None => Motion::between(pose, committed_pose),
            Some(e) => Motion::expanding(pose, committed_pose, e),
        };
        // Two passes over each group of contacts: first geometry and the
        // normal part (the long square- and cube-root chains) of every
        // contact of the group, then the tangential law and the tangent, so
        // that the chains of different contacts overlap in the processor
        // (`contact_layer::NormalPart`; the same operations per contact).
        let mut normal = [NormalPart::default(); GROUP];
        for start in (0..states.len()).step_by(GROUP) {
            let end = (start + GROUP).min(states.len());
            for i in start..end {
                let g = self.coupling.geometry(i, pose);
                let memo = &mut out[i].committed_root;
                normal[i - start] = NormalPart::new(self.coupling, i, &g, &states[i], memo);
                out[i].geometry = g;
            }
            for i in start..end {
                let moved = Moved {
                    du: motion.displacement(&out[i].geometry.point),
                    committed: &states[i],
                    friction: self.friction[i].during(duration),
                };
                evaluate_into(&mut out[i], self.coupling, i, &moved, &normal[i - start], tangent);
            }
        }
    }

    /// Net force and moment on the moving half: the preload forces
    /// ([`applied`]), the contacts, and the extra load.
    fn residual(&self, pose: &BodyPose, evals: &[ContactEval], loads: &Loads) -> Vector6<f64> {
        let contacts = evals.iter().map(|e| (&e.force, &e.geometry.point));
        let mut r = self.net_wrench(pose, loads.lambda, contacts);
        if let Some((fe, pe)) = self.extra_force(pose, loads) {
            let m = pe.cross(&fe);
            r += Vector6::new(fe.x, fe.y, fe.z, m.x, m.y, m.z);
            let me = self.extra_moment(loads);
            r += Vector6::new(0.0, 0.0, 0.0, me.x, me.y, me.z);
        }
        r
    }

    /// The net force and moment about the origin of the preload forces at
    /// `lambda` and then of `contacts` (force, point), in that order (per
    /// lane for lanes: the residual of [`Self::newton`] and of the lanes').
    #[inline(always)]
    pub(super) fn net_wrench<'e, T: Lane>(
        &self,
        pose: &BodyPose<T>,
        lambda: f64,
        contacts: impl Iterator<Item = (&'e Vector3<T>, &'e Vector3<T>)>,
    ) -> Vector6<T> {
        let mut r = Vector6::zeros();
        let mut add = |f: &Vector3<T>, at: &Vector3<T>| {
            let m = at.cross(f);
            r += Vector6::new(f.x, f.y, f.z, m.x, m.y, m.z);
        };
        for a in applied(self.coupling, self.preload, pose, lambda) {
            add(&a.force, &a.point);
        }
        for (f, at) in contacts {
            add(f, at);
        }
        r
    }

    /// The extra load's force and its world point (a load path only).
    fn extra_force(&self, pose: &BodyPose, loads: &Loads) -> Option<PointForce> {
        match self.program {
            Program::Load { load, .. } => Some((load.force * loads.extra, pose.apply(&load.point))),
            Program::Seat | Program::Hold => None,
        }
    }

    /// The extra load's pure moment (a load path only).
    fn extra_moment(&self, loads: &Loads) -> Vector3<f64> {
        match self.program {
            Program::Load { load, .. } => load.moment * loads.extra,
            Program::Seat | Program::Hold => Vector3::zeros(),
        }
    }

    /// Per lane for lanes, with f64's `max` (a NaN side gives the other).
    #[inline(always)]
    pub(super) fn relative<T: Lane>(&self, r: &Vector6<T>) -> T {
        let fp = splat::<T>(self.force_scale);
        let rf = r.fixed_rows::<3>(0).norm() / fp;
        let rm = r.fixed_rows::<3>(3).norm() / (fp * splat(self.length));
        let larger = rf.simd_max(rm);
        rm.select(rf.simd_ne(rf), rf.select(rm.simd_ne(rm), larger))
    }

    /// Newton from `start` on the increment with `loads` from the committed
    /// pose and states; the evaluations of the last iterate are left in `evals`.
    pub fn newton(
        &self,
        committed_pose: &BodyPose,
        states: &[TangentialState],
        start: BodyPose,
        loads: &Loads,
        evals: &mut Vec<ContactEval>,
    ) -> Step {
        let mut pose = start;
        let mut last = f64::INFINITY;
        for it in 0..self.opts.max_newton {
            // Lazy tangent (module docs): formed with the forces where this
            // iterate is expected to fail the test, else only if it does.
            let eager = last > self.opts.tolerance.sqrt();
            self.evaluate_all(&pose, committed_pose, states, loads.duration, eager, evals);
            let r = self.residual(&pose, evals, loads);
            let rel = self.relative(&r);
            if !rel.is_finite() {
                return Step::Failed(rel);
            }
            if rel < self.opts.tolerance {
                return Step::Converged(pose, it + 1);
            }
            let stalled = rel > 0.1 * last;
            last = rel;
            if !eager {
                self.evaluate_all(&pose, committed_pose, states, loads.duration, true, evals);
            }
            let j = self.jacobian(evals, &pose, loads);
            let Some(dx) = solve6(&j, &(-r)) else {
                return Step::Failed(rel);
            };
            if !dx.iter().all(|v| v.is_finite()) || dx.fixed_rows::<3>(0).norm() > self.max_travel {
                return Step::Failed(rel);
            }
            if stalled && self.at_resolution(&dx) {
                return Step::Converged(pose, it + 1);
            }
            pose = pose.moved(&dx.fixed_rows::<3>(0).into(), &dx.fixed_rows::<3>(3).into());
        }
        Step::Failed(last)
    }

    /// A Newton correction below what f64 resolves in a pose of size L:
    /// |dv| + L |dw| <= 64 eps L (module docs).
    /// Per lane for lanes.
    #[inline(always)]
    pub(super) fn at_resolution<T: Lane>(&self, dx: &Vector6<T>) -> Mask<T> {
        let size =
            dx.fixed_rows::<3>(0).norm() + splat::<T>(self.length) * dx.fixed_rows::<3>(3).norm();
        size.simd_le(splat(64.0 * f64::EPSILON * self.length))
    }

    /// dR/d(v, w) for a twist about the world origin: contact stiffness K_i
    /// mapped through dp = v - [p]x w, plus the moments of forces whose
    /// points move with the body ([`add_contact`]), plus each preload
    /// spring's stiffness the same way.
    fn jacobian(&self, evals: &[ContactEval], pose: &BodyPose, loads: &Loads) -> Matrix6<f64> {
        let contacts = evals.iter().enumerate().map(|(i, e)| {
            debug_assert!(e.tangent, "contact {i} evaluated without its tangent");
            (&e.stiffness, &e.force, &e.geometry)
        });
        let mut j = self.wrench_jacobian(pose, loads.lambda, contacts);
        if let Some((f, p)) = self.extra_force(pose, loads) {
            add_fixed_force(&mut j, &f, &p);
        }
        j
    }

    /// The Jacobian of [`Self::net_wrench`]: each contact's (stiffness,
    /// force, geometry), then each preload force (per lane for lanes: the
    /// Jacobian of [`Self::newton`] and of the lanes').
    #[inline(always)]
    pub(super) fn wrench_jacobian<'e, T: Lane>(
        &self,
        pose: &BodyPose<T>,
        lambda: f64,
        contacts: impl Iterator<Item = (&'e Matrix3<T>, &'e Vector3<T>, &'e ContactGeometry<T>)>,
    ) -> Matrix6<T> {
        let mut j = Matrix6::zeros();
        for (i, (k, f, g)) in contacts.enumerate() {
            let centre = g.point + g.normal * splat::<T>(self.coupling.contacts[i].radius);
            add_contact(&mut j, k, f, &g.point, &centre);
        }
        for a in applied(self.coupling, self.preload, pose, lambda) {
            match a.stiffness {
                Some(k) => add_contact(&mut j, &k, &a.force, &a.point, &a.point),
                None => add_fixed_force(&mut j, &a.force, &a.point),
            }
        }
        j
    }
}

/// The reported contacts of the evaluations `evals` (contact order) with
/// their frictions.
pub(super) fn contact_results(
    coupling: &Coupling,
    friction: &[Friction],
    evals: &[ContactEval],
) -> Vec<ContactResult> {
    evals
        .iter()
        .enumerate()
        .map(|(i, e)| ContactResult::from_eval(coupling, i, e, friction[i]))
        .collect()
}

/// The predictor twist per unit s of a seating (module docs of [`super`]):
/// W x_1 = -delta_i(f_i), W the constraint rows at the touching pose, f_i
/// the frictionless contact forces at full preload, delta_i the approach
/// (Hertz plus support compliance). Depends on the coupling and the
/// preload; allocates nothing.
pub(super) fn predictor(coupling: &Coupling, preload: &Preload) -> Vector6<f64> {
    let w = coupling.constraint_rows(&coupling.touching_pose);
    let f = frictionless_forces(coupling, preload);
    let rhs = Vector6::from_fn(|i, _| -coupling.contacts[i].normal.approach(f[i].max(0.0)));
    w.lu().solve(&rhs).unwrap_or_else(Vector6::zeros)
}

/// The twist (v, w) with `from.moved(v, w) == to` (per lane for lanes).
pub(super) fn twist_between<T: Lane>(from: &BodyPose<T>, to: &BodyPose<T>) -> Vector6<T> {
    let dq = to.rotation * from.rotation.inverse();
    let w = rotation_log(&dq);
    let v = to.translation - dq * from.translation;
    Vector6::new(v.x, v.y, v.z, w.x, w.y, w.z)
}

/// The rotation vector w of the unit quaternion q = (c, v): w = 2
/// atan2(|v|, |c|) v/|v| (v negated where c < 0: the angle in [0, pi]), as
/// nalgebra's `UnitQuaternion::scaled_axis`. For |v| < 1e-4 (an
/// increment's turn) by the series 2 atan(r)/r = 2 (1 - r^2/3 + r^4/5),
/// r = |v|/|c|, whose first omitted term r^6/7 is below 1e-24: equal to
/// rounding, without atan2 and the normalisation. Each lane by its own
/// turn (nalgebra's form lane by lane: it has none over lanes).
fn rotation_log<T: Lane>(q: &UnitQuaternion<T>) -> Vector3<T> {
    let (c, v) = (q.w, q.imag());
    let vv = v.norm_squared();
    branch::<T, _>(
        vv.simd_ge(splat(1e-8)),
        |_| each_lane(q, |q: UnitQuaternion<f64>| q.scaled_axis()),
        |_| {
            let (one, r2) = (T::one(), vv / (c * c));
            v * (splat::<T>(2.0) / c * (one - r2 / splat(3.0) * (one - splat::<T>(0.6) * r2)))
        },
    )
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assembly::rotation_exp;

    /// The series of `rotation_exp` and `rotation_log` against nalgebra's
    /// sin/cos and atan2 forms, over turns from 1e-12 to 1 rad on both
    /// sides of the series' thresholds, and their round trip.
    #[test]
    fn rotation_series_equal_the_trigonometric_forms() {
        let axes = [
            Vector3::new(0.3, -0.5, 0.81),
            Vector3::new(-1.0, 0.2, 0.0),
            Vector3::new(0.0, 0.0, -1.0),
        ];
        for axis in axes {
            let axis = axis.normalize();
            for e in -120..=0 {
                let w = axis * 10f64.powf(e as f64 / 10.0);
                let q = rotation_exp(&w);
                let reference = UnitQuaternion::from_scaled_axis(w);
                assert!((q.coords - reference.coords).amax() <= 2e-16, "{w:?}");
                assert!((q.norm() - 1.0).abs() <= 4e-16, "{w:?}");
                let back = rotation_log(&reference);
                let expected = reference.scaled_axis();
                assert!((back - expected).amax() <= 1e-15 * w.norm(), "{w:?}");
                assert!((back - w).amax() <= 1e-14 * w.norm(), "{w:?}");
                // the other sign of the same rotation
                let negated = UnitQuaternion::new_unchecked(-reference.into_inner());
                assert!((rotation_log(&negated) - expected).amax() <= 1e-15 * w.norm());
            }
        }
        assert_eq!(rotation_log(&UnitQuaternion::<f64>::identity()), Vector3::zeros());
        // Over lanes, each lane is its own f64 log (turns on both sides of
        // the series' threshold in one set of four).
        use crate::lane::F64x4;
        use simba::simd::SimdValue;
        let turns = [1e-12, 3e-5, 1e-3, 0.7].map(|t| axes[0] * t);
        let q = turns.map(UnitQuaternion::from_scaled_axis);
        let lanes = UnitQuaternion::new_unchecked(nalgebra::Quaternion::from(
            nalgebra::Vector4::from_fn(|i, _| F64x4::from(q.map(|q| q.coords[i]))),
        ));
        let logs = rotation_log(&lanes);
        for (i, q) in q.iter().enumerate() {
            let alone = rotation_log(q);
            assert!((0..3).all(|r| logs[r].extract(i).to_bits() == alone[r].to_bits()), "{i}");
        }
        // A turn of rounding size is none, as in nalgebra's exp.
        let noise = Vector3::new(1e-19, -2e-19, 4e-17);
        assert_eq!(rotation_exp(&noise), UnitQuaternion::identity());
        assert_eq!(UnitQuaternion::from_scaled_axis(noise), UnitQuaternion::identity());
    }
}
