//! The TOML scene format as serde types (both forms). Values that are
//! validated later keep their source span, so errors can name the line.
//!
//! High-level form: a `[coupling]` table (arrangement, diameters, groove
//! realisation, materials, opening angle). Explicit form: `[[balls]]` and
//! `[[surfaces]]`. Both share `[preload]`, `[friction]`, `[study]`,
//! `[[evaluation_points]]` and `[[materials]]`. See docs/scenes.md.

mod goals;
mod points;

use serde::{Deserialize, Serialize};
use toml::Spanned;

pub use goals::GoalsFile;
pub use points::{DirectionFile, EvaluationPointFile, FrameFile};

use crate::contact::TangentialLaw;

/// A numeric array as written (a point, a direction, a pair of bounds).
/// Its length and element types are checked when the scene is resolved,
/// where the error can name the field: an array of the wrong length or with
/// an element that is not a number is an error, never cut to size.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(transparent)]
pub struct Numbers(pub Vec<toml::Value>);

/// The number a TOML value holds: a float, or an integer written without
/// a decimal point (`force = 20`).
pub fn number(x: &toml::Value) -> Option<f64> {
    x.as_float().or(x.as_integer().map(|i| i as f64))
}

impl Numbers {
    /// The array of these values (as `expand` writes it).
    pub fn of(values: &[f64]) -> Self {
        Numbers(values.iter().map(|v| toml::Value::Float(*v)).collect())
    }
}

/// A scene file as written.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SceneFile {
    /// Optional display name.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub name: Option<String>,
    /// Accept magnitudes beyond the plausibility bounds of `scene::plausible`
    /// (a ball above 0.5 m, a circle of balls above 5 m, a preload above 1 MN,
    /// and the bounds below: a ball below 10 um, E below 10 MPa, ...).
    #[serde(default, skip_serializing_if = "std::ops::Not::not")]
    pub allow_large_values: bool,
    /// User-defined materials (a built-in or earlier name only with `override = true`).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub materials: Vec<MaterialFile>,
    /// High-level form.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub coupling: Option<CouplingFile>,
    /// Explicit form: the moving balls (body frame = world frame in the
    /// unloaded touching pose).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub balls: Vec<BallFile>,
    /// Explicit form: the fixed surfaces, each serving one ball.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub surfaces: Vec<SurfaceFile>,
    pub preload: PreloadFile,
    pub friction: FrictionFile,
    #[serde(default)]
    pub study: StudyFile,
    /// Points of the moving half whose pose is reported (default: the centre;
    /// Kelvin adds the trihedral ball).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub evaluation_points: Vec<EvaluationPointFile>,
    /// Mass properties of the moving half for the dynamic solver (optional;
    /// default: three balls plus a plate, see `solve::dynamic::mass`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub dynamics: Option<DynamicsFile>,
    /// Bounds of the further sources of scatter a study may vary
    /// (`--vary preload`, `--vary tolerances`); every bound defaults to 0.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub variation: Option<VariationFile>,
    /// The bodies that carry the elements, their expansion and the
    /// temperature cycle (`kinrepro thermal`, a study's thermal drift).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub thermal: Option<ThermalFile>,
    /// What `sweep` and `optimize` seek when no objective or constraint is
    /// given on the command line (docs/guide-design.md, "Objectives and
    /// constraints"); the scene's physics does not read it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub goals: Option<GoalsFile>,
}

