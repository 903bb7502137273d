//! x-y scatter of the errors of the samples, one panel per variant and
//! evaluation point, each with the 90 % covariance ellipse of its samples.

use plotters::prelude::*;

use super::{PlotError, Result};
use super::{VariantScatter, check_finite, color, headroom, plot_err};

/// An SVG with one square panel per variant and evaluation point (grid),
/// captioned `variant · point (n samples)`, all with the same symmetric axes
/// `x [nm]`, `y [nm]` so that variants and points can be compared by eye.
/// Panel i has the colour of series i, as the bars of the same variants
/// and points (`charts::study_charts` passes both in one order). Each panel's ellipse
/// ([`covariance_ellipse`]) holds 90 % of a normal distribution with the
/// samples' mean and covariance. Five ticks per axis at most, so that
/// their labels stay apart in the narrowest panel.
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
    let mut svg = String::new();
    {
        let size = (420 * cols as u32, 420 * rows as u32);
        let root = SVGBackend::with_string(&mut svg, size).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        for (i, (panel, area)) in data.iter().zip(root.split_evenly((rows, cols))).enumerate() {
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
                .x_labels(5)
                .y_labels(5)
                .x_desc("x [nm]")
                .y_desc("y [nm]")
                .draw()
                .map_err(plot_err)?;
            // The series' colour: the i-th series of the page (variant, then
            // point), as in the sigma bars.
            let col = color(i);
            chart
                .draw_series(
                    panel.xy.iter().map(move |&(x, y)| Circle::new((x, y), 3, col.filled())),
                )
                .map_err(plot_err)?;
            if let Some(e) = covariance_ellipse(&panel.xy, ELLIPSE_LEVEL) {
                let line = PathElement::new(e, col.stroke_width(2));
                chart.draw_series(std::iter::once(line)).map_err(plot_err)?;
            }
        }
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}

/// The probability the scatter's ellipses hold.
pub const ELLIPSE_LEVEL: f64 = 0.90;

/// The ellipse holding `level` of a bivariate normal distribution with the
/// mean and sample covariance S (divisor n - 1) of `xy`: the points
/// m + sqrt(c) L (cos t, sin t), L L^T = S, c = -2 ln(1 - level) (the
/// chi-square quantile of 2 degrees of freedom, in closed form), 73
/// points, closed. None for fewer than 3 samples or a singular S.
pub fn covariance_ellipse(xy: &[(f64, f64)], level: f64) -> Option<Vec<(f64, f64)>> {
    let n = xy.len() as f64;
    if xy.len() < 3 || !(0.0..1.0).contains(&level) {
        return None;
    }
    let (mx, my) = xy.iter().fold((0.0, 0.0), |a, p| (a.0 + p.0 / n, a.1 + p.1 / n));
    let (mut sxx, mut sxy, mut syy) = (0.0, 0.0, 0.0);
    for &(x, y) in xy {
        let (dx, dy) = (x - mx, y - my);
        sxx += dx * dx / (n - 1.0);
        sxy += dx * dy / (n - 1.0);
        syy += dy * dy / (n - 1.0);
    }
    // Cholesky of [[sxx, sxy], [sxy, syy]].
    let l11 = sxx.sqrt();
    let l21 = sxy / l11;
    let l22 = (syy - l21 * l21).sqrt();
    if !(l11 > 0.0 && l22 > 0.0) {
        return None;
    }
    let c = (-2.0 * (1.0 - level).ln()).sqrt();
    let point = |k: usize| {
        let t = std::f64::consts::TAU * k as f64 / 72.0;
        let (u, v) = (c * t.cos(), c * t.sin());
        (mx + l11 * u, my + l21 * u + l22 * v)
    };
    Some((0..=72).map(point).collect())
}
