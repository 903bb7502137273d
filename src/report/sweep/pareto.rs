//! The sweep's Pareto chart: every evaluated design at (lowest principal
//! stiffness [N/um], largest translational sigma [nm]), the front in
//! colour, each front point labelled `#index` (the `#` of the table of
//! design points). Labels are placed ([`place_labels`]) so that none
//! overlaps another label or a marker and none leaves the plot; a label
//! pushed away from its point is joined to it by a thin line. The data
//! (which designs, where) come from `report::sweep::plot`.

use super::SweepPlotError;
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::explore::DesignReport;
use crate::report::study::plot::color;

/// Label font size [px] and the width of one of its characters (digits
/// and `#` of a sans-serif font, rounded up) [px].
const FONT: f64 = 12.0;
const CHAR_W: f64 = 7.0;
/// Marker radius [px].
const MARKER: f64 = 4.0;

/// An axis-aligned box in pixels: x0, y0, x1, y1.
pub type PixelBox = [f64; 4];

fn overlap(a: &PixelBox, b: &PixelBox) -> f64 {
    let w = a[2].min(b[2]) - a[0].max(b[0]);
    let h = a[3].min(b[3]) - a[1].max(b[1]);
    if w > 0.0 && h > 0.0 { w * h } else { 0.0 }
}

/// Boxes for labels of sizes `sizes[i]` (w, h) at the markers
/// `points[labelled[i]]`, inside `bounds`: per label the first free spot
/// of 8 directions on rings of growing distance from its point (free: no
/// overlap with a placed label or any marker), else the spot of least
/// overlap. Greedy, in the order given.
pub fn place_labels(
    points: &[(f64, f64)],
    labelled: &[usize],
    sizes: &[(f64, f64)],
    bounds: PixelBox,
) -> Vec<PixelBox> {
    let markers: Vec<PixelBox> =
        points.iter().map(|&(x, y)| [x - MARKER, y - MARKER, x + MARKER, y + MARKER]).collect();
    let mut placed: Vec<PixelBox> = Vec::new();
    for (&i, &(w, h)) in labelled.iter().zip(sizes) {
        let (px, py) = points[i];
        let mut best: Option<(f64, PixelBox)> = None;
        'rings: for ring in 1..=6 {
            let d = MARKER + 2.0 + (ring - 1) as f64 * h;
            // Right, left, above, below, then the diagonals.
            for (ux, uy) in [
                (1.0, 0.0),
                (-1.0, 0.0),
                (0.0, -1.0),
                (0.0, 1.0),
                (1.0, -1.0),
                (-1.0, -1.0),
                (1.0, 1.0),
                (-1.0, 1.0),
            ] {
                let x0 = px + ux * d + (ux - 1.0) * w / 2.0;
                let y0 = py + uy * d + (uy - 1.0) * h / 2.0;
                let b = [x0, y0, x0 + w, y0 + h];
                if b[0] < bounds[0] || b[1] < bounds[1] || b[2] > bounds[2] || b[3] > bounds[3] {
                    continue;
                }
                let cost: f64 = placed.iter().chain(&markers).map(|o| overlap(&b, o)).sum();
                if best.is_none_or(|(c, _)| cost < c) {
                    best = Some((cost, b));
                }
                if cost == 0.0 {
                    break 'rings;
                }
            }
        }
        // A plot narrower than a label: at the point, clamped into bounds.
        let b = best.map_or_else(
            || {
                let x0 = (px + MARKER).min(bounds[2] - w).max(bounds[0]);
                let y0 = (py - h / 2.0).min(bounds[3] - h).max(bounds[1]);
                [x0, y0, x0 + w, y0 + h]
            },
            |(_, b)| b,
        );
        placed.push(b);
    }
    placed
}

/// A panel's caption, axis titles and ranges.
pub struct Axes {
    pub caption: String,
    pub x: String,
    pub y: String,
    pub x_range: (f64, f64),
    pub y_range: (f64, f64),
}

/// The chart into `area`: `pts` the feasible evaluated designs at their
/// (x, y), the front coloured and labelled, the dominated grey;
/// `infeasible` the designs that break a constraint, grey crosses (the
/// error: plotters' message).
pub fn draw(
    axes: &Axes,
    pts: &[(f64, f64, &DesignReport)],
    infeasible: &[(f64, f64)],
    area: &DrawingArea<SVGBackend<'_>, Shift>,
) -> Result<(), SweepPlotError> {
    let draw_err = |e: DrawingAreaErrorKind<_>| SweepPlotError::Draw(e.to_string());
    let ((x0, x1), (y0, y1)) = (axes.x_range, axes.y_range);
    let mut chart = ChartBuilder::on(area)
        .caption(&axes.caption, ("sans-serif", 16))
        .margin(10)
        .margin_right(24)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(x0..x1, y0..y1)
        .map_err(draw_err)?;
    chart
        .configure_mesh()
        .x_desc(&axes.x)
        .y_desc(&axes.y)
        .x_labels(5)
        .y_labels(5)
        .label_style(("sans-serif", 12))
        .draw()
        .map_err(draw_err)?;
    let grey = RGBColor(150, 150, 150);
    let crosses = infeasible.iter().map(|&(x, y)| Cross::new((x, y), 4, grey.stroke_width(2)));
    chart.draw_series(crosses).map_err(draw_err)?;
    for (x, y, d) in pts {
        let col = match d.pareto == Some(true) {
            true => color(5),
            false => RGBColor(150, 150, 150),
        };
        chart
            .draw_series(std::iter::once(Circle::new((*x, *y), 4, col.filled())))
            .map_err(draw_err)?;
    }
    let base = area.get_base_pixel();
    let px: Vec<(f64, f64)> = pts
        .iter()
        .map(|p| {
            let (u, v) = chart.backend_coord(&(p.0, p.1));
            ((u - base.0) as f64, (v - base.1) as f64)
        })
        .collect();
    let front: Vec<usize> = (0..pts.len()).filter(|&i| pts[i].2.pareto == Some(true)).collect();
    let texts: Vec<String> = front.iter().map(|&i| format!("#{}", pts[i].2.index)).collect();
    let sizes: Vec<(f64, f64)> =
        texts.iter().map(|t| (CHAR_W * t.chars().count() as f64 + 2.0, FONT + 2.0)).collect();
    let (xr, yr) = chart.plotting_area().get_pixel_range();
    let bounds = [
        (xr.start - base.0) as f64,
        (yr.start - base.1) as f64,
        (xr.end - base.0) as f64,
        (yr.end - base.1) as f64,
    ];
    let boxes = place_labels(&px, &front, &sizes, bounds);
    for ((&i, text), b) in front.iter().zip(texts).zip(&boxes) {
        let (cx, cy) = ((b[0] + b[2]) / 2.0, (b[1] + b[3]) / 2.0);
        let (dx, dy) = (cx - px[i].0, cy - px[i].1);
        if dx.hypot(dy) > 2.5 * FONT {
            let to = (b[0].max(px[i].0.min(b[2])), b[1].max(px[i].1.min(b[3])));
            let line = [(px[i].0, px[i].1), to].map(|(x, y)| (x as i32, y as i32));
            area.draw(&PathElement::new(line, color(5).mix(0.6))).map_err(draw_err)?;
        }
        let at = ((b[0] + 1.0) as i32, (b[1] + 1.0) as i32);
        area.draw(&Text::new(text, at, ("sans-serif", FONT))).map_err(draw_err)?;
    }
    Ok(())
}
