//! Output of `kinrepro run`: one seating, as a table (nm, nrad, N) or JSON (SI).

use std::fmt::Write;

use serde::Serialize;

use crate::assembly::Coupling;
use crate::solve::{ContactResult, PointPose, Seating, SeatingPath};

/// Pose of one evaluation point, from the touching pose and from the nominal seating.
#[derive(Debug, Clone, Serialize)]
pub struct PointReport {
    pub name: String,
    pub position_m: [f64; 3],
    pub pose: PointPose,
    pub pose_rel_nominal: PointPose,
}

/// Everything `kinrepro run` reports.
#[derive(Debug, Clone, Serialize)]
pub struct RunReport {
    /// What produced it (`study::provenance`).
    pub kinrepro_version: String,
    pub schema_version: u32,
    pub scene: String,
    pub name: String,
    pub solver: String,
    pub mu_static: Vec<f64>,
    /// Pose of the first evaluation point (the centre by default).
    pub pose: PointPose,
    pub pose_rel_nominal: PointPose,
    pub points: Vec<PointReport>,
    pub contacts: Vec<ContactResult>,
    pub increments: usize,
    pub newton_iterations: usize,
    /// Which path of the solver seated it: `uniform` (quasi-static fast
    /// path), `adaptive` (quasi-static with halving) or `dynamic`.
    pub seating_path: SeatingPath,
    /// Pose components reported but not evaluated for reproducibility
    /// (rotation about z, which the paper leaves out; docs/model.md).
    pub not_evaluated: Vec<&'static str>,
}

impl RunReport {
    pub fn new(
        coupling: &Coupling,
        mu: &[f64],
        seating: &Seating,
        nominal: &Seating,
        solver: &str,
    ) -> Self {
        let points: Vec<PointReport> = coupling
            .scene
            .evaluation_points
            .iter()
            .map(|p| PointReport {
                name: p.name.clone(),
                position_m: [p.position.x, p.position.y, p.position.z],
                pose: PointPose::between(&coupling.touching_pose, &seating.pose, &p.position),
                pose_rel_nominal: PointPose::between(&nominal.pose, &seating.pose, &p.position),
            })
            .collect();
        RunReport {
            kinrepro_version: crate::study::provenance::VERSION.to_string(),
            schema_version: crate::study::provenance::SCHEMA_VERSION,
            scene: coupling.scene.file.clone(),
            name: coupling.scene.name.clone(),
            solver: solver.to_string(),
            mu_static: mu.to_vec(),
            pose: points[0].pose,
            pose_rel_nominal: points[0].pose_rel_nominal,
            points,
            contacts: seating.contacts.clone(),
            increments: seating.increments,
            newton_iterations: seating.newton_iterations,
            seating_path: seating.path,
            not_evaluated: vec!["phi_z_rad"],
        }
    }

    /// Human-readable table: nm, nrad, N, MPa.
    pub fn table(&self) -> String {
        let mut s = String::new();
        self.header(&mut s);
        let _ = writeln!(s);
        self.pose_rows(&mut s);
        let _ = writeln!(s);
        self.contact_rows(&mut s);
        s
    }

    /// Scene and solver.
    fn header(&self, s: &mut String) {
        let _ = writeln!(s, "{}  ({})", self.scene, self.name);
        let mu: Vec<String> = self.mu_static.iter().map(|m| format!("{m:.4}")).collect();
        if self.solver == "dynamic" {
            let _ = writeln!(
                s,
                "solver: dynamic (rapier3d-f64), {} time steps; mu_s = [{}]",
                self.increments,
                mu.join(", ")
            );
        } else {
            let _ = writeln!(
                s,
                "solver: {} ({} path), {} load increments, {} Newton iterations; mu_s = [{}]",
                self.solver,
                self.seating_path.name(),
                self.increments,
                self.newton_iterations,
                mu.join(", ")
            );
        }
    }

