//! The preload on the moving half: one or more forces, each constant, a
//! spring or the weight of the half, ramped together by the load path
//! (docs/scenes.md, `[preload]`).

use nalgebra::Vector3;
use serde::Serialize;

pub use super::magnet::MagnetLaw;

/// Standard gravity [m/s^2] (CGPM 1901), along -z for `[preload] gravity
/// = true`.
pub const STANDARD_GRAVITY: f64 = 9.80665;
/// The largest gravity vector a scene gives without `allow_large_values`
/// [m/s^2] (about 100 g): above it, millimetres per second squared were
/// probably meant.
pub const GRAVITY_MAX: f64 = 1000.0;

/// How a preload force follows the motion of the moving half.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub enum ForceLaw {
    /// Constant magnitude and direction (the load factor scales it).
    Constant,
    /// A spring along `direction` between an anchor on the fixed half and
    /// `point`: F = lambda force - stiffness (p - p_0) . direction, p_0 the
    /// point in the touching pose (docs/scenes.md).
    Spring {
        /// Stiffness along the direction [N/m].
        stiffness: f64,
        /// Free length [m]; the length in the touching pose is
        /// free_length - force / stiffness.
        free_length: f64,
    },
    /// The weight of the moving half, m |g| along g at its centre of mass
    /// (constant; not varied by `--vary preload`).
    Weight,
    /// A magnet at `point` pulling along `direction` towards its keeper on
    /// the fixed half: F = lambda F(gap), gap = gap_0 - (p - p_0) . d, F
    /// from its table ([`MagnetLaw`]; docs/scenes.md).
    Magnet(MagnetLaw),
}

/// One force of the preload.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PreloadForce {
    /// Magnitude at full load in the touching pose [N].
    pub force: f64,
    /// Point of application in the moving half [m].
    pub point: Vector3<f64>,
    /// Unit direction (fixed in the world).
    pub direction: Vector3<f64>,
    pub law: ForceLaw,
}

impl PreloadForce {
    /// A constant force.
    pub fn constant(force: f64, point: Vector3<f64>, direction: Vector3<f64>) -> Self {
        PreloadForce { force, point, direction, law: ForceLaw::Constant }
    }

    /// The weight m g of a half of mass `mass` [kg] at `centre_of_mass` [m]
    /// under the gravity vector `g` [m/s^2] (nonzero): m |g| along g.
    pub fn weight(mass: f64, centre_of_mass: Vector3<f64>, g: Vector3<f64>) -> Self {
        let size = g.norm();
        PreloadForce {
            force: mass * size,
            point: centre_of_mass,
            direction: g / size,
            law: ForceLaw::Weight,
        }
    }

    /// The spring stiffness along the direction [N/m] (0 unless a spring).
    pub fn stiffness(&self) -> f64 {
        match self.law {
            ForceLaw::Spring { stiffness, .. } => stiffness,
            _ => 0.0,
        }
    }

    /// True if `--vary preload` moves and tilts this force (every force but
    /// the weight).
    pub fn varies(&self) -> bool {
        self.law != ForceLaw::Weight
    }
}

/// The preload: its forces (at least one) and the duration of the ramp.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Preload {
    /// The forces, in the order of `[[preload.forces]]` (or the single
    /// `force`), the weight last.
    pub forces: Vec<PreloadForce>,
    /// Duration of the ramp from 0 to full load [s] (`[preload] ramp_time`).
    pub ramp_time: f64,
}

impl Preload {
    /// The paper's preload: one constant force.
    pub fn single(
        force: f64,
        point: Vector3<f64>,
        direction: Vector3<f64>,
        ramp_time: f64,
    ) -> Self {
        Preload { forces: vec![PreloadForce::constant(force, point, direction)], ramp_time }
    }

    /// The force scale of residuals and of normalised loads: the sum of the
    /// magnitudes at full load [N] (the force itself for a single force).
    pub fn scale(&self) -> f64 {
        self.forces.iter().map(|f| f.force).sum()
    }

    /// The resultant force at full load in the touching pose [N].
    pub fn resultant(&self) -> Vector3<f64> {
        self.forces.iter().map(|f| f.direction * f.force).sum()
    }

    /// The unit direction of the resultant (a single force's direction as
    /// given).
    pub fn resultant_direction(&self) -> Vector3<f64> {
        match self.forces.as_slice() {
            [one] => one.direction,
            _ => self.resultant().normalize(),
        }
    }

    /// The point of the resultant in the body frame: the force-weighted
    /// mean of the points (exact for parallel forces; a single force's point).
    pub fn centre(&self) -> Vector3<f64> {
        match self.forces.as_slice() {
            [one] => one.point,
            _ => {
                let sum: Vector3<f64> = self.forces.iter().map(|f| f.point * f.force).sum();
                sum / self.scale()
            }
        }
    }

    /// True for the paper's preload: one constant force.
    pub fn is_single_constant(&self) -> bool {
        matches!(self.forces.as_slice(), [one] if one.law == ForceLaw::Constant)
    }
}
