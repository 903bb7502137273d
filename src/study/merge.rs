//! `kinrepro merge`: shard parts of one study back into the document of one
//! run. Parts must carry the current output schema and equal study
//! fingerprints ([`Fingerprint`]); a refusal names the part and the field
//! that differs, or the shards (and their sample ranges) that are missing.
//! The statistics are recomputed from the records sorted by sample index, so
//! the merged result equals the one of a single run.

use thiserror::Error;

use super::provenance::{Fingerprint, READABLE_SCHEMAS, SCHEMA_VERSION};
use super::record::StudyRecord;
use super::result::{StudyReport, VariantReport};
use super::stats::{ShardFile, merge, verify_inputs};
use super::{Shard, StudyError};

/// Why parts could not be merged (one line each).
#[derive(Debug, Error)]
pub enum MergeError {
    #[error("no parts to merge")]
    Empty,
    #[error(
        "{file}: output schema {found}, this kinrepro reads schemas {} to {SCHEMA_VERSION} (re-run the shard with this version)",
        READABLE_SCHEMAS.start()
    )]
    Schema { file: String, found: u32 },
    #[error("{file}: holds {found} scene(s), {first} holds {expected}: not parts of one study")]
    VariantCount { file: String, first: String, found: usize, expected: usize },
    #[error(
        "{file}: its study fingerprint is of version {found} ({first} has version {expected}): \
         parts written by kinrepro releases with different fingerprints do not merge (re-run \
         the shards with one version)"
    )]
    FingerprintVersion { file: String, first: String, found: u32, expected: u32 },
    #[error("{file}: not a part of the study of {first}: {scene}: {field} differs")]
    Fingerprint { file: String, first: String, scene: String, field: String },
    #[error("{file}: shard {shard} of {count} shards, {first} has {expected} shards")]
    ShardCount { file: String, first: String, shard: Shard, count: usize, expected: usize },
    #[error("{file}: shard {shard} is also in {other}")]
    DuplicateShard { file: String, other: String, shard: Shard },
    #[error("{file}: invalid shard {shard}")]
    BadShard { file: String, shard: Shard },
    #[error("{0} missing")]
    MissingShards(String),
    /// A part that no study could have written.
    #[error("{file}: {source}")]
    Invalid {
        file: String,
        #[source]
        source: super::validate::DocumentError,
    },
    #[error("{scene}: {source}")]
    Records {
        scene: String,
        #[source]
        source: StudyError,
    },
}

/// Merge named parts (file name, document) in any order.
pub fn merge_parts(parts: Vec<(String, StudyReport)>) -> Result<StudyReport, MergeError> {
    let (first_file, first) = parts.first().ok_or(MergeError::Empty)?;
    for (file, p) in &parts {
        if !READABLE_SCHEMAS.contains(&p.schema_version) {
            return Err(MergeError::Schema { file: file.clone(), found: p.schema_version });
        }
        super::validate::check_document(p)
            .map_err(|source| MergeError::Invalid { file: file.clone(), source })?;
        check_same_study(first_file, first, file, p)?;
    }
    let shards: Vec<(&str, Shard)> = parts.iter().map(|(f, p)| (f.as_str(), p.shard)).collect();
    let n = first.variants.first().map_or(0, |v| v.samples);
    check_shards(&shards, n, ("samples", 0))?;
    let mut variants = Vec::new();
    for (j, proto) in first.variants.iter().enumerate() {
        let mine: Vec<&VariantReport> = parts.iter().map(|(_, p)| &p.variants[j]).collect();
        variants.push(
            merge_variant(proto, &mine)
                .map_err(|source| MergeError::Records { scene: proto.scene.clone(), source })?,
        );
    }
    Ok(StudyReport::new(variants, Shard::whole()))
}

