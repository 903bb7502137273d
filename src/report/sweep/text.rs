//! The sweep's terminal table (nm, nrad, labelled) and long-format CSV (SI).

use std::fmt::Write;

use crate::dof::nano;
use crate::explore::SweptValue;
use crate::explore::{DesignReport, SweepReport};
use crate::report::study::text::{
    estimates, interval_methods, point_csv_rows, sigma_cells, sigma_columns, thermal_output_point,
    truncate,
};
use crate::report::table::{Cell, Column, Table, cells};
use crate::study::PointStats;
use crate::study::provenance::{SCHEMA_VERSION, VERSION};
use crate::study::stats::SigmaMethod;

/// A number in at most 4 significant digits, no trailing zeros (tables
/// and chart ticks; the JSON and CSV keep every digit).
pub fn short(v: f64) -> String {
    if v != 0.0 && !(1e-3..1e5).contains(&v.abs()) {
        return format!("{v:.3e}");
    }
    let digits = (3 - v.abs().log10().floor() as i32).clamp(0, 6) as usize;
    let t = format!("{v:.digits$}");
    if t.contains('.') { t.trim_end_matches('0').trim_end_matches('.').to_string() } else { t }
}

/// The unit of a swept field in the scene format (docs/scenes.md): `m`,
/// `deg`, `N`, ...; `-` for a dimensionless number, "" for a name.
pub fn field_unit(path: &str) -> &'static str {
    match path.rsplit('.').next().unwrap_or(path) {
        "diameter"
        | "ball_diameter"
        | "groove_element_diameter"
        | "groove_radius"
        | "canoe_radius" => "m",
        "opening_angle_deg" => "deg",
        "support_compliance" => "m/N",
        "force" => "N",
        "ramp_time" => "s",
        "decay_coefficient" => "s/m",
        "youngs_modulus" | "allowable_pressure" | "allowable_shear_stress" => "Pa",
        "mu_static" | "spread" | "dynamic_ratio" | "poisson_ratio" | "path_tolerance" => "-",
        "thermal_expansion" => "1/K",
        _ => "",
    }
}

