//! Settings of the dynamic solver and their checks (defaults and why: the
//! module docs of [`super`]).

use nalgebra::Vector3;

use super::forces::Damping;
use crate::solve::SolveError;

/// Where the moving half starts (at rest).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StartPose {
    /// Translation from the touching pose [m] (z > 0: above the seat).
    pub offset: Vector3<f64>,
    /// Rotation vector about the scene origin, applied before the offset [rad].
    pub tilt: Vector3<f64>,
}

impl StartPose {
    /// The touching pose itself (the quasi-static start).
    pub fn touching() -> Self {
        StartPose { offset: Vector3::zeros(), tilt: Vector3::zeros() }
    }
}

impl StartPose {
    /// A start must be finite and tilted by at most 0.1 rad.
    pub(super) fn check(&self) -> Result<(), SolveError> {
        let finite3 = |v: &Vector3<f64>| v.iter().all(|x| x.is_finite());
        if !finite3(&self.offset) || !finite3(&self.tilt) {
            return Err(SolveError::BadOption(
                "the start offset and tilt must be finite numbers".into(),
            ));
        }
        if self.tilt.norm() > 0.1 {
            return Err(SolveError::BadOption(format!(
                "tilt {:.3e} rad is too large: a seating start is tilted by at most 0.1 rad",
                self.tilt.norm()
            )));
        }
        Ok(())
    }

    /// True unless this is the touching pose.
    pub fn is_offset(&self) -> bool {
        self.offset.norm() > 0.0 || self.tilt.norm() > 0.0
    }
}

/// Settings of the dynamic solver (its start is the seating's:
/// `solve::Load::start`).
#[derive(Debug, Clone, Copy, PartialEq, serde::Serialize)]
pub struct DynamicOptions {
    /// Time steps per period of the highest natural mode at full preload,
    /// for a seating from the touching pose (the preload is the largest
    /// load the contacts meet).
    pub steps_per_period: f64,
    /// The same for a half that arrives moving (an offset or tilted
    /// start): its impacts load the contacts beyond the preload.
    pub arrival_steps_per_period: f64,
    /// Ramp duration in periods of the fundamental (lowest) mode; 0: step load.
    pub ramp_periods: f64,
    pub damping: Damping,
    /// Amplitude of motion below which the body counts as at rest [m].
    pub settle_displacement: f64,
    /// Force and moment residual at rest, relative to F_p and F_p L.
    pub settle_force: f64,
    /// Give up this many fundamental periods after the ramp.
    pub max_settle_periods: f64,
}

impl Default for DynamicOptions {
    fn default() -> Self {
        DynamicOptions {
            steps_per_period: 20.0,
            arrival_steps_per_period: 30.0,
            ramp_periods: 40.0,
            damping: Damping { normal: 0.3, tangential: 1.0 },
            settle_displacement: 1e-14,
            settle_force: 1e-9,
            max_settle_periods: 2000.0,
        }
    }
}

impl DynamicOptions {
    /// The time steps per shortest period of a seating from `start`.
    pub fn steps_per_period_from(&self, start: &StartPose) -> f64 {
        if start.is_offset() { self.arrival_steps_per_period } else { self.steps_per_period }
    }

    pub(super) fn check(&self) -> Result<(), SolveError> {
        let bad = |m: String| Err(SolveError::BadOption(m));
        for (name, n) in [
            ("steps_per_period", self.steps_per_period),
            ("arrival_steps_per_period", self.arrival_steps_per_period),
        ] {
            if !(n >= 20.0 && n.is_finite()) {
                return bad(format!(
                    "{name} = {n} must be at least 20 (explicit damping needs zeta omega dt < 1)"
                ));
            }
        }
        if !(self.ramp_periods >= 0.0 && self.ramp_periods.is_finite()) {
            return bad(format!("ramp_periods = {} must be >= 0", self.ramp_periods));
        }
        for (name, z) in [("normal", self.damping.normal), ("tangential", self.damping.tangential)]
        {
            if !(0.0..=1.0).contains(&z) {
                return bad(format!(
                    "{name} damping ratio {z} must lie in [0, 1] (above 1 the explicit dashpot loses stability)"
                ));
            }
        }
        if !(self.settle_displacement > 0.0
            && self.settle_force > 0.0
            && self.max_settle_periods > 0.0)
        {
            return bad("settling thresholds and the time limit must be positive".into());
        }
        Ok(())
    }
}
