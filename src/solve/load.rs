//! What one coupling cycle seats the coupling under: the inputs that vary
//! from seating to seating, given to the solvers as an argument (the
//! [`Coupling`] holds geometry, materials and laws only).

use super::SolveError;
use super::dynamic::StartPose;
use crate::assembly::Coupling;
use crate::contact::Friction;
use crate::scene::resolve::MU_MAX;
use crate::scene::thermal::DEFAULT_THERMAL_TOLERANCE;
use crate::scene::{Preload, Scene, Temperatures};

/// The load of one seating.
#[derive(Debug, Clone, PartialEq)]
pub struct Load {
    /// Static friction coefficient mu_s of each contact, in contact order.
    pub mu: Vec<f64>,
    /// The preload forces and their ramp.
    pub preload: Preload,
    /// Where the dynamic solver starts (the quasi-static solver always
    /// starts from the touching pose).
    pub start: StartPose,
    /// The temperature changes a thermal path visits after the seating
    /// (`[thermal] cycle`; empty for a scene without `[thermal]`). The
    /// seating itself is at the seating temperature.
    pub cycle: Vec<Temperatures>,
    /// The error tolerance of the cycle's legs (`[thermal] path_tolerance`).
    pub thermal_tolerance: f64,
}

impl Load {
    /// The scene's nominal load: mu0 at every contact, its preload, the
    /// touching start.
    pub fn nominal(scene: &Scene) -> Self {
        Load {
            mu: nominal_mu(scene),
            preload: scene.preload.clone(),
            start: StartPose::touching(),
            cycle: nominal_cycle(scene),
            thermal_tolerance: thermal_tolerance(scene),
        }
    }

    /// This load with the static coefficients `mu`.
    pub fn with_mu(&self, mu: &[f64]) -> Self {
        Load { mu: mu.to_vec(), ..self.clone() }
    }

    /// Each contact's friction (mu_d = ratio mu_s, the coupling's sliding
    /// law), checked: one coefficient per contact, each in [0, MU_MAX].
    pub fn frictions(&self, coupling: &Coupling) -> Result<Vec<Friction>, SolveError> {
        let mut out = Vec::with_capacity(self.mu.len());
        frictions_into(coupling, &self.mu, &mut out)?;
        Ok(out)
    }
}

/// The nominal static coefficients of a scene (mu0 at every contact).
pub fn nominal_mu(scene: &Scene) -> Vec<f64> {
    (0..scene.surfaces.len()).map(|k| scene.friction_of(k).0).collect()
}

/// The scene's temperature cycle (`[thermal] cycle`; empty without one).
pub fn nominal_cycle(scene: &Scene) -> Vec<Temperatures> {
    scene.thermal.as_ref().map_or_else(Vec::new, |t| t.cycle.clone())
}

/// The scene's `[thermal] path_tolerance` (the default without `[thermal]`).
pub fn thermal_tolerance(scene: &Scene) -> f64 {
    scene.thermal.as_ref().map_or(DEFAULT_THERMAL_TOLERANCE, |t| t.path_tolerance)
}

/// Static coefficients -> per-contact friction (mu_d = ratio mu_s, the
/// coupling's friction law), checked, into `out` (cleared first; no
/// allocation once it has the capacity). The solver sets each increment's
/// duration.
pub fn frictions_into(
    coupling: &Coupling,
    mu_s: &[f64],
    out: &mut Vec<Friction>,
) -> Result<(), SolveError> {
    if mu_s.len() != coupling.contacts.len() {
        return Err(SolveError::MuCount { expected: coupling.contacts.len(), got: mu_s.len() });
    }
    let laws = coupling.friction;
    out.clear();
    for (i, &m) in mu_s.iter().enumerate() {
        if !(0.0..=MU_MAX).contains(&m) {
            return Err(SolveError::MuRange { index: i + 1, value: m, max: MU_MAX });
        }
        out.push(Friction { law: laws.law, ..Friction::switch(m, laws.dynamic_ratio * m) });
    }
    Ok(())
}
