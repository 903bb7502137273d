//! Output of `kinrepro thermal`: the drift of each evaluation point along
//! the temperature cycle, as a table (nm, nrad, K) or JSON (SI units,
//! kelvin), and the first slip.

use std::fmt::Write;

use serde::Serialize;

use crate::assembly::{AssemblyError, Coupling};
use crate::report::seating::run::{pose_cells, pose_table};
use crate::report::table::{Column, cells};
use crate::scene::{Body, Scene, Temperatures, ThermalBodies};
use crate::solve::thermal::{FirstSlip, ThermalPath};
use crate::solve::{Load, PointPose, Seating};

/// One body of `[thermal]`.
#[derive(Debug, Clone, Serialize)]
pub struct BodyReport {
    pub material: String,
    pub thermal_expansion_per_k: f64,
    pub origin_m: [f64; 3],
}

impl From<&Body> for BodyReport {
    fn from(b: &Body) -> Self {
        BodyReport {
            material: b.material.clone(),
            thermal_expansion_per_k: b.thermal_expansion,
            origin_m: b.origin.into(),
        }
    }
}

/// The drift of one evaluation point at one cycle point.
#[derive(Debug, Clone, Serialize)]
pub struct DriftReport {
    pub name: String,
    /// Its displacement from where it was seated, in the fixed frame (the
    /// moving half's rigid motion and the body's own expansion) [m].
    pub displacement_m: [f64; 3],
    /// The rotation of the moving half since the seating (rotation vector) [rad].
    pub rotation_rad: [f64; 3],
}

/// One point of the cycle.
#[derive(Debug, Clone, Serialize)]
pub struct CycleReport {
    /// Temperature changes [moving, fixed] from the seating temperature [K].
    pub delta_t_k: Temperatures,
    /// Estimated discretisation error relative to the larger of the
    /// seating's motion and the leg's (null on fixed increments).
    pub path_error: Option<f64>,
    /// Contacts (1-based) that slid on the way from the previous point.
    pub slipping_contacts: Vec<usize>,
    pub points: Vec<DriftReport>,
    pub increments: usize,
    pub newton_iterations: usize,
}

/// Everything `kinrepro thermal` reports.
#[derive(Debug, Clone, Serialize)]
pub struct ThermalReport {
    /// What produced it (`study::provenance`).
    pub kinrepro_version: String,
    pub schema_version: u32,
    pub scene: String,
    pub name: String,
    pub solver: String,
    /// The seating's load-path tolerance (null: fixed increments).
    pub path_tolerance: Option<f64>,
    /// The cycle's legs' tolerance (`[thermal] path_tolerance`; null: fixed
    /// increments).
    pub thermal_path_tolerance: Option<f64>,
    pub tangential_law: String,
    pub mu_static: Vec<f64>,
    pub moving_body: BodyReport,
    pub fixed_body: BodyReport,
    /// The seating's estimated path error (the cycle starts from it).
    pub seating_path_error: Option<f64>,
    pub cycle: Vec<CycleReport>,
    /// The larger in size of the two bodies' temperature changes at which
    /// the first contact slides [K]; null when none slides.
    pub first_slip_delta_t_k: Option<f64>,
    pub first_slip: Option<FirstSlip>,
}

