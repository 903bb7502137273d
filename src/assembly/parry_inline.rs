//! parry's contact query of a ball against a fixed plane, pin (a capsule)
//! or sphere, written out operation for operation: the same IEEE operations in
//! the same order as `parry3d_f64::query::contact` (parry 0.31 on glam
//! 0.33), so the same bits, without the shape dispatcher and the rotations
//! by the identity that parry's general path performs.
//! The fast seating path ([`crate::solve::contact_layer::GeometrySource`])
//! uses it so that it evaluates the very functions the adaptive path
//! evaluates with parry; `tests/scenes.rs` (`parry_inline_is_parrys_query_bit_for_bit`)
//! checks it against parry's query bit for bit, so a parry or glam upgrade
//! that changes their arithmetic fails there, not silently in a study.
//!
//! parry computes a contact in the fixed shape's frame: pos12 = pos1^-1 pos2
//! (pos1 the shape's pose, pos2 = (c, I) the ball's), the pair's contact
//! there, then points and normal back to the world (`Contact::transform_by_mut`).
//! Every fixed shape here has the identity rotation (a plane and a sphere
//! are placed by a translation, a pin is a capsule in world coordinates),
//! so every rotation in that chain is by the unit quaternion (0, 0, 0, 1),
//! which glam's v (w^2 - b.b) + b 2(v.b) + (b x v) 2w returns exactly (up
//! to the sign of an exact zero): those rotations are left out.
//!
//! The chains (c ball centre, r ball radius, vector operations componentwise,
//! dot products summed x, y, z):
//! ```text
//! plane (pose (p, I), normal n):  t = c - p;  d = t - n r;  gap = n.d;
//!                                 point1 = (d - n gap) + p;  point2 = (d - t) + c
//! sphere (pose (s, I), radius R): t = c - s;  gap = sqrt(t.t) - (R + r);  n = t (1/sqrt(t.t));
//!                                 point1 = n R + s;  point2 = c - n r
//! pin (capsule a-b, radius R):    o = a + (b - a) ((b - a).(c - a) / (b - a).(b - a));
//!                                 e = (c - o) / |c - o|;  m = o + e R;
//!                                 u = (m - c) / |m - c|;  gap = |m - c| - r;  n = -u;
//!                                 point1 = m;  point2 = u r + c
//! ```
//! with x / |x| formed as x (1/|x|), and point = (point1 + point2) 0.5.
//! Where parry would take another branch (a ball centre inside a pin or
//! beyond its segment, a degenerate normal, beyond the prediction distance,
//! a shape posed otherwise) this returns `None` and the caller asks parry
//! itself.

use nalgebra::Vector3;

use super::geometry::{ContactGeometry, FixedShape};

/// glam's `DVec3::dot`: (x x' + y y') + z z'.
#[inline(always)]
fn dot(a: &Vector3<f64>, b: &Vector3<f64>) -> f64 {
    a.x * b.x + a.y * b.y + a.z * b.z
}

/// glam's `normalize_and_length` of a 3-vector: (v (1/|v|), |v|), or
/// `None` where glam would return its fallback (X, 0).
#[inline(always)]
fn normalize_and_length(v: &Vector3<f64>) -> Option<(Vector3<f64>, f64)> {
    let length = dot(v, v).sqrt();
    let rcp = 1.0 / length;
    (rcp.is_finite() && rcp > 0.0).then(|| (v * rcp, length))
}

/// parry's contact of a ball of `radius` centred at `centre` with `shape`,
/// or `None` where parry takes a branch not written out here (module docs):
/// then the caller asks parry.
#[inline]
pub fn contact(
    shape: &FixedShape,
    centre: &Vector3<f64>,
    radius: f64,
    prediction: f64,
) -> Option<ContactGeometry> {
    let v = |p: parry3d_f64::math::Vector| Vector3::new(p.x, p.y, p.z);
    match shape {
        FixedShape::Plane(halfspace, pose) => {
            if !is_identity(pose) {
                return None;
            }
            let (p, n) = (v(pose.translation), v(halfspace.normal));
            let t = centre - p;
            // Ball::support_point_toward(pos12, -n) = t + (-n) r = t - n r.
            let deepest = t - n * radius;
            let gap = dot(&n, &deepest);
            (gap <= prediction).then_some(())?;
            let point1 = (deepest - n * gap) + p;
            let point2 = (deepest - t) + centre;
            Some(ContactGeometry {
                gap,
                normal: n,
                point: (point1 + point2) * 0.5,
            })
        }
        FixedShape::Sphere(ball, pose) => {
            if !is_identity(pose) {
                return None;
            }
            let s = v(pose.translation);
            let t = centre - s;
            let distance_squared = dot(&t, &t);
            let sum_radius = ball.radius + radius;
            let with_prediction = sum_radius + prediction;
            (distance_squared < with_prediction * with_prediction && distance_squared != 0.0)
                .then_some(())?;
            let length = distance_squared.sqrt();
            let n = t * (1.0 / length);
            let point1 = n * ball.radius + s;
            let point2 = centre - n * radius;
            Some(ContactGeometry {
                gap: length - sum_radius,
                normal: n,
                point: (point1 + point2) * 0.5,
            })
        }
        FixedShape::Cylinder(capsule, pose) => {
            if !is_identity(pose) || pose.translation != parry3d_f64::math::Vector::ZERO {
                return None;
            }
            let (sa, sb) = (v(capsule.segment.a), v(capsule.segment.b));
            // Segment::project_local_point_and_get_location, interior.
            let ab = sb - sa;
            let ap = centre - sa;
            let ab_ap = dot(&ab, &ap);
            let sqnab = dot(&ab, &ab);
            (ab_ap > 0.0 && ab_ap < sqnab).then_some(())?;
            let on_axis = sa + ab * (ab_ap / sqnab);
            // Capsule::project_local_point, the centre outside.
            let (e, l) = normalize_and_length(&(centre - on_axis))?;
            (l >= f64::EPSILON && l > capsule.radius).then_some(())?;
            let m = on_axis + e * capsule.radius;
            // contact_convex_polyhedron_ball, the projection outside.
            let (u, k) = normalize_and_length(&(m - centre))?;
            (k >= f64::EPSILON).then_some(())?;
            let gap = k - radius;
            (gap <= prediction).then_some(())?;
            // normal1 = -u; point2 = normal2 r + c with normal2 = u.
            let point2 = u * radius + centre;
            Some(ContactGeometry {
                gap,
                normal: -u,
                point: (m + point2) * 0.5,
            })
        }
    }
}

/// Whether a fixed shape's pose has exactly the identity rotation (all of
/// `FixedShape::new`'s).
fn is_identity(pose: &parry3d_f64::math::Pose) -> bool {
    let q = pose.rotation;
    q.w == 1.0 && q.x == 0.0 && q.y == 0.0 && q.z == 0.0
}
