//! Keyword arguments into the library's option types, with the checks and
//! the messages of the CLI's flags (`src/bin/kinrepro/flags/high.rs`).

use kinrepro::solve::dynamic::{DynamicOptions, StartPose};
use kinrepro::solve::{INCREMENTS, Method, SolverOptions};
use kinrepro::study::runner::{StartBounds, StudyOptions, Variation};
use kinrepro::study::{Sampler, Shard};
use nalgebra::Vector3;
use pyo3::prelude::*;

use crate::err;


/// The seating solver by name (`quasi-static`, `dynamic`).
pub fn method(solver: &str, increments: usize) -> PyResult<Method> {
    if !INCREMENTS.contains(&increments) {
        return Err(err(format!(
            "increments={increments}: out of range, need {}..={} load increments",
            INCREMENTS.start(),
            INCREMENTS.end()
        )));
    }
    match solver {
        "quasi-static" | "quasistatic" | "quasi_static" => Ok(Method::QuasiStatic(SolverOptions {
            increments,
            ..Default::default()
        })),
        "dynamic" => Ok(Method::Dynamic(DynamicOptions {
            start: StartPose::touching(),
            ..Default::default()
        })),
        _ => Err(err(format!(
            "solver={solver:?}: need \"quasi-static\" or \"dynamic\""
        ))),
    }
}

/// `"INDEX/COUNT"` or a tuple `(index, count)` (1-based index).
pub fn shard(s: Option<&Bound<'_, PyAny>>) -> PyResult<Shard> {
    let Some(s) = s else { return Ok(Shard::whole()) };
    if let Ok(text) = s.extract::<String>() {
        return text.parse().map_err(err);
    }
    let (i, c): (usize, usize) = s
        .extract()
        .map_err(|_| err("shard: give \"INDEX/COUNT\" or (index, count), e.g. \"2/4\""))?;
    Shard::new(i, c).map_err(err)
}

fn bounds(name: &str, v: Option<[f64; 3]>) -> PyResult<Vector3<f64>> {
    let v = Vector3::from(v.unwrap_or_default());
    if v.iter().any(|x| !x.is_finite() || *x < 0.0) {
        return Err(err(format!("{name}: bounds must be finite and >= 0")));
    }
    Ok(v)
}

/// The study's settings as `kinrepro study` builds them from its flags.
pub struct StudyArgs {
    pub samples: Option<usize>,
    pub sampler: Option<String>,
    pub seed: Option<u64>,
    pub vary: Vec<String>,
    pub shard: Shard,
    pub solver: String,
    pub increments: usize,
    pub replicates: Option<usize>,
    pub sensitivity: bool,
    pub offset_bounds: Option<[f64; 3]>,
    pub tilt_bounds: Option<[f64; 3]>,
}

impl StudyArgs {
    pub fn options(&self) -> PyResult<StudyOptions> {
        const KINDS: [&str; 4] = ["friction", "preload", "start", "tolerances"];
        if let Some(v) = self.vary.iter().find(|v| !KINDS.contains(&v.as_str())) {
            return Err(err(format!(
                "vary: unknown `{v}`, need any of friction, preload, start, tolerances"
            )));
        }
        let has = |k: &str| self.vary.iter().any(|v| v == k);
        let start = if has("start") {
            Some(StartBounds {
                offset: bounds("offset_bounds", self.offset_bounds)?,
                tilt: bounds("tilt_bounds", self.tilt_bounds)?,
            })
        } else if self.offset_bounds.is_some() || self.tilt_bounds.is_some() {
            return Err(err("offset_bounds and tilt_bounds need vary=(..., \"start\")"));
        } else {
            None
        };
        let sampler = self
            .sampler
            .as_deref()
            .map(|s| {
                s.parse::<Sampler>()
                    .map_err(|_| err(format!("sampler={s:?}: need \"lhs\", \"mc\" or \"corners\"")))
            })
            .transpose()?;
        if sampler == Some(Sampler::Corners) && self.samples.is_some() {
            return Err(err(
                "samples does not apply to sampler=\"corners\": the corner design has all 2^d extremes",
            ));
        }
        Ok(StudyOptions {
            sampler,
            samples: self.samples,
            seed: self.seed,
            shard: self.shard,
            method: method(&self.solver, self.increments)?,
            variation: Variation {
                friction: has("friction"),
                preload: has("preload"),
                tolerances: has("tolerances"),
                start,
            },
            sensitivity: self.sensitivity,
            replicates: self.replicates,
        })
    }
}
