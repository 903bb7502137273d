//! The sweep's design charts as SVG (plotters): sigma against each swept
//! field with its 90 % interval as a band (one panel per DOF, one line per
//! combination of the other fields), a heat map of the largest
//! translational sigma over two fields (a grid of exactly two `--set`),
//! and the Pareto front (largest translational sigma against the lowest
//! principal stiffness, the front marked). Every chart carries the
//! provenance line. [`charts`] returns the SVG texts (for an HTML report),
//! [`stage_charts`] writes them to temporaries the caller commits.

use std::path::Path;

use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

pub use super::SweepPlotError;
use crate::dof::Dof;
use crate::explore::SweptValue;
use crate::explore::goal::{Objective, Output};
use crate::explore::{DesignReport, SweepReport};
use std::io::Write;

use crate::output::atomic::{AtomicFile, WriteError, check_overwrite};
use crate::report::study::plot::color;
use crate::report::sweep::text::field_label;
use crate::report::sweep::text::short as tick;
use crate::study::PointStats;

fn draw_err<E: std::fmt::Display>(e: E) -> SweepPlotError {
    SweepPlotError::Draw(e.to_string())
}

type Area<'a> = DrawingArea<SVGBackend<'a>, Shift>;
type Chart<'a, 'b> = ChartContext<'a, SVGBackend<'b>, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// The design charts as (file stem / title, SVG text), in a fixed order:
/// `sweep_sigma_<field>` per swept field, `sweep_heatmap` (grids of two
/// fields), `sweep_pareto` (when two or more designs were evaluated),
/// `sweep_not_evaluated` (when a design point was not evaluated:
/// `report::sweep::status`).
pub fn charts(r: &SweepReport) -> Result<Vec<(String, String)>, SweepPlotError> {
    let foot = r.produced_by();
    let mut out = Vec::new();
    for k in 0..r.sets.len() {
        let title = format!("sweep_sigma_{}", r.sets[k].field.replace('.', "_"));
        let size = (1200, 760 + legend_height(groups(r, k).len()));
        out.push((title, svg(&foot, size, |a| sigma_chart(r, k, a))?));
    }
    if r.sets.len() == 2 && r.design.name() == "grid" {
        out.push(("sweep_heatmap".to_string(), svg(&foot, (1200, 700), |a| heatmap(r, a))?));
    }
    let objectives = r.goals.objectives.len();
    if objectives >= 2 {
        let panels = objectives * (objectives - 1) / 2;
        let size = (1200, if panels == 1 { 700 } else { 60 + 420 * panels.div_ceil(3) as u32 });
        out.push(("sweep_pareto".to_string(), svg(&foot, size, |a| goal_front_chart(r, a))?));
    } else if objectives == 0 && r.designs.iter().filter(|d| r.objectives(d).is_some()).count() >= 2
    {
        out.push(("sweep_pareto".to_string(), svg(&foot, (1200, 700), |a| pareto_chart(r, a))?));
    }
    if !super::status::not_evaluated(r).is_empty() {
        let size = (1200, super::status::height(r));
        let chart = svg(&foot, size, |a| super::status::draw(r, a))?;
        out.push(("sweep_not_evaluated".to_string(), chart));
    }
    Ok(out)
}

/// Write [`charts`] as `<title>.svg` into `dir` under temporary names
/// (none if any exists, unless `force`), for the caller to commit all at
/// once ([`crate::output::atomic::commit_all`]).
pub fn stage_charts(
    r: &SweepReport,
    dir: &Path,
    force: bool,
) -> Result<Vec<AtomicFile>, SweepPlotError> {
    std::fs::create_dir_all(dir).map_err(|e| WriteError::io(dir, e))?;
    let all = charts(r)?;
    for (t, _) in &all {
        check_overwrite(&dir.join(format!("{t}.svg")), force)?;
    }
    let stage = |(t, text): (String, String)| {
        let p = dir.join(format!("{t}.svg"));
        let mut f = AtomicFile::create(&p, force)?;
        f.write_all(text.as_bytes()).map_err(|e| WriteError::io(&p, e))?;
        Ok(f)
    };
    all.into_iter().map(stage).collect()
}

