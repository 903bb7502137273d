//! Output of `kinrepro stiffness` and `kinrepro load`: tables (N/um,
//! N m/urad, nm, nrad) and JSON (SI).

use std::fmt::Write;

use crate::report::seating::run::{pose_cells, pose_table};
use crate::report::table::{Table, cells};

use nalgebra::Vector3;
use serde::Serialize;

use crate::analysis::load::Envelope;
use crate::analysis::stiffness::CouplingStiffness;
use crate::scene::Scene;
use crate::solve::quasistatic::{ExternalLoad, LIFT_OFF_RATIO, LoadEvent, LoadPath};
use crate::solve::{ContactResult, PointPose, Seating};

/// Why a stiffness report cannot be made.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
pub enum ReportError {
    /// The compliance (its inverse) and the principal stiffnesses need a
    /// positive definite matrix.
    #[error("the stiffness matrix is not positive definite")]
    NotPositiveDefinite,
}

/// A principal stiffness and its direction.
#[derive(Debug, Clone, Serialize)]
pub struct PrincipalReport {
    /// [N/m] (translational) or [N m/rad] (rotational).
    pub stiffness: f64,
    pub direction: [f64; 3],
}

/// The stiffness at one point.
#[derive(Debug, Clone, Serialize)]
pub struct StiffnessPoint {
    pub name: String,
    /// Point in the moving half, scene coordinates [m].
    pub position_m: [f64; 3],
    /// 6x6 stiffness for (u, phi) at the point -> (F, M about it), SI, row-major.
    pub matrix: [[f64; 6]; 6],
    /// Its inverse: (F, M) at the point -> (u [m], phi [rad]).
    pub compliance: [[f64; 6]; 6],
    /// Ascending: pure force at the point, rotation free [N/m].
    pub translational: Vec<PrincipalReport>,
    /// Ascending: pure moment, translation free [N m/rad].
    pub rotational: Vec<PrincipalReport>,
}

/// One contact spring.
#[derive(Debug, Clone, Serialize)]
pub struct SpringReport {
    pub normal_force_n: f64,
    pub normal_stiffness_n_per_m: f64,
    pub tangential_stiffness_n_per_m: f64,
}

/// Everything `kinrepro stiffness` reports.
#[derive(Debug, Clone, Serialize)]
pub struct StiffnessReport {
    pub scene: String,
    pub name: String,
    pub mu_static: Vec<f64>,
    pub points: Vec<StiffnessPoint>,
    pub contacts: Vec<SpringReport>,
}

fn rows(m: &nalgebra::Matrix6<f64>) -> [[f64; 6]; 6] {
    std::array::from_fn(|r| std::array::from_fn(|c| m[(r, c)]))
}

impl StiffnessReport {
    /// `points`: (name, body point); the matrix is taken at the seated
    /// position. `scene` names the scene.
    pub fn new(
        scene: &Scene,
        mu: &[f64],
        seating: &Seating,
        k: &CouplingStiffness,
        points: &[(String, Vector3<f64>)],
    ) -> Result<Self, ReportError> {
        let pts = points
            .iter()
            .map(|(name, p)| {
                let q = seating.pose().apply(p);
                let m = k.matrix_at(&q);
                let c = k.compliance_at(&q).ok_or(ReportError::NotPositiveDefinite)?;
                let pr = k.principal_at(&q).ok_or(ReportError::NotPositiveDefinite)?;
                let conv = |v: &[(f64, Vector3<f64>); 3]| {
                    v.iter()
                        .map(|(s, d)| PrincipalReport { stiffness: *s, direction: [d.x, d.y, d.z] })
                        .collect()
                };
                Ok(StiffnessPoint {
                    name: name.clone(),
                    position_m: [p.x, p.y, p.z],
                    matrix: rows(&m),
                    compliance: rows(&c),
                    translational: conv(&pr.translational),
                    rotational: conv(&pr.rotational),
                })
            })
            .collect::<Result<Vec<_>, ReportError>>()?;
        Ok(StiffnessReport {
            scene: scene.file.clone(),
            name: scene.name.clone(),
            mu_static: mu.to_vec(),
            points: pts,
            contacts: k
                .springs
                .iter()
                .map(|s| SpringReport {
                    normal_force_n: s.normal_force,
                    normal_stiffness_n_per_m: s.normal_stiffness,
                    tangential_stiffness_n_per_m: s.tangential_stiffness,
                })
                .collect(),
        })
    }

