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

use rayon::prelude::*;
use thiserror::Error;

use super::StudyError;
use super::stats::SampleRecord;
use super::{DesignSpec, Sampler, Shard};
use crate::assembly::Coupling;
use nalgebra::Vector3;

use crate::solve::dynamic::StartPose;
use crate::solve::{Method, PointPose, SolveError, nominal_mu};

/// Output components per evaluation point (relative to the nominal seating, SI).
pub const COMPONENTS: [&str; 5] = ["x_m", "y_m", "z_m", "phi_x_rad", "phi_y_rad"];

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
    /// The start pose (needs the dynamic solver).
    pub start: Option<StartBounds>,
}

impl Default for Variation {
    fn default() -> Self {
        Variation {
            friction: true,
            start: None,
        }
    }
}

impl Variation {
    /// Names of the design dimensions, in row order.
    pub fn input_names(&self, contacts: usize) -> Vec<String> {
        let mut v: Vec<String> = Vec::new();
        if self.friction {
            v.extend((1..=contacts).map(|k| format!("mu_{k}")));
        }
        if self.start.is_some() {
            v.extend(
                [
                    "offset_x_m",
                    "offset_y_m",
                    "offset_z_m",
                    "tilt_x_rad",
                    "tilt_y_rad",
                    "tilt_z_rad",
                ]
                .map(String::from),
            );
        }
        v
    }

    /// Static coefficients and start pose of one design row (of
    /// `input_names().len()` coordinates).
    pub fn map(&self, coupling: &Coupling, row: &[f64]) -> (Vec<f64>, StartPose) {
        let n = coupling.contacts.len();
        let (mu, rest) = if self.friction {
            (mu_of_row(coupling, &row[..n]), &row[n..])
        } else {
            (nominal_mu(coupling), row)
        };
        let start = match self.start {
            Some(b) => {
                let tilted = StartPose {
                    offset: Vector3::new(
                        b.offset.x * (2.0 * rest[0] - 1.0),
                        b.offset.y * (2.0 * rest[1] - 1.0),
                        0.0,
                    ),
                    tilt: Vector3::new(
                        b.tilt.x * (2.0 * rest[3] - 1.0),
                        b.tilt.y * (2.0 * rest[4] - 1.0),
                        b.tilt.z * (2.0 * rest[5] - 1.0),
                    ),
                };
                let mut s = lifted_clear(coupling, tilted);
                s.offset.z += b.offset.z * rest[2];
                s
            }
            None => StartPose::touching(),
        };
        (mu, start)
    }
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
    let dims = opts.variation.input_names(coupling.contacts.len()).len();
    DesignSpec::new(sampler, dims, n, opts.seed.unwrap_or(st.seed))
}

/// Static coefficients of one design row.
pub fn mu_of_row(coupling: &Coupling, row: &[f64]) -> Vec<f64> {
    let f = &coupling.scene.friction;
    row.iter()
        .map(|u| f.mu_static + f.spread * (2.0 * u - 1.0))
        .collect()
}

/// Names of the recorded outputs.
pub fn output_names(coupling: &Coupling) -> Vec<String> {
    coupling
        .scene
        .evaluation_points
        .iter()
        .flat_map(|p| COMPONENTS.iter().map(move |c| format!("{}/{c}", p.name)))
        .collect()
}

/// Run this shard's samples of one scene. `tick` is called once per finished sample.
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
    if !opts.variation.friction && opts.variation.start.is_none() {
        return Err(RunError::Options {
            file,
            reason: "the study varies nothing: vary friction, the start pose, or both".into(),
        });
    }
    if opts.variation.start.is_some() && !matches!(opts.method, Method::Dynamic(_)) {
        return Err(RunError::Options {
            file,
            reason: "a varied start pose needs the dynamic solver (--solver dynamic)".into(),
        });
    }
    let design = design_for(coupling, opts).map_err(design_err)?;
    let range = opts.shard.range(design.n).map_err(design_err)?;
    let rows = design.range(range.clone()).map_err(design_err)?;
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
        .map_err(|e| seat_err(usize::MAX, &nominal_mu, e))?;
    let points: Vec<_> = coupling
        .scene
        .evaluation_points
        .iter()
        .map(|p| p.position)
        .collect();
    let records = range
        .into_par_iter()
        .zip(rows.into_par_iter())
        .map(|(index, row)| {
            let (mu, start) = opts.variation.map(coupling, &row);
            let s = opts
                .method
                .seat(coupling, &mu, &start)
                .map_err(|e| seat_err(index, &mu, e))?;
            let outputs = points
                .iter()
                .flat_map(|p| PointPose::between(&nominal.pose, &s.pose, p).evaluated())
                .collect();
            tick();
            Ok(SampleRecord {
                index,
                inputs: row,
                outputs,
            })
        })
        .collect::<Result<Vec<_>, RunError>>()?;
    Ok(VariantRun {
        design,
        shard: opts.shard,
        output_names: output_names(coupling),
        records,
    })
}
