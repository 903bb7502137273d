//! The sweep's HTML report (`kinrepro sweep --html FILE`): the run's
//! provenance (as a study report shows its own), the table of design
//! points (swept values by field, sigma per DOF at each evaluation point
//! with its 90 % interval, k_min, SF_p, mu_lim and its margin, the Pareto
//! mark, the status with the reason of a point not evaluated), the design
//! charts (`report::sweep::plot`, whose Pareto labels are the table's `#`),
//! the drawing of the base coupling at its nominal seating and the base
//! scene's text. It renders the sweep document; nothing is
//! recomputed.

use std::fmt::Write;

use super::tables::settings;
use super::{HtmlError, drawing, page};
use crate::assembly::Coupling;
use crate::explore::{DesignKind, DesignReport, SweepReport, SweptValue};
use crate::report::study::text::{interval_methods, sigma_cells, sigma_columns};
use crate::report::sweep::plot::charts;
use crate::report::sweep::text::{field_label, short, sigma_estimates};
use crate::report::table::{Cell, Column, Table, cells, escape};
use crate::scene::Scene;
use crate::study::provenance::VERSION;

/// The whole document; `scene_text`: the base scene file as read, `base`:
/// the base scene and its coupling (drawn at its nominal seating).
pub fn sweep_html(
    r: &SweepReport,
    scene_text: &str,
    base: (&Scene, &Coupling),
) -> Result<String, HtmlError> {
    let charts = charts(r)?;
    let seating = super::nominal_seating(base.0, base.1)?;
    let mut body = String::new();
    let _ = writeln!(
        body,
        "<header><h1>kinrepro: design sweep of {}</h1>\n<p class=\"prov\">{}</p></header>",
        escape(&r.name),
        escape(&r.produced_by())
    );
    body.push_str("<nav><ul>\n<li><a href=\"#run\">Run</a></li><li><a href=\"#designs\">Design points</a></li>\n");
    for (title, _) in &charts {
        let heading = heading(r, title);
        let _ =
            writeln!(body, "<li><a href=\"#{}\">{}</a></li>", chart_id(title), escape(&heading));
    }
    body.push_str("<li><a href=\"#coupling\">Base coupling</a></li><li><a href=\"#scene\">Base scene</a></li>\n</ul></nav>\n");
    body.push_str("<section id=\"run\"><h2>Run</h2>\n");
    body.push_str(&provenance(r));
    body.push_str("</section>\n<section id=\"designs\"><h2>Design points</h2>\n");
    body.push_str(&design_table(r));
    body.push_str("</section>\n<section id=\"charts\"><h2>Charts</h2>\n");
    for (title, svg) in &charts {
        let _ = writeln!(body, "<h3>{}</h3>", escape(&heading(r, title)));
        body.push_str(&page::figure(&chart_id(title), svg, caption(title)));
    }
    body.push_str(
        "</section>\n<section id=\"coupling\"><h2>Base coupling at the nominal seating</h2>\n",
    );
    body.push_str(&drawing::coupling_views("base", base, &seating));
    let _ = writeln!(
        body,
        "</section>\n<section id=\"scene\"><h2>Base scene ({})</h2>\n<pre data-check=\"scene\">{}</pre>\n</section>",
        escape(&r.scene),
        escape(scene_text)
    );
    let _ = writeln!(
        body,
        "<footer class=\"muted\">Written by kinrepro {VERSION}. Self-contained: inline CSS and SVG, no script, no network.</footer>"
    );
    Ok(page::document(&format!("kinrepro sweep: {}", r.name), &body))
}

/// The heading of chart `name` (its file stem, `sweep_heatmap`): a title
/// that says what it shows, with the swept field and its unit.
fn heading(r: &SweepReport, name: &str) -> String {
    match name {
        "sweep_heatmap" => format!(
            "Heat map: the largest translational σ at {} over the two swept fields",
            r.pareto_point
        ),
        "sweep_pareto" if !r.goals.objectives.is_empty() => format!(
            "Pareto front on {}",
            r.goals.objectives.iter().map(|o| o.name()).collect::<Vec<_>>().join(", ")
        ),
        "sweep_pareto" => "Pareto front: the largest translational σ against k_min".to_string(),
        "sweep_not_evaluated" => "Design points not evaluated".to_string(),
        other => {
            let field = (r.sets.iter())
                .find(|s| other == format!("sweep_sigma_{}", s.field.replace('.', "_")))
                .map_or_else(|| other.to_string(), |s| field_label(&s.field));
            format!("σ against {field}")
        }
    }
}

fn chart_id(title: &str) -> String {
    title.replace('_', "-")
}

