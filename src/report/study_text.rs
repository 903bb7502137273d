//! Text helpers of the study table: the Table 2 style sigma table, the
//! per-point detail, what varied and the `[variation]` bounds in words.

use std::fmt::Write;

use crate::scene::VariationBounds;
use crate::study::result::varied_kinds;
use crate::study::runner::COMPONENTS;
use crate::study::{Dofs, PointStats, VariantReport};

/// The Table 2 style sigma table of `points(v)` for every variant.
pub(crate) fn sigma_table(
    s: &mut String,
    variants: &[VariantReport],
    points: impl Fn(&VariantReport) -> &Vec<PointStats>,
) {
    let _ = writeln!(
        s,
        "{:<4}{:<46}{:<16}{:>5} {:>13} {:>13} {:>13} {:>17} {:>17} {:>17}",
        "#",
        "variant",
        "point",
        "n",
        "sigma_x [nm]",
        "sigma_y [nm]",
        "sigma_z [nm]",
        "sigma_phi_x[nrad]",
        "sigma_phi_y[nrad]",
        "sigma_phi_z[nrad]"
    );
    for (i, v) in variants.iter().enumerate() {
        if v.partial {
            let _ = writeln!(
                s,
                "{:<4}{:<46}(shard {} of {} samples: run `kinrepro merge` for statistics)",
                i + 1,
                v.name,
                v.shard,
                v.samples
            );
            continue;
        }
        for p in points(v) {
            let sg = p.sigma.values();
            let _ = writeln!(
                s,
                "{:<4}{:<46}{:<16}{:>5} {:>13.3} {:>13.3} {:>13.3} {:>17.2} {:>17.2} {:>17.2}",
                i + 1,
                truncate(&v.name, 45),
                p.name,
                p.n,
                sg[0],
                sg[1],
                sg[2],
                sg[3],
                sg[4],
                sg[5]
            );
            let (Some(lo), Some(hi)) = (&p.sigma_ci90_low, &p.sigma_ci90_high) else {
                let _ = writeln!(s, "{:<71}(no interval: {})", "", p.sigma_interval_method);
                continue;
            };
            let (lo, hi) = (lo.values(), hi.values());
            let ci: Vec<String> = (0..6)
                .map(|k| {
                    let w = if k < 3 { 13 } else { 17 };
                    format!("{:>w$}", format!("[{:.2}, {:.2}]", lo[k], hi[k]))
                })
                .collect();
            let _ = writeln!(s, "{:<71}{}", "", ci.join(" "));
        }
    }
}

/// Mean, min, max, sigma and 3 sigma of every DOF of each point.
pub(crate) fn detail(s: &mut String, points: &[PointStats]) {
    for p in points {
        let _ = writeln!(
            s,
            "  {:<16} {:<10} {:>12} {:>12} {:>12} {:>12} {:>12}",
            p.name, "", "mean", "min", "max", "sigma", "+-3 sigma"
        );
        let rows = [
            ("x [nm]", 0),
            ("y [nm]", 1),
            ("z [nm]", 2),
            ("phi_x [nrad]", 3),
            ("phi_y [nrad]", 4),
            ("phi_z [nrad]", 5),
        ];
        for (label, k) in rows {
            let _ = writeln!(
                s,
                "  {:<16} {:<10} {:>12.3} {:>12.3} {:>12.3} {:>12.3} {:>12.3}",
                "",
                label,
                p.mean.values()[k],
                p.min.values()[k],
                p.max.values()[k],
                p.sigma.values()[k],
                p.three_sigma.values()[k]
            );
        }
    }
}

/// What varied, in words.
pub(crate) fn varied(v: &VariantReport) -> String {
    let parts = varied_kinds(&v.variation());
    format!("{} ({} inputs)", parts.join(", "), v.inputs.len())
}

/// The non-zero `[variation]` bounds, in um and mrad.
pub(crate) fn bounds_text(b: &VariationBounds) -> String {
    let um = |x: f64| format!("{}", x * 1e6);
    let mut parts = Vec::new();
    if b.preload_offset_m.iter().any(|x| *x > 0.0) {
        parts.push(format!(
            "preload offset +-{}, +-{} um",
            um(b.preload_offset_m[0]),
            um(b.preload_offset_m[1])
        ));
    }
    if b.preload_tilt_rad > 0.0 {
        parts.push(format!(
            "preload tilt +-{} mrad per axis",
            b.preload_tilt_rad * 1e3
        ));
    }
    if b.ball_diameter_m > 0.0 {
        parts.push(format!("ball diameter +-{} um", um(b.ball_diameter_m)));
    }
    if b.ball_position_m.iter().any(|x| *x > 0.0) {
        let p = b.ball_position_m;
        parts.push(format!(
            "ball position +-{}, +-{}, +-{} um",
            um(p[0]),
            um(p[1]),
            um(p[2])
        ));
    }
    if b.surface_normal_m > 0.0 {
        parts.push(format!("surface normal +-{} um", um(b.surface_normal_m)));
    }
    if b.surface_tilt_rad > 0.0 {
        parts.push(format!("surface tilt +-{} mrad", b.surface_tilt_rad * 1e3));
    }
    if b.groove_position_m.iter().any(|x| *x > 0.0) {
        parts.push(format!(
            "groove position +-{}, +-{} um",
            um(b.groove_position_m[0]),
            um(b.groove_position_m[1])
        ));
    }
    if parts.is_empty() {
        "none".to_string()
    } else {
        parts.join("; ")
    }
}

pub(crate) fn truncate(s: &str, n: usize) -> String {
    if s.chars().count() <= n {
        s.to_string()
    } else {
        s.chars().take(n - 1).collect::<String>() + "…"
    }
}

/// The statistics columns of one evaluation point in the summary CSVs of a
/// study and of a sweep, one string per DOF (`COMPONENTS` order):
/// `point,dof,unit,n,mean,min,max,sigma,three_sigma,sigma_ci90_low,
/// sigma_ci90_high,sigma_interval_method`, values in SI (m, rad); no interval
/// (corners, a single LHS) is an empty field.
pub(crate) fn point_csv_fields(p: &PointStats) -> Vec<String> {
    COMPONENTS
        .iter()
        .enumerate()
        .map(|(k, comp)| {
            let (dof, unit) = comp.rsplit_once('_').unwrap_or((comp, ""));
            let si = |d: &Dofs| format!("{:e}", d.values()[k] * 1e-9);
            let ci = |d: &Option<Dofs>| d.as_ref().map_or(String::new(), si);
            format!(
                "{},{dof},{unit},{},{},{},{},{},{},{},{},{}",
                csv_field(&p.name),
                p.n,
                si(&p.mean),
                si(&p.min),
                si(&p.max),
                si(&p.sigma),
                si(&p.three_sigma),
                ci(&p.sigma_ci90_low),
                ci(&p.sigma_ci90_high),
                csv_field(&p.sigma_interval_method)
            )
        })
        .collect()
}

pub(crate) fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}
