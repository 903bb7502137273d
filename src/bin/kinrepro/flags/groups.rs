//! Flag groups several verbs share (flattened into each, `#[command(flatten)]`),
//! and the fixed sets of names some flags take.

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use kinrepro::solve::quasistatic::Lanes;
use kinrepro::study::{Sampler, Shard, StudyOptions};

/// The design of each scene's study (`study`, `sweep`).
#[derive(Args)]
pub struct DesignFlags {
    /// Samples of each study (default: the scene's [study] samples; corners: 2^6).
    #[arg(long)]
    pub samples: Option<usize>,
    /// lhs (space-filling Latin hypercube) | mc (Monte Carlo) | corners (all 2^6 extremes).
    #[arg(long)]
    pub sampler: Option<Sampler>,
    /// Seed of the design (default: the scene's [study] seed; a sweep's LHS
    /// of design points takes it too).
    #[arg(long)]
    pub seed: Option<u64>,
    /// LHS: number of independent replicates the samples are split into
    /// (default 5, or the largest divisor of the samples in 2..=5); the
    /// interval of sigma comes from their spread. 1: a single LHS, no interval.
    #[arg(long)]
    pub replicates: Option<usize>,
}

/// The quasi-static solver's load path (`run`, `study`, `sweep`).
#[derive(Args)]
pub struct PathFlags {
    /// Fixed load increments per seating (quasi-static solver),
    /// 1..=100000, instead of the load-path error control.
    #[arg(long)]
    pub increments: Option<usize>,
    /// Load-path error control (quasi-static solver, the default): the
    /// tolerance on the estimated error of the seated pose relative to the
    /// seating's motion, 1e-9..=1e-2 [default: 1e-5]; excludes --increments.
    #[arg(long, allow_hyphen_values = true)]
    pub path_tolerance: Option<f64>,
}

/// Where a study or sweep runs: its shard and threads.
#[derive(Args)]
pub struct RunFlags {
    /// Run only shard I of N (1-based, e.g. 3/16): of a study's samples, of
    /// a sweep's design points; merge the JSON outputs with `kinrepro merge`.
    #[arg(long)]
    pub shard: Option<Shard>,
    /// Worker threads (default: all cores; capped at 4 per core and at the
    /// number of samples).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// Seat quasi-static samples four at a time in SIMD lanes: auto (where
    /// this build's lanes are faster: built for a CPU with AVX) | on |
    /// off. The results are the same bits either way.
    #[arg(long, value_enum, default_value_t = Lanes::Auto)]
    pub lanes: Lanes,
}

/// What a study or sweep writes.
#[derive(Args)]
pub struct OutputFlags {
    /// Output: table (nm, nrad) | csv (SI; a sweep's in long format) | json
    /// (docs/output.md: statistics in nm/nrad, samples in SI).
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
    /// Also write files into this directory: a study's per-sample CSV and
    /// SVG plots, a sweep's SVG design charts (existing files are refused,
    /// unless --force).
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Also write the self-contained HTML report to FILE (inline SVG, no
    /// network).
    #[arg(long)]
    pub html: Option<PathBuf>,
    /// Replace existing files of --out and --html.
    #[arg(long)]
    pub force: bool,
}

impl DesignFlags {
    /// These flags and `path`, `run` in the library's options (the rest at
    /// its defaults: friction varied, quasi-static).
    pub fn options(&self, path: &PathFlags, run: &RunFlags) -> StudyOptions {
        StudyOptions {
            sampler: self.sampler,
            samples: self.samples,
            seed: self.seed,
            replicates: self.replicates,
            shard: run.shard.unwrap_or_else(Shard::whole),
            increments: path.increments,
            path_tolerance: path.path_tolerance,
            lanes: run.lanes,
            ..StudyOptions::default()
        }
    }
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    Table,
    Csv,
    Json,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TextFormat {
    /// Human table (nm, nrad).
    Table,
    /// JSON (calibration: SI; predict: the study schema, nm and nrad).
    Json,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MeshKind {
    Default,
    Coarse,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum DesignArg {
    /// Every combination of the --set values.
    Grid,
    /// A space-filling Latin hypercube of --points points over the ranges.
    Lhs,
}
