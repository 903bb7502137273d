//! Seating the Saltelli matrices of a study ([`super::sobol::saltelli_rows`]) with the
//! study's solver and variation: the model evaluations behind its Sobol indices.

use super::super::StudyError;
use super::super::options::Settings;
use super::super::runner::{evaluate_rows, recorded_output_names};
use super::super::variant::Variant;
use super::sobol::{SobolRun, saltelli_rows};
use crate::param::{Param, ParamError};

/// Seat the coupling once per row of the Saltelli matrices of base size `base_samples` over the
/// study's inputs (`s.variation`), seeded with the study's seed. `tick` once per row.
pub fn run_sobol(
    s: &Settings,
    v: &Variant,
    base_samples: usize,
    tick: &(dyn Fn() + Sync),
) -> Result<SobolRun, StudyError> {
    let spec = v.design;
    let rows =
        saltelli_rows(spec.dims, base_samples, spec.seed).map_err(|e| e.in_file(v.file()))?;
    let mut records = evaluate_rows(s, v, rows.into_iter().enumerate().collect(), tick)?;
    records.sort_by_key(|r| r.index);
    let failed = records.iter().filter(|r| !r.centred()).count();
    if failed > 0 {
        let p = Param::Sensitivity;
        return Err(StudyError::from(ParamError::new(
            p,
            format!(
                "{p}: {failed} of the {} Saltelli seatings did not centre; the Sobol indices need every seating (narrow {}/{} or drop {p})",
                records.len(),
                Param::OffsetBounds,
                Param::TiltBounds
            ),
        ))
        .in_file(v.file()));
    }
    Ok(SobolRun {
        base_samples,
        seed: spec.seed,
        dims: spec.dims,
        output_names: recorded_output_names(&v.scene, &s.variation),
        outputs: records.into_iter().map(|r| r.outputs).collect(),
    })
}