/// `[thermal]`: the body carrying the moving elements and the body carrying
/// the fixed ones (materials by name, each with a thermal expansion), the
/// point of each that stays put as it expands, and the temperature changes
/// of the two bodies from the seating temperature, visited in order.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct ThermalFile {
    pub moving_body: Spanned<String>,
    pub fixed_body: Spanned<String>,
    /// [m] (default: the origin).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub moving_origin: Option<Spanned<Numbers>>,
    /// [m] (default: the origin).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub fixed_origin: Option<Spanned<Numbers>>,
    /// Temperature changes [K] of (moving, fixed) body, one pair per point.
    pub cycle: Spanned<Vec<Spanned<Numbers>>>,
    /// The thermal path's error tolerance, relative (default
    /// [`crate::scene::thermal::DEFAULT_THERMAL_TOLERANCE`]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub path_tolerance: Option<Spanned<f64>>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct MaterialFile {
    pub name: Spanned<String>,
    /// Young's modulus [Pa].
    pub youngs_modulus: Spanned<f64>,
    /// Poisson's ratio [-].
    pub poisson_ratio: Spanned<f64>,
    /// Allowable peak contact pressure [Pa].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub allowable_pressure: Option<Spanned<f64>>,
    /// Allowable maximum (subsurface) shear stress [Pa].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub allowable_shear_stress: Option<Spanned<f64>>,
    /// Mean linear coefficient of thermal expansion [1/K] (needed where a
    /// `[thermal]` scene uses the material).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub thermal_expansion: Option<Spanned<f64>>,
    /// `override = true`: this entry intentionally replaces the built-in
    /// material or the earlier entry of the same name. Without it a reused
    /// name is an error; with it, a name that replaces nothing is one.
    #[serde(default, rename = "override", skip_serializing_if = "Option::is_none")]
    pub replaces: Option<Spanned<bool>>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Arrangement {
    /// Three V-grooves pointing at the centre.
    Maxwell,
    /// Trihedral seat, V-groove and flat.
    Kelvin,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum GrooveKind {
    /// Two flat flanks.
    Planes,
    /// Two cylindrical pins along the groove.
    Cylinders,
    /// Two fixed balls.
    Balls,
    /// Two concave circular flanks of `groove_radius` (a gothic arch).
    GothicArch,
}

/// The moving elements' contact surfaces (`coupling.ball_shape`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum BallShape {
    /// Balls of `ball_diameter`.
    #[default]
    Sphere,
    /// Canoe balls: each contact surface a spherical patch of
    /// `canoe_radius`, placed where a ball of `ball_diameter` would touch.
    Canoe,
    /// Crossed pins: at each contact a pin of `ball_diameter` on the moving
    /// half, across the groove's pin (needs groove = "cylinders").
    Pins,
}

/// High-level coupling description (lengths in metres).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct CouplingFile {
    pub arrangement: Arrangement,
    /// Diameter of the circle of ball centres [m].
    pub diameter: Spanned<f64>,
    /// Moving ball diameter [m].
    pub ball_diameter: Spanned<f64>,
    pub ball_material: Spanned<String>,
    /// How the grooves (and, for Kelvin, the trihedral seat) are realised.
    pub groove: GrooveKind,
    /// Pin or fixed-ball diameter [m] (cylinders, balls).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub groove_element_diameter: Option<Spanned<f64>>,
    /// Radius of each flank of a gothic-arch groove [m] (larger than the ball's).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub groove_radius: Option<Spanned<f64>>,
    /// Kelvin only: the elements of the trihedral seat of ball 1 (default:
    /// those of `groove`; for a gothic-arch groove, three planes).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seat: Option<GrooveKind>,
    /// sphere (default) | canoe.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ball_shape: Option<BallShape>,
    /// Radius of each canoe patch [m] (ball_shape = "canoe").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub canoe_radius: Option<Spanned<f64>>,
    pub groove_material: Spanned<String>,
    /// Angle between the two flanks of a groove [deg].
    #[serde(default = "default_opening_angle")]
    pub opening_angle_deg: Spanned<f64>,
    /// Support compliance in series with every contact, normal direction [m/N].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub support_compliance: Option<Spanned<toml::Value>>,
}

fn default_opening_angle() -> Spanned<f64> {
    Spanned::new(0..0, 90.0)
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct BallFile {
    /// Centre [m].
    pub centre: Spanned<Numbers>,
    /// Radius [m].
    pub radius: Spanned<f64>,
    pub material: Spanned<String>,
}

#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum SurfaceKind {
    Plane,
    Cylinder,
    Sphere,
    ConcaveCylinder,
}

impl SurfaceKind {
    /// The scene-file spelling.
    pub fn name(self) -> &'static str {
        match self {
            SurfaceKind::Plane => "plane",
            SurfaceKind::Cylinder => "cylinder",
            SurfaceKind::Sphere => "sphere",
            SurfaceKind::ConcaveCylinder => "concave-cylinder",
        }
    }
}

