//! Hand-written SVG drawings of a coupling at its nominal seating.
//!
//! * The layout, seen from the top (x right, y up): moving balls, fixed
//!   elements, contact points (numbered in the order of `--mu`), the
//!   evaluation points and the preload point; the circle of ball centres
//!   with its diameter dimensioned.
//! * Per ball, a close-up from the top and a side view along the axis of
//!   its V (a ball with two contacts) or else along its radial direction
//!   e_r (horizontal axis s = e_z x e_r, z up; for a ball on the axis, x):
//!   the ball, its fixed elements, the contact points, the contact normals
//!   (unit length) and the seated contact forces on the moving half,
//!   N n + T, to one force scale per coupling (a force bar shows it); in
//!   the side view the ball's diameter and the V's opening angle
//!   dimensioned ([`super::dimensions`]).
//!
//! Lengths are to scale within each drawing (a length bar shows it). Fixed
//! elements are schematic where their true extent is unbounded: a plane as
//! a segment (a square patch seen face on), a pin as a band (a circle seen
//! end on), a fixed ball as a circle.

use std::fmt::Write;

use nalgebra::Vector3;

use super::dimensions::{ball_circle, ball_diameter, groove_angle};
use super::svg::{Shape, bounds, svg};
use crate::assembly::Coupling;
use crate::report::coupling::preload::force_text;
use crate::scene::{Preload, Scene, SurfaceGeometry};
use crate::solve::{ContactResult, Seating};

use super::svg::{BALL, CONTACT, FIXED, FORCE, NORMAL, PRELOAD};

/// A projection onto the plane of two orthonormal axes (horizontal, up).
#[derive(Clone, Copy)]
struct Proj {
    u: Vector3<f64>,
    v: Vector3<f64>,
}

impl Proj {
    fn top() -> Self {
        Proj { u: Vector3::x(), v: Vector3::y() }
    }
    /// Looking along the radial direction of a ball at `c`.
    fn along_radius(c: &Vector3<f64>) -> Self {
        let r = Vector3::new(c.x, c.y, 0.0);
        let u = if r.norm() > 1e-12 { Vector3::z().cross(&r).normalize() } else { Vector3::x() };
        Proj { u, v: Vector3::z() }
    }
    /// The side view of ball `b`: along the axis of its V (the cross
    /// product of its two contact normals, when horizontal), where the V
    /// shows its true opening; else along e_r. With the caption.
    fn side(c: &Coupling, s: &Seating, b: usize) -> (Self, &'static str) {
        let centre = s.pose().apply(&c.balls[b].centre);
        if let [i, j] = contacts_of(c, b)[..] {
            let (i, j) = (&s.contacts[i], &s.contacts[j]);
            let g = Vector3::from(i.normal).cross(&Vector3::from(j.normal));
            let h = Vector3::new(g.x, g.y, 0.0);
            if g.norm() > 1e-6 && h.norm() > 0.95 * g.norm() {
                let h = if h.dot(&centre) < 0.0 { -h } else { h };
                let u = Vector3::z().cross(&h).normalize();
                return (Proj { u, v: Vector3::z() }, "side view along the groove");
            }
        }
        (Proj::along_radius(&centre), "side view along e_r")
    }
    fn p(&self, p: &Vector3<f64>) -> (f64, f64) {
        (p.dot(&self.u), p.dot(&self.v))
    }
}

fn force_vector(k: &ContactResult) -> Vector3<f64> {
    Vector3::from(k.normal) * k.normal_force_n + Vector3::from(k.tangential_force)
}

