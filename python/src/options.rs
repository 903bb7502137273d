//! Keyword arguments into the library's [`StudyRequest`], which checks them
//! (`kinrepro::study::request`, the same checks and messages as the CLI's
//! flags): only the Python types are converted here.

use kinrepro::solve::Method;
use kinrepro::solve::dynamic::StartPose;
use kinrepro::study::request::{self, Solver, StudyRequest, StudySettings, Varied};
use kinrepro::study::{Sampler, Shard};
use pyo3::prelude::*;

use crate::err;

/// The seating method of `solver` (`"quasi-static"`, `"dynamic"`) with
/// fixed `increments` or the load path's `path_tolerance` (None, None: the
/// error-controlled default; quasi-static only).
pub fn method(
    solver: &str,
    increments: Option<usize>,
    path_tolerance: Option<f64>,
) -> PyResult<Method> {
    let solver: Solver = solver.parse().map_err(err)?;
    request::method(solver, increments, path_tolerance, StartPose::touching()).map_err(err)
}

/// `"INDEX/COUNT"` or a tuple `(index, count)` (1-based index).
pub fn shard(s: Option<&Bound<'_, PyAny>>) -> PyResult<Shard> {
    let Some(s) = s else {
        return Ok(Shard::whole());
    };
    if let Ok(text) = s.extract::<String>() {
        return text.parse().map_err(err);
    }
    let (i, c): (usize, usize) = s
        .extract()
        .map_err(|_| err("shard: give \"INDEX/COUNT\" or (index, count), e.g. \"2/4\""))?;
    Shard::new(i, c).map_err(err)
}

/// The keywords of `study` (and, friction varied and quasi-static, of
/// `sweep`) as given.
#[derive(Default)]
pub struct StudyArgs {
    pub samples: Option<usize>,
    pub sampler: Option<String>,
    pub seed: Option<u64>,
    pub vary: Option<Vec<String>>,
    /// None: the whole study.
    pub shard: Option<Shard>,
    pub solver: Option<String>,
    pub increments: Option<usize>,
    pub path_tolerance: Option<f64>,
    pub replicates: Option<usize>,
    pub sensitivity: bool,
    pub sobol_samples: Option<usize>,
    pub offset_bounds: Option<[f64; 3]>,
    pub tilt_bounds: Option<[f64; 3]>,
}

impl StudyArgs {
    /// The library's request of these keywords, checked by the library.
    pub fn settings(self) -> PyResult<StudySettings> {
        let sampler = self
            .sampler
            .as_deref()
            .map(str::parse::<Sampler>)
            .transpose()
            .map_err(err)?;
        let defaults = StudyRequest::default();
        let vary = match self.vary {
            None => defaults.vary,
            Some(v) => v
                .iter()
                .map(|s| s.parse::<Varied>())
                .collect::<Result<_, _>>()
                .map_err(err)?,
        };
        let solver = match self.solver.as_deref() {
            None => defaults.solver,
            Some(s) => s.parse().map_err(err)?,
        };
        StudyRequest {
            sampler,
            samples: self.samples,
            seed: self.seed,
            shard: self.shard.unwrap_or_else(Shard::whole),
            solver,
            increments: self.increments,
            path_tolerance: self.path_tolerance,
            vary,
            offset_bounds: self.offset_bounds,
            tilt_bounds: self.tilt_bounds,
            sensitivity: self.sensitivity,
            sobol_samples: self.sobol_samples,
            replicates: self.replicates,
        }
        .check()
        .map_err(err)
    }
}
