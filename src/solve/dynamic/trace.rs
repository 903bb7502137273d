//! What a dynamic seating reports per step: the trace sample of each step
//! and the energy balance.

use crate::assembly::BodyPose;

#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum TraceState {
    Open,
    Stick,
    Slip,
}

impl TraceState {
    pub fn name(self) -> &'static str {
        match self {
            TraceState::Open => "open",
            TraceState::Stick => "stick",
            TraceState::Slip => "slip",
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TraceContact {
    /// Normal force including the dashpot [N].
    pub normal_force: f64,
    /// Tangential force magnitude including the dashpot [N].
    pub tangential_force: f64,
    /// Hertz approach, negative when open [m].
    pub approach: f64,
    pub state: TraceState,
}

/// The state at the start of one time step.
#[derive(Debug, Clone, PartialEq)]
pub struct TraceSample {
    pub time: f64,
    pub load_fraction: f64,
    pub pose: BodyPose,
    pub kinetic_energy: f64,
    pub contacts: Vec<TraceContact>,
}

/// Energy at the start of the last step (time t_n), in J.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Energy {
    /// 1/2 m v^2 + 1/2 w.I w with the velocity of step n-1 -> n (rapier's).
    pub kinetic: f64,
    /// The same with the velocity interpolated to t_n, (v_(n-1/2) + v_(n+1/2)) / 2:
    /// symplectic Euler is the leapfrog scheme with velocities at half steps,
    /// so this is the kinetic energy that belongs to the position x_n.
    pub kinetic_synchronized: f64,
    /// Hertz potential sum 2/5 K delta^(5/2) (the integral of K delta^(3/2)).
    pub hertz: f64,
    /// Work done by the preload on the body since t = 0 (sum F_k . dx_k).
    pub preload_work: f64,
}

impl Energy {
    /// Total energy kinetic + Hertz - preload work (constant for a
    /// conservative system; uses the synchronized kinetic energy).
    pub fn total(&self) -> f64 {
        self.kinetic_synchronized + self.hertz - self.preload_work
    }
}
