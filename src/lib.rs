//! kinrepro: friction-induced re-seating scatter of kinematic couplings.
//!
//! Data flows one way (see README.md, "Architecture"):
//! scene file -> [`scene`] -> coupling assembly -> solver -> pose -> study -> report.
//! The compliant contact laws ([`contact`]) and the materials ([`material`])
//! sit under everything; the CLI (`src/main.rs`) holds no physics.

pub mod analysis;
pub mod assembly;
pub mod calibrate;
pub mod contact;
pub mod error;
pub mod fe;
pub mod material;
pub mod report;
pub mod scene;
pub mod solve;
pub mod study;

pub use contact::{ContactLaw, ContactPair, ContactShape};
pub use material::Material;
