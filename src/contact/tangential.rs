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

use nalgebra::{Matrix3, Vector3};

pub use super::tangential_types::{
    Friction, Rotation, SlipState, TangentialInput, TangentialLaw, TangentialResponse,
    TangentialState, UnknownLaw,
};
use super::{coulomb, mindlin_deresiewicz};

impl TangentialState {
    /// Evaluate the chosen law for a trial increment. Pure: `self` is not changed.
    pub fn update(&self, law: TangentialLaw, input: &TangentialInput) -> TangentialResponse {
        let n = input.normal;
        if input.normal_force <= 0.0 {
            // No normal force, no friction; history is lost when a contact opens.
            return TangentialResponse {
                force: Vector3::zeros(),
                state: TangentialState::new(n),
                slip: SlipState::Stick,
                d_force_d_du: Matrix3::zeros(),
                d_force_d_fn: Vector3::zeros(),
            };
        }
        let old = self.rotated_to(&n);
        let proj = Matrix3::identity() - n * n.transpose();
        let du = proj * input.du;
        match law {
            TangentialLaw::Coulomb => coulomb::update(&old, &du, input),
            TangentialLaw::MindlinDeresiewicz => {
                mindlin_deresiewicz::update(&old, &proj, &du, input)
            }
        }
    }
}
