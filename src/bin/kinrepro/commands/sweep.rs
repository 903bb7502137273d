//! `kinrepro sweep`: reproducibility, stiffness and safety over a grid or
//! an LHS of scene fields (library: `explore`; output: `report::sweep_text`, `report::sweep_plot`).

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use kinrepro::explore::run::run;
use kinrepro::explore::{DesignKind, SweepSpec};
use kinrepro::explore::{SweepReport, merge_sweeps};
use kinrepro::study::runner::{StudyOptions, Variation};
use kinrepro::study::{Sampler, Shard};

use super::*;
use crate::args::Format;
use crate::error::{CliError, Context};

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum DesignArg {
    /// Every combination of the --set values.
    Grid,
    /// A space-filling Latin hypercube of --points points over the ranges.
    Lhs,
}

#[derive(Args)]
pub struct SweepArgs {
    /// The high-level scene file (TOML) whose fields are swept.
    pub scene: PathBuf,
    /// FIELD=VALUES: a scene field by its TOML path (e.g. preload.force,
    /// coupling.opening_angle_deg, coupling.groove_material,
    /// materials.NAME.youngs_modulus) and its values: a list 5,10,20, a
    /// range a:b:count, log:a:b:count, or material names. Repeatable.
    #[arg(long = "set", required = true)]
    pub sets: Vec<String>,
    /// grid (every combination) | lhs (--points N, space-filling).
    #[arg(long, value_enum, default_value_t = DesignArg::Grid)]
    pub design: DesignArg,
    /// Design points of an LHS design.
    #[arg(long)]
    pub points: Option<usize>,
    /// Evaluation point whose largest translational sigma is the Pareto
    /// objective (default: the scene's first).
    #[arg(long)]
    pub pareto_point: Option<String>,
    /// Samples per design point (default: the scene's [study] samples).
    #[arg(long)]
    pub samples: Option<usize>,
    /// lhs | mc | corners: the study design of every point.
    #[arg(long)]
    pub sampler: Option<Sampler>,
    /// Seed of the study design (the same for every point) and of an LHS sweep design.
    #[arg(long)]
    pub seed: Option<u64>,
    /// LHS replicates of each point's study (see `study --replicates`).
    #[arg(long)]
    pub replicates: Option<usize>,
    /// Nominal number of load increments per seating, 1..=100000.
    #[arg(long, default_value_t = 20)]
    pub increments: usize,
    /// Worker threads (capped at 4 per core).
    #[arg(long)]
    pub jobs: Option<usize>,
    /// table (nm, nrad) | csv (SI, long format) | json (docs/output.md).
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
    /// Write the SVG design charts into this directory.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Write the design charts as one self-contained HTML report
    /// (inline SVG, no network).
    #[arg(long)]
    pub html: Option<PathBuf>,
    /// Replace existing files of --out and --html.
    #[arg(long)]
    pub force: bool,
    /// Evaluate only shard I of N of the design points; merge the JSON
    /// parts with `kinrepro merge`.
    #[arg(long)]
    pub shard: Option<Shard>,
}

pub fn sweep(args: SweepArgs) -> Result<(), CliError> {
    let file = args.scene.display().to_string();
    let text = std::fs::read_to_string(&args.scene)
        .map_err(|e| CliError::file(&file, "cannot read: ", e))?;
    let base = kinrepro::scene::Scene::parse(&text, &file)?;
    let base = kinrepro::assembly::Coupling::new(&base).context(&file)?;
    check_increments(args.increments)?;
    if args.sampler == Some(Sampler::Corners) && args.samples.is_some() {
        return Err(CliError::Usage(
            "--samples does not apply to --sampler corners: the corner design has all 2^d extremes"
                .into(),
        ));
    }
    let opts = StudyOptions {
        sampler: args.sampler,
        samples: args.samples,
        seed: args.seed,
        shard: args.shard.unwrap_or_else(Shard::whole),
        method: kinrepro::solve::Method::QuasiStatic(kinrepro::solve::SolverOptions {
            increments: args.increments,
            ..Default::default()
        }),
        variation: Variation {
            friction: true,
            ..Default::default()
        },
        sensitivity: false,
        replicates: args.replicates,
    };
    let design = match (args.design, args.points) {
        (DesignArg::Grid, None) => DesignKind::Grid,
        (DesignArg::Grid, Some(_)) => {
            return Err(CliError::Usage("--points needs --design lhs".into()));
        }
        (DesignArg::Lhs, None) => {
            return Err(CliError::Usage("--design lhs needs --points N".into()));
        }
        (DesignArg::Lhs, Some(points)) => DesignKind::Lhs {
            points,
            seed: args.seed.unwrap_or(base.scene.study.seed),
        },
    };
    let spec = SweepSpec::new(&file, &text, &args.sets, design)?;
    // One tick per seated sample (points that cannot seat tick none).
    let points = spec.points()?.len();
    let samples = kinrepro::study::runner::design_for(&base, &opts)
        .context(&file)?
        .n;
    let share = opts.shard.range(points).context("--shard")?.len();
    set_jobs(args.jobs, share * samples)?;
    let bar = super::study::progress(share * samples)?;
    let report = run(&spec, &base, &opts, args.pareto_point.as_deref(), &|| {
        bar.inc(1)
    })?;
    bar.finish_and_clear();
    print_sweep(&report, args.format)?;
    if let Some(dir) = &args.out {
        for f in kinrepro::report::sweep_plot::write_charts(&report, dir, args.force)? {
            eprintln!("wrote {f}");
        }
    }
    if let Some(path) = &args.html {
        super::report::sweep_html(&report, path, args.force)?;
    }
    Ok(())
}

pub fn print_sweep(report: &SweepReport, format: Format) -> Result<(), CliError> {
    match format {
        Format::Table => emit(&report.table()),
        Format::Csv => emit(&report.csv()),
        Format::Json => print_json(report),
    }
}

/// `kinrepro merge` of sweep parts (JSON documents with `"document":
/// "sweep"`); `first`: the first part's text, already read.
pub fn merge(parts: &[PathBuf], first: Option<String>, format: Format) -> Result<(), CliError> {
    let docs = read_json_parts::<SweepReport>(parts, first, "sweep")?;
    let merged = merge_sweeps(docs)?;
    print_sweep(&merged, format)
}

/// True if a JSON text is a sweep document (`"document": "sweep"`); only
/// that field is read, the rest is skipped without building a tree.
pub fn is_sweep(text: &str) -> bool {
    #[derive(serde::Deserialize)]
    struct Document {
        #[serde(default)]
        document: Option<String>,
    }
    serde_json::from_str::<Document>(text).is_ok_and(|d| d.document.as_deref() == Some("sweep"))
}