/// Draw into an SVG string; the provenance line goes at the bottom.
fn svg(
    footer: &str,
    size: (u32, u32),
    draw: impl FnOnce(&Area) -> Result<(), SweepPlotError>,
) -> Result<String, SweepPlotError> {
    let mut s = String::new();
    {
        let root = SVGBackend::with_string(&mut s, size).into_drawing_area();
        root.fill(&WHITE).map_err(draw_err)?;
        let (body, foot) = root.split_vertically(size.1 - 22);
        draw(&body)?;
        foot.draw(&Text::new(
            footer.to_string(),
            (8, 4),
            ("sans-serif", 12).into_font().color(&BLACK.mix(0.7)),
        ))
        .map_err(draw_err)?;
        root.present().map_err(draw_err)?;
    }
    Ok(s)
}

/// The x coordinate of a swept value: the number, or the index of a name.
fn x_of(r: &SweepReport, k: usize, v: &SweptValue) -> f64 {
    match v {
        SweptValue::Number(x) => *x,
        SweptValue::Name(_) => levels(r, k).iter().position(|m| m == v).unwrap_or(0) as f64,
    }
}

fn point<'a>(r: &SweepReport, d: &'a DesignReport) -> Option<&'a PointStats> {
    d.points.iter().find(|p| p.name == r.pareto_point)
}

/// Evaluated designs grouped by the values of every field but `k`: (label,
/// [(x, design)] sorted by x).
type Groups<'a> = Vec<(String, Vec<(f64, &'a DesignReport)>)>;

fn groups(r: &SweepReport, k: usize) -> Groups<'_> {
    let mut groups: Groups = Vec::new();
    for d in r.designs.iter().filter(|d| point(r, d).is_some()) {
        let label: Vec<String> = r
            .sets
            .iter()
            .enumerate()
            .filter(|(j, _)| *j != k)
            .map(|(_, s)| {
                let v = d.values.get(&s.field).map_or(String::new(), value_tick);
                // With its unit (`preload.force = 26.67 N`); a name has none.
                match crate::report::sweep::text::field_unit(&s.field) {
                    "" | "-" => format!("{} = {v}", s.field),
                    unit => format!("{} = {v} {unit}", s.field),
                }
            })
            .collect();
        let label = label.join(", ");
        let x = d.values.get(&r.sets[k].field).map_or(0.0, |v| x_of(r, k, v));
        match groups.iter_mut().find(|(l, _)| *l == label) {
            Some((_, g)) => g.push((x, d)),
            None => groups.push((label, vec![(x, d)])),
        }
    }
    for (_, g) in &mut groups {
        g.sort_by(|a, b| a.0.total_cmp(&b.0));
    }
    groups
}

fn sigma_chart(r: &SweepReport, k: usize, area: &Area) -> Result<(), SweepPlotError> {
    let groups = groups(r, k);
    let title = format!("σ at {} against {} ({})", r.pareto_point, r.sets[k].field, r.name);
    let below = area.titled(&title, ("sans-serif", 20)).map_err(draw_err)?;
    let (legend_area, panels) = below.split_vertically(legend_height(groups.len()));
    legend(&groups, &legend_area)?;
    let xs: Vec<f64> = groups.iter().flat_map(|(_, g)| g.iter().map(|p| p.0)).collect();
    let xr = span(&xs);
    for (j, cell) in panels.split_evenly((2, 3)).iter().enumerate() {
        // Per group: (x, sigma, interval low, high) of DOF j [nm or nrad].
        let series: Vec<(RGBColor, Vec<[f64; 4]>)> = groups
            .iter()
            .map(|(label, g)| {
                let rows = g
                    .iter()
                    .filter_map(|(x, d)| {
                        let p = point(r, d)?;
                        let ci =
                            |c: &Option<crate::study::Dofs>| c.map_or(f64::NAN, |c| c.values()[j]);
                        Some([
                            *x,
                            p.sigma.values()[j],
                            ci(&p.sigma_ci90_low),
                            ci(&p.sigma_ci90_high),
                        ])
                    })
                    .collect();
                (color_of(label, &groups), rows)
            })
            .collect();
        dof_panel(r, k, Dof::ALL[j], &series, cell, xr)?;
    }
    Ok(())
}

/// Lines of the legend shown; the rest are counted in a last line.
const LEGEND_LINES: usize = 8;

/// Height [px] of the legend strip above the panels (none for one group).
fn legend_height(groups: usize) -> u32 {
    match groups {
        0 | 1 => 0,
        n => 8 + 16 * n.min(LEGEND_LINES + 1) as u32,
    }
}

