//! Scenes: the TOML file format (high-level and explicit forms), the
//! expansion of the high-level form, and validation into a [`Scene`].
//!
//! Axes and contact numbering follow docs/model.md: origin at the centre of
//! the circle of ball centres in their plane (unloaded touching pose), z from
//! the fixed to the moving half, balls 1, 2, 3 at azimuths 90, 210 and 330
//! degrees; contacts are numbered ball by ball, which is the order of `--mu`.

pub mod bundled;
pub mod error;
pub mod expand;
pub mod file;
pub mod magnet;
pub mod mu;
pub mod plausible;
pub mod point;
pub mod preload;
pub mod resolve;
pub mod thermal;
mod tidy;

use std::path::Path;

use nalgebra::Vector3;
use serde::{Deserialize, Serialize};

use crate::contact::{FrictionLaw, TangentialLaw, TangentialSupport};
use crate::material::Material;
use crate::param::{Param, ParamError};
use error::ErrorContext;
pub use error::SceneError;
pub use file::{Arrangement, GrooveKind, SceneFile};
pub use mu::MuDistribution;
pub use point::{Direction, EvaluationPoint};
pub use preload::{ForceLaw, Preload, PreloadForce};
pub use thermal::{Body, Temperatures, Thermal, ThermalBodies};

/// A moving ball (body frame = world frame in the touching pose).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Ball {
    pub centre: Vector3<f64>,
    pub radius: f64,
    pub material: Material,
    /// Line in the scene file, for error messages (not part of the
    /// coupling: left out of its serialisation, the fingerprint's).
    #[serde(skip)]
    pub line: Option<usize>,
}

#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub enum SurfaceGeometry {
    /// Half-space below `point` with unit outward `normal` (towards the ball).
    Plane { point: Vector3<f64>, normal: Vector3<f64> },
    /// Cylinder (pin) of `radius` around the line through `axis_point`
    /// along the unit `direction`.
    Cylinder { axis_point: Vector3<f64>, direction: Vector3<f64>, radius: f64 },
    /// Fixed ball.
    Sphere { centre: Vector3<f64>, radius: f64 },
    /// The inside of a cylinder of `radius` around the line through
    /// `axis_point` along the unit `direction`: a concave groove flank
    /// (one flank of a gothic arch); the ball lies inside it.
    ConcaveCylinder { axis_point: Vector3<f64>, direction: Vector3<f64>, radius: f64 },
}

/// The moving element's own surface at one contact, when it is not the
/// ball's sphere: a spherical patch of `radius` centred at `centre` (body
/// frame), e.g. one face of a canoe ball; or, with an `axis`, a pin of
/// `radius` about the line through `centre` along the unit `axis` (crossed
/// pins).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MovingPatch {
    /// Centre of curvature (a point of the axis for a pin), body frame [m].
    pub centre: Vector3<f64>,
    /// Radius of curvature [m].
    pub radius: f64,
    /// A pin's unit axis direction in the body frame; `None`: a sphere.
    pub axis: Option<Vector3<f64>>,
}

/// A fixed surface serving one moving ball: one contact.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Surface {
    pub geometry: SurfaceGeometry,
    pub material: Material,
    /// Index of the moving ball (0-based).
    pub ball: usize,
    /// Line in the scene file, for error messages (not serialised).
    #[serde(skip)]
    pub line: Option<usize>,
    /// Support compliance in series with the contact, normal direction [m/N].
    pub support_compliance: f64,
    /// Support compliance in series with the contact's tangential
    /// stiffness [m/N]: isotropic in the tangent plane, or along and
    /// across an axis (rigid: none).
    #[serde(flatten)]
    pub tangential_support: TangentialSupport,
    /// The moving element's surface at this contact; `None`: the ball's sphere.
    pub moving: Option<MovingPatch>,
}

/// Default `[preload] ramp_time` [s]: the end time of a static load step in
/// FE codes (ANSYS), so that slip velocities mean the same in both.
pub const DEFAULT_RAMP_TIME: f64 = 1.0;

/// Friction settings: mu_s in mu0 +- spread (uniform), mu_d = ratio mu_s,
/// and the law of the sliding coefficient (switch or decay).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct FrictionSettings {
    /// mu0: the one value, or the mean of the per-contact values.
    pub mu_static: f64,
    /// The spread: the one value, or the mean of the per-contact values.
    pub spread: f64,
    pub dynamic_ratio: f64,
    pub tangential_law: TangentialLaw,
    pub law: FrictionLaw,
}

