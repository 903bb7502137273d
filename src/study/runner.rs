//! Running a reproducibility study of one scene: draw the design, seat the
//! coupling once per sample (rayon across samples), and record the pose of
//! every evaluation point relative to the nominal-mu seating.
//!
//! Inputs: the row u_i of the design on [0, 1]^d maps to the varied
//! quantities in order: with friction varied, mu_s,k = mu0 + spread
//! (2 u_ik - 1) for contact k (MODEL.md §4, rectangular distribution); with
//! the start varied (dynamic solver), an offset x, y in +-b_x, +-b_y, z in
//! [0, b_z] above the seat and a tilt in +-b_phi per axis. A row depends only
//! on (sampler, n, seed, i), so shards of the sample range computed anywhere
//! merge into exactly one run.
//!
//! With `preload` varied, the preload point moves by (dx, dy) in +-b per
//! axis and its direction turns by the rotation vector (t_x, t_y, 0), each
//! component in +-b_tilt (so the angle from the nominal direction is at
//! most sqrt(2) b_tilt). With `tolerances` varied, each row also draws
//! manufacturing errors ([`Tolerances`]); the perturbed coupling is seated
//! at nominal friction and preload and reported separately
//! (interchangeability of coupling halves, outputs `interchange/...`).

use rayon::prelude::*;
use thiserror::Error;

use super::StudyError;
use super::stats::SampleRecord;
use super::{DesignSpec, Sampler, Shard};
use crate::assembly::{AssemblyError, Coupling};
use crate::scene::{Preload, Scene, SurfaceGeometry};
use nalgebra::{UnitQuaternion, Vector3};

use crate::solve::dynamic::StartPose;
use crate::solve::{Method, PointPose, SolveError, nominal_mu};

/// Output components per evaluation point (relative to the nominal seating,
/// SI): translation of the point and rotation vector, phi_z being the
/// clocking about z (evaluated since output schema 2; MODEL.md §2's "not
/// evaluated" is superseded).
pub const COMPONENTS: [&str; 6] = ["x_m", "y_m", "z_m", "phi_x_rad", "phi_y_rad", "phi_z_rad"];

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
        Variation {
            friction: true,
            preload: false,
            tolerances: false,
            start: None,
        }
    }
}

/// One varied quantity: a column of the design.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Input {
    /// Static coefficient of contact k (0-based).
    Mu(usize),
    /// Preload point offset along x (0) or y (1).
    PreloadOffset(usize),
    /// Preload direction tilt about x (0) or y (1).
    PreloadTilt(usize),
    /// Start pose: offset x, y, z (0-2), tilt x, y, z (3-5).
    Start(usize),
    /// Diameter error of ball b.
    BallDiameter(usize),
    /// Centre error of ball b along axis a.
    BallPosition(usize, usize),
    /// Shift of surface s along its nominal contact normal.
    SurfaceNormal(usize),
    /// Rotation of surface s about its horizontal axis through the contact point.
    SurfaceTilt(usize),
    /// Shift of the groove of ball b along x (0) or y (1).
    GroovePosition(usize, usize),
}

impl Input {
    /// True for the manufacturing tolerances (interchangeability inputs).
    pub fn is_tolerance(&self) -> bool {
        matches!(
            self,
            Input::BallDiameter(_)
                | Input::BallPosition(..)
                | Input::SurfaceNormal(_)
                | Input::SurfaceTilt(_)
                | Input::GroovePosition(..)
        )
    }