/// A fixed surface. Which fields are needed depends on `type`:
/// plane: `point`, `normal`; cylinder and concave-cylinder: `axis_point`,
/// `direction`, `radius`; sphere: `centre`, `radius`. `moving_centre` and
/// `moving_radius` (both or neither) give the moving element's own
/// spherical patch at this contact (a canoe ball's face) instead of the
/// ball's sphere; with `moving_direction` too, a moving pin whose axis
/// passes through `moving_centre` (crossed pins).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct SurfaceFile {
    #[serde(rename = "type")]
    pub kind: Spanned<SurfaceKind>,
    /// The moving ball this surface serves, 1-based.
    pub ball: Spanned<i64>,
    pub material: Spanned<String>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub point: Option<Spanned<Numbers>>,
    /// Outward normal of a plane (towards the ball).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub normal: Option<Spanned<Numbers>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub axis_point: Option<Spanned<Numbers>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub direction: Option<Spanned<Numbers>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub centre: Option<Spanned<Numbers>>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub radius: Option<Spanned<f64>>,
    /// Support compliance in series with this contact, normal direction [m/N].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub support_compliance: Option<Spanned<toml::Value>>,
    /// Centre of curvature of the moving element's patch at this contact,
    /// in the moving half [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub moving_centre: Option<Spanned<Numbers>>,
    /// Radius of curvature of that patch [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub moving_radius: Option<Spanned<f64>>,
    /// Makes the patch a pin (crossed pins): its axis direction; the axis
    /// passes through `moving_centre`.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub moving_direction: Option<Spanned<Numbers>>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PreloadFile {
    /// Total preload [N], ramped from 0 (the single central force; absent
    /// when `forces` gives the preload, docs/scenes.md).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub force: Option<Spanned<f64>>,
    /// Point of application in the moving half [m] (default: the centre).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub point: Option<Spanned<Numbers>>,
    /// Direction (default [0, 0, -1]).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub direction: Option<Spanned<Numbers>>,
    /// Duration of the ramp from 0 to the full preload [s] (default 1 s):
    /// the time base of the slip velocity of the quasi-static solver.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ramp_time: Option<Spanned<f64>>,
    /// Adds the weight of the moving half (mass from `mass` or
    /// `[dynamics]`): `true` (standard gravity along -z), `false`, or the
    /// gravity vector [gx, gy, gz] in m/s^2.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gravity: Option<Spanned<toml::Value>>,
    /// Mass of the moving half for `gravity` [kg].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub mass: Option<Spanned<f64>>,
    /// Centre of mass of the moving half for `gravity` [m] (default: the origin).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub centre_of_mass: Option<Spanned<Numbers>>,
    /// Several forces (`[[preload.forces]]`) instead of the single `force`.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub forces: Vec<PreloadForceFile>,
}

/// `[[preload.forces]]`: one force on the moving half, constant or a spring.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct PreloadForceFile {
    /// Force at full load in the touching pose [N] (not for a magnet,
    /// whose table gives it).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub force: Option<Spanned<f64>>,
    /// Point of application in the moving half [m].
    pub point: Spanned<Numbers>,
    /// Direction (normalised).
    pub direction: Spanned<Numbers>,
    /// Spring stiffness along `direction` [N/m] (with `free_length`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub stiffness: Option<Spanned<f64>>,
    /// Free length of the spring [m] (with `stiffness`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub free_length: Option<Spanned<f64>>,
    /// A magnet: the gap to its keeper in the touching pose [m] (with
    /// `force_table`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub gap: Option<Spanned<f64>>,
    /// A magnet's pull against the gap: [[gap_m, force_n], ...] by
    /// increasing gap (with `gap`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub force_table: Option<Spanned<Vec<Spanned<Numbers>>>>,
}

