//! Grouped bar chart of sigma per variant and DOF.

use std::path::Path;

use plotters::prelude::*;

use super::super::error::{Result, StudyError};
use super::{Dof, VariantSigma, check_finite, color, headroom, plot_err};

/// Writes an SVG with two panels, translations \[nm\] and rotations \[nrad\]: one group of bars per
/// DOF, one bar per variant, legend with the variant names.
pub fn plot_sigma_bars(path: &Path, data: &[VariantSigma]) -> Result<()> {
    if data.is_empty() {
        return Err(StudyError::NothingToPlot("no variants".into()));
    }
    check_finite(data.iter().flat_map(|v| v.sigma.iter()), "sigma")?;
    if data.iter().flat_map(|v| v.sigma).any(|s| s < 0.0) {
        return Err(StudyError::InvalidParameter("negative sigma".into()));
    }
    let root = SVGBackend::new(path, (1100, 480)).into_drawing_area();
    root.fill(&WHITE).map_err(plot_err)?;
    let (left, right) = root.split_horizontally(550);
    panel(&left, data, &[Dof::X, Dof::Y, Dof::Z], "translations", true)?;
    panel(
        &right,
        data,
        &[Dof::PhiX, Dof::PhiY, Dof::PhiZ],
        "rotations",
        false,
    )?;
    root.present().map_err(plot_err)
}

fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    data: &[VariantSigma],
    dofs: &[Dof],
    title: &str,
    legend: bool,
) -> Result<()> {
    let idx = |d: Dof| Dof::ALL.iter().position(|&x| x == d).unwrap_or(0);
    let ymax = data
        .iter()
        .flat_map(|v| dofs.iter().map(|&d| v.sigma[idx(d)]))
        .fold(0.0, f64::max);
    let unit = dofs[0].unit();
    let m = dofs.len();
    // Room above the bars for the legend box (about one line per variant).
    let legend_room = if legend {
        1.0 + 0.08 * data.len() as f64
    } else {
        1.0
    };
    let mut chart = ChartBuilder::on(area)
        .caption(format!("re-seating σ, {title}"), ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(75)
        .build_cartesian_2d(
            -0.5f64..(m as f64 - 0.5),
            0f64..headroom(ymax * legend_room)?,
        )
        .map_err(plot_err)?;
    let names: Vec<&str> = dofs.iter().map(|d| d.label()).collect();
    let fmt = |v: &f64| {
        let r = v.round();
        if (v - r).abs() < 1e-6 && r >= 0.0 && (r as usize) < names.len() {
            names[r as usize].to_string()
        } else {
            String::new()
        }
    };
    chart
        .configure_mesh()
        .label_style(("sans-serif", 15))
        .axis_desc_style(("sans-serif", 17))
        .disable_x_mesh()
        .x_labels(m)
        .x_label_formatter(&fmt)
        .x_desc("degree of freedom")
        .y_desc(format!("σ [{unit}]"))
        .draw()
        .map_err(plot_err)?;

    let width = 0.8 / data.len() as f64;
    for (v, variant) in data.iter().enumerate() {
        let col = color(v);
        let bars = dofs.iter().enumerate().map(move |(c, &d)| {
            let x0 = c as f64 - 0.4 + v as f64 * width;
            Rectangle::new(
                [(x0, 0.0), (x0 + width, variant.sigma[idx(d)])],
                col.filled(),
            )
        });
        let anno = chart.draw_series(bars).map_err(plot_err)?;
        if legend {
            anno.label(variant.variant.as_str())
                .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 12, y + 5)], col.filled()));
        }
    }
    if legend {
        chart
            .configure_series_labels()
            .label_font(("sans-serif", 15))
            .position(SeriesLabelPosition::UpperRight)
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .draw()
            .map_err(plot_err)?;
    }
    Ok(())
}
