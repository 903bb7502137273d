//! Hand-written SVG drawings of a coupling at its nominal seating.
//!
//! * The layout, seen from the top (x right, y up): moving balls, fixed
//!   elements, contact points (numbered in the order of `--mu`), the
//!   evaluation points and the preload point.
//! * Per ball, a close-up from the top and a side view along the ball's
//!   radial direction e_r (horizontal axis s = e_z x e_r, z up; for a ball
//!   on the axis, x): the ball, its fixed elements, the contact points, the
//!   contact normals (unit length) and the seated contact forces on the
//!   moving half, N n + T, to one force scale per coupling (a force bar shows
//!   it).
//!
//! Lengths are to scale within each drawing (a length bar shows it). Fixed
//! elements are schematic where their true extent is unbounded: a plane as
//! a segment (a square patch seen face on), a pin as a band (a circle seen
//! end on), a fixed ball as a circle.

use std::fmt::Write;

use nalgebra::Vector3;

use super::svg::{Shape, bounds, svg};
use crate::assembly::Coupling;
use crate::report::preload::force_text;
use crate::scene::{Preload, SurfaceGeometry};
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
        Proj {
            u: Vector3::x(),
            v: Vector3::y(),
        }
    }
    /// Looking along the radial direction of a ball at `c`.
    fn along_radius(c: &Vector3<f64>) -> Self {
        let r = Vector3::new(c.x, c.y, 0.0);
        let u = if r.norm() > 1e-12 {
            Vector3::z().cross(&r).normalize()
        } else {
            Vector3::x()
        };
        Proj { u, v: Vector3::z() }
    }
    fn p(&self, p: &Vector3<f64>) -> (f64, f64) {
        (p.dot(&self.u), p.dot(&self.v))
    }
}

fn force_vector(k: &ContactResult) -> Vector3<f64> {
    Vector3::from(k.normal) * k.normal_force_n + Vector3::from(k.tangential_force)
}

