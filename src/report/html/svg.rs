//! SVG primitives of the coupling drawings ([`super::drawing`]): shapes in
//! projected world coordinates (m), their bounds, and their rendering into
//! an SVG with a length bar and a force bar. Text labels are placed last,
//! each at the first position near its anchor where it overlaps no label
//! placed before it and stays inside the drawing ([`Labels`]).

use std::fmt::Write;

use crate::report::table::escape;

pub const BALL: &str = "#0072b2";
pub const FIXED: &str = "#8c959f";
pub const CONTACT: &str = "#d55e00";
pub const NORMAL: &str = "#009e73";
pub const FORCE: &str = "#e69f00";
pub const PRELOAD: &str = "#cc79a7";
/// Dimension lines and their values.
pub const DIM: &str = "#24292f";
/// Font size of every label [px of the SVG's own width].
pub const FONT: f64 = 13.0;

/// Primitives in projected world coordinates (m).
pub enum Shape {
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
    /// A dashed reference circle (e.g. the circle of ball centres).
    Ring {
        c: (f64, f64),
        r: f64,
    },
    /// A linear dimension from `a` to `b`, arrows at both ends, its value
    /// `text` next to the point `label`.
    Dim {
        a: (f64, f64),
        b: (f64, f64),
        label: (f64, f64),
        text: String,
    },
    /// An angle dimension: the arc about `c` of radius `r` from direction
    /// `from` to `to` [rad, counter-clockwise], its value at `label`.
    Angle {
        c: (f64, f64),
        r: f64,
        from: f64,
        to: f64,
        label: (f64, f64),
        text: String,
    },
}

/// Bounds (x0, y0, x1, y1) of the shapes, with a margin.
pub fn bounds(shapes: &[Shape]) -> (f64, f64, f64, f64) {
    let mut b = (f64::INFINITY, f64::INFINITY, f64::NEG_INFINITY, f64::NEG_INFINITY);
    let mut add = |(x, y): (f64, f64), r: f64| {
        b = (b.0.min(x - r), b.1.min(y - r), b.2.max(x + r), b.3.max(y + r));
    };
    for s in shapes {
        match s {
            Shape::Circle { c, r, .. } => add(*c, *r),
            Shape::Line { a, b, .. } | Shape::Arrow { a, b, .. } => {
                let w = if let Shape::Line { width_m, .. } = s { width_m / 2.0 } else { 0.0 };
                add(*a, w);
                add(*b, w);
            }
            Shape::Dot { c, .. } | Shape::Text { at: c, .. } => add(*c, 0.0),
            Shape::Ring { c, r } => add(*c, *r),
            Shape::Dim { a, b, label, .. } => {
                add(*a, 0.0);
                add(*b, 0.0);
                add(*label, 0.0);
            }
            Shape::Angle { c, r, label, .. } => {
                add(*c, *r);
                add(*label, 0.0);
            }
        }
    }
    let m = 0.1 * (b.2 - b.0).max(b.3 - b.1).max(1e-9);
    (b.0 - m, b.1 - m, b.2 + m, b.3 + m)
}

/// The SVG of `shapes`, `width` px wide, with a length bar and, given
/// `(scale [m/N], largest force [N])`, a force bar; `span` [m]: a square
/// window of that size around the shapes' centre (same scale for several
/// drawings), else their own bounds.
pub fn svg(
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
    for (name, col) in [("n", NORMAL), ("f", FORCE), ("d", DIM)] {
        let _ = write!(
            o,
            "<marker id=\"{id}-{name}\" viewBox=\"0 0 10 10\" refX=\"9\" refY=\"5\" markerWidth=\"6\" markerHeight=\"6\" orient=\"auto-start-reverse\"><path d=\"M0,0 L10,5 L0,10 z\" fill=\"{col}\"/></marker>"
        );
    }
    o.push_str("</defs><rect width=\"100%\" height=\"100%\" fill=\"#fff\"/>\n");
    for sh in shapes {
        emit(&mut o, sh, &tx, &ty, k, id);
    }
    let w = (x1 - x0) * k;
    let mut labels = Labels::new(w, height - bar_room);
    for sh in shapes {
        let (at, text, colour, class) = match sh {
            Shape::Text { at, text, colour } => (at, text, *colour, ""),
            Shape::Dim { label, text, .. } | Shape::Angle { label, text, .. } => {
                (label, text, DIM, " class=\"dim\"")
            }
            _ => continue,
        };
        let (x, y) = labels.place(tx(at.0), ty(at.1), text);
        let _ = writeln!(
            o,
            "<text x=\"{x:.2}\" y=\"{y:.2}\" font-size=\"{FONT}\" fill=\"{colour}\" text-anchor=\"middle\" dominant-baseline=\"middle\"{class}>{}</text>",
            escape(text)
        );
    }
    let y = height - bar_room / 2.0;
    let len_m = round_down(0.3 * w / k);
    bar(&mut o, 8.0, y, len_m * k, &format!("{} mm", len_m * 1e3), "#000");
    if let Some((scale, fmax)) = forces.filter(|(s, f)| *s > 0.0 && *f > 0.0) {
        let f = round_down(0.8 * fmax);
        bar(&mut o, w / 2.0 + 4.0, y, f * scale * k, &format!("{f} N"), FORCE);
    }
    o.push_str("</svg>");
    o
}

/// The largest of 1, 2, 5 times a power of ten not above `v`.
fn round_down(v: f64) -> f64 {
    let p = 10f64.powf(v.log10().floor());
    [5.0, 2.0, 1.0].iter().map(|m| m * p).find(|c| *c <= v).unwrap_or(p)
}

