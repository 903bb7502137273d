//! What a study varies ([`Variation`]) and how one design row u in [0, 1]^d
//! maps onto a [`Sample`]: friction per contact, preload, start pose and
//! manufacturing tolerances (the mapping is described in `study::runner`).

use nalgebra::{UnitQuaternion, Vector3};

use super::inputs::{Input, Tolerances};
use crate::assembly::Coupling;
use crate::scene::{Scene, VariationBounds};
use crate::solve::dynamic::StartPose;
use crate::solve::{Load, nominal_cycle, nominal_mu, thermal_tolerance};

/// Bounds of a randomly drawn start pose of the moving half (dynamic solver).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StartBounds {
    /// Half-widths of x and y, and the largest height z above the seat [m].
    pub offset: Vector3<f64>,
    /// Half-widths of the tilt about x, y, z [rad].
    pub tilt: Vector3<f64>,
}

/// What a study varies from sample to sample.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Variation {
    /// The six static friction coefficients (the paper's study).
    pub friction: bool,
    /// The preload point and direction, within the scene's `[variation]`
    /// bounds (re-seating scatter: it changes every cycle).
    pub preload: bool,
    /// Manufacturing tolerances of balls and surfaces within the scene's
    /// `[variation]` bounds (interchangeability: reported separately, each
    /// sample a perturbed coupling seated at nominal friction and preload).
    pub tolerances: bool,
    /// The start pose (needs the dynamic solver).
    pub start: Option<StartBounds>,
}

impl Default for Variation {
    fn default() -> Self {
        Variation { friction: true, preload: false, tolerances: false, start: None }
    }
}

/// Everything one design row sets.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// The load of this cycle's seating: static coefficients, preload, start.
    pub load: Load,
    /// Manufacturing errors (when tolerances vary).
    pub tolerances: Option<Tolerances>,
    /// Each design column in SI units (mu, m, rad), in row order.
    pub physical: Vec<f64>,
}

impl Variation {
    /// The design columns, in row order: friction, preload, start,
    /// tolerances. Preload and tolerance columns appear only for non-zero
    /// bounds of the scene's `[variation]` table.
    pub fn inputs(&self, scene: &Scene) -> Vec<Input> {
        let b = &scene.variation;
        let mut v = Vec::new();
        if self.friction {
            v.extend((0..scene.surfaces.len()).map(Input::Mu));
        }
        if self.preload {
            // Each force but the weight, force by force: its offsets, then its tilts.
            let forces = scene.preload.forces.iter().enumerate();
            for (f, _) in forces.filter(|(_, f)| f.varies()) {
                let offsets = (0..2).filter(|&a| b.preload_offset_m[a] > 0.0);
                v.extend(offsets.map(|a| Input::PreloadOffset(f, a)));
                if b.preload_tilt_rad > 0.0 {
                    v.extend([Input::PreloadTilt(f, 0), Input::PreloadTilt(f, 1)]);
                }
            }
        }
        if self.start.is_some() {
            v.extend((0..6).map(Input::Start));
        }
        if self.tolerances {
            let balls = scene.balls.len();
            let surfaces = scene.surfaces.len();
            if b.ball_diameter_m > 0.0 {
                v.extend((0..balls).map(Input::BallDiameter));
            }
            // (ball, axis) of every ball and every axis with a bound > 0.
            let per_ball = |bound: &[f64]| -> Vec<(usize, usize)> {
                let axes = 0..bound.len();
                let pairs = (0..balls).flat_map(|k| axes.clone().map(move |a| (k, a)));
                pairs.filter(|&(_, a)| bound[a] > 0.0).collect()
            };
            v.extend(
                per_ball(&b.ball_position_m).into_iter().map(|(k, a)| Input::BallPosition(k, a)),
            );
            if b.surface_normal_m > 0.0 {
                v.extend((0..surfaces).map(Input::SurfaceNormal));
            }
            if b.surface_tilt_rad > 0.0 {
                v.extend((0..surfaces).map(Input::SurfaceTilt));
            }
            v.extend(
                per_ball(&b.groove_position_m)
                    .into_iter()
                    .map(|(k, a)| Input::GroovePosition(k, a)),
            );
        }
        v
    }

    /// True if one pair of halves re-seats differently from sample to
    /// sample (friction, preload or start varied).
    pub fn reseating(&self) -> bool {
        self.friction || self.preload || self.start.is_some()
    }