    pub fn table(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "{}  ({})", self.scene, self.name);
        let mu: Vec<String> = self.mu_static.iter().map(|m| format!("{m:.4}")).collect();
        let _ = writeln!(
            s,
            "stiffness of the seated coupling at rest (sticking contacts, Mindlin k_t; frictionless: normal only); mu_s = [{}]",
            mu.join(", ")
        );
        let _ = writeln!(s);
        let mut t = Table::new(">#; >F_n [N]:.5; >k_n [N/um]:.4; >k_t [N/um]:.4");
        for (i, c) in self.contacts.iter().enumerate() {
            t.row(cells![
                i + 1,
                c.normal_force_n,
                c.normal_stiffness_n_per_m * 1e-6,
                c.tangential_stiffness_n_per_m * 1e-6,
            ]);
        }
        s += &t.text();
        for p in &self.points {
            let _ = writeln!(s);
            let [x, y, z] = p.position_m;
            let _ = writeln!(s, "point {} at ({x:.4}, {y:.4}, {z:.4}) m", p.name);
            let _ = writeln!(s, "  stiffness matrix (u [m], phi [rad]) -> (F [N], M [N m]), SI:");
            for (i, row) in p.matrix.iter().enumerate() {
                let cells: Vec<String> = (row.iter().enumerate())
                    .map(|(j, &v)| format!("{:>12.4e}", rounding_zero(&p.matrix, i, j, v)))
                    .collect();
                let _ = writeln!(s, "   {}", cells.join(" "));
            }
            for (title, rows, unit) in [
                (
                    "principal translational stiffness (pure force at the point, rotation free):",
                    &p.translational,
                    "N/um      along",
                ),
                (
                    "principal rotational stiffness (pure moment, translation free):",
                    &p.rotational,
                    "N m/urad  about",
                ),
            ] {
                let _ = writeln!(s, "  {title}");
                for r in rows {
                    // A component below 1e-9 of the unit direction is rounding: 0.
                    let [x, y, z] = r.direction.map(|c| if c.abs() < 1e-9 { 0.0 } else { c });
                    let k = r.stiffness * 1e-6;
                    let _ = writeln!(s, "    {k:>12.4} {unit} ({x:>7.4}, {y:>7.4}, {z:>7.4})");
                }
            }
        }
        s
    }
}

/// An off-diagonal entry K_ij below 1e-9 sqrt(|K_ii K_jj|) is the
/// rounding of terms that cancel (a symmetric coupling's couplings between
/// DOFs): the table prints 0 for it, so that it does not change with the
/// order of floating-point operations; the JSON keeps the computed value.
fn rounding_zero(m: &[[f64; 6]; 6], i: usize, j: usize, v: f64) -> f64 {
    if i != j && v.abs() < 1e-9 * (m[i][i] * m[j][j]).abs().sqrt() { 0.0 } else { v }
}

/// The deflection of one point under the load.
#[derive(Debug, Clone, Serialize)]
pub struct DeflectionReport {
    pub name: String,
    pub position_m: [f64; 3],
    /// Relative to the seated pose.
    pub deflection: PointPose,
}

/// The envelope as reported.
#[derive(Debug, Clone, Serialize)]
pub struct EnvelopeReport {
    /// The first event: contact, kind and bracket of factors; null if none
    /// up to `searched_to`.
    pub event: Option<LoadEvent>,
    /// The critical load factor (middle of the bracket).
    pub factor: Option<f64>,
    pub searched_to: f64,
}

/// Everything `kinrepro load` reports.
#[derive(Debug, Clone, Serialize)]
pub struct LoadReport {
    pub scene: String,
    pub name: String,
    pub mu_static: Vec<f64>,
    pub force_n: [f64; 3],
    pub point_m: [f64; 3],
    pub moment_n_m: [f64; 3],
    /// Load factor reached (1 unless the load separates the coupling first).
    pub factor_reached: f64,
    /// Why the path ended early, if it did.
    pub stopped: Option<String>,
    pub points: Vec<DeflectionReport>,
    pub contacts: Vec<ContactResult>,
    pub seated_contacts: Vec<ContactResult>,
    /// Per contact: lifted off at the end of the path (no normal force, or
    /// below [`LIFT_OFF_RATIO`] of the seated one on a path that ended at a
    /// lift-off); its `state` and friction ratios then mean nothing.
    pub lifted_off: Vec<bool>,
    pub envelope: EnvelopeReport,
}

/// Per contact, whether it lifted off along `path` (see
/// [`LoadReport::lifted_off`]). A path that ended short without an error
/// ended at a lift-off.
fn lifted_off(path: &LoadPath, seating: &Seating) -> Vec<bool> {
    let lifted_path = path.factor < 1.0 && path.stopped.is_none();
    path.contacts
        .iter()
        .zip(&seating.contacts)
        .map(|(c, c0)| {
            c.normal_force_n <= 0.0
                || (lifted_path && c.normal_force_n < LIFT_OFF_RATIO * c0.normal_force_n)
        })
        .collect()
}