/// The layout and the close-ups of every ball, with the legend.
pub fn coupling_views(id: &str, (scene, c): (&Scene, &Coupling), s: &Seating) -> String {
    let r = c.balls.iter().map(|b| b.radius).fold(0.0, f64::max);
    let fmax = s.contacts.iter().map(|k| force_vector(k).norm()).fold(0.0, f64::max);
    // The longest contact force is drawn 1.2 ball radii long.
    let scale = if fmax > 0.0 { 1.2 * r / fmax } else { 0.0 };
    let mut out = String::from("<div class=\"views\">\n");
    let layout = svg(&format!("{id}-layout"), 640.0, &layout_shapes(scene, c, s), None, None);
    let _ = writeln!(
        out,
        "<figure data-check=\"drawing\" id=\"{id}-layout\">{layout}<figcaption>layout, top view (x right, y up)</figcaption></figure>"
    );
    out.push_str("</div>\n<div class=\"balls\">\n");
    // Every close-up at one scale: the largest extent of any of them.
    let views: Vec<(usize, &str, &str, Vec<Shape>)> = (0..c.balls.len())
        .flat_map(|b| {
            let (side, along) = Proj::side(c, s, b);
            [("top", "top view", Proj::top()), ("side", along, side)].into_iter().map(
                move |(tag, what, proj)| {
                    let mut shapes = ball_shapes(c, s, b, proj, scale);
                    if tag == "side" {
                        shapes.extend(side_dimensions(c, s, b, proj));
                    }
                    (b, tag, what, shapes)
                },
            )
        })
        .collect();
    let span = views
        .iter()
        .map(|(_, _, _, sh)| {
            let (x0, y0, x1, y1) = bounds(sh);
            (x1 - x0).max(y1 - y0)
        })
        .fold(0.0, f64::max);
    for (b, tag, what, shapes) in &views {
        if *tag == "top" {
            let _ = write!(out, "<div class=\"ball\">");
        }
        let fid = format!("{id}-b{}-{tag}", b + 1);
        let drawn = svg(&fid, 280.0, shapes, Some((scale, fmax)), Some(span));
        let _ = write!(
            out,
            "<figure data-check=\"drawing\" id=\"{fid}\">{drawn}<figcaption>ball {}: {what}</figcaption></figure>",
            b + 1
        );
        if *tag == "side" {
            out.push_str("</div>\n");
        }
    }
    out.push_str("</div>\n");
    let _ = writeln!(
        out,
        "<p class=\"note\">Nominal seating (nominal μ, quasi-static). <span style=\"color:{BALL}\">Blue</span>: moving balls; <span style=\"color:{FIXED}\">grey</span>: fixed elements; <span style=\"color:{CONTACT}\">red dots</span>: contact points, numbered in contact order; <span style=\"color:{NORMAL}\">green</span>: contact normals (unit length, not to scale); <span style=\"color:{FORCE}\">orange</span>: seated contact force on the moving half, N n + T, to the force bar's scale (largest {fmax:.3} N); <span style=\"color:{PRELOAD}\">pink</span>: {}.</p>",
        preload_note(&scene.preload)
    );
    out
}

/// The preload in the drawing's note: the point of a single force, or
/// each force's point F_i.
fn preload_note(p: &Preload) -> String {
    match p.forces.as_slice() {
        [f] => format!(
            "preload point, F_p = {:.3} N along ({:.3}, {:.3}, {:.3})",
            f.force,
            // + 0.0 prints -0 as 0.
            f.direction.x + 0.0,
            f.direction.y + 0.0,
            f.direction.z + 0.0
        ),
        forces => {
            let each = forces.iter().enumerate();
            let each = each.map(|(i, f)| format!("F_{} = {}", i + 1, force_text(f)));
            format!("preload points, {}", each.collect::<Vec<_>>().join("; "))
        }
    }
}

