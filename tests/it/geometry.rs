//! The closed-form contact geometry (`assembly::geometry::contact`, one
//! closed form per shape pair) against parry's `query::contact`, the
//! reference, on the shapes of `assembly::geometry::parry_shape`: random
//! poses at a coupling's scale (fixed surfaces placed about 0.04 m from
//! the origin in random orientations, ball radii 3-5 mm, separations and
//! penetrations from 1 nm to 1 um), the gap and the contact point within
//! 1e-15 m and the normal within 4e-15 of parry's (a pin's normal is the
//! direction of a vector of length R + r, about 5 mm, formed from
//! positions of 0.04 m: each computation carries about eps 0.04 / 0.005,
//! 2e-15, of rounding; measured 2.8e-15 apart, ball-ball 2e-16, plane 0;
//! a ball in a concave groove against the projection onto parry's solid
//! cylinder from inside, within a bound that grows as the groove's radius
//! approaches the ball's, see `check`).
//! The gap is also checked against the separation the ball was placed at.

use kinrepro::assembly::geometry::{ContactGeometry, contact, parry_shape, pin_contact};
use kinrepro::scene::SurfaceGeometry;
use nalgebra::Vector3;
use parry3d_f64::math::{Pose, Vector};
use parry3d_f64::query;
use parry3d_f64::shape::{Ball, Capsule};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

const CASES: usize = 20_000;

/// A random unit vector.
fn unit(rng: &mut ChaCha8Rng) -> Vector3<f64> {
    loop {
        let v = Vector3::from_fn(|_, _| rng.random_range(-1.0..1.0));
        if (0.1..1.0).contains(&v.norm()) {
            return v.normalize();
        }
    }
}

/// A unit vector perpendicular to the unit `n`.
fn across(rng: &mut ChaCha8Rng, n: &Vector3<f64>) -> Vector3<f64> {
    let v = unit(rng);
    (v - n * n.dot(&v)).normalize()
}

/// A separation (positive) or penetration (negative) from 1 nm to 1 um,
/// log-uniform.
fn separation(rng: &mut ChaCha8Rng) -> f64 {
    let magnitude = 10f64.powf(rng.random_range(-9.0..-6.0));
    if rng.random_bool(0.5) { magnitude } else { -magnitude }
}

/// A point about 0.04 m from the origin.
fn placed(rng: &mut ChaCha8Rng) -> Vector3<f64> {
    unit(rng) * rng.random_range(0.03..0.05)
}

/// parry's contact of a ball of `radius` at `centre` with `surface`; for a
/// concave cylinder, the ball centre's projection onto the wall of parry's
/// solid cylinder from inside (the nearest wall point: gap = its distance
/// - r, normal from it to the centre).
fn parry(surface: &SurfaceGeometry, centre: &Vector3<f64>, radius: f64) -> ContactGeometry {
    // A pin's capsule reaches as far as the dynamic solver's (4 (R + r)).
    let pin = match surface {
        SurfaceGeometry::Cylinder { radius, .. } => *radius,
        SurfaceGeometry::ConcaveCylinder { radius, .. } => *radius,
        _ => 0.0,
    };
    let (shape, pose) = parry_shape(surface, centre, 4.0 * (pin + radius));
    let c = Vector::new(centre.x, centre.y, centre.z);
    let v = |p: Vector| Vector3::new(p.x, p.y, p.z);
    if let SurfaceGeometry::ConcaveCylinder { .. } = surface {
        let projection = shape.project_point(&pose, c, false);
        assert!(projection.is_inside, "the ball centre lies inside the groove");
        let to_centre = v(c - projection.point);
        let (d, normal) = (to_centre.norm(), to_centre.normalize());
        let gap = d - radius;
        return ContactGeometry { gap, normal, point: centre - normal * (radius + 0.5 * gap) };
    }
    let at = Pose::from_translation(c);
    let c = query::contact(&pose, &*shape, &at, &Ball::new(radius), 1.0)
        .expect("parry supports these pairs")
        .expect("within the prediction distance");
    ContactGeometry { gap: c.dist, normal: v(c.normal1), point: v((c.point1 + c.point2) * 0.5) }
}

