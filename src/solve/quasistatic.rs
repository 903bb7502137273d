//! Quasi-static seating: the preload ramps from 0 to F_p; at each increment
//! Newton solves the six pose unknowns of the moving half so that the
//! preload and the contact forces balance (MODEL.md §3).
//!
//! - Load schedule: lambda = s^(3/2) with s in uniform steps, so that every
//!   increment adds about the same Hertz approach (delta ~ F^(2/3)).
//! - Predictor: the linearised frictionless solution, x(lambda) = s x_1,
//!   where W x_1 = -(f_i / K_i)^(2/3) (W the constraint rows, f_i the
//!   frictionless contact forces at full preload).
//! - Corrector: Newton on R(x) = sum_i [F_i; p_i x F_i] + [P; p_P x P] = 0
//!   with the consistent tangent of the contact layer plus the geometric
//!   terms of moving points; finite rotations (quaternions), contact points
//!   and normals from parry at the current pose. Converged when
//!   |R_F| < tol F_p and |R_M| < tol F_p L (L the coupling radius).
//! - Adaptivity: an increment is halved when Newton fails, and when a
//!   contact changes between stick and slip, until that change is located
//!   within 2^-max_splits of a nominal increment.

use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};

use super::contact_layer::{ContactEval, evaluate};
use super::{ContactResult, Seating, SolveError, SolverOptions, frictions};
use crate::assembly::constraint::frictionless_preload_forces;
use crate::assembly::{BodyPose, Coupling};
use crate::contact::{Friction, SlipState, TangentialState};

/// Seat the coupling with static coefficients `mu_s` (contact order).
pub fn seat(
    coupling: &Coupling,
    mu_s: &[f64],
    opts: &SolverOptions,
) -> Result<Seating, SolveError> {
    let fr = frictions(coupling, mu_s)?;
    Solver::new(coupling, fr, *opts).run()
}

struct Solver<'a> {
    coupling: &'a Coupling,
    friction: Vec<Friction>,
    opts: SolverOptions,
    /// Coupling radius, the length scale of moments [m].
    length: f64,
    /// Predictor twist per unit s.
    x1: Vector6<f64>,
    /// Slide-away bound on the translation [m].
    max_travel: f64,
}

enum Step {
    Converged(BodyPose, Vec<ContactEval>, usize),
    Failed(f64),
}

impl<'a> Solver<'a> {
    fn new(coupling: &'a Coupling, friction: Vec<Friction>, opts: SolverOptions) -> Self {
        let touching = coupling.touching_pose;
        let length = coupling.length_scale();
        let rows = coupling.constraint_rows(&touching);
        let w = Matrix6::from_fn(|r, c| rows[r][c]);
        let f = frictionless_preload_forces(coupling);
        let rhs = Vector6::from_fn(|i, _| {
            -(f[i].max(0.0) / coupling.contacts[i].law.hertz.hertz_constant).powf(2.0 / 3.0)
        });
        let x1 = w.lu().solve(&rhs).unwrap_or_else(Vector6::zeros);
        Solver {
            coupling,
            friction,
            opts,
            length,
            x1,
            max_travel: coupling.slide_away_travel(),
        }
    }

    fn run(&self) -> Result<Seating, SolveError> {
        let c = self.coupling;
        let n = c.contacts.len();
        let mut pose = c.touching_pose;
        let mut states: Vec<TangentialState> = (0..n)
            .map(|i| TangentialState::new(c.geometry(i, &pose).normal))
            .collect();
        let nominal = 1.0 / self.opts.increments.max(1) as f64;
        let h_min = nominal / f64::powi(2.0, self.opts.max_splits as i32);
        let (mut s, mut h) = (0.0_f64, nominal);
        let mut evals: Vec<ContactEval> = Vec::new();
        let (mut accepted, mut iterations) = (0, 0);
        let mut last_step: Option<(Vector6<f64>, f64)> = None;
        while s < 1.0 {
            let s_next = if s + h > 1.0 - 1e-12 { 1.0 } else { s + h };
            let lambda = s_next.powf(1.5);
            // Secant predictor from the last accepted increment (the path is
            // nearly straight in s), the frictionless one at the start.
            let dx = match last_step {
                Some((dx, ds)) => dx * ((s_next - s) / ds),
                None => self.x1 * (s_next - s),
            };
            let predictor =
                pose.moved(&dx.fixed_rows::<3>(0).into(), &dx.fixed_rows::<3>(3).into());
            match self.newton(&pose, &states, predictor, lambda) {
                Step::Failed(residual) => {
                    if h <= h_min * 1.5 {
                        return Err(self.failure(lambda, residual, &pose));
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
                    if let Some(i) = new_evals.iter().position(|e| e.normal_force <= 0.0) {
                        return Err(SolveError::ContactOpened {
                            contact: i + 1,
                            percent: 100.0 * lambda,
                        });
                    }
                    let travel = (new_pose.translation - c.touching_pose.translation).norm();
                    if travel > self.max_travel {
                        return Err(SolveError::SlidAway {
                            percent: 100.0 * lambda,
                            displacement_m: travel,
                        });
                    }
                    states = new_evals.iter().map(|e| e.tangential.state).collect();
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
        Ok(Seating {
            pose,
            contacts: evals
                .iter()
                .enumerate()
                .map(|(i, e)| self.result(i, e))
                .collect(),
            increments: accepted,
            newton_iterations: iterations,
        })
    }

    fn failure(&self, lambda: f64, residual: f64, pose: &BodyPose) -> SolveError {
        let travel = (pose.translation - self.coupling.touching_pose.translation).norm();
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
    ) -> Vec<ContactEval> {
        (0..self.coupling.contacts.len())
            .map(|i| {
                evaluate(
                    self.coupling,
                    i,
                    pose,
                    committed_pose,
                    &states[i],
                    self.friction[i],
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
    ) -> (Vector6<f64>, Vector3<f64>, Vector3<f64>) {
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
        (r, fp, pp)
    }

    fn relative(&self, r: &Vector6<f64>) -> f64 {
        let fp = self.coupling.scene.preload.force;
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
    ) -> Step {
        let mut pose = start;
        let mut last = f64::INFINITY;
        for it in 0..self.opts.max_newton {
            let evals = self.evaluate_all(&pose, committed_pose, states);
            let (r, fp, pp) = self.residual(&pose, &evals, lambda);
            let rel = self.relative(&r);
            if !rel.is_finite() {
                return Step::Failed(rel);
            }
            if rel < self.opts.tolerance {
                return Step::Converged(pose, evals, it + 1);
            }
            last = rel;
            let j = self.jacobian(&evals, &fp, &pp);
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
    fn jacobian(
        &self,
        evals: &[ContactEval],
        fp: &Vector3<f64>,
        pp: &Vector3<f64>,
    ) -> Matrix6<f64> {
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
        add_point_force(&Matrix3::zeros(), fp, pp, pp);
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
