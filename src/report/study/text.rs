//! Text helpers of the study table: the Table 2 style sigma table, the
//! per-point detail, what varied and the `[variation]` bounds in words;
//! the statistics rows of the summary CSVs.

use crate::dof::Dof;
use crate::report::table::{Cell, Column, Table, cells};
use crate::scene::VariationBounds;
use crate::study::result::varied_kinds;
use crate::study::stats::SigmaMethod;
use crate::study::{Dofs, PointStats, VariantReport};

/// The six sigma columns: `<prefix><dof> [unit]`, nm with 3 decimals, nrad with 2.
pub(crate) fn sigma_columns(header: impl Fn(Dof) -> String) -> Vec<Column> {
    Dof::ALL.map(|d| Column::right(header(d)).fixed(if d.is_rotation() { 2 } else { 3 })).into()
}

/// Sigma of a point per DOF as cells, and the 90 % interval of each under
/// it (`[low, high]`), or None without an interval.
pub(crate) fn sigma_cells(p: &PointStats) -> (Vec<Cell>, Option<Vec<String>>) {
    let cells = p.sigma.values().map(Cell::Num).into();
    let (Some(lo), Some(hi)) = (&p.sigma_ci90_low, &p.sigma_ci90_high) else {
        return (cells, None);
    };
    let (lo, hi) = (lo.values(), hi.values());
    let under = (0..6).map(|k| format!("[{:.2}, {:.2}]", lo[k], hi[k]));
    (cells, Some(under.collect()))
}

/// The Table 2 style sigma table of `points(v)` for every variant.
pub(crate) fn sigma_table(
    variants: &[VariantReport],
    points: impl Fn(&VariantReport) -> &Vec<PointStats>,
) -> String {
    let mut t = Table::new("<#; <variant; <point; >n").with(sigma_columns(|d| d.header("sigma_")));
    for (i, v) in variants.iter().enumerate() {
        if v.partial {
            t.note(format!(
                "{} {}: shard {} of {} samples: run `kinrepro merge` for statistics",
                i + 1,
                v.name,
                v.shard,
                v.samples
            ));
            continue;
        }
        if v.cannot_seat.is_some() {
            t.note(format!("{} {}: CANNOT SEAT: no scatter to report (see above)", i + 1, v.name));
            continue;
        }
        for p in points(v) {
            let (sigma, under) = sigma_cells(p);
            let mut row = cells![i + 1, truncate(&v.name, 45), &p.name, p.n];
            row.extend(sigma);
            let r = t.row(row);
            match under {
                Some(u) => {
                    r.under([vec![String::new(); 4], u].concat());
                }
                None => t.note(format!("  (no interval: {})", p.sigma_interval_method)),
            }
        }
    }
    t.text()
}

/// Mean, min, max, sigma and 3 sigma of every DOF of each point.
pub(crate) fn detail(points: &[PointStats]) -> String {
    let mut s = String::new();
    for p in points {
        let mut t = Table::of([Column::left(&p.name)])
            .with(Column::list("<; >mean:.3; >min:.3; >max:.3; >sigma:.3; >+-3 sigma:.3"))
            .indent(2);
        let values = [p.mean, p.min, p.max, p.sigma, p.three_sigma].map(|d| d.values());
        for d in Dof::ALL {
            let mut row = cells!["", d.header("")];
            row.extend(values.iter().map(|v| Cell::Num(v[d.index()])));
            t.row(row);
        }
        for d in &p.directions {
            let mut row = cells!["", format!("{} [{}]", d.label(), d.unit)];
            row.extend([d.mean, d.min, d.max, d.sigma, d.three_sigma].map(Cell::Num));
            t.row(row);
        }
        s += &t.text();
    }
    s
}

/// What varied, in words.
pub(crate) fn varied(v: &VariantReport) -> String {
    let parts = varied_kinds(&v.variation());
    format!("{} ({} inputs)", parts.join(", "), v.inputs.len())
}

/// The distinct interval methods of `points`, in order, joined by `; `
/// (`none` where there are none).
pub(crate) fn interval_methods<'a>(
    points: impl IntoIterator<Item = &'a PointStats>,
    none: &str,
) -> String {
    let mut m: Vec<&str> = Vec::new();
    for p in points {
        if !m.contains(&p.sigma_interval_method.as_str()) {
            m.push(&p.sigma_interval_method);
        }
    }
    if m.is_empty() { none.to_string() } else { m.join("; ") }
}

/// The distinct point estimates of sigma of the designs that ran
/// ([`crate::study::stats::SigmaMethod::estimate`]), in order, joined by `; `.
pub(crate) fn sigma_estimates<'a>(variants: impl IntoIterator<Item = &'a VariantReport>) -> String {
    estimates(variants.into_iter().map(|v| v.sigma_method(v.seating_failures.unwrap_or(0))))
}

