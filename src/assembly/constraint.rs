//! Kinematic design check: the constraint matrix of the six contacts, exact
//! constraint, the frictionless preload distribution, and the friction limit
//! for seating.
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

use std::collections::HashMap;
use std::sync::{LazyLock, Mutex};

use microlp::{ComparisonOp, OptimizationDirection, Problem};
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

fn reference(coupling: &Coupling) -> (Vector3<f64>, f64) {
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
fn preload_wrench(
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

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FrictionLimit {
    /// Largest mu at which no contact can stay open while the others hold
    /// the preload in their friction cones; infinite if none can at mu = 10.
    pub mu_limit: f64,
    /// The contact whose opening needs the least friction (1-based).
    pub critical_contact: usize,
    /// Relative error bound of the polyhedral friction cone: the true limit
    /// lies in [mu_limit cos(pi/K), mu_limit].
    pub cone_error_bound: f64,
}

/// Number of facets of the inscribed friction pyramid.
const CONE_FACETS: usize = 64;
/// Search range and resolution of the limit.
const MU_SEARCH_MAX: f64 = 10.0;
const MU_RESOLUTION: f64 = 1e-4;

/// The friction limit for seating (centring ability, after Hale 1999,
/// "Friction-based design of kinematic couplings", and Patti & Vogels 2019):
/// the coupling cannot centre if, with one contact i still open, the other
/// five can balance the preload with forces inside their friction cones
/// |F_t| <= mu F_n — the half then sticks off its seat. For each i the least
/// such mu is found by bisection on a linear feasibility problem (friction
/// cone replaced by an inscribed pyramid of K facets, microlp); the limit is
/// the least over i. Below it the preload always drives the last contact
/// closed.
pub fn friction_limit(coupling: &Coupling, preload: &Preload) -> FrictionLimit {
    let (cones, target) = program(coupling, preload);
    let key: Vec<u64> = (cones.iter().flat_map(|(n, a)| [n, a]))
        .chain(&target)
        .flat_map(|v| v.iter().map(|x| x.to_bits()))
        .collect();
    let solved = || SOLVED.lock().unwrap_or_else(|poisoned| poisoned.into_inner());
    if let Some(limit) = solved().get(&key) {
        return *limit;
    }
    let limit = solve_limit(&cones, &target);
    let mut memo = solved();
    if memo.len() >= SOLVED_MAX {
        memo.clear();
    }
    memo.insert(key, limit);
    limit
}

/// [`friction_limit`] solved anew, without the memo of solved limits.
pub fn friction_limit_solved_anew(coupling: &Coupling, preload: &Preload) -> FrictionLimit {
    let (cones, target) = program(coupling, preload);
    solve_limit(&cones, &target)
}

/// The inputs of the friction limit's programs: each contact's normal and
/// its point's arm (p - o) / L in the touching pose, and the preload's
/// wrench per unit of its scale (force, moment / L; a single force: its
/// direction), negated.
#[allow(clippy::type_complexity)]
fn program(
    coupling: &Coupling,
    preload: &Preload,
) -> (Vec<(Vector3<f64>, Vector3<f64>)>, [Vector3<f64>; 2]) {
    let (o, l) = reference(coupling);
    let pose = coupling.touching_pose;
    let cones = (0..coupling.contacts.len())
        .map(|i| coupling.geometry(i, &pose))
        .map(|g| (g.normal, (g.point - o) / l))
        .collect();
    let (target_f, target_m) = preload_wrench(preload, &pose, Some(o));
    (cones, [-target_f, -target_m / l])
}

/// Limits already solved, by the bits of their programs' inputs (the
/// contact normals and arms, the preload's direction): the limit depends on
/// the geometry and the preload's direction only, so a sweep over any
/// other field (preload force, materials, friction, samples) solves each
/// geometry once. Equal bits give the same programs and so the same
/// result; a different rounding of the same geometry is solved anew.
static SOLVED: LazyLock<Mutex<HashMap<Vec<u64>, FrictionLimit>>> =
    LazyLock::new(|| Mutex::new(HashMap::new()));

/// Limits kept at most (then the memo starts again).
const SOLVED_MAX: usize = 4096;

/// [`friction_limit`] of the contacts `cones` (normal, arm) under the unit
/// preload wrench `target` (force, moment / L): the bisection per open
/// contact.
fn solve_limit(
    cones: &[(Vector3<f64>, Vector3<f64>)],
    target: &[Vector3<f64>; 2],
) -> FrictionLimit {
    let m = cones.len();
    let [target_f, target_m] = *target;
    let feasible = |open: usize, mu: f64| -> bool {
        let mut lp = Problem::new(OptimizationDirection::Minimize);
        let mut rows: [Vec<(microlp::Variable, f64)>; 6] = Default::default();
        for (j, (n, arm)) in cones.iter().enumerate() {
            if j == open {
                continue;
            }
            let e1 =
                n.cross(&if n.x.abs() < 0.9 { Vector3::x() } else { Vector3::y() }).normalize();
            let e2 = n.cross(&e1);
            for k in 0..CONE_FACETS {
                let phi = 2.0 * std::f64::consts::PI * k as f64 / CONE_FACETS as f64;
                let generator = n + (e1 * phi.cos() + e2 * phi.sin()) * mu;
                let mom = arm.cross(&generator);
                let var = lp.add_var(1.0, (0.0, f64::INFINITY));
                for r in 0..3 {
                    rows[r].push((var, generator[r]));
                    rows[3 + r].push((var, mom[r]));
                }
            }
        }
        let rhs = [target_f.x, target_f.y, target_f.z, target_m.x, target_m.y, target_m.z];
        for (r, row) in rows.iter().enumerate() {
            lp.add_constraint(row.as_slice(), ComparisonOp::Eq, rhs[r]);
        }
        lp.solve().is_ok()
    };
    let mut best = (f64::INFINITY, 1);
    for open in 0..m {
        if !feasible(open, MU_SEARCH_MAX.min(best.0)) {
            continue;
        }
        let (mut lo, mut hi) = (0.0, MU_SEARCH_MAX.min(best.0));
        while hi - lo > MU_RESOLUTION {
            let mid = 0.5 * (lo + hi);
            if feasible(open, mid) { hi = mid } else { lo = mid }
        }
        if hi < best.0 {
            best = (hi, open + 1);
        }
    }
    FrictionLimit {
        mu_limit: best.0,
        critical_contact: best.1,
        cone_error_bound: 1.0 - (std::f64::consts::PI / CONE_FACETS as f64).cos(),
    }
}
