//! The self-contained HTML report (`kinrepro report`, `kinrepro study
//! --html FILE`): one file with inline CSS and inline SVG, no script, no
//! external resource (a Content Security Policy forbids fetching anything).
//!
//! Sections, in order: the verdict ([`verdict`]: +-3 sigma with its
//! interval, mean, min and max, the friction limit, the contact safety),
//! the run's metadata (version, schema, solver, sampler, seed, samples,
//! what varied), the sigma tables with intervals (nm, nrad)
//! and reference values, the charts (`report::study::charts`: sigma bars
//! with interval bars and reference ticks, x-y scatter of every evaluation
//! point, convergence of sigma in all six DOFs, interchangeability), then per
//! scene a top and a side view of the coupling at its nominal seating
//! ([`drawing`]), the contact forces, stresses and stiffnesses
//! ([`mechanics`]) and the scene in both forms (the file as written and the
//! explicit form of `kinrepro expand`), and last any extra sections given
//! as `(title, svg)` ([`Section`], e.g. a sweep's design charts).
//!
//! A sweep's report (`kinrepro sweep --html FILE`) is its own page:
//! [`sweep`].
//!
//! Every element the browser test checks carries `data-check` (`table`,
//! `chart`, `drawing`).

mod dimensions;
mod drawing;
pub mod inputs;
mod mechanics;
pub mod optimize;
pub(crate) mod page;
pub mod prediction;
mod svg;
pub mod sweep;
mod tables;
mod verdict;

use std::fmt::Write;

use thiserror::Error;

use crate::analysis::stiffness::CouplingStiffness;
use crate::assembly::{AssemblyError, Coupling};
pub use crate::report::study::reference::{ReferenceRow, load_reference, parse_reference, unshown};
use crate::report::table::escape;
use crate::scene::{Scene, SceneError};
use crate::solve::{Load, Seating, SolveError};
use crate::study::VariantReport;
use crate::study::provenance::VERSION;
pub use inputs::{SceneInput, StudyInput, load_study, scene_input};