fn bar(o: &mut String, x: f64, y: f64, w: f64, label: &str, col: &str) {
    let _ = writeln!(
        o,
        "<line x1=\"{x:.1}\" y1=\"{y:.1}\" x2=\"{:.1}\" y2=\"{y:.1}\" stroke=\"{col}\" stroke-width=\"3\"/><text x=\"{:.1}\" y=\"{y:.1}\" font-size=\"{FONT}\" fill=\"{col}\" dominant-baseline=\"middle\">{}</text>",
        x + w,
        x + w + 5.0,
        escape(label)
    );
}

/// One shape in SVG: world (m) to pixels by `tx`, `ty` (y down) and `k`
/// [px/m]; arrows use the markers `{id}-n` and `{id}-f`.
fn emit(
    o: &mut String,
    sh: &Shape,
    tx: &dyn Fn(f64) -> f64,
    ty: &dyn Fn(f64) -> f64,
    k: f64,
    id: &str,
) {
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
        Shape::Line { a, b, colour, .. } | Shape::Arrow { a, b, colour } => {
            let end = match sh {
                Shape::Line { width_m, .. } => format!("{:.2}\"", (width_m * k).max(2.0)),
                _ => format!(
                    "2\" marker-end=\"url(#{id}-{})\"",
                    if *colour == NORMAL { "n" } else { "f" }
                ),
            };
            let (x1, y1, x2, y2) = (tx(a.0), ty(a.1), tx(b.0), ty(b.1));
            let _ = writeln!(
                o,
                "<line x1=\"{x1:.2}\" y1=\"{y1:.2}\" x2=\"{x2:.2}\" y2=\"{y2:.2}\" stroke=\"{colour}\" stroke-width=\"{end}/>"
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
        Shape::Text { .. } => {}
        Shape::Ring { c, r } => {
            let _ = writeln!(
                o,
                "<circle cx=\"{:.2}\" cy=\"{:.2}\" r=\"{:.2}\" fill=\"none\" stroke=\"{FIXED}\" stroke-width=\"1\" stroke-dasharray=\"6 4\"/>",
                tx(c.0),
                ty(c.1),
                r * k
            );
        }
        Shape::Dim { a, b, .. } => {
            let _ = writeln!(
                o,
                "<line x1=\"{:.2}\" y1=\"{:.2}\" x2=\"{:.2}\" y2=\"{:.2}\" stroke=\"{DIM}\" stroke-width=\"1\" marker-start=\"url(#{id}-d)\" marker-end=\"url(#{id}-d)\"/>",
                tx(a.0),
                ty(a.1),
                tx(b.0),
                ty(b.1)
            );
        }
        Shape::Angle { c, r, from, to, .. } => {
            let at = |t: f64| (tx(c.0 + r * t.cos()), ty(c.1 + r * t.sin()));
            let ((xa, ya), (xb, yb)) = (at(*from), at(*to));
            let large = u8::from(to - from > std::f64::consts::PI);
            // y down: counter-clockwise in the world is sweep-flag 0.
            let _ = writeln!(
                o,
                "<path d=\"M{xa:.2},{ya:.2} A{0:.2},{0:.2} 0 {large} 0 {xb:.2},{yb:.2}\" fill=\"none\" stroke=\"{DIM}\" stroke-width=\"1\" marker-start=\"url(#{id}-d)\" marker-end=\"url(#{id}-d)\"/>",
                r * k
            );
        }
    }
}

/// The boxes [px] of the labels placed so far in a drawing `w` x `h`.
struct Labels {
    w: f64,
    h: f64,
    boxes: Vec<[f64; 4]>,
}

impl Labels {
    fn new(w: f64, h: f64) -> Self {
        Labels { w, h, boxes: Vec::new() }
    }

    /// The centre for `text` nearest its anchor `(x, y)` on rings of 8
    /// directions, inside the drawing and clear of every label placed so
    /// far (the anchor itself when no position is clear). The box is an
    /// upper bound of the text's: 0.62 em per character, 1.25 em high.
    fn place(&mut self, x: f64, y: f64, text: &str) -> (f64, f64) {
        let (bw, bh) = (0.62 * FONT * text.chars().count() as f64 + 2.0, 1.25 * FONT);
        let inside = |(cx, cy): (f64, f64)| {
            let cx = cx.clamp(bw / 2.0 + 1.0, (self.w - bw / 2.0 - 1.0).max(bw / 2.0 + 1.0));
            let cy = cy.clamp(bh / 2.0 + 1.0, (self.h - bh / 2.0 - 1.0).max(bh / 2.0 + 1.0));
            (cx, cy)
        };
        let boxed =
            |(cx, cy): (f64, f64)| [cx - bw / 2.0, cy - bh / 2.0, cx + bw / 2.0, cy + bh / 2.0];
        let clear = |b: &[f64; 4]| {
            self.boxes.iter().all(|o| b[2] <= o[0] || o[2] <= b[0] || b[3] <= o[1] || o[3] <= b[1])
        };
        let rings = (1..=12).flat_map(|ring| {
            (0..8).map(move |d| {
                let t = f64::from(d) * std::f64::consts::FRAC_PI_4;
                let step = 0.6 * bh * f64::from(ring);
                (x + step * t.cos(), y + step * t.sin())
            })
        });
        let at = std::iter::once((x, y))
            .chain(rings)
            .map(inside)
            .find(|c| clear(&boxed(*c)))
            .unwrap_or_else(|| inside((x, y)));
        self.boxes.push(boxed(at));
        at
    }
}
