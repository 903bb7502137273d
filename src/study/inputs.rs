//! The varied quantities of a study ([`Input`], one design column each) and
//! the manufacturing errors of one sample ([`Tolerances`]); see
//! `study::runner` for how a design row maps onto them.

use nalgebra::{UnitQuaternion, Vector3};
use serde::{Deserialize, Serialize};

use crate::assembly::{AssemblyError, Coupling};
use crate::dof::Dof;
use crate::param::{Param, ParamError};
use crate::scene::{Scene, SurfaceGeometry};

/// One varied quantity: a column of the design. In JSON and CSV its
/// [`Input::name`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Input {
    /// Static coefficient of contact k (0-based).
    Mu(usize),
    /// Point offset of preload force f (0-based) along x (0) or y (1).
    PreloadOffset(usize, usize),
    /// Direction tilt of preload force f about x (0) or y (1).
    PreloadTilt(usize, usize),
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
    /// What this input varies.
    pub fn kind(&self) -> Varied {
        match self {
            Input::Mu(_) => Varied::Friction,
            Input::PreloadOffset(..) | Input::PreloadTilt(..) => Varied::Preload,
            Input::Start(_) => Varied::Start,
            _ => Varied::Tolerances,
        }
    }

    /// True for the manufacturing tolerances (interchangeability inputs).
    pub fn is_tolerance(&self) -> bool {
        self.kind() == Varied::Tolerances
    }

    /// The column name (SI unit as suffix), e.g. `mu_1`, `ball_2_x_m`.
    pub fn name(&self) -> String {
        let axis = Dof::axis;
        match *self {
            Input::Mu(k) => format!("mu_{}", k + 1),
            Input::PreloadOffset(f, a) => format!("preload{}_{}_m", force_tag(f), axis(a)),
            Input::PreloadTilt(f, a) => format!("preload{}_tilt_{}_rad", force_tag(f), axis(a)),
            Input::Start(j) if j < 3 => format!("offset_{}_m", axis(j)),
            Input::Start(j) => format!("tilt_{}_rad", axis(j - 3)),
            Input::BallDiameter(b) => format!("ball_{}_diameter_m", b + 1),
            Input::BallPosition(b, a) => format!("ball_{}_{}_m", b + 1, axis(a)),
            Input::SurfaceNormal(s) => format!("surface_{}_normal_m", s + 1),
            Input::SurfaceTilt(s) => format!("surface_{}_tilt_rad", s + 1),
            Input::GroovePosition(b, a) => format!("groove_{}_{}_m", b + 1, axis(a)),
        }
    }

    /// The input named `name` ([`Input::name`] read back).
    pub fn from_name(name: &str) -> Option<Input> {
        // The only number in a name is the 1-based index of a contact,
        // ball or surface; the candidates with that index name every input.
        let k = name.split('_').find_map(|p| p.parse::<usize>().ok());
        let k = k.unwrap_or(1).checked_sub(1)?;
        let axes = |f: fn(usize, usize) -> Input| (0..3).map(move |a| f(k, a));
        [Input::Mu(k), Input::BallDiameter(k)]
            .into_iter()
            .chain([Input::SurfaceNormal(k), Input::SurfaceTilt(k)])
            .chain(axes(Input::BallPosition).chain(axes(Input::GroovePosition)))
            .chain((0..2).flat_map(|a| [Input::PreloadOffset(k, a), Input::PreloadTilt(k, a)]))
            .chain((0..6).map(Input::Start))
            .find(|i| i.name() == name)
    }
}

/// The force number in a preload input's name: none for the first force
/// (the single preload's names, `preload_x_m`), `_2`, `_3`, ... after it.
fn force_tag(f: usize) -> String {
    match f {
        0 => String::new(),
        _ => format!("_{}", f + 1),
    }
}

impl std::fmt::Display for Input {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(&self.name())
    }
}

impl PartialEq<str> for Input {
    fn eq(&self, name: &str) -> bool {
        self.name() == name
    }
}

impl PartialEq<&str> for Input {
    fn eq(&self, name: &&str) -> bool {
        self.name() == *name
    }
}

