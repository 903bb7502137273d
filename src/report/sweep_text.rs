//! The sweep's terminal table (nm, nrad, labelled) and long-format CSV (SI).

use std::fmt::Write;

use crate::explore::SweptValue;
use crate::explore::{DesignReport, SweepReport};
use crate::report::study_text::{csv_field, point_csv_fields, truncate};
use crate::study::provenance::{SCHEMA_VERSION, VERSION};

/// A number in at most 4 significant digits, no trailing zeros (tables
/// and chart ticks; the JSON and CSV keep every digit).
pub fn short(v: f64) -> String {
    if v != 0.0 && !(1e-3..1e5).contains(&v.abs()) {
        return format!("{v:.3e}");
    }
    let digits = (3 - v.abs().log10().floor() as i32).clamp(0, 6) as usize;
    let t = format!("{v:.digits$}");
    if t.contains('.') {
        t.trim_end_matches('0').trim_end_matches('.').to_string()
    } else {
        t
    }
}

/// Provenance and design columns, then the swept fields, then these.
pub const CSV_TAIL: &str = "status,pareto,point,dof,unit,n,mean,min,max,sigma,three_sigma,sigma_ci90_low,sigma_ci90_high,sigma_interval_method,min_principal_stiffness_n_per_m,min_pressure_safety_factor,friction_limit,friction_limit_margin,nominal_approach_m";

/// Columns before the swept fields.
pub const CSV_HEAD: &str =
    "kinrepro_version,schema_version,solver,sampler,seed,samples,vary,design,scene,design_index";

fn opt(x: Option<f64>) -> String {
    x.map_or(String::new(), |x| format!("{x:e}"))
}

fn value_text(v: Option<&SweptValue>) -> String {
    match v {
        Some(SweptValue::Number(x)) => format!("{x}"),
        Some(SweptValue::Name(s)) => csv_field(s),
        None => String::new(),
    }
}

fn pareto_text(p: Option<bool>) -> &'static str {
    match p {
        Some(true) => "true",
        Some(false) => "false",
        None => "",
    }
}

impl SweepReport {
    /// One row per design point, evaluation point and DOF (one row with
    /// empty statistics for a design that was not evaluated), SI units.
    pub fn csv(&self) -> String {
        let fields: Vec<String> = self.sets.iter().map(|s| csv_field(&s.field)).collect();
        let mut s = format!("{CSV_HEAD},{},{CSV_TAIL}\n", fields.join(","));
        for d in &self.designs {
            let head = format!(
                "{VERSION},{SCHEMA_VERSION},{},{},{},{},{},{},{},{},{},{},{}",
                self.solver,
                self.sampler,
                self.seed,
                self.samples,
                self.vary.join("+"),
                self.design.name(),
                csv_field(&self.scene),
                d.index,
                self.sets
                    .iter()
                    .map(|f| value_text(d.values.get(&f.field)))
                    .collect::<Vec<_>>()
                    .join(","),
                csv_field(&d.status),
                pareto_text(d.pareto)
            );
            let tail = format!(
                "{},{},{},{},{}",
                opt(d.principal_stiffness_n_per_m.map(|k| k[0])),
                opt(d.min_pressure_safety_factor),
                opt(d.friction_limit),
                opt(d.friction_limit_margin),
                opt(d.nominal_approach_m)
            );
            if d.points.is_empty() {
                let _ = writeln!(s, "{head},,,,,,,,,,,,,,{tail}");
            }
            for p in &d.points {
                for stats in point_csv_fields(p) {
                    let _ = writeln!(s, "{head},{stats},{tail}");
                }
            }
        }
        s
    }