    /// The column name (SI unit as suffix).
    pub fn name(&self) -> String {
        const XYZ: [&str; 3] = ["x", "y", "z"];
        match *self {
            Input::Mu(k) => format!("mu_{}", k + 1),
            Input::PreloadOffset(a) => format!("preload_{}_m", XYZ[a]),
            Input::PreloadTilt(a) => format!("preload_tilt_{}_rad", XYZ[a]),
            Input::Start(j) => [
                "offset_x_m",
                "offset_y_m",
                "offset_z_m",
                "tilt_x_rad",
                "tilt_y_rad",
                "tilt_z_rad",
            ][j]
                .to_string(),
            Input::BallDiameter(b) => format!("ball_{}_diameter_m", b + 1),
            Input::BallPosition(b, a) => format!("ball_{}_{}_m", b + 1, XYZ[a]),
            Input::SurfaceNormal(s) => format!("surface_{}_normal_m", s + 1),
            Input::SurfaceTilt(s) => format!("surface_{}_tilt_rad", s + 1),
            Input::GroovePosition(b, a) => format!("groove_{}_{}_m", b + 1, XYZ[a]),
        }
    }
}

/// Manufacturing errors of one sample: each value drawn within the
/// scene's `[variation]` bounds.
#[derive(Debug, Clone, PartialEq)]
pub struct Tolerances {
    /// Diameter error per ball [m].
    pub ball_diameter: Vec<f64>,
    /// Centre error per ball [m].
    pub ball_position: Vec<Vector3<f64>>,
    /// Shift of each surface along its nominal contact normal [m].
    pub surface_normal: Vec<f64>,
    /// Rotation of each surface about its tilt axis [rad].
    pub surface_tilt: Vec<f64>,
    /// Shift of each ball's groove, x and y (z = 0) [m].
    pub groove_position: Vec<Vector3<f64>>,
}

impl Tolerances {
    /// No error anywhere.
    pub fn zero(coupling: &Coupling) -> Self {
        let (b, s) = (coupling.balls.len(), coupling.contacts.len());
        Tolerances {
            ball_diameter: vec![0.0; b],
            ball_position: vec![Vector3::zeros(); b],
            surface_normal: vec![0.0; s],
            surface_tilt: vec![0.0; s],
            groove_position: vec![Vector3::zeros(); b],
        }
    }

    /// The scene with these errors applied (explicit geometry). Surface i
    /// with nominal contact point p_i and normal n_i (at the touching
    /// pose) is rotated by its tilt about the axis t_i = n_i x e_z
    /// (normalised; e_x for a normal along z) through p_i — a positive
    /// tilt turns the normal towards +z, i.e. flattens a flank, so equal
    /// tilts of both flanks of a V widen its opening angle by twice the
    /// tilt — then shifted by its normal error along n_i and by its
    /// groove's x, y error. Ball k's centre moves by its position error and
    /// its radius grows by half its diameter error.
    pub fn apply(&self, coupling: &Coupling) -> Scene {
        let mut scene = coupling.scene.clone();
        for (k, b) in scene.balls.iter_mut().enumerate() {
            b.centre += self.ball_position[k];
            b.radius += 0.5 * self.ball_diameter[k];
        }
        for (i, s) in scene.surfaces.iter_mut().enumerate() {
            let g = coupling.geometry(i, &coupling.touching_pose);
            let n = g.normal;
            let axis = n.cross(&Vector3::z());
            let axis = if axis.norm() < 1e-9 {
                Vector3::x()
            } else {
                axis.normalize()
            };
            let r = UnitQuaternion::from_scaled_axis(axis * self.surface_tilt[i]);
            let shift = n * self.surface_normal[i] + self.groove_position[s.ball];
            let moved = |x: Vector3<f64>| r * (x - g.point) + g.point + shift;
            s.geometry = match s.geometry {
                SurfaceGeometry::Plane { point, normal } => SurfaceGeometry::Plane {
                    point: moved(point),
                    normal: r * normal,
                },
                SurfaceGeometry::Cylinder {
                    axis_point,
                    direction,
                    radius,
                } => SurfaceGeometry::Cylinder {
                    axis_point: moved(axis_point),
                    direction: r * direction,
                    radius,
                },
                SurfaceGeometry::Sphere { centre, radius } => SurfaceGeometry::Sphere {
                    centre: moved(centre),
                    radius,
                },
            };
        }
        scene
    }

