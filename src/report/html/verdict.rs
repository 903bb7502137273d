//! The report's verdict, its first result: per variant and evaluation
//! point +-3 sigma (the reproducibility in the sense of the paper) with
//! its 90 % interval, then the friction limit against the largest
//! coefficient drawn (a warning above it), the smallest contact safety
//! factor with the bodies it covers and what it leaves out, and the
//! seating failures. The same numbers as the text table's verdict
//! (`report::study::verdict`), from the study document.

use std::fmt::Write;

use crate::report::study::text::sigma_columns;
use crate::report::study::verdict::{friction_line, safety_line};
use crate::report::table::{Cell, Table, cells, escape};
use crate::study::VariantReport;

/// The named directions of every point (`directions`, `frame`): ±3σ with
/// its interval, σ, mean, min and max of the translation along each (or
/// rotation about it); empty where no point has directions.
fn directions_table(variants: &[&VariantReport]) -> String {
    let columns = ">#; <variant; <point; <direction; <unit; >±3σ:.2; <90 % interval of ±3σ; >σ:.3; >mean:.3; >min:.3; >max:.3";
    let mut t = Table::new(columns);
    let reported =
        variants.iter().enumerate().filter(|(_, v)| !v.partial && v.cannot_seat.is_none());
    for (i, v) in reported {
        for p in &v.points {
            for d in &p.directions {
                let interval = d.interval().map_or("none (design)".to_string(), |[l, h]| {
                    format!("[{:.2}, {:.2}]", 3.0 * l, 3.0 * h)
                });
                t.row(cells![
                    i + 1,
                    &v.name,
                    &p.name,
                    d.label(),
                    &d.unit,
                    d.three_sigma,
                    interval,
                    d.sigma,
                    d.mean,
                    d.min,
                    d.max
                ]);
            }
        }
    }
    if t.is_empty() {
        return String::new();
    }
    let mut s = String::from("<h3>Along the named directions</h3>\n");
    s += &t.html("verdict-directions");
    s += "<p class=\"note\">along: the translation of the point projected on the direction's unit vector; about: the rotation of the half about it (a frame's axes). Computed per sample from the pose, summarised like every DOF.</p>\n";
    s
}

/// The verdict section (`<section id="verdict">`).
pub fn verdict_section(variants: &[&VariantReport]) -> String {
    let mut s = String::from("<section id=\"verdict\"><h2>Verdict</h2>\n");
    let three = sigma_columns(|d| format!("±3σ_{} [{}]", d.symbol(), d.unit()));
    let mut t = Table::new(">#; <variant; <point; <statistic").with(three);
    for (i, v) in variants.iter().enumerate() {
        if v.partial {
            t.note(format!("{} {}: one shard of several: merge the parts first", i + 1, v.name));
            continue;
        }
        if let Some(reason) = &v.cannot_seat {
            t.note(format!("{} {}: CANNOT SEAT: {reason}", i + 1, v.name));
            continue;
        }
        for p in &v.points {
            let mut row = cells![i + 1, &v.name, &p.name, "±3σ"];
            row.extend(p.three_sigma.values().map(Cell::Num));
            match (&p.sigma_ci90_low, &p.sigma_ci90_high) {
                (Some(lo), Some(hi)) => {
                    let (lo, hi) = (lo.values(), hi.values());
                    let under = (0..6).map(|k| format!("[{:.2}, {:.2}]", 3.0 * lo[k], 3.0 * hi[k]));
                    t.row(row).under([vec![String::new(); 4], under.collect()].concat());
                }
                _ => {
                    t.row(row);
                }
            }
            for (what, d) in [("mean", &p.mean), ("min", &p.min), ("max", &p.max)] {
                let mut row = cells!["", "", "", what];
                row.extend(d.values().map(Cell::Num));
                t.row(row);
            }
        }
    }
    s += &t.html("verdict");
    s += "<p class=\"note\">±3σ: three standard deviations of the seated pose relative to the nominal seating, the reproducibility in the sense of the paper; under each its 90 % interval (three times σ's). mean, min, max: of the samples, relative to the nominal seating.</p>\n";
    s += &directions_table(variants);
    s += "<ul class=\"verdict\">\n";
    for (i, v) in variants.iter().enumerate().filter(|(_, v)| !v.partial) {
        let Some(a) = &v.assessment else { continue };
        let class = if a.above_friction_limit { " class=\"warn\"" } else { "" };
        let _ = writeln!(
            s,
            "<li{class}>{} {}: {}</li>\n<li>{} {}: {}</li>",
            i + 1,
            escape(&v.name),
            escape(&friction_line(a)),
            i + 1,
            escape(&v.name),
            escape(&safety_line(a))
        );
        if let (Some(k), Some(share)) = (v.seating_failures, v.seating_failure_share)
            && k > 0
        {
            let _ = writeln!(
                s,
                "<li class=\"warn\">{} {}: {k} of {} seatings did not centre ({:.1} %)</li>",
                i + 1,
                escape(&v.name),
                v.samples,
                100.0 * share
            );
        }
    }
    s + "</ul>\n</section>\n"
}
