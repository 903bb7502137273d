//! `kinrepro study` and `kinrepro merge`: reproducibility studies.

use std::path::PathBuf;

use kinrepro::report::study::files::{SamplesCsv, samples_file_name};
use kinrepro::study::{StudyOptions, StudyPlan, StudyReport};

use super::{
    check_jobs, force_needs_output, print_as, progress, read_json_parts, read_scene, read_text,
    set_jobs, vector3,
};
use crate::error::{Error, Result};
use crate::flags::groups::OutputFlags;
use crate::flags::{Format, MergeArgs, StudyArgs};

/// `kinrepro study`: the scenes, the library's study options, and what
/// the command does with the result.
pub struct Study {
    scenes: Vec<PathBuf>,
    options: StudyOptions,
    jobs: Option<usize>,
    output: OutputFlags,
    reference: Option<PathBuf>,
    allow_unseated: bool,
}

impl TryFrom<StudyArgs> for Study {
    type Error = Error;

    fn try_from(a: StudyArgs) -> Result<Study> {
        force_needs_output(a.output.force, [&a.output.out, &a.output.html])?;
        check_jobs(a.run.jobs)?;
        let triple = |flag: &str, v: Option<&[f64]>| {
            v.map(|v| vector3(flag, Some(v)).map(Into::into)).transpose()
        };
        let options = StudyOptions {
            solver: a.solver,
            vary: a.vary,
            offset_bounds: triple("offset-bounds", a.offset_bounds.as_deref())?,
            tilt_bounds: triple("tilt-bounds", a.tilt_bounds.as_deref())?,
            sensitivity: a.sensitivity,
            sobol_samples: a.sensitivity.then_some(a.sobol_samples),
            ..a.design.options(&a.path, &a.run)
        };
        Ok(Study {
            scenes: a.scenes,
            options,
            jobs: a.run.jobs,
            output: a.output,
            reference: a.reference,
            allow_unseated: a.allow_unseated,
        })
    }
}

pub fn study(s: Study) -> Result {
    let models = s.scenes.iter().map(|p| read_scene(p)).collect::<Result<Vec<_>>>()?;
    for (scene, coupling) in &models {
        for w in kinrepro::report::coupling::check::study_warnings(scene, coupling) {
            eprintln!("warning: {}: {w}", scene.file);
        }
    }
    let plan = StudyPlan::new(models, &s.options)?;
    set_jobs(s.jobs, plan.seatings)?;
    let bar = progress(plan.seatings, plan.method())?;
    let out = &s.output;
    // A streamed study writes its per-sample CSV as the samples arrive.
    let samples_dir = out.out.as_deref().filter(|_| plan.streamed());
    if let Some(dir) = samples_dir {
        std::fs::create_dir_all(dir)
            .map_err(|e| Error::new(format!("{}: cannot create the folder: {e}", dir.display())))?;
    }
    let (report, pending_csv) = plan.run(&|| bar.inc(1), |i, v| {
        samples_dir
            .map(|dir| SamplesCsv::create(&dir.join(samples_file_name(i, v)), v, out.force))
            .transpose()
    })?;
    bar.finish_and_clear();
    // Results first: a failed file write must not lose them.
    print_study(&report, out.format)?;
    for w in report.unconverged() {
        eprintln!("warning: {w}");
    }
    // Every file of --out under its temporary name, then all renamed at once.
    let mut staged = pending_csv
        .into_iter()
        .map(SamplesCsv::finish)
        .collect::<std::result::Result<Vec<_>, _>>()?;
    let streamed = staged.len();
    if let Some(dir) = &out.out {
        staged.extend(report.stage_files(dir, out.force, plan.streamed())?);
    }
    for f in crate::signals::commit(staged)?.iter().skip(streamed) {
        eprintln!("wrote {f}");
    }
    if let Some(path) = &out.html {
        super::report::study_html(&report, &plan, s.reference.as_deref(), path, out.force)?;
    }
    refuse_unseated(&report, s.allow_unseated)
}

fn print_study(report: &StudyReport, format: Format) -> Result {
    print_as(format, report, || report.table(), || report.csv())
}

/// A study whose coupling cannot seat fails unless `--allow-unseated`.
fn refuse_unseated(report: &StudyReport, allow: bool) -> Result {
    let bad = report.cannot_seat();
    if bad.is_empty() {
        return Ok(());
    }
    if allow {
        for b in &bad {
            eprintln!("warning: cannot seat: {b}");
        }
        return Ok(());
    }
    Err(Error::new(format!(
        "cannot seat: {} (pass --allow-unseated to accept this result)",
        bad.join("; ")
    )))
}

/// The `"document"` field of a JSON text (`sweep`, `optimize`; a study's
/// has none); only that field is read, the rest is skipped without
/// building a tree.
fn document_kind(text: &str) -> Option<String> {
    #[derive(serde::Deserialize)]
    struct Document {
        #[serde(default)]
        document: Option<String>,
    }
    serde_json::from_str::<Document>(text).ok().and_then(|d| d.document)
}

pub fn merge(args: MergeArgs) -> Result {
    let MergeArgs { parts, format, allow_unseated } = args;
    // The first part (clap asks for one at least) says which kind of
    // document is merged; it is read once.
    let first = read_text(&parts[0])?;
    match document_kind(&first).as_deref() {
        Some("sweep") => return super::sweep::merge(&parts, first, format),
        Some("optimize") => return super::optimize::merge(&parts, first, format),
        _ => {}
    }
    let docs = read_json_parts::<StudyReport>(&parts, first, "study")?;
    let merged =
        kinrepro::study::merge::merge_parts(docs).map_err(|e| Error::new(format!("merge: {e}")))?;
    print_study(&merged, format)?;
    refuse_unseated(&merged, allow_unseated)
}