    /// A bound on how far the perturbed balls may miss their surfaces at
    /// the scene's pose (for [`Coupling::new_perturbed`]).
    pub fn max_gap(&self, coupling: &Coupling) -> f64 {
        let amax = |v: &[f64]| v.iter().fold(0.0_f64, |a, x| a.max(x.abs()));
        let vmax = |v: &[Vector3<f64>]| v.iter().fold(0.0_f64, |a, x| a.max(x.norm()));
        let r = coupling.balls.iter().fold(0.0_f64, |a, b| a.max(b.radius));
        1e-6 + 2.0
            * (0.5 * amax(&self.ball_diameter)
                + vmax(&self.ball_position)
                + amax(&self.surface_normal)
                + vmax(&self.groove_position)
                + r * amax(&self.surface_tilt))
    }

    /// The perturbed coupling (touching pose solved for the perturbed geometry).
    pub fn coupling(&self, coupling: &Coupling) -> Result<Coupling, AssemblyError> {
        Coupling::new_perturbed(&self.apply(coupling), self.max_gap(coupling))
    }
}

/// Everything one design row sets.
#[derive(Debug, Clone, PartialEq)]
pub struct Sample {
    /// Static coefficients, one per contact.
    pub mu: Vec<f64>,
    /// Start pose (dynamic solver).
    pub start: StartPose,
    /// Preload of this cycle.
    pub preload: Preload,
    /// Manufacturing errors (when tolerances vary).
    pub tolerances: Option<Tolerances>,
    /// Each design column in SI units (mu, m, rad), in row order.
    pub physical: Vec<f64>,
}

impl Variation {
    /// The design columns, in row order: friction, preload, start,
    /// tolerances. Preload and tolerance columns appear only for non-zero
    /// bounds of the scene's `[variation]` table.
    pub fn inputs(&self, coupling: &Coupling) -> Vec<Input> {
        let b = &coupling.scene.variation;
        let mut v = Vec::new();
        if self.friction {
            v.extend((0..coupling.contacts.len()).map(Input::Mu));
        }
        if self.preload {
            for a in 0..2 {
                if b.preload_offset_m[a] > 0.0 {
                    v.push(Input::PreloadOffset(a));
                }
            }
            if b.preload_tilt_rad > 0.0 {
                v.extend([Input::PreloadTilt(0), Input::PreloadTilt(1)]);
            }
        }
        if self.start.is_some() {
            v.extend((0..6).map(Input::Start));
        }
        if self.tolerances {
            let balls = coupling.balls.len();
            let surfaces = coupling.contacts.len();
            if b.ball_diameter_m > 0.0 {
                v.extend((0..balls).map(Input::BallDiameter));
            }
            for k in 0..balls {
                for a in 0..3 {
                    if b.ball_position_m[a] > 0.0 {
                        v.push(Input::BallPosition(k, a));
                    }
                }
            }
            if b.surface_normal_m > 0.0 {
                v.extend((0..surfaces).map(Input::SurfaceNormal));
            }
            if b.surface_tilt_rad > 0.0 {
                v.extend((0..surfaces).map(Input::SurfaceTilt));
            }
            for k in 0..balls {
                for a in 0..2 {
                    if b.groove_position_m[a] > 0.0 {
                        v.push(Input::GroovePosition(k, a));
                    }
                }
            }
        }
        v
    }

    /// Names of the design dimensions, in row order.
    pub fn input_names(&self, coupling: &Coupling) -> Vec<String> {
        self.inputs(coupling).iter().map(Input::name).collect()
    }

    /// True if one pair of halves re-seats differently from sample to
    /// sample (friction, preload or start varied).
    pub fn reseating(&self) -> bool {
        self.friction || self.preload || self.start.is_some()
    }

