//! `kinrepro optimize`: the best design within bounds on one objective
//! under constraints (library: `explore::optimize`; output:
//! `report::optimize`).

use std::io::Write;
use std::path::{Path, PathBuf};

use kinrepro::explore::goal::Goals;
use kinrepro::explore::optimize::{
    OptimizeReport, OptimizeSpec, merge_optimizations, optimize as run,
};
use kinrepro::explore::run::study_plan;
use kinrepro::output::atomic::AtomicFile;
use kinrepro::study::{Shard, StudyOptions};

use super::{emit, print_json, read_json_parts, read_text, set_jobs};
use crate::error::{Error, Result};
use crate::flags::groups::TextFormat;
use crate::flags::{Format, OptimizeArgs};

pub fn optimize(a: OptimizeArgs) -> Result {
    let file = a.scene.display().to_string();
    let text = read_text(&a.scene)?;
    let (scene, coupling) = kinrepro::error::parse_scene(&text, &file)?;
    let varied: Vec<String> = a
        .vary
        .iter()
        .filter_map(|v| v.split_once('=').map(|(p, _)| p.trim().to_string()))
        .collect();
    let mut spec = OptimizeSpec::new(&file, &text, &a.vary, Goals::default(), a.max_iterations)?;
    spec.starts = a.starts;
    spec.shard = a.shard.unwrap_or_else(Shard::whole);
    let objectives: Vec<String> = a.objective.iter().cloned().collect();
    let asked = (objectives.as_slice(), a.constraint.as_slice());
    spec.goals =
        Goals::asked(asked, (&spec.base, &file, &text), &scene, &varied).map_err(|e| match e {
            kinrepro::explore::ExploreError::Goal(g) => Error::new(format!("{file}: {g}")),
            e => e.into(),
        })?;
    let options = StudyOptions {
        sampler: a.study.sampler,
        samples: a.study.samples,
        seed: a.study.seed,
        replicates: a.study.replicates,
        increments: a.path.increments,
        path_tolerance: a.path.path_tolerance,
        ..StudyOptions::default()
    };
    let plan = study_plan(scene, coupling, &options)?;
    set_jobs(a.jobs, plan.variants[0].design.n)?;
    let report = run(&spec, &plan, &|| {})?;
    if kinrepro::cancel::requested() {
        return Err(Error::new("interrupted"));
    }
    print_optimization(&report, a.json, a.format, a.html.as_deref(), a.force, &text)?;
    if report.optimum.is_none() && report.shard == Shard::whole() {
        return Err(no_feasible_design(&report));
    }
    Ok(())
}

/// `kinrepro merge` of optimisation parts (`"document": "optimize"`);
/// `first`: the first part's text, already read.
pub fn merge(parts: &[PathBuf], first: String, format: Format) -> Result {
    let json = match format {
        Format::Json => true,
        Format::Table => false,
        Format::Csv => {
            return Err(Error::new(
                "merge: an optimisation has no CSV form: give --format table or json",
            ));
        }
    };
    let docs = read_json_parts::<OptimizeReport>(parts, first, "optimize")?;
    let merged = merge_optimizations(docs).map_err(|e| Error::new(format!("merge: {e}")))?;
    print_optimization(&merged, json, TextFormat::Table, None, false, "")?;
    match merged.optimum {
        None => Err(no_feasible_design(&merged)),
        Some(_) => Ok(()),
    }
}

fn no_feasible_design(report: &OptimizeReport) -> Error {
    Error::new(format!(
        "{}: no feasible design: none of the {} candidates meets every constraint",
        report.scene,
        report.history.len()
    ))
}

/// The document as a table or JSON on stdout, and its HTML page.
fn print_optimization(
    report: &OptimizeReport,
    json: bool,
    format: TextFormat,
    html: Option<&Path>,
    force: bool,
    text: &str,
) -> Result {
    match (json, format) {
        (true, _) | (_, TextFormat::Json) => print_json(&report)?,
        _ => emit(&report.table())?,
    }
    if let Some(path) = html {
        let html = kinrepro::report::html::optimize::optimize_html(report, text)?;
        let mut f = AtomicFile::create(path, force)?;
        f.write_all(html.as_bytes()).map_err(|e| Error::new(format!("{}: {e}", path.display())))?;
        for f in crate::signals::commit(vec![f])? {
            eprintln!("wrote {f}");
        }
    }
    Ok(())
}
