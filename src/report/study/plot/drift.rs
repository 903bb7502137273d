//! Thermal drift against the temperature cycle, one panel per DOF.

use plotters::prelude::*;

use super::{DriftSeries, check_finite, color, draw_legend, plot_err};
use super::{PlotError, Result};
use crate::dof::Dof;

/// An SVG of the drift along a thermal cycle: one panel per DOF (three
/// per row, each in its unit), x the cycle step (0 the seated state, then
/// each cycle point, labelled with its [dT_moving, dT_fixed] in K), per
/// series (a variant's evaluation point, colour by series) the mean drift
/// over the samples as a line and mean +- 3 sigma as a shaded band; the
/// legend in the first panel.
pub fn drift_svg(data: &[DriftSeries]) -> Result<String> {
    let steps = data.iter().map(|s| s.steps.len()).max().unwrap_or(0);
    if steps == 0 {
        return Err(PlotError::NothingToPlot("no thermal cycle points".into()));
    }
    let values =
        data.iter().flat_map(|s| s.steps.iter()).flat_map(|p| p.mean.iter().chain(&p.sigma));
    check_finite(values, "thermal drift")?;
    let labels: Vec<String> = std::iter::once("seated".to_string())
        .chain(data[0].steps.iter().map(|p| format!("[{}, {}] K", p.delta_t_k[0], p.delta_t_k[1])))
        .collect();
    let mut svg = String::new();
    {
        let size = (420 * 3, (400 + 14 * data.len() as u32) * 2);
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        for (n, (dof, area)) in Dof::ALL.iter().zip(root.split_evenly((2, 3))).enumerate() {
            panel(&area, *dof, data, &labels, n == 0)?;
        }
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}

/// Mean and mean +- 3 sigma of `dof` at each step of a series, the
/// seated state (0, 0) first.
fn band(s: &DriftSeries, dof: Dof) -> Vec<(f64, f64, f64)> {
    let i = dof.index();
    std::iter::once((0.0, 0.0, 0.0))
        .chain(
            s.steps.iter().enumerate().map(|(k, p)| ((k + 1) as f64, p.mean[i], 3.0 * p.sigma[i])),
        )
        .collect()
}

fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    dof: Dof,
    data: &[DriftSeries],
    labels: &[String],
    legend: bool,
) -> Result<()> {
    let unit = dof.unit();
    let bands: Vec<_> = data.iter().map(|s| band(s, dof)).collect();
    let lo = bands.iter().flatten().map(|(_, m, w)| m - w).fold(0.0, f64::min);
    let hi = bands.iter().flatten().map(|(_, m, w)| m + w).fold(0.0, f64::max);
    let pad = if hi > lo { 0.1 * (hi - lo) } else { 1.0 };
    let top = hi + pad + if legend { 0.12 * data.len() as f64 * (hi - lo + pad) } else { 0.0 };
    let last = (labels.len() - 1).max(1) as f64;
    let mut chart = ChartBuilder::on(area)
        .caption(format!("drift {} [{unit}]", dof.symbol()), ("sans-serif", 17))
        .margin(10)
        .x_label_area_size(42)
        .y_label_area_size(70)
        .build_cartesian_2d(-0.2f64..last + 0.2, (lo - pad)..top)
        .map_err(plot_err)?;
    let label = |v: &f64| {
        let k = v.round();
        if (v - k).abs() < 1e-9 && k >= 0.0 {
            labels.get(k as usize).cloned().unwrap_or_default()
        } else {
            String::new()
        }
    };
    chart
        .configure_mesh()
        .x_labels(labels.len())
        .label_style(("sans-serif", 13))
        .axis_desc_style(("sans-serif", 15))
        .x_label_formatter(&label)
        .x_desc("cycle point: [dT moving, dT fixed]")
        .y_desc(format!("drift from the seated pose [{unit}]"))
        .draw()
        .map_err(plot_err)?;
    for (i, (s, b)) in data.iter().zip(&bands).enumerate() {
        let col = color(i);
        let outline: Vec<(f64, f64)> = b
            .iter()
            .map(|&(x, m, w)| (x, m + w))
            .chain(b.iter().rev().map(|&(x, m, w)| (x, m - w)))
            .collect();
        chart
            .draw_series(std::iter::once(Polygon::new(outline, col.mix(0.2).filled())))
            .map_err(plot_err)?;
        chart
            .draw_series(LineSeries::new(b.iter().map(|&(x, m, _)| (x, m)), col.stroke_width(2)))
            .map_err(plot_err)?
            .label(s.label.as_str())
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 16, y)], col.stroke_width(2)));
    }
    if !legend {
        return Ok(());
    }
    draw_legend(&mut chart, 13)
}
