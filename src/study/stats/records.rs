//! Per-sample records, shard files, and merging shards back into one study.
//!
//! A shard file holds the design it belongs to ([`DesignSpec`]: sampler, dims, n, seed), its
//! shard (`i/N`), the names of the output quantities and one [`SampleRecord`] per sample it
//! computed. [`merge`] concatenates the records of all shard files, sorts them by sample index
//! and checks that they form exactly the samples 0..n of one design: statistics recomputed from
//! the merged records are those of a single run (the same values in the same order).
//!
//! Bit-exactness needs a lossless file format: with serde_json enable its `float_roundtrip`
//! feature, otherwise parsing may change the last bit of an f64 (observed in this crate's tests).

use serde::{Deserialize, Serialize};

use super::super::error::{Result, StudyError};
use super::super::sampling::shard::Shard;
use super::super::sampling::{DesignSpec, validate};

/// Inputs (design coordinates in [0, 1]) and outputs of one sample.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SampleRecord {
    /// Row of the design, 0-based.
    pub index: usize,
    /// Design coordinates of this row (unit hypercube, before mapping to physical ranges).
    pub inputs: Vec<f64>,
    /// One value per output quantity, in the order of the file's `output_names`.
    pub outputs: Vec<f64>,
}

impl SampleRecord {
    /// A sample whose seating did not centre (varied start): no outputs.
    pub fn not_centred(index: usize, inputs: Vec<f64>) -> Self {
        SampleRecord { index, inputs, outputs: Vec::new() }
    }

    /// False for a seating that did not centre.
    pub fn centred(&self) -> bool {
        !self.outputs.is_empty()
    }
}

/// What one shard (one batch job) writes.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ShardFile {
    pub design: DesignSpec,
    pub shard: Shard,
    pub output_names: Vec<String>,
    pub records: Vec<SampleRecord>,
}

/// A complete study: all records 0..n of one design, sorted by index.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct MergedStudy {
    pub design: DesignSpec,
    pub output_names: Vec<String>,
    pub records: Vec<SampleRecord>,
}

impl ShardFile {
    /// Checks the file on its own: valid design and shard, record shapes, indices inside the
    /// shard's range.
    pub fn check(&self) -> Result<()> {
        let d = &self.design;
        validate(d.sampler, d.dims, d.n)?;
        let range = Shard::new(self.shard.index, self.shard.count)?.range(d.n)?;
        for r in &self.records {
            if !range.contains(&r.index) {
                return Err(StudyError::IndexOutOfRange {
                    index: r.index,
                    what: format!("shard {} ({}..{})", self.shard, range.start, range.end),
                });
            }
            if r.inputs.len() != d.dims {
                return Err(StudyError::RecordShape {
                    index: r.index,
                    what: format!("{} inputs, design has {} dims", r.inputs.len(), d.dims),
                });
            }
            if r.centred() && r.outputs.len() != self.output_names.len() {
                return Err(StudyError::RecordShape {
                    index: r.index,
                    what: format!(
                        "{} outputs, file names {}",
                        r.outputs.len(),
                        self.output_names.len()
                    ),
                });
            }
        }
        Ok(())
    }
}

/// Merges shard files (in any order) into one study.
///
/// Errors when there is no file, files disagree in design or output names, a file fails
/// [`ShardFile::check`], a sample index appears twice, or samples are missing.
pub fn merge(shards: impl IntoIterator<Item = ShardFile>) -> Result<MergedStudy> {
    let mut iter = shards.into_iter();
    let first = iter.next().ok_or(StudyError::EmptyMerge)?;
    first.check()?;
    let design = first.design;
    let output_names = first.output_names;
    let mut records = first.records;
    for file in iter {
        if file.design != design {
            return Err(StudyError::DesignMismatch(format!("{:?} vs {:?}", file.design, design)));
        }
        if file.output_names != output_names {
            return Err(StudyError::DesignMismatch(format!(
                "outputs {:?} vs {:?}",
                file.output_names, output_names
            )));
        }
        file.check()?;
        records.extend(file.records);
    }
    records.sort_by_key(|r| r.index);
    if let Some(w) = records.windows(2).find(|w| w[0].index == w[1].index) {
        return Err(StudyError::DuplicateSample(w[0].index));
    }
    if records.len() != design.n {
        let first_missing = records
            .iter()
            .enumerate()
            .find(|(i, r)| r.index != *i)
            .map_or(records.len(), |(i, _)| i);
        return Err(StudyError::MissingSamples {
            first: first_missing,
            count: design.n - records.len(),
        });
    }
    Ok(MergedStudy { design, output_names, records })
}

/// Regenerates the design and checks that every stored input row equals it exactly
/// (catches files written by another version of the samplers).
pub fn verify_inputs(study: &MergedStudy) -> Result<()> {
    let rows = study.design.rows()?;
    for r in &study.records {
        let expected = rows
            .get(r.index)
            .ok_or(StudyError::IndexOutOfRange { index: r.index, what: "design".into() })?;
        let same = expected.len() == r.inputs.len()
            && expected.iter().zip(&r.inputs).all(|(a, b)| a.to_bits() == b.to_bits());
        if !same {
            return Err(StudyError::InputsMismatch(r.index));
        }
    }
    Ok(())
}
