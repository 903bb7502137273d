//! The optimisation's HTML page (`kinrepro optimize --html FILE`): the
//! run, the optimum with its constraint margins and the statistical error
//! of its objective, its re-seating statistics, the convergence plot
//! (every candidate's objective, the best feasible so far as a line,
//! candidates that break a constraint as grey crosses) and the history.
//! It renders the optimisation document; nothing is recomputed.

use std::fmt::Write;

use plotters::prelude::*;

use super::{HtmlError, page};
use crate::explore::optimize::OptimizeReport;
use crate::report::study::plot::color;
use crate::report::table::{Cell, Column, Table, cells, escape};
use crate::study::provenance::VERSION;

/// The whole document; `scene_text`: the base scene file as read.
pub fn optimize_html(r: &OptimizeReport, scene_text: &str) -> Result<String, HtmlError> {
    let mut b = String::new();
    let _ = writeln!(
        b,
        "<header><h1>kinrepro: optimisation of {}</h1>\n<p class=\"prov\">{}</p></header>",
        escape(&r.name),
        escape(&r.produced_by())
    );
    let goals: Vec<String> = (r.goals.objectives.iter().map(|o| format!("objective {}", o.name())))
        .chain(r.goals.constraints.iter().map(|c| format!("constraint {}", c.name())))
        .collect();
    let _ = writeln!(
        b,
        "<section id=\"run\"><h2>Run</h2>\n<p>{}</p>\n<p class=\"note\">{}; {}.</p>\n</section>",
        escape(&goals.join("; ")),
        escape(&r.method),
        escape(&r.searches_text())
    );
    b += "<section id=\"optimum\"><h2>Optimum</h2>\n";
    match &r.optimum {
        None => {
            b += "<p class=\"warn\">No feasible design: no candidate meets every constraint.</p>\n"
        }
        Some(o) => {
            let mut t = Table::new("<quantity; <value");
            for (k, v) in &o.fields {
                t.row(cells![k, v.to_string()]);
            }
            let unit = r.goals.objectives[0].output.unit();
            t.row(cells![r.goals.objectives[0].name(), format!("{:.6e} {unit}", o.objective)]);
            for m in &o.constraint_margins {
                t.row(cells![format!("margin of {}", m.constraint), format!("{:.6e}", m.margin)]);
            }
            b += &t.html("optimum");
            let _ = writeln!(
                b,
                "<p class=\"note\">Statistical error: {}</p>",
                escape(&o.statistical_error)
            );
            b += &points_table(o);
        }
    }
    b += "</section>\n<section id=\"convergence\"><h2>Convergence</h2>\n";
    b += &page::figure(
        "convergence",
        &convergence_svg(r)?,
        "Every candidate's objective in the order evaluated; line: the best feasible so far; grey crosses: candidates that break a constraint.",
    );
    b += "</section>\n<section id=\"history\"><h2>History</h2>\n";
    let mut t = Table::of([Column::right("#"), Column::left("fields")])
        .with(Column::list(">objective:.6g; <feasible; >cost:.6g; <status"));
    for c in &r.history {
        let fields: Vec<String> = c.fields.iter().map(|(k, v)| format!("{k} = {v}")).collect();
        t.row(cells![
            c.evaluation,
            fields.join(", "),
            c.objective.map_or(Cell::Missing, Cell::Num),
            if c.feasible { "yes" } else { "no" },
            c.cost,
            &c.status
        ]);
    }
    b += &t.html("history");
    let _ = writeln!(
        b,
        "</section>\n<section id=\"scene\"><h2>Base scene ({})</h2>\n<pre data-check=\"scene\">{}</pre>\n</section>\n<footer class=\"muted\">Written by kinrepro {VERSION}. Self-contained: inline CSS and SVG, no script, no network.</footer>",
        escape(&r.scene),
        escape(scene_text)
    );
    Ok(page::document(&format!("kinrepro optimize: {}", r.name), &b))
}

