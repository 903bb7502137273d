//! Four seatings at once: the seat kernel [`super::seat_in`] over lanes
//! ([`crate::lane`]), one seating per lane, with the load-path error
//! control of `super::control` (levels of 3 and 6 graded increments, the
//! Richardson pose) or a fixed level. Each lane's [`SeatedPose`] is the
//! one `seat_in` gives for its load, bit for bit; a lane the lanes cannot
//! follow (its f64 path would halve or stop, it needs a finer level than
//! 6, its law has no form over lanes) is seated by `seat_in` itself.
//!
//! After it the workspace holds no seating's contacts (`Workspace::seating`
//! reports the last `seat_in` of it, if any lane needed one).

use nalgebra::Vector6;
use simba::simd::{SimdComplexField, SimdPartialOrd, SimdValue};

use super::path_lanes::LaneEnd;
use super::solver::{Program, Solver, twist_between};
use super::{SeatingSetup, Workspace, seat_in};
use crate::assembly::BodyPose;
use crate::contact::{Friction, friction};
use crate::lane::{F64x4, splat};
use crate::solve::contact_lanes::{LaneFriction, LaneState};
use crate::solve::{Load, SeatedPose, SeatingPath, SolveError, SolverOptions, frictions_into};

/// Whether a study seats its samples four at a time in lanes (`lanes`).
/// The results are the same bits either way ([`seat4_in`]); only the time
/// differs.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Lanes {
    /// In lanes where this build's lanes are the faster way (built for a
    /// CPU with AVX), else one seating at a time.
    #[default]
    Auto,
    /// Always in lanes.
    On,
    /// One seating at a time.
    Off,
}

/// True if this build runs [`F64x4`]'s operations on 256-bit registers
/// (built for a CPU with AVX, e.g. `-C target-cpu=native` on one): four
/// seatings in lanes then take half the time of four one at a time or
/// less (docs/benchmarks.md). Built for the x86-64 baseline (SSE2), each
/// lane operation is two 128-bit ones and the lanes are no faster.
pub const LANES_ARE_FAST: bool = cfg!(target_feature = "avx");

impl std::str::FromStr for Lanes {
    type Err = crate::param::ParamError;

    /// `auto`, `on`, `off`.
    fn from_str(s: &str) -> Result<Self, Self::Err> {
        use crate::param::{Param, ParamError};
        <Lanes as clap::ValueEnum>::from_str(s, false).map_err(|_| {
            let msg = format!("{}: unknown, need auto, on or off", Param::Lanes.with(s));
            ParamError::new(Param::Lanes, msg)
        })
    }
}

impl Lanes {
    /// Whether the seatings go in lanes.
    pub fn used(self) -> bool {
        match self {
            Lanes::Auto => LANES_ARE_FAST,
            Lanes::On => true,
            Lanes::Off => false,
        }
    }
}

/// Seat `setup`'s coupling under each of four `loads` (module docs).
pub fn seat4_in(
    setup: &SeatingSetup,
    loads: [&Load; 4],
    opts: &SolverOptions,
    ws: &mut Workspace,
) -> [Result<SeatedPose, SolveError>; 4] {
    let lanes = seat_in_lanes(setup, loads, opts);
    std::array::from_fn(|l| match lanes[l] {
        Some(seated) => Ok(seated),
        None => seat_in(setup, loads[l], opts, ws),
    })
}