/// The distinct estimates of `methods`, in order, joined by `; `.
pub(crate) fn estimates(methods: impl IntoIterator<Item = SigmaMethod>) -> String {
    let mut m: Vec<String> = Vec::new();
    for e in methods.into_iter().map(|m| m.estimate()) {
        if !m.contains(&e) {
            m.push(e);
        }
    }
    m.join("; ")
}

/// The non-zero `[variation]` bounds, in um and mrad.
pub(crate) fn bounds_text(b: &VariationBounds) -> String {
    let um = |x: f64| format!("{}", x * 1e6);
    let pm = |v: &[f64]| v.iter().map(|x| format!("+-{}", um(*x))).collect::<Vec<_>>();
    let mut parts = Vec::new();
    if b.preload_offset_m.iter().any(|x| *x > 0.0) {
        let p = pm(&b.preload_offset_m).join(", ");
        parts.push(format!("preload offset {p} um"));
    }
    if b.preload_tilt_rad > 0.0 {
        parts.push(format!("preload tilt +-{} mrad per axis", b.preload_tilt_rad * 1e3));
    }
    if b.ball_diameter_m > 0.0 {
        parts.push(format!("ball diameter +-{} um", um(b.ball_diameter_m)));
    }
    if b.ball_position_m.iter().any(|x| *x > 0.0) {
        let p = pm(&b.ball_position_m).join(", ");
        parts.push(format!("ball position {p} um"));
    }
    if b.surface_normal_m > 0.0 {
        parts.push(format!("surface normal +-{} um", um(b.surface_normal_m)));
    }
    if b.surface_tilt_rad > 0.0 {
        parts.push(format!("surface tilt +-{} mrad", b.surface_tilt_rad * 1e3));
    }
    if b.groove_position_m.iter().any(|x| *x > 0.0) {
        let p = pm(&b.groove_position_m).join(", ");
        parts.push(format!("groove position {p} um"));
    }
    if parts.is_empty() { "none".to_string() } else { parts.join("; ") }
}

pub(crate) fn truncate(s: &str, n: usize) -> String {
    if s.chars().count() <= n {
        s.to_string()
    } else {
        s.chars().take(n - 1).collect::<String>() + "…"
    }
}

/// The statistics columns of one evaluation point in the summary CSVs of a
/// study and of a sweep, one row per DOF: `point,dof,unit,n,mean,min,max,
/// sigma,three_sigma,sigma_ci90_low,sigma_ci90_high,sigma_interval_method`,
/// values in SI (m, rad); no interval (corners, a single LHS) is an empty
/// field. A point's thermal drift statistics follow it, one block per
/// cycle point, the point named `thermal/<k>/<point>`.
pub(crate) fn point_csv_rows(p: &PointStats) -> Vec<Vec<String>> {
    let mut rows = dof_csv_rows(p, &p.name);
    for (k, c) in p.thermal.iter().enumerate() {
        rows.extend(dof_csv_rows(&c.drift, &thermal_output_point(k, &p.name)));
    }
    rows
}

/// The output name of a point's drift at cycle point `k` (0-based):
/// `thermal/<k + 1>/<point>`, as the study's records name it.
pub(crate) fn thermal_output_point(k: usize, point: &str) -> String {
    format!("{}{}/{point}", crate::study::runner::THERMAL_PREFIX, k + 1)
}

/// One row per DOF of `p`'s statistics, then one per direction (`dof`
/// `along/<name>` or `about/<name>`), the point named `name`.
fn dof_csv_rows(p: &PointStats, name: &str) -> Vec<Vec<String>> {
    let si = |x: f64| format!("{:e}", x / crate::dof::NANO);
    let directions = p.directions.iter().map(|d| {
        let ci = |v: Option<f64>| v.map_or(String::new(), si);
        vec![
            name.to_string(),
            d.key(),
            d.si_unit().to_string(),
            p.n.to_string(),
            si(d.mean),
            si(d.min),
            si(d.max),
            si(d.sigma),
            si(d.three_sigma),
            ci(d.sigma_ci90_low),
            ci(d.sigma_ci90_high),
            p.sigma_interval_method.clone(),
        ]
    });
    Dof::ALL
        .iter()
        .map(|d| {
            let k = d.index();
            let si = |v: &Dofs| format!("{:e}", v.si()[k]);
            let ci = |v: &Option<Dofs>| v.as_ref().map_or(String::new(), si);
            vec![
                name.to_string(),
                d.name().to_string(),
                d.si_unit().to_string(),
                p.n.to_string(),
                si(&p.mean),
                si(&p.min),
                si(&p.max),
                si(&p.sigma),
                si(&p.three_sigma),
                ci(&p.sigma_ci90_low),
                ci(&p.sigma_ci90_high),
                p.sigma_interval_method.clone(),
            ]
        })
        .chain(directions)
        .collect()
}
