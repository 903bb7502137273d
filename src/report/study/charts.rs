//! The study's charts as SVG text: sigma bars with intervals (and reference
//! values), x-y scatter of every evaluation point, convergence of sigma in
//! all six DOFs, histograms of every point's samples per DOF with the
//! normal of the reported mean and sigma, the thermal drift along a `[thermal]` cycle, and the same
//! bars and scatter for the interchangeability when tolerances vary. `kinrepro study --out` writes them as files, the
//! HTML report inlines them; both take them from [`study_charts`].

use std::path::Path;

use crate::dof::{Dof, nano};
use crate::report::study::plot::PlotError;
use crate::report::study::plot::{
    ConvergenceSeries, DriftSeries, DriftStep, HistogramPanel, VariantScatter, VariantSigma,
    convergence_svg, drift_svg, histogram_svg, sensitivity_svg, sigma_bars_svg, xy_scatter_svg,
};
use crate::report::study::reference::ReferenceRow;
use crate::report::study::text::truncate;
use crate::scene::point::{Measure, split_output};
use crate::study::runner::INTERCHANGE_PREFIX;
use crate::study::stats::sigma_convergence;
use crate::study::{PointStats, VariantReport};

/// One chart: the file name `--out` gives it, a title and the SVG text.
#[derive(Debug, Clone, PartialEq)]
pub struct Chart {
    pub file_name: String,
    pub title: String,
    pub svg: String,
}

/// A short label of a variant: its scene file stem (they tell the variants
/// apart), else its truncated name.
pub fn variant_label(v: &VariantReport) -> String {
    Path::new(&v.scene)
        .file_stem()
        .map_or_else(|| truncate(&v.name, 30), |s| s.to_string_lossy().into_owned())
}

/// `label · point` where a variant has several evaluation points, else the label.
fn series_label(v: &VariantReport, point: &str, points: usize) -> String {
    if points > 1 { format!("{} · {point}", variant_label(v)) } else { variant_label(v) }
}

/// Bars of every variant and evaluation point, with intervals and the
/// reference values that match (by scene stem or name, and point).
fn bars(
    variants: &[&VariantReport],
    stats: fn(&VariantReport) -> &[PointStats],
    references: &[ReferenceRow],
) -> Vec<VariantSigma> {
    let mut out = Vec::new();
    for v in variants {
        let pts = stats(v);
        for p in pts {
            let interval = match (&p.sigma_ci90_low, &p.sigma_ci90_high) {
                (Some(l), Some(h)) => Some((l.values(), h.values())),
                _ => None,
            };
            out.push(VariantSigma {
                variant: series_label(v, &p.name, pts.len()),
                sigma: p.sigma.values(),
                interval,
                reference: ReferenceRow::find(references, v, &p.name).map(|r| r.sigma),
            });
        }
    }
    out
}

/// The x-y scatter [nm] of every variant and evaluation point, of the
/// re-seating outputs or (`interchange`) of the interchangeability outputs.
fn scatter(variants: &[&VariantReport], interchange: bool) -> Vec<VariantScatter> {
    let (mut out, x) = (Vec::new(), format!("/{}", Dof::X.si_key()));
    for v in variants.iter().filter(|v| !v.records.is_empty()) {
        for (k, name) in v.output_names.iter().enumerate() {
            let Some(point) = name.strip_suffix(&x) else {
                continue;
            };
            if point.starts_with(INTERCHANGE_PREFIX) != interchange {
                continue;
            }
            let point = point.trim_start_matches(INTERCHANGE_PREFIX).to_string();
            out.push(VariantScatter {
                variant: variant_label(v),
                point,
                xy: v
                    .records
                    .iter()
                    .filter(|r| r.centred())
                    .map(|r| (nano(r.outputs[k]), nano(r.outputs[k + 1])))
                    .collect(),
            });
        }
    }
    out
}

/// Sigma of the first k samples for all six DOFs of every re-seating
/// evaluation point.
fn convergence(variants: &[&VariantReport]) -> Result<Vec<ConvergenceSeries>, PlotError> {
    let (mut out, x) = (Vec::new(), format!("/{}", Dof::X.si_key()));
    for v in variants.iter().filter(|v| !v.records.is_empty()) {
        let starts: Vec<(usize, &str)> = v
            .output_names
            .iter()
            .enumerate()
            .filter_map(|(k, n)| n.strip_suffix(&x).map(|p| (k, p)))
            .filter(|(_, p)| !p.starts_with(INTERCHANGE_PREFIX))
            .collect();
        for &(k0, point) in &starts {
            for (j, &dof) in Dof::ALL.iter().enumerate() {
                let values: Vec<f64> = (v.records.iter())
                    .filter(|r| r.centred())
                    .map(|r| nano(r.outputs[k0 + j]))
                    .collect();
                out.push(ConvergenceSeries {
                    variant: series_label(v, point, starts.len()),
                    dof,
                    points: sigma_convergence(&values)?,
                });
            }
        }
    }
    Ok(out)
}