fn layout_shapes(scene: &Scene, c: &Coupling, s: &Seating) -> Vec<Shape> {
    let proj = Proj::top();
    let p = |v: &Vector3<f64>| proj.p(v);
    let r = c.balls.iter().map(|b| b.radius).fold(0.0, f64::max);
    let mut out = ball_circle(c);
    out.extend((c.contacts.iter()).flat_map(|k| fixed_element(proj, &k.surface, r)));
    let centres: Vec<Vector3<f64>> = c.balls.iter().map(|b| s.pose().apply(&b.centre)).collect();
    for (i, (b, centre)) in c.balls.iter().zip(&centres).enumerate() {
        out.push(Shape::Circle { c: p(centre), r: b.radius, stroke: BALL, fill: "#cfe6f5" });
        // Outside the coupling, clear of the fixed elements.
        out.push(Shape::Text {
            at: p(&(centre + outward(centre) * 2.6 * r)),
            text: format!("ball {}", i + 1),
            colour: BALL,
        });
    }
    for k in &s.contacts {
        out.push(Shape::Dot { c: p(&Vector3::from(k.point_m)), colour: CONTACT });
    }
    let forces = &scene.preload.forces;
    for (i, f) in forces.iter().enumerate() {
        let pl = p(&f.point);
        out.push(Shape::Dot { c: pl, colour: PRELOAD });
        out.push(Shape::Text {
            at: (pl.0 + 1.3 * r, pl.1 + 0.9 * r),
            text: match forces.len() {
                1 => "F_p".into(),
                _ => format!("F_{}", i + 1),
            },
            colour: PRELOAD,
        });
    }
    for e in &scene.evaluation_points {
        let q = p(&s.pose().apply(&e.position));
        let d = 0.35 * r;
        out.push(Shape::Line {
            a: (q.0 - d, q.1 - d),
            b: (q.0 + d, q.1 + d),
            width_m: 0.0,
            colour: "#000",
        });
        out.push(Shape::Line {
            a: (q.0 - d, q.1 + d),
            b: (q.0 + d, q.1 - d),
            width_m: 0.0,
            colour: "#000",
        });
        // A point at a ball is labelled inside the coupling, others below.
        let at = s.pose().apply(&e.position);
        let near = centres.iter().any(|b| (b - at).xy().norm() < 1.5 * r);
        out.push(Shape::Text {
            at: match near {
                true => p(&(at - outward(&at) * 2.6 * r)),
                false => (q.0, q.1 - 1.2 * r),
            },
            text: e.name.clone(),
            colour: "#000",
        });
    }
    out
}

/// The indices of the contacts of ball `b`.
fn contacts_of(c: &Coupling, b: usize) -> Vec<usize> {
    (0..c.contacts.len()).filter(|&i| c.contacts[i].ball == b).collect()
}

/// The horizontal unit vector from the axis to `p` (y off the axis).
fn outward(p: &Vector3<f64>) -> Vector3<f64> {
    let r = Vector3::new(p.x, p.y, 0.0);
    if r.norm() > 1e-12 { r.normalize() } else { Vector3::y() }
}

/// A side view's dimensions: the ball's diameter (not for crossed pins)
/// and, for a ball in a V of two contacts, the groove's opening angle.
fn side_dimensions(c: &Coupling, s: &Seating, b: usize, proj: Proj) -> Vec<Shape> {
    let mine = contacts_of(c, b);
    if mine.iter().any(|&i| c.contacts[i].axis.is_some()) {
        return Vec::new();
    }
    let r = c.balls[b].radius;
    let mut out = ball_diameter(proj.p(&s.pose().apply(&c.balls[b].centre)), r);
    if let [i, j] = mine[..] {
        let (ki, kj) = (&s.contacts[i], &s.contacts[j]);
        let n = [Vector3::from(ki.normal), Vector3::from(kj.normal)];
        let p = [ki, kj].map(|k| proj.p(&Vector3::from(k.point_m)));
        out.extend(groove_angle(p, n.map(|n| proj.p(&n)), n, r));
    }
    out
}

