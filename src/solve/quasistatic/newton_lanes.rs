//! Newton on one increment of a seating over lanes: four seatings' poses
//! corrected at once, one per lane ([`crate::lane`]), by the iteration of
//! [`Solver::newton`] (module docs of `super::solver`) written over the
//! same functions: the contacts in lanes (`solve::contact_lanes`), the
//! preload forces, a contact's Jacobian columns, the 6x6 solve and the
//! pose's move. A lane that has converged keeps its pose (its contacts are
//! evaluated again there, to the same values) while the others iterate,
//! so that each lane's pose, iteration count and contacts are its f64
//! seating's bit for bit. The lazy tangent is formed where any iterating
//! lane would form it (it changes no force or state).
//!
//! `None` where the f64 Newton of some lane would fail (a residual that is
//! not finite, a singular or unbounded correction, no convergence in
//! `max_newton` iterations), where the contacts cannot be followed in
//! lanes, and for a program other than a seating: the set of four is then
//! seated one by one.

use nalgebra::Vector6;
use simba::simd::{SimdBool, SimdValue};

use super::lu6::solve6;
use super::solver::{Loads, Program, Solver};
use crate::assembly::BodyPose;
use crate::lane::{Lane, Mask, splat};
use crate::solve::contact_lanes::{LaneContact, LaneFriction, LaneState, evaluate_lanes};
use crate::solve::contact_layer::Motion;

/// The committed side of an increment in lanes: the pose, each contact's
/// state, its normal force's cube root and its friction.
pub(super) struct LaneIncrement<'a, T: Lane> {
    pub pose: &'a BodyPose<T>,
    pub states: &'a [LaneState<T>],
    pub roots: &'a [T],
    pub frictions: &'a [LaneFriction<T>],
}