/// A swept field with its unit, for headers and axes: `preload.force [N]`.
pub fn field_label(path: &str) -> String {
    match field_unit(path) {
        "" => path.to_string(),
        u => format!("{path} [{u}]"),
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

impl SweepReport {
    /// One row per design point, evaluation point and DOF (one row with
    /// empty statistics for a design that was not evaluated), SI units.
    pub fn csv(&self) -> String {
        let fields = self.sets.iter().map(|s| s.field.as_str());
        let header = CSV_HEAD.split(',').chain(fields).chain(CSV_TAIL.split(','));
        let mut t = Table::of(header.map(Column::left));
        for d in &self.designs {
            let values = self.sets.iter().map(|f| match d.values.get(&f.field) {
                Some(SweptValue::Number(x)) => format!("{x}"),
                Some(SweptValue::Name(s)) => s.clone(),
                None => String::new(),
            });
            let pareto = d.pareto.map_or(String::new(), |p| p.to_string());
            let head: Vec<String> = [VERSION.to_string(), SCHEMA_VERSION.to_string()]
                .into_iter()
                .chain([self.solver.clone(), self.sampler.to_string()])
                .chain([self.seed.to_string(), self.samples.to_string(), self.vary.join("+")])
                .chain([self.design.name().to_string(), self.scene.clone(), d.index.to_string()])
                .chain(values)
                .chain([d.status.clone(), pareto])
                .collect();
            let tail = [
                d.principal_stiffness_n_per_m.map(|k| k[0]),
                d.min_pressure_safety_factor,
                d.friction_limit,
                d.friction_limit_margin,
                d.nominal_approach_m,
            ]
            .map(opt);
            let stats = match d.points.is_empty() {
                true => vec![vec![String::new(); 12]],
                false => d.points.iter().flat_map(point_csv_rows).collect(),
            };
            for st in stats {
                t.row(head.iter().chain(&st).chain(&tail).map(Into::into).collect());
            }
        }
        t.csv()
    }

    /// The terminal table: one block per design point.
    pub fn table(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "{}", self.produced_by());
        let sets: Vec<String> =
            self.sets.iter().map(|x| format!("{} = {}", x.field, x.values)).collect();
        let _ = writeln!(
            s,
            "Sweep of {} ({}): {}. Per design point and evaluation point the standard deviation of the seated pose relative to the design's nominal seating ({}), its 90 % interval below ({}); then for the nominal seating: k_min, the lowest principal translational stiffness [N/um]; SF_p, the smallest safety factor against the allowable contact pressure; mu_lim, the friction limit for seating and its margin over mu_static + spread; approach along the preload [nm]; for a scene with [thermal], thermal/k/point: the mean and sigma of the point's drift from each sample's seated pose at cycle point k. {}",
            self.name,
            self.scene,
            sets.join("; "),
            sigma_estimates(self),
            interval_methods(self.designs.iter().flat_map(|d| &d.points), "no design evaluated"),
            self.front_description()
        );
        let _ = writeln!(s);
        let sigma = sigma_columns(|d| format!("σ{} [{}]", d.symbol(), d.unit()));
        let tail = Column::list(">k_min:.2; >SF_p:.2; >mu_lim:.4; >margin:.4; >appr [nm]:.1; <P");
        let mut t = Table::new("<#; <values; <point").with(sigma).with(tail);
        for d in &self.designs {
            self.design_rows(&mut t, d);
        }
        s + &t.text()
    }

    /// The rows of one design point: one per evaluation point with its
    /// interval under it; the nominal seating's columns on the first.
    fn design_rows(&self, t: &mut Table, d: &DesignReport) {
        let values: Vec<String> = self
            .sets
            .iter()
            .map(|f| match d.values.get(&f.field) {
                Some(SweptValue::Number(x)) => short(*x),
                Some(SweptValue::Name(n)) => n.clone(),
                None => String::new(),
            })
            .collect();
        let tail = cells![
            d.principal_stiffness_n_per_m.map(|k| k[0] * 1e-6),
            d.min_pressure_safety_factor,
            d.friction_limit,
            d.friction_limit_margin,
            d.nominal_approach_m.map(nano),
            match (d.pareto, d.broken_constraints.is_empty()) {
                (Some(true), _) => "*",
                (_, false) => "x",
                _ => "",
            },
        ];
        let mut head = cells![d.index, truncate(&values.join(", "), 33)];
        if d.points.is_empty() {
            let blank = std::iter::repeat_n(Cell::from(""), 7);
            t.row(head.into_iter().chain(blank).chain(tail).collect());
            t.note(format!("  {}", d.status));
            return;
        }
        for (i, p) in d.points.iter().enumerate() {
            let (sigma, under) = sigma_cells(p);
            let mut row = std::mem::replace(&mut head, cells!["", ""]);
            row.push(truncate(&p.name, 15).into());
            row.extend(sigma);
            match i {
                0 => row.extend(tail.iter().cloned()),
                _ => row.extend(std::iter::repeat_n(Cell::from(""), tail.len())),
            }
            let r = t.row(row);
            match under {
                Some(u) => {
                    r.under([vec![String::new(); 3], u, vec![String::new(); 6]].concat());
                }
                None => t.note(format!("  (no interval: {})", p.sigma_interval_method)),
            }
            if !p.directions.is_empty() {
                t.note(format!("  {}: {}", p.name, directions_text(p)));
            }
            if i == 0 && !d.broken_constraints.is_empty() {
                t.note(format!("  breaks {}", d.broken_constraints.join(", ")));
            }
            for (k, c) in p.thermal.iter().enumerate() {
                // The drift's scatter at cycle point k, under its mean.
                let name = truncate(&thermal_output_point(k, &p.name), 15);
                let mut mean = cells!["", "", format!("{name} mean")];
                mean.extend(c.drift.mean.values().map(Cell::Num));
                t.row(mean);
                let (sigma, _) = sigma_cells(&c.drift);
                let mut row = cells!["", "", format!("{name} σ")];
                row.extend(sigma);
                t.row(row);
            }
        }
    }
}

impl SweepReport {
    /// What the P column marks: the front's objectives and constraints.
    pub fn front_description(&self) -> String {
        let g = &self.goals;
        let objectives = match g.objectives.is_empty() {
            true => format!("largest translational sigma at {}, k_min, SF_p", self.pareto_point),
            false => g.objectives.iter().map(|o| o.name()).collect::<Vec<_>>().join(", "),
        };
        match g.constraints.is_empty() {
            true => format!("P: on the Pareto front ({objectives})."),
            false => format!(
                "P: * on the Pareto front ({objectives}) of the designs that meet {} (SI units); x: breaks a constraint (named under its row), off the front.",
                g.constraints.iter().map(|c| c.name()).collect::<Vec<_>>().join(", ")
            ),
        }
    }
}

/// `σ along <name> <value> [<unit>] [<low>, <high>]` per direction of `p`.
fn directions_text(p: &PointStats) -> String {
    let each = p.directions.iter().map(|d| {
        let ci = d.interval().map_or(String::new(), |[l, h]| format!(" [{l:.2}, {h:.2}]"));
        format!("σ {} {:.3} {}{ci}", d.label(), d.sigma, d.unit)
    });
    each.collect::<Vec<_>>().join(", ")
}

/// The point estimate of sigma of the sampler that ran, in words
/// ([`SigmaMethod::estimate`]): one per kind among the evaluated design
/// points (an LHS some of whose seatings did not centre has its own, which
/// its points' interval method names).
pub(crate) fn sigma_estimates(r: &SweepReport) -> String {
    let ran = SigmaMethod::for_sampler(r.sampler, r.fingerprint.study.replicates);
    let incomplete = SigmaMethod::IncompleteLhs.describe();
    let methods = r.designs.iter().filter(|d| !d.points.is_empty()).map(|d| {
        let gaps = (d.points.iter()).any(|p| p.sigma_interval_method.starts_with(&incomplete));
        if gaps { SigmaMethod::IncompleteLhs } else { ran }
    });
    match estimates(methods) {
        e if e.is_empty() => ran.estimate(),
        e => e,
    }
}
