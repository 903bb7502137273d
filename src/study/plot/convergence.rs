//! Convergence of sigma with the number of samples.

use std::path::Path;

use plotters::prelude::*;

use super::super::error::{Result, StudyError};
use super::{ConvergenceSeries, check_finite, color, headroom, plot_err};

/// Writes an SVG of sigma of the first k samples against k: one panel for translations \[nm\]
/// and one for rotations \[nrad\] (only the panels that have series), one line per series.
pub fn plot_convergence(path: &Path, data: &[ConvergenceSeries]) -> Result<()> {
    if data.iter().all(|s| s.points.is_empty()) {
        return Err(StudyError::NothingToPlot("no convergence points".into()));
    }
    check_finite(
        data.iter().flat_map(|s| s.points.iter().map(|p| &p.sigma)),
        "convergence sigma",
    )?;
    let groups: Vec<Vec<(usize, &ConvergenceSeries)>> = [false, true]
        .iter()
        .map(|&rot| {
            data.iter()
                .enumerate()
                .filter(|(_, s)| s.dof.is_rotation() == rot && !s.points.is_empty())
                .collect::<Vec<_>>()
        })
        .filter(|g| !g.is_empty())
        .collect();
    let root = SVGBackend::new(path, (560 * groups.len() as u32, 460)).into_drawing_area();
    root.fill(&WHITE).map_err(plot_err)?;
    for (group, area) in groups.iter().zip(root.split_evenly((1, groups.len()))) {
        panel(&area, group)?;
    }
    root.present().map_err(plot_err)
}

fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    series: &[(usize, &ConvergenceSeries)],
) -> Result<()> {
    let unit = series[0].1.dof.unit();
    let points = || series.iter().flat_map(|(_, s)| s.points.iter());
    let kmax = points().map(|p| p.k).max().unwrap_or(2).max(3) as f64;
    let ymax = headroom(points().map(|p| p.sigma).fold(0.0, f64::max))?;
    let mut chart = ChartBuilder::on(area)
        .caption(format!("convergence of σ [{unit}]"), ("sans-serif", 18))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(75)
        .build_cartesian_2d(1f64..kmax, 0f64..ymax)
        .map_err(plot_err)?;
    chart
        .configure_mesh()
        .label_style(("sans-serif", 15))
        .axis_desc_style(("sans-serif", 17))
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
            .label(format!("{} {}", s.variant, s.dof.label()))
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 16, y)], col.stroke_width(2)));
    }
    chart
        .configure_series_labels()
        .label_font(("sans-serif", 15))
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(plot_err)
}