/// The closed form against parry and against the placed separation `gap`;
/// returns the largest differences (gap, point, normal) seen.
fn check(surface: &SurfaceGeometry, centre: &Vector3<f64>, radius: f64, gap: f64) -> [f64; 3] {
    let ours = contact(surface, centre, radius);
    let reference = parry(surface, centre, radius);
    let d = [
        (ours.gap - reference.gap).abs(),
        (ours.point - reference.point).norm(),
        (ours.normal - reference.normal).norm(),
    ];
    // In a groove the normal is the direction of the ball centre's offset
    // from the axis, of length R - r - gap (0.1 mm for R = 1.02 r), formed
    // from 0.04 m coordinates in both computations (parry's in its
    // cylinder's frame): each carries about eps 0.04 / (R - r) of rounding.
    let normal_tol = match surface {
        SurfaceGeometry::ConcaveCylinder { axis_point, radius: groove, .. } => {
            let offset = groove - radius - gap;
            16.0 * f64::EPSILON * (centre.norm() + axis_point.norm()) / offset
        }
        _ => 4e-15,
    };
    assert!(
        d[0] <= 1e-15 && d[1] <= 1e-15 && d[2] <= normal_tol,
        "{surface:?} ball {centre} r {radius}: {ours:?} vs parry {reference:?}"
    );
    assert!((ours.gap - gap).abs() <= 1e-15, "{surface:?}: {} vs {gap}", ours.gap);
    d
}

/// Run `case` (which places one ball against one surface and checks it)
/// on `CASES` random poses and print the largest differences.
fn run(label: &str, seed: u64, mut case: impl FnMut(&mut ChaCha8Rng) -> [f64; 3]) {
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let mut worst = [0.0f64; 3];
    for _ in 0..CASES {
        let d = case(&mut rng);
        for k in 0..3 {
            worst[k] = worst[k].max(d[k]);
        }
    }
    println!(
        "{label}: largest difference from parry: gap {:.1e} m, point {:.1e} m, normal {:.1e}",
        worst[0], worst[1], worst[2]
    );
}

#[test]
fn ball_plane_is_parrys_half_space() {
    run("ball-plane", 1, |rng| {
        let (normal, point) = (unit(rng), placed(rng));
        let radius = rng.random_range(0.003..0.005);
        let gap = separation(rng);
        let lateral = across(rng, &normal) * rng.random_range(0.0..0.003);
        let centre = point + lateral + normal * (radius + gap);
        check(&SurfaceGeometry::Plane { point, normal }, &centre, radius, gap)
    });
}

#[test]
fn ball_pin_is_parrys_capsule_side() {
    run("ball-pin", 2, |rng| {
        let (direction, axis_point) = (unit(rng), placed(rng));
        let pin = rng.random_range(0.001..0.003);
        let radius = rng.random_range(0.003..0.005);
        let gap = separation(rng);
        let along = direction * rng.random_range(-0.01..0.01);
        let out = across(rng, &direction);
        let centre = axis_point + along + out * (pin + radius + gap);
        let surface = SurfaceGeometry::Cylinder { axis_point, direction, radius: pin };
        check(&surface, &centre, radius, gap)
    });
}

#[test]
fn ball_ball_is_parrys_ball() {
    run("ball-ball", 3, |rng| {
        let fixed = placed(rng);
        let fixed_radius = rng.random_range(0.003..0.005);
        let radius = rng.random_range(0.003..0.005);
        let gap = separation(rng);
        let centre = fixed + unit(rng) * (fixed_radius + radius + gap);
        let surface = SurfaceGeometry::Sphere { centre: fixed, radius: fixed_radius };
        check(&surface, &centre, radius, gap)
    });
}

#[test]
fn ball_in_groove_is_inside_parrys_cylinder() {
    run("ball-groove", 4, |rng| {
        let (direction, axis_point) = (unit(rng), placed(rng));
        let radius = rng.random_range(0.003..0.005);
        // A gothic-arch flank 1.02 to 1.5 times the ball's radius.
        let groove = radius * rng.random_range(1.02..1.5);
        let gap = separation(rng);
        let along = direction * rng.random_range(-0.01..0.01);
        let out = across(rng, &direction);
        // The wall is at distance R from the axis; the ball centre r + gap inside it.
        let centre = axis_point + along + out * (groove - radius - gap);
        let surface = SurfaceGeometry::ConcaveCylinder { axis_point, direction, radius: groove };
        check(&surface, &centre, radius, gap)
    });
}