impl ThermalReport {
    /// The report of `path`, which followed the cycle after `seating` of
    /// `scene` (assembled as `coupling`) under `load`.
    pub fn new(
        (scene, coupling): (&Scene, &Coupling),
        load: &Load,
        seating: &Seating,
        path: &ThermalPath,
        path_tolerance: Option<f64>,
    ) -> Result<Self, AssemblyError> {
        let bodies: &ThermalBodies = coupling.thermal_bodies()?;
        let cycle = (path.points.iter().enumerate())
            .map(|(k, c)| CycleReport {
                delta_t_k: c.temperatures,
                path_error: c.path_error,
                slipping_contacts: c.slipping.clone(),
                points: (scene.evaluation_points.iter())
                    .map(|p| {
                        let q = path.drift(bodies, k, &p.position);
                        let [x, y, z, a, b, g] = q.components();
                        DriftReport {
                            name: p.name.clone(),
                            displacement_m: [x, y, z],
                            rotation_rad: [a, b, g],
                        }
                    })
                    .collect(),
                increments: c.increments,
                newton_iterations: c.newton_iterations,
            })
            .collect();
        Ok(ThermalReport {
            kinrepro_version: crate::study::provenance::VERSION.to_string(),
            schema_version: crate::study::provenance::SCHEMA_VERSION,
            scene: scene.file.clone(),
            name: scene.name.clone(),
            solver: "quasi-static".to_string(),
            path_tolerance,
            thermal_path_tolerance: path_tolerance.map(|_| load.thermal_tolerance),
            tangential_law: scene.friction.tangential_law.name().to_string(),
            mu_static: load.mu.clone(),
            moving_body: (&bodies.moving).into(),
            fixed_body: (&bodies.fixed).into(),
            seating_path_error: seating.seated.path_error,
            cycle,
            first_slip_delta_t_k: path.first_slip.map(|f| f.temperatures.size()),
            first_slip: path.first_slip,
        })
    }

    /// Human-readable: the bodies, then per cycle point the drift of each
    /// evaluation point (nm, nrad), the contacts that slid, the first slip.
    pub fn table(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "{}  ({})", self.scene, self.name);
        let mu: Vec<String> = self.mu_static.iter().map(|m| format!("{m:.4}")).collect();
        let control = match (self.path_tolerance, self.thermal_path_tolerance) {
            (Some(t), Some(c)) => format!("path tolerance {t:.0e} seating, {c:.0e} cycle"),
            _ => "fixed increments".to_string(),
        };
        let _ = writeln!(
            s,
            "kinrepro {}: thermal path after the seating, solver {} ({control}), {} law; mu_s = [{}]",
            self.kinrepro_version,
            self.solver,
            self.tangential_law,
            mu.join(", ")
        );
        for (what, b) in [("moving", &self.moving_body), ("fixed", &self.fixed_body)] {
            let [x, y, z] = b.origin_m;
            let _ = writeln!(
                s,
                "{what} body: {} (alpha {:.3e} /K), expanding about [{x}, {y}, {z}] m",
                b.material, b.thermal_expansion_per_k
            );
        }
        let _ = writeln!(
            s,
            "\ndrift from the seated pose (displacement in the fixed frame, rotation of the moving half):"
        );
        let mut t = pose_table(">dT moving [K]:.3; >dT fixed [K]:.3; <point")
            .with(Column::list("<slid; >path error:.1e"));
        for c in &self.cycle {
            for (j, p) in c.points.iter().enumerate() {
                let [x, y, z] = p.displacement_m;
                let [a, b, g] = p.rotation_rad;
                let q = PointPose::from_components([x, y, z, a, b, g]);
                let first = if j == 0 {
                    cells![c.delta_t_k.moving, c.delta_t_k.fixed, p.name.as_str()]
                } else {
                    cells!["", "", p.name.as_str()]
                };
                let mut row = pose_cells(first, &q);
                let slid: Vec<String> = c.slipping_contacts.iter().map(|i| i.to_string()).collect();
                let slid = if slid.is_empty() { "none".to_string() } else { slid.join(",") };
                let error = if j == 0 { c.path_error } else { None };
                row.extend(cells![if j == 0 { slid } else { String::new() }, error]);
                t.row(row);
            }
        }
        s += &t.text();
        let _ = writeln!(s);
        match &self.first_slip {
            Some(f) => {
                let _ = writeln!(
                    s,
                    "first slip: contact {} at dT = [{:.4}, {:.4}] K (moving, fixed), on the way to cycle point {}",
                    f.contact, f.temperatures.moving, f.temperatures.fixed, f.cycle_point
                );
            }
            None => {
                let _ = writeln!(
                    s,
                    "no contact slides on this cycle: the drift is elastic and reversible"
                );
            }
        }
        if let Some(last) = self.cycle.last()
            && last.delta_t_k == Temperatures::ZERO
        {
            let _ = writeln!(
                s,
                "the last point is back at the seating temperature: its drift is the residual (thermal hysteresis)"
            );
        }
        s
    }
}
