//! The data of a load applied after seating: the external wrench
//! ([`ExternalLoad`]) and the contact events along its path
//! ([`LoadEvent`]). Plain types shared by the solver, the path walker and
//! `load` (which applies the load), so that none of them imports another
//! that imports it back.

use nalgebra::Vector3;
use serde::Serialize;

/// An extra load on the moving half after seating: a force of fixed
/// direction applied at a point of the moving half, and a moment.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ExternalLoad {
    /// Force [N] (world axes, direction fixed).
    pub force: Vector3<f64>,
    /// Point of application in the moving half, scene coordinates [m].
    pub point: Vector3<f64>,
    /// Moment [N m].
    pub moment: Vector3<f64>,
}

/// What ends the at-rest (sticking, closed) response of a contact.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum LoadEventKind {
    /// The normal force reaches 0: the contact opens.
    Separation,
    /// |F_t| reaches mu_s F_n: the contact starts to slip.
    Slip,
}

impl LoadEventKind {
    pub fn name(self) -> &'static str {
        match self {
            LoadEventKind::Separation => "separates",
            LoadEventKind::Slip => "starts to slip",
        }
    }
}

/// The first contact event along a load path.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct LoadEvent {
    /// Contact, 1-based.
    pub contact: usize,
    pub kind: LoadEventKind,
    /// The event happens between these load factors: `previous` is the last
    /// solved factor without it, `factor` the first with it (or the factor
    /// beyond which no equilibrium exists).
    pub previous: f64,
    pub factor: f64,
}

/// A contact whose normal force has fallen below this fraction of its
/// seated value when a load path cannot go on has lifted off (the
/// separating contact leaves the moving half without equilibrium).
pub const LIFT_OFF_RATIO: f64 = 0.05;
