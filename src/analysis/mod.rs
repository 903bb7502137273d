//! Design analysis of a seated coupling: its stiffness ([`stiffness`]) and
//! its response to external loads applied after seating, with the safe load
//! envelope ([`load`]). Both start from a quasi-static seating and the
//! at-rest contact states; the physics stays in the contact layer and the
//! solver.

pub mod load;
pub mod stiffness;
