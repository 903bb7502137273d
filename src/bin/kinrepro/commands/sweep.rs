//! `kinrepro sweep`: reproducibility, stiffness and safety over a grid or
//! an LHS of scene fields (library: `explore`; output: `report::sweep::text`, `report::sweep::plot`).

use std::path::PathBuf;

use kinrepro::explore::run::run;
use kinrepro::explore::{DesignKind, SweepReport, SweepSpec, merge_sweeps};

use super::*;
use crate::error::{CliError, Context};
use crate::flags::high::Checked;
use crate::flags::low::SweepArgs;
use kinrepro::study::runner::StudyOptions;

pub fn sweep(o: Checked<SweepArgs, StudyOptions>) -> Result<(), CliError> {
    let Checked { args: a, opts } = o;
    let file = a.scene.display().to_string();
    let text = read_text(&a.scene)?;
    let base = kinrepro::scene::Scene::parse(&text, &file)?;
    let base = kinrepro::assembly::Coupling::new(&base).context(&file)?;
    let design = DesignKind::new(a.points, opts.seed, &base);
    let spec = SweepSpec::new(&file, &text, &a.sets, design)?;
    // One tick per seated sample (points that cannot seat tick none).
    let points = spec.points()?.len();
    let samples = kinrepro::study::runner::design_for(&base, &opts)
        .context(&file)?
        .n;
    let share = opts.shard.range(points).context("--shard")?.len();
    let seatings = share.saturating_mul(samples);
    set_jobs(a.jobs, seatings)?;
    let bar = progress(seatings, &opts.method)?;
    let report = run(&spec, &base, &opts, a.pareto_point.as_deref(), &|| {
        bar.inc(1)
    })?;
    bar.finish_and_clear();
    print_sweep(&report, a.format)?;
    if let Some(dir) = &a.out {
        for f in kinrepro::report::sweep::plot::write_charts(&report, dir, a.force)? {
            eprintln!("wrote {f}");
        }
    }
    if let Some(path) = &a.html {
        super::report::sweep_html(&report, &text, &base, path, a.force)?;
    }
    // Exit 1 only when no design point was evaluated (all listed with their status).
    Ok(report.check_any_valid()?)
}

fn print_sweep(report: &SweepReport, format: Format) -> Result<(), CliError> {
    match format {
        Format::Table => emit(&report.table()),
        Format::Csv => emit(&report.csv()),
        Format::Json => print_json(report),
    }
}

/// `kinrepro merge` of sweep parts (JSON documents with `"document":
/// "sweep"`); `first`: the first part's text, already read.
pub fn merge(parts: &[PathBuf], first: String, format: Format) -> Result<(), CliError> {
    let docs = read_json_parts::<SweepReport>(parts, first, "sweep")?;
    let merged = merge_sweeps(docs)?;
    print_sweep(&merged, format)?;
    Ok(merged.check_any_valid()?)
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
