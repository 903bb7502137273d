//! Sensitivity of one block (`--sensitivity`): one panel per DOF (and
//! direction of the point), the
//! inputs along x, per input three bars, each series one colour in every
//! panel: the variance share of the linear fit (normalised SRC^2), the
//! first-order Sobol index S and the total index ST, the two Sobol bars
//! with their 90 % bootstrap intervals as error bars. Indices in [0, 1].

use plotters::prelude::*;

use super::{PlotError, Result, check_finite, color, plot_err};
use crate::report::study::labels::{block_label, output_point};
use crate::study::sensitivity::SensitivityBlock;

/// The three series: label and colour index (the palette's, as every chart).
const SERIES: [(&str, usize); 3] =
    [("variance share (SRC²)", 0), ("Sobol S (first order)", 1), ("Sobol ST (total)", 2)];

/// One DOF's bars: per input (share, S, ST) and the intervals of S and ST.
struct DofBars {
    label: String,
    values: Vec<[Option<f64>; 3]>,
    intervals: Vec<[Option<(f64, f64)>; 2]>,
}

/// The chart of `block` (module docs); `what` heads it.
pub fn sensitivity_svg(block: &SensitivityBlock, what: &str) -> Result<String> {
    let names: Vec<String> = block.inputs.iter().map(|i| i.name()).collect();
    if names.is_empty() || block.dofs.is_empty() {
        return Err(PlotError::NothingToPlot("no inputs or outputs".into()));
    }
    let dofs = bars(block);
    check_finite(
        dofs.iter().flat_map(|d| d.values.iter().flatten().flatten()),
        "sensitivity indices",
    )?;
    let mut svg = String::new();
    {
        let width = (180 + 40 * names.len() as u32).clamp(360, 700);
        let rows = dofs.len().div_ceil(3);
        let root = SVGBackend::with_string(&mut svg, (3 * width, rows as u32 * 330 + 44))
            .into_drawing_area();
        root.fill(&WHITE).map_err(plot_err)?;
        let (top, body) = root.split_vertically(44);
        let title = Text::new(what.to_string(), (12, 4), ("sans-serif", 18));
        top.draw(&title).map_err(plot_err)?;
        legend(&top)?;
        for (area, d) in body.split_evenly((rows, 3)).iter().zip(&dofs) {
            panel(area, d, &names)?;
        }
        root.present().map_err(plot_err)?;
    }
    Ok(svg)
}

/// The bars of each DOF of the block (in the order of its outputs).
fn bars(block: &SensitivityBlock) -> Vec<DofBars> {
    let n = block.inputs.len();
    let point = block.dofs.first().map_or("", |d| output_point(&d.output));
    (block.dofs.iter().enumerate())
        .map(|(k, d)| {
            let sobol = block.sobol.as_ref().and_then(|s| s.dofs.get(k)?.indices.as_ref());
            let values = (0..n)
                .map(|j| {
                    [d.share.get(j).copied(), sobol.map(|x| x.first[j]), sobol.map(|x| x.total[j])]
                })
                .collect();
            let intervals = (0..n)
                .map(|j| {
                    [
                        sobol.map(|x| (x.first_ci90_low[j], x.first_ci90_high[j])),
                        sobol.map(|x| (x.total_ci90_low[j], x.total_ci90_high[j])),
                    ]
                })
                .collect();
            DofBars { label: block_label(point, &d.output, true), values, intervals }
        })
        .collect()
}

/// The legend row: a swatch and the label of each series, one colour each.
fn legend<DB: DrawingBackend>(area: &DrawingArea<DB, plotters::coord::Shift>) -> Result<()> {
    let (w, _) = area.dim_in_pixel();
    let step = (w as i32 - 40) / 4;
    for (i, (label, c)) in SERIES.iter().enumerate() {
        let x = 20 + step * (i as i32 + 1) - step / 2;
        let swatch = Rectangle::new([(x, 26), (x + 14, 36)], color(*c).filled());
        area.draw(&swatch).map_err(plot_err)?;
        let text = Text::new(*label, (x + 20, 26), ("sans-serif", 14));
        area.draw(&text).map_err(plot_err)?;
    }
    Ok(())
}

/// One DOF's panel: per input the three bars and the two error bars.
fn panel<DB: DrawingBackend>(
    area: &DrawingArea<DB, plotters::coord::Shift>,
    d: &DofBars,
    names: &[String],
) -> Result<()> {
    let m = names.len();
    let mut chart = ChartBuilder::on(area)
        .caption(&d.label, ("sans-serif", 17))
        .margin(8)
        .x_label_area_size(40)
        .y_label_area_size(45)
        .build_cartesian_2d(-0.5f64..(m as f64 - 0.5), 0f64..1.05f64)
        .map_err(plot_err)?;
    let label = |v: &f64| {
        let r = v.round();
        let ok = (v - r).abs() < 1e-6 && r >= 0.0 && (r as usize) < m;
        if ok { names[r as usize].clone() } else { String::new() }
    };
    chart
        .configure_mesh()
        .label_style(("sans-serif", 12))
        .disable_x_mesh()
        .x_labels(m)
        .x_label_formatter(&label)
        .y_desc("index or share [1]")
        .draw()
        .map_err(plot_err)?;
    let width = 0.8 / 3.0;
    for (s, (_, c)) in SERIES.iter().enumerate() {
        let col = color(*c);
        let x0 = move |j: usize| j as f64 - 0.4 + s as f64 * width;
        let rects = (d.values.iter().enumerate())
            .filter_map(|(j, v)| v[s].map(|y| (j, y.max(0.0))))
            .map(|(j, y)| Rectangle::new([(x0(j), 0.0), (x0(j) + width, y)], col.filled()));
        chart.draw_series(rects).map_err(plot_err)?;
        if s == 0 {
            continue;
        }
        let whiskers = (d.intervals.iter().enumerate())
            .filter_map(|(j, iv)| iv[s - 1].map(|(lo, hi)| (j, lo.max(0.0), hi.min(1.05))))
            .map(|(j, lo, hi)| {
                let xm = x0(j) + width / 2.0;
                PathElement::new([(xm, lo), (xm, hi)], BLACK.stroke_width(2))
            });
        chart.draw_series(whiskers).map_err(plot_err)?;
    }
    Ok(())
}