impl Serialize for Input {
    fn serialize<S: serde::Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        s.serialize_str(&self.name())
    }
}

impl<'de> Deserialize<'de> for Input {
    fn deserialize<D: serde::Deserializer<'de>>(d: D) -> Result<Self, D::Error> {
        let name = String::deserialize(d)?;
        Input::from_name(&name)
            .ok_or_else(|| serde::de::Error::custom(format!("unknown input `{name}`")))
    }
}

/// What varies from sample to sample (`vary`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, clap::ValueEnum)]
pub enum Varied {
    /// The six static friction coefficients.
    Friction,
    /// The preload point and direction (scene [variation] bounds).
    Preload,
    /// The start pose of the moving half (dynamic solver).
    Start,
    /// Manufacturing tolerances (scene [variation] bounds): interchangeability.
    Tolerances,
}

impl Varied {
    /// The name as in `vary` and in the study document.
    pub fn name(self) -> &'static str {
        match self {
            Varied::Friction => "friction",
            Varied::Preload => "preload",
            Varied::Start => "start",
            Varied::Tolerances => "tolerances",
        }
    }
}

impl std::str::FromStr for Varied {
    type Err = ParamError;

    fn from_str(s: &str) -> Result<Self, ParamError> {
        <Varied as clap::ValueEnum>::from_str(s, false).map_err(|_| {
            ParamError::new(
                Param::Vary,
                format!(
                    "{}: unknown, need any of friction, preload, start, tolerances",
                    Param::Vary.with(s)
                ),
            )
        })
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
    pub fn zero(scene: &Scene) -> Self {
        let (b, s) = (scene.balls.len(), scene.surfaces.len());
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
    /// its radius grows by half its diameter error; a moving patch (canoe
    /// face) of ball k moves and grows with it.
    pub fn apply(&self, scene: &Scene, coupling: &Coupling) -> Scene {
        let mut scene = scene.clone();
        for (k, b) in scene.balls.iter_mut().enumerate() {
            b.centre += self.ball_position[k];
            b.radius += 0.5 * self.ball_diameter[k];
        }
        for (i, s) in scene.surfaces.iter_mut().enumerate() {
            let g = coupling.geometry(i, &coupling.touching_pose);
            let n = g.normal;
            let axis = n.cross(&Vector3::z());
            let axis = if axis.norm() < 1e-9 { Vector3::x() } else { axis.normalize() };
            let r = UnitQuaternion::from_scaled_axis(axis * self.surface_tilt[i]);
            let shift = n * self.surface_normal[i] + self.groove_position[s.ball];
            let moved = |x: Vector3<f64>| r * (x - g.point) + g.point + shift;
            s.geometry = match s.geometry {
                SurfaceGeometry::Plane { point, normal } => {
                    SurfaceGeometry::Plane { point: moved(point), normal: r * normal }
                }
                SurfaceGeometry::Cylinder { axis_point, direction, radius } => {
                    SurfaceGeometry::Cylinder {
                        axis_point: moved(axis_point),
                        direction: r * direction,
                        radius,
                    }
                }
                SurfaceGeometry::Sphere { centre, radius } => {
                    SurfaceGeometry::Sphere { centre: moved(centre), radius }
                }
                SurfaceGeometry::ConcaveCylinder { axis_point, direction, radius } => {
                    SurfaceGeometry::ConcaveCylinder {
                        axis_point: moved(axis_point),
                        direction: r * direction,
                        radius,
                    }
                }
            };
            // A moving patch moves with its ball; a diameter error moves its
            // surface along the normal as it moves the ball's.
            if let Some(p) = &mut s.moving {
                p.centre += self.ball_position[s.ball];
                p.radius += 0.5 * self.ball_diameter[s.ball];
            }
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

    /// The perturbed coupling of `scene` assembled as `coupling` (touching
    /// pose solved for the perturbed geometry).
    pub fn coupling(&self, scene: &Scene, coupling: &Coupling) -> Result<Coupling, AssemblyError> {
        Coupling::new_perturbed(&self.apply(scene, coupling), self.max_gap(coupling))
    }
}