/// The study defaults of a scene (`[study]`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct StudyDefaults {
    pub samples: usize,
    pub sampler: Sampler,
    pub seed: u64,
}

/// Which design a study draws (`[study] sampler`, `--sampler`); the designs
/// themselves are `study::sampling`'s. Serialised (and parsed by
/// [`FromStr`](std::str::FromStr)) as `lhs`, `mc`, `corners`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Sampler {
    /// Space-filling optimised Latin hypercube.
    #[serde(rename = "lhs")]
    Lhs,
    /// Plain Monte Carlo, independently computable per sample index.
    #[serde(rename = "mc")]
    MonteCarlo,
    /// All 2^d corners of the hypercube.
    #[serde(rename = "corners")]
    Corners,
}

impl Sampler {
    /// The name used in files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Sampler::Lhs => "lhs",
            Sampler::MonteCarlo => "mc",
            Sampler::Corners => "corners",
        }
    }

    /// The sampler named `name`, spelled exactly as [`Sampler::name`]
    /// (as every other keyword of a scene: `MC` is refused, not read as
    /// `mc`).
    pub fn parse(name: &str) -> Option<Self> {
        match name {
            "lhs" => Some(Sampler::Lhs),
            "mc" => Some(Sampler::MonteCarlo),
            "corners" => Some(Sampler::Corners),
            _ => None,
        }
    }
}

impl std::fmt::Display for Sampler {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        f.write_str(self.name())
    }
}

impl std::str::FromStr for Sampler {
    type Err = ParamError;

    fn from_str(s: &str) -> Result<Self, ParamError> {
        Sampler::parse(s).ok_or_else(|| {
            ParamError::new(
                Param::Sampler,
                format!("unknown sampler '{s}': expected lhs, mc or corners"),
            )
        })
    }
}

/// Mass properties of the moving half given in the scene (`[dynamics]`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct DynamicsSettings {
    /// Mass [kg].
    pub mass: f64,
    /// Principal moments of inertia about the centre of mass along x, y, z [kg m^2].
    pub inertia: Vector3<f64>,
    /// Centre of mass in the body frame [m].
    pub centre_of_mass: Vector3<f64>,
}

/// A validated scene in explicit form. Its serialisation (serde_json) is
/// the canonical form the study fingerprint hashes (`study::provenance`).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Scene {
    /// The file it came from (for messages).
    pub file: String,
    pub name: String,
    pub balls: Vec<Ball>,
    /// Fixed surfaces, ordered ball by ball: the contact order (`--mu`).
    pub surfaces: Vec<Surface>,
    pub preload: Preload,
    pub friction: FrictionSettings,
    /// `[friction] mu_static` or `spread` given per contact: (mu0, spread)
    /// of each contact, in contact order (`None`: the one pair of
    /// `friction` at every contact).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_friction: Option<Vec<[f64; 2]>>,
    /// `[friction] distribution`: how each contact's mu_s is drawn beyond
    /// its mu0 and spread (`mu`); left out of the serialised form (and so
    /// of the fingerprint) when uniform.
    #[serde(default, skip_serializing_if = "MuDistribution::is_uniform")]
    pub mu_distribution: MuDistribution,
    /// `[friction] correlation`: between the coefficients of the contacts
    /// of one ball (`mu::correlate`); left out when 0.
    #[serde(default, skip_serializing_if = "is_zero")]
    pub mu_correlation: f64,
    pub study: StudyDefaults,
    pub evaluation_points: Vec<EvaluationPoint>,
    /// Mass properties for the dynamic solver; `None`: the default model.
    pub dynamics: Option<DynamicsSettings>,
    /// Bounds of the preload and tolerance variation (`[variation]`; 0: not varied).
    pub variation: VariationBounds,
    /// The thermal model and cycle (`[thermal]`), if any; left out of the
    /// canonical form when absent, so that a scene without it keeps the
    /// fingerprint it had before thermal drift existed.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub thermal: Option<Thermal>,
}