impl Solver<'_> {
    /// Newton from `start` on the increment with `loads`: the converged
    /// pose and iteration count of each lane, its contacts left in
    /// `evals` (module docs).
    pub(super) fn newton_lanes<T: Lane>(
        &self,
        inc: &LaneIncrement<T>,
        start: BodyPose<T>,
        loads: &Loads,
        evals: &mut Vec<LaneContact<T>>,
    ) -> Option<(BodyPose<T>, T)> {
        if self.program != Program::Seat || self.expansion.is_some() {
            return None;
        }
        let (mut pose, mut its) = (start, T::zero());
        let mut last = splat::<T>(f64::INFINITY);
        let mut active = Mask::<T>::splat(true);
        for it in 0..self.opts.max_newton {
            let eager = (last.simd_gt(splat(self.opts.tolerance.sqrt())) & active).any();
            self.evaluate_lanes_all(&pose, inc, loads.duration, eager, evals)?;
            let r = self.residual_lanes(&pose, evals, loads);
            let rel = self.relative(&r);
            if (!rel.simd_eq(rel) | rel.simd_abs().simd_eq(splat(f64::INFINITY))).any() {
                return None;
            }
            let converged = rel.simd_lt(splat(self.opts.tolerance)) & active;
            its = splat::<T>((it + 1) as f64).select(converged, its);
            active = active & !converged;
            if active.none() {
                return Some((pose, its));
            }
            let stalled = rel.simd_gt(splat::<T>(0.1) * last);
            last = rel;
            if !eager {
                self.evaluate_lanes_all(&pose, inc, loads.duration, true, evals)?;
            }
            let contacts = evals.iter().map(|e| (&e.stiffness, &e.force, &e.geometry));
            let j = self.wrench_jacobian(&pose, loads.lambda, contacts);
            let dx = solve6(&j, &(-r))?;
            let v = dx.fixed_rows::<3>(0).into_owned();
            let w = dx.fixed_rows::<3>(3).into_owned();
            let finite = dx.iter().fold(Mask::<T>::splat(true), |m, x| m & x.simd_eq(*x))
                & !dx.iter().fold(Mask::<T>::splat(false), |m, x| {
                    m | x.simd_abs().simd_eq(splat(f64::INFINITY))
                });
            let far = v.norm().simd_gt(splat(self.max_travel));
            if ((!finite | far) & active).any() {
                return None;
            }
            let done = stalled & self.at_resolution(&dx) & active;
            its = splat::<T>((it + 1) as f64).select(done, its);
            active = active & !done;
            if active.none() {
                return Some((pose, its));
            }
            let moved = pose.moved(&v, &w);
            pose = BodyPose {
                rotation: moved.rotation.select(active, pose.rotation),
                translation: moved.translation.select(active, pose.translation),
            };
        }
        None
    }

    /// Every contact at `pose` in lanes into `out` ([`evaluate_lanes`]).
    fn evaluate_lanes_all<T: Lane>(
        &self,
        pose: &BodyPose<T>,
        inc: &LaneIncrement<T>,
        duration: f64,
        tangent: bool,
        out: &mut Vec<LaneContact<T>>,
    ) -> Option<()> {
        let motion = Motion::between(pose, inc.pose);
        out.clear();
        for i in 0..inc.states.len() {
            let g = self.coupling.geometry(i, pose);
            let du = motion.displacement(&g.point);
            let friction = LaneFriction { duration, ..inc.frictions[i] };
            let (state, root) = (&inc.states[i], inc.roots[i]);
            out.push(evaluate_lanes(self.coupling, i, g, du, state, root, &friction, tangent)?);
        }
        Some(())
    }

    /// [`Solver::residual`] of a seating in lanes ([`Solver::net_wrench`]).
    fn residual_lanes<T: Lane>(
        &self,
        pose: &BodyPose<T>,
        evals: &[LaneContact<T>],
        loads: &Loads,
    ) -> Vector6<T> {
        self.net_wrench(pose, loads.lambda, evals.iter().map(|e| (&e.force, &e.geometry.point)))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assembly::Coupling;
    use crate::contact::TangentialState;
    use crate::contact::hertz::load_root;
    use crate::lane::F64x4;
    use crate::scene::Scene;
    use crate::solve::SolverOptions;
    use crate::solve::contact_layer::ContactEval;
    use crate::solve::quasistatic::lanes_testing::{draw_frictions, lane_frictions, pose_lanes};
    use crate::solve::quasistatic::solver::{Step, predictor, twist_between};
    use rand::SeedableRng;

    /// The six increments of four seatings of scenes 01, 02 and 06
    /// (their contacts' mu drawn apart, so that lanes stick and slip
    /// differently and take different Newton counts): in lanes, each
    /// lane's pose, iteration count, contact forces and states bit for bit
    /// its f64 seating's, increment by increment.
    #[test]
    fn increments_in_lanes_are_each_seatings_own() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(9);
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
        let mut counts = Vec::new();
        for name in ["01_maxwell_vgroove_steel", "02_maxwell_pins_steel", "06_kelvin_steel"] {
            let scene = Scene::load(&dir.join(format!("{name}.toml"))).unwrap();
            let c = Coupling::new(&scene).unwrap();
            let preload = &scene.preload;
            let opts = SolverOptions { increments: 6, path_tolerance: None, ..Default::default() };
            let x1 = predictor(&c, preload);
            // One f64 solver per lane, with that lane's frictions.
            let frictions = draw_frictions(&mut rng, &c, 0.05..0.4);
            let solvers: Vec<_> = frictions
                .iter()
                .map(|f| Solver::new(&c, f, preload, opts, Program::Seat, x1))
                .collect();
            let mut poses = [c.touching_pose; 4];
            let mut previous = poses;
            let mut states: Vec<Vec<TangentialState>> = (0..4)
                .map(|_| {
                    (0..6)
                        .map(|i| TangentialState::new(c.geometry(i, &c.touching_pose).normal))
                        .collect()
                })
                .collect();
            let mut s = 0.0;
            for k in 1..=6 {
                let s_next = k as f64 / 6.0;
                let (lambda, extra) = solvers[0].loads_at(s_next);
                let loads =
                    Loads { lambda, extra, duration: (s_next - s) * preload.ramp_time, s: s_next };
                // The path's predictors: x_1 first, then each lane's secant.
                let starts: [BodyPose; 4] = std::array::from_fn(|l| {
                    let dx = match k {
                        1 => x1 * (s_next - s),
                        _ => twist_between(&previous[l], &poses[l]),
                    };
                    poses[l].moved(&dx.fixed_rows::<3>(0).into(), &dx.fixed_rows::<3>(3).into())
                });
                // f64, lane by lane.
                let alone = newton_alone(&solvers, &poses, &states, &starts, &loads, name);
                // Lanes.
                let pose = pose_lanes(&poses);
                let (lane_states, roots, fr) = lane_inputs(&states, &frictions);
                let inc = LaneIncrement {
                    pose: &pose,
                    states: &lane_states,
                    roots: &roots,
                    frictions: &fr,
                };
                let start = pose_lanes(&starts);
                let mut evals = Vec::new();
                let (p, its) =
                    solvers[0].newton_lanes(&inc, start, &loads, &mut evals).expect("lanes follow");
                for (l, (pa, ia, ea)) in alone.iter().enumerate() {
                    let what = format!("{name} increment {k} lane {l}");
                    assert_lane_is((&p, its, &evals), l, (pa, *ia, ea), &what);
                    counts.push(*ia);
                    // Commit lane l's increment for the next one.
                    previous[l] = poses[l];
                    poses[l] = *pa;
                    for (st, a) in states[l].iter_mut().zip(ea) {
                        st.clone_from(&a.tangential.state);
                    }
                }
                s = s_next;
            }
        }
        // The lanes took different Newton counts somewhere.
        assert!(counts.iter().any(|&n| n != counts[0]), "{counts:?}");
    }

    /// Each lane's f64 Newton: (pose, iterations, contacts).
    fn newton_alone(
        solvers: &[Solver],
        poses: &[BodyPose; 4],
        states: &[Vec<TangentialState>],
        starts: &[BodyPose; 4],
        loads: &Loads,
        name: &str,
    ) -> Vec<(BodyPose, usize, Vec<ContactEval>)> {
        (0..4)
            .map(|l| {
                let mut evals: Vec<ContactEval> = Vec::new();
                match solvers[l].newton(&poses[l], &states[l], starts[l], loads, &mut evals) {
                    Step::Converged(p, its) => (p, its, evals),
                    Step::Failed(r) => panic!("{name} lane {l} failed: {r}"),
                }
            })
            .collect()
    }

    /// The lanes' committed states, cube roots and frictions of four f64
    /// seatings' (`states[lane][contact]`, `frictions[lane][contact]`).
    #[allow(clippy::type_complexity)]
    fn lane_inputs(
        states: &[Vec<TangentialState>],
        frictions: &[Vec<crate::contact::Friction>],
    ) -> (Vec<LaneState<F64x4>>, Vec<F64x4>, Vec<LaneFriction<F64x4>>) {
        let lanes = |f: &dyn Fn(usize) -> f64| F64x4::from([0, 1, 2, 3].map(f));
        let lane_states =
            (0..6).map(|i| LaneState::from_states(&[0, 1, 2, 3].map(|l| &states[l][i]))).collect();
        let roots = (0..6).map(|i| lanes(&|l| load_root(states[l][i].normal_force))).collect();
        let fr = lane_frictions(frictions);
        (lane_states, roots, fr)
    }

    /// Lane `l` of a Newton over lanes (pose, iterations, contacts) has the
    /// bits of the f64 Newton's.
    fn assert_lane_is(
        (p, its, evals): (&BodyPose<F64x4>, F64x4, &[LaneContact<F64x4>]),
        l: usize,
        (pa, ia, ea): (&BodyPose, usize, &[ContactEval]),
        what: &str,
    ) {
        let bits = |a: f64, b: f64| a.to_bits() == b.to_bits();
        assert!(
            (0..4).all(|q| bits(p.rotation.coords[q].extract(l), pa.rotation.coords[q])),
            "{what}"
        );
        assert!((0..3).all(|q| bits(p.translation[q].extract(l), pa.translation[q])), "{what}");
        assert_eq!(its.extract(l), ia as f64, "{what}");
        for (i, (e, a)) in evals.iter().zip(ea).enumerate() {
            assert!((0..3).all(|q| bits(e.force[q].extract(l), a.force[q])), "{what} contact {i}");
            let st = e.state.lane(l);
            assert_eq!(st.sliding, a.tangential.state.sliding, "{what} contact {i}");
            assert!((0..3).all(|q| bits(st.force[q], a.tangential.state.force[q])), "{what}");
        }
    }
}
