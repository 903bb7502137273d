//! Compliant contact laws: the general Hertz contact of two bodies by their
//! principal radii of curvature (`curvature`, Johnson 1985 eq. 4.2), the
//! Hertz normal law (circular and elliptical) and the tangential laws.
//!
//! The named shapes are cases of the general geometry (body 1 the moving
//! element of radius R1, body 2 the fixed one of radius R2; principal
//! radii, negative concave, `inf` flat):
//!
//! | shape | body 1 | body 2 | relative radii |
//! | --- | --- | --- | --- |
//! | sphere-plane | (R1, R1) | (inf, inf) | R = R1 |
//! | sphere-sphere | (R1, R1) | (R2, R2) | 1/R = 1/R1 + 1/R2 |
//! | sphere-seat (R2 > R1) | (R1, R1) | (-R2, -R2) | 1/R = 1/R1 - 1/R2 |
//! | sphere-cylinder | (R1, R1) | (R2, inf) | 1/Rx = 1/R1 + 1/R2, Ry = R1 (along the pin) |
//! | sphere-groove (R2 > R1) | (R1, R1) | (-R2, inf) | Rx = R1 (along the groove), 1/Ry = 1/R1 - 1/R2 (across) |
//! | crossed-cylinders (crossed at 90 deg) | (R1, inf) | (R2, inf) | Rx = min(R1, R2), Ry = max(R1, R2) |
//!
//! sphere-groove is a ball in a concave cylindrical flank (a gothic arch):
//! its contact ellipse is long across the groove.

pub mod coulomb;
pub mod curvature;
pub mod elliptic;
pub mod friction;
pub mod hertz;
pub mod history;
mod increment;
pub mod mindlin;
pub mod mindlin_deresiewicz;
pub mod quadrature;
pub mod series;
pub mod stress;
pub mod support;
pub mod tangential;
pub mod tangential_types;

use nalgebra::{Matrix3, Vector3};
use serde::{Deserialize, Serialize};
use thiserror::Error;

use crate::material::{Material, effective_modulus, effective_shear_modulus};
pub use curvature::{PairCurvature, RelativeCurvature};
pub use friction::FrictionLaw;
pub use hertz::HertzLaw;
pub use mindlin::{PrincipalStiffness, mindlin_axis_coefficients, tangential_tensor};
pub use series::SeriesNormal;
pub use support::TangentialSupport;
pub use tangential::{
    Friction, SlipState, TangentialInput, TangentialLaw, TangentialResponse, TangentialState,
};

/// The geometric type of a contact pair: a moving ball against a fixed element.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum ContactShape {
    SpherePlane,
    SphereSphere,
    SphereSeat,
    SphereCylinder,
    /// A ball in a concave cylinder (a gothic-arch flank) of larger radius.
    SphereGroove,
    /// Two pins crossing (at 90 degrees for `contact --shape`; a scene's
    /// crossed pins at the angle of their axes).
    CrossedCylinders,
    /// Two bodies given by their principal radii (`contact --radii1 --radii2`).
    General,
}

impl ContactShape {
    /// The shapes given by two radii (`contact --shape`).
    pub const ALL: [ContactShape; 6] = [
        ContactShape::SpherePlane,
        ContactShape::SphereSphere,
        ContactShape::SphereSeat,
        ContactShape::SphereCylinder,
        ContactShape::SphereGroove,
        ContactShape::CrossedCylinders,
    ];

    /// Kebab-case name, as in scene files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            ContactShape::SpherePlane => "sphere-plane",
            ContactShape::SphereSphere => "sphere-sphere",
            ContactShape::SphereSeat => "sphere-seat",
            ContactShape::SphereCylinder => "sphere-cylinder",
            ContactShape::SphereGroove => "sphere-groove",
            ContactShape::CrossedCylinders => "crossed-cylinders",
            ContactShape::General => "general",
        }
    }

    /// Whether the shape needs the second body's radius.
    pub fn needs_radius2(self) -> bool {
        !matches!(self, ContactShape::SpherePlane)
    }

    /// The principal radii of the two bodies of this shape (module table)
    /// for the moving element's radius `r1` and the fixed element's `r2`.
    pub fn curvature(self, r1: f64, r2: Option<f64>) -> Result<PairCurvature, ContactError> {
        let r1 = check_radius("radius1", r1)?;
        let r2 = match (self.needs_radius2(), r2) {
            (false, _) => f64::INFINITY,
            (true, None) => return Err(ContactError::MissingRadius2 { shape: self.name() }),
            (true, Some(r)) => check_radius("radius2", r)?,
        };
        let inf = f64::INFINITY;
        let pair = |radii1, radii2, angle| PairCurvature { radii1, radii2, angle };
        Ok(match self {
            ContactShape::SpherePlane | ContactShape::SphereSphere => pair([r1; 2], [r2; 2], 0.0),
            ContactShape::SphereSeat | ContactShape::SphereGroove if r2 <= r1 => {
                return Err(ContactError::SeatTooSmall { shape: self.name(), r1, r2 });
            }
            ContactShape::SphereSeat => pair([r1; 2], [-r2; 2], 0.0),
            ContactShape::SphereCylinder => pair([r1; 2], [r2, inf], 0.0),
            ContactShape::SphereGroove => pair([r1; 2], [-r2, inf], 0.0),
            ContactShape::CrossedCylinders => {
                pair([r1, inf], [r2, inf], std::f64::consts::FRAC_PI_2)
            }
            ContactShape::General => return Err(ContactError::GeneralNeedsRadii),
        })
    }
}

