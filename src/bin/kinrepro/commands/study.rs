//! `kinrepro study` and `kinrepro merge`: reproducibility studies.

use kinrepro::report::study::files::{SamplesCsv, samples_file_name};
use kinrepro::study::{StudyPlan, StudyReport};

use super::*;
use crate::error::CliError;
use crate::flags::high::Checked;
use crate::flags::low::{MergeArgs, StudyArgs};
use kinrepro::study::request::StudySettings;

pub fn study(o: Checked<StudyArgs, StudySettings>) -> Result<(), CliError> {
    let Checked { args: a, opts } = o;
    let StudySettings {
        options: opts,
        sobol_samples,
    } = opts;
    let couplings = a
        .scenes
        .iter()
        .map(|p| kinrepro::error::read_coupling(p))
        .collect::<Result<Vec<_>, _>>()?;
    let plan = StudyPlan::new(&couplings, opts, sobol_samples)?;
    set_jobs(a.jobs, plan.seatings)?;
    let bar = progress(plan.seatings, &opts.method)?;
    // A streamed study writes its per-sample CSV as the samples arrive.
    let samples_dir = a.out.as_deref().filter(|_| plan.streamed());
    if let Some(dir) = samples_dir {
        std::fs::create_dir_all(dir)
            .map_err(|e| CliError::file(dir.display(), "cannot create the folder: ", e))?;
    }
    let (report, pending_csv) = plan.run(&|| bar.inc(1), |i, v| {
        samples_dir
            .map(|dir| SamplesCsv::create(&dir.join(samples_file_name(i, v)), v, a.force))
            .transpose()
    })?;
    bar.finish_and_clear();
    // Results first: a failed file write must not lose them.
    print_study(&report, a.format)?;
    for w in report.unconverged() {
        eprintln!("warning: {w}");
    }
    // Every file of --out under its temporary name, then all renamed at once.
    let mut staged = pending_csv
        .into_iter()
        .map(SamplesCsv::finish)
        .collect::<Result<Vec<_>, _>>()?;
    let streamed = staged.len();
    if let Some(dir) = &a.out {
        staged.extend(report.stage_files(dir, a.force, plan.streamed())?);
    }
    for f in crate::signals::commit(staged)?.iter().skip(streamed) {
        eprintln!("wrote {f}");
    }
    if let Some(path) = &a.html {
        super::report::study_html(&report, &couplings, a.reference.as_deref(), path, a.force)?;
    }
    refuse_unseated(&report, a.allow_unseated)
}

/// A study whose coupling cannot seat fails unless `--allow-unseated`.
fn refuse_unseated(report: &StudyReport, allow: bool) -> Result<(), CliError> {
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
    Err(CliError::CannotSeat(bad.join("; ")))
}

pub fn merge(args: MergeArgs) -> Result<(), CliError> {
    let MergeArgs {
        parts,
        format,
        allow_unseated,
    } = args;
    // The first part (clap asks for one at least) says which kind of
    // document is merged; it is read once.
    let first = read_text(&parts[0])?;
    if super::sweep::is_sweep(&first) {
        return super::sweep::merge(&parts, first, format);
    }
    let docs = read_json_parts::<StudyReport>(&parts, first, "study")?;
    let merged = kinrepro::study::merge::merge_parts(docs)?;
    print_study(&merged, format)?;
    refuse_unseated(&merged, allow_unseated)
}
