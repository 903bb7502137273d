//! The friction limit for seating (centring ability, after Hale 1999,
//! "Friction-based design of kinematic couplings", and Patti & Vogels 2019):
//! the coupling cannot centre if, with one contact i still open, the other
//! five can balance the preload with forces inside their friction cones
//! |F_t| <= mu F_n: the half then sticks off its seat. For each i the least
//! such mu is found by bisection on a linear feasibility problem, the cone
//! replaced by its inscribed pyramid of K = 64 facets; the limit is the
//! least over i. Below it the preload always drives the last contact
//! closed.
//!
//! The feasibility problem of contact i open at friction mu, in the
//! pyramid's generator form (microlp): multipliers lambda_jk >= 0 on the
//! generators g_jk = n_j + mu (e1_j cos phi_k + e2_j sin phi_k),
//! phi_k = 2 pi k / K, of every other contact j, with
//! ```text
//! sum_jk lambda_jk g_jk          = -F / |F|
//! sum_jk lambda_jk r_j x g_jk    = -M / (|F| L)
//! ```
//! (r_j the contact point's arm from the centroid of the balls over L, F
//! and M the preload's force and moment there). A test solves the same
//! pyramid in its facet form as the second solver: the normal force
//! N_j >= 0 and the tangential force (a_j, b_j) in (e1_j, e2_j), with
//! cos(psi_k) a_j + sin(psi_k) b_j <= mu cos(pi/K) N_j,
//! psi_k = 2 pi (k + 1/2) / K (facet k of the regular K-gon of
//! circumradius mu N_j lies at distance mu N_j cos(pi/K) along psi_k).

use std::collections::HashMap;
use std::sync::{LazyLock, Mutex};

use microlp::{ComparisonOp, OptimizationDirection, Problem, Variable};
use nalgebra::Vector3;

use super::Coupling;
use super::constraint::{preload_wrench, reference};
use crate::scene::Preload;

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

