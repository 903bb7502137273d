//! Grouped bar chart of sigma per variant and DOF, with the 90 % interval of
//! each sigma as an error bar and reference values as black ticks.

use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

use super::{PlotError, Result};
use super::{VariantSigma, check_finite, color, draw_legend, headroom, legend_room, plot_err};
use crate::dof::Dof;

/// An SVG with two panels, translations \[nm\] and rotations \[nrad\]: one
/// group of bars per DOF, one bar per variant, a vertical error bar from the
/// low to the high end of the interval of sigma (where there is one), a
/// black tick at each reference value, and a legend with the variant names.
/// `what` heads the panels (e.g. "re-seating σ", "interchangeability σ").
pub fn sigma_bars_svg(data: &[VariantSigma], what: &str) -> Result<String> {
    if data.is_empty() {
        return Err(PlotError::NothingToPlot("no variants".into()));
    }
    check_finite(data.iter().flat_map(|v| v.sigma.iter()), "sigma")?;
    check_finite(
        data.iter().filter_map(|v| v.interval.as_ref()).flat_map(|(l, h)| l.iter().chain(h.iter())),
        "interval of sigma",
    )?;
    check_finite(
        data.iter().filter_map(|v| v.reference.as_ref()).flat_map(|r| r.iter().flatten()),
        "reference sigma",
    )?;
    for v in data {
        if let Some((d, s)) = v.sigma.iter().enumerate().find(|(_, s)| **s < 0.0) {
            return Err(PlotError::InvalidParameter(format!(
                "variant `{}`: sigma of {} = {s} is negative (a standard deviation is >= 0)",
                v.variant,
                Dof::ALL[d].name()
            )));
        }
    }
    let mut svg = String::new();
    {
        let entries = data.len() + usize::from(data.iter().any(|v| v.reference.is_some()));
        let height = 480 + 12 * entries.saturating_sub(4) as u32;
        let root = SVGBackend::with_string(&mut svg, (1100, height)).into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let (left, right) = root.split_horizontally(550);
        let translations = [Dof::X, Dof::Y, Dof::Z];
        let rotations = [Dof::PhiX, Dof::PhiY, Dof::PhiZ];
        panel(&left, data, &translations, &format!("{what}, translations"), true)?;
        panel(&right, data, &rotations, &format!("{what}, rotations"), false)?;
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}

fn idx(d: Dof) -> usize {
    Dof::ALL.iter().position(|&x| x == d).unwrap_or(0)
}

/// The largest value drawn in the panel: bar, interval top or reference.
fn panel_max(data: &[VariantSigma], dofs: &[Dof]) -> f64 {
    data.iter()
        .flat_map(|v| {
            dofs.iter().map(move |&d| {
                let k = idx(d);
                let hi = v.interval.map_or(0.0, |(_, h)| h[k]);
                let rf = v.reference.and_then(|r| r[k]).unwrap_or(0.0);
                v.sigma[k].max(hi).max(rf)
            })
        })
        .fold(0.0, f64::max)
}

type Chart<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// One panel: the axes with the DOF names, per variant its bars and marks
/// ([`variant_bars`]), the legend entry of the marks ([`marks_legend`]),
/// and the legend box if `legend`.
fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    data: &[VariantSigma],
    dofs: &[Dof],
    title: &str,
    legend: bool,
) -> Result<()> {
    let m = dofs.len();
    // Room above the bars for the legend box (about one line per entry).
    let has_ref = data.iter().any(|v| v.reference.is_some());
    let has_ci = data.iter().any(|v| v.interval.is_some());
    let entries = data.len() + usize::from(has_ref || has_ci);
    let (_, height) = area.dim_in_pixel();
    let room = if legend { legend_room(entries, f64::from(height) - 100.0) } else { 1.0 };
    let mut chart = ChartBuilder::on(area)
        .caption(title, ("sans-serif", 20))
        .margin(12)
        .x_label_area_size(45)
        .y_label_area_size(75)
        .build_cartesian_2d(
            -0.5f64..(m as f64 - 0.5),
            0f64..headroom(panel_max(data, dofs) * room)?,
        )
        .map_err(plot_err)?;
    axes(&mut chart, dofs)?;
    let width = 0.8 / data.len() as f64;
    for (v, variant) in data.iter().enumerate() {
        variant_bars(&mut chart, v, variant, dofs, width)?;
    }
    marks_legend(&mut chart, has_ref, has_ci)?;
    if !legend {
        return Ok(());
    }
    draw_legend(&mut chart, 15)
}