/// Ball `b`, its fixed elements and contacts, normals and forces.
fn ball_shapes(c: &Coupling, s: &Seating, b: usize, proj: Proj, scale: f64) -> Vec<Shape> {
    let p = |v: &Vector3<f64>| proj.p(v);
    let ball = &c.balls[b];
    let r = ball.radius;
    let mut out = Vec::new();
    let mine = contacts_of(c, b);
    for &i in &mine {
        out.extend(fixed_element(proj, &c.contacts[i].surface, r));
    }
    // Crossed pins: the moving pins (a band along each axis, or a circle
    // seen end-on) instead of the ball.
    let pins: Vec<_> =
        (mine.iter()).filter_map(|&i| c.contacts[i].axis.map(|a| (&c.contacts[i], a))).collect();
    if pins.is_empty() {
        out.push(Shape::Circle {
            c: p(&s.pose().apply(&ball.centre)),
            r,
            stroke: BALL,
            fill: "#cfe6f5",
        });
    }
    for (k, axis) in pins {
        let (at, d) = (s.pose().apply(&k.centre), s.pose().rotation * axis);
        out.push(match rod_ends(proj, &at, &d, 1.6 * r, k.radius) {
            None => Shape::Circle { c: p(&at), r: k.radius, stroke: BALL, fill: "#cfe6f5" },
            Some((a, b)) => Shape::Line { a, b, width_m: 2.0 * k.radius, colour: "#cfe6f5" },
        });
    }
    for &i in &mine {
        let k = &s.contacts[i];
        let at = Vector3::from(k.point_m);
        let n = Vector3::from(k.normal);
        out.push(Shape::Arrow { a: p(&at), b: p(&(at + n * 0.8 * r)), colour: NORMAL });
        out.push(Shape::Arrow { a: p(&at), b: p(&(at + force_vector(k) * scale)), colour: FORCE });
        out.push(Shape::Dot { c: p(&at), colour: CONTACT });
        out.push(Shape::Text {
            at: p(&(at - n * 0.3 * r)),
            text: format!("{}", i + 1),
            colour: CONTACT,
        });
    }
    out
}

/// The projected ends of a rod (a pin's axis) through `at` along the unit
/// `direction`, `reach` either way; `None` when it is seen end-on (its
/// projection shorter than half its `radius`), to be drawn as a circle.
fn rod_ends(
    proj: Proj,
    at: &Vector3<f64>,
    direction: &Vector3<f64>,
    reach: f64,
    radius: f64,
) -> Option<((f64, f64), (f64, f64))> {
    let (a, b) = (proj.p(&(at - direction * reach)), proj.p(&(at + direction * reach)));
    ((a.0 - b.0).hypot(a.1 - b.1) >= 0.5 * radius).then_some((a, b))
}

fn fixed_element(proj: Proj, g: &SurfaceGeometry, r: f64) -> Vec<Shape> {
    let p = |v: &Vector3<f64>| proj.p(v);
    let grey = "#c6ccd3";
    match *g {
        SurfaceGeometry::Sphere { centre, radius } => {
            vec![Shape::Circle { c: p(&centre), r: radius, stroke: FIXED, fill: "#eaeef2" }]
        }
        SurfaceGeometry::Cylinder { axis_point, direction, radius }
        | SurfaceGeometry::ConcaveCylinder { axis_point, direction, radius } => {
            // A gothic-arch flank is drawn as the outline of its cylinder.
            let concave = matches!(g, SurfaceGeometry::ConcaveCylinder { .. });
            vec![match rod_ends(proj, &axis_point, &direction, 1.6 * r, radius) {
                None => Shape::Circle {
                    c: p(&axis_point),
                    r: radius,
                    stroke: FIXED,
                    fill: if concave { "none" } else { "#eaeef2" },
                },
                Some((a, b)) => Shape::Line {
                    a,
                    b,
                    width_m: if concave { 0.0 } else { 2.0 * radius },
                    colour: if concave { FIXED } else { grey },
                },
            }]
        }
        SurfaceGeometry::Plane { point, normal } => {
            let (nx, ny) = p(&normal);
            let len = nx.hypot(ny);
            let (x, y) = p(&point);
            if len < 0.3 {
                let h = 0.9 * r;
                return vec![Shape::Line {
                    a: (x - h, y),
                    b: (x + h, y),
                    width_m: 2.0 * h,
                    colour: "#eaeef2",
                }];
            }
            let (tx, ty, h) = (-ny / len, nx / len, 1.3 * r);
            vec![Shape::Line {
                a: (x - h * tx, y - h * ty),
                b: (x + h * tx, y + h * ty),
                width_m: 0.0,
                colour: FIXED,
            }]
        }
    }
}
