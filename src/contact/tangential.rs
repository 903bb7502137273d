//! Tangential contact: the dispatcher between the tangential laws. Each law
//! is its own module over the shared types of [`super::tangential_types`]
//! (re-exported here): the Coulomb stick/slip law (`coulomb`, the paper's)
//! and Mindlin-Deresiewicz partial slip (`mindlin_deresiewicz`). A new law
//! gets its own file, a variant of [`TangentialLaw`] and one arm below.
//!
//! Sign convention: `du` is the tangential displacement of the moving body
//! relative to the fixed surface at the contact, and the law's force is the
//! tangential force along it that the moving body exerts on the fixed
//! surface (a spring stretched by du). The friction force on the moving
//! body is its negative.

use nalgebra::Matrix3;

use super::mindlin::PrincipalStiffness;
pub use super::tangential_types::{
    Friction, Rotation, SlipState, TangentialInput, TangentialLaw, TangentialResponse,
    TangentialState, UnknownLaw,
};
use super::{coulomb, mindlin_deresiewicz};

impl TangentialState {
    /// Evaluate the chosen law for a trial increment. Pure: `self` is not changed.
    pub fn update(&self, law: TangentialLaw, input: &TangentialInput) -> TangentialResponse {
        self.update_with(law, input, None)
    }

    /// [`Self::update`] with K_t (`input.stiffness`) also given by its
    /// principal values and axes: the Coulomb return mapping then projects
    /// without an eigen-decomposition, in closed form for a circular
    /// contact ([`PrincipalStiffness::project`], the same map).
    pub fn update_with(
        &self,
        law: TangentialLaw,
        input: &TangentialInput,
        principal: Option<&PrincipalStiffness>,
    ) -> TangentialResponse {
        let mut out = TangentialResponse::open(input.normal);
        self.update_into(law, input, principal, true, &mut out);
        out
    }

    /// [`Self::update_with`] written into `out` (the solvers' buffers: no
    /// response is built on the stack and moved). With `tangent` false the
    /// consistent tangent (`d_force_d_du`, `d_force_d_fn`) is not formed
    /// and `out`'s are left as they were (a Newton iterate that converges
    /// never reads it); force, state and slip are formed by the same
    /// operations either way, the same bits.
    pub fn update_into(
        &self,
        law: TangentialLaw,
        input: &TangentialInput,
        principal: Option<&PrincipalStiffness>,
        tangent: bool,
        out: &mut TangentialResponse,
    ) {
        let n = input.normal;
        if input.normal_force <= 0.0 {
            // No normal force, no friction; history is lost when a contact opens.
            *out = TangentialResponse::open(n);
            return;
        }
        let old = self.rotated_to(&n);
        match law {
            TangentialLaw::Coulomb => {
                let du = input.du - n * n.dot(&input.du);
                coulomb::update(&old, &du, input, principal, tangent, out);
            }
            TangentialLaw::MindlinDeresiewicz => {
                let proj = Matrix3::identity() - n * n.transpose();
                *out = mindlin_deresiewicz::update(&old, &proj, &(proj * input.du), input, tangent);
            }
        }
    }
}
