//! Seating the Saltelli matrices of a study ([`super::sobol::saltelli_rows`]) with the
//! study's solver and variation: the model evaluations behind its Sobol indices.

use super::super::runner::{
    RunError, StudyOptions, design_for, evaluate_rows, recorded_output_names,
};
use super::sobol::{SobolRun, saltelli_rows};
use crate::assembly::Coupling;

/// Seat the coupling once per row of the Saltelli matrices of base size `base_samples` over the
/// study's inputs (`opts.variation`), seeded with the study's seed. `tick` once per row.
pub fn run_sobol(
    coupling: &Coupling,
    opts: &StudyOptions,
    base_samples: usize,
    tick: &(dyn Fn() + Sync),
) -> Result<SobolRun, RunError> {
    let file = coupling.scene.file.clone();
    let design_err = |source| RunError::Design {
        file: file.clone(),
        source,
    };
    let spec = design_for(coupling, opts).map_err(design_err)?;
    let rows = saltelli_rows(spec.dims, base_samples, spec.seed).map_err(design_err)?;
    let mut records = evaluate_rows(coupling, opts, rows.into_iter().enumerate().collect(), tick)?;
    records.sort_by_key(|r| r.index);
    let failed = records.iter().filter(|r| !r.centred()).count();
    if failed > 0 {
        return Err(RunError::Options {
            file,
            reason: format!(
                "--sensitivity: {failed} of the {} Saltelli seatings did not centre; the Sobol indices need every seating (narrow --offset-bounds/--tilt-bounds or drop --sensitivity)",
                records.len()
            ),
        });
    }
    Ok(SobolRun {
        base_samples,
        seed: spec.seed,
        dims: spec.dims,
        output_names: recorded_output_names(coupling, &opts.variation),
        outputs: records.into_iter().map(|r| r.outputs).collect(),
    })
}
