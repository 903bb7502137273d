//! Kinematic design check: the constraint matrix of the six contacts, exact
//! constraint and the frictionless preload distribution (the friction limit
//! for seating, which builds on them: `super::friction_limit`).
//!
//! Constraint matrix (Plücker coordinates of the contact normals; Blanding,
//! *Exact Constraint*, 1999; Hale, *Principles and Techniques for Designing
//! Precision Machines*, 1999, §7): row i is w_i = [n_i, (c_i - o) x n_i / L]
//! with c_i the ball centre (every normal of a ball contact passes through
//! it), o the centroid of the ball centres and L their largest distance from
//! o, so that the matrix is dimensionless. A twist (v, w L) of the moving
//! half changes gap i by w_i . (v, w L). The coupling is exactly constrained
//! when there are six contacts and the matrix has rank 6; free motions span
//! its null space, redundant constraints the null space of its transpose.

use nalgebra::{DMatrix, Vector3, Vector6};

use super::{BodyPose, Coupling};
use crate::scene::Preload;

/// Rank threshold on the eigenvalues of A^T A and A A^T (the squared
/// singular values), relative to the largest: singular values below 1e-6 of
/// the largest count as zero (a condition number beyond 1e6 is no
/// constraint in practice, and it stays well above the eigen-solver's
/// rounding, ~1e-16 of the largest eigenvalue).
const EIGEN_RANK_TOL: f64 = 1e-12;

#[derive(Debug, Clone, PartialEq)]
pub struct ConstraintReport {
    pub contacts: usize,
    pub rank: usize,
    pub exactly_constrained: bool,
    /// Condition number of the dimensionless constraint matrix (infinite when singular).
    pub condition_number: f64,
    /// Free motions (null space), described in words.
    pub free_motions: Vec<String>,
    /// Number of redundant constraints: contacts - rank, the dimension of
    /// the self-stress states (null space of A^T).
    pub redundant_constraints: usize,
    /// The contacts (1-based) that take part in a self-stress state, i.e.
    /// fight the others when the preload presses them all.
    pub redundant_contacts: Vec<usize>,
}

impl ConstraintReport {
    /// One sentence on what is wrong (or right).
    pub fn describe(&self) -> String {
        if self.exactly_constrained {
            return format!(
                "exactly constrained (6 contacts, rank 6, condition number {:.3})",
                self.condition_number
            );
        }
        let mut parts = vec![format!("{} contacts, rank {}", self.contacts, self.rank)];
        if !self.free_motions.is_empty() {
            parts.push(format!("under-constrained, free: {}", self.free_motions.join("; ")));
        }
        if self.redundant_constraints > 0 {
            let k = self.redundant_constraints;
            parts.push(format!(
                "over-constrained, {k} redundant constraint{}: contacts {} fight each other",
                if k == 1 { "" } else { "s" },
                ranges(&self.redundant_contacts)
            ));
        }
        parts.join("; ")
    }
}

/// Sorted 1-based indices as a compact list: `1, 3-7, 9`.
fn ranges(v: &[usize]) -> String {
    let mut out: Vec<String> = Vec::new();
    let mut i = 0;
    while i < v.len() {
        let mut j = i;
        while j + 1 < v.len() && v[j + 1] == v[j] + 1 {
            j += 1;
        }
        out.push(if j > i { format!("{}-{}", v[i], v[j]) } else { v[i].to_string() });
        i = j + 1;
    }
    out.join(", ")
}

pub(super) fn reference(coupling: &Coupling) -> (Vector3<f64>, f64) {
    let n = coupling.balls.len() as f64;
    let o = coupling.balls.iter().map(|b| b.centre).sum::<Vector3<f64>>() / n;
    let l = coupling
        .balls
        .iter()
        .map(|b| (b.centre - o).norm())
        .fold(0.0, f64::max)
        .max(coupling.balls.iter().map(|b| b.radius).fold(0.0, f64::max));
    (o, l)
}

/// Dimensionless constraint matrix (contacts x 6) at the scene pose.
pub fn constraint_matrix(coupling: &Coupling) -> DMatrix<f64> {
    let (o, l) = reference(coupling);
    let pose = BodyPose::identity();
    let m = coupling.contacts.len();
    let mut a = DMatrix::zeros(m, 6);
    for i in 0..m {
        let g = coupling.geometry(i, &pose);
        let n = g.normal;
        let mom = (g.point - o).cross(&n) / l;
        for k in 0..3 {
            a[(i, k)] = n[k];
            a[(i, 3 + k)] = mom[k];
        }
    }
    a
}

/// Leverage below which a contact counts as taking part in a self-stress.
const LEVERAGE_TOL: f64 = 1e-6;

