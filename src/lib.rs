//! kinrepro: friction-induced re-seating scatter of kinematic couplings.
//!
//! Data flows one way (docs/architecture.md):
//! scene file -> [`scene`] -> [`assembly`] -> [`solve`] -> [`study`] -> [`report`].
//! The compliant contact laws ([`contact`]) and the materials ([`material`])
//! sit under everything; [`analysis`] and [`fe`] are side branches above
//! `solve`; the CLI (`src/bin/kinrepro`) holds no physics.

pub mod analysis;
pub mod assembly;
pub mod calibrate;
pub mod cancel;
pub mod contact;
pub mod delimited;
pub mod dof;
pub mod error;
pub mod explore;
pub mod fe;
pub mod input;
pub mod lane;
pub mod material;
pub mod output;
pub mod param;
pub mod report;
pub mod scene;
pub mod solve;
pub mod study;

pub use contact::{ContactLaw, ContactPair, ContactShape};
pub use material::Material;
