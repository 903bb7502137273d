//! Reproducibility studies: sampling designs over the varied inputs, the seatings of every
//! sample, the study document with its statistics (the numbers every output renders) and
//! merging of sharded runs; `report` renders them (text, CSV, SVG, HTML).
//!
//! * [`options`]: a study's options as the CLI and the Python package give them
//!   ([`StudyOptions`]), checked in one place into the [`options::Settings`] of a run;
//!   [`plan`]: the [`StudyPlan`], every scene's coupling, design and shard of samples, checked
//!   and bounded once; [`document`]: a plan run into one [`StudyReport`]; [`runner`]: one
//!   scene's seatings; [`stream`]: large Monte Carlo studies in bounded memory.
//! * [`result`], [`record`]: the document's types ([`StudyReport`], [`VariantReport`],
//!   [`PointStats`], [`StudyRecord`]); [`summary`]: their statistics; [`merge`]: shard parts
//!   into one document; [`provenance`]: schema version and the fingerprint of a study.
//! * [`sampling`]: optimised Latin hypercube (replicated: r independent LHS of n/r points),
//!   plain Monte Carlo and full-factorial corners over [0, 1]^d, each a pure function of
//!   `(sampler, dims, n, seed, replicates)`; shard ranges.
//! * [`stats`]: mean, min, max, sigma, 3 sigma, an interval of sigma valid for the design
//!   (replicated LHS: t on the replicates; Monte Carlo: Bonett's kurtosis-adjusted interval,
//!   also from streamed moments; corners: none), convergence of sigma, per-sample records and
//!   shard merging.
//! * [`sensitivity`]: SRC shares (linear regression) and first-order and total Sobol indices
//!   (Saltelli matrices seated with [`runner::evaluate_rows`]) with bootstrap intervals.
//!
//! # Scaling out with shards
//!
//! A study of n samples is split into N contiguous, balanced shards
//! ([`sampling::shard::shard_range`], 1-based `--shard i/N`). Every shard regenerates the same
//! design from `(sampler, dims, n, seed)` — Monte Carlo rows are computed individually from
//! `(seed, index)`, an LHS design is recomputed whole (milliseconds) and sliced — evaluates only
//! its rows, and writes its [`StudyReport`] carrying the design spec, its shard and one record
//! per sample. No communication between shards is needed, so they map directly onto a
//! batch scheduler's job array, e.g. Slurm:
//!
//! ```text
//! #SBATCH --array=1-16
//! N=16
//! kinrepro study SCENE --sampler lhs --samples 400 --seed 7 \
//!     --shard $SLURM_ARRAY_TASK_ID/$N --format json > part_$SLURM_ARRAY_TASK_ID.json
//! # afterwards (e.g. a job with --dependency=afterok:<array job id>):
//! kinrepro merge part_*.json
//! ```
//!
//! `merge` ([`merge::merge_parts`], [`stats::merge`]) checks that all parts share one design and
//! output list and that the sample indices 0..n appear exactly once, sorts the records by index
//! and recomputes the statistics, so the merged result is the one of a single run. A failed
//! array task is simply re-run with the same `--shard`.

pub mod assessment;
pub mod bounds;
pub mod document;
pub mod error;
pub mod inputs;
pub mod merge;
pub mod options;
pub mod paths;
pub mod plan;
mod progress;
pub mod provenance;
pub mod record;
pub mod result;
mod rng;
mod rows;
pub mod runner;
pub mod sampling;
pub mod sensitivity;
pub mod stats;
pub mod stream;
pub mod summary;
pub mod validate;
pub mod variant;
pub mod variation;
pub mod verdict;

pub use error::{Result, StudyError};
pub use options::{StudyOptions, Varied};
pub use plan::StudyPlan;
pub use record::{Dofs, PointStats, StudyRecord};
pub use result::{StudyDocument, StudyReport, VariantReport};
pub use sampling::shard::{Shard, shard_range};
pub use sampling::{DesignSpec, Sampler, design, sample_range};
pub use variant::Variant;