/// Same number of variants and equal fingerprints, variant by variant.
fn check_same_study(
    first_file: &str,
    first: &StudyReport,
    file: &str,
    p: &StudyReport,
) -> Result<(), MergeError> {
    if p.variants.len() != first.variants.len() {
        return Err(MergeError::VariantCount {
            file: file.to_string(),
            first: first_file.to_string(),
            found: p.variants.len(),
            expected: first.variants.len(),
        });
    }
    for (a, b) in first.variants.iter().zip(&p.variants) {
        let fa: &Fingerprint = &a.fingerprint;
        let (expected, found) = (fa.fingerprint_version, b.fingerprint.fingerprint_version);
        if found != expected {
            return Err(MergeError::FingerprintVersion {
                file: file.to_string(),
                first: first_file.to_string(),
                found,
                expected,
            });
        }
        if let Some(field) = fa.first_difference(&b.fingerprint) {
            return Err(MergeError::Fingerprint {
                file: file.to_string(),
                first: first_file.to_string(),
                scene: b.scene.clone(),
                field,
            });
        }
    }
    Ok(())
}

/// Every shard 1..=N exactly once, N the same in every part (file name and
/// shard); a missing shard is named with its range of the `n` `unit`
/// (`samples` of a study, `design points` of a sweep: numbered from 0;
/// `searches` of an optimisation: from 1), `(unit, first number)`.
pub fn check_shards(
    parts: &[(&str, Shard)],
    n: usize,
    (unit, origin): (&str, usize),
) -> Result<(), MergeError> {
    let Some(&(first_file, first)) = parts.first() else {
        return Err(MergeError::Empty);
    };
    let count = first.count;
    let mut seen: Vec<Option<&str>> = vec![None; count];
    for &(file, shard) in parts {
        if shard.count != count {
            return Err(MergeError::ShardCount {
                file: file.to_string(),
                first: first_file.to_string(),
                shard,
                count: shard.count,
                expected: count,
            });
        }
        if shard.index == 0 || shard.index > count {
            return Err(MergeError::BadShard { file: file.to_string(), shard });
        }
        let slot = &mut seen[shard.index - 1];
        if let Some(other) = slot {
            return Err(MergeError::DuplicateShard {
                file: file.to_string(),
                other: other.to_string(),
                shard,
            });
        }
        *slot = Some(file);
    }
    let missing: Vec<String> = (1..=count)
        .filter(|i| seen[i - 1].is_none())
        .map(|i| {
            let s = Shard { index: i, count };
            match s.range(n) {
                Ok(r) if !r.is_empty() => {
                    format!("shard {s} ({unit} {}..{})", r.start + origin, r.end - 1 + origin)
                }
                _ => format!("shard {s} (no {unit})"),
            }
        })
        .collect();
    if missing.is_empty() { Ok(()) } else { Err(MergeError::MissingShards(missing.join(", "))) }
}

/// The records of one variant from every part, checked against the
/// regenerated design, with the statistics recomputed.
fn merge_variant(
    proto: &VariantReport,
    parts: &[&VariantReport],
) -> Result<VariantReport, StudyError> {
    let files: Vec<ShardFile> = parts
        .iter()
        .map(|v| ShardFile {
            design: v.design,
            shard: v.shard,
            output_names: v.output_names.clone(),
            records: v.records.iter().map(StudyRecord::sample).collect(),
        })
        .collect();
    let merged = merge(files)?;
    verify_inputs(&merged)?;
    let mut records: Vec<StudyRecord> = parts.iter().flat_map(|v| v.records.clone()).collect();
    records.sort_by_key(|r| r.index);
    let mut v = proto.clone();
    v.partial = false;
    v.shard = Shard::whole();
    v.records = records;
    v.cannot_seat = parts.iter().find_map(|p| p.cannot_seat.clone());
    v.seating_paths = super::paths::SeatingPaths::total(parts.iter().map(|p| p.seating_paths));
    v.load_path = super::paths::LoadPath::total(parts.iter().map(|p| p.load_path));
    v.finish()?;
    Ok(v)
}