    /// The terminal table: one block per design point.
    pub fn table(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "{}", self.produced_by());
        let sets: Vec<String> = self
            .sets
            .iter()
            .map(|x| format!("{} = {}", x.field, x.values))
            .collect();
        let _ = writeln!(
            s,
            "Sweep of {} ({}): {}. Per design point and evaluation point the standard deviation of the seated pose relative to the design's nominal seating (divisor n-1), its 90 % interval below ({}); then for the nominal seating: k_min, the lowest principal translational stiffness [N/um]; SF_p, the smallest safety factor against the allowable contact pressure; mu_lim, the friction limit for seating and its margin over mu_static + spread; approach along the preload [nm]. P: on the Pareto front (largest translational sigma at {}, k_min, SF_p).",
            self.name,
            self.scene,
            sets.join("; "),
            self.interval_method(),
            self.pareto_point
        );
        let _ = writeln!(s);
        let _ = writeln!(
            s,
            "{:<5}{:<34}{:<16}{:>14}{:>14}{:>14}{:>18}{:>18}{:>18}{:>10}{:>8}{:>8}{:>9}{:>10} P",
            "#",
            "values",
            "point",
            "σx [nm]",
            "σy [nm]",
            "σz [nm]",
            "σφx [nrad]",
            "σφy [nrad]",
            "σφz [nrad]",
            "k_min",
            "SF_p",
            "mu_lim",
            "margin",
            "appr [nm]"
        );
        for d in &self.designs {
            self.design_rows(&mut s, d);
        }
        s
    }

    fn design_rows(&self, s: &mut String, d: &DesignReport) {
        let values: Vec<String> = self
            .sets
            .iter()
            .map(|f| match d.values.get(&f.field) {
                Some(SweptValue::Number(x)) => short(*x),
                Some(SweptValue::Name(n)) => n.clone(),
                None => String::new(),
            })
            .collect();
        let values = truncate(&values.join(", "), 33);
        let num = |x: Option<f64>, p: usize| x.map_or("-".to_string(), |x| format!("{x:.p$}"));
        let tail = format!(
            "{:>10}{:>8}{:>8}{:>9}{:>10} {}",
            num(d.principal_stiffness_n_per_m.map(|k| k[0] * 1e-6), 2),
            num(d.min_pressure_safety_factor, 2),
            num(d.friction_limit, 4),
            num(d.friction_limit_margin, 4),
            num(d.nominal_approach_m.map(|a| a * 1e9), 1),
            match d.pareto {
                Some(true) => "*",
                _ => "",
            }
        );
        if d.points.is_empty() {
            let _ = writeln!(
                s,
                "{:<5}{:<34}{:<112}{tail}",
                d.index,
                values,
                truncate(&d.status, 111)
            );
            return;
        }
        for (i, p) in d.points.iter().enumerate() {
            let sg = p.sigma.values();
            let _ = writeln!(
                s,
                "{:<5}{:<34}{:<16}{:>14.3}{:>14.3}{:>14.3}{:>18.2}{:>18.2}{:>18.2}{}",
                if i == 0 {
                    d.index.to_string()
                } else {
                    String::new()
                },
                if i == 0 { values.as_str() } else { "" },
                truncate(&p.name, 15),
                sg[0],
                sg[1],
                sg[2],
                sg[3],
                sg[4],
                sg[5],
                if i == 0 { tail.as_str() } else { "" }
            );
            if let (Some(lo), Some(hi)) = (&p.sigma_ci90_low, &p.sigma_ci90_high) {
                let (lo, hi) = (lo.values(), hi.values());
                let ci: Vec<String> = (0..6)
                    .map(|k| {
                        let w = if k < 3 { 14 } else { 18 };
                        format!("{:>w$}", format!("[{:.2}, {:.2}]", lo[k], hi[k]))
                    })
                    .collect();
                let _ = writeln!(s, "{:<55}{}", "", ci.join(""));
            } else {
                let _ = writeln!(s, "{:<55}(no interval: {})", "", p.sigma_interval_method);
            }
        }
    }

    /// The interval methods of the evaluated designs.
    fn interval_method(&self) -> String {
        let mut m: Vec<&str> = Vec::new();
        for p in self.designs.iter().flat_map(|d| &d.points) {
            if !m.contains(&p.sigma_interval_method.as_str()) {
                m.push(&p.sigma_interval_method);
            }
        }
        if m.is_empty() {
            "no design evaluated".to_string()
        } else {
            m.join("; ")
        }
    }
}

#[cfg(test)]
mod tests {
    use super::short;

    #[test]
    fn short_numbers() {
        assert_eq!(short(5.0), "5");
        assert_eq!(short(16.666666666666664), "16.67");
        assert_eq!(short(0.005), "0.005");
        assert_eq!(short(0.0), "0");
        assert_eq!(short(-2.5), "-2.5");
        assert_eq!(short(2.1e11), "2.100e11");
    }
}