    /// Static coefficients and start pose of one design row (of
    /// `input_names().len()` coordinates).
    pub fn map(&self, coupling: &Coupling, row: &[f64]) -> (Vec<f64>, StartPose) {
        let s = self.sample(coupling, row);
        (s.mu, s.start)
    }

    /// Everything one design row sets. Each column u in [0, 1] maps to
    /// b (2u - 1), uniform in +-b (mu: mu0 + spread (2u - 1)); the start
    /// pose as described in the module documentation.
    pub fn sample(&self, coupling: &Coupling, row: &[f64]) -> Sample {
        let inputs = self.inputs(coupling);
        let b = coupling.scene.variation;
        let f = &coupling.scene.friction;
        let nominal = coupling.scene.preload;
        let mut mu = nominal_mu(coupling);
        let mut start_u = [0.5; 6];
        let mut offset = Vector3::zeros();
        let mut tilt = Vector3::zeros();
        let mut tol = self.tolerances.then(|| Tolerances::zero(coupling));
        let mut physical = Vec::with_capacity(inputs.len());
        for (input, &u) in inputs.iter().zip(row) {
            let c = 2.0 * u - 1.0;
            let t = tol.as_mut();
            let value = match (*input, t) {
                (Input::Mu(k), _) => {
                    mu[k] = f.mu_static + f.spread * c;
                    mu[k]
                }
                (Input::PreloadOffset(a), _) => {
                    offset[a] = b.preload_offset_m[a] * c;
                    offset[a]
                }
                (Input::PreloadTilt(a), _) => {
                    tilt[a] = b.preload_tilt_rad * c;
                    tilt[a]
                }
                (Input::Start(j), _) => {
                    start_u[j] = u;
                    f64::NAN
                }
                (Input::BallDiameter(k), Some(t)) => {
                    t.ball_diameter[k] = b.ball_diameter_m * c;
                    t.ball_diameter[k]
                }
                (Input::BallPosition(k, a), Some(t)) => {
                    t.ball_position[k][a] = b.ball_position_m[a] * c;
                    t.ball_position[k][a]
                }
                (Input::SurfaceNormal(i), Some(t)) => {
                    t.surface_normal[i] = b.surface_normal_m * c;
                    t.surface_normal[i]
                }
                (Input::SurfaceTilt(i), Some(t)) => {
                    t.surface_tilt[i] = b.surface_tilt_rad * c;
                    t.surface_tilt[i]
                }
                (Input::GroovePosition(k, a), Some(t)) => {
                    t.groove_position[k][a] = b.groove_position_m[a] * c;
                    t.groove_position[k][a]
                }
                (_, None) => f64::NAN,
            };
            physical.push(value);
        }
        let start = match self.start {
            Some(bounds) => start_pose(coupling, &bounds, &start_u),
            None => StartPose::touching(),
        };
        if self.start.is_some() {
            let values = [
                start.offset.x,
                start.offset.y,
                start.offset.z,
                start.tilt.x,
                start.tilt.y,
                start.tilt.z,
            ];
            for (input, v) in inputs.iter().zip(physical.iter_mut()) {
                if let Input::Start(j) = input {
                    *v = values[*j];
                }
            }
        }
        let preload = Preload {
            force: nominal.force,
            point: nominal.point + offset,
            direction: UnitQuaternion::from_scaled_axis(tilt) * nominal.direction,
        };
        Sample {
            mu,
            start,
            preload,
            tolerances: tol,
            physical,
        }
    }
}