    /// The pose of each point, from touching and relative to nominal mu.
    fn pose_rows(&self, s: &mut String) {
        let _ = writeln!(
            s,
            "{:<16} {:<22} {:>10} {:>10} {:>10} {:>11} {:>11} {:>11}",
            "point",
            "pose",
            "x [nm]",
            "y [nm]",
            "z [nm]",
            "phi_x[nrad]",
            "phi_y[nrad]",
            "phi_z[nrad]*"
        );
        for p in &self.points {
            for (label, q) in [
                ("from touching", &p.pose),
                ("rel. to nominal mu", &p.pose_rel_nominal),
            ] {
                let _ = writeln!(
                    s,
                    "{:<16} {:<22} {:>10.4} {:>10.4} {:>10.4} {:>11.3} {:>11.3} {:>11.3}",
                    p.name,
                    label,
                    q.x_m * 1e9,
                    q.y_m * 1e9,
                    q.z_m * 1e9,
                    q.phi_x_rad * 1e9,
                    q.phi_y_rad * 1e9,
                    q.phi_z_rad * 1e9
                );
            }
        }
        let _ = writeln!(
            s,
            "* phi_z is reported but not evaluated for reproducibility."
        );
    }

    /// Each contact: forces, state, stresses and safety factors, with notes.
    fn contact_rows(&self, s: &mut String) {
        let _ = writeln!(
            s,
            "{:>2} {:>7} {:>7} {:>10} {:>10} {:>9} {:>6} {:>11} {:>9} {:>13} {:>8} {:>8} {:>8}",
            "#",
            "mu_s",
            "mu_d",
            "F_n [N]",
            "|F_t| [N]",
            "|F_t|/F_n",
            "state",
            "approach[nm]",
            "p0 [MPa]",
            "tau_max [MPa]",
            "SF_p",
            "SF_tau",
            "SF"
        );
        for (i, c) in self.contacts.iter().enumerate() {
            let _ = writeln!(
                s,
                "{:>2} {:>7.4} {:>7.4} {:>10.6} {:>10.6} {:>9.6} {:>6} {:>11.4} {:>9.2} {:>13.2} {:>8} {:>8} {:>8}",
                i + 1,
                c.mu_static,
                c.mu_dynamic,
                c.normal_force_n,
                c.tangential_force_n,
                c.tangential_force_n / c.normal_force_n,
                match c.state {
                    crate::contact::SlipState::Stick => "stick",
                    crate::contact::SlipState::Slip => "slip",
                },
                c.approach_m * 1e9,
                c.max_pressure_pa / 1e6,
                c.max_shear_stress_pa / 1e6,
                factor(c.pressure_safety_factor),
                factor(c.shear_safety_factor),
                factor(c.safety_factor)
            );
        }
        support_split(s, &self.contacts);
        let _ = writeln!(
            s,
            "tau_max: maximum subsurface shear stress on the contact axis (closed form for circles, Boussinesq quadrature for ellipses); SF = allowable / actual, \"-\" where the materials give no allowable"
        );
        let left_out = self
            .contacts
            .iter()
            .map(|c| c.safety_factor_left_out.as_slice());
        for note in crate::report::safety::left_out_notes(left_out) {
            let _ = writeln!(s, "{note}");
        }
    }
}

/// With a series support compliance (`support_compliance`): each contact's
/// approach split into its Hertz and support parts.
fn support_split(s: &mut String, contacts: &[ContactResult]) {
    if contacts.iter().all(|c| c.support_compliance_m_per_n == 0.0) {
        return;
    }
    let _ = writeln!(
        s,
        "approach = Hertz + support (series support compliance c):\n{:>2} {:>12} {:>12} {:>12} {:>12}",
        "#", "c [m/N]", "Hertz [nm]", "support [nm]", "total [nm]"
    );
    for (i, c) in contacts.iter().enumerate() {
        let _ = writeln!(
            s,
            "{:>2} {:>12.4e} {:>12.4} {:>12.4} {:>12.4}",
            i + 1,
            c.support_compliance_m_per_n,
            c.hertz_approach_m * 1e9,
            c.support_approach_m * 1e9,
            c.approach_m * 1e9
        );
    }
}

/// A safety factor for a table, "-" where no allowable is known.
pub fn factor(f: Option<f64>) -> String {
    f.map(|f| format!("{f:.2}"))
        .unwrap_or_else(|| "-".to_string())
}
