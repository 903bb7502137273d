//! One contact of the assembly from its scene surface: the moving surface
//! (the ball's sphere, a canoe patch or a moving pin), the pair's
//! curvature and laws, and the orientation of its contact ellipse.

use nalgebra::{Matrix3, Vector3};

use super::{AssemblyError, Contact, MovingBall, geometry};
use crate::contact::stress::ShearRatios;
use crate::contact::{
    ContactError, ContactLaw, ContactPair, ContactShape, PairCurvature, SeriesNormal,
    TangentialSupport,
};
use crate::material::Material;
use crate::scene::{Surface, SurfaceGeometry};

/// Contact `i` (0-based) of surface `s`, served by `ball`.
pub(super) fn build(i: usize, s: &Surface, ball: &MovingBall) -> Result<Contact, AssemblyError> {
    let (centre, radius, axis) = match s.moving {
        Some(p) => (p.centre, p.radius, p.axis),
        None => (ball.centre, ball.radius, None),
    };
    let moving = MovingSurface { centre, radius, axis };
    let materials = (ball.material.clone(), s.material.clone());
    let compliance = (s.support_compliance, s.tangential_support);
    place(i, s.ball, moving, s.geometry, materials, compliance)
}

/// The least angle between an anisotropic support's axis and the contact
/// normal [deg]: the axis is projected into the tangent plane, and nearer
/// the normal its projection's direction is set by round-off.
pub const MIN_SUPPORT_AXIS_ANGLE_DEG: f64 = 5.0;

/// The moving element's surface at one contact: its centre of curvature
/// (a point of a pin's axis) in the body frame, its radius and a pin's axis.
#[derive(Debug, Clone, Copy)]
pub(super) struct MovingSurface {
    pub centre: Vector3<f64>,
    pub radius: f64,
    pub axis: Option<Vector3<f64>>,
}

/// Contact `i` (0-based) of moving ball `ball`: its moving surface against
/// the fixed `surface`, of `materials` (moving, fixed), with the support
/// compliance (normal, tangential) [m/N]: the pair's curvature, its laws and the orientation
/// of its ellipse; an anisotropic support's axis must not lie within
/// [`MIN_SUPPORT_AXIS_ANGLE_DEG`] of the contact normal (also the contact of a coupling at other temperatures,
/// `assembly::thermal`).
pub(super) fn place(
    i: usize,
    ball: usize,
    moving: MovingSurface,
    surface: SurfaceGeometry,
    (m1, m2): (Material, Material),
    (compliance, tangential): (f64, TangentialSupport),
) -> Result<Contact, AssemblyError> {
    let err = |source| AssemblyError::Contact { contact: i + 1, source };
    let MovingSurface { centre, radius, axis } = moving;
    let (pair, major_axis) = match axis {
        None => sphere_pair(&surface, &centre, radius, m1, m2).map_err(err)?,
        Some(axis) => pin_pair(&surface, &axis, radius, m1, m2).map_err(err)?,
    };
    if !tangential.is_isotropic() {
        let n = geometry::contact(&surface, &centre, radius).normal;
        let angle = n.dot(&tangential.axis).abs().clamp(0.0, 1.0).acos().to_degrees();
        if angle < MIN_SUPPORT_AXIS_ANGLE_DEG {
            return Err(err(ContactError::SupportAxisAlongNormal { angle_deg: angle }));
        }
    }
    let law = ContactLaw { tangential_support: tangential, ..pair.law().map_err(err)? };
    Ok(Contact {
        ball,
        centre,
        radius,
        axis,
        major_axis,
        surface,
        shape: pair.shape,
        shear: ShearRatios::new(&pair, &law.hertz),
        normal: SeriesNormal::new(law.hertz, compliance),
        pair,
        law,
    })
}

/// A sphere of `radius` centred at `centre` against the fixed surface: the
/// named shape and the major axis of its ellipse (along a pin, across a
/// concave groove; none for a circle).
fn sphere_pair(
    surface: &SurfaceGeometry,
    centre: &Vector3<f64>,
    radius: f64,
    m1: Material,
    m2: Material,
) -> Result<(ContactPair, Vector3<f64>), ContactError> {
    let (shape, radius2, major) = match *surface {
        SurfaceGeometry::Plane { .. } => (ContactShape::SpherePlane, None, Vector3::zeros()),
        SurfaceGeometry::Sphere { radius: r2, .. } => {
            (ContactShape::SphereSphere, Some(r2), Vector3::zeros())
        }
        SurfaceGeometry::Cylinder { radius: r2, direction, .. } => {
            (ContactShape::SphereCylinder, Some(r2), direction)
        }
        SurfaceGeometry::ConcaveCylinder { radius: r2, direction, .. } => {
            let n = geometry::contact(surface, centre, radius).normal;
            (ContactShape::SphereGroove, Some(r2), direction.cross(&n))
        }
    };
    let pair = ContactPair::from_shape(shape, radius, radius2, m1, m2)?;
    Ok((pair, major))
}

/// A moving pin (`axis`, `radius`) against a fixed pin crossing it:
/// principal radii (r, inf) and (R, inf), the angle between them that of
/// the axes; the major axis of the ellipse is the principal direction of
/// the smaller relative curvature.
fn pin_pair(
    surface: &SurfaceGeometry,
    axis: &Vector3<f64>,
    radius: f64,
    m1: Material,
    m2: Material,
) -> Result<(ContactPair, Vector3<f64>), ContactError> {
    let SurfaceGeometry::Cylinder { direction, radius: r2, .. } = *surface else {
        return Err(ContactError::MovingPinNeedsPin);
    };
    let cos = axis.dot(&direction).clamp(-1.0, 1.0);
    let curvature = PairCurvature {
        radii1: [radius, f64::INFINITY],
        radii2: [r2, f64::INFINITY],
        angle: cos.acos(),
    };
    curvature.relative()?;
    let pair = ContactPair {
        shape: ContactShape::CrossedCylinders,
        curvature,
        material1: m1,
        material2: m2,
    };
    Ok((pair, crossed_major_axis(axis, radius, &direction, r2)))
}

/// The direction of the smaller curvature of the gap between crossed pins:
/// the curvature tensor 1/r u1 u1^T + 1/R u2 u2^T (u_i = n x d_i, across
/// each axis, in the tangent plane of n = d1 x d2) has it as the
/// eigenvector of its smallest non-zero eigenvalue.
fn crossed_major_axis(d1: &Vector3<f64>, r1: f64, d2: &Vector3<f64>, r2: f64) -> Vector3<f64> {
    let n = d1.cross(d2).normalize();
    let (u1, u2) = (n.cross(d1).normalize(), n.cross(d2).normalize());
    let k: Matrix3<f64> = u1 * u1.transpose() / r1 + u2 * u2.transpose() / r2;
    let eig = k.symmetric_eigen();
    // The eigenvector along n has eigenvalue 0; of the two in the plane,
    // the smaller eigenvalue's.
    (0..3)
        .filter(|&j| eig.eigenvectors.column(j).dot(&n).abs() < 0.5)
        .min_by(|&a, &b| eig.eigenvalues[a].total_cmp(&eig.eigenvalues[b]))
        .map(|j| eig.eigenvectors.column(j).into_owned())
        .unwrap_or_else(Vector3::zeros)
}
