//! `kinrepro optimize`: the best design within bounds on one objective
//! under constraints (library: `explore::optimize`; output:
//! `report::optimize`).

use std::io::Write;

use kinrepro::explore::goal::Goals;
use kinrepro::explore::optimize::{OptimizeSpec, optimize as run};
use kinrepro::explore::run::study_plan;
use kinrepro::output::atomic::AtomicFile;
use kinrepro::study::StudyOptions;

use super::{emit, print_json, read_text, set_jobs};
use crate::error::{Error, Result};
use crate::flags::OptimizeArgs;
use crate::flags::groups::TextFormat;

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
    match (a.json, a.format) {
        (true, _) | (_, TextFormat::Json) => print_json(&report)?,
        _ => emit(&report.table())?,
    }
    if let Some(path) = &a.html {
        let html = kinrepro::report::html::optimize::optimize_html(&report, &text)?;
        let mut f = AtomicFile::create(path, a.force)?;
        f.write_all(html.as_bytes()).map_err(|e| Error::new(format!("{}: {e}", path.display())))?;
        for f in crate::signals::commit(vec![f])? {
            eprintln!("wrote {f}");
        }
    }
    if report.optimum.is_none() {
        return Err(Error::new(format!(
            "{file}: no feasible design: none of the {} candidates meets every constraint",
            report.history.len()
        )));
    }
    Ok(())
}
