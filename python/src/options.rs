//! Keyword arguments into the library's `StudyOptions`, which the
//! library's study plan checks (the same checks and messages as the CLI's
//! flags, each message naming the keyword): only the Python types are
//! converted here.

use kinrepro::solve::{Method, Solver};
use kinrepro::study::{Sampler, Shard, StudyOptions, Varied};
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
    Method::new(solver, increments, path_tolerance).map_err(err)
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

/// The keywords a study and a sweep share, as the library's options
/// (friction varied, quasi-static: a sweep's; a study sets the rest).
pub struct Keywords<'a, 'py> {
    pub samples: Option<usize>,
    pub sampler: Option<String>,
    pub seed: Option<u64>,
    pub shard: Option<&'a Bound<'py, PyAny>>,
    pub increments: Option<usize>,
    pub path_tolerance: Option<f64>,
    pub replicates: Option<usize>,
}

impl Keywords<'_, '_> {
    pub fn options(self) -> PyResult<StudyOptions> {
        Ok(StudyOptions {
            sampler: self.sampler.as_deref().map(str::parse::<Sampler>).transpose().map_err(err)?,
            samples: self.samples,
            seed: self.seed,
            shard: shard(self.shard)?,
            increments: self.increments,
            path_tolerance: self.path_tolerance,
            replicates: self.replicates,
            ..StudyOptions::default()
        })
    }
}

/// The solver and what varies of a study.
pub fn solver_and_vary(solver: &str, vary: &[String]) -> PyResult<(Solver, Vec<Varied>)> {
    let vary = vary.iter().map(|s| s.parse::<Varied>()).collect::<Result<_, _>>().map_err(err)?;
    Ok((solver.parse().map_err(err)?, vary))
}