/// The friction limit for seating of `coupling` under `preload` (module
/// docs), kept for the next call with the same programs ([`SOLVED`]).
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
fn program(coupling: &Coupling, preload: &Preload) -> Program {
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

/// One contact of a friction-limit program: its normal and its point's arm
/// (p - o) / L.
type Cone = (Vector3<f64>, Vector3<f64>);

/// The contacts of a friction-limit program.
type Cones = [Cone];

/// A friction-limit program: the contacts and the unit preload wrench
/// (force, moment / L), negated.
type Program = (Vec<Cone>, [Vector3<f64>; 2]);

/// [`friction_limit`] of the contacts `cones` under the unit preload wrench
/// `target`: the bisection per open contact on [`feasible`].
fn solve_limit(cones: &Cones, target: &[Vector3<f64>; 2]) -> FrictionLimit {
    bisect(cones.len(), |open, mu| feasible(cones, target, open, mu))
}

/// The least over open contacts of the least mu at which `feasible(open,
/// mu)`, by bisection to [`MU_RESOLUTION`] in (0, [`MU_SEARCH_MAX`]]: a
/// contact is searched only below the least limit found so far.
fn bisect(contacts: usize, feasible: impl Fn(usize, f64) -> bool) -> FrictionLimit {
    let mut best = (f64::INFINITY, 1);
    for open in 0..contacts {
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

/// A unit tangent basis (e1, e2) of the plane normal to `n`.
fn tangent_basis(n: &Vector3<f64>) -> (Vector3<f64>, Vector3<f64>) {
    let e1 = n.cross(&if n.x.abs() < 0.9 { Vector3::x() } else { Vector3::y() }).normalize();
    (e1, n.cross(&e1))
}

/// Whether the contacts `cones` other than `open` can balance `target` with
/// forces in their pyramids of friction `mu`, in the generator form
/// (module docs): lambda_jk >= 0 on n_j + mu (e1_j cos phi_k + e2_j sin
/// phi_k). A pure feasibility problem (no objective): any point will do,
/// and the dual simplex stops at the first (an objective, such as the
/// least total normal force, took 2.5 times the work for the same answer).
fn feasible(cones: &Cones, target: &[Vector3<f64>; 2], open: usize, mu: f64) -> bool {
    let mut lp = Problem::new(OptimizationDirection::Minimize);
    let mut rows: [Vec<(Variable, f64)>; 6] = Default::default();
    for (j, (n, arm)) in cones.iter().enumerate() {
        if j == open {
            continue;
        }
        let (e1, e2) = tangent_basis(n);
        for k in 0..CONE_FACETS {
            let phi = 2.0 * std::f64::consts::PI * k as f64 / CONE_FACETS as f64;
            let generator = n + (e1 * phi.cos() + e2 * phi.sin()) * mu;
            let mom = arm.cross(&generator);
            let var = lp.add_var(0.0, (0.0, f64::INFINITY));
            for r in 0..3 {
                rows[r].push((var, generator[r]));
                rows[3 + r].push((var, mom[r]));
            }
        }
    }
    equilibrium(lp, &rows, target)
}

/// `lp` with the six equilibrium rows `rows` = `target`: feasible?
fn equilibrium(
    mut lp: Problem,
    rows: &[Vec<(Variable, f64)>; 6],
    target: &[Vector3<f64>; 2],
) -> bool {
    let [f, m] = target;
    let rhs = [f.x, f.y, f.z, m.x, m.y, m.z];
    for (r, row) in rows.iter().enumerate() {
        lp.add_constraint(row.as_slice(), ComparisonOp::Eq, rhs[r]);
    }
    lp.solve().is_ok()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The pyramid's facet form (module docs), the second solver: the
    /// tangential force (a_j, b_j) inside the K-gon of circumradius mu N_j.
    fn feasible_by_facets(cones: &Cones, target: &[Vector3<f64>; 2], open: usize, mu: f64) -> bool {
        let mut lp = Problem::new(OptimizationDirection::Minimize);
        let mut rows: [Vec<(Variable, f64)>; 6] = Default::default();
        let reach = mu * (std::f64::consts::PI / CONE_FACETS as f64).cos();
        let facets: Vec<(f64, f64)> = (0..CONE_FACETS)
            .map(|k| (2.0 * std::f64::consts::PI * (k as f64 + 0.5) / CONE_FACETS as f64).sin_cos())
            .collect();
        for (j, (n, arm)) in cones.iter().enumerate() {
            if j == open {
                continue;
            }
            let (e1, e2) = tangent_basis(n);
            let normal = lp.add_var(1.0, (0.0, f64::INFINITY));
            let a = lp.add_var(0.0, (f64::NEG_INFINITY, f64::INFINITY));
            let b = lp.add_var(0.0, (f64::NEG_INFINITY, f64::INFINITY));
            for (var, direction) in [(normal, n), (a, &e1), (b, &e2)] {
                let mom = arm.cross(direction);
                for r in 0..3 {
                    rows[r].push((var, direction[r]));
                    rows[3 + r].push((var, mom[r]));
                }
            }
            for &(sin, cos) in &facets {
                lp.add_constraint([(a, cos), (b, sin), (normal, -reach)], ComparisonOp::Le, 0.0);
            }
        }
        equilibrium(lp, &rows, target)
    }

    /// Six ball contacts on three balls at 120 degrees (two per ball, a
    /// groove of half-angle `half` turned by `twist` from radial), preloaded
    /// along -z through a point `offset` off the axis: the programs of
    /// Maxwell-like couplings, symmetric and not.
    fn maxwell(half: f64, twist: f64, offset: [f64; 2]) -> Program {
        let mut cones = Vec::new();
        for b in 0..3 {
            let at = 2.0 * std::f64::consts::PI * b as f64 / 3.0;
            let centre = Vector3::new(at.cos(), at.sin(), 0.0);
            let across = Vector3::new(-(at + twist).sin(), (at + twist).cos(), 0.0);
            for side in [-1.0, 1.0] {
                let n = (Vector3::z() * half.cos() + across * (side * half.sin())).normalize();
                cones.push((n, centre - n * 0.06));
            }
        }
        let force = -Vector3::z();
        let point = Vector3::new(offset[0], offset[1], 0.3);
        (cones, [-force, -point.cross(&force)])
    }

    /// The facet form and the generator form describe one polyhedron: the
    /// two limits bracket the same least mu from above within the
    /// bisection's resolution, on symmetric and skewed couplings and
    /// off-axis preloads, and name the same critical contact where no other
    /// contact ties with it (the symmetric coupling's six contacts do, by
    /// its symmetry: their limits differ only in rounding).
    #[test]
    fn facet_form_and_generator_form_give_the_same_limit() {
        let cases = [
            (45f64.to_radians(), 0.0, [0.0, 0.0], false),
            (30f64.to_radians(), 0.0, [0.0, 0.0], false),
            (60f64.to_radians(), 0.2, [0.1, -0.05], true),
            (45f64.to_radians(), -0.35, [-0.2, 0.15], true),
            (20f64.to_radians(), 0.1, [0.3, 0.0], true),
        ];
        for (half, twist, offset, skewed) in cases {
            let (cones, target) = maxwell(half, twist, offset);
            let generators = solve_limit(&cones, &target);
            let facets =
                bisect(cones.len(), |open, mu| feasible_by_facets(&cones, &target, open, mu));
            let case = format!("half {half} twist {twist} offset {offset:?}");
            assert!(generators.mu_limit.is_finite() && generators.mu_limit > 0.01, "{case}");
            assert!(
                (facets.mu_limit - generators.mu_limit).abs() <= MU_RESOLUTION,
                "{case}: {facets:?} vs {generators:?}"
            );
            if skewed {
                assert_eq!(facets.critical_contact, generators.critical_contact, "{case}");
            }
        }
    }
}
