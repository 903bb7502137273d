//! `kinrepro sweep`: reproducibility, stiffness and safety over a grid or
//! an LHS of scene fields (library: `explore`; output: `report::sweep`).

use std::io::Write;
use std::path::PathBuf;

use kinrepro::explore::goal::Goals;
use kinrepro::explore::run::{run, study_plan};
use kinrepro::explore::{DesignKind, SweepReport, SweepSpec, merge_sweeps};
use kinrepro::output::atomic::AtomicFile;
use kinrepro::study::StudyOptions;

use super::{
    check_jobs, force_needs_output, print_as, progress, read_json_parts, read_text, set_jobs,
};
use crate::error::{Context, Error, Result, usage};
use crate::flags::groups::{DesignArg, OutputFlags};
use crate::flags::{Format, SweepArgs};

/// `kinrepro sweep`: the base scene, the swept fields, each design point's
/// study options (friction varied, quasi-static) and the outputs.
pub struct Sweep {
    scene: PathBuf,
    sets: Vec<String>,
    points: Option<usize>,
    pareto_point: Option<String>,
    objectives: Vec<String>,
    constraints: Vec<String>,
    options: StudyOptions,
    jobs: Option<usize>,
    output: OutputFlags,
}

impl TryFrom<SweepArgs> for Sweep {
    type Error = Error;

    fn try_from(a: SweepArgs) -> Result<Sweep> {
        force_needs_output(a.output.force, [&a.output.out, &a.output.html])?;
        match (a.design, a.points) {
            (DesignArg::Grid, Some(_)) => usage!("--points needs --design lhs"),
            (DesignArg::Lhs, None) => usage!("--design lhs needs --points N"),
            _ => check_jobs(a.run.jobs)?,
        }
        Ok(Sweep {
            options: a.study.options(&a.path, &a.run),
            scene: a.scene,
            sets: a.sets,
            points: a.points,
            pareto_point: a.pareto_point,
            objectives: a.objective,
            constraints: a.constraint,
            jobs: a.run.jobs,
            output: a.output,
        })
    }
}

pub fn sweep(s: Sweep) -> Result {
    let file = s.scene.display().to_string();
    let text = read_text(&s.scene)?;
    let (scene, coupling) = kinrepro::error::parse_scene(&text, &file)?;
    let design = DesignKind::new(s.points, s.options.seed, &scene);
    let spec = SweepSpec::new(&file, &text, &s.sets, design)?;
    let asked = (s.objectives.as_slice(), s.constraints.as_slice());
    let goals = Goals::asked(asked, (&spec.base, &file, &text), &scene, &spec.paths()).map_err(
        |e| match e {
            kinrepro::explore::ExploreError::Goal(g) => Error::new(format!("{file}: {g}")),
            e => e.into(),
        },
    )?;
    let base = (scene.clone(), coupling.clone());
    let plan = study_plan(scene, coupling, &s.options)?;
    // One tick per seated sample (points that cannot seat tick none).
    let points = spec.points()?.len();
    let shard = s.options.shard;
    let share = shard.range(points).context("--shard")?.len();
    let seatings = share.saturating_mul(plan.variants[0].design.n);
    set_jobs(s.jobs, seatings)?;
    let bar = progress(seatings, plan.method())?;
    let report = run(&spec, &plan, shard, (s.pareto_point.as_deref(), &goals), &|| bar.inc(1))?;
    bar.finish_and_clear();
    // A stop asked for during the run leaves design points "interrupted":
    // neither their table nor a file of them is a result.
    if kinrepro::cancel::requested() {
        return Err(Error::new("interrupted"));
    }
    print_sweep(&report, s.output.format)?;
    // Every output under its temporary name, then all renamed at once.
    let force = s.output.force;
    let mut staged = Vec::new();
    if let Some(dir) = &s.output.out {
        staged.extend(kinrepro::report::sweep::plot::stage_charts(&report, dir, force)?);
    }
    if let Some(path) = &s.output.html {
        let html = kinrepro::report::html::sweep::sweep_html(&report, &text, (&base.0, &base.1))?;
        let mut f = AtomicFile::create(path, force)?;
        f.write_all(html.as_bytes()).map_err(|e| Error::new(format!("{}: {e}", path.display())))?;
        staged.push(f);
    }
    for f in crate::signals::commit(staged)? {
        eprintln!("wrote {f}");
    }
    // Exit 1 only when no design point was evaluated (all listed with their status).
    Ok(report.check_any_valid()?)
}

fn print_sweep(report: &SweepReport, format: Format) -> Result {
    print_as(format, report, || report.table(), || report.csv())
}

/// `kinrepro merge` of sweep parts (JSON documents with `"document":
/// "sweep"`); `first`: the first part's text, already read.
pub fn merge(parts: &[PathBuf], first: String, format: Format) -> Result {
    let docs = read_json_parts::<SweepReport>(parts, first, "sweep")?;
    let merged = merge_sweeps(docs).map_err(|e| Error::new(format!("merge: {e}")))?;
    print_sweep(&merged, format)?;
    Ok(merged.check_any_valid()?)
}
