//! The error of the study module: designing, planning, running and
//! summarising a study (every bad input is reported, nothing panics).

use thiserror::Error;

use crate::assembly::AssemblyError;
use crate::param::{Param, ParamError};
use crate::solve::SolveError;

/// Everything that can go wrong while planning, running or summarising a
/// study; an error about one scene of it carries the scene file
/// ([`StudyError::In`]).
#[derive(Debug, Error)]
pub enum StudyError {
    /// A parameter out of range, or parameters that do not go together.
    #[error(transparent)]
    Param(#[from] ParamError),
    /// `source` about a bound of parameter `param`.
    #[error("{param}: {source}")]
    At {
        param: Param,
        #[source]
        source: Box<StudyError>,
    },
    /// `source` about the scene read from `file`.
    #[error("{file}: {source}")]
    In {
        file: String,
        #[source]
        source: Box<StudyError>,
    },
    /// A stop was asked for ([`crate::cancel`]).
    #[error("interrupted")]
    Cancelled,
    #[error(
        "sample {index}: the coupling perturbed by the drawn tolerances ([variation] {keys}) \
         does not assemble: {source}; a bound may reach beyond what the coupling can take"
    )]
    Perturbed {
        index: usize,
        /// The `[variation]` keys drawn, comma-separated.
        keys: Box<str>,
        #[source]
        source: AssemblyError,
    },
    #[error(
        "the nominal seating (the reference of every sample; mu_s = {mu:?}, touching start) failed: {source}"
    )]
    Nominal {
        mu: Vec<f64>,
        #[source]
        source: SolveError,
    },
    #[error(
        "the seating at mu_s = {mu:?} (touching start) that tells whether friction moves the \
         pose failed: {source}"
    )]
    FrictionProbe {
        mu: Vec<f64>,
        #[source]
        source: SolveError,
    },
    #[error("sample {index} (mu_s = {mu:?}{varied}): {source}")]
    Seating {
        index: usize,
        mu: Vec<f64>,
        /// Empty, or the `[variation]` keys this sample drew within:
        /// `; drawn within [variation] preload_offset, ...` and a hint.
        varied: Box<str>,
        #[source]
        source: Box<SolveError>,
    },
    /// The sink of a streamed study's records failed (e.g. its CSV file).
    #[error(transparent)]
    Sink(Box<dyn std::error::Error + Send + Sync>),
    /// A run size above its bound (`study::bounds`).
    #[error("{what} = {count} is above the bound of {max} (docs/output.md, Bounds)")]
    AboveBound { what: &'static str, count: String, max: usize },
    /// A design needs at least one input dimension.
    #[error("a design needs at least one dimension (dims = 0)")]
    ZeroDims,
    /// A design needs at least one sample.
    #[error("a design needs at least one sample (n = 0)")]
    ZeroSamples,
    /// Too many dimensions for a full-factorial corner design.
    #[error(
        "corner design with {dims} dimensions has 2^{dims} rows; at most {max} dimensions are allowed"
    )]
    TooManyCornerDims { dims: usize, max: usize },
    /// A corner design always has 2^dims rows.
    #[error(
        "corner design with {dims} dimensions has {expected} rows, but n = {got} was requested"
    )]
    CornerCount { dims: usize, expected: usize, got: usize },
    /// The optimised Latin hypercube keeps an n x n distance matrix.
    #[error("optimised Latin hypercube supports at most {max} samples (n = {n}); use Monte Carlo")]
    LhsTooLarge { n: usize, max: usize },
    /// A requested sample range does not lie inside 0..n.
    #[error("sample range {start}..{end} is not inside 0..{n}")]
    RangeOutOfBounds { start: usize, end: usize, n: usize },
    /// Shard index/count out of range (shards are 1-based: 1..=count).
    #[error("invalid shard {index}/{count}: need 1 <= index <= count")]
    InvalidShard { index: usize, count: usize },
    /// A `--shard` argument could not be parsed.
    #[error("cannot parse shard '{0}': expected INDEX/COUNT, e.g. 3/8")]
    ShardParse(String),
    /// Statistics need at least two samples.
    #[error("statistics need at least 2 samples, got {n}")]
    TooFewSamples { n: usize },
    /// NaN or infinity in data that must be finite.
    #[error("non-finite value in {what}")]
    NonFinite { what: String },
    /// Invalid parameter (bootstrap level, resample count, ...).
    #[error("invalid parameter: {0}")]
    InvalidParameter(String),
    /// Records disagree in their number of inputs or outputs.
    #[error("sample {index}: {what}")]
    RecordShape { index: usize, what: String },
    /// Nothing was given to merge.
    #[error("no shard files to merge")]
    EmptyMerge,
    /// Shard files were produced by different designs or output sets.
    #[error("shard files do not belong to the same study: {0}")]
    DesignMismatch(String),
    /// The same sample index appears twice.
    #[error("sample {0} appears more than once")]
    DuplicateSample(usize),
    /// Sample indices missing after a merge.
    #[error("{count} sample(s) missing, the first is {first}")]
    MissingSamples { first: usize, count: usize },
    /// A sample index lies outside its design or its shard.
    #[error("sample index {index} outside {what}")]
    IndexOutOfRange { index: usize, what: String },
    /// Stored inputs differ from the regenerated design.
    #[error("sample {0}: stored inputs differ from the regenerated design")]
    InputsMismatch(usize),
}

impl StudyError {
    /// This error about the scene read from `file`.
    pub fn in_file(self, file: &str) -> Self {
        StudyError::In { file: file.to_string(), source: Box::new(self) }
    }

    /// This error about a bound of parameter `param`.
    pub fn at(self, param: Param) -> Self {
        StudyError::At { param, source: Box::new(self) }
    }

    /// The error itself, without the scene file or parameter it is about.
    pub fn root(&self) -> &StudyError {
        match self {
            StudyError::In { source, .. } | StudyError::At { source, .. } => source.root(),
            e => e,
        }
    }

    /// The error of a record sink.
    pub fn sink(e: impl std::error::Error + Send + Sync + 'static) -> Self {
        StudyError::Sink(Box::new(e))
    }
}

pub type Result<T> = std::result::Result<T, StudyError>;
