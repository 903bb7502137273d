//! x-y scatter of the re-seating errors of the samples, one panel per variant.

use std::path::Path;

use plotters::prelude::*;

use super::super::error::{Result, StudyError};
use super::{VariantScatter, check_finite, color, headroom, plot_err};

/// Writes an SVG with one square panel per variant (grid), all with the same symmetric axes
/// `x [nm]`, `y [nm]` so that the variants can be compared by eye.
pub fn plot_xy_scatter(path: &Path, data: &[VariantScatter]) -> Result<()> {
    if data.is_empty() {
        return Err(StudyError::NothingToPlot("no variants".into()));
    }
    check_finite(
        data.iter()
            .flat_map(|v| v.xy.iter().flat_map(|(x, y)| [x, y])),
        "x-y samples",
    )?;
    let cols = (1..).find(|c| c * c >= data.len()).unwrap_or(1);
    let rows = data.len().div_ceil(cols);
    let r = headroom(
        data.iter()
            .flat_map(|v| v.xy.iter().map(|(x, y)| x.abs().max(y.abs())))
            .fold(0.0, f64::max),
    )?;
    let size = (420 * cols as u32, 420 * rows as u32);
    let root = SVGBackend::new(path, size).into_drawing_area();
    root.fill(&WHITE).map_err(plot_err)?;
    for (i, (variant, area)) in data.iter().zip(root.split_evenly((rows, cols))).enumerate() {
        let mut chart = ChartBuilder::on(&area)
            .caption(
                format!("{} ({} samples)", variant.variant, variant.xy.len()),
                ("sans-serif", 18),
            )
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
        let col = color(i);
        chart
            .draw_series(
                variant
                    .xy
                    .iter()
                    .map(move |&(x, y)| Circle::new((x, y), 3, col.filled())),
            )
            .map_err(plot_err)?;
    }
    root.present().map_err(plot_err)
}
