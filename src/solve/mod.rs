//! Seating solvers and their result types.
//!
//! The quasi-static path-following solver ([`quasistatic`]) ramps the
//! preload and solves the six pose unknowns by Newton at each increment; it
//! shares the compliant contact layer ([`contact_layer`]) with the dynamic
//! solver.

pub mod contact_layer;
pub mod quasistatic;

use nalgebra::Vector3;
use serde::Serialize;
use thiserror::Error;

use crate::assembly::{BodyPose, Coupling};
use crate::contact::{Friction, SlipState};
use crate::scene::resolve::MU_MAX;

/// Settings of the quasi-static solver.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SolverOptions {
    /// Nominal number of load increments (uniform in F^(2/3), i.e. in approach).
    pub increments: usize,
    /// How often an increment may be halved (stick/slip changes, Newton trouble).
    pub max_splits: u32,
    /// Newton iterations per increment.
    pub max_newton: usize,
    /// Force residual tolerance relative to the preload (moments: to preload x
    /// coupling radius).
    pub tolerance: f64,
}

impl Default for SolverOptions {
    fn default() -> Self {
        SolverOptions {
            increments: 20,
            max_splits: 8,
            max_newton: 40,
            tolerance: 1e-10,
        }
    }
}

/// A seating that did not end in a valid seated pose.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SolveError {
    #[error("--mu needs {expected} values (one per contact, in contact order), got {got}")]
    MuCount { expected: usize, got: usize },
    #[error("--mu value {index} = {value} is outside [0, {max}]")]
    MuRange { index: usize, value: f64, max: f64 },
    #[error(
        "the seating solve did not converge at {percent:.3} % of the preload (relative residual \
         {residual:.3e} after halving the increment {splits} times)"
    )]
    NotConverged {
        percent: f64,
        residual: f64,
        splits: u32,
    },
    #[error(
        "contact {contact} opened completely at {percent:.3} % of the preload: the preload lifts \
         the moving half off that contact instead of seating it"
    )]
    ContactOpened { contact: usize, percent: f64 },
    #[error(
        "the coupling slides away instead of seating: at {percent:.3} % of the preload the \
         moving half has moved {displacement_m:.3e} m"
    )]
    SlidAway { percent: f64, displacement_m: f64 },
}

/// Per-contact state at the end of a seating (SI units).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContactResult {
    pub normal_force_n: f64,
    /// Tangential (friction) force on the moving half [N].
    pub tangential_force: [f64; 3],
    pub tangential_force_n: f64,
    pub approach_m: f64,
    pub state: SlipState,
    /// Static and dynamic coefficient used.
    pub mu_static: f64,
    pub mu_dynamic: f64,
    pub max_pressure_pa: f64,
    /// Peak pressure / allowable pressure of the weaker material, where known.
    pub pressure_ratio: Option<f64>,
    pub point_m: [f64; 3],
    pub normal: [f64; 3],
}

/// The result of one seating.
#[derive(Debug, Clone, PartialEq)]
pub struct Seating {
    /// Final pose of the moving half.
    pub pose: BodyPose,
    pub contacts: Vec<ContactResult>,
    /// Accepted load increments and Newton iterations in all.
    pub increments: usize,
    pub newton_iterations: usize,
}

/// Pose of an evaluation point relative to a reference pose: translation of
/// the point and the rotation vector of R R_ref^-1 (finite rotation; phi_z
/// is reported but not evaluated for reproducibility).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct PointPose {
    pub x_m: f64,
    pub y_m: f64,
    pub z_m: f64,
    pub phi_x_rad: f64,
    pub phi_y_rad: f64,
    pub phi_z_rad: f64,
}

impl PointPose {
    /// Motion of body point `p` (scene coordinates) from pose `from` to pose `to`.
    pub fn between(from: &BodyPose, to: &BodyPose, p: &Vector3<f64>) -> Self {
        let d = to.apply(p) - from.apply(p);
        let phi = (to.rotation * from.rotation.inverse()).scaled_axis();
        PointPose {
            x_m: d.x,
            y_m: d.y,
            z_m: d.z,
            phi_x_rad: phi.x,
            phi_y_rad: phi.y,
            phi_z_rad: phi.z,
        }
    }

    /// The five evaluated components [x, y, z, phi_x, phi_y].
    pub fn evaluated(&self) -> [f64; 5] {
        [self.x_m, self.y_m, self.z_m, self.phi_x_rad, self.phi_y_rad]
    }
}

/// Static coefficients -> per-contact friction (mu_d = ratio mu_s), checked.
pub fn frictions(coupling: &Coupling, mu_s: &[f64]) -> Result<Vec<Friction>, SolveError> {
    if mu_s.len() != coupling.contacts.len() {
        return Err(SolveError::MuCount {
            expected: coupling.contacts.len(),
            got: mu_s.len(),
        });
    }
    let ratio = coupling.scene.friction.dynamic_ratio;
    mu_s.iter()
        .enumerate()
        .map(|(i, &m)| {
            if (0.0..=MU_MAX).contains(&m) {
                Ok(Friction {
                    mu_s: m,
                    mu_d: ratio * m,
                })
            } else {
                Err(SolveError::MuRange {
                    index: i + 1,
                    value: m,
                    max: MU_MAX,
                })
            }
        })
        .collect()
}

/// The nominal static coefficients of a scene (mu0 at every contact).
pub fn nominal_mu(coupling: &Coupling) -> Vec<f64> {
    vec![coupling.scene.friction.mu_static; coupling.contacts.len()]
}
