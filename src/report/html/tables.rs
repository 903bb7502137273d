//! The run's metadata and the sigma tables (nm, nrad) with the 90 %
//! interval of each sigma under it, and the reference values that match.

use crate::report::study::reference::ReferenceRow;
use crate::report::study::text::{interval_methods, sigma_cells, sigma_columns, sigma_estimates};
use crate::report::study::thermal::{delta_t_text, heading};
use crate::report::table::escape;
use crate::report::table::{Cell, Table, cells};
use crate::study::result::varied_kinds;
use crate::study::{PointStats, StudyReport, VariantReport};

/// The provenance of one study: version, schema, solver, sampler, seed,
/// samples, what varied, shard; then one row per scene.
pub fn metadata(source: &str, r: &StudyReport) -> String {
    let or_scene = |x: Option<String>| x.unwrap_or_else(|| "per scene".to_string());
    let mut s = settings([
        ("source", source.to_string()),
        ("kinrepro version", r.kinrepro_version.clone()),
        ("output schema", r.schema_version.to_string()),
        ("solver", or_scene(r.solver.clone())),
        ("sampler", or_scene(r.sampler.map(|s| s.to_string()))),
        ("seed", or_scene(r.seed.map(|s| s.to_string()))),
        ("samples", or_scene(r.samples.map(|s| s.to_string()))),
        ("varied", r.vary.join(", ")),
        ("shard", r.shard.to_string()),
    ]);
    let mut t = Table::new(
        ">#; <scene; <name; >samples; >sampler; >seed; >replicates; >μ_s:.4g; >spread:.4g; >μ_d/μ_s:.4g; <varied",
    );
    for (i, v) in r.variants.iter().enumerate() {
        t.row(cells![
            i + 1,
            &v.scene,
            &v.name,
            v.samples,
            v.sampler.to_string(),
            v.seed.to_string(),
            v.design.replicates,
            v.mu_static,
            v.spread,
            v.dynamic_ratio,
            varied_kinds(&v.variation()).join(", "),
        ]);
    }
    s += &t.html("runs");
    s
}

/// A provenance table: one row per (setting, value).
pub fn settings<'a>(rows: impl IntoIterator<Item = (&'a str, String)>) -> String {
    let mut t = Table::new("<setting; <value");
    for (k, v) in rows {
        t.row(cells![k, v]);
    }
    t.html("meta")
}

/// One row per variant and evaluation point: sigma, and under it the 90 %
/// interval `[low, high]` where the design admits one; a highlighted row
/// for each matching reference. `stats` picks re-seating or
/// interchangeability statistics.
pub fn sigma_table(
    variants: &[&VariantReport],
    stats: fn(&VariantReport) -> &[PointStats],
    references: &[ReferenceRow],
) -> String {
    let sigma = sigma_columns(|d| format!("σ_{} [{}]", d.symbol(), d.unit()));
    let mut t = Table::new(">#; <variant; <point; >n").with(sigma);
    for (i, v) in variants.iter().enumerate() {
        if v.partial {
            t.note(format!(
                "{} {}: one shard of several: merge the parts first (kinrepro merge)",
                i + 1,
                v.name
            ));
            continue;
        }
        if let Some(reason) = &v.cannot_seat {
            t.note(format!("{} {}: CANNOT SEAT: {reason}", i + 1, v.name));
        }
        for p in stats(v) {
            let (sigma, under) = sigma_cells(p);
            let mut row = cells![i + 1, &v.name, &p.name, p.n];
            row.extend(sigma);
            if let Some(u) = under {
                t.row(row).under([vec![String::new(); 4], u].concat());
            } else {
                t.row(row);
            }
            if let Some(r) = ReferenceRow::find(references, v, &p.name) {
                let mut row = cells!["", format!("reference: {}", r.label), "", ""];
                row.extend(r.sigma.map(Cell::from));
                t.row(row).class("ref");
            }
        }
    }
    let points = variants.iter().filter(|v| !v.partial).flat_map(|v| stats(v));
    let methods = interval_methods(points, "none");
    let estimates = sigma_estimates(variants.iter().copied().filter(|v| !v.partial));
    t.html("sigma")
        + &format!(
            "<p class=\"note\">σ: standard deviation of the seated pose relative to the nominal seating ({}). Below each σ its 90 % interval, by a method valid for the design: {}.</p>\n",
            escape(&estimates),
            escape(&methods)
        )
}

/// The thermal drift of the variants with `[thermal]`: per evaluation
/// point and cycle point a row of the mean drift over the samples and a
/// row of its sigma with the 90 % interval under it (nm, nrad); empty
/// without one.
pub fn thermal_table(variants: &[&VariantReport]) -> String {
    let with: Vec<&VariantReport> =
        variants.iter().copied().filter(|v| !v.partial && v.thermal.is_some()).collect();
    if with.is_empty() {
        return String::new();
    }
    let columns = sigma_columns(|d| format!("{} [{}]", d.symbol(), d.unit()));
    let mut t = Table::new("<variant; <point; <cycle point; <statistic").with(columns);
    for v in &with {
        for p in &v.points {
            for c in &p.thermal {
                let at = delta_t_text(c.delta_t_k);
                let mut mean = cells![&v.name, &p.name, &at, "mean"];
                mean.extend(c.drift.mean.values().map(Cell::Num));
                t.row(mean);
                let (sigma, under) = sigma_cells(&c.drift);
                let mut row = cells!["", "", "", "σ"];
                row.extend(sigma);
                match under {
                    Some(u) => t.row(row).under([vec![String::new(); 4], u].concat()),
                    None => t.row(row),
                };
            }
        }
    }
    let headings: Vec<String> =
        with.iter().filter_map(|v| v.thermal.as_ref()).map(heading).collect();
    t.html("sigma")
        + &format!(
            "<p class=\"note\">Drift of each evaluation point from each sample's own seated pose at each cycle point: its mean over the samples, and σ with its 90 % interval under it ({}). {}.</p>\n",
            escape(&interval_methods(
                with.iter()
                    .flat_map(|v| v.points.iter().flat_map(|p| p.thermal.iter().map(|c| &c.drift))),
                "none"
            )),
            escape(&headings.join("; "))
        )
}