/// Colour of the group `label`: its position among the groups.
fn color_of(label: &str, groups: &Groups) -> RGBColor {
    color(groups.iter().position(|(l, _)| l == label).unwrap_or(0))
}

/// The legend of the groups in a strip of its own above the panels, so
/// that it covers no curve: per group a line in its colour and its label.
fn legend(groups: &Groups, area: &Area) -> Result<(), SweepPlotError> {
    if groups.len() < 2 {
        return Ok(());
    }
    let font = ("sans-serif", 13).into_font();
    for (i, (label, _)) in groups.iter().take(LEGEND_LINES).enumerate() {
        let y = 12 + 16 * i as i32;
        let col = color(i);
        area.draw(&PathElement::new(vec![(70, y), (96, y)], col.stroke_width(3)))
            .map_err(draw_err)?;
        area.draw(&Text::new(label.clone(), (104, y - 7), font.clone())).map_err(draw_err)?;
    }
    if groups.len() > LEGEND_LINES {
        let more = format!("and {} more lines", groups.len() - LEGEND_LINES);
        let y = 5 + 16 * LEGEND_LINES as i32;
        area.draw(&Text::new(more, (104, y), font)).map_err(draw_err)?;
    }
    Ok(())
}

/// One DOF's panel: per group the sigma line and dots, the interval as a
/// band and as bars.
fn dof_panel(
    r: &SweepReport,
    k: usize,
    dof: Dof,
    series: &[(RGBColor, Vec<[f64; 4]>)],
    cell: &Area,
    (x0, x1): (f64, f64),
) -> Result<(), SweepPlotError> {
    let ymax = series
        .iter()
        .flat_map(|(_, g)| g.iter().flat_map(|v| [v[1], v[3]]))
        .filter(|y| y.is_finite())
        .fold(0.0, f64::max);
    let mut chart = ChartBuilder::on(cell)
        .margin(8)
        .x_label_area_size(36)
        .y_label_area_size(62)
        .build_cartesian_2d(x0..x1, 0.0..(if ymax > 0.0 { ymax * 1.1 } else { 1.0 }))
        .map_err(draw_err)?;
    let material = r.sets[k].kind != crate::explore::FieldKind::Number;
    let level_names = levels(r, k);
    let fmt = |v: &f64| match material {
        true => (level_names.get(v.round().max(0.0) as usize)).map_or(String::new(), value_tick),
        false => tick(*v),
    };
    chart
        .configure_mesh()
        .label_style(("sans-serif", 12))
        .x_label_formatter(&fmt)
        .x_desc(field_label(&r.sets[k].field))
        .y_desc(format!("σ_{} [{}]", dof.symbol(), dof.unit()))
        .draw()
        .map_err(draw_err)?;
    for (col, g) in series {
        group(&mut chart, *col, g)?;
    }
    Ok(())
}

/// One group's sigma line and dots, its interval as a band (where every
/// point has one) and as bars.
/// Rows of `g`: [x, sigma, interval low, interval high].
fn group(chart: &mut Chart, col: RGBColor, g: &[[f64; 4]]) -> Result<(), SweepPlotError> {
    let band: Vec<(f64, f64)> = g
        .iter()
        .map(|v| (v[0], v[3]))
        .chain(g.iter().rev().map(|v| (v[0], v[2])))
        .filter(|p| p.1.is_finite())
        .collect();
    if g.len() > 1 && band.len() == 2 * g.len() {
        chart
            .draw_series(std::iter::once(Polygon::new(band, col.mix(0.2).filled())))
            .map_err(draw_err)?;
    }
    let bars = g.iter().filter(|v| v[2].is_finite() && v[3].is_finite());
    chart
        .draw_series(bars.map(|v| PathElement::new(vec![(v[0], v[2]), (v[0], v[3])], col)))
        .map_err(draw_err)?;
    chart
        .draw_series(g.iter().map(|v| Circle::new((v[0], v[1]), 3, col.filled())))
        .map_err(draw_err)?;
    chart
        .draw_series(LineSeries::new(g.iter().map(|v| (v[0], v[1])), col.stroke_width(2)))
        .map_err(draw_err)?;
    Ok(())
}

/// A swept value as a tick label.
fn value_tick(v: &SweptValue) -> String {
    match v {
        SweptValue::Number(x) => tick(*x),
        SweptValue::Name(n) => n.clone(),
    }
}

