//! A seating's path over lanes: four seatings ramped through the same
//! schedule of increments at once, one per lane ([`crate::lane`]), by the
//! path follower of [`Solver::run`] (`super::path`) for a seating: each
//! lane's own predictor (x_1 first, then its secant), Newton in lanes
//! ([`Solver::newton_lanes`]), and each lane's commit of its contacts'
//! states and slip, so that each lane ends where its f64 seating ends,
//! bit for bit.
//!
//! The lanes share the schedule, so they follow the f64 path only while
//! no lane's f64 path would leave it: `None` (the set of four is seated one
//! by one) where some lane would halve an increment (a Newton failure, a
//! loaded contact changing between stick and slip), or would stop (a
//! contact that opens during the seating, a coupling that slides away).

use nalgebra::Vector6;
use simba::simd::{SimdBool, SimdValue};

use super::newton_lanes::LaneIncrement;
use super::solver::{Loads, Program, Solver, twist_between};
use crate::assembly::BodyPose;
use crate::contact::hertz::load_roots;
use crate::lane::{Lane, Mask, lift, splat};
use crate::solve::contact_lanes::{LaneContact, LaneFriction, LaneState};

/// The end of a seating's path in lanes (each field per lane).
pub(super) struct LaneEnd<T: Lane> {
    pub pose: BodyPose<T>,
    /// Accepted increments (the schedule's: every lane's).
    pub increments: usize,
    pub newton_iterations: T,
    /// Whether a contact slid in an accepted increment.
    pub slid: Mask<T>,
    /// Each contact's slip over the path [m] (`path::Buffers::slip_path`).
    pub slip_path: Vec<T>,
    /// The final contacts and their states.
    pub evals: Vec<LaneContact<T>>,
}

