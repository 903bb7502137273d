//! A study's options as a front end gives them ([`StudyOptions`]: the
//! flags of `kinrepro study` and `kinrepro sweep`, the keywords of the
//! Python package's `study` and `sweep`), and their check, in one place,
//! into the [`Settings`] every seating of the study shares. The plan
//! (`super::plan`) checks the options once, against every scene; nothing
//! after it checks them again. Every message names the parameter
//! ([`crate::param`]).

pub use super::inputs::Varied;
use super::variation::{StartBounds, Variation};
use super::{Sampler, Shard};
use crate::param::{Param, ParamError};
use crate::solve::quasistatic::Lanes;
use crate::solve::{Method, Solver};

/// The default base sample size N of the Sobol indices (`sobol_samples`):
/// N (d + 2) extra seatings for d inputs (`sensitivity::sobol`; the
/// Ishigami indices are then within 0.02, tests/it/sobol.rs).
pub const DEFAULT_BASE_SAMPLES: usize = 32768;

/// The options of a study or a sweep as given (None: the default, mostly
/// the scene's `[study]` value).
#[derive(Debug, Clone, PartialEq)]
pub struct StudyOptions {
    pub sampler: Option<Sampler>,
    pub samples: Option<usize>,
    pub seed: Option<u64>,
    pub shard: Shard,
    pub solver: Solver,
    /// Fixed load increments of the quasi-static solver (None: the load
    /// path is error-controlled).
    pub increments: Option<usize>,
    /// Tolerance of the load-path error control (None: the default;
    /// excludes `increments`).
    pub path_tolerance: Option<f64>,
    pub vary: Vec<Varied>,
    /// Start variation: half-widths of the x, y offset and the largest
    /// height z above the seat [m].
    pub offset_bounds: Option<[f64; 3]>,
    /// Start variation: half-widths of the tilt about x, y, z [rad].
    pub tilt_bounds: Option<[f64; 3]>,
    pub sensitivity: bool,
    /// Base sample size of the Sobol indices (None: the default; only with
    /// `sensitivity`).
    pub sobol_samples: Option<usize>,
    /// LHS replicates (None: [`super::sampling::default_replicates`]).
    pub replicates: Option<usize>,
    /// Whether quasi-static samples are seated four at a time in lanes
    /// (the same results; [`Lanes`]).
    pub lanes: Lanes,
}

impl Default for StudyOptions {
    /// Friction varied, quasi-static solver, everything else the scene's.
    fn default() -> Self {
        StudyOptions {
            sampler: None,
            samples: None,
            seed: None,
            shard: Shard::whole(),
            solver: Solver::QuasiStatic,
            increments: None,
            path_tolerance: None,
            vary: vec![Varied::Friction],
            offset_bounds: None,
            tilt_bounds: None,
            sensitivity: false,
            sobol_samples: None,
            replicates: None,
            lanes: Lanes::Auto,
        }
    }
}

/// What every seating of a study shares, checked ([`StudyOptions::settings`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Settings {
    pub method: Method,
    pub variation: Variation,
    /// The part of every scene's design this run seats.
    pub shard: Shard,
    /// Also compute the sensitivity (SRC) tables.
    pub sensitivity: bool,
    /// Base sample size of the Sobol indices, when sensitivity is asked for.
    pub sobol_samples: Option<usize>,
    /// Seat quasi-static samples four at a time in lanes ([`Lanes::used`]).
    pub lanes: bool,
}

fn fail<T>(param: Param, message: impl Into<String>) -> Result<T, ParamError> {
    Err(ParamError::new(param, message))
}

impl StudyOptions {
    /// Friction-varied Monte Carlo of `samples` samples seeded `seed`,
    /// seated by `method`'s solver (a calibration's model studies).
    pub fn monte_carlo(samples: usize, seed: u64, solver: Solver) -> Self {
        StudyOptions {
            sampler: Some(Sampler::MonteCarlo),
            samples: Some(samples),
            seed: Some(seed),
            solver,
            ..StudyOptions::default()
        }
    }

    /// Check every option and the options that go together (what does not
    /// depend on the scenes).
    pub fn settings(&self) -> Result<Settings, ParamError> {
        let method = Method::new(self.solver, self.increments, self.path_tolerance)?;
        let start = self.start_bounds()?;
        let sobol_samples = self.sobol()?;
        if self.sampler == Some(Sampler::Corners) && self.samples.is_some() {
            return fail(
                Param::Samples,
                format!(
                    "{} does not apply to {}: the corner design has all 2^d extremes",
                    Param::Samples,
                    Param::Sampler.with("corners")
                ),
            );
        }
        let has = |v: Varied| self.vary.contains(&v);
        Ok(Settings {
            method,
            variation: Variation {
                friction: has(Varied::Friction),
                preload: has(Varied::Preload),
                tolerances: has(Varied::Tolerances),
                start,
            },
            shard: self.shard,
            sensitivity: self.sensitivity,
            sobol_samples,
            lanes: self.lanes.used(),
        })
    }

    /// The start bounds of a varied start: finite, >= 0, not all zero;
    /// refused without it.
    fn start_bounds(&self) -> Result<Option<StartBounds>, ParamError> {
        let (offset, tilt) = (Param::OffsetBounds, Param::TiltBounds);
        if !self.vary.contains(&Varied::Start) {
            if self.offset_bounds.is_some() || self.tilt_bounds.is_some() {
                return fail(
                    offset,
                    format!("{offset} and {tilt} need {}", Param::Vary.with(Varied::Start.name())),
                );
            }
            return Ok(None);
        }
        let bounds = |param: Param, v: Option<[f64; 3]>| {
            let v = v.unwrap_or_default();
            if v.iter().any(|x| !x.is_finite() || *x < 0.0) {
                return fail(param, format!("{param}: bounds must be finite and >= 0"));
            }
            Ok(v.into())
        };
        let b = StartBounds {
            offset: bounds(offset, self.offset_bounds)?,
            tilt: bounds(tilt, self.tilt_bounds)?,
        };
        if b.offset.iter().chain(b.tilt.iter()).all(|x| *x == 0.0) {
            return fail(
                offset,
                format!(
                    "{} needs its bounds: {} [m] and/or {} [rad] (half-widths; without them the start would not vary)",
                    Param::Vary.with(Varied::Start.name()),
                    offset.with("X,Y,Z"),
                    tilt.with("X,Y,Z")
                ),
            );
        }
        Ok(Some(b))
    }

    /// The Sobol base sample size: at least 2, only with sensitivity.
    fn sobol(&self) -> Result<Option<usize>, ParamError> {
        let p = Param::SobolSamples;
        match (self.sensitivity, self.sobol_samples) {
            (false, None) => Ok(None),
            (false, Some(_)) => {
                fail(p, format!("{p}: has no effect without {}", Param::Sensitivity))
            }
            (true, Some(n)) if n < 2 => {
                fail(p, format!("{p}: the base sample size must be at least 2"))
            }
            (true, n) => Ok(Some(n.unwrap_or(DEFAULT_BASE_SAMPLES))),
        }
    }
}
