//! Contact geometry of a moving ball against a fixed surface, from parry3d-f64.
//!
//! parry's exact paths are used: ball-halfspace, ball-ball and ball-capsule
//! (analytic projection; a pin is parry's capsule of the pin's radius about
//! a segment on its axis, whose side is the pin's cylinder, long enough
//! that a ball never reaches its ends). GJK/EPA, which loses ~1e-14 m near
//! contact, is never reached: [`FixedShape`] only holds those three shapes,
//! and the test
//! `parry_contact_matches_closed_form` checks every pair against the closed
//! forms below at separations and penetrations from 1 nm to 1 um (agreement
//! below 1e-12 m is required; observed ~1e-17 m).
//!
//! Closed forms (unit normal n from the fixed surface into the ball, ball
//! centre c, ball radius r):
//! ```text
//! plane (point p, normal m):       gap = (c - p).m - r,          n = m
//! cylinder (axis a + t d, R):      v = (c - a) - ((c - a).d) d,  gap = |v| - R - r,  n = v/|v|
//! sphere (centre s, R):            gap = |c - s| - R - r,        n = (c - s)/|c - s|
//! ```

use nalgebra::Vector3;
use parry3d_f64::math::{Pose as DPose3, Vector as DVec3};
use parry3d_f64::query;
use parry3d_f64::shape::{Ball, Capsule, HalfSpace, Shape};

use crate::scene::SurfaceGeometry;

/// Contact geometry of one ball against one fixed surface.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct ContactGeometry {
    /// Signed distance [m]; negative = overlap (the Hertz approach is -gap).
    pub gap: f64,
    /// Unit normal from the fixed surface into the ball.
    pub normal: Vector3<f64>,
    /// Contact point: midway between the two surface points [m].
    pub point: Vector3<f64>,
}

/// A fixed surface as a parry shape and its pose.
#[derive(Debug, Clone)]
pub enum FixedShape {
    Plane(HalfSpace, DPose3),
    /// A pin: a capsule about a segment of its axis, in world coordinates
    /// (its pose the identity, so that no rotation enters its contacts).
    Cylinder(Capsule, DPose3),
    Sphere(Ball, DPose3),
}

pub(crate) fn dvec(v: &Vector3<f64>) -> DVec3 {
    DVec3::new(v.x, v.y, v.z)
}

fn nvec(v: DVec3) -> Vector3<f64> {
    Vector3::new(v.x, v.y, v.z)
}

impl FixedShape {
    /// Build the parry shape of a surface. A pin's capsule reaches
    /// `half_length` either way along its axis from the foot of the ball
    /// centre `ball` (long enough that the ball never reaches its ends,
    /// wherever on the axis the scene put `axis_point`).
    pub fn new(surface: &SurfaceGeometry, half_length: f64, ball: &Vector3<f64>) -> Self {
        match *surface {
            SurfaceGeometry::Plane { point, normal } => FixedShape::Plane(
                HalfSpace::new(dvec(&normal)),
                DPose3::from_translation(dvec(&point)),
            ),
            SurfaceGeometry::Cylinder {
                axis_point,
                direction,
                radius,
            } => {
                let foot = axis_point + direction * direction.dot(&(ball - axis_point));
                FixedShape::Cylinder(
                    Capsule::new(
                        dvec(&(foot - direction * half_length)),
                        dvec(&(foot + direction * half_length)),
                        radius,
                    ),
                    DPose3::IDENTITY,
                )
            }
            SurfaceGeometry::Sphere { centre, radius } => {
                FixedShape::Sphere(Ball::new(radius), DPose3::from_translation(dvec(&centre)))
            }
        }
    }

    fn parts(&self) -> (&dyn Shape, &DPose3) {
        match self {
            FixedShape::Plane(s, p) => (s, p),
            FixedShape::Cylinder(s, p) => (s, p),
            FixedShape::Sphere(s, p) => (s, p),
        }
    }

    /// Geometry against a ball of `radius` centred at `centre`, found by
    /// parry's contact query. `None` if they are further apart than
    /// `prediction` [m].
    pub fn contact(
        &self,
        centre: &Vector3<f64>,
        radius: f64,
        prediction: f64,
    ) -> Option<ContactGeometry> {
        let (shape, pose) = self.parts();
        let ball = Ball::new(radius);
        let c = query::contact(
            pose,
            shape,
            &DPose3::from_translation(dvec(centre)),
            &ball,
            prediction,
        )
        .expect("parry supports ball against halfspace, cylinder and ball")?;
        Some(ContactGeometry {
            gap: c.dist,
            normal: nvec(c.normal1),
            point: nvec((c.point1 + c.point2) * 0.5),
        })
    }
}

/// The closed-form geometry (module table), the independent check of parry.
pub fn closed_form(
    surface: &SurfaceGeometry,
    centre: &Vector3<f64>,
    radius: f64,
) -> ContactGeometry {
    let (gap, normal) = match *surface {
        SurfaceGeometry::Plane { point, normal } => {
            ((centre - point).dot(&normal) - radius, normal)
        }
        SurfaceGeometry::Cylinder {
            axis_point,
            direction,
            radius: r_cyl,
        } => {
            let w = centre - axis_point;
            let v = w - direction * w.dot(&direction);
            let d = v.norm();
            (d - r_cyl - radius, v / d)
        }
        SurfaceGeometry::Sphere {
            centre: s,
            radius: r_s,
        } => {
            let v = centre - s;
            let d = v.norm();
            (d - r_s - radius, v / d)
        }
    };
    ContactGeometry {
        gap,
        normal,
        point: centre - normal * (radius + 0.5 * gap),
    }
}
