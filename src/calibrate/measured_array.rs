//! A cycles measurement given as numbers in SI rather than as a file (the
//! Python package's `calibrate` with an n x k array): one row per
//! re-seating cycle, one column per measured DOF, checked like the rows of
//! a cycles file ([`super::measurement`]).

use super::error::CalibrateError;
use super::measurement::{MIN_CYCLES, MeasuredData, Measurement, reading_out_of_range};
use crate::dof::Dof;

impl Measurement {
    /// The measurement `origin` (named so in messages, e.g. `measured
    /// array`) of `point` (None: the scene's first): `rows[i][j]` is cycle
    /// i's reading of `dofs[j]` in m or rad; `noise` per DOF [SI].
    pub fn from_cycles(
        origin: &str,
        point: Option<String>,
        dofs: &[Dof],
        rows: Vec<Vec<f64>>,
        noise: [Option<f64>; 6],
    ) -> Result<Measurement, CalibrateError> {
        let whole = |reason: String| CalibrateError::Array { origin: origin.to_string(), reason };
        if dofs.is_empty() {
            return Err(whole("no measured DOF column".into()));
        }
        if let Some((j, d)) = (dofs.iter().enumerate()).find(|(j, d)| dofs[..*j].contains(d)) {
            return Err(whole(format!("column {}: {} measured twice", j + 1, d.name())));
        }
        for (i, row) in rows.iter().enumerate() {
            if row.len() != dofs.len() {
                let r = format!("row {}: {} values for {} DOFs", i + 1, row.len(), dofs.len());
                return Err(whole(r));
            }
            for (v, d) in row.iter().zip(dofs) {
                let bad = if v.is_finite() {
                    reading_out_of_range(d.index(), *v)
                } else {
                    Some(format!("{v} is not a finite measured value"))
                };
                if let Some(r) = bad {
                    return Err(whole(format!("row {}, {}: {r}", i + 1, d.si_key())));
                }
            }
        }
        if rows.len() < MIN_CYCLES {
            let r =
                format!("{} cycle(s), need at least {MIN_CYCLES} re-seating cycles", rows.len());
            return Err(whole(r));
        }
        Ok(Measurement {
            file: origin.to_string(),
            point,
            dofs: dofs.iter().map(|d| d.index()).collect(),
            data: MeasuredData::Cycles(rows),
            noise,
            metadata: Vec::new(),
        })
    }
}