impl std::str::FromStr for ContactShape {
    type Err = UnknownShape;
    fn from_str(s: &str) -> Result<Self, UnknownShape> {
        ContactShape::ALL
            .into_iter()
            .find(|c| c.name() == s)
            .ok_or_else(|| UnknownShape(s.to_string()))
    }
}

/// A contact shape name that is none of [`ContactShape::ALL`].
#[derive(Debug, Clone, PartialEq, Error)]
#[error("unknown contact shape `{0}` (expected one of {names})", names = shape_names())]
pub struct UnknownShape(pub String);

fn shape_names() -> String {
    let names: Vec<_> = ContactShape::ALL.iter().map(|c| c.name()).collect();
    names.join(", ")
}

#[derive(Debug, Clone, PartialEq, Error)]
pub enum ContactError {
    #[error("{field} = {value} m is invalid: a radius must be a positive, finite length")]
    BadRadius { field: &'static str, value: f64 },
    #[error(
        "{field} = {value} m is invalid: a principal radius must be non-zero (negative: concave, inf: flat)"
    )]
    BadPrincipalRadius { field: &'static str, value: f64 },
    #[error("{shape} needs radius2 (the radius of the fixed element)")]
    MissingRadius2 { shape: &'static str },
    #[error(
        "{shape} needs a concave radius radius2 = {r2} m larger than the ball radius radius1 = {r1} m"
    )]
    SeatTooSmall { shape: &'static str, r1: f64, r2: f64 },
    #[error(
        "the general contact needs the principal radii of both bodies ({}, {})",
        crate::param::Param::Radii1,
        crate::param::Param::Radii2
    )]
    GeneralNeedsRadii,
    #[error(
        "angle = {0} rad is invalid: the angle between the principal directions must be finite"
    )]
    BadAngle(f64),
    #[error(
        "not a point contact: the smaller relative curvature A = {a:.6e} 1/m (B = {b:.6e} 1/m) must be positive \
         (A = 0: the surfaces touch along a line, e.g. a pin on a flat or parallel pins; A < 0: a concave \
         surface is curved more tightly than the convex one it should hold, e.g. a ball larger than its seat)"
    )]
    NotPointContact { a: f64, b: f64 },
    #[error("load = {0} N is invalid: the normal load must be positive and finite")]
    BadLoad(f64),
    #[error(
        "a moving pin touches only a fixed pin that crosses it (a plane, ball or concave \
         groove would touch it along a line or not at a single point)"
    )]
    MovingPinNeedsPin,
    #[error(
        "the support compliance's axis lies {angle_deg:.2} deg from the contact normal: `along` \
         acts in the tangent plane, so give an axis at least 5 deg from the normal (along the \
         groove, or across it)"
    )]
    SupportAxisAlongNormal { angle_deg: f64 },
}

/// One contact pair: its shape, the principal radii of both bodies and the
/// materials (1 = the moving element, 2 = the fixed element).
#[derive(Debug, Clone, PartialEq)]
pub struct ContactPair {
    pub shape: ContactShape,
    pub curvature: PairCurvature,
    pub material1: Material,
    pub material2: Material,
}

/// The laws of one contact pair, ready to evaluate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ContactLaw {
    pub hertz: HertzLaw,
    /// Effective tangential modulus G* [Pa].
    pub g_star: f64,
    /// Mindlin's k_t / a along the major and the minor axis of the contact
    /// ellipse [N/m^2] (`mindlin`), a the major semi-axis.
    pub mindlin: [f64; 2],
    /// A support compliance in series with Mindlin's stiffness in the
    /// tangent plane (rigid: none): isotropic, k_t,eff = 1 / (1/k_t + c_t)
    /// along each principal axis; or along and across an axis, the tensor
    /// (K_m^-1 + C)^-1 (`support`, [`ContactLaw::increment_stiffness`]).
    pub tangential_support: TangentialSupport,
}

