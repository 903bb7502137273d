//! The parameters a caller gives the library, named as data: a message
//! about one says which [`Param`] it is, and each front end spells it its
//! own way. The library's own spelling is the parameter's name with its
//! value as a keyword (`path_tolerance=-1`), as the Python package takes
//! it; the command line installs its flag spelling (`--path-tolerance -1`)
//! once at start with [`set_spelling`]. No text of the library names a
//! command-line flag.

use std::fmt;
use std::sync::OnceLock;

/// A parameter of a library call (a study option, a seating input, a
/// sweep or calibration argument, an output setting).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Param {
    Samples,
    Sampler,
    Seed,
    Shard,
    Solver,
    Increments,
    PathTolerance,
    Vary,
    OffsetBounds,
    TiltBounds,
    Sensitivity,
    SobolSamples,
    Replicates,
    /// The static friction coefficient of each contact.
    Mu,
    /// A swept field and its values (`FIELD=VALUES`).
    Sets,
    /// The design points of an LHS sweep.
    Points,
    ParetoPoint,
    /// The design of a sweep (grid or lhs).
    Design,
    /// The parameters a calibration fits.
    Fit,
    Noise,
    /// The measured evaluation point of a calibration.
    Point,
    Delimiter,
    /// The sample count of a calibration's model studies.
    ModelSamples,
    /// The principal radii of a general contact's two bodies.
    Radii1,
    Radii2,
    /// Permission to replace an existing output file.
    Force,
    Jobs,
    /// The temperature changes a thermal path visits.
    Cycle,
    /// The iterations of an optimisation's search.
    MaxIterations,
    /// The searches of an optimisation per combination of listed values.
    Starts,
    /// Whether a study seats four samples at a time in SIMD lanes.
    Lanes,
}

impl Param {
    /// The parameter's name in the library and the Python package.
    pub const fn name(self) -> &'static str {
        match self {
            Param::Samples => "samples",
            Param::Sampler => "sampler",
            Param::Seed => "seed",
            Param::Shard => "shard",
            Param::Solver => "solver",
            Param::Increments => "increments",
            Param::PathTolerance => "path_tolerance",
            Param::Vary => "vary",
            Param::OffsetBounds => "offset_bounds",
            Param::TiltBounds => "tilt_bounds",
            Param::Sensitivity => "sensitivity",
            Param::SobolSamples => "sobol_samples",
            Param::Replicates => "replicates",
            Param::Mu => "mu",
            Param::Sets => "sets",
            Param::Points => "points",
            Param::ParetoPoint => "pareto_point",
            Param::Design => "design",
            Param::Fit => "fit",
            Param::Noise => "noise",
            Param::Point => "point",
            Param::Delimiter => "delimiter",
            Param::ModelSamples => "model_samples",
            Param::Radii1 => "radii1",
            Param::Radii2 => "radii2",
            Param::Force => "force",
            Param::Jobs => "jobs",
            Param::Cycle => "cycle",
            Param::MaxIterations => "max_iterations",
            Param::Starts => "starts",
            Param::Lanes => "lanes",
        }
    }

    /// This parameter with a value, for a message: `samples=7` in the
    /// library's spelling.
    pub fn with(self, value: impl fmt::Display) -> Mention {
        Mention { param: self, value: Some(value.to_string()) }
    }
}

impl fmt::Display for Param {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        Mention { param: *self, value: None }.fmt(f)
    }
}

/// A parameter named in a message, with or without its value.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Mention {
    pub param: Param,
    pub value: Option<String>,
}

impl fmt::Display for Mention {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let spell = SPELLING.get().copied().unwrap_or(keyword);
        f.write_str(&spell(self.param, self.value.as_deref()))
    }
}

/// How a front end writes a parameter and its value in a message.
pub type Spelling = fn(Param, Option<&str>) -> String;

static SPELLING: OnceLock<Spelling> = OnceLock::new();

/// The library's spelling: the name, `name=value` with a value.
pub fn keyword(param: Param, value: Option<&str>) -> String {
    match value {
        None => param.name().to_string(),
        Some(v) => format!("{}={v}", param.name()),
    }
}

/// Spell every parameter of every later message with `spelling` (a front
/// end calls it once, before any work; later calls are ignored).
pub fn set_spelling(spelling: Spelling) {
    let _ = SPELLING.set(spelling);
}

/// A parameter whose value is out of range, unknown, or does not go with
/// another: the parameter as data, and the message, which names it (and
/// any other) by [`Param::with`] or [`Param`]'s `Display`.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[error("{message}")]
pub struct ParamError {
    pub param: Param,
    pub message: String,
}

impl ParamError {
    pub fn new(param: Param, message: impl Into<String>) -> Self {
        ParamError { param, message: message.into() }
    }
}
