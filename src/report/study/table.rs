//! The Table 2 style text table of a study: the variants side by side,
//! then each variant's statistics and sensitivity.

use std::fmt::Write;

use super::labels::{block_label, output_point};
use crate::contact::FrictionLaw;
use crate::report::study::text::{
    bounds_text, detail, interval_methods, sigma_estimates, sigma_table, varied,
};
use crate::report::table::{Cell, Column, Table, cells};
use crate::study::sensitivity::{DofSensitivity, SensitivityBlock};
use crate::study::{StudyReport, VariantReport};

impl StudyReport {
    /// The text table: the variants side by side as in the paper's Table 2,
    /// then the full statistics of each variant.
    pub fn table(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "{}, shard {}", self.produced_by(), self.shard);
        for w in self.cannot_seat() {
            let _ = writeln!(s, "CANNOT SEAT: {w}");
        }
        if self.variants.iter().any(|v| v.partial || !v.points.is_empty()) {
            let _ = writeln!(
                s,
                "Standard deviation of the seated pose relative to the nominal seating (nominal friction and preload, touching start; {}); below each row the 90 % interval of sigma, by a method valid for the design: {}.",
                sigma_estimates(&self.variants),
                interval_methods(
                    self.variants.iter().flat_map(|v| &v.points),
                    "per variant, after merging"
                )
            );
            let _ = writeln!(s);
            s += &sigma_table(&self.variants, |v| &v.points);
        }
        if self.variants.iter().any(|v| !v.interchangeability.is_empty()) {
            if self.variants.iter().any(|v| !v.points.is_empty()) {
                s.push('\n');
            }
            s += "Interchangeability (manufacturing tolerances): standard deviation (and its interval) as above, of the seated pose of each perturbed coupling at nominal friction and preload, relative to the nominal geometry's seating.\n\n";
            s += &sigma_table(&self.variants, |v| &v.interchangeability);
        }
        for v in self.variants.iter().filter(|v| !v.partial) {
            s += &variant_text(v);
        }
        s
    }
}

/// One complete variant in words: its settings, what varied, the seating
/// failures of a varied start, the statistics of each point and the
/// sensitivity tables.
fn variant_text(v: &VariantReport) -> String {
    let mut s = String::new();
    let mu = crate::scene::mu::describe_friction(
        (v.mu_static, v.spread),
        v.contact_friction.as_deref(),
        (&v.mu_distribution, v.mu_correlation),
        "uniform",
    );
    let _ = writeln!(
        s,
        "\n{} ({}): {} samples, {} seed {}, {mu}, mu_d = {} mu_s, {}",
        v.name,
        v.scene,
        v.samples,
        v.sampler,
        v.seed,
        v.dynamic_ratio,
        friction_law_text(&v.friction_law, v.ramp_time_s)
    );
    let _ = writeln!(s, "  varied: {}", varied(v));
    if let Some(p) = &v.load_path {
        let error = match p.max_path_error {
            Some(e) => format!("largest path error {e:.1e}"),
            None => "path error not estimated (fixed increments)".to_string(),
        };
        let _ = writeln!(
            s,
            "  load path: {error}; {:.1} load increments per seating (max {})",
            p.increments_mean, p.increments_max
        );
    }
    if v.streamed {
        let _ = writeln!(
            s,
            "  streamed: statistics from one-pass moments in sample order (no records kept); interval of sigma: {}",
            crate::study::stats::interval::METHOD_BONETT
        );
    }
    if let Some(b) = &v.variation_bounds {
        let _ = writeln!(s, "  [variation] bounds: {}", bounds_text(b));
    }
    if let (Some(k), Some(share)) = (v.seating_failures, v.seating_failure_share) {
        let _ = writeln!(
            s,
            "  seating failures: {k} of {} seatings did not centre ({:.1} %); the statistics are over the {} that did (conditional on centring)",
            v.samples,
            100.0 * share,
            v.samples - k
        );
    }
    if let Some(reason) = &v.cannot_seat {
        // The samples' zero or noise-level scatter is not a result.
        let _ = writeln!(s, "  CANNOT SEAT: {reason}");
        return s;
    }
    s += &super::verdict::verdict_text(v);
    if !v.points.is_empty() {
        let _ = writeln!(s, "  re-seating scatter (one pair of halves):");
        s += &detail(&v.points);
    }
    s += &super::thermal::thermal_text(v);
    if !v.interchangeability.is_empty() {
        let _ = writeln!(s, "  interchangeability (tolerances; nominal friction and preload):");
        s += &detail(&v.interchangeability);
    }
    if let Some(blocks) = &v.sensitivity {
        for b in blocks {
            s += &sensitivity_table(b);
            s += &super::sensitivity::sobol_table(b);
        }
    }
    s
}

/// One SRC table: inputs down, DOFs across.
fn sensitivity_table(b: &SensitivityBlock) -> String {
    let point = b.dofs.first().map_or("", |d| output_point(&d.output));
    let mut s = format!(
        "  sensitivity of the {} scatter at {point}: share of each DOF's variance per input (normalised SRC^2: R^2 SRC_j^2 / sum SRC^2; R^2 of the linear fit)\n",
        b.kind
    );
    let dofs = b.dofs.iter().map(|d| Column::right(block_label(point, &d.output, false)).fixed(3));
    let mut t = Table::new("<input").with(dofs).indent(2);
    let row = |label: String, f: &dyn Fn(&DofSensitivity) -> Option<f64>| {
        let mut r = cells![label];
        r.extend(b.dofs.iter().map(|d| Cell::from(f(d))));
        r
    };
    for (j, input) in b.inputs.iter().enumerate() {
        t.row(row(input.name(), &|d| d.share.get(j).copied()));
    }
    let sum = |d: &DofSensitivity| (!d.share.is_empty()).then(|| d.share.iter().sum());
    t.row(row("sum of shares".into(), &sum));
    t.row(row("R^2".into(), &|d| d.r_squared));
    s += &t.text();
    for d in &b.dofs {
        if let Some(n) = &d.note {
            s += &format!("  note, {}: {n}\n", d.output);
        }
    }
    s
}

/// The friction reading in words, for the study header.
fn friction_law_text(law: &FrictionLaw, ramp_time: f64) -> String {
    match law {
        FrictionLaw::Switch => "sudden switch".to_string(),
        FrictionLaw::Decay { coefficient } => format!(
            "decay mu = mu_d + (mu_s - mu_d) exp(-{coefficient} s/m * v_slip), ramp {ramp_time} s"
        ),
    }
}
