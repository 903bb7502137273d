//! A variant's verdict in words, first in its part of the text table (the
//! HTML report shows the same numbers, `report::html::verdict`): +-3 sigma
//! of each evaluation point with its 90 % interval (3 times sigma's), the
//! friction limit against the largest coefficient drawn, the smallest
//! contact safety factor with the bodies it covers and the materials it
//! leaves out, and the seating failures.

use std::fmt::Write;

use crate::dof::Dof;
use crate::study::VariantReport;
use crate::study::assessment::Assessment;
use crate::study::record::PointStats;

/// The verdict lines of `v` (indented two spaces; empty for a shard).
pub fn verdict_text(v: &VariantReport) -> String {
    let mut s = String::from("  verdict:\n");
    for p in &v.points {
        let _ = writeln!(s, "    {}", three_sigma_line(p));
    }
    if let Some(a) = &v.assessment {
        let _ = writeln!(s, "    {}", friction_line(a));
        let _ = writeln!(s, "    {}", safety_line(a));
    }
    match (v.seating_failures, v.seating_failure_share) {
        (Some(k), Some(share)) if k > 0 => {
            let _ = writeln!(
                s,
                "    seating failures: {k} of {} seatings did not centre ({:.1} %)",
                v.samples,
                100.0 * share
            );
        }
        _ => {}
    }
    s
}

/// `+-3 sigma at centre [nm, nrad]: x 14.05 [12.10, 16.90], ...`.
pub fn three_sigma_line(p: &PointStats) -> String {
    let three = p.three_sigma.values();
    let ends = |d: Option<&crate::dof::Dofs>| d.map(|d| d.values().map(|x| 3.0 * x));
    let (low, high) = (ends(p.sigma_ci90_low.as_ref()), ends(p.sigma_ci90_high.as_ref()));
    let each: Vec<String> = Dof::ALL
        .iter()
        .map(|d| {
            let j = d.index();
            match (low, high) {
                (Some(l), Some(h)) => {
                    format!("{} {:.2} [{:.2}, {:.2}]", d.name(), three[j], l[j], h[j])
                }
                _ => format!("{} {:.2}", d.name(), three[j]),
            }
        })
        .chain(p.directions.iter().map(|d| match d.interval() {
            Some([l, h]) => {
                format!("{} {:.2} [{:.2}, {:.2}]", d.label(), d.three_sigma, 3.0 * l, 3.0 * h)
            }
            None => format!("{} {:.2}", d.label(), d.three_sigma),
        }))
        .collect();
    format!("+-3 sigma at {} [nm, nrad; 90 % interval]: {}", p.name, each.join(", "))
}

/// The friction limit against the largest coefficient drawn.
pub fn friction_line(a: &Assessment) -> String {
    match (a.friction_limit, a.friction_limit_contact) {
        (Some(limit), Some(k)) if a.above_friction_limit => format!(
            "WARNING: the largest mu_s drawn, {:.3}, is above the friction limit for seating \
             {limit:.4} (contact {k} can stay open first): seating from the touching pose, as \
             this study does, is unaffected, but a half that arrives off-centre may stick off \
             its seat instead of centring",
            a.mu_max
        ),
        (Some(limit), Some(k)) => format!(
            "friction limit for seating {limit:.4} (contact {k}): above the largest mu_s drawn, \
             {:.3}; a half that arrives off-centre slides into its seat",
            a.mu_max
        ),
        _ => "friction limit for seating: none below mu = 10".to_string(),
    }
}

/// The smallest contact safety factor, the bodies it covers and the
/// materials it leaves out (as `check` says it).
pub fn safety_line(a: &Assessment) -> String {
    let Some(w) = a.weakest() else {
        return "contact safety factor: none (no material gives an allowable stress)".into();
    };
    let [m1, m2] = &w.materials;
    let mut s = format!(
        "smallest contact safety factor {:.2} at contact {} ({m1} on {m2}, at the frictionless \
         preload forces)",
        w.safety_factor.unwrap_or(f64::NAN),
        w.contact
    );
    let left: Vec<String> =
        w.left_out.iter().map(|l| format!("{} (no {})", l.material, l.missing)).collect();
    if !left.is_empty() {
        let _ = write!(s, "; it leaves out {}, so it covers the other body only", left.join(", "));
    }
    s
}
