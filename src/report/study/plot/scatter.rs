//! x-y scatter of the errors of the samples, one panel per variant and
//! evaluation point.

use plotters::prelude::*;

use super::{PlotError, Result};
use super::{VariantScatter, check_finite, color, headroom, plot_err};

/// An SVG with one square panel per variant and evaluation point (grid),
/// captioned `variant · point (n samples)`, all with the same symmetric axes
/// `x [nm]`, `y [nm]` so that variants and points can be compared by eye.
/// Panels of one variant share its colour.
pub fn xy_scatter_svg(data: &[VariantScatter]) -> Result<String> {
    if data.is_empty() {
        return Err(PlotError::NothingToPlot("no variants".into()));
    }
    check_finite(data.iter().flat_map(|v| v.xy.iter().flat_map(|(x, y)| [x, y])), "x-y samples")?;
    let cols = (1..).find(|c| c * c >= data.len()).unwrap_or(1).min(4);
    let rows = data.len().div_ceil(cols);
    let r = headroom(
        data.iter()
            .flat_map(|v| v.xy.iter().map(|(x, y)| x.abs().max(y.abs())))
            .fold(0.0, f64::max),
    )?;
    // One colour per variant, in order of first appearance.
    let mut variants: Vec<&str> = Vec::new();
    for v in data {
        if !variants.contains(&v.variant.as_str()) {
            variants.push(&v.variant);
        }
    }
    let mut svg = String::new();
    {
        let size = (420 * cols as u32, 420 * rows as u32);
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        for (panel, area) in data.iter().zip(root.split_evenly((rows, cols))) {
            let caption = if panel.point.is_empty() {
                format!("{} ({} samples)", panel.variant, panel.xy.len())
            } else {
                format!("{} · {} ({} samples)", panel.variant, panel.point, panel.xy.len())
            };
            let mut chart = ChartBuilder::on(&area)
                .caption(caption, ("sans-serif", 17))
                .margin(12)
                .x_label_area_size(45)
                .y_label_area_size(65)
                .build_cartesian_2d(-r..r, -r..r)
                .map_err(plot_err)?;
            chart
                .configure_mesh()
                .label_style(("sans-serif", 15))
                .axis_desc_style(("sans-serif", 17))
                .x_desc("x [nm]")
                .y_desc("y [nm]")
                .draw()
                .map_err(plot_err)?;
            let i = variants.iter().position(|v| *v == panel.variant).unwrap_or(0);
            let col = color(i);
            chart
                .draw_series(
                    panel.xy.iter().map(move |&(x, y)| Circle::new((x, y), 3, col.filled())),
                )
                .map_err(plot_err)?;
        }
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}