/// parry's contact of two capsules about segments of the pins' axes
/// (reaching 4 (R + r) either way from the feet of the common normal, so
/// that the nearest points lie on both sides, never at an end).
fn parry_pins(
    moving: (&Vector3<f64>, &Vector3<f64>, f64),
    fixed: (&Vector3<f64>, &Vector3<f64>, f64),
) -> ContactGeometry {
    let reach = 4.0 * (moving.2 + fixed.2);
    let capsule = |(a, d, r): (&Vector3<f64>, &Vector3<f64>, f64)| {
        let v = |p: Vector3<f64>| Vector::new(p.x, p.y, p.z);
        Capsule::new(v(a - d * reach), v(a + d * reach), r)
    };
    let c =
        query::contact(&Pose::IDENTITY, &capsule(fixed), &Pose::IDENTITY, &capsule(moving), 1.0)
            .expect("parry supports capsules")
            .expect("within the prediction distance");
    let v = |p: Vector| Vector3::new(p.x, p.y, p.z);
    ContactGeometry { gap: c.dist, normal: v(c.normal1), point: v((c.point1 + c.point2) * 0.5) }
}

#[test]
fn crossed_pins_are_parrys_capsules() {
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let mut worst = [0.0f64; 3];
    for _ in 0..CASES {
        let (fixed_direction, fixed_point) = (unit(&mut rng), placed(&mut rng));
        let fixed_radius = rng.random_range(0.001..0.005);
        let radius = rng.random_range(0.003..0.005);
        let gap = separation(&mut rng);
        // A common normal across the fixed pin, and a moving axis across
        // the normal at 20 to 90 degrees to the fixed one.
        let n = across(&mut rng, &fixed_direction);
        let angle = rng.random_range(20f64..90.0).to_radians();
        let side = n.cross(&fixed_direction);
        let direction = fixed_direction * angle.cos() + side * angle.sin();
        let foot = fixed_point + fixed_direction * rng.random_range(-0.01..0.01);
        let moving_foot = foot + n * (fixed_radius + radius + gap);
        let axis_point = moving_foot + direction * rng.random_range(-0.01..0.01);
        let surface = SurfaceGeometry::Cylinder {
            axis_point: fixed_point,
            direction: fixed_direction,
            radius: fixed_radius,
        };
        let ours = pin_contact(&surface, &axis_point, &direction, radius);
        let reference = parry_pins(
            (&axis_point, &direction, radius),
            (&fixed_point, &fixed_direction, fixed_radius),
        );
        let d = [
            (ours.gap - reference.gap).abs(),
            (ours.point - reference.point).norm(),
            (ours.normal - reference.normal).norm(),
        ];
        // parry's capsule pair goes through GJK/EPA (at nanometre gaps its
        // error reaches 7e-11 m in the gap, 1.4e-6 m in the points and 1.4e-8
        // in the normal), so it checks only the conventions (sign of the gap,
        // direction of the normal); the exact reference is the construction:
        // gap, normal n and the point midway between the surfaces on the
        // common normal, within the rounding of 0.04 m positions.
        assert!(
            d[0] <= 1e-10 && d[2] <= 1e-6,
            "{surface:?} pin {axis_point} {direction} r {radius}: {ours:?} vs parry {reference:?}"
        );
        let placed_point = foot + n * (fixed_radius + 0.5 * gap);
        assert!(
            (ours.gap - gap).abs() <= 2e-15
                && (ours.normal - n).norm() <= 2e-14
                && (ours.point - placed_point).norm() <= 1e-15,
            "{ours:?} vs the placed gap {gap}, normal {n}, point {placed_point}"
        );
        for k in 0..3 {
            worst[k] = worst[k].max(d[k]);
        }
    }
    println!(
        "crossed pins: largest difference from parry (GJK): gap {:.1e} m, point {:.1e} m, normal {:.1e}",
        worst[0], worst[1], worst[2]
    );
}