/// Half-widths of the uniform distributions of `[variation]` (SI units;
/// 0 = not varied). See docs/scenes.md for exactly what each one moves.
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize, Deserialize)]
pub struct VariationBounds {
    /// Preload point offset, x and y [m].
    pub preload_offset_m: [f64; 2],
    /// Each tilt component of the preload direction (about x, about y) [rad].
    pub preload_tilt_rad: f64,
    /// Diameter error of each moving ball [m].
    pub ball_diameter_m: f64,
    /// Centre position error of each moving ball, x, y, z [m].
    pub ball_position_m: [f64; 3],
    /// Shift of each fixed surface along its nominal contact normal [m].
    pub surface_normal_m: f64,
    /// Rotation of each fixed surface about the horizontal axis through its
    /// nominal contact point perpendicular to the contact normal [rad].
    pub surface_tilt_rad: f64,
    /// Shift of each groove (the surfaces of one ball together), x and y [m].
    pub groove_position_m: [f64; 2],
}

impl VariationBounds {
    /// True if any preload bound is non-zero.
    pub fn preload_varies(&self) -> bool {
        self.preload_offset_m.iter().any(|b| *b > 0.0) || self.preload_tilt_rad > 0.0
    }

    /// The `[variation]` keys with a non-zero bound: the preload's if
    /// `preload`, the tolerances' if `tolerances` (for messages naming
    /// what a sample drew).
    pub fn keys(&self, preload: bool, tolerances: bool) -> Vec<&'static str> {
        let any = |v: &[f64]| v.iter().any(|b| *b > 0.0);
        let preload_keys = [
            ("preload_offset", any(&self.preload_offset_m)),
            ("preload_tilt", self.preload_tilt_rad > 0.0),
        ];
        let tolerance_keys = [
            ("ball_diameter", self.ball_diameter_m > 0.0),
            ("ball_position", any(&self.ball_position_m)),
            ("surface_normal", self.surface_normal_m > 0.0),
            ("surface_tilt", self.surface_tilt_rad > 0.0),
            ("groove_position", any(&self.groove_position_m)),
        ];
        let chosen = preload_keys.iter().filter(|_| preload);
        (chosen.chain(tolerance_keys.iter().filter(|_| tolerances)))
            .filter(|(_, on)| *on)
            .map(|(k, _)| *k)
            .collect()
    }

    /// True if any tolerance bound is non-zero.
    pub fn tolerances_vary(&self) -> bool {
        self.ball_diameter_m > 0.0
            || self.ball_position_m.iter().any(|b| *b > 0.0)
            || self.surface_normal_m > 0.0
            || self.surface_tilt_rad > 0.0
            || self.groove_position_m.iter().any(|b| *b > 0.0)
    }
}

impl Scene {
    /// Read and validate a scene file.
    pub fn load(path: &Path) -> Result<Scene, SceneError> {
        let file = path.display().to_string();
        let source = crate::input::read_to_string(path).map_err(|e| SceneError {
            file: file.clone(),
            line: None,
            field: String::new(),
            reason: format!("cannot read the file: {e}"),
        })?;
        Scene::parse(&source, &file)
    }

    /// Parse and validate scene text; `file` names it in errors.
    pub fn parse(source: &str, file: &str) -> Result<Scene, SceneError> {
        let ctx = ErrorContext::new(file, source);
        let raw = parse_file(source, &ctx)?;
        let explicit = expand::to_explicit(&raw, &ctx)?;
        resolve::resolve(&explicit, &ctx)
    }

    /// Validate a scene file's typed form, e.g. one whose fields a sweep
    /// set ([`crate::explore::field`]): `source` is the text it was read
    /// from (errors name its lines; a value set since has none), `file`
    /// names it in errors.
    pub fn from_file(raw: &SceneFile, file: &str, source: &str) -> Result<Scene, SceneError> {
        let ctx = ErrorContext::new(file, source);
        let explicit = expand::to_explicit(raw, &ctx)?;
        resolve::resolve(&explicit, &ctx)
    }