/// The layout and the close-ups of every ball, with the legend.
pub fn coupling_views(id: &str, c: &Coupling, s: &Seating) -> String {
    let r = c.balls.iter().map(|b| b.radius).fold(0.0, f64::max);
    let fmax = s
        .contacts
        .iter()
        .map(|k| force_vector(k).norm())
        .fold(0.0, f64::max);
    // The longest contact force is drawn 1.2 ball radii long.
    let scale = if fmax > 0.0 { 1.2 * r / fmax } else { 0.0 };
    let mut out = String::from("<div class=\"views\">\n");
    let layout = svg(
        &format!("{id}-layout"),
        460.0,
        &layout_shapes(c, s),
        None,
        None,
    );
    let _ = writeln!(
        out,
        "<figure data-check=\"drawing\" id=\"{id}-layout\">{layout}<figcaption>layout, top view (x right, y up)</figcaption></figure>"
    );
    out.push_str("</div>\n<div class=\"balls\">\n");
    // Every close-up at one scale: the largest extent of any of them.
    let views: Vec<(usize, &str, Vec<Shape>)> = c
        .balls
        .iter()
        .enumerate()
        .flat_map(|(b, ball)| {
            let centre = s.pose.apply(&ball.centre);
            [("top", Proj::top()), ("side", Proj::along_radius(&centre))]
                .into_iter()
                .map(move |(tag, proj)| (b, tag, ball_shapes(c, s, b, proj, scale)))
        })
        .collect();
    let span = views
        .iter()
        .map(|(_, _, sh)| {
            let (x0, y0, x1, y1) = bounds(sh);
            (x1 - x0).max(y1 - y0)
        })
        .fold(0.0, f64::max);
    for (b, tag, shapes) in &views {
        if *tag == "top" {
            let _ = write!(out, "<div class=\"ball\">");
        }
        let fid = format!("{id}-b{}-{tag}", b + 1);
        let drawn = svg(&fid, 300.0, shapes, Some((scale, fmax)), Some(span));
        let what = if *tag == "top" {
            "top view"
        } else {
            "side view along e_r"
        };
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
        "<p class=\"note\">Nominal seating (nominal μ, quasi-static). <span style=\"color:{BALL}\">Blue</span>: moving balls; <span style=\"color:{FIXED}\">grey</span>: fixed elements; <span style=\"color:{CONTACT}\">red dots</span>: contact points, numbered in the order of --mu; <span style=\"color:{NORMAL}\">green</span>: contact normals (unit length, not to scale); <span style=\"color:{FORCE}\">orange</span>: seated contact force on the moving half, N n + T, to the force bar's scale (largest {fmax:.3} N); <span style=\"color:{PRELOAD}\">pink</span>: {}.</p>",
        preload_note(&c.scene.preload)
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

fn layout_shapes(c: &Coupling, s: &Seating) -> Vec<Shape> {
    let proj = Proj::top();
    let p = |v: &Vector3<f64>| proj.p(v);
    let r = c.balls.iter().map(|b| b.radius).fold(0.0, f64::max);
    let mut out: Vec<Shape> = c
        .contacts
        .iter()
        .flat_map(|k| fixed_element(proj, &k.surface, r))
        .collect();
    for (i, b) in c.balls.iter().enumerate() {
        let centre = p(&s.pose.apply(&b.centre));
        out.push(Shape::Circle {
            c: centre,
            r: b.radius,
            stroke: BALL,
            fill: "#cfe6f5",
        });
        out.push(Shape::Text {
            at: (centre.0, centre.1 + 1.6 * b.radius),
            text: format!("ball {}", i + 1),
            colour: BALL,
        });
    }
    for k in &s.contacts {
        out.push(Shape::Dot {
            c: p(&Vector3::from(k.point_m)),
            colour: CONTACT,
        });
    }
    let forces = &c.scene.preload.forces;
    for (i, f) in forces.iter().enumerate() {
        let pl = p(&f.point);
        out.push(Shape::Dot {
            c: pl,
            colour: PRELOAD,
        });
        out.push(Shape::Text {
            at: (pl.0 + 1.3 * r, pl.1 + 0.9 * r),
            text: match forces.len() {
                1 => "F_p".into(),
                _ => format!("F_{}", i + 1),
            },
            colour: PRELOAD,
        });
    }
    for e in &c.scene.evaluation_points {
        let q = p(&s.pose.apply(&e.position));
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
        out.push(Shape::Text {
            at: (q.0, q.1 - 1.2 * r),
            text: e.name.clone(),
            colour: "#000",
        });
    }
    out
}

/// Ball `b`, its fixed elements and contacts, normals and forces.
fn ball_shapes(c: &Coupling, s: &Seating, b: usize, proj: Proj, scale: f64) -> Vec<Shape> {
    let p = |v: &Vector3<f64>| proj.p(v);
    let ball = &c.balls[b];
    let r = ball.radius;
    let mut out = Vec::new();
    let mine: Vec<usize> = (0..c.contacts.len())
        .filter(|&i| c.contacts[i].ball == b)
        .collect();
    for &i in &mine {
        out.extend(fixed_element(proj, &c.contacts[i].surface, r));
    }
    // Crossed pins: the moving pins (a band along each axis, or a circle
    // seen end-on) instead of the ball.
    let pins: Vec<_> = (mine.iter())
        .filter_map(|&i| c.contacts[i].axis.map(|a| (&c.contacts[i], a)))
        .collect();
    if pins.is_empty() {
        out.push(Shape::Circle {
            c: p(&s.pose.apply(&ball.centre)),
            r,
            stroke: BALL,
            fill: "#cfe6f5",
        });
    }
    for (k, axis) in pins {
        let (at, d) = (s.pose.apply(&k.centre), s.pose.rotation * axis);
        out.push(match rod_ends(proj, &at, &d, 1.6 * r, k.radius) {
            None => Shape::Circle {
                c: p(&at),
                r: k.radius,
                stroke: BALL,
                fill: "#cfe6f5",
            },
            Some((a, b)) => Shape::Line {
                a,
                b,
                width_m: 2.0 * k.radius,
                colour: "#cfe6f5",
            },
        });
    }
    for &i in &mine {
        let k = &s.contacts[i];
        let at = Vector3::from(k.point_m);
        let n = Vector3::from(k.normal);
        out.push(Shape::Arrow {
            a: p(&at),
            b: p(&(at + n * 0.8 * r)),
            colour: NORMAL,
        });
        out.push(Shape::Arrow {
            a: p(&at),
            b: p(&(at + force_vector(k) * scale)),
            colour: FORCE,
        });
        out.push(Shape::Dot {
            c: p(&at),
            colour: CONTACT,
        });
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
    let (a, b) = (
        proj.p(&(at - direction * reach)),
        proj.p(&(at + direction * reach)),
    );
    ((a.0 - b.0).hypot(a.1 - b.1) >= 0.5 * radius).then_some((a, b))
}

fn fixed_element(proj: Proj, g: &SurfaceGeometry, r: f64) -> Vec<Shape> {
    let p = |v: &Vector3<f64>| proj.p(v);
    let grey = "#c6ccd3";
    match *g {
        SurfaceGeometry::Sphere { centre, radius } => {
            vec![Shape::Circle {
                c: p(&centre),
                r: radius,
                stroke: FIXED,
                fill: "#eaeef2",
            }]
        }
        SurfaceGeometry::Cylinder {
            axis_point,
            direction,
            radius,
        }
        | SurfaceGeometry::ConcaveCylinder {
            axis_point,
            direction,
            radius,
        } => {
            // A gothic-arch flank is drawn as the outline of its cylinder.
            let concave = matches!(g, SurfaceGeometry::ConcaveCylinder { .. });
            vec![
                match rod_ends(proj, &axis_point, &direction, 1.6 * r, radius) {
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
                },
            ]
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