/// The report could not be made.
#[derive(Debug, Error)]
pub enum HtmlError {
    #[error(transparent)]
    Reference(#[from] crate::report::study::reference::ReferenceError),
    #[error("{file}: {reason}")]
    Input { file: String, reason: String },
    #[error(transparent)]
    Scene(#[from] SceneError),
    #[error("{file}: {source}")]
    Assembly {
        file: String,
        #[source]
        source: AssemblyError,
    },
    #[error("{file}: the nominal seating (for the drawing and the stresses) failed: {source}")]
    Solve {
        file: String,
        #[source]
        source: SolveError,
    },
    #[error("charts: {0}")]
    Chart(#[from] crate::report::study::plot::PlotError),
    #[error(transparent)]
    SweepChart(#[from] crate::report::sweep::plot::SweepPlotError),
}

/// An extra section of the report: a title and an SVG (e.g. a sweep's
/// design charts), appended after the scenes in the order given.
#[derive(Debug, Clone, PartialEq)]
pub struct Section {
    pub title: String,
    pub svg: String,
}

/// Everything one report shows.
#[derive(Debug, Clone, Default)]
pub struct HtmlReport {
    pub studies: Vec<StudyInput>,
    /// Reference values of sigma (`--reference FILE`) and the file's name.
    pub references: Vec<ReferenceRow>,
    pub reference_source: Option<String>,
    pub sections: Vec<Section>,
}

impl HtmlReport {
    /// The HTML document.
    pub fn render(&self) -> Result<String, HtmlError> {
        let variants: Vec<&VariantReport> =
            self.studies.iter().flat_map(|s| s.report.variants.iter()).collect();
        // Reference rows: the --reference file's, then the measured sigma
        // of a prediction's calibrated design.
        let mut references = self.references.clone();
        for st in &self.studies {
            references.extend(st.prediction.measured.iter().cloned());
        }
        let charts = crate::report::study::charts::study_charts(&variants, &references)?;
        let mut body = String::new();
        let mut toc: Vec<(String, String)> = Vec::new();
        if !self.studies.is_empty() {
            toc.push(("verdict".into(), "Verdict".into()));
            toc.push(("run".into(), "Run".into()));
            toc.push(("sigma".into(), "σ tables".into()));
        }
        if !charts.is_empty() {
            toc.push(("charts".into(), "Charts".into()));
        }
        for (i, v) in variants.iter().enumerate() {
            toc.push((format!("scene-{}", i + 1), format!("{}. {}", i + 1, v.name)));
        }
        for (i, s) in self.sections.iter().enumerate() {
            toc.push((format!("extra-{}", i + 1), s.title.clone()));
        }
        self.header(&mut body, &toc, &variants);
        if !self.studies.is_empty() {
            self.results(&mut body, &variants, &references);
        }
        if !charts.is_empty() {
            body.push_str("<section id=\"charts\"><h2>Charts</h2>\n");
            for c in &charts {
                let id = c.file_name.trim_end_matches(".svg").replace('_', "-");
                let _ = writeln!(body, "<h3>{}</h3>", escape(&c.title));
                body.push_str(&page::figure(&id, &c.svg, chart_caption(&c.file_name)));
            }
            body.push_str("</section>\n");
        }
        let scenes = self.studies.iter().flat_map(|s| s.report.variants.iter().zip(&s.scenes));
        for (i, (v, scene)) in scenes.enumerate() {
            scene_section(&mut body, i + 1, v, scene)?;
        }
        for (i, s) in self.sections.iter().enumerate() {
            let _ = writeln!(body, "<section id=\"extra-{}\"><h2>{}</h2>", i + 1, escape(&s.title));
            body.push_str(&page::figure(&format!("extra-{}-svg", i + 1), &s.svg, &s.title));
            body.push_str("</section>\n");
        }
        let sources: Vec<&str> = self.studies.iter().map(|s| s.source.as_str()).collect();
        let from = if sources.is_empty() {
            String::new()
        } else {
            format!(" from {}", sources.join(", "))
        };
        let _ = writeln!(
            body,
            "<footer class=\"muted\">Written by kinrepro {VERSION}{}. Self-contained: inline CSS and SVG, no script, no network.</footer>",
            escape(&from)
        );
        Ok(page::document("kinrepro report", &body))
    }

    /// Title, provenance, contents, then the verdict and the run.
    fn header(&self, body: &mut String, toc: &[(String, String)], variants: &[&VariantReport]) {
        body.push_str("<header><h1>kinrepro: re-seating reproducibility report</h1>\n");
        for st in &self.studies {
            let _ = writeln!(
                body,
                "<p class=\"prov\">{}, shard {}</p>",
                escape(&st.report.produced_by()),
                st.report.shard
            );
        }
        body.push_str("</header>\n<nav><ul>\n");
        for (id, title) in toc {
            let _ = writeln!(body, "<li><a href=\"#{}\">{}</a></li>", escape(id), escape(title));
        }
        body.push_str("</ul></nav>\n");
        if self.studies.is_empty() {
            return;
        }
        body.push_str(&verdict::verdict_section(variants));
        body.push_str("<section id=\"run\"><h2>Run</h2>\n");
        for st in &self.studies {
            body.push_str(&tables::metadata(&st.source, &st.report));
            body.push_str(&st.prediction.html());
        }
        body.push_str("</section>\n");
    }

    fn results(&self, body: &mut String, variants: &[&VariantReport], references: &[ReferenceRow]) {
        body.push_str("<section id=\"sigma\"><h2>σ tables</h2>\n<h3>Re-seating scatter (one pair of halves)</h3>\n");
        body.push_str(&tables::sigma_table(variants, |v| &v.points, references));
        if let Some(src) = &self.reference_source {
            let _ = writeln!(
                body,
                "<p class=\"note\">Reference rows (highlighted) and the black ticks on the bars: {}.</p>",
                escape(src)
            );
        }
        let thermal = tables::thermal_table(variants);
        if !thermal.is_empty() {
            body.push_str("<h3>Thermal drift along the [thermal] cycle</h3>\n");
            body.push_str(&thermal);
        }
        if variants.iter().any(|v| !v.interchangeability.is_empty()) {
            body.push_str("<h3>Interchangeability (manufacturing tolerances; nominal friction and preload)</h3>\n");
            body.push_str(&tables::sigma_table(variants, |v| &v.interchangeability, &[]));
        }
        body.push_str("</section>\n");
    }
}

fn chart_caption(file: &str) -> &'static str {
    match file {
        "sigma_bars.svg" | "interchange_sigma_bars.svg" => {
            "Bars: σ per variant and evaluation point; black error bars: the 90 % interval of σ; black ticks: reference values. Left nm, right nrad."
        }
        "scatter_xy.svg" | "interchange_scatter_xy.svg" => {
            "Every sample's x-y error relative to the nominal seating [nm], one panel per variant and evaluation point, common axes; the line: the ellipse holding 90 % of a normal distribution with the samples' mean and covariance (chi-square quantile of 2 degrees of freedom, 4.605)."
        }
        f if f.starts_with("sensitivity_") => {
            "Per input and DOF: the share of the variance a linear fit gives it (normalised SRC², left), the first-order Sobol index S (middle) and the total index ST (right), each series one colour in every panel; black error bars: the 90 % bootstrap interval of S and ST. ST - S is the input's share through interactions."
        }
        "thermal_drift.svg" => {
            "Mean drift of each evaluation point from each sample's seated pose (line) and mean ± 3σ over the samples (band), at the seated state and each cycle point [nm, nrad]."
        }
        _ => {
            "σ of the first k samples against k, one panel per DOF. For an LHS a prefix is not itself a Latin hypercube: the curve shows how σ settles."
        }
    }
}

/// The nominal seating of `scene` (assembled as `c`) under its nominal
/// load, quasi-static with default settings, as the drawings show it.
fn nominal_seating(scene: &Scene, c: &Coupling) -> Result<Seating, HtmlError> {
    let load = Load::nominal(scene);
    crate::solve::quasistatic::seat(c, &load, &Default::default())
        .map_err(|source| HtmlError::Solve { file: scene.file.clone(), source })
}

/// One scene: drawing, mechanics, scene text in both forms.
fn scene_section(
    body: &mut String,
    n: usize,
    v: &VariantReport,
    scene: &SceneInput,
) -> Result<(), HtmlError> {
    let (c, model) = (&scene.coupling, (&scene.scene, &scene.coupling));
    let file = v.scene.clone();
    let seating = nominal_seating(&scene.scene, c)?;
    let load = Load::nominal(&scene.scene);
    let k = CouplingStiffness::new(c, &seating, &load)
        .map_err(|source| HtmlError::Solve { file: file.clone(), source })?;
    let _ = writeln!(
        body,
        "<section id=\"scene-{n}\"><h2>{n}. {}</h2>\n<p class=\"muted\">{}</p>\n<h3>Coupling at the nominal seating</h3>",
        escape(&v.name),
        escape(&v.scene)
    );
    body.push_str(&drawing::coupling_views(&format!("d{n}"), model, &seating));
    body.push_str("<h3>Stiffness and stresses</h3>\n");
    body.push_str(&mechanics::mechanics(model, &seating, &k));
    let explicit = Scene::expand_text(&scene.text, &file)?;
    let _ = writeln!(
        body,
        "<h3>Scene</h3><div class=\"two\"><div><h4>As written ({})</h4><pre data-check=\"scene\">{}</pre></div><div><h4>Explicit form (kinrepro expand)</h4><pre data-check=\"scene\">{}</pre></div></div>\n</section>",
        escape(&file),
        escape(&scene.text),
        escape(&explicit)
    );
    Ok(())
}