/// Everything a contact gives at one normal load (SI units).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContactEvaluation {
    pub shape: ContactShape,
    pub load_n: f64,
    pub effective_modulus_pa: f64,
    pub effective_shear_modulus_pa: f64,
    /// Relative radii of curvature [Rx, Ry], Rx <= Ry.
    pub relative_radii_m: [f64; 2],
    pub hertz_constant: f64,
    pub approach_m: f64,
    /// [a, b], a >= b.
    pub semi_axes_m: [f64; 2],
    pub max_pressure_pa: f64,
    pub normal_stiffness_n_per_m: f64,
    /// Geometric mean of the two below (8 G* a for a circle).
    pub tangential_stiffness_n_per_m: f64,
    /// Mindlin's k_t along the major axis a (along the pin for sphere-cylinder).
    pub tangential_stiffness_major_n_per_m: f64,
    /// Mindlin's k_t along the minor axis b (across the pin).
    pub tangential_stiffness_minor_n_per_m: f64,
    /// Maximum subsurface shear stress (the body with the larger value) [Pa].
    pub max_shear_stress_pa: f64,
    /// Its depth below the surface [m].
    pub max_shear_depth_m: f64,
}

fn check_radius(field: &'static str, value: f64) -> Result<f64, ContactError> {
    if value.is_finite() && value > 0.0 {
        Ok(value)
    } else {
        Err(ContactError::BadRadius { field, value })
    }
}

impl ContactPair {
    /// The pair of a named shape (the module table) with the moving
    /// element's radius `radius1` and the fixed element's `radius2`.
    pub fn from_shape(
        shape: ContactShape,
        radius1: f64,
        radius2: Option<f64>,
        material1: Material,
        material2: Material,
    ) -> Result<ContactPair, ContactError> {
        Ok(ContactPair {
            shape,
            curvature: shape.curvature(radius1, radius2)?,
            material1,
            material2,
        })
    }

    /// Relative radii of curvature [Rx, Ry], Rx <= Ry (Johnson eq. 4.2, `curvature`).
    pub fn relative_radii(&self) -> Result<[f64; 2], ContactError> {
        Ok(self.curvature.relative()?.radii())
    }

    /// The first principal radius of each body: the moving element's, and
    /// the fixed element's (`None` for a flat).
    pub fn nominal_radii(&self) -> (f64, Option<f64>) {
        let r2 = self.curvature.radii2[0];
        (self.curvature.radii1[0], r2.is_finite().then_some(r2))
    }

    /// Build the laws of this pair.
    pub fn law(&self) -> Result<ContactLaw, ContactError> {
        let [rx, ry] = self.relative_radii()?;
        let e_star = effective_modulus(&self.material1, &self.material2);
        let hertz = HertzLaw::elliptical(rx, ry, e_star);
        Ok(ContactLaw {
            hertz,
            g_star: effective_shear_modulus(&self.material1, &self.material2),
            mindlin: mindlin_axis_coefficients(&self.material1, &self.material2, hertz.axis_ratio),
            tangential_support: TangentialSupport::default(),
        })
    }

    /// Evaluate the pair at a normal load F > 0: Hertz, Mindlin and the
    /// subsurface shear stress.
    pub fn evaluate(&self, load: f64) -> Result<ContactEvaluation, ContactError> {
        let law = self.law()?;
        if !(load.is_finite() && load > 0.0) {
            return Err(ContactError::BadLoad(load));
        }
        let h = &law.hertz;
        let approach = h.approach(load);
        let ratios = stress::ShearRatios::new(self, h);
        let st = stress::contact_stress(self, h, &ratios, load);
        let [k_major, k_minor] = law.tangential_stiffness_axes(load);
        Ok(ContactEvaluation {
            shape: self.shape,
            load_n: load,
            effective_modulus_pa: h.e_star,
            effective_shear_modulus_pa: law.g_star,
            relative_radii_m: h.radii,
            hertz_constant: h.hertz_constant,
            approach_m: approach,
            semi_axes_m: h.semi_axes(load),
            max_pressure_pa: h.max_pressure(load),
            normal_stiffness_n_per_m: h.stiffness(approach),
            tangential_stiffness_n_per_m: law.tangential_stiffness(load).0,
            tangential_stiffness_major_n_per_m: k_major,
            tangential_stiffness_minor_n_per_m: k_minor,
            max_shear_stress_pa: st.max_shear_stress_pa[0].max(st.max_shear_stress_pa[1]),
            max_shear_depth_m: st.max_shear_depth_m.unwrap_or(0.0),
        })
    }
}

