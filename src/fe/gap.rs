//! The gap between the rigid indenter and the block's surface: Hertz's
//! quadratic profile (the default) or the exact separation of the pair's
//! two surfaces.
//!
//! Body 1 lies above the common tangent plane z = 0 at the contact point,
//! body 2 below. A surface of revolution of signed radius R (positive
//! convex, negative concave, as [`PairCurvature`]) that touches z = 0 at
//! the origin lies at the distance
//!
//! ```text
//! s(R, rho^2) = R - sign(R) sqrt(R^2 - rho^2)
//!             = rho^2 / (R + sign(R) sqrt(R^2 - rho^2))      (no cancellation)
//!             = rho^2/(2R) + rho^4/(8R^3) + rho^6/(16R^5) + ...
//! ```
//!
//! from that plane, away from the other body when convex (the lower half of
//! a ball of radius R centred at z = R), towards it when concave (the wall
//! of a hollow of radius |R| whose centre lies on the other body's side).
//! For a sphere rho^2 = x^2 + y^2, for a circular cylinder rho^2 is the
//! square of the coordinate across its axis, for a plane s = 0. The
//! vertical separation of the two surfaces, the gap of a rigid indenter
//! pressed along z, is the sum h = s_1 + s_2. A ball of radius r in a
//! gothic-arch flank of radius R_g (a concave cylinder, its axis along x,
//! so that y runs across the groove) gives
//!
//! ```text
//! h(x, y) = (r - sqrt(r^2 - x^2 - y^2)) - (R_g - sqrt(R_g^2 - y^2))
//!         = x^2/(2r) + y^2 (1/r - 1/R_g)/2 + (x^2 + y^2)^2/(8r^3) - y^4/(8R_g^3) + ...
//! ```
//!
//! whose quadratic part is Hertz's h = x^2/(2R_x) + y^2/(2R_y) with
//! R_x = r, R_y = r R_g/(R_g - r) (Johnson 1985, eq. 4.2). The quartic
//! remainder is positive for every pair here (a concave radius is larger
//! than the convex one it holds): the exact gap opens faster than Hertz's
//! away from the contact. It is defined only inside each curved body's
//! footprint, rho^2 < R^2 (x^2 + y^2 < r^2, |y| < R_g above).

use crate::contact::curvature::PairCurvature;
use crate::fe::FeError;

/// One body's surface near the contact, in the FE's axes (x along the
/// smaller relative radius R_x, y along R_y).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Surface {
    Plane,
    /// A sphere of signed radius (positive convex, negative concave).
    Sphere(f64),
    /// A circular cylinder of signed radius, curved along x (its axis
    /// along y) if `along_x`, else curved along y.
    Cylinder {
        radius: f64,
        along_x: bool,
    },
}

impl Surface {
    /// The distance s of the surface from the tangent plane at (x, y)
    /// (module docs); `None` outside its footprint rho^2 < R^2.
    pub fn sag(&self, x: f64, y: f64) -> Option<f64> {
        let (r, rho2) = match *self {
            Surface::Plane => return Some(0.0),
            Surface::Sphere(r) => (r, x * x + y * y),
            Surface::Cylinder { radius, along_x } => (radius, if along_x { x * x } else { y * y }),
        };
        let room = r * r - rho2;
        (room > 0.0).then(|| rho2 / (r + r.signum() * room.sqrt()))
    }

    /// The curvatures [1/R along x, 1/R along y] of the surface at the
    /// origin: s = x^2/(2R_x) + y^2/(2R_y) + O(rho^4).
    pub fn curvatures(&self) -> [f64; 2] {
        match *self {
            Surface::Plane => [0.0; 2],
            Surface::Sphere(r) => [1.0 / r; 2],
            Surface::Cylinder { radius, along_x } if along_x => [1.0 / radius, 0.0],
            Surface::Cylinder { radius, .. } => [0.0, 1.0 / radius],
        }
    }