/// Analyse the constraint matrix A (m x 6), in time linear in m: only the
/// 6 x 6 matrix A^T A is decomposed.
///
/// Free motions: eigenvectors of A^T A with (relatively) zero eigenvalue.
/// Redundancy: the self-stress states y (A^T y = 0) span a space of
/// dimension m - rank. Contact i takes part in one iff e_i is not in the
/// column space of A, i.e. iff its leverage h_i = a_i^T (A^T A)^+ a_i (the
/// diagonal of the projector A (A^T A)^+ A^T onto that space) is below 1
/// (Hoaglin & Welsch, Am. Stat. 32 (1978) 17): its row lies in the span of
/// the other rows, so removing it leaves the rank unchanged.
pub fn analyse(coupling: &Coupling) -> ConstraintReport {
    let a = constraint_matrix(coupling);
    let m = a.nrows();
    let (o, l) = reference(coupling);
    let eig = (a.transpose() * &a).symmetric_eigen();
    let lmax = eig.eigenvalues.max().max(f64::MIN_POSITIVE);
    let mut free_motions = Vec::new();
    let mut kept = Vec::new();
    for k in 0..6 {
        if eig.eigenvalues[k] > EIGEN_RANK_TOL * lmax {
            kept.push(k);
        } else {
            let v = eig.eigenvectors.column(k);
            free_motions.push(describe_twist(
                &Vector3::new(v[0], v[1], v[2]),
                &Vector3::new(v[3], v[4], v[5]),
                &o,
                l,
            ));
        }
    }
    let rank = kept.len();
    let redundant_contacts: Vec<usize> = if m > rank {
        (0..m)
            .filter(|&i| {
                let h: f64 = kept
                    .iter()
                    .map(|&k| {
                        let d = a.row(i).dot(&eig.eigenvectors.column(k).transpose());
                        d * d / eig.eigenvalues[k]
                    })
                    .sum();
                h < 1.0 - LEVERAGE_TOL
            })
            .map(|i| i + 1)
            .collect()
    } else {
        Vec::new()
    };
    let exactly = m == 6 && rank == 6;
    let lmin = eig.eigenvalues.min();
    ConstraintReport {
        contacts: m,
        rank,
        exactly_constrained: exactly,
        condition_number: if rank == 6 { (lmax / lmin).sqrt() } else { f64::INFINITY },
        free_motions,
        redundant_constraints: m - rank,
        redundant_contacts,
    }
}

/// Describe a dimensionless twist (v, w L) about the centroid `o` in words.
fn describe_twist(v: &Vector3<f64>, wl: &Vector3<f64>, o: &Vector3<f64>, l: f64) -> String {
    let fmt = |x: &Vector3<f64>| format!("({:.3}, {:.3}, {:.3})", x.x, x.y, x.z);
    if wl.norm() < 1e-6 {
        return format!("translation along {}", fmt(&v.normalize()));
    }
    let w = wl / l;
    let axis = w.normalize();
    // The screw axis passes through o + w x v / |w|^2.
    let q = o + w.cross(v) / w.norm_squared();
    format!("rotation about the axis {} through {} m", fmt(&axis), fmt(&q))
}

/// Contact forces that balance `preload` with no friction: solve
/// sum_i f_i [n_i; c_i x n_i] = -[F; p x F] (a positive f_i presses).
pub fn frictionless_preload_forces(coupling: &Coupling, preload: &Preload) -> Vec<f64> {
    frictionless_forces(coupling, preload).as_slice().to_vec()
}

/// [`frictionless_preload_forces`] without allocating (zero where the
/// system is singular).
pub fn frictionless_forces(coupling: &Coupling, preload: &Preload) -> Vector6<f64> {
    let pose = coupling.touching_pose;
    let a = coupling.constraint_rows(&pose).transpose();
    let (f, mom) = preload_wrench(preload, &pose, None);
    let rhs = -Vector6::new(f.x, f.y, f.z, mom.x, mom.y, mom.z);
    a.lu().solve(&rhs).unwrap_or_else(Vector6::zeros)
}

/// The preload's full-load force and moment about the origin in the
/// touching pose `pose` (each spring gives its `force` there); with `unit`,
/// per unit of [`Preload::scale`] and about that point.
pub(super) fn preload_wrench(
    p: &Preload,
    pose: &BodyPose,
    unit: Option<Vector3<f64>>,
) -> (Vector3<f64>, Vector3<f64>) {
    let scale = p.scale();
    let (mut f, mut m) = (Vector3::zeros(), Vector3::zeros());
    for k in &p.forces {
        let point = pose.apply(&k.point);
        let fk = match unit {
            None => k.direction * k.force,
            Some(_) => k.direction * (k.force / scale),
        };
        f += fk;
        m += (point - unit.unwrap_or_else(Vector3::zeros)).cross(&fk);
    }
    (f, m)
}