    /// The explicit TOML of a scene file (`kinrepro expand`).
    pub fn expand_text(source: &str, file: &str) -> Result<String, SceneError> {
        let ctx = ErrorContext::new(file, source);
        let raw = parse_file(source, &ctx)?;
        let explicit = expand::to_explicit(&raw, &ctx)?;
        // Validate before printing, so that expand never prints a bad scene.
        resolve::resolve(&explicit, &ctx)?;
        let to_text = |e: toml::ser::Error| ctx.error(None, "", e.to_string());
        let mut value = toml::Value::try_from(&explicit).map_err(to_text)?;
        tidy::tidy(&mut value);
        // Back through the typed form, which keeps the order of the fields.
        let tidied = parse_file(&toml::to_string(&value).map_err(to_text)?, &ctx)?;
        let body = toml::to_string_pretty(&tidied).map_err(to_text)?;
        Ok(format!(
            "# Explicit form of {file}, written by `kinrepro expand`.\n\
             # Lengths in m, forces in N, moduli in Pa; contacts in the order of --mu.\n\n{body}"
        ))
    }
}

impl SceneFile {
    /// The typed form of scene text, not yet validated; `file` names it in
    /// errors.
    pub fn parse(source: &str, file: &str) -> Result<SceneFile, SceneError> {
        parse_file(source, &ErrorContext::new(file, source))
    }
}

fn parse_file(source: &str, ctx: &ErrorContext) -> Result<SceneFile, SceneError> {
    toml::from_str::<SceneFile>(source).map_err(|e| {
        let span = e.span();
        ctx.error(span.as_ref(), "", e.message().trim().to_string())
    })
}

/// Serde: leave a zero out (a field added later, so that documents and
/// fingerprints without it stay as they were).
pub(crate) fn is_zero(x: &f64) -> bool {
    *x == 0.0
}

impl Scene {
    /// The scale of the friction coefficients' distribution, the one number
    /// a calibration fits for it: the spread of a uniform one, the sd of a
    /// normal or lognormal one (its first contact's; `calibrate` requires
    /// one for all); 0 for empirical values (nothing to scale).
    pub fn mu_scale(&self) -> f64 {
        match &self.mu_distribution {
            MuDistribution::Uniform => self.friction.spread,
            MuDistribution::Normal { sd } | MuDistribution::Lognormal { sd } => {
                sd.first().copied().unwrap_or(0.0)
            }
            MuDistribution::Empirical { .. } => 0.0,
        }
    }

    /// Set [`Scene::mu_scale`] to `x` at every contact (empirical values
    /// are left as they are).
    pub fn set_mu_scale(&mut self, x: f64) {
        match &mut self.mu_distribution {
            MuDistribution::Uniform => self.friction.spread = x,
            MuDistribution::Normal { sd } | MuDistribution::Lognormal { sd } => sd.fill(x),
            MuDistribution::Empirical { .. } => {}
        }
    }

    /// The warning where the truncation of a normal or lognormal
    /// distribution removes much of it ([`MuDistribution::truncation_warning`]).
    pub fn truncation_warning(&self) -> Option<String> {
        let mu0s: Vec<f64> = (0..self.surfaces.len()).map(|k| self.friction_of(k).0).collect();
        self.mu_distribution.truncation_warning(&mu0s)
    }

    /// (mu0, spread) of contact `k` (0-based): its own where `[friction]`
    /// gives lists, else the scene's.
    pub fn friction_of(&self, k: usize) -> (f64, f64) {
        match &self.contact_friction {
            Some(v) => (v[k][0], v[k][1]),
            None => (self.friction.mu_static, self.friction.spread),
        }
    }

    /// mu_s of contact `k` at the design coordinate `u` in [0, 1]: the
    /// quantile of its distribution (`mu`).
    pub fn mu_at(&self, k: usize, u: f64) -> f64 {
        let (mu0, spread) = self.friction_of(k);
        self.mu_distribution.quantile(k, mu0, spread, u)
    }

    /// The range contact `k`'s mu_s is drawn from
    /// ([`MuDistribution::range`]).
    pub fn mu_range(&self, k: usize) -> (f64, f64) {
        let (mu0, spread) = self.friction_of(k);
        self.mu_distribution.range(k, mu0, spread)
    }

    /// The largest mu_s a study draws at any contact (the top of
    /// [`Scene::mu_range`]; mu0 + spread where uniform).
    pub fn largest_mu(&self) -> f64 {
        let start = match self.mu_distribution {
            MuDistribution::Uniform => self.friction.mu_static + self.friction.spread,
            _ => 0.0,
        };
        (0..self.surfaces.len()).map(|k| self.mu_range(k).1).fold(start, f64::max)
    }
}