/// Sigma and +-3 sigma of every DOF and direction of each point at the optimum.
fn points_table(o: &crate::explore::optimize::Optimum) -> String {
    let mut t = Table::new("<point; <DOF; >σ:.3; >±3σ:.3; <90 % interval of σ");
    for p in &o.design.points {
        let (lo, hi) =
            (p.sigma_ci90_low.map(|d| d.values()), p.sigma_ci90_high.map(|d| d.values()));
        for d in crate::dof::Dof::ALL {
            let k = d.index();
            let ci = lo
                .zip(hi)
                .map_or("none".to_string(), |(l, h)| format!("[{:.2}, {:.2}]", l[k], h[k]));
            let label = format!("{} [{}]", d.name(), d.unit());
            t.row(cells![&p.name, label, p.sigma.values()[k], p.three_sigma.values()[k], ci]);
        }
        for d in &p.directions {
            let ci = d.interval().map_or("none".to_string(), |[l, h]| format!("[{l:.2}, {h:.2}]"));
            t.row(cells![
                &p.name,
                format!("{} [{}]", d.label(), d.unit),
                d.sigma,
                d.three_sigma,
                ci
            ]);
        }
    }
    format!("<h3>Re-seating scatter at the optimum</h3>\n{}", t.html("points"))
}

/// The convergence plot (module docs).
fn convergence_svg(r: &OptimizeReport) -> Result<String, HtmlError> {
    let err = |e: String| HtmlError::Chart(crate::report::study::plot::PlotError::Backend(e));
    let objective = &r.goals.objectives[0];
    let pts: Vec<(f64, f64, bool)> = (r.history.iter())
        .filter_map(|c| Some((c.evaluation as f64, c.objective?, c.feasible)))
        .collect();
    let (lo, hi) =
        pts.iter().fold((f64::INFINITY, f64::NEG_INFINITY), |a, p| (a.0.min(p.1), a.1.max(p.1)));
    let pad = if hi > lo { 0.05 * (hi - lo) } else { lo.abs().max(1e-300) * 0.05 };
    let n = r.history.len().max(2) as f64;
    // The best feasible objective so far, at each feasible candidate.
    let mut best: Vec<(f64, f64)> = Vec::new();
    for &(x, y, _) in pts.iter().filter(|p| p.2) {
        let so_far = best.last().map_or(y, |&(_, b)| match objective.sense {
            crate::explore::goal::Sense::Min => b.min(y),
            crate::explore::goal::Sense::Max => b.max(y),
        });
        best.push((x, so_far));
    }
    let mut svg = String::new();
    {
        let root = SVGBackend::with_string(&mut svg, (1100, 480)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| err(e.to_string()))?;
        let (y0, y1) = if pts.is_empty() { (0.0, 1.0) } else { (lo - pad, hi + pad) };
        let mut chart = ChartBuilder::on(&root)
            .margin(14)
            .x_label_area_size(40)
            .y_label_area_size(90)
            .build_cartesian_2d(0.0..n + 1.0, y0..y1)
            .map_err(|e| err(e.to_string()))?;
        chart
            .configure_mesh()
            .x_desc("candidate (order evaluated)")
            .y_desc(format!("{} [{}]", objective.name(), objective.output.unit()))
            .x_labels(6)
            .y_labels(6)
            .y_label_formatter(&|v| format!("{v:.3e}"))
            .label_style(("sans-serif", 13))
            .draw()
            .map_err(|e| err(e.to_string()))?;
        let grey = RGBColor(150, 150, 150);
        let dots =
            pts.iter().filter(|p| p.2).map(|&(x, y, _)| Circle::new((x, y), 3, color(0).filled()));
        chart.draw_series(dots).map_err(|e| err(e.to_string()))?;
        let off = pts
            .iter()
            .filter(|p| !p.2)
            .map(|&(x, y, _)| Cross::new((x, y), 3, grey.stroke_width(1)));
        chart.draw_series(off).map_err(|e| err(e.to_string()))?;
        chart
            .draw_series(LineSeries::new(best, color(5).stroke_width(2)))
            .map_err(|e| err(e.to_string()))?;
        root.present().map_err(|e| err(e.to_string()))?;
    }
    Ok(svg)
}