/// Axis span of `xs` with 5 % margins (a unit span around a single value).
fn span(xs: &[f64]) -> (f64, f64) {
    let lo = xs.iter().copied().fold(f64::INFINITY, f64::min);
    let hi = xs.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    if !lo.is_finite() || !hi.is_finite() {
        return (0.0, 1.0);
    }
    let w = if hi > lo { 0.05 * (hi - lo) } else { 0.5 * lo.abs().max(1.0) };
    (lo - w, hi + w)
}

/// Colour of t in [0, 1] (blue - green - yellow, after viridis).
fn ramp(t: f64) -> RGBColor {
    let stops = [(68.0, 1.0, 84.0), (33.0, 145.0, 140.0), (253.0, 231.0, 37.0)];
    let t = t.clamp(0.0, 1.0) * 2.0;
    let i = (t as usize).min(1);
    let f = t - i as f64;
    let mix = |a: f64, b: f64| (a + f * (b - a)).round() as u8;
    let (a, b) = (stops[i], stops[i + 1]);
    RGBColor(mix(a.0, b.0), mix(a.1, b.1), mix(a.2, b.2))
}

/// Largest translational sigma at the Pareto point [nm].
fn sigma_max(r: &SweepReport, d: &DesignReport) -> Option<f64> {
    let s = point(r, d)?.sigma.values();
    Some(s[0].max(s[1]).max(s[2]))
}

/// The distinct values of field `k`, in design order.
fn levels(r: &SweepReport, k: usize) -> Vec<SweptValue> {
    let mut v: Vec<SweptValue> = Vec::new();
    for d in &r.designs {
        if let Some(x) = d.values.get(&r.sets[k].field)
            && !v.contains(x)
        {
            v.push(x.clone());
        }
    }
    v
}

/// The Pareto chart (`report::sweep::pareto`) of the evaluated designs on
/// the default objectives: the largest translational sigma against k_min.
fn pareto_chart(r: &SweepReport, area: &Area) -> Result<(), SweepPlotError> {
    let at = |d: &DesignReport| Some((r.objectives(d)?.stiffness_min * 1e-6, sigma_max(r, d)?));
    let (mut pts, mut off) = (Vec::new(), Vec::new());
    for d in &r.designs {
        match (at(d), d.broken_constraints.is_empty()) {
            (Some((x, y)), true) => pts.push((x, y, d)),
            (Some(xy), false) => off.push(xy),
            _ => {}
        }
    }
    let xs: Vec<f64> = pts.iter().map(|p| p.0).chain(off.iter().map(|p| p.0)).collect();
    let ymax = pts.iter().map(|p| p.1).chain(off.iter().map(|p| p.1)).fold(0.0, f64::max);
    let axes = super::pareto::Axes {
        caption: "Pareto front: lower σ, higher k_min, higher SF_p (front: coloured, labelled with the # of the table)".to_string(),
        x: "lowest principal translational stiffness k_min [N/µm]".to_string(),
        y: format!("largest translational σ at {} [nm]", r.pareto_point),
        x_range: span(&xs),
        y_range: (0.0, (ymax * 1.15).max(1e-12)),
    };
    super::pareto::draw(&axes, &pts, &off, area)
}

/// An objective's value in the chart's unit (sigma in nm or nrad, k_min
/// in N/µm, others as they are) and its axis title.
fn objective_axis(o: &Objective) -> (f64, String) {
    let name = o.name();
    match (&o.output, o.output.unit()) {
        (
            Output::Sigma { .. }
            | Output::Pm3sigma { .. }
            | Output::Drift { .. }
            | Output::Residual { .. },
            unit,
        ) if unit == "m" || unit == "rad" => {
            (1e9, format!("{name} [{}]", if unit == "m" { "nm" } else { "nrad" }))
        }
        (Output::KMin, _) => (1e-6, format!("{name} [N/µm]")),
        _ => (1.0, name),
    }
}