fn caption(title: &str) -> &'static str {
    match title {
        "sweep_heatmap" => {
            "The largest translational σ at the Pareto point over the two swept fields; grey: not evaluated."
        }
        "sweep_pareto" => {
            "Every evaluated design point, one panel per pair of objectives; the Pareto front in colour, labelled with its # in the table of design points; dominated designs grey; grey crosses: designs that break a constraint."
        }
        "sweep_not_evaluated" => "The design points not evaluated, with the reason.",
        _ => {
            "σ against the swept field, one line per combination of the other fields (legend above the panels); band and bars: the 90 % interval of σ."
        }
    }
}

/// The run's settings, the design and the swept fields.
fn provenance(r: &SweepReport) -> String {
    let design = match r.design {
        DesignKind::Grid => format!("grid, {} points", r.design_points),
        DesignKind::Lhs { points, seed } => {
            format!("Latin hypercube, {points} points (design seed {seed})")
        }
    };
    let mut rows = vec![
        ("kinrepro version", r.kinrepro_version.clone()),
        ("output schema", r.schema_version.to_string()),
        ("solver", r.solver.clone()),
        ("sampler", r.sampler.to_string()),
        ("seed", r.seed.to_string()),
        ("samples per design point", r.samples.to_string()),
        ("varied", r.vary.join(", ")),
        ("base scene", format!("{} ({})", r.scene, r.name)),
        ("design", design),
    ];
    for s in &r.sets {
        rows.push(("swept field", format!("{} = {}", field_label(&s.field), s.values)));
    }
    rows.push((
        "Pareto objectives",
        format!(
            "largest translational σ at {} (lower), k_min (higher), SF_p (higher)",
            r.pareto_point
        ),
    ));
    rows.push(("shard", r.shard.to_string()));
    settings(rows)
}

/// One row per design point and evaluation point, the interval of each
/// sigma under it; the nominal seating's columns and the status on the
/// design's first row.
fn design_table(r: &SweepReport) -> String {
    // Headers break between words only: a field's path may also break
    // after each dot and underscore (a zero-width space), never inside a
    // word.
    let breakable = |f: &str| field_label(f).replace('.', ".\u{200B}").replace('_', "_\u{200B}");
    let fields = r.sets.iter().map(|s| Column::left(breakable(&s.field)));
    let sigma = sigma_columns(|d| format!("σ_{} [{}]", d.symbol(), d.unit()));
    let tail = Column::list(">k_min [N/µm]:.2; >SF_p:.2; >μ_lim:.4; >margin:.4; <Pareto; <status");
    let mut t = Table::new(">#").with(fields).with([Column::left("point")]).with(sigma).with(tail);
    let lead = 2 + r.sets.len();
    for d in &r.designs {
        let mut head = cells![d.index];
        head.extend(r.sets.iter().map(|s| match d.values.get(&s.field) {
            Some(SweptValue::Number(x)) => Cell::from(short(*x)),
            Some(SweptValue::Name(n)) => Cell::from(n.as_str()),
            None => Cell::Missing,
        }));
        let first = cells![
            d.principal_stiffness_n_per_m.map(|k| k[0] * 1e-6),
            d.min_pressure_safety_factor,
            d.friction_limit,
            d.friction_limit_margin,
            pareto_mark(d),
            d.status.as_str(),
        ];
        if d.points.is_empty() {
            let blank = std::iter::repeat_n(Cell::Missing, 7);
            t.row(head.into_iter().chain(blank).chain(first).collect());
            continue;
        }
        for (i, p) in d.points.iter().enumerate() {
            let (sigma, under) = sigma_cells(p);
            let mut row = match i {
                0 => head.clone(),
                _ => vec![Cell::from(""); lead - 1],
            };
            row.push(p.name.as_str().into());
            row.extend(sigma);
            match i {
                0 => row.extend(first.iter().cloned()),
                _ => row.extend(std::iter::repeat_n(Cell::from(""), first.len())),
            }
            let row = t.row(row);
            if let Some(u) = under {
                row.under([vec![String::new(); lead], u].concat());
            }
        }
    }
    let methods = interval_methods(r.designs.iter().flat_map(|d| &d.points), "none");
    t.html("designs")
        + &format!(
            "<p class=\"note\">σ: standard deviation of the seated pose relative to the design's nominal seating ({}); under it the 90 % interval ({}). k_min: the lowest principal translational stiffness of the nominal seating; SF_p: the smallest safety factor against the allowable contact pressure; μ_lim: the friction limit for seating, margin: μ_lim - (μ_static + spread). Pareto: on the front of the three objectives. #: the label of the design point in the charts.</p>\n",
            escape(&sigma_estimates(r)),
            escape(&methods)
        )
}

fn pareto_mark(d: &DesignReport) -> &'static str {
    match d.pareto {
        Some(true) => "front",
        Some(false) => "",
        None => "(shard)",
    }
}
