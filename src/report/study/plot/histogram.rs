//! Histograms of one evaluation point's samples, one panel per DOF (and
//! direction), each with the normal distribution of the reported mean and
//! sigma drawn over it as expected counts: a reviewer sees whether +-3
//! sigma, a statement about a normal distribution, describes the samples
//! (a skewed or heavy-tailed scatter shows as bars outside the curve).

use plotters::prelude::*;

use super::{PlotError, Result, check_finite, color, plot_err};

/// One panel: its label (`x [nm]`, `along beam [nm]`), the samples and
/// the reported mean and sigma (same unit).
#[derive(Debug, Clone, PartialEq)]
pub struct HistogramPanel {
    pub label: String,
    pub values: Vec<f64>,
    pub mean: f64,
    pub sigma: f64,
}

/// Equal bins over [min, max] of `values`: the edges (bins + 1) and the
/// count in each; the last bin holds its upper edge. Bins by the Rice rule,
/// ceil(2 n^(1/3)), between 5 and 40. None for fewer than 2 values or
/// values that do not vary.
pub fn histogram(values: &[f64]) -> Option<(Vec<f64>, Vec<usize>)> {
    let lo = values.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = values.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if values.len() < 2 || hi <= lo || hi.is_nan() || lo.is_nan() || !(hi - lo).is_finite() {
        return None;
    }
    let bins = ((2.0 * (values.len() as f64).cbrt()).ceil() as usize).clamp(5, 40);
    let width = (hi - lo) / bins as f64;
    // The last edge is the largest value itself, not lo + bins width rounded.
    let edges: Vec<f64> =
        (0..=bins).map(|k| if k == bins { hi } else { lo + k as f64 * width }).collect();
    let mut counts = vec![0; bins];
    for v in values {
        let k = (((v - lo) / width).floor() as usize).min(bins - 1);
        counts[k] += 1;
    }
    Some((edges, counts))
}

/// The expected count of a normal(mean, sigma) sample of n in a bin of
/// `width` around x: n width phi((x - mean) / sigma) / sigma.
pub fn normal_count(x: f64, n: usize, width: f64, mean: f64, sigma: f64) -> f64 {
    let z = (x - mean) / sigma;
    n as f64 * width * (-0.5 * z * z).exp() / (sigma * (std::f64::consts::TAU).sqrt())
}

/// An SVG of `panels` (three per row), titled `title`, every panel in the
/// colour `series` (the point's colour in the other charts), the normal
/// curve in black.
pub fn histogram_svg(title: &str, panels: &[HistogramPanel], series: usize) -> Result<String> {
    if panels.is_empty() {
        return Err(PlotError::NothingToPlot("no samples".into()));
    }
    check_finite(panels.iter().flat_map(|p| p.values.iter()), "histogram samples")?;
    let cols = panels.len().min(3);
    let rows = panels.len().div_ceil(cols);
    let mut svg = String::new();
    {
        let size = (380 * cols as u32, 300 * rows as u32 + 40);
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let (top, body) = root.split_vertically(40);
        let text = Text::new(title.to_string(), (12, 8), ("sans-serif", 18));
        top.draw(&text).map_err(plot_err)?;
        for (p, area) in panels.iter().zip(body.split_evenly((rows, cols))) {
            panel(&area, p, color(series))?;
        }
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}

/// One DOF's bars and its normal curve.
fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    p: &HistogramPanel,
    col: RGBColor,
) -> Result<()> {
    let Some((edges, counts)) = histogram(&p.values) else {
        let text = Text::new(format!("{}: no scatter", p.label), (12, 20), ("sans-serif", 15));
        return area.draw(&text).map_err(plot_err);
    };
    let (lo, hi) = (edges[0], edges[edges.len() - 1]);
    let width = edges[1] - edges[0];
    let (n, s) = (p.values.len(), p.sigma);
    let curve: Vec<(f64, f64)> = (0..=80)
        .map(|k| lo + (hi - lo) * k as f64 / 80.0)
        .map(|x| (x, if s > 0.0 { normal_count(x, n, width, p.mean, s) } else { 0.0 }))
        .collect();
    let top = counts.iter().map(|&c| c as f64).chain(curve.iter().map(|c| c.1)).fold(0.0, f64::max);
    let mut chart = ChartBuilder::on(area)
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(45)
        .build_cartesian_2d(lo..hi, 0.0..top * 1.1)
        .map_err(plot_err)?;
    chart
        .configure_mesh()
        .label_style(("sans-serif", 13))
        .axis_desc_style(("sans-serif", 15))
        .x_labels(4)
        .y_labels(5)
        .y_label_formatter(&|v| format!("{v:.0}"))
        .x_desc(p.label.as_str())
        .y_desc("samples")
        .draw()
        .map_err(plot_err)?;
    let bars = (counts.iter().enumerate()).map(|(k, &c)| {
        Rectangle::new([(edges[k], 0.0), (edges[k + 1], c as f64)], col.mix(0.7).filled())
    });
    chart.draw_series(bars).map_err(plot_err)?;
    let line = LineSeries::new(curve, BLACK.stroke_width(2));
    chart.draw_series(line).map_err(plot_err)?;
    Ok(())
}