/// The mesh: one x label per DOF (its name at the integer positions), the
/// y axis in the DOFs' unit.
fn axes<DB: DrawingBackend>(chart: &mut Chart<DB>, dofs: &[Dof]) -> Result<()> {
    let unit = dofs[0].unit();
    let names: Vec<&str> = dofs.iter().map(|d| d.symbol()).collect();
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
        .x_labels(dofs.len())
        .x_label_formatter(&fmt)
        .x_desc("degree of freedom")
        .y_desc(format!("σ [{unit}]"))
        .draw()
        .map_err(plot_err)
}

/// Variant `v`'s bars (one per DOF, `width` wide, its legend entry) and
/// their error bars and reference ticks.
fn variant_bars<DB: DrawingBackend>(
    chart: &mut Chart<DB>,
    v: usize,
    variant: &VariantSigma,
    dofs: &[Dof],
    width: f64,
) -> Result<()> {
    let col = color(v);
    let x0 = move |c: usize| c as f64 - 0.4 + v as f64 * width;
    let bars = dofs.iter().enumerate().map(move |(c, &d)| {
        Rectangle::new([(x0(c), 0.0), (x0(c) + width, variant.sigma[idx(d)])], col.filled())
    });
    chart
        .draw_series(bars)
        .map_err(plot_err)?
        .label(variant.variant.as_str())
        .legend(move |(x, y)| Rectangle::new([(x, y - 5), (x + 12, y + 5)], col.filled()));
    chart.draw_series(marks(variant, dofs, &x0, width)).map_err(plot_err)?;
    Ok(())
}

/// An empty series that carries the legend entry of the marks (reference
/// ticks and/or interval bars), if any variant has them.
fn marks_legend<DB: DrawingBackend>(
    chart: &mut Chart<DB>,
    has_ref: bool,
    has_ci: bool,
) -> Result<()> {
    let mark_label = match (has_ref, has_ci) {
        (true, true) => Some("reference value (tick); 90 % interval (bar)"),
        (true, false) => Some("reference value (tick)"),
        (false, true) => Some("90 % interval of σ (error bar)"),
        (false, false) => None,
    };
    if let Some(label) = mark_label {
        let width = if has_ref { 4 } else { 2 };
        chart
            .draw_series(std::iter::empty::<PathElement<(f64, f64)>>())
            .map_err(plot_err)?
            .label(label)
            .legend(move |(x, y)| {
                PathElement::new([(x, y), (x + 12, y)], BLACK.stroke_width(width))
            });
    }
    Ok(())
}

/// The error bars (a vertical line from the low to the high end of the
/// interval, caps a third of the bar wide) and the reference ticks (across
/// the bar, thicker) of one variant; bar c spans [x0(c), x0(c) + width].
fn marks(
    variant: &VariantSigma,
    dofs: &[Dof],
    x0: &dyn Fn(usize) -> f64,
    width: f64,
) -> Vec<PathElement<(f64, f64)>> {
    let mut out = Vec::new();
    for (c, &d) in dofs.iter().enumerate() {
        let k = idx(d);
        if let Some((lo, hi)) = variant.interval {
            let (xm, cap) = (x0(c) + width / 2.0, width / 6.0);
            let style = BLACK.stroke_width(2);
            out.push(PathElement::new([(xm, lo[k]), (xm, hi[k])], style));
            out.push(PathElement::new([(xm - cap, lo[k]), (xm + cap, lo[k])], style));
            out.push(PathElement::new([(xm - cap, hi[k]), (xm + cap, hi[k])], style));
        }
        if let Some(y) = variant.reference.and_then(|r| r[k]) {
            out.push(PathElement::new([(x0(c), y), (x0(c) + width, y)], BLACK.stroke_width(4)));
        }
    }
    out
}