impl LoadReport {
    pub fn new(
        scene: &Scene,
        mu: &[f64],
        seating: &Seating,
        load: &ExternalLoad,
        path: &LoadPath,
        envelope: &Envelope,
        points: &[(String, Vector3<f64>)],
    ) -> Self {
        let v = |x: &Vector3<f64>| [x.x, x.y, x.z];
        LoadReport {
            scene: scene.file.clone(),
            name: scene.name.clone(),
            mu_static: mu.to_vec(),
            force_n: v(&load.force),
            point_m: v(&load.point),
            moment_n_m: v(&load.moment),
            factor_reached: path.factor,
            stopped: path.stopped.as_ref().map(|e| e.to_string()),
            points: points
                .iter()
                .map(|(name, p)| DeflectionReport {
                    name: name.clone(),
                    position_m: v(p),
                    deflection: PointPose::between(&seating.pose(), &path.pose, p),
                })
                .collect(),
            contacts: path.contacts.clone(),
            seated_contacts: seating.contacts.clone(),
            lifted_off: lifted_off(path, seating),
            envelope: EnvelopeReport {
                event: envelope.event,
                factor: envelope.factor(),
                searched_to: envelope.searched_to,
            },
        }
    }

    pub fn table(&self) -> String {
        let mut s = String::new();
        self.header(&mut s);
        let _ = writeln!(s);
        self.deflections(&mut s);
        let _ = writeln!(s);
        self.contact_rows(&mut s);
        let _ = writeln!(s);
        self.envelope_text(&mut s);
        s
    }

    /// Scene, load and friction; a warning if the load path stopped short.
    fn header(&self, s: &mut String) {
        let _ = writeln!(s, "{}  ({})", self.scene, self.name);
        let mu: Vec<String> = self.mu_static.iter().map(|m| format!("{m:.4}")).collect();
        let [f, p, m] = [self.force_n, self.point_m, self.moment_n_m]
            .map(|[x, y, z]| format!("({x}, {y}, {z})"));
        let _ = writeln!(
            s,
            "load after seating (preload held): F = {f} N at {p} m, M = {m} N m; mu_s = [{}]",
            mu.join(", ")
        );
        if self.factor_reached < 1.0 {
            let _ = writeln!(
                s,
                "WARNING: the load path ended at load factor {:.6}{}",
                self.factor_reached,
                self.stopped
                    .as_ref()
                    .map(|e| format!(": {e}"))
                    .unwrap_or_else(|| ": the coupling lifts off its seat".to_string())
            );
        }
    }

    /// The deflection of each point [nm, nrad].
    fn deflections(&self, s: &mut String) {
        let mut t = pose_table("<deflection");
        for q in &self.points {
            t.row(pose_cells(cells![&q.name], &q.deflection));
        }
        *s += &t.text();
    }

    /// Each contact before and after the load.
    fn contact_rows(&self, s: &mut String) {
        let mut t = Table::new(
            ">#; >F_n0 [N]:.6; >F_n [N]:.6; >|F_t| [N]:.6; >|F_t|/F_n:.6; >|F_t|/mu_sF_n:.4; >state",
        );
        let lifted = self.lifted_off.iter().filter(|&&off| off).count();
        let rows = self.contacts.iter().zip(&self.seated_contacts);
        for (i, ((c, c0), &off)) in rows.zip(&self.lifted_off).enumerate() {
            let ratio = (!off).then(|| c.tangential_force_n / c.normal_force_n);
            let used = (c.mu_static > 0.0 && !off)
                .then(|| c.tangential_force_n / (c.mu_static * c.normal_force_n));
            t.row(cells![
                i + 1,
                c0.normal_force_n,
                c.normal_force_n,
                c.tangential_force_n,
                ratio,
                used,
                if off { "lift-off" } else { c.state.name() },
            ]);
        }
        if lifted > 0 {
            t.note(format!(
                "WARNING: {lifted} contact(s) lifted off (normal force below {} % of the seated one): their friction ratios are not defined (-)",
                100.0 * LIFT_OFF_RATIO
            ));
        }
        *s += &t.text();
    }

    /// The safe load envelope and where the given load lies in it.
    fn envelope_text(&self, s: &mut String) {
        match (&self.envelope.event, self.envelope.factor) {
            (Some(e), Some(f)) => {
                let [fl, ml] = [self.force_n, self.moment_n_m]
                    .map(|v| v.map(|c| f * c))
                    .map(|[x, y, z]| format!("({x:.5}, {y:.5}, {z:.5})"));
                let _ = writeln!(
                    s,
                    "safe load envelope: contact {} {} at load factor {f:.5} (bracket [{:.6}, {:.6}]) = F {fl} N, M {ml} N m",
                    e.contact,
                    e.kind.name(),
                    e.previous,
                    e.factor,
                );
                let _ = writeln!(
                    s,
                    "  {}",
                    if f > 1.0 {
                        format!("the given load is inside it (margin {f:.3}x)")
                    } else {
                        "WARNING: the given load is outside it: the coupling loses or changes its seat".to_string()
                    }
                );
            }
            _ => {
                let _ = writeln!(
                    s,
                    "safe load envelope: no contact separates or slips up to load factor {:.4e}",
                    self.envelope.searched_to
                );
            }
        }
    }
}