impl ContactLaw {
    /// Mindlin's k_t along the major and the minor axis at normal load F
    /// (k_t ~ a ~ F^(1/3), so dk/dF = k / (3 F)); zero when unloaded. In
    /// series with the support taken isotropic at its mean compliance
    /// (exact for an isotropic support; an anisotropic one's principal
    /// values need the contact's orientation, which the contact laws give
    /// [`ContactLaw::increment_stiffness`]).
    pub fn tangential_stiffness_axes(&self, load: f64) -> [f64; 2] {
        let a = self.hertz.semi_axes(load)[0];
        let s = &self.tangential_support;
        let c_t = 0.5 * (s.along + s.across);
        self.mindlin.map(|c| c * a).map(|k| if c_t > 0.0 { k / (1.0 + k * c_t) } else { k })
    }

    /// A scalar k_t at normal load F: sqrt(det K) of the 2x2 tangential
    /// stiffness (8 G* a for a circle), and dk_t/dF. For uses that need
    /// one number (damping, frequency estimates); the contact laws use the
    /// 2x2 stiffness of [`ContactLaw::increment_stiffness`]. With Mindlin's
    /// k1, k2 in series with the support (`support`),
    /// det K = k1 k2 / D, D = 1 + c_m (k1 + k2) + c_along c_across k1 k2,
    /// c_m = (c_along + c_across)/2 (tr(C K_m) averaged over the support's
    /// orientation; exact for an isotropic support or a circular contact),
    /// and, with k_i ~ F^(1/3),
    /// d ln k_t/dF = (1 - (c_m (k1 + k2) + 2 c_along c_across k1 k2) / (2 D)) / (3 F).
    pub fn tangential_stiffness(&self, load: f64) -> (f64, f64) {
        if load <= 0.0 {
            return (0.0, 0.0);
        }
        let a = self.hertz.semi_axes(load)[0];
        let [k1, k2] = self.mindlin.map(|c| c * a);
        let s = &self.tangential_support;
        let c_m = 0.5 * (s.along + s.across);
        let cross = s.along * s.across * k1 * k2;
        let d = 1.0 + c_m * (k1 + k2) + cross;
        let kt = (k1 * k2 / d).sqrt();
        let share = 1.0 - (c_m * (k1 + k2) + 2.0 * cross) / (2.0 * d);
        (kt, kt / (3.0 * load) * share)
    }

    /// k_t = sqrt(det K) of the contact's 2x2 tangential stiffness at
    /// normal load F, oriented: Mindlin's principal stiffness about
    /// `major_axis` in series with the support (exact for an anisotropic
    /// support too, unlike [`Self::tangential_stiffness`]); zero unloaded.
    pub fn oriented_tangential_stiffness(
        &self,
        load: f64,
        normal: &Vector3<f64>,
        major_axis: &Vector3<f64>,
    ) -> f64 {
        if load <= 0.0 {
            return 0.0;
        }
        let a = self.hertz.semi_axes(load)[0];
        let (principal, _, _) = self.increment_stiffness(a, 0.0, normal, major_axis, false);
        (principal.k[0] * principal.k[1]).sqrt()
    }

    /// Mindlin-Deresiewicz: the equal-area radius sqrt(ab) at `fn_` and the
    /// shape K_t / (8 G* sqrt(ab)) (the Coulomb law reads neither: they are
    /// left at zero for it).
    #[inline]
    pub fn mindlin_deresiewicz_inputs(
        &self,
        tangential_law: TangentialLaw,
        fn_: f64,
        normal: &Vector3<f64>,
        major_axis: &Vector3<f64>,
    ) -> (f64, Matrix3<f64>) {
        match tangential_law {
            TangentialLaw::Coulomb => (0.0, Matrix3::zeros()),
            TangentialLaw::MindlinDeresiewicz => {
                let hertz = &self.hertz;
                let [a, b] = hertz.semi_axes(fn_);
                let shape = self.mindlin.map(|c| c / (8.0 * self.g_star * hertz.axis_ratio.sqrt()));
                ((a * b).sqrt(), tangential_tensor(shape, normal, major_axis))
            }
        }
    }
}