    /// Everything one design row sets for the scene `scene` assembled as
    /// `coupling`. Each column u in [0, 1] maps to b (2u - 1), uniform in
    /// +-b; a contact's mu to the quantile of its distribution at u
    /// (`Scene::mu_at`: mu0 + spread (2u - 1) where uniform); the start
    /// pose as described in the module documentation of `study::runner`.
    pub fn sample(&self, scene: &Scene, coupling: &Coupling, row: &[f64]) -> Sample {
        let inputs = self.inputs(scene);
        let b = scene.variation;
        let mut preload = scene.preload.clone();
        let mut mu = nominal_mu(scene);
        let mut start_u = [0.5; 6];
        let mut offset = vec![Vector3::zeros(); preload.forces.len()];
        let mut tilt = offset.clone();
        let mut tol = self.tolerances.then(|| Tolerances::zero(scene));
        let mut physical = Vec::with_capacity(inputs.len());
        // The friction columns (the first, one per contact) made dependent
        // within each ball where `[friction] correlation` asks for it.
        let correlated;
        let row = if self.friction && scene.mu_correlation > 0.0 {
            let mut r = row.to_vec();
            let balls: Vec<usize> = scene.surfaces.iter().map(|s| s.ball).collect();
            crate::scene::mu::correlate(&mut r[..balls.len()], &balls, scene.mu_correlation);
            correlated = r;
            &correlated[..]
        } else {
            row
        };
        for (input, &u) in inputs.iter().zip(row) {
            let c = 2.0 * u - 1.0;
            let t = tol.as_mut();
            let value = match (*input, t) {
                (Input::Mu(k), _) => {
                    mu[k] = scene.mu_at(k, u);
                    mu[k]
                }
                (Input::PreloadOffset(k, a), _) => {
                    offset[k][a] = b.preload_offset_m[a] * c;
                    offset[k][a]
                }
                (Input::PreloadTilt(k, a), _) => {
                    tilt[k][a] = b.preload_tilt_rad * c;
                    tilt[k][a]
                }
                (Input::Start(j), _) => {
                    start_u[j] = u;
                    f64::NAN
                }
                (tolerance, Some(t)) => set_tolerance(t, tolerance, &b, c),
                (_, None) => f64::NAN,
            };
            physical.push(value);
        }
        let start = match self.start {
            Some(bounds) => start_pose(coupling, &bounds, &start_u),
            None => StartPose::touching(),
        };
        if self.start.is_some() {
            fill_start_values(&inputs, &start, &mut physical);
        }
        for ((f, offset), tilt) in preload.forces.iter_mut().zip(offset).zip(tilt) {
            f.point += offset;
            f.direction = UnitQuaternion::from_scaled_axis(tilt) * f.direction;
        }
        let (cycle, thermal_tolerance) = (nominal_cycle(scene), thermal_tolerance(scene));
        let load = Load { mu, preload, start, cycle, thermal_tolerance };
        Sample { load, tolerances: tol, physical }
    }
}

/// Sets tolerance `input` to b (2u - 1) = `b` * `c` (its bound times c) and
/// returns the value; NaN for an input that is not a tolerance.
fn set_tolerance(t: &mut Tolerances, input: Input, b: &VariationBounds, c: f64) -> f64 {
    let (slot, bound) = match input {
        Input::BallDiameter(k) => (&mut t.ball_diameter[k], b.ball_diameter_m),
        Input::BallPosition(k, a) => (&mut t.ball_position[k][a], b.ball_position_m[a]),
        Input::SurfaceNormal(i) => (&mut t.surface_normal[i], b.surface_normal_m),
        Input::SurfaceTilt(i) => (&mut t.surface_tilt[i], b.surface_tilt_rad),
        Input::GroovePosition(k, a) => (&mut t.groove_position[k][a], b.groove_position_m[a]),
        _ => return f64::NAN,
    };
    *slot = bound * c;
    *slot
}

/// The physical values of the start inputs: the offset and tilt of `start`.
fn fill_start_values(inputs: &[Input], start: &StartPose, physical: &mut [f64]) {
    let values: Vec<f64> = start.offset.iter().chain(&start.tilt).copied().collect();
    for (input, v) in inputs.iter().zip(physical.iter_mut()) {
        if let Input::Start(j) = input {
            *v = values[*j];
        }
    }
}

/// The start pose of design coordinates `u` (offset x, y, z, tilt x, y, z).
fn start_pose(coupling: &Coupling, b: &StartBounds, u: &[f64; 6]) -> StartPose {
    let c = u.map(|u| 2.0 * u - 1.0);
    let tilted = StartPose {
        offset: Vector3::new(b.offset.x * c[0], b.offset.y * c[1], 0.0),
        tilt: b.tilt.component_mul(&Vector3::new(c[3], c[4], c[5])),
    };
    let mut s = lifted_clear(coupling, tilted);
    s.offset.z += b.offset.z * u[2];
    s
}

/// Gap every ball keeps from its surfaces when a start pose is lifted clear [m].
pub const START_CLEARANCE: f64 = 1e-9;

/// `start` raised along z just enough that every ball clears its surfaces by
/// [`START_CLEARANCE`] (the height of first contact for that lateral offset
/// and tilt): a drawn start height then counts from there, so that every
/// drawn start lies above the seat.
pub fn lifted_clear(coupling: &Coupling, mut start: StartPose) -> StartPose {
    for _ in 0..50 {
        let pose = coupling.touching_pose.moved(&start.offset, &start.tilt);
        let (i, gap) = (0..coupling.contacts.len())
            .map(|i| (i, coupling.geometry(i, &pose).gap))
            .fold((0, f64::INFINITY), |a, b| if b.1 < a.1 { b } else { a });
        if gap >= START_CLEARANCE * (1.0 - 1e-6) {
            break;
        }
        let nz = coupling.geometry(i, &pose).normal.z.max(1e-3);
        start.offset.z += (START_CLEARANCE - gap) / nz;
    }
    start
}