/// `[friction] distribution`: how each contact's mu_s is drawn
/// (`scene::mu`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Distribution {
    /// Rectangular in mu0 +- spread (the paper's).
    #[default]
    Uniform,
    /// Normal of mean mu0 and standard deviation `sd`, truncated to
    /// [0, MU_MAX].
    Normal,
    /// Lognormal of mean mu0 and standard deviation `sd`, truncated above
    /// MU_MAX.
    Lognormal,
    /// The measured `values`, each equally likely (resampled).
    Empirical,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct FrictionFile {
    /// Nominal static coefficient mu0: a number, or a list with one per
    /// contact (contact order).
    pub mu_static: Spanned<toml::Value>,
    /// Half-width of the variation: mu_s in mu0 +- spread; a number, or a
    /// list with one per contact.
    #[serde(default = "zero")]
    pub spread: Spanned<toml::Value>,
    #[serde(default)]
    pub distribution: Distribution,
    /// Standard deviation of mu_s (normal, lognormal): a number, or a list
    /// with one per contact.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sd: Option<Spanned<toml::Value>>,
    /// The measured coefficients an empirical distribution resamples.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub values: Option<Spanned<Vec<f64>>>,
    /// Correlation in [0, 1] between the coefficients of the contacts of
    /// one ball (a Gaussian copula, `scene::mu::correlate`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub correlation: Option<Spanned<f64>>,
    /// mu_d / mu_s.
    #[serde(default = "default_dynamic_ratio")]
    pub dynamic_ratio: Spanned<f64>,
    #[serde(default)]
    pub tangential_law: TangentialLaw,
    /// switch (default) | decay: which coefficient acts while sliding.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub law: Option<Spanned<FrictionLawName>>,
    /// c in mu(v) = mu_d + (mu_s - mu_d) exp(-c v) [s/m] (law = "decay").
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub decay_coefficient: Option<Spanned<f64>>,
}

/// `[friction] law`: the sliding coefficient (contact::friction).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FrictionLawName {
    /// Sudden switch to mu_d = dynamic_ratio * mu_s.
    Switch,
    /// Exponential decay from mu_s to mu_d with the slip velocity.
    Decay,
}

fn zero() -> Spanned<toml::Value> {
    Spanned::new(0..0, toml::Value::Float(0.0))
}

fn default_dynamic_ratio() -> Spanned<f64> {
    Spanned::new(0..0, 0.8)
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct StudyFile {
    #[serde(default = "default_samples")]
    pub samples: Spanned<i64>,
    /// lhs | mc | corners
    #[serde(default = "default_sampler")]
    pub sampler: Spanned<String>,
    #[serde(default)]
    pub seed: u64,
}

fn default_samples() -> Spanned<i64> {
    Spanned::new(0..0, 25)
}

fn default_sampler() -> Spanned<String> {
    Spanned::new(0..0, "lhs".to_string())
}

impl Default for StudyFile {
    fn default() -> Self {
        StudyFile { samples: default_samples(), sampler: default_sampler(), seed: 0 }
    }
}

/// `[dynamics]`: mass properties of the moving half (dynamic solver only;
/// the seated pose does not depend on them, only the time scale does).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct DynamicsFile {
    /// Mass of the moving half [kg].
    pub mass: Spanned<f64>,
    /// Principal moments of inertia about the centre of mass, along the
    /// scene axes x, y, z [kg m^2].
    pub inertia: Spanned<Numbers>,
    /// Centre of mass in the moving half [m] (default: the origin).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub centre_of_mass: Option<Spanned<Numbers>>,
}

/// `[variation]`: half-widths of the uniform distributions a study draws
/// when it varies the preload (re-seating scatter, every cycle) or the
/// manufacturing tolerances (interchangeability of coupling halves). All
/// optional, default 0 (not varied), never negative.
#[derive(Debug, Clone, PartialEq, Default, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct VariationFile {
    /// Offset of the preload point from its nominal position, x and y [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub preload_offset: Option<Spanned<Numbers>>,
    /// Tilt of the preload direction: each of the two tilt components
    /// (rotation about x and about y) uniform in +-this [rad].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub preload_tilt: Option<Spanned<f64>>,
    /// Diameter error of each moving ball [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ball_diameter: Option<Spanned<f64>>,
    /// Position error of each moving ball's centre in the moving half, x, y, z [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub ball_position: Option<Spanned<Numbers>>,
    /// Position error of each fixed surface along its nominal contact normal [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub surface_normal: Option<Spanned<f64>>,
    /// Angle error of each fixed surface: rotation about the horizontal axis
    /// through its nominal contact point, perpendicular to the contact normal [rad].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub surface_tilt: Option<Spanned<f64>>,
    /// Position error of each groove (all surfaces serving one ball, moved
    /// together), x and y [m].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub groove_position: Option<Spanned<Numbers>>,
}
