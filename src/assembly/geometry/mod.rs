//! Contact geometry of a moving ball against a fixed surface: one closed
//! form per shape pair (one file each, like parry's `query::contact`),
//! behind one dispatcher ([`contact`]) that every solver path calls.
//!
//! With c the ball centre, r its radius and n the unit normal from the
//! fixed surface into the ball, each pair gives the signed distance (gap)
//! and n; the contact point is midway between the two surface points,
//! p = c - n (r + gap/2) (the ball's surface point c - n r and the fixed
//! surface's c - n (r + gap)).
//!
//! parry3d-f64 is the reference: `tests/it/geometry.rs` checks each closed
//! form against parry's `query::contact` with the shapes of
//! [`parry_shape`] on random poses at the coupling's scale. The closed
//! forms replace parry's query in the solvers because the query's shape
//! dispatch and pose transforms cost several times the arithmetic.

mod ball_ball;
mod ball_groove;
mod ball_pin;
mod ball_plane;
mod pin_pin;

use nalgebra::Vector3;
use parry3d_f64::math::{Pose, Rotation, Vector};
use parry3d_f64::shape::{Ball, Capsule, Cylinder, HalfSpace, SharedShape};

use crate::lane::{Lane, splat};
use crate::scene::SurfaceGeometry;

/// Contact geometry of one ball against one fixed surface.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactGeometry<T: Lane = f64> {
    /// Signed distance [m]; negative = overlap (the Hertz approach is -gap).
    pub gap: T,
    /// Unit normal from the fixed surface into the ball.
    pub normal: Vector3<T>,
    /// Contact point: midway between the two surface points [m].
    pub point: Vector3<T>,
}

impl<T: Lane> ContactGeometry<T> {
    /// The geometry of a ball (centre `centre`, radius `radius`) at `gap`
    /// along the unit `normal`, with the point midway (module docs).
    #[inline(always)]
    fn midway(centre: &Vector3<T>, radius: f64, gap: T, normal: Vector3<T>) -> Self {
        let point = centre - normal * (splat::<T>(radius) + splat::<T>(0.5) * gap);
        ContactGeometry { gap, normal, point }
    }
}

/// The offset of `centre` from the line through `axis_point` along the
/// unit `direction`: v = (c - a) - ((c - a) . d) d (a pin's or a groove's
/// axis; its length is the centre's distance from the axis).
#[inline(always)]
fn axis_offset<T: Lane>(
    centre: &Vector3<T>,
    axis_point: &Vector3<T>,
    direction: &Vector3<T>,
) -> Vector3<T> {
    let w = centre - axis_point;
    w - direction * w.dot(direction)
}

/// The geometry of a ball of `radius` centred at `centre` (world
/// coordinates) against the fixed `surface`.
#[inline]
pub fn contact<T: Lane>(
    surface: &SurfaceGeometry,
    centre: &Vector3<T>,
    radius: f64,
) -> ContactGeometry<T> {
    match surface {
        SurfaceGeometry::Plane { point, normal } => {
            ball_plane::contact(centre, radius, point, normal)
        }
        SurfaceGeometry::Cylinder { axis_point, direction, radius: pin } => {
            ball_pin::contact(centre, radius, axis_point, direction, *pin)
        }
        SurfaceGeometry::Sphere { centre: fixed, radius: r_fixed } => {
            ball_ball::contact(centre, radius, fixed, *r_fixed)
        }
        SurfaceGeometry::ConcaveCylinder { axis_point, direction, radius: groove } => {
            ball_groove::contact(centre, radius, axis_point, direction, *groove)
        }
    }
}

/// The geometry of a moving pin of `radius` about the line through
/// `axis_point` along the unit `direction` (world coordinates) against the
/// fixed `surface`: a fixed pin crossing it. Other fixed surfaces do not
/// touch a pin at a point (the assembly refuses them): their gap is NaN.
#[inline]
pub fn pin_contact<T: Lane>(
    surface: &SurfaceGeometry,
    axis_point: &Vector3<T>,
    direction: &Vector3<T>,
    radius: f64,
) -> ContactGeometry<T> {
    match surface {
        SurfaceGeometry::Cylinder {
            axis_point: fixed,
            direction: fixed_direction,
            radius: fixed_radius,
        } => pin_pin::contact(axis_point, direction, radius, fixed, fixed_direction, *fixed_radius),
        _ => ContactGeometry { gap: splat(f64::NAN), normal: Vector3::zeros(), point: *axis_point },
    }
}

/// A fixed surface as a parry shape and its pose: a half-space, a ball, or
/// for a pin a capsule of the pin's radius about the part of its axis that
/// reaches `half_length` either way from the foot of `ball_centre` (a
/// capsule's side is the cylinder, and no ball reaches its ends). A concave
/// cylinder is the solid cylinder whose wall it is, of that length (parry
/// has no hollow shape; the ball lies inside this one). The dynamic
/// solver's colliders, and the reference of the closed forms.
pub fn parry_shape(
    surface: &SurfaceGeometry,
    ball_centre: &Vector3<f64>,
    half_length: f64,
) -> (SharedShape, Pose) {
    let v = |v: &Vector3<f64>| Vector::new(v.x, v.y, v.z);
    match *surface {
        SurfaceGeometry::Plane { point, normal } => {
            (SharedShape::new(HalfSpace::new(v(&normal))), Pose::from_translation(v(&point)))
        }
        SurfaceGeometry::Cylinder { axis_point, direction, radius } => {
            let foot = ball_centre - axis_offset(ball_centre, &axis_point, &direction);
            let (a, b) = (foot - direction * half_length, foot + direction * half_length);
            let capsule = Capsule::new(v(&a), v(&b), radius);
            (SharedShape::new(capsule), Pose::IDENTITY)
        }
        SurfaceGeometry::Sphere { centre, radius } => {
            (SharedShape::new(Ball::new(radius)), Pose::from_translation(v(&centre)))
        }
        SurfaceGeometry::ConcaveCylinder { axis_point, direction, radius } => {
            // parry's cylinder lies along its local y axis.
            let foot = ball_centre - axis_offset(ball_centre, &axis_point, &direction);
            let rotation = Rotation::from_rotation_arc(Vector::Y, v(&direction));
            let cylinder = Cylinder::new(half_length, radius);
            (SharedShape::new(cylinder), Pose::from_parts(v(&foot), rotation))
        }
    }
}
