//! `kinrepro report` (the self-contained HTML report of study JSON files),
//! `kinrepro study --html FILE` (the same for the study just run) and
//! `kinrepro materials` (the built-in materials and their sources).

use std::path::Path;

use kinrepro::report::html::{HtmlReport, StudyInput, load_reference, load_study, scene_input};
use kinrepro::study::{StudyPlan, StudyReport};

use super::print_as;
use crate::error::Result;
use crate::flags::{Format, ReportArgs};

pub fn report(args: ReportArgs) -> Result {
    let studies =
        args.studies.iter().map(|p| load_study(p)).collect::<std::result::Result<Vec<_>, _>>()?;
    write_html(studies, args.reference.as_deref(), &args.out, args.force)
}

/// `study --html FILE`: the report of the study just run under `plan`.
pub fn study_html(
    report: &StudyReport,
    plan: &StudyPlan,
    reference: Option<&Path>,
    out: &Path,
    force: bool,
) -> Result {
    let scenes = plan
        .variants
        .iter()
        .map(|v| scene_input(v.scene.clone(), v.coupling.clone()))
        .collect::<std::result::Result<Vec<_>, _>>()?;
    let study = StudyInput {
        source: "this run".into(),
        report: report.clone(),
        scenes,
        prediction: Default::default(),
    };
    write_html(vec![study], reference, out, force)
}

fn write_html(
    studies: Vec<StudyInput>,
    reference: Option<&Path>,
    out: &Path,
    force: bool,
) -> Result {
    let references = match reference {
        Some(p) => load_reference(p)?,
        None => Vec::new(),
    };
    let variants: Vec<_> = studies.iter().flat_map(|s| &s.report.variants).collect();
    let unshown: Vec<String> = kinrepro::report::html::unshown(&references, &variants)
        .iter()
        .map(|r| format!("`{}` {}/{}", r.label, r.scene, r.point))
        .collect();
    if let (Some(p), false) = (reference, unshown.is_empty()) {
        eprintln!(
            "warning: {}: {} reference row(s) match no variant and evaluation point of the \
             report, or follow another label's row for the same one, and are not shown: {}",
            p.display(),
            unshown.len(),
            kinrepro::report::printable::printable(&unshown.join(", "))
        );
    }
    let html = HtmlReport {
        studies,
        references,
        reference_source: reference.map(|p| p.display().to_string()),
        sections: Vec::new(),
    }
    .render()?;
    kinrepro::output::atomic::write_file(out, &html, force)?;
    eprintln!("wrote {}", out.display());
    Ok(())
}

pub fn materials(format: Format) -> Result {
    use kinrepro::report::materials::*;
    print_as(format, &materials_doc(), materials_table, materials_csv)
}
