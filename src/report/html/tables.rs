//! The run's metadata and the sigma tables (nm, nrad) with the 90 %
//! interval of each sigma under it, and the reference values that match.

use std::fmt::Write;

use super::page::{escape, num};
use super::reference::ReferenceRow;
use crate::study::result::varied_kinds;
use crate::study::{PointStats, StudyReport, VariantReport};

/// The provenance of one study: version, schema, solver, sampler, seed,
/// samples, what varied, shard; then one row per scene.
pub fn metadata(source: &str, r: &StudyReport) -> String {
    let or_scene = |x: Option<String>| x.unwrap_or_else(|| "per scene".to_string());
    let rows = [
        ("source", source.to_string()),
        ("kinrepro version", r.kinrepro_version.clone()),
        ("output schema", r.schema_version.to_string()),
        ("solver", or_scene(r.solver.clone())),
        ("sampler", or_scene(r.sampler.map(|s| s.to_string()))),
        ("seed", or_scene(r.seed.map(|s| s.to_string()))),
        ("samples", or_scene(r.samples.map(|s| s.to_string()))),
        ("varied", r.vary.join(", ")),
        ("shard", r.shard.to_string()),
    ];
    let mut s =
        String::from("<div class=\"scroll\"><table class=\"meta\" data-check=\"table\"><tbody>\n");
    for (k, v) in rows {
        let _ = writeln!(
            s,
            "<tr><th class=\"l\">{}</th><td class=\"l\">{}</td></tr>",
            escape(k),
            escape(&v)
        );
    }
    s.push_str("</tbody></table></div>\n");
    s.push_str(
        "<div class=\"scroll\"><table data-check=\"table\"><thead><tr><th>#</th><th class=\"l\">scene</th><th class=\"l\">name</th><th>samples</th><th>sampler</th><th>seed</th><th>replicates</th><th>μ_s</th><th>spread</th><th>μ_d/μ_s</th><th class=\"l\">varied</th></tr></thead><tbody>\n",
    );
    for (i, v) in r.variants.iter().enumerate() {
        let _ = writeln!(
            s,
            "<tr><td>{}</td><td class=\"l\">{}</td><td class=\"l\">{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td class=\"l\">{}</td></tr>",
            i + 1,
            escape(&v.scene),
            escape(&v.name),
            v.samples,
            v.sampler,
            v.seed,
            v.design.replicates,
            v.mu_static,
            v.spread,
            v.dynamic_ratio,
            escape(&varied_kinds(&v.variation()).join(", "))
        );
    }
    s.push_str("</tbody></table></div>\n");
    s
}

const HEAD: &str = "<th>σ_x [nm]</th><th>σ_y [nm]</th><th>σ_z [nm]</th><th>σ_φx [nrad]</th><th>σ_φy [nrad]</th><th>σ_φz [nrad]</th>";

/// One row per variant and evaluation point: sigma, and under it the 90 %
/// interval `[low, high]` where the design admits one; a highlighted row
/// for each matching reference. `stats` picks re-seating or
/// interchangeability statistics.
pub fn sigma_table(
    variants: &[&VariantReport],
    stats: fn(&VariantReport) -> &[PointStats],
    references: &[ReferenceRow],
) -> String {
    let mut s = format!(
        "<div class=\"scroll\"><table class=\"sigma\" data-check=\"table\"><thead><tr><th>#</th><th class=\"l\">variant</th><th class=\"l\">point</th><th>n</th>{HEAD}</tr></thead><tbody>\n"
    );
    let mut methods: Vec<&str> = Vec::new();
    for (i, v) in variants.iter().enumerate() {
        if v.partial {
            let _ = writeln!(
                s,
                "<tr><td>{}</td><td class=\"l\">{}</td><td class=\"l\" colspan=\"8\">one shard of several: merge the parts first (kinrepro merge)</td></tr>",
                i + 1,
                escape(&v.name)
            );
            continue;
        }
        if let Some(reason) = &v.cannot_seat {
            let _ = writeln!(
                s,
                "<tr><td>{}</td><td class=\"l\">{}</td><td class=\"l\" colspan=\"8\">CANNOT SEAT: {}</td></tr>",
                i + 1,
                escape(&v.name),
                escape(reason)
            );
        }
        for p in stats(v) {
            if !methods.contains(&p.sigma_interval_method.as_str()) {
                methods.push(&p.sigma_interval_method);
            }
            point_rows(&mut s, i, v, p, references);
        }
    }
    s.push_str("</tbody></table></div>\n");
    let _ = writeln!(
        s,
        "<p class=\"note\">σ: standard deviation of the seated pose relative to the nominal seating (divisor n − 1; for a replicated LHS the unbiased replicate estimate). Below each σ its 90 % interval, by a method valid for the design: {}.</p>",
        escape(&if methods.is_empty() {
            "none".to_string()
        } else {
            methods.join("; ")
        })
    );
    s
}

/// The row of one evaluation point (sigma, interval under it) and the
/// matching reference row.
fn point_rows(
    s: &mut String,
    i: usize,
    v: &VariantReport,
    p: &PointStats,
    references: &[ReferenceRow],
) {
    let sigma = p.sigma.values();
    let interval = match (&p.sigma_ci90_low, &p.sigma_ci90_high) {
        (Some(l), Some(h)) => Some((l.values(), h.values())),
        _ => None,
    };
    let _ = write!(
        s,
        "<tr><td>{}</td><td class=\"l\">{}</td><td class=\"l\">{}</td><td>{}</td>",
        i + 1,
        escape(&v.name),
        escape(&p.name),
        p.n
    );
    for k in 0..6 {
        let digits = if k < 3 { 3 } else { 2 };
        let ci = interval.map_or(String::new(), |(l, h)| {
            format!(
                "<span class=\"ci\">[{}, {}]</span>",
                num(l[k], digits),
                num(h[k], digits)
            )
        });
        let _ = write!(s, "<td>{}{ci}</td>", num(sigma[k], digits));
    }
    s.push_str("</tr>\n");
    if let Some(r) = ReferenceRow::find(references, v, &p.name) {
        let _ = write!(
            s,
            "<tr class=\"ref\"><td></td><td class=\"l\" colspan=\"2\">reference: {}</td><td></td>",
            escape(&r.label)
        );
        for (k, x) in r.sigma.iter().enumerate() {
            let digits = if k < 3 { 3 } else { 2 };
            let _ = write!(s, "<td>{}</td>", x.map_or("-".into(), |x| num(x, digits)));
        }
        s.push_str("</tr>\n");
    }
}