/// The front in the chosen objectives: one panel per pair of objectives
/// (a scatter matrix for three or more), the front coloured, dominated
/// designs grey, designs that break a constraint grey crosses.
fn goal_front_chart(r: &SweepReport, area: &Area) -> Result<(), SweepPlotError> {
    let objectives = &r.goals.objectives;
    let pairs: Vec<(usize, usize)> = (0..objectives.len())
        .flat_map(|i| (i + 1..objectives.len()).map(move |j| (i, j)))
        .collect();
    let cols = pairs.len().min(3);
    let panels = area.split_evenly((pairs.len().div_ceil(cols), cols));
    for (&(i, j), panel) in pairs.iter().zip(&panels) {
        let ((fx, tx), (fy, ty)) = (objective_axis(&objectives[i]), objective_axis(&objectives[j]));
        let at = |d: &DesignReport| {
            let v = |k: usize| objectives[k].output.value(d);
            Some((v(i)? * fx, v(j)? * fy))
        };
        let (mut pts, mut off) = (Vec::new(), Vec::new());
        for d in r.designs.iter().filter(|d| d.status == "ok") {
            match (at(d), d.broken_constraints.is_empty()) {
                (Some((x, y)), true) => pts.push((x, y, d)),
                (Some(xy), false) => off.push(xy),
                _ => {}
            }
        }
        let all = || pts.iter().map(|p| (p.0, p.1)).chain(off.iter().copied());
        let axes = super::pareto::Axes {
            caption: format!("front: {} and {}", objectives[i].name(), objectives[j].name()),
            x: tx,
            y: ty,
            x_range: span(&all().map(|p| p.0).collect::<Vec<_>>()),
            y_range: span(&all().map(|p| p.1).collect::<Vec<_>>()),
        };
        super::pareto::draw(&axes, &pts, &off, panel)?;
    }
    Ok(())
}

/// Heat map over the two fields of a grid: cells by level index, coloured
/// by the largest translational sigma; designs not evaluated are grey.
fn heatmap(r: &SweepReport, area: &Area) -> Result<(), SweepPlotError> {
    let (lx, ly) = (levels(r, 0), levels(r, 1));
    let values: Vec<f64> = r.designs.iter().filter_map(|d| sigma_max(r, d)).collect();
    let (vmin, vmax) = (
        values.iter().copied().fold(f64::INFINITY, f64::min),
        values.iter().copied().fold(f64::NEG_INFINITY, f64::max),
    );
    let title = format!(
        "largest translational σ at {} [nm] ({:.3} to {:.3}; grey: not evaluated)",
        r.pareto_point, vmin, vmax
    );
    let mut chart = ChartBuilder::on(area)
        .caption(title, ("sans-serif", 16))
        .margin(10)
        .x_label_area_size(40)
        .y_label_area_size(70)
        .build_cartesian_2d(-0.5..(lx.len() as f64 - 0.5), -0.5..(ly.len() as f64 - 0.5))
        .map_err(draw_err)?;
    let label = |v: &[SweptValue]| {
        let v = v.to_vec();
        move |x: &f64| v.get(x.round().max(0.0) as usize).map_or(String::new(), value_tick)
    };
    chart
        .configure_mesh()
        .disable_mesh()
        .x_labels(lx.len())
        .y_labels(ly.len())
        .x_label_formatter(&label(&lx))
        .y_label_formatter(&label(&ly))
        .x_desc(field_label(&r.sets[0].field))
        .y_desc(field_label(&r.sets[1].field))
        .label_style(("sans-serif", 12))
        .draw()
        .map_err(draw_err)?;
    for d in &r.designs {
        let (Some(x), Some(y)) = (d.values.get(&r.sets[0].field), d.values.get(&r.sets[1].field))
        else {
            continue;
        };
        let i = lx.iter().position(|v| v == x).unwrap_or(0) as f64;
        let j = ly.iter().position(|v| v == y).unwrap_or(0) as f64;
        let fill = match sigma_max(r, d) {
            Some(v) if vmax > vmin => ramp((v - vmin) / (vmax - vmin)),
            Some(_) => ramp(0.5),
            None => RGBColor(190, 190, 190),
        };
        chart
            .draw_series(std::iter::once(Rectangle::new(
                [(i - 0.5, j - 0.5), (i + 0.5, j + 0.5)],
                fill.filled(),
            )))
            .map_err(draw_err)?;
        let text = sigma_max(r, d).map_or("-".to_string(), |v| format!("{v:.3}"));
        let ink = if fill.1 > 160 { BLACK } else { WHITE };
        chart
            .draw_series(std::iter::once(Text::new(
                text,
                (i - 0.2, j),
                ("sans-serif", 12).into_font().color(&ink),
            )))
            .map_err(draw_err)?;
    }
    Ok(())
}
