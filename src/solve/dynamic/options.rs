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
        StartPose {
            offset: Vector3::zeros(),
            tilt: Vector3::zeros(),
        }
    }
}

#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DynamicOptions {
    pub start: StartPose,
    /// Time steps per period of the highest natural mode at full preload.
    pub steps_per_period: f64,
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
            start: StartPose::touching(),
            steps_per_period: 30.0,
            ramp_periods: 40.0,
            damping: Damping {
                normal: 0.3,
                tangential: 1.0,
            },
            settle_displacement: 1e-14,
            settle_force: 1e-9,
            max_settle_periods: 2000.0,
        }
    }
}

impl DynamicOptions {
    pub(super) fn check(&self) -> Result<(), SolveError> {
        let bad = |m: String| Err(SolveError::BadOption(m));
        let finite3 = |v: &Vector3<f64>| v.iter().all(|x| x.is_finite());
        if !finite3(&self.start.offset) || !finite3(&self.start.tilt) {
            return bad("the start offset and tilt must be finite numbers".into());
        }
        if self.start.tilt.norm() > 0.1 {
            return bad(format!(
                "tilt {:.3e} rad is too large: a seating start is tilted by at most 0.1 rad",
                self.start.tilt.norm()
            ));
        }
        if !(self.steps_per_period >= 20.0 && self.steps_per_period.is_finite()) {
            return bad(format!(
                "steps_per_period = {} must be at least 20 (explicit damping needs zeta omega dt < 1)",
                self.steps_per_period
            ));
        }
        if !(self.ramp_periods >= 0.0 && self.ramp_periods.is_finite()) {
            return bad(format!("ramp_periods = {} must be >= 0", self.ramp_periods));
        }
        for (name, z) in [
            ("normal", self.damping.normal),
            ("tangential", self.damping.tangential),
        ] {
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
