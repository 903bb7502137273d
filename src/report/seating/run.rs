//! Output of `kinrepro run`: one seating, as a table (nm, nrad, N) or JSON (SI).

use std::fmt::Write;

use serde::Serialize;

use crate::assembly::Coupling;
use crate::dof::{Dof, nano};
use crate::report::table::{Cell, Column, Table, cells};
use crate::scene::Scene;
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
    /// Load increments taken (all levels of a controlled seating), or the
    /// dynamic solver's time steps.
    pub increments: usize,
    pub newton_iterations: usize,
    /// Estimated discretisation error of the seated pose relative to the
    /// seating's motion (load-path error control); null where not
    /// estimated (`--increments`, the dynamic solver).
    pub path_error: Option<f64>,
    /// Which path of the solver seated it: `uniform` (quasi-static fast
    /// path), `adaptive` (quasi-static with halving) or `dynamic`.
    pub seating_path: SeatingPath,
    /// Pose components left out of the reproducibility evaluation: none.
    /// phi_z is evaluated like the other five DOFs, as a study reports it
    /// (docs/model.md); the list stays for readers of the field.
    pub not_evaluated: Vec<String>,
    /// What makes these numbers indicative only: each contact too
    /// conformal for Hertz at its seated force (`contact i: ...`); empty
    /// when none.
    pub warnings: Vec<String>,
}

impl RunReport {
    /// The report of `seating` with static coefficients `mu` of `scene`
    /// (assembled as `coupling`), against its `nominal` seating.
    pub fn new(
        (scene, coupling): (&Scene, &Coupling),
        mu: &[f64],
        seating: &Seating,
        nominal: &Seating,
        solver: &str,
    ) -> Self {
        let at = seating.pose();
        let points: Vec<PointReport> = scene
            .evaluation_points
            .iter()
            .map(|p| PointReport {
                name: p.name.clone(),
                position_m: [p.position.x, p.position.y, p.position.z],
                pose: PointPose::between(&coupling.touching_pose, &at, &p.position),
                pose_rel_nominal: PointPose::between(&nominal.pose(), &at, &p.position),
            })
            .collect();
        let seated = &seating.seated;
        let forces: Vec<f64> = seating.contacts.iter().map(|c| c.normal_force_n).collect();
        RunReport {
            kinrepro_version: crate::study::provenance::VERSION.to_string(),
            schema_version: crate::study::provenance::SCHEMA_VERSION,
            scene: scene.file.clone(),
            name: scene.name.clone(),
            solver: solver.to_string(),
            mu_static: mu.to_vec(),
            pose: points[0].pose,
            pose_rel_nominal: points[0].pose_rel_nominal,
            points,
            contacts: seating.contacts.clone(),
            increments: seated.increments,
            newton_iterations: seated.newton_iterations,
            path_error: seated.path_error,
            seating_path: seated.path,
            not_evaluated: Vec::new(),
            warnings: crate::report::contact::conformity_warnings(coupling, &forces),
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
        for w in &self.warnings {
            let _ = writeln!(s, "WARNING: {w}");
        }
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
            let error = match self.path_error {
                Some(e) => format!("path error {e:.1e}"),
                None => "path error not estimated".to_string(),
            };
            let _ = writeln!(
                s,
                "solver: {} ({} path), {} load increments, {} Newton iterations, {error}; mu_s = [{}]",
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
        let mut t = pose_table("<point; <pose");
        for p in &self.points {
            for (label, q) in
                [("from touching", &p.pose), ("rel. to nominal mu", &p.pose_rel_nominal)]
            {
                t.row(pose_cells(cells![&p.name, label], q));
            }
        }
        *s += &t.text();
    }

    /// Each contact: forces, state, stresses and safety factors, with notes.
    fn contact_rows(&self, s: &mut String) {
        let mut t = Table::new(
            ">#; >mu_s:.4; >mu_d:.4; >F_n [N]:.6; >|F_t| [N]:.6; >|F_t|/F_n:.6; >state; >approach[nm]:.4; >p0 [MPa]:.2; >tau_max [MPa]:.2; >SF_p:.2; >SF_tau:.2; >SF:.2",
        );
        for (i, c) in self.contacts.iter().enumerate() {
            t.row(cells![
                i + 1,
                c.mu_static,
                c.mu_dynamic,
                c.normal_force_n,
                c.tangential_force_n,
                c.tangential_force_n / c.normal_force_n,
                c.state.name(),
                nano(c.approach_m),
                c.max_pressure_pa / 1e6,
                c.max_shear_stress_pa / 1e6,
                c.pressure_safety_factor,
                c.shear_safety_factor,
                c.safety_factor,
            ]);
        }
        *s += &t.text();
        support_split(s, &self.contacts);
        let _ = writeln!(
            s,
            "tau_max: maximum subsurface shear stress on the contact axis (closed form for circles, Boussinesq quadrature for ellipses); SF = allowable / actual, \"-\" where the materials give no allowable"
        );
        let left_out = self.contacts.iter().map(|c| c.safety_factor_left_out.as_slice());
        for note in crate::report::contact::safety::left_out_notes(left_out) {
            let _ = writeln!(s, "{note}");
        }
    }
}

/// A table of poses after the columns `first`: the six DOFs in nm and nrad.
pub(crate) fn pose_table(first: &str) -> Table {
    Table::new(first).with(Dof::ALL.map(|d| {
        let p = if d.is_rotation() { 3 } else { 4 };
        Column::right(d.header("")).fixed(p)
    }))
}

/// `first`, then the six DOFs of `q` in nm and nrad.
pub(crate) fn pose_cells(mut first: Vec<Cell>, q: &PointPose) -> Vec<Cell> {
    first.extend(q.components().map(|v| Cell::Num(nano(v))));
    first
}

/// With a series support compliance (`support_compliance`): each contact's
/// approach split into its Hertz and support parts.
fn support_split(s: &mut String, contacts: &[ContactResult]) {
    if contacts.iter().all(|c| c.support_compliance_m_per_n == 0.0) {
        return;
    }
    s.push_str("approach = Hertz + support (series support compliance c):\n");
    let mut t = Table::new(">#; >c [m/N]:.4e; >Hertz [nm]:.4; >support [nm]:.4; >total [nm]:.4");
    for (i, c) in contacts.iter().enumerate() {
        t.row(cells![
            i + 1,
            c.support_compliance_m_per_n,
            nano(c.hertz_approach_m),
            nano(c.support_approach_m),
            nano(c.approach_m),
        ]);
    }
    *s += &t.text();
}