/// The lanes' seatings; `None` for a lane they cannot follow.
fn seat_in_lanes(
    setup: &SeatingSetup,
    loads: [&Load; 4],
    opts: &SolverOptions,
) -> [Option<SeatedPose>; 4] {
    let none = [None; 4];
    let c = setup.coupling;
    if loads.iter().any(|l| l.preload != setup.preload) {
        return none;
    }
    let Some((frictions, lane_frictions)) = frictions_of(setup.coupling, loads) else {
        return none;
    };
    let virgin: Vec<LaneState<F64x4>> =
        setup.virgin.iter().map(|s| LaneState::from_states(&[s, s, s, s])).collect();
    let start = BodyPose::from_lanes(&[c.touching_pose; 4]);
    let level = |n: usize| {
        let opts = SolverOptions { increments: n, ..*opts };
        let solver = Solver::new(c, &frictions[0], &setup.preload, opts, Program::Seat, setup.x1);
        solver.run_lanes(start, &virgin, &lane_frictions)
    };
    let cv = |end: &LaneEnd<F64x4>, l: usize| {
        let path: Vec<f64> = end.slip_path.iter().map(|x| x.extract(l)).collect();
        friction::seating_cv(&frictions[l], &path, setup.preload.ramp_time)
    };
    let Some(tolerance) = opts.path_tolerance else {
        let Some(end) = level(opts.increments) else { return none };
        return std::array::from_fn(|l| {
            Some(SeatedPose {
                pose: end.pose.lane(l),
                increments: end.increments,
                newton_iterations: end.newton_iterations.extract(l) as usize,
                path: SeatingPath::Uniform,
                decay_cv: cv(&end, l),
                path_error: None,
                slid: end.slid.extract(l),
            })
        });
    };
    let (Some(coarse), Some(fine)) = (level(3), level(6)) else { return none };
    // The error of `control::seat_controlled`, per lane.
    let length = c.length_scale();
    let size = |t: &Vector6<F64x4>| {
        let v = t.fixed_rows::<3>(0).norm();
        let w = t.fixed_rows::<3>(3).norm();
        v.simd_hypot(splat::<F64x4>(length) * w)
    };
    let d = twist_between(&coarse.pose, &fine.pose);
    let motion = size(&twist_between(&start, &fine.pose));
    let change = size(&d);
    let floor = fine.increments as f64 * opts.tolerance;
    let positive = motion.simd_gt(splat::<F64x4>(0.0));
    let error = (change / motion).select(positive, splat::<F64x4>(0.0)) + splat(floor);
    let pose = fine.pose.moved(&d.fixed_rows::<3>(0).into(), &d.fixed_rows::<3>(3).into());
    std::array::from_fn(|l| {
        let e = error.extract(l);
        (e <= tolerance).then(|| SeatedPose {
            pose: pose.lane(l),
            increments: coarse.increments + fine.increments,
            newton_iterations: (coarse.newton_iterations + fine.newton_iterations).extract(l)
                as usize,
            path: SeatingPath::Uniform,
            path_error: Some(e),
            decay_cv: cv(&fine, l),
            slid: fine.slid.extract(l),
        })
    })
}

/// Each of four seatings' frictions, in contact order.
type FourFrictions = [Vec<Friction>; 4];

/// Each load's frictions, and per contact over lanes; `None` where one
/// is not valid (that seating's error is `seat_in`'s).
fn frictions_of(
    c: &crate::assembly::Coupling,
    loads: [&Load; 4],
) -> Option<(FourFrictions, Vec<LaneFriction<F64x4>>)> {
    let mut frictions: [Vec<Friction>; 4] = Default::default();
    for (f, load) in frictions.iter_mut().zip(loads) {
        frictions_into(c, &load.mu, f).ok()?;
    }
    let lanes = (0..c.contacts.len())
        .map(|i| LaneFriction::from_frictions(&[0, 1, 2, 3].map(|l| &frictions[l][i])))
        .collect();
    Some((frictions, lanes))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::assembly::Coupling;
    use crate::scene::Scene;
    use rand::{Rng, SeedableRng};

    /// The paper scenes' seatings are followed in lanes (no lane is left
    /// to `seat_in`), with and without the error control, and each lane
    /// is `seat_in`'s seating (tests/it/lanes.rs compares `seat4_in`).
    #[test]
    fn the_lanes_follow_the_paper_seatings() {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(11);
        let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
        for name in ["01_maxwell_vgroove_steel", "02_maxwell_pins_steel", "06_kelvin_steel"] {
            let scene = Scene::load(&dir.join(format!("{name}.toml"))).unwrap();
            let c = Coupling::new(&scene).unwrap();
            let nominal = Load::nominal(&scene);
            let setup = SeatingSetup::new(&c, &nominal.preload);
            for opts in [
                SolverOptions::default(),
                SolverOptions { path_tolerance: None, ..SolverOptions::default() },
            ] {
                let loads: Vec<Load> = (0..4)
                    .map(|_| {
                        let mu: Vec<f64> = (0..6).map(|_| rng.random_range(0.05..0.3)).collect();
                        nominal.with_mu(&mu)
                    })
                    .collect();
                let lanes =
                    seat_in_lanes(&setup, [&loads[0], &loads[1], &loads[2], &loads[3]], &opts);
                for (l, got) in lanes.iter().enumerate() {
                    let got = got.unwrap_or_else(|| panic!("{name} lane {l} left to seat_in"));
                    let alone = seat_in(&setup, &loads[l], &opts, &mut Workspace::new()).unwrap();
                    assert_eq!(got, alone, "{name} lane {l}");
                }
            }
        }
    }
}