/// The start pose of design coordinates `u` (offset x, y, z, tilt x, y, z).
fn start_pose(coupling: &Coupling, b: &StartBounds, u: &[f64; 6]) -> StartPose {
    let tilted = StartPose {
        offset: Vector3::new(
            b.offset.x * (2.0 * u[0] - 1.0),
            b.offset.y * (2.0 * u[1] - 1.0),
            0.0,
        ),
        tilt: Vector3::new(
            b.tilt.x * (2.0 * u[3] - 1.0),
            b.tilt.y * (2.0 * u[4] - 1.0),
            b.tilt.z * (2.0 * u[5] - 1.0),
        ),
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

/// How to run a study; `None` takes the scene's study settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StudyOptions {
    pub sampler: Option<Sampler>,
    pub samples: Option<usize>,
    pub seed: Option<u64>,
    pub shard: Shard,
    pub method: Method,
    pub variation: Variation,
    /// Also compute the sensitivity (SRC) tables of the report.
    pub sensitivity: bool,
}

impl Default for StudyOptions {
    fn default() -> Self {
        StudyOptions {
            sampler: None,
            samples: None,
            seed: None,
            shard: Shard::whole(),
            method: Method::default(),
            variation: Variation::default(),
            sensitivity: false,
        }
    }
}

/// A study could not be run.
#[derive(Debug, Error)]
pub enum RunError {
    #[error("{file}: {source}")]
    Design {
        file: String,
        #[source]
        source: StudyError,
    },
    #[error("{file}: {reason}")]
    Options { file: String, reason: String },
    #[error(
        "{file}: sample {index}: the coupling perturbed by the drawn tolerances does not \
         assemble: {source}"
    )]
    Perturbed {
        file: String,
        index: usize,
        #[source]
        source: AssemblyError,
    },
    #[error(
        "{file}: the nominal seating (the reference of every sample; mu_s = {mu:?}, touching start) failed: {source}"
    )]
    Nominal {
        file: String,
        mu: Vec<f64>,
        #[source]
        source: SolveError,
    },
    #[error("{file}: sample {index} (mu_s = {mu:?}): {source}")]
    Seating {
        file: String,
        index: usize,
        mu: Vec<f64>,
        #[source]
        source: SolveError,
    },
}

/// The samples of one scene that this run (shard) computed.
#[derive(Debug, Clone, PartialEq)]
pub struct VariantRun {
    pub design: DesignSpec,
    pub shard: Shard,
    /// `point/component` for every evaluation point and component.
    pub output_names: Vec<String>,
    pub records: Vec<SampleRecord>,
}

/// The design a scene's study uses under `opts`.
pub fn design_for(coupling: &Coupling, opts: &StudyOptions) -> Result<DesignSpec, StudyError> {
    let st = &coupling.scene.study;
    let sampler = opts.sampler.unwrap_or(st.sampler);
    let n = match sampler {
        Sampler::Corners => None,
        _ => Some(opts.samples.unwrap_or(st.samples)),
    };
    let dims = opts.variation.inputs(coupling).len();
    DesignSpec::new(sampler, dims, n, opts.seed.unwrap_or(st.seed))
}

/// Static coefficients of one design row.
pub fn mu_of_row(coupling: &Coupling, row: &[f64]) -> Vec<f64> {
    let f = &coupling.scene.friction;
    row.iter()
        .map(|u| f.mu_static + f.spread * (2.0 * u - 1.0))
        .collect()
}

/// Prefix of the interchangeability outputs (`interchange/<point>/<dof>`).
pub const INTERCHANGE_PREFIX: &str = "interchange/";

/// Names of the re-seating outputs (`<point>/<dof>`).
pub fn output_names(coupling: &Coupling) -> Vec<String> {
    coupling
        .scene
        .evaluation_points
        .iter()
        .flat_map(|p| COMPONENTS.iter().map(move |c| format!("{}/{c}", p.name)))
        .collect()
}

/// Names of all recorded outputs under `variation`: the re-seating outputs
/// (if friction, preload or start vary), then the interchangeability
/// outputs (if tolerances vary).
pub fn recorded_output_names(coupling: &Coupling, variation: &Variation) -> Vec<String> {
    let mut v = Vec::new();
    if variation.reseating() {
        v.extend(output_names(coupling));
    }
    if variation.tolerances {
        v.extend(
            output_names(coupling)
                .into_iter()
                .map(|n| format!("{INTERCHANGE_PREFIX}{n}")),
        );
    }
    v
}

