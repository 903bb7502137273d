//! Convergence of sigma with the number of samples, one panel per DOF.

use plotters::prelude::*;

use super::{ConvergenceSeries, check_finite, color, draw_legend, headroom, legend_room, plot_err};
use super::{PlotError, Result};
use crate::dof::Dof;

/// An SVG of sigma of the first k samples against k: one panel per DOF that
/// has series (in the order of [`Dof::ALL`]; three per row),
/// each in its unit, one line per variant (colour by variant, in order of
/// first appearance), the legend in the first panel.
pub fn convergence_svg(data: &[ConvergenceSeries]) -> Result<String> {
    if data.iter().all(|s| s.points.is_empty()) {
        return Err(PlotError::NothingToPlot("no convergence points".into()));
    }
    check_finite(data.iter().flat_map(|s| s.points.iter().map(|p| &p.sigma)), "convergence sigma")?;
    let mut variants: Vec<&str> = Vec::new();
    for s in data {
        if !variants.contains(&s.variant.as_str()) {
            variants.push(&s.variant);
        }
    }
    let groups: Vec<(Dof, Vec<(usize, &ConvergenceSeries)>)> = Dof::ALL
        .iter()
        .map(|&dof| {
            let series = data
                .iter()
                .filter(|s| s.dof == dof && !s.points.is_empty())
                .map(|s| {
                    let i = variants.iter().position(|v| *v == s.variant).unwrap_or(0);
                    (i, s)
                })
                .collect::<Vec<_>>();
            (dof, series)
        })
        .filter(|(_, g)| !g.is_empty())
        .collect();
    let cols = groups.len().min(3);
    let rows = groups.len().div_ceil(cols);
    let mut svg = String::new();
    {
        // The first panel holds the legend: taller panels for many series.
        let legend_lines = groups.first().map_or(0, |(_, g)| g.len()) as u32;
        let size = (420 * cols as u32, (400 + 14 * legend_lines) * rows as u32);
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        for (n, ((dof, group), area)) in
            groups.iter().zip(root.split_evenly((rows, cols))).enumerate()
        {
            panel(&area, *dof, group, n == 0)?;
        }
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}

fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    dof: Dof,
    series: &[(usize, &ConvergenceSeries)],
    legend: bool,
) -> Result<()> {
    let unit = dof.unit();
    let points = || series.iter().flat_map(|(_, s)| s.points.iter());
    let kmax = points().map(|p| p.k).max().unwrap_or(2).max(3) as f64;
    let ymax = points().map(|p| p.sigma).fold(0.0, f64::max);
    let (_, height) = area.dim_in_pixel();
    let room = if legend { legend_room(series.len(), f64::from(height) - 90.0) } else { 1.0 };
    let mut chart = ChartBuilder::on(area)
        .caption(format!("convergence of σ {} [{unit}]", dof.symbol()), ("sans-serif", 17))
        .margin(10)
        .x_label_area_size(42)
        .y_label_area_size(65)
        .build_cartesian_2d(1f64..kmax, 0f64..headroom(ymax * room)?)
        .map_err(plot_err)?;
    chart
        .configure_mesh()
        .label_style(("sans-serif", 14))
        .axis_desc_style(("sans-serif", 15))
        .x_label_formatter(&|v| format!("{v:.0}"))
        .x_desc("number of samples k")
        .y_desc(format!("σ of first k samples [{unit}]"))
        .draw()
        .map_err(plot_err)?;
    for &(i, s) in series {
        let col = color(i);
        chart
            .draw_series(LineSeries::new(
                s.points.iter().map(|p| (p.k as f64, p.sigma)),
                col.stroke_width(2),
            ))
            .map_err(plot_err)?
            .label(s.variant.as_str())
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 16, y)], col.stroke_width(2)));
    }
    if !legend {
        return Ok(());
    }
    draw_legend(&mut chart, 13)
}
