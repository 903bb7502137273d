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

use super::page::escape;
use crate::assembly::Coupling;
use crate::scene::SurfaceGeometry;
use crate::solve::{ContactResult, Seating};

const BALL: &str = "#0072b2";
const FIXED: &str = "#8c959f";
const CONTACT: &str = "#d55e00";
const NORMAL: &str = "#009e73";
const FORCE: &str = "#e69f00";
const PRELOAD: &str = "#cc79a7";

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

/// Primitives in projected world coordinates (m).
enum Shape {
    Circle {
        c: (f64, f64),
        r: f64,
        stroke: &'static str,
        fill: &'static str,
    },
    Line {
        a: (f64, f64),
        b: (f64, f64),
        width_m: f64,
        colour: &'static str,
    },
    Arrow {
        a: (f64, f64),
        b: (f64, f64),
        colour: &'static str,
    },
    Dot {
        c: (f64, f64),
        colour: &'static str,
    },
    Text {
        at: (f64, f64),
        text: String,
        colour: &'static str,
    },
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
    let layout = svg(&format!("{id}-layout"), 460.0, &layout_shapes(c, s), None);
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
        let drawn = svg_at(&fid, 300.0, shapes, Some((scale, fmax)), Some(span));
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
        "<p class=\"note\">Nominal seating (nominal μ, quasi-static). <span style=\"color:{BALL}\">Blue</span>: moving balls; <span style=\"color:{FIXED}\">grey</span>: fixed elements; <span style=\"color:{CONTACT}\">red dots</span>: contact points, numbered in the order of --mu; <span style=\"color:{NORMAL}\">green</span>: contact normals (unit length, not to scale); <span style=\"color:{FORCE}\">orange</span>: seated contact force on the moving half, N n + T, to the force bar's scale (largest {fmax:.3} N); <span style=\"color:{PRELOAD}\">pink</span>: preload point, F_p = {:.3} N along ({:.3}, {:.3}, {:.3}).</p>",
        c.scene.preload.force,
        // + 0.0 prints -0 as 0.
        c.scene.preload.direction.x + 0.0,
        c.scene.preload.direction.y + 0.0,
        c.scene.preload.direction.z + 0.0
    );
    out
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
    let pl = p(&c.scene.preload.point);
    out.push(Shape::Dot {
        c: pl,
        colour: PRELOAD,
    });
    out.push(Shape::Text {
        at: (pl.0 + 1.3 * r, pl.1 + 0.9 * r),
        text: "F_p".into(),
        colour: PRELOAD,
    });
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
    out.push(Shape::Circle {
        c: p(&s.pose.apply(&ball.centre)),
        r,
        stroke: BALL,
        fill: "#cfe6f5",
    });
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
        } => {
            let (pa, pb) = (
                p(&(axis_point - direction * 1.6 * r)),
                p(&(axis_point + direction * 1.6 * r)),
            );
            if (pa.0 - pb.0).hypot(pa.1 - pb.1) < 0.5 * radius {
                vec![Shape::Circle {
                    c: p(&axis_point),
                    r: radius,
                    stroke: FIXED,
                    fill: "#eaeef2",
                }]
            } else {
                vec![Shape::Line {
                    a: pa,
                    b: pb,
                    width_m: 2.0 * radius,
                    colour: grey,
                }]
            }
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

/// Bounds (x0, y0, x1, y1) of the shapes, with a margin.
fn bounds(shapes: &[Shape]) -> (f64, f64, f64, f64) {
    let mut b = (
        f64::INFINITY,
        f64::INFINITY,
        f64::NEG_INFINITY,
        f64::NEG_INFINITY,
    );
    let mut add = |(x, y): (f64, f64), r: f64| {
        b = (
            b.0.min(x - r),
            b.1.min(y - r),
            b.2.max(x + r),
            b.3.max(y + r),
        );
    };
    for s in shapes {
        match s {
            Shape::Circle { c, r, .. } => add(*c, *r),
            Shape::Line { a, b, width_m, .. } => {
                add(*a, width_m / 2.0);
                add(*b, width_m / 2.0);
            }
            Shape::Arrow { a, b, .. } => {
                add(*a, 0.0);
                add(*b, 0.0);
            }
            Shape::Dot { c, .. } | Shape::Text { at: c, .. } => add(*c, 0.0),
        }
    }
    let m = 0.1 * (b.2 - b.0).max(b.3 - b.1).max(1e-9);
    (b.0 - m, b.1 - m, b.2 + m, b.3 + m)
}

fn svg(id: &str, width: f64, shapes: &[Shape], forces: Option<(f64, f64)>) -> String {
    svg_at(id, width, shapes, forces, None)
}

/// The SVG of `shapes`, `width` px wide, with a length bar and, given
/// `(scale [m/N], largest force [N])`, a force bar; `span` [m]: a square
/// window of that size around the shapes' centre (same scale for several
/// drawings), else their own bounds.
fn svg_at(
    id: &str,
    width: f64,
    shapes: &[Shape],
    forces: Option<(f64, f64)>,
    span: Option<f64>,
) -> String {
    let (mut x0, mut y0, mut x1, mut y1) = bounds(shapes);
    if let Some(w) = span {
        let (cx, cy) = ((x0 + x1) / 2.0, (y0 + y1) / 2.0);
        (x0, y0, x1, y1) = (cx - w / 2.0, cy - w / 2.0, cx + w / 2.0, cy + w / 2.0);
    }
    let k = width / (x1 - x0).max(y1 - y0);
    let bar_room = 34.0;
    let height = (y1 - y0) * k + bar_room;
    let tx = |x: f64| (x - x0) * k;
    let ty = |y: f64| (y1 - y) * k;
    let mut o = format!(
        "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {:.1} {height:.1}\" width=\"{:.0}\" height=\"{height:.0}\" font-family=\"sans-serif\"><defs>",
        (x1 - x0) * k,
        (x1 - x0) * k
    );
    for (name, col) in [("n", NORMAL), ("f", FORCE)] {
        let _ = write!(
            o,
            "<marker id=\"{id}-{name}\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"6\" markerHeight=\"6\" orient=\"auto\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"{col}\"/></marker>"
        );
    }
    o.push_str("</defs><rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n");
    for sh in shapes {
        match sh {
            Shape::Circle { c, r, stroke, fill } => {
                let _ = writeln!(
                    o,
                    "<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"{:.2}\" fill=\"{fill}\" stroke=\"{stroke}\" stroke-width=\"1.5\"/>",
                    tx(c.0),
                    ty(c.1),
                    r * k
                );
            }
            Shape::Line {
                a,
                b,
                width_m,
                colour,
            } => {
                let w = (width_m * k).max(2.0);
                let _ = writeln!(
                    o,
                    "<line x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" stroke=\"{colour}\" stroke-width=\"{w:.2}\"/>",
                    tx(a.0),
                    ty(a.1),
                    tx(b.0),
                    ty(b.1)
                );
            }
            Shape::Arrow { a, b, colour } => {
                let m = if *colour == NORMAL { "n" } else { "f" };
                let _ = writeln!(
                    o,
                    "<line x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" stroke=\"{colour}\" stroke-width=\"2\" marker-end=\"url(#{id}-{m})\"/>",
                    tx(a.0),
                    ty(a.1),
                    tx(b.0),
                    ty(b.1)
                );
            }
            Shape::Dot { c, colour } => {
                let _ = writeln!(
                    o,
                    "<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"3.5\" fill=\"{colour}\"/>",
                    tx(c.0),
                    ty(c.1)
                );
            }
            Shape::Text { at, text, colour } => {
                let _ = writeln!(
                    o,
                    "<text x=\"{:.2}\" y=\"{:.2}\" font-size=\"12\" fill=\"{colour}\" text-anchor=\"middle\" dominant-baseline=\"middle\">{}</text>",
                    tx(at.0),
                    ty(at.1),
                    escape(text)
                );
            }
        }
    }
    let w = (x1 - x0) * k;
    let y = height - bar_room / 2.0;
    let len_m = round_down(0.3 * w / k);
    bar(
        &mut o,
        8.0,
        y,
        len_m * k,
        &format!("{} mm", len_m * 1e3),
        "#000",
    );
    if let Some((scale, fmax)) = forces.filter(|(s, f)| *s > 0.0 && *f > 0.0) {
        let f = round_down(0.8 * fmax);
        bar(
            &mut o,
            w / 2.0 + 4.0,
            y,
            f * scale * k,
            &format!("{f} N"),
            FORCE,
        );
    }
    o.push_str("</svg>");
    o
}

/// The largest of 1, 2, 5 times a power of ten not above `v`.
fn round_down(v: f64) -> f64 {
    let p = 10f64.powf(v.log10().floor());
    [5.0, 2.0, 1.0]
        .iter()
        .map(|m| m * p)
        .find(|c| *c <= v)
        .unwrap_or(p)
}

fn bar(o: &mut String, x: f64, y: f64, w: f64, label: &str, col: &str) {
    let _ = writeln!(
        o,
        "<line x1=\"{x:.1}\" y1=\"{y:.1}\" x2=\"{:.1}\" y2=\"{y:.1}\" stroke=\"{col}\" stroke-width=\"3\"/><text x=\"{:.1}\" y=\"{y:.1}\" font-size=\"12\" fill=\"{col}\" dominant-baseline=\"middle\">{}</text>",
        x + w,
        x + w + 5.0,
        escape(label)
    );
}