/// Check that `opts` can run on this scene: something varies, a varied
/// start has the dynamic solver, and the scene gives bounds for a varied
/// preload or tolerances.
pub fn check_options(coupling: &Coupling, opts: &StudyOptions) -> Result<(), RunError> {
    let var = opts.variation;
    let err = |reason: &str| {
        Err(RunError::Options {
            file: coupling.scene.file.clone(),
            reason: reason.to_string(),
        })
    };
    if !var.reseating() && !var.tolerances {
        return err(
            "the study varies nothing: vary friction, preload, tolerances or the start pose",
        );
    }
    if var.start.is_some() && !matches!(opts.method, Method::Dynamic(_)) {
        return err("a varied start pose needs the dynamic solver (--solver dynamic)");
    }
    let bounds = coupling.scene.variation;
    if var.preload && !bounds.preload_varies() {
        return err(
            "--vary preload: the scene's [variation] table gives no preload bound \
             (preload_offset, preload_tilt)",
        );
    }
    if var.tolerances && !bounds.tolerances_vary() {
        return err(
            "--vary tolerances: the scene's [variation] table gives no tolerance \
             (ball_diameter, ball_position, surface_normal, surface_tilt, groove_position)",
        );
    }
    Ok(())
}

/// Run this shard's samples of one scene. `tick` is called once per finished sample.
///
/// Per sample: with friction, preload or start varied, the nominal
/// coupling is seated with the sample's friction, preload and start, and
/// its pose recorded relative to the nominal seating (re-seating scatter);
/// with tolerances varied, the sample's perturbed coupling is also seated
/// at nominal friction and preload, and its pose recorded relative to the
/// same nominal seating (interchangeability, `interchange/...` outputs).
pub fn run_variant(
    coupling: &Coupling,
    opts: &StudyOptions,
    tick: &(dyn Fn() + Sync),
) -> Result<VariantRun, RunError> {
    let file = coupling.scene.file.clone();
    let design_err = |source| RunError::Design {
        file: file.clone(),
        source,
    };
    check_options(coupling, opts)?;
    let design = design_for(coupling, opts).map_err(design_err)?;
    let range = opts.shard.range(design.n).map_err(design_err)?;
    let rows = design.range(range.clone()).map_err(design_err)?;
    let records = evaluate_rows(coupling, opts, range.zip(rows).collect(), tick)?;
    Ok(VariantRun {
        design,
        shard: opts.shard,
        output_names: recorded_output_names(coupling, &opts.variation),
        records,
    })
}

/// True if friction moves the seated pose: the coupling seated from the
/// touching pose with every mu_s at mu0 - spread and at mu0 + spread (and
/// mu0 +- 10 % for a scene without spread) ends in different poses. False
/// means every contact stuck from the first load increment: the coupling
/// cannot seat, and a friction study gives zero scatter.
pub fn friction_moves_pose(coupling: &Coupling, method: &Method) -> Result<bool, RunError> {
    let f = &coupling.scene.friction;
    let d = if f.spread > 0.0 {
        f.spread
    } else {
        0.1 * f.mu_static
    };
    let n = coupling.contacts.len();
    let mut poses = Vec::new();
    for mu in [(f.mu_static - d).max(0.0), f.mu_static + d] {
        let m = vec![mu; n];
        let s = method
            .seat(coupling, &m, &StartPose::touching())
            .map_err(|source| RunError::Nominal {
                file: coupling.scene.file.clone(),
                mu: m,
                source,
            })?;
        poses.push(s.pose);
    }
    let p = &coupling.scene.evaluation_points[0].position;
    Ok(PointPose::between(&poses[0], &poses[1], p)
        .components()
        .iter()
        .any(|c| *c != 0.0))
}