/// The thermal drift of each variant's evaluation points (variants with
/// `[thermal]` only).
fn drift_series(variants: &[&VariantReport]) -> Vec<DriftSeries> {
    let mut out = Vec::new();
    for v in variants {
        for p in v.points.iter().filter(|p| !p.thermal.is_empty()) {
            let steps = p.thermal.iter().map(|c| DriftStep {
                delta_t_k: c.delta_t_k,
                mean: c.drift.mean.values(),
                sigma: c.drift.sigma.values(),
            });
            let label = format!("{} · {}", variant_label(v), p.name);
            out.push(DriftSeries { label, steps: steps.collect() });
        }
    }
    out
}

/// The histogram panels of point `p` of `v` from its records: one per DOF
/// and direction, with the reported mean and sigma (nm, nrad).
fn histogram_panels(v: &VariantReport, p: &PointStats) -> Vec<HistogramPanel> {
    let column = |k: usize| -> Vec<f64> {
        v.records.iter().filter(|r| r.centred()).map(|r| nano(r.outputs[k])).collect()
    };
    let mut panels = Vec::new();
    for (k, name) in v.output_names.iter().enumerate() {
        let Some((head, measure)) = split_output(name).filter(|(h, _)| *h == p.name) else {
            continue;
        };
        let (label, mean, sigma) = match measure {
            Measure::Dof(d) => {
                let label = format!("{} [{}]", d.name(), d.unit());
                (label, p.mean.values()[d.index()], p.sigma.values()[d.index()])
            }
            Measure::Along(n) | Measure::About(n) => {
                let label = measure.label(false);
                let Some(s) = p.directions.iter().find(|s| s.label() == label) else {
                    continue;
                };
                debug_assert_eq!((head, n), (p.name.as_str(), s.name.as_str()));
                (format!("{label} [{}]", s.unit), s.mean, s.sigma)
            }
        };
        panels.push(HistogramPanel { label, values: column(k), mean, sigma });
    }
    panels
}

/// The charts of the complete variants of a study. Scatter and convergence
/// need the samples, which a streamed study does not keep.
pub fn study_charts(
    variants: &[&VariantReport],
    references: &[ReferenceRow],
) -> Result<Vec<Chart>, PlotError> {
    let full: Vec<&VariantReport> = variants
        .iter()
        .copied()
        .filter(|v| !v.partial && (!v.points.is_empty() || !v.interchangeability.is_empty()))
        .collect();
    let mut charts = Vec::new();
    let mut add = |file_name: &str, title: &str, svg| {
        let (file_name, title) = (file_name.into(), title.into());
        charts.push(Chart { file_name, title, svg });
    };
    let with = |f: fn(&VariantReport) -> bool| full.iter().copied().filter(|v| f(v)).collect();
    let reseat: Vec<&VariantReport> = with(|v| !v.points.is_empty());
    if !reseat.is_empty() {
        let svg = sigma_bars_svg(&bars(&reseat, |v| &v.points, references), "re-seating σ")?;
        add("sigma_bars.svg", "Re-seating σ per DOF, with 90 % intervals", svg);
    }
    let inter: Vec<&VariantReport> = with(|v| !v.interchangeability.is_empty());
    if !inter.is_empty() {
        let svg = sigma_bars_svg(&bars(&inter, |v| &v.interchangeability, &[]), "interchange σ")?;
        let title = "Interchangeability σ (manufacturing tolerances), with 90 % intervals";
        add("interchange_sigma_bars.svg", title, svg);
    }
    let xy = scatter(&reseat, false);
    if !xy.is_empty() {
        let title = "Re-seating x-y scatter of every sample, per evaluation point";
        add("scatter_xy.svg", title, xy_scatter_svg(&xy)?);
        let title = "Convergence of σ with the number of samples, all six DOFs";
        add("sigma_convergence.svg", title, convergence_svg(&convergence(&reseat)?)?);
    }
    let mut series = 0;
    for (i, v) in reseat.iter().enumerate() {
        for (j, p) in v.points.iter().enumerate() {
            let panels = histogram_panels(v, p);
            if !panels.is_empty() {
                let title = format!(
                    "{} · {}: samples per DOF, and the normal distribution of the reported mean and σ",
                    variant_label(v),
                    p.name
                );
                let file = format!("histogram_{}_{}.svg", i + 1, j + 1);
                add(&file, &title, histogram_svg(&title, &panels, series)?);
            }
            series += 1;
        }
    }
    let drift = drift_series(&reseat);
    if !drift.is_empty() {
        let title = "Thermal drift along the cycle: mean over the samples and the ±3σ band, per evaluation point";
        add("thermal_drift.svg", title, drift_svg(&drift)?);
    }
    let xy = scatter(&inter, true);
    if !xy.is_empty() {
        let title = "Interchangeability x-y scatter, per evaluation point";
        add("interchange_scatter_xy.svg", title, xy_scatter_svg(&xy)?);
    }
    for (i, v) in full.iter().enumerate() {
        for b in v.sensitivity.iter().flatten() {
            let point = b.dofs.first().map_or("", |d| super::labels::output_point(&d.output));
            let what =
                format!("{}: sensitivity of the {} scatter at {point}", variant_label(v), b.kind);
            let file = format!("sensitivity_{}_{}.svg", i + 1, b.kind);
            add(&file, &what, sensitivity_svg(b, &what)?);
        }
    }
    Ok(charts)
}
