//! Natural frequencies of the seated coupling, which set the time step and
//! the time scales of the dynamic solver.
//!
//! At full preload with no friction each contact i carries the force f_i of
//! `constraint::frictionless_preload_forces`, so it has the Hertz normal
//! stiffness and the Mindlin tangential stiffness
//! ```text
//! k_n,i = dF/d delta = 3/2 K_i delta_i^(1/2),  delta_i = (f_i / K_i)^(2/3)   (Johnson 1985, eq. 4.23)
//! k_t,i = 8 G* sqrt(a b)                                                     (Mindlin 1949)
//! ```
//! (k_t counts as if every contact stuck, the stiffest case). With J_i the
//! map from the body twist (v, w) about the centre of mass to the velocity
//! of contact point p_i, J_i = [1, -[p_i - c]x], the stiffness matrix is
//! ```text
//! K = sum_i J_i^T (k_n,i n_i n_i^T + k_t,i (1 - n_i n_i^T)) J_i
//! ```
//! and the mass matrix M = diag(m 1, I_c). The squared natural circular
//! frequencies are the eigenvalues of L^-1 K L^-T, M = L L^T (Cholesky).

use nalgebra::{Matrix3, Matrix6};

use super::mass::MassModel;
use crate::assembly::Coupling;
use crate::assembly::constraint::frictionless_preload_forces;
use crate::scene::Preload;

/// Highest and lowest natural circular frequency at full preload [rad/s].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Frequencies {
    pub omega_max: f64,
    pub omega_min: f64,
}

impl Frequencies {
    /// Period of the highest mode, T = 2 pi / omega_max [s].
    pub fn shortest_period(&self) -> f64 {
        2.0 * std::f64::consts::PI / self.omega_max
    }

    /// Period of the lowest (fundamental) mode [s].
    pub fn longest_period(&self) -> f64 {
        2.0 * std::f64::consts::PI / self.omega_min
    }
}

/// The natural frequencies of `coupling` with mass model `mass` (module docs).
/// `None` if the preload leaves a contact unloaded or the matrices are singular.
pub fn seated_frequencies(
    coupling: &Coupling,
    preload: &Preload,
    mass: &MassModel,
) -> Option<Frequencies> {
    let pose = coupling.touching_pose;
    let com = pose.apply(&mass.centre_of_mass);
    let forces = frictionless_preload_forces(coupling, preload);
    let mut k = Matrix6::zeros();
    for (i, &f) in forces.iter().enumerate() {
        if f.is_nan() || f <= 0.0 {
            return None;
        }
        let law = &coupling.contacts[i].law;
        let normal = &coupling.contacts[i].normal;
        let (_, kn) = normal.force_and_stiffness(normal.approach(f));
        let (kt, _) = law.tangential_stiffness(f);
        let g = coupling.geometry(i, &pose);
        let n = g.normal;
        let s = n * n.transpose() * kn + (Matrix3::identity() - n * n.transpose()) * kt;
        let mut j = nalgebra::Matrix3x6::zeros();
        j.fixed_view_mut::<3, 3>(0, 0).copy_from(&Matrix3::identity());
        j.fixed_view_mut::<3, 3>(0, 3).copy_from(&(-(g.point - com).cross_matrix()));
        k += j.transpose() * s * j;
    }
    let r = pose.rotation.to_rotation_matrix().into_inner();
    let inertia_world = r * mass.inertia * r.transpose();
    let mut m = Matrix6::zeros();
    m.fixed_view_mut::<3, 3>(0, 0).copy_from(&(Matrix3::identity() * mass.mass));
    m.fixed_view_mut::<3, 3>(3, 3).copy_from(&inertia_world);
    let l = m.cholesky()?.l();
    let l_inv = l.try_inverse()?;
    let a = l_inv * k * l_inv.transpose();
    let a = (a + a.transpose()) * 0.5;
    let eig = a.symmetric_eigen().eigenvalues;
    let (lo, hi) = (eig.min(), eig.max());
    if !(lo > 0.0 && hi.is_finite()) {
        return None;
    }
    Some(Frequencies { omega_max: hi.sqrt(), omega_min: lo.sqrt() })
}