/// Run this shard's samples in chunks of `chunk` rows (rayon within a
/// chunk), handing each chunk's records to `sink` in sample-index order:
/// bounded memory for any sample count, and results that do not depend on
/// the number of threads. Returns the design.
pub fn run_chunked(
    coupling: &Coupling,
    opts: &StudyOptions,
    chunk: usize,
    tick: &(dyn Fn() + Sync),
    sink: &mut dyn FnMut(Vec<SampleRecord>) -> Result<(), RunError>,
) -> Result<DesignSpec, RunError> {
    let file = coupling.scene.file.clone();
    let design_err = |source| RunError::Design {
        file: file.clone(),
        source,
    };
    check_options(coupling, opts)?;
    let design = design_for(coupling, opts).map_err(design_err)?;
    let range = opts.shard.range(design.n).map_err(design_err)?;
    let mut start = range.start;
    while start < range.end {
        let end = (start + chunk.max(1)).min(range.end);
        let rows = design.range(start..end).map_err(design_err)?;
        sink(evaluate_rows(
            coupling,
            opts,
            (start..end).zip(rows).collect(),
            tick,
        )?)?;
        start = end;
    }
    Ok(design)
}

/// Seat the coupling once per `(index, design row)` (rayon across rows)
/// and record the outputs named by [`recorded_output_names`], relative to
/// the nominal seating (nominal friction and preload, touching start, same
/// solver). Any design over `opts.variation`'s inputs may be passed (a
/// study's design, or e.g. the matrices of a variance-based sensitivity
/// analysis). `tick` is called once per finished row.
pub fn evaluate_rows(
    coupling: &Coupling,
    opts: &StudyOptions,
    rows: Vec<(usize, Vec<f64>)>,
    tick: &(dyn Fn() + Sync),
) -> Result<Vec<SampleRecord>, RunError> {
    let file = coupling.scene.file.clone();
    let var = opts.variation;
    let seat_err = |index: usize, mu: &[f64], source| RunError::Seating {
        file: file.clone(),
        index,
        mu: mu.to_vec(),
        source,
    };
    let nominal_mu = nominal_mu(coupling);
    // The reference: nominal friction, from the touching pose, same solver.
    let nominal = opts
        .method
        .seat(coupling, &nominal_mu, &StartPose::touching())
        .map_err(|source| RunError::Nominal {
            file: file.clone(),
            mu: nominal_mu.clone(),
            source,
        })?;
    let points: Vec<_> = coupling
        .scene
        .evaluation_points
        .iter()
        .map(|p| p.position)
        .collect();
    rows.into_par_iter()
        .map(|(index, row)| {
            let sample = var.sample(coupling, &row);
            let mut outputs: Vec<f64> = Vec::new();
            if var.reseating() {
                let loaded;
                let c = if var.preload {
                    let mut c = coupling.clone();
                    c.scene.preload = sample.preload;
                    loaded = c;
                    &loaded
                } else {
                    coupling
                };
                let s = opts
                    .method
                    .seat(c, &sample.mu, &sample.start)
                    .map_err(|e| seat_err(index, &sample.mu, e))?;
                outputs.extend(
                    points
                        .iter()
                        .flat_map(|p| PointPose::between(&nominal.pose, &s.pose, p).components()),
                );
            }
            if let Some(t) = &sample.tolerances {
                let perturbed = t.coupling(coupling).map_err(|source| RunError::Perturbed {
                    file: file.clone(),
                    index,
                    source,
                })?;
                let s = opts
                    .method
                    .seat(&perturbed, &nominal_mu, &StartPose::touching())
                    .map_err(|e| seat_err(index, &nominal_mu, e))?;
                outputs.extend(
                    points
                        .iter()
                        .flat_map(|p| PointPose::between(&nominal.pose, &s.pose, p).components()),
                );
            }
            tick();
            Ok(SampleRecord {
                index,
                inputs: row,
                outputs,
            })
        })
        .collect::<Result<Vec<_>, RunError>>()
}
