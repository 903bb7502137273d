//! The stiffness of the seated coupling.
//!
//! Physics decision: after seating stops the contacts are at rest, so static
//! friction governs again. Under small additional loads every contact with
//! mu_s > 0 sticks (Mindlin k_t at its final normal force; it slips only
//! when |F_t| reaches mu_s F_n, see [`super::load`]), and a frictionless
//! contact carries no tangential load. Each contact is then a spring of
//! stiffness
//!
//! ```text
//! K_i = k_n n n^T + k_t (I - n n^T),   k_n = 3/2 K delta^(1/2),  k_t = 8 G* sqrt(a b)  (0 if mu_s = 0)
//! ```
//!
//! at its contact point p_i, and the coupling's 6x6 stiffness for a twist
//! (v, w) of the moving half about a point q is
//!
//! ```text
//! K_q = sum_i T_i^T K_i T_i,   T_i = [I, -[p_i - q]x]   (displacement of p_i = v + w x (p_i - q))
//! ```
//!
//! symmetric and, for an exactly constrained coupling with every contact
//! closed, positive definite. K_i is taken from the contact layer
//! ([`crate::solve::contact_layer::evaluate`]) at the seated pose with the
//! at-rest states and zero increment, which gives exactly these tangents.
//! Preload springs (`[[preload.forces]] stiffness`) act in parallel: each
//! adds k d d^T at its point like a contact. Left out: the geometric (load) stiffness of the preload and contact
//! forces moving with the body, of relative size F/(k_n R) ~ 1e-4 for the
//! bundled scenes (the finite-difference test through the nonlinear solver,
//! which contains it, agrees to better than 1 %).
//!
//! Compliance C_q = K_q^-1 maps a wrench (F, M) applied at q to the
//! deflection (u_q, phi). Principal stiffnesses reported at q:
//! - translational: the eigenvalues k_1 <= k_2 <= k_3 of the inverse of the
//!   translational compliance block C_q[0..3, 0..3], with their directions:
//!   the stiffness felt by a pure force at q, the rotation left free;
//! - rotational: likewise from the rotational block C_q[3..6, 3..6]: a pure
//!   moment, the translation left free.

use nalgebra::{Matrix3, Matrix6, SymmetricEigen, Vector3};

use crate::assembly::{BodyPose, Coupling};
use crate::solve::contact_layer::evaluate;
use crate::solve::preload_forces::applied;
use crate::solve::quasistatic::at_rest_states;
use crate::solve::{Load, Seating, SolveError};

/// One contact's spring at rest.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactSpring {
    pub point: Vector3<f64>,
    pub normal: Vector3<f64>,
    pub normal_force: f64,
    /// Normal stiffness k_n [N/m] (Hertz, in series with the support compliance).
    pub normal_stiffness: f64,
    /// Mindlin tangential stiffness k_t [N/m] in series with the tangential
    /// support compliance: sqrt(det) of the 2x2 in the tangent plane (the
    /// geometric mean of the principal values; 0 for a frictionless contact).
    pub tangential_stiffness: f64,
    /// d(force on the moving half)/d(displacement of the contact point) [N/m],
    /// i.e. -K_i.
    pub tangent: Matrix3<f64>,
}

#[derive(Debug, Clone, PartialEq)]
pub struct CouplingStiffness {
    pub pose: BodyPose,
    pub springs: Vec<ContactSpring>,
    /// The preload springs in parallel (`[[preload.forces]] stiffness`):
    /// each point and its tangent -k d d^T (empty without springs).
    pub preload_springs: Vec<(Vector3<f64>, Matrix3<f64>)>,
}

/// Principal stiffnesses at a point.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Principal {
    /// Ascending translational stiffnesses [N/m] and unit directions.
    pub translational: [(f64, Vector3<f64>); 3],
    /// Ascending rotational stiffnesses [N m/rad] and unit axes.
    pub rotational: [(f64, Vector3<f64>); 3],
}

impl CouplingStiffness {
    /// The at-rest contact springs of a seating made under `load` (the
    /// seating's own contact states), and the preload's springs.
    pub fn new(coupling: &Coupling, seating: &Seating, load: &Load) -> Result<Self, SolveError> {
        let friction = load.frictions(coupling)?;
        let states = at_rest_states(seating);
        let pose = seating.pose();
        let springs = (0..coupling.contacts.len())
            .map(|i| {
                let e = evaluate(coupling, i, &pose, &pose, &states[i], friction[i]);
                let n = e.geometry.normal;
                let nn = n * n.transpose();
                let contact = &coupling.contacts[i];
                let (tangent, kt) = if friction[i].mu_s > 0.0 {
                    let major = &contact.major_axis;
                    (
                        e.stiffness,
                        contact.law.oriented_tangential_stiffness(e.normal_force, &n, major),
                    )
                } else {
                    // Frictionless: the normal spring only.
                    (-e.normal_stiffness * nn, 0.0)
                };
                ContactSpring {
                    point: e.geometry.point,
                    normal: n,
                    normal_force: e.normal_force,
                    normal_stiffness: e.normal_stiffness,
                    tangential_stiffness: kt,
                    tangent,
                }
            })
            .collect();
        let preload_springs = applied(coupling, &load.preload, &pose, 1.0)
            .filter_map(|a| a.stiffness.map(|k| (a.point, k)))
            .collect();
        Ok(CouplingStiffness { pose, springs, preload_springs })
    }

    /// The 6x6 stiffness for a twist (v, w) about the world point `q`
    /// (v = displacement of q) and the restoring wrench (F, M about q),
    /// with the sign of a stiffness (positive definite): W = -K x.
    pub fn matrix_at(&self, q: &Vector3<f64>) -> Matrix6<f64> {
        let mut k = Matrix6::zeros();
        let contacts = self.springs.iter().map(|s| (s.point, s.tangent));
        for (point, tangent) in contacts.chain(self.preload_springs.iter().copied()) {
            let ki = -(tangent + tangent.transpose()) * 0.5;
            let mut t = nalgebra::Matrix3x6::zeros();
            t.fixed_view_mut::<3, 3>(0, 0).copy_from(&Matrix3::identity());
            t.fixed_view_mut::<3, 3>(0, 3).copy_from(&(-(point - q).cross_matrix()));
            k += t.transpose() * ki * t;
        }
        (k + k.transpose()) * 0.5
    }

    /// Compliance at `q`: the deflection (u_q, phi) per wrench (F, M about q).
    pub fn compliance_at(&self, q: &Vector3<f64>) -> Option<Matrix6<f64>> {
        let c = self.matrix_at(q).cholesky()?.inverse();
        Some((c + c.transpose()) * 0.5)
    }

    /// Principal stiffnesses at `q` (module doc).
    pub fn principal_at(&self, q: &Vector3<f64>) -> Option<Principal> {
        let c = self.compliance_at(q)?;
        let block = |r: usize| -> [(f64, Vector3<f64>); 3] {
            let b: Matrix3<f64> = c.fixed_view::<3, 3>(r, r).into();
            let eig = SymmetricEigen::new(b);
            let mut out: [(f64, Vector3<f64>); 3] = std::array::from_fn(|k| {
                let mut d: Vector3<f64> = eig.eigenvectors.column(k).into();
                // Sign convention: largest component positive.
                if d[d.iamax()] < 0.0 {
                    d = -d;
                }
                (1.0 / eig.eigenvalues[k], d)
            });
            out.sort_by(|a, b| a.0.total_cmp(&b.0));
            out
        };
        Some(Principal { translational: block(0), rotational: block(3) })
    }
}
