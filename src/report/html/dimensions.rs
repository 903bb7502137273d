//! The dimensions of a coupling drawing ([`super::drawing`]), with values
//! from the assembly: the circle of ball centres (layout), each ball's
//! diameter and a V-groove's opening angle (side view along e_r). Lengths in
//! mm, angles in degrees, to at most 4 significant digits.

use nalgebra::Vector3;

use super::svg::{FIXED, Shape};
use crate::assembly::Coupling;
use crate::report::sweep::text::short;

type P = (f64, f64);

fn sub(a: P, b: P) -> P {
    (a.0 - b.0, a.1 - b.1)
}

fn along(a: P, d: P, t: f64) -> P {
    (a.0 + t * d.0, a.1 + t * d.1)
}

fn unit(d: P) -> P {
    let n = d.0.hypot(d.1);
    (d.0 / n, d.1 / n)
}

/// The circle through three points (centre, radius); None when they are
/// (nearly) on one line.
fn circumcircle(a: P, b: P, c: P) -> Option<(P, f64)> {
    let (b, c) = (sub(b, a), sub(c, a));
    let d = 2.0 * (b.0 * c.1 - b.1 * c.0);
    let scale = b.0.hypot(b.1) * c.0.hypot(c.1);
    if d.abs() <= 1e-9 * scale {
        return None;
    }
    let (bb, cc) = (b.0 * b.0 + b.1 * b.1, c.0 * c.0 + c.1 * c.1);
    let u = ((c.1 * bb - b.1 * cc) / d, (b.0 * cc - c.0 * bb) / d);
    Some((along(a, u, 1.0), u.0.hypot(u.1)))
}

/// The circle of the ball centres (through the first three, seen from the
/// top) dashed, and its diameter dimensioned across it, perpendicular to
/// the direction of ball 1 (between the balls of a three-ball coupling).
pub fn ball_circle(c: &Coupling) -> Vec<Shape> {
    let p: Vec<P> = c.balls.iter().map(|b| (b.centre.x, b.centre.y)).collect();
    let [a, b, d, ..] = p.as_slice() else {
        return Vec::new();
    };
    let Some((o, r)) = circumcircle(*a, *b, *d) else {
        return Vec::new();
    };
    let up = unit(sub(*a, o));
    let u = (up.1, -up.0);
    vec![
        Shape::Ring { c: o, r },
        Shape::Dim {
            a: along(o, u, -r),
            b: along(o, u, r),
            label: along(along(o, u, 0.5 * r), up, 0.06 * r),
            text: format!("Ø{} mm", short(2e3 * r)),
        },
    ]
}

/// A ball's diameter, dimensioned above it in a side view (ball centre
/// `o`, radius `r`), with its extension lines.
pub fn ball_diameter(o: P, r: f64) -> Vec<Shape> {
    let y = o.1 + 1.3 * r;
    let ext =
        |x: f64| Shape::Line { a: (x, o.1), b: (x, y + 0.1 * r), width_m: 0.0, colour: FIXED };
    vec![
        ext(o.0 - r),
        ext(o.0 + r),
        Shape::Dim {
            a: (o.0 - r, y),
            b: (o.0 + r, y),
            label: (o.0, y + 0.3 * r),
            text: format!("Ø{} mm", short(2e3 * r)),
        },
    ]
}

/// The opening angle of a V-groove, 180° less the angle between its two
/// contact normals `n` (3-D, unit), dimensioned at the vertex where the two
/// flanks (through the projected contact points `p`, normal to the projected
/// normals `q`) meet; nothing unless both normals lie in the view (their
/// projections at least 0.95 long), `r`: the ball's radius.
pub fn groove_angle(p: [P; 2], q: [P; 2], n: [Vector3<f64>; 2], r: f64) -> Vec<Shape> {
    if q.iter().any(|q| q.0.hypot(q.1) < 0.95) {
        return Vec::new();
    }
    // The flanks' directions t_i; p_0 + s t_0 = p_1 + w t_1.
    let t = q.map(|q| unit((-q.1, q.0)));
    let det = t[1].0 * t[0].1 - t[0].0 * t[1].1;
    if det.abs() < 1e-6 {
        return Vec::new();
    }
    let e = sub(p[1], p[0]);
    let s = (t[1].0 * e.1 - t[1].1 * e.0) / det;
    let v = along(p[0], t[0], s);
    let to = p.map(|p| sub(p, v));
    if to.iter().any(|d| d.0.hypot(d.1) < 1e-3 * r) {
        return Vec::new();
    }
    let (mut a0, mut a1) = (to[0].1.atan2(to[0].0), to[1].1.atan2(to[1].0));
    if (a1 - a0).rem_euclid(std::f64::consts::TAU) > std::f64::consts::PI {
        std::mem::swap(&mut a0, &mut a1);
    }
    let a1 = a0 + (a1 - a0).rem_euclid(std::f64::consts::TAU);
    let mid = 0.5 * (a0 + a1);
    let flank = |d: P| Shape::Line {
        a: v,
        b: along(v, unit(d), d.0.hypot(d.1)),
        width_m: 0.0,
        colour: FIXED,
    };
    let opening = 180.0 - n[0].dot(&n[1]).clamp(-1.0, 1.0).acos().to_degrees();
    vec![
        flank(to[0]),
        flank(to[1]),
        Shape::Angle {
            c: v,
            r: 0.35 * r,
            from: a0,
            to: a1,
            label: along(v, (mid.cos(), mid.sin()), -0.45 * r),
            text: format!("{opening:.1}°"),
        },
    ]
}
