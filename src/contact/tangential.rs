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

pub use super::tangential_types::{
    Friction, Rotation, SlipState, TangentialInput, TangentialLaw, TangentialResponse,
    TangentialState, UnknownLaw,
};
use super::{coulomb, mindlin_deresiewicz};

impl TangentialState {
    /// The chosen law's response to a trial increment, written into `out`
    /// (the solvers' buffers: no response is built and then moved). Pure:
    /// `self`, the committed state, is not changed. With `tangent` false
    /// the consistent tangent (`d_force_d_du`, `d_force_d_fn`) is not
    /// formed and `out`'s are left as they were (a Newton iterate that
    /// converges never reads it); force, state and slip are formed by the
    /// same operations either way.
    pub fn update(
        &self,
        law: TangentialLaw,
        input: &TangentialInput,
        tangent: bool,
        out: &mut TangentialResponse,
    ) {
        if input.normal_force <= 0.0 {
            // No normal force, no friction; history is lost when a contact opens.
            *out = TangentialResponse::open(input.normal);
            return;
        }
        let old = self.rotated_to(&input.normal);
        match law {
            TangentialLaw::Coulomb => coulomb::update(&old, input, tangent, out),
            TangentialLaw::MindlinDeresiewicz => {
                mindlin_deresiewicz::update(&old, input, tangent, out)
            }
        }
    }
}
