//! `[thermal]` resolved: the two bodies that carry the coupling's elements,
//! each with its expansion coefficient and the point that stays put as it
//! expands, every element's own coefficient, and the temperature cycle
//! (docs/model.md, "Thermal drift").

use nalgebra::Vector3;
use serde::Serialize;

use crate::param::{Param, ParamError};

/// Most points of one cycle: each adds a row per evaluation point to every
/// output.
pub const MAX_CYCLE_POINTS: usize = 100;

/// Largest temperature change accepted [K] without `allow_large_values`:
/// a linear expansion coefficient describes a few tens of kelvin about
/// room temperature, not hundreds (that of steel grows by a fifth from 20
/// to 200 C).
pub const DELTA_T_MAX: f64 = 100.0;

/// Temperature changes of the two bodies from the seating temperature [K].
#[derive(Debug, Clone, Copy, PartialEq, Default, Serialize)]
#[serde(into = "[f64; 2]")]
pub struct Temperatures {
    /// Change of the moving body (and the elements it carries) [K].
    pub moving: f64,
    /// Change of the fixed body (and the elements it carries) [K].
    pub fixed: f64,
}

impl Temperatures {
    pub const fn new(moving: f64, fixed: f64) -> Self {
        Temperatures { moving, fixed }
    }

    /// The seating temperature: no change.
    pub const ZERO: Temperatures = Temperatures::new(0.0, 0.0);

    /// The point a fraction `s` of the way from `self` to `to`.
    pub fn towards(self, to: Temperatures, s: f64) -> Temperatures {
        Temperatures::new(
            self.moving + s * (to.moving - self.moving),
            self.fixed + s * (to.fixed - self.fixed),
        )
    }

    /// The larger of the two changes in size [K].
    pub fn size(self) -> f64 {
        self.moving.abs().max(self.fixed.abs())
    }
}

impl From<Temperatures> for [f64; 2] {
    fn from(t: Temperatures) -> [f64; 2] {
        [t.moving, t.fixed]
    }
}

/// One body as it expands: every point p of it goes to
/// o + (1 + alpha dT) (p - o).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Body {
    /// The body's material (by name, as in the scene file).
    pub material: String,
    /// Its coefficient of thermal expansion [1/K].
    pub thermal_expansion: f64,
    /// The point that stays put [m] (the moving body's in its body frame,
    /// which is the world frame of the scene as written).
    pub origin: Vector3<f64>,
}

impl Body {
    /// The stretch 1 + alpha dT of the body at a change `dt` [K].
    pub fn stretch(&self, dt: f64) -> f64 {
        1.0 + self.thermal_expansion * dt
    }

    /// Where the point `p` of the body goes at a change `dt` [K].
    pub fn map(&self, p: &Vector3<f64>, dt: f64) -> Vector3<f64> {
        p + (p - self.origin) * (self.thermal_expansion * dt)
    }
}

/// The expansion model of a scene with `[thermal]`: both bodies, and the
/// coefficient of each element's own material (its radii grow with it).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ThermalBodies {
    /// The body carrying the moving elements (balls, patches, moving pins,
    /// evaluation points, preload points).
    pub moving: Body,
    /// The body carrying the fixed elements (flats, pins, fixed balls,
    /// arches, spring anchors).
    pub fixed: Body,
    /// Each moving ball's material coefficient [1/K], ball order.
    pub balls: Vec<f64>,
    /// Each fixed surface's material coefficient [1/K], contact order.
    pub surfaces: Vec<f64>,
}

/// `[thermal]`: the expansion model and the cycle a thermal path visits.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct Thermal {
    pub bodies: ThermalBodies,
    /// Temperature changes from the seating temperature, visited in order.
    pub cycle: Vec<Temperatures>,
    /// The load-path error control of the cycle's legs: the tolerance on
    /// each leg's estimated error relative to the larger of the seating's
    /// and the leg's motion (`solve::quasistatic::cycle`).
    pub path_tolerance: f64,
}

/// `[thermal] path_tolerance` by default: 1e-3 of the seating's motion
/// (about 0.5 nm on the bundled scenes), below the scatter the drift is
/// read against by more than an order of magnitude.
pub const DEFAULT_THERMAL_TOLERANCE: f64 = 1e-3;
/// The range `[thermal] path_tolerance` takes.
pub const THERMAL_TOLERANCE_RANGE: std::ops::RangeInclusive<f64> = 1e-9..=1e-1;

/// What is wrong with a cycle of temperature changes [moving, fixed] [K]:
/// the point (0-based; `None`: the cycle as a whole) and why. A cycle has
/// 1 to [`MAX_CYCLE_POINTS`] points of finite changes, each at most
/// [`DELTA_T_MAX`] in size unless `allow_large`.
pub fn cycle_problem(points: &[[f64; 2]], allow_large: bool) -> Option<(Option<usize>, String)> {
    if points.is_empty() {
        let reason = "empty: give at least one pair [moving, fixed] of temperature changes [K]";
        return Some((None, reason.to_string()));
    }
    if points.len() > MAX_CYCLE_POINTS {
        let reason = format!("{} points: at most {MAX_CYCLE_POINTS} per cycle", points.len());
        return Some((None, reason));
    }
    points.iter().enumerate().find_map(|(k, &[moving, fixed])| {
        let reason = if !(moving.is_finite() && fixed.is_finite()) {
            "temperature changes must be finite numbers of kelvin".to_string()
        } else if !allow_large && moving.abs().max(fixed.abs()) > DELTA_T_MAX {
            format!(
                "[{moving}, {fixed}] K: a change above {DELTA_T_MAX} K is beyond a linear \
                 expansion coefficient (a scene file accepts it with `allow_large_values = true`)"
            )
        } else {
            return None;
        };
        Some((Some(k), reason))
    })
}

/// A caller's cycle [moving, fixed] [K], checked ([`cycle_problem`]; a
/// change above [`DELTA_T_MAX`] only in a scene file that allows it).
pub fn cycle_of(points: &[[f64; 2]]) -> Result<Vec<Temperatures>, ParamError> {
    match cycle_problem(points, false) {
        Some((at, reason)) => {
            let at = at.map_or(String::new(), |k| format!("point {}: ", k + 1));
            Err(ParamError::new(Param::Cycle, format!("{}: {at}{reason}", Param::Cycle)))
        }
        None => Ok(points.iter().map(|&[m, f]| Temperatures::new(m, f)).collect()),
    }
}