    /// The surfaces a body of principal radii `radii` may be in the FE's
    /// axes: a ball, a plane, or a cylinder curved along x or along y; an
    /// error for a body with two different finite radii (a torus, a saddle:
    /// no exact gap is built for those).
    fn candidates(radii: [f64; 2]) -> Result<Vec<Surface>, FeError> {
        let [r1, r2] = radii;
        match (r1.is_finite(), r2.is_finite()) {
            (false, false) => Ok(vec![Surface::Plane]),
            (true, true) if r1 == r2 => Ok(vec![Surface::Sphere(r1)]),
            (true, false) | (false, true) => {
                let radius = if r1.is_finite() { r1 } else { r2 };
                Ok([true, false].map(|along_x| Surface::Cylinder { radius, along_x }).to_vec())
            }
            (true, true) => Err(FeError::InvalidInput(format!(
                "no exact gap for a body of principal radii {r1} m and {r2} m \
                 (only balls, pins, grooves and planes)"
            ))),
        }
    }
}

/// The gap profile h(x, y) of an FE case.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum Gap {
    /// Hertz's h = x^2/(2R_x) + y^2/(2R_y) of the case's radii.
    #[default]
    Quadratic,
    /// The exact separation h = s_1 + s_2 of the two surfaces (module docs).
    Exact([Surface; 2]),
}

impl Gap {
    /// The gap at (x, y) for the case's relative radii `rx`, `ry`; `None`
    /// where the exact gap is not defined (outside a curved body's footprint).
    pub fn height(&self, rx: f64, ry: f64, x: f64, y: f64) -> Option<f64> {
        match self {
            Gap::Quadratic => Some(x * x / (2.0 * rx) + y * y / (2.0 * ry)),
            Gap::Exact([s1, s2]) => Some(s1.sag(x, y)? + s2.sag(x, y)?),
        }
    }

    /// The exact gap of a pair of bodies whose quadratic limit is the FE
    /// case's h = x^2/(2rx) + y^2/(2ry) (rx <= ry, as
    /// [`crate::contact::HertzLaw`] orders them): each body a ball, a plane
    /// or a pin/groove laid along x or y, the layout whose curvatures sum
    /// to [1/rx, 1/ry] (within 1e-9). Pins crossed at an angle other than
    /// 90 degrees, or bodies with two different finite radii, are an error.
    pub fn exact(pair: &PairCurvature, rx: f64, ry: f64) -> Result<Gap, FeError> {
        let want = [1.0 / rx, 1.0 / ry];
        let close = |c: [f64; 2]| (0..2).all(|k| (c[k] - want[k]).abs() <= 1e-9 * want[0]);
        for s1 in Surface::candidates(pair.radii1)? {
            for s2 in Surface::candidates(pair.radii2)? {
                let [c1, c2] = [s1.curvatures(), s2.curvatures()];
                if close([c1[0] + c2[0], c1[1] + c2[1]]) {
                    return Ok(Gap::Exact([s1, s2]));
                }
            }
        }
        Err(FeError::InvalidInput(format!(
            "no exact gap for bodies of radii {:?} and {:?} m at {} rad: their \
             principal directions must be aligned with the contact ellipse's axes",
            pair.radii1, pair.radii2, pair.angle
        )))
    }

    /// The gap at (x, y), or an error naming the point and the footprints
    /// when the exact gap is not defined there.
    pub fn height_in_range(&self, rx: f64, ry: f64, x: f64, y: f64) -> Result<f64, FeError> {
        self.height(rx, ry, x, y).ok_or_else(|| {
            FeError::GapUndefined(format!(
                "the contact candidates reach (x, y) = ({:.4e}, {:.4e}) m, outside the \
                 footprint of {self:?} (a ball of radius r needs x^2 + y^2 < r^2, a pin \
                 or groove of radius R a distance below R across it): the Hertz contact \
                 is too large for the bodies",
                x, y
            ))
        })
    }
}