impl Solver<'_> {
    /// The seating's path from `start` with the contacts' `virgin` states
    /// and `frictions`, in lanes (module docs).
    pub(super) fn run_lanes<T: Lane>(
        &self,
        start: BodyPose<T>,
        virgin: &[LaneState<T>],
        frictions: &[LaneFriction<T>],
    ) -> Option<LaneEnd<T>> {
        if self.program != Program::Seat || self.expansion.is_some() {
            return None;
        }
        let nominal = 1.0 / self.opts.increments.max(1) as f64;
        let can_halve = nominal > nominal / f64::powi(2.0, self.opts.max_splits as i32) * 1.5;
        let graded = self.opts.path_tolerance.is_some();
        let mut states = virgin.to_vec();
        let mut end = LaneEnd {
            pose: start,
            increments: 0,
            newton_iterations: T::zero(),
            slid: Mask::<T>::splat(false),
            slip_path: vec![T::zero(); virgin.len()],
            evals: Vec::new(),
        };
        let (mut s, mut t) = (0.0, 0.0);
        let mut last_step: Option<(Vector6<T>, f64)> = None;
        let (mut trial, mut roots) = (Vec::new(), Vec::with_capacity(states.len()));
        while s < 1.0 {
            let t_next = if t + nominal > 1.0 - 1e-12 { 1.0 } else { t + nominal };
            let s_next = if graded { t_next * t_next } else { t_next };
            let (lambda, extra) = self.loads_at(s_next);
            let dx = match last_step {
                Some((dx, ds)) => dx * splat::<T>((s_next - s) / ds),
                None => lift::<T, 6, 1>(&self.x1) * splat::<T>(s_next - s),
            };
            let pose = &end.pose;
            let predictor =
                pose.moved(&dx.fixed_rows::<3>(0).into(), &dx.fixed_rows::<3>(3).into());
            let loads = Loads { lambda, extra, duration: (s_next - s) * self.ramp_time, s: s_next };
            roots.clear();
            roots.extend(states.iter().map(|st| load_roots(st.normal_force)));
            let inc = LaneIncrement { pose, states: &states, roots: &roots, frictions };
            let (new_pose, its) = self.newton_lanes(&inc, predictor, &loads, &mut trial)?;
            if (self.stick_slip_changed_lanes(&end.evals, &states, &trial) && can_halve)
                || self.stops_lanes(&start, &new_pose, &trial)
            {
                return None;
            }
            // The commit (`path::commit`), lane by lane in lanes.
            for ((st, e), path) in states.iter_mut().zip(&trial).zip(end.slip_path.iter_mut()) {
                *st = e.state;
                *path += st.slip_velocity * splat(loads.duration);
                end.slid = end.slid | st.sliding;
            }
            last_step = Some((twist_between(&end.pose, &new_pose), s_next - s));
            end.pose = new_pose;
            end.newton_iterations += its;
            end.increments += 1;
            std::mem::swap(&mut end.evals, &mut trial);
            (s, t) = (s_next, t_next);
        }
        Some(end)
    }

    /// Whether some lane's loaded contact changed between stick and slip
    /// (`path::stick_slip_changed`; `committed` empty before the first
    /// increment).
    fn stick_slip_changed_lanes<T: Lane>(
        &self,
        committed: &[LaneContact<T>],
        states: &[LaneState<T>],
        trial: &[LaneContact<T>],
    ) -> bool {
        committed.iter().zip(states).zip(trial).any(|((old, st), e)| {
            let (a, b) = (e.state.sliding, st.sliding);
            let differ = (a & !b) | (!a & b);
            (differ & old.normal_force.simd_gt(T::zero())).any()
        })
    }

    /// Whether some lane's seating would stop at this increment
    /// (`path::Solver::judge`: a contact open, the coupling slid away).
    fn stops_lanes<T: Lane>(
        &self,
        start: &BodyPose<T>,
        new_pose: &BodyPose<T>,
        trial: &[LaneContact<T>],
    ) -> bool {
        let opened = trial.iter().any(|e| e.normal_force.simd_le(T::zero()).any());
        let travel = (new_pose.translation - start.translation).norm();
        opened || travel.simd_gt(splat(self.max_travel)).any()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assembly::Coupling;
    use crate::contact::TangentialState;
    use crate::lane::F64x4;
    use crate::scene::Scene;
    use crate::solve::SolverOptions;
    use crate::solve::quasistatic::lanes_testing::{draw_frictions, lane_frictions, pose_lanes};
    use crate::solve::quasistatic::path::{Buffers, End};
    use crate::solve::quasistatic::solver::predictor;
    use rand::SeedableRng;

    /// Four seatings of each paper scene through a level of 3 and one of
    /// 6 increments (graded in t = sqrt(s), as the error-controlled
    /// seating takes them) in lanes, against the f64 path of each: pose,
    /// increments, Newton iterations, slip paths and the final contacts
    /// bit for bit; a set the lanes cannot follow is `None`, never a
    /// different answer.
    #[test]
    fn seatings_in_lanes_end_where_each_f64_seating_ends() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(10);
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
        let (mut followed, mut sets) = (0, 0);
        for k in 1..=7 {
            let name = std::fs::read_dir(&dir)
                .unwrap()
                .map(|e| e.unwrap().file_name().into_string().unwrap())
                .find(|n| n.starts_with(&format!("0{k}_")))
                .unwrap();
            let scene = Scene::load(&dir.join(&name)).unwrap();
            let c = Coupling::new(&scene).unwrap();
            let x1 = predictor(&c, &scene.preload);
            for n in [3, 6] {
                let opts = SolverOptions { increments: n, ..Default::default() };
                for _ in 0..3 {
                    sets += 1;
                    let frictions = draw_frictions(&mut rng, &c, 0.05..0.3);
                    let virgin: Vec<TangentialState> = (0..6)
                        .map(|i| TangentialState::new(c.geometry(i, &c.touching_pose).normal))
                        .collect();
                    let fr = lane_frictions(&frictions);
                    let v: Vec<LaneState<F64x4>> =
                        virgin.iter().map(|s| LaneState::from_states(&[s, s, s, s])).collect();
                    let solver =
                        Solver::new(&c, &frictions[0], &scene.preload, opts, Program::Seat, x1);
                    let start = pose_lanes(&[c.touching_pose; 4]);
                    let end = solver.run_lanes(start, &v, &fr);
                    for (l, f) in frictions.iter().enumerate() {
                        let alone = Solver::new(&c, f, &scene.preload, opts, Program::Seat, x1);
                        let mut bufs = Buffers { states: virgin.clone(), ..Default::default() };
                        let e = alone.run(c.touching_pose, &mut bufs);
                        let Some(end) = &end else {
                            continue;
                        };
                        let e = e.expect("a seating the lanes followed succeeds alone");
                        let what = format!("{name} level {n} lane {l}");
                        assert_lane_is(end, l, &e, &bufs, &what);
                    }
                    followed += usize::from(end.is_some());
                }
            }
        }
        // The paper scenes' seatings take the nominal increments: the lanes follow them.
        assert!(followed == sets, "{followed} of {sets}");
    }

    /// Lane `l` of a path in lanes ends where the f64 path `e` (its
    /// buffers `bufs`) ends, bit for bit.
    fn assert_lane_is(end: &LaneEnd<F64x4>, l: usize, e: &End, bufs: &Buffers, what: &str) {
        assert!(!e.halved, "{what}");
        let bits = |a: f64, b: f64| a.to_bits() == b.to_bits();
        let (p, q) = (&end.pose, &e.pose);
        assert!(
            (0..4).all(|i| bits(p.rotation.coords[i].extract(l), q.rotation.coords[i])),
            "{what}"
        );
        assert!((0..3).all(|i| bits(p.translation[i].extract(l), q.translation[i])), "{what}");
        assert_eq!(end.increments, e.increments, "{what}");
        assert_eq!(end.newton_iterations.extract(l), e.newton_iterations as f64, "{what}");
        assert_eq!(end.slid.extract(l), e.slid, "{what}");
        for (a, b) in end.slip_path.iter().zip(&bufs.slip_path) {
            assert!(bits(a.extract(l), *b), "{what}");
        }
        for (a, b) in end.evals.iter().zip(&bufs.evals) {
            assert!((0..3).all(|i| bits(a.force[i].extract(l), b.force[i])), "{what}");
        }
    }
}
