//! SVG of predicted sigma with its prediction interval per scene (first
//! evaluation point), translations [nm] and rotations [nrad] side by side,
//! the measured sigma of the calibrated design as crosses.

use std::path::Path;

use plotters::prelude::*;
use thiserror::Error;

use super::PredictionReport;
use crate::dof::{Dof, nano};
use crate::output::atomic::{WriteError, write_file};

/// The plot could not be drawn or written.
#[derive(Debug, Error)]
pub enum PlotError {
    #[error("{path}: cannot draw the plot: {reason}")]
    Draw { path: String, reason: String },
    #[error("{path}: nothing to plot: {reason}")]
    Empty { path: String, reason: String },
    #[error(transparent)]
    Write(#[from] WriteError),
}

/// One scene's values at its first point: sigma, low, high, measured (nm, nrad).
struct Row {
    label: String,
    sigma: [f64; 6],
    low: [f64; 6],
    high: [f64; 6],
    measured: [Option<f64>; 6],
}

fn rows(r: &PredictionReport) -> Vec<Row> {
    r.predictions
        .iter()
        .filter_map(|p| {
            let pt = p.variant.points.first()?;
            let stem = Path::new(&p.variant.scene)
                .file_stem()
                .map_or(p.variant.scene.clone(), |s| s.to_string_lossy().into_owned());
            let measured = std::array::from_fn(|j| {
                p.measured
                    .as_ref()
                    .filter(|(name, _)| *name == pt.name)
                    .and_then(|(_, d)| d.iter().find(|d| d.dof == Dof::ALL[j]))
                    .map(|d| nano(d.measured_sigma))
            });
            Some(Row {
                label: stem.chars().take(2).collect(),
                sigma: pt.sigma.values(),
                low: pt.sigma_ci90_low?.values(),
                high: pt.sigma_ci90_high?.values(),
                measured,
            })
        })
        .collect()
}

/// Write the SVG to `path` (whole or not at all; `force` to overwrite).
pub fn plot_predictions(
    path: &Path,
    report: &PredictionReport,
    force: bool,
) -> Result<(), PlotError> {
    let p = path.display().to_string();
    let data = rows(report);
    if data.is_empty() {
        return Err(PlotError::Empty { path: p, reason: "no prediction with an interval".into() });
    }
    let err =
        |e: &dyn std::fmt::Display| PlotError::Draw { path: p.clone(), reason: e.to_string() };
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1100, 520)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(&e))?;
        let title = format!(
            "{}; {} calibrated on {}",
            report.study().produced_by(),
            super::parameters_summary(&report.calibration),
            report.calibration.scene
        );
        let root = root.titled(&title, ("sans-serif", 13)).map_err(|e| err(&e))?;
        let (left, right) = root.split_horizontally(550);
        panel(&left, &data, 0, "translations", "nm").map_err(|e| err(&e))?;
        panel(&right, &data, 3, "rotations", "nrad").map_err(|e| err(&e))?;
        root.present().map_err(|e| err(&e))?;
    }
    write_file(path, &svg, force)?;
    Ok(())
}

fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    data: &[Row],
    first: usize,
    title: &str,
    unit: &str,
) -> Result<(), DrawingAreaErrorKind<DB::ErrorType>> {
    let ymax = data
        .iter()
        .flat_map(|r| (first..first + 3).flat_map(|j| [r.high[j], r.measured[j].unwrap_or(0.0)]))
        .fold(0.0, f64::max)
        .max(1e-12)
        * 1.15;
    let labels: Vec<String> = data.iter().map(|r| r.label.clone()).collect();
    let mut chart = ChartBuilder::on(area)
        .caption(format!("predicted σ with 90 % prediction interval, {title}"), ("sans-serif", 16))
        .margin(12)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(-0.5f64..(data.len() as f64 - 0.5), 0f64..ymax)?;
    let fmt = |v: &f64| {
        let r = v.round();
        if (v - r).abs() < 1e-6 && r >= 0.0 && (r as usize) < labels.len() {
            labels[r as usize].clone()
        } else {
            String::new()
        }
    };
    chart
        .configure_mesh()
        .disable_x_mesh()
        .x_labels(data.len())
        .x_label_formatter(&fmt)
        .x_desc("scene")
        .y_desc(format!("σ [{unit}]"))
        .draw()?;
    let colors = [RGBColor(31, 119, 180), RGBColor(214, 39, 40), RGBColor(44, 160, 44)];
    for (c, j) in (first..first + 3).enumerate() {
        let col = colors[c];
        let dx = (c as f64 - 1.0) * 0.2;
        let bars = data.iter().enumerate().map(move |(i, r)| {
            PathElement::new(
                vec![(i as f64 + dx, r.low[j]), (i as f64 + dx, r.high[j])],
                col.stroke_width(2),
            )
        });
        chart.draw_series(bars)?;
        chart
            .draw_series(
                data.iter()
                    .enumerate()
                    .map(move |(i, r)| Circle::new((i as f64 + dx, r.sigma[j]), 4, col.filled())),
            )?
            .label(Dof::ALL[j].name())
            .legend(move |(x, y)| Circle::new((x + 6, y), 4, col.filled()));
        let crosses = chart.draw_series(data.iter().enumerate().filter_map(move |(i, r)| {
            r.measured[j].map(|m| Cross::new((i as f64 + dx, m), 6, BLACK.stroke_width(2)))
        }))?;
        if c == 2 && data.iter().any(|r| r.measured.iter().any(Option::is_some)) {
            crosses
                .label("measured (raw)")
                .legend(|(x, y)| Cross::new((x + 6, y), 5, BLACK.stroke_width(2)));
        }
    }
    chart
        .configure_series_labels()
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()?;
    Ok(())
}
