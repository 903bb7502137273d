//! A study's options as a front end receives them (the flags of `kinrepro
//! study` and `kinrepro sweep`, the keywords of the Python package's `study`
//! and `sweep`), checked in one place into the [`StudyOptions`] the runner
//! takes, so that the same options give the same study whichever front end
//! asks. Every message names the option by its command-line flag
//! (`--samples`), as the library's other messages do.

use std::str::FromStr;

use thiserror::Error;

use super::runner::{StartBounds, StudyOptions, Variation};
use super::sensitivity::sobol::DEFAULT_BASE_SAMPLES;
use super::{Sampler, Shard};
use crate::solve::dynamic::{DynamicOptions, StartPose};
use crate::solve::{INCREMENTS, Method, PATH_TOLERANCES, SolverOptions};

/// An option out of range, or options that do not go together.
#[derive(Debug, Clone, PartialEq, Eq, Error)]
#[error("{0}")]
pub struct OptionError(pub String);

fn fail<T>(message: impl Into<String>) -> Result<T, OptionError> {
    Err(OptionError(message.into()))
}

/// The seating solver (`--solver`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Solver {
    /// Quasi-static path following.
    #[default]
    QuasiStatic,
    /// Seating dynamics.
    Dynamic,
}

impl FromStr for Solver {
    type Err = OptionError;

    /// `quasi-static` (or `quasistatic`, `quasi_static`), `dynamic`.
    fn from_str(s: &str) -> Result<Self, OptionError> {
        match s {
            "quasi-static" | "quasistatic" | "quasi_static" => Ok(Solver::QuasiStatic),
            "dynamic" => Ok(Solver::Dynamic),
            _ => fail(format!(
                "--solver {s}: unknown, need quasi-static or dynamic"
            )),
        }
    }
}

/// What varies from sample to sample (`--vary`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Varied {
    Friction,
    Preload,
    Start,
    Tolerances,
}

impl FromStr for Varied {
    type Err = OptionError;

    fn from_str(s: &str) -> Result<Self, OptionError> {
        match s {
            "friction" => Ok(Varied::Friction),
            "preload" => Ok(Varied::Preload),
            "start" => Ok(Varied::Start),
            "tolerances" => Ok(Varied::Tolerances),
            _ => fail(format!(
                "--vary {s}: unknown, need any of friction, preload, start, tolerances"
            )),
        }
    }
}

/// The options of a study or a sweep as given (None: the default, mostly
/// the scene's `[study]` value).
#[derive(Debug, Clone, PartialEq)]
pub struct StudyRequest {
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
    pub replicates: Option<usize>,
}

impl Default for StudyRequest {
    /// Friction varied, quasi-static solver, everything else the scene's.
    fn default() -> Self {
        StudyRequest {
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
        }
    }
}

/// A checked request: the runner's options, and the base sample size of
/// the Sobol indices when sensitivity is asked for.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StudySettings {
    pub options: StudyOptions,
    pub sobol_samples: Option<usize>,
}

impl StudyRequest {
    /// Check every option and the options that go together.
    pub fn check(&self) -> Result<StudySettings, OptionError> {
        let method = method(
            self.solver,
            self.increments,
            self.path_tolerance,
            StartPose::touching(),
        )?;
        let start = self.start_bounds()?;
        let sobol_samples = self.sobol()?;
        if self.sampler == Some(Sampler::Corners) && self.samples.is_some() {
            return fail(
                "--samples does not apply to --sampler corners: the corner design has all 2^d extremes",
            );
        }
        let has = |v: Varied| self.vary.contains(&v);
        let options = StudyOptions {
            sampler: self.sampler,
            samples: self.samples,
            seed: self.seed,
            shard: self.shard,
            method,
            variation: Variation {
                friction: has(Varied::Friction),
                preload: has(Varied::Preload),
                tolerances: has(Varied::Tolerances),
                start,
            },
            sensitivity: self.sensitivity,
            replicates: self.replicates,
        };
        Ok(StudySettings {
            options,
            sobol_samples,
        })
    }

