//! The thermal drift of a study (a scene with `[thermal]`) in words: per
//! evaluation point and cycle point, the drift of each sample from its own
//! seated pose over the samples: mean, min, max, sigma with its 90 %
//! interval and +- 3 sigma (nm, nrad).

use std::fmt::Write;

use crate::dof::Dof;
use crate::report::table::{Cell, Column, Table, cells};
use crate::study::VariantReport;
use crate::study::record::CycleStats;
use crate::study::result::ThermalStudy;

/// The thermal block of a variant's text (empty without `[thermal]`).
pub(crate) fn thermal_text(v: &VariantReport) -> String {
    let Some(t) = &v.thermal else {
        return String::new();
    };
    let mut s = String::new();
    let _ = writeln!(s, "  {}", heading(t));
    for p in &v.points {
        for c in &p.thermal {
            s += &cycle_table(c);
        }
    }
    s
}

/// What the thermal block shows, and of what.
pub(crate) fn heading(t: &ThermalStudy) -> String {
    format!(
        "thermal drift: {} moving half (alpha {:.3e}/K) on {} fixed half (alpha {:.3e}/K); each sample's drift from its own seated pose (rigid motion and expansion), per cycle point; legs to a path tolerance of {:e}",
        t.moving_body,
        t.moving_thermal_expansion_per_k,
        t.fixed_body,
        t.fixed_thermal_expansion_per_k,
        t.path_tolerance
    )
}

/// `[dT_moving, dT_fixed] K` of a cycle point.
pub(crate) fn delta_t_text(d: [f64; 2]) -> String {
    format!("dT = [{}, {}] K", d[0], d[1])
}

/// One point's drift at one cycle point: a row per DOF and direction.
fn cycle_table(c: &CycleStats) -> String {
    let p = &c.drift;
    let title = format!("{} at {}", p.name, delta_t_text(c.delta_t_k));
    let mut t = Table::of([Column::left(&title)])
        .with(Column::list(
            "<; >mean:.3; >min:.3; >max:.3; >sigma:.3; >sigma 90 % interval; >+-3 sigma:.3",
        ))
        .indent(2);
    let values = [p.mean, p.min, p.max, p.sigma].map(|d| d.values());
    let (low, high) = (p.sigma_ci90_low.map(|d| d.values()), p.sigma_ci90_high.map(|d| d.values()));
    let three = p.three_sigma.values();
    for d in Dof::ALL {
        let i = d.index();
        let mut row = cells!["", d.header("")];
        row.extend(values.iter().map(|v| Cell::Num(v[i])));
        row.push(match (low, high) {
            (Some(l), Some(h)) => Cell::Text(format!("[{:.3}, {:.3}]", l[i], h[i])),
            _ => Cell::Missing,
        });
        row.push(Cell::Num(three[i]));
        t.row(row);
    }
    for d in &p.directions {
        let mut row = cells!["", format!("{} [{}]", d.label(), d.unit)];
        row.extend([d.mean, d.min, d.max, d.sigma].map(Cell::Num));
        row.push(
            d.interval().map_or(Cell::Missing, |[l, h]| Cell::Text(format!("[{l:.3}, {h:.3}]"))),
        );
        row.push(Cell::Num(d.three_sigma));
        t.row(row);
    }
    t.text()
}
