//! Running a reproducibility study of one scene: draw the design, seat the
//! coupling once per sample (rayon across samples), and record the pose of
//! every evaluation point relative to the nominal-mu seating.
//!
//! Sample i uses mu_s,k = mu0 + spread (2 u_ik - 1) for contact k, where u_i
//! is row i of the design on [0, 1]^6 (MODEL.md §4, rectangular
//! distribution). Its values depend only on (sampler, n, seed, i), so shards
//! of the sample range computed anywhere merge into exactly one run.

use rayon::prelude::*;
use thiserror::Error;

use super::StudyError;
use super::stats::SampleRecord;
use super::{DesignSpec, Sampler, Shard};
use crate::assembly::Coupling;
use crate::solve::quasistatic::seat;
use crate::solve::{PointPose, SolveError, SolverOptions, nominal_mu};

/// Output components per evaluation point (relative to the nominal seating, SI).
pub const COMPONENTS: [&str; 5] = ["x_m", "y_m", "z_m", "phi_x_rad", "phi_y_rad"];

/// How to run a study; `None` takes the scene's study settings.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StudyOptions {
    pub sampler: Option<Sampler>,
    pub samples: Option<usize>,
    pub seed: Option<u64>,
    pub shard: Shard,
    pub solver: SolverOptions,
}

impl Default for StudyOptions {
    fn default() -> Self {
        StudyOptions {
            sampler: None,
            samples: None,
            seed: None,
            shard: Shard::whole(),
            solver: SolverOptions::default(),
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
    DesignSpec::new(
        sampler,
        coupling.contacts.len(),
        n,
        opts.seed.unwrap_or(st.seed),
    )
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
    let nominal = seat(coupling, &nominal_mu, &opts.solver)
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
            let mu = mu_of_row(coupling, &row);
            let s = seat(coupling, &mu, &opts.solver).map_err(|e| seat_err(index, &mu, e))?;
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