    /// The start bounds of `--vary start`: finite, >= 0, not all zero;
    /// refused without it.
    fn start_bounds(&self) -> Result<Option<StartBounds>, OptionError> {
        if !self.vary.contains(&Varied::Start) {
            if self.offset_bounds.is_some() || self.tilt_bounds.is_some() {
                return fail("--offset-bounds and --tilt-bounds need --vary start");
            }
            return Ok(None);
        }
        let bounds = |flag: &str, v: Option<[f64; 3]>| {
            let v = v.unwrap_or_default();
            if v.iter().any(|x| !x.is_finite() || *x < 0.0) {
                return fail(format!("--{flag}: bounds must be finite and >= 0"));
            }
            Ok(v.into())
        };
        let b = StartBounds {
            offset: bounds("offset-bounds", self.offset_bounds)?,
            tilt: bounds("tilt-bounds", self.tilt_bounds)?,
        };
        if b.offset.iter().chain(b.tilt.iter()).all(|x| *x == 0.0) {
            return fail(
                "--vary start needs its bounds: --offset-bounds X,Y,Z [m] and/or --tilt-bounds X,Y,Z [rad] (half-widths; without them the start would not vary)",
            );
        }
        Ok(Some(b))
    }

    /// The Sobol base sample size: at least 2, only with `--sensitivity`.
    fn sobol(&self) -> Result<Option<usize>, OptionError> {
        match (self.sensitivity, self.sobol_samples) {
            (false, None) => Ok(None),
            (false, Some(_)) => fail("--sobol-samples: has no effect without --sensitivity"),
            (true, Some(n)) if n < 2 => {
                fail("--sobol-samples: the base sample size must be at least 2")
            }
            (true, n) => Ok(Some(n.unwrap_or(DEFAULT_BASE_SAMPLES))),
        }
    }
}

/// The seating method. Quasi-static: `increments` N fixed load increments
/// ([`SolverOptions::fixed`], not error-controlled), or else load-path
/// error control to `path_tolerance` (None: [`SolverOptions::default`]'s);
/// the two exclude each other. Dynamic: started at `start` (its time step
/// comes from the contact frequencies: increments and a path tolerance are
/// refused there).
pub fn method(
    solver: Solver,
    increments: Option<usize>,
    path_tolerance: Option<f64>,
    start: StartPose,
) -> Result<Method, OptionError> {
    match (solver, increments, path_tolerance) {
        (Solver::Dynamic, Some(n), _) => fail(format!(
            "--increments {n}: has no effect with --solver dynamic (load increments belong to the quasi-static solver; the dynamic one steps in time)"
        )),
        (Solver::Dynamic, None, Some(t)) => fail(format!(
            "--path-tolerance {t}: has no effect with --solver dynamic (the load path belongs to the quasi-static solver; the dynamic one steps in time)"
        )),
        (Solver::Dynamic, None, None) => Ok(Method::Dynamic(DynamicOptions {
            start,
            ..Default::default()
        })),
        (Solver::QuasiStatic, Some(n), Some(t)) => fail(format!(
            "--increments {n} and --path-tolerance {t} exclude each other: fixed load \
             increments are not error-controlled (give one)"
        )),
        (Solver::QuasiStatic, Some(n), None) if !INCREMENTS.contains(&n) => fail(format!(
            "--increments {n}: out of range, need {}..={} load increments",
            INCREMENTS.start(),
            INCREMENTS.end()
        )),
        (Solver::QuasiStatic, Some(n), None) => Ok(Method::QuasiStatic(SolverOptions::fixed(n))),
        (Solver::QuasiStatic, None, Some(t)) if !PATH_TOLERANCES.contains(&t) => fail(format!(
            "--path-tolerance {t}: out of range, need {:e}..={:e} (the estimated error of \
             the seated pose relative to the seating's motion)",
            PATH_TOLERANCES.start(),
            PATH_TOLERANCES.end()
        )),
        (Solver::QuasiStatic, None, t) => Ok(Method::QuasiStatic(SolverOptions {
            path_tolerance: t.or(SolverOptions::default().path_tolerance),
            ..Default::default()
        })),
    }
}
