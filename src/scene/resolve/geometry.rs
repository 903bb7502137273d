//! `[[balls]]` and `[[surfaces]]`: every ball placed, every surface
//! complete for its kind and attached to a ball, every ball touching one.

use nalgebra::Vector3;
use toml::Spanned;

use super::fields::Fields;
use super::support::{Support, support};
use crate::scene::error::{ErrorContext, SceneError};
use crate::scene::file::{BallFile, Numbers, SceneFile, SurfaceFile, SurfaceKind};
use crate::scene::plausible;
use crate::scene::{Ball, MovingPatch, Surface, SurfaceGeometry};

/// The moving balls, in file order.
pub fn balls(f: &SceneFile, fx: &Fields) -> Result<Vec<Ball>, SceneError> {
    if f.balls.is_empty() {
        return Err(fx.ctx.error(
            None,
            "balls",
            "no moving balls: give a [coupling] table or [[balls]] and [[surfaces]]",
        ));
    }
    let ball = |(i, b): (usize, &BallFile)| {
        let field = |k: &str| format!("balls[{}].{k}", i + 1);
        Ok(Ball {
            centre: fx.finite(&b.centre, &field("centre"))?,
            radius: fx.positive(&b.radius, &field("radius"), "m")?,
            material: fx.material(&b.material, &field("material"))?,
            line: fx.ctx.line_of(&b.radius.span()),
        })
    };
    f.balls.iter().enumerate().map(ball).collect()
}

/// The fixed surfaces, numbered ball by ball (the order of `--mu`); each
/// ball must touch at least one.
pub fn surfaces(f: &SceneFile, fx: &Fields, balls: &[Ball]) -> Result<Vec<Surface>, SceneError> {
    // Radii are checked positive below; first the magnitudes (millimetres?).
    let centres: Vec<Vector3<f64>> = balls.iter().map(|b| b.centre).collect();
    plausible::check_explicit(f, &centres, fx.ctx)?;
    let mut surfaces = (f.surfaces.iter().enumerate())
        .map(|(i, s)| surface(s, i, fx, balls.len()))
        .collect::<Result<Vec<_>, _>>()?;
    fixed_apart(&surfaces, fx.ctx)?;
    // Contacts are numbered ball by ball (the order of --mu).
    surfaces.sort_by_key(|s| s.ball);
    match (0..balls.len()).find(|&k| !surfaces.iter().any(|s| s.ball == k)) {
        Some(k) => Err(SceneError {
            file: fx.ctx.file.to_string(),
            line: balls[k].line,
            field: format!("balls[{}]", k + 1),
            reason: "this ball touches no fixed surface (no [[surfaces]] entry has ball = \
                     its number)"
                .to_string(),
        }),
        None => Ok(surfaces),
    }
}

/// The fixed balls and pins serving one ball must not overlap (file
/// order, 0-based): two fixed balls closer than R1 + R2 (centre to
/// centre), two parallel pins whose axes are closer than R1 + R2, a ball
/// and a pin whose centre lies closer to the axis than R1 + R2. (Pins that
/// cross are lines here, finite in a real part: not checked; nor are
/// planes, whose half-spaces meet along a V's edge by design.)
fn fixed_apart(surfaces: &[Surface], ctx: &ErrorContext) -> Result<(), SceneError> {
    let line_distance = |p: &Vector3<f64>, a: &Vector3<f64>, d: &Vector3<f64>| {
        let r = p - a;
        (r - d * d.dot(&r)).norm()
    };
    for (j, b) in surfaces.iter().enumerate() {
        for (i, a) in surfaces[..j].iter().enumerate().filter(|(_, a)| a.ball == b.ball) {
            use SurfaceGeometry::{Cylinder, Sphere};
            let apart = match (a.geometry, b.geometry) {
                (Sphere { centre: c1, radius: r1 }, Sphere { centre: c2, radius: r2 }) => {
                    Some(((c1 - c2).norm(), r1 + r2, "centres"))
                }
                (
                    Cylinder { axis_point: p1, direction: d1, radius: r1 },
                    Cylinder { axis_point: p2, direction: d2, radius: r2 },
                ) if d1.cross(&d2).norm() < 1e-9 => {
                    Some((line_distance(&p2, &p1, &d1), r1 + r2, "axes"))
                }
                (Sphere { centre, radius: r1 }, Cylinder { axis_point, direction, radius: r2 })
                | (Cylinder { axis_point, direction, radius: r2 }, Sphere { centre, radius: r1 }) => {
                    Some((
                        line_distance(&centre, &axis_point, &direction),
                        r1 + r2,
                        "centre and axis",
                    ))
                }
                _ => None,
            };
            if let Some((distance, reach, what)) = apart
                && distance < reach * (1.0 - 1e-12)
            {
                return Err(SceneError {
                    file: ctx.file.to_string(),
                    line: b.line,
                    field: format!("surfaces[{}].radius", j + 1),
                    reason: format!(
                        "overlaps surfaces[{}] (both serve ball {}): their {what} are {distance:.6} \
                         m apart, less than the sum of their radii {reach:.6} m",
                        i + 1,
                        b.ball + 1
                    ),
                });
            }
        }
    }
    Ok(())
}

/// Surface `i` (0-based) of the file, for a coupling of `n_balls` balls.
fn surface(s: &SurfaceFile, i: usize, fx: &Fields, n_balls: usize) -> Result<Surface, SceneError> {
    let ctx = fx.ctx;
    let field = |k: &str| format!("surfaces[{}].{k}", i + 1);
    let ball = *s.ball.get_ref();
    if ball < 1 || ball as usize > n_balls {
        return Err(ctx.error(
            Some(&s.ball.span()),
            field("ball"),
            format!("{ball} names no moving ball (there are {n_balls})"),
        ));
    }
    let need = |v: &Option<Spanned<Numbers>>, k: &str| -> Result<Spanned<Numbers>, SceneError> {
        v.clone().ok_or_else(|| missing(s, ctx, &field(k), k))
    };
    let radius = |s: &SurfaceFile| -> Result<f64, SceneError> {
        let r = s.radius.as_ref().ok_or_else(|| missing(s, ctx, &field("radius"), "radius"))?;
        fx.positive(r, &field("radius"), "m")
    };
    unused_keys(s, ctx, &field)?;
    let geometry = match s.kind.get_ref() {
        SurfaceKind::Plane => SurfaceGeometry::Plane {
            point: fx.finite(&need(&s.point, "point")?, &field("point"))?,
            normal: fx.unit(&need(&s.normal, "normal")?, &field("normal"))?,
        },
        SurfaceKind::Cylinder => SurfaceGeometry::Cylinder {
            axis_point: fx.finite(&need(&s.axis_point, "axis_point")?, &field("axis_point"))?,
            direction: fx.unit(&need(&s.direction, "direction")?, &field("direction"))?,
            radius: radius(s)?,
        },
        SurfaceKind::Sphere => SurfaceGeometry::Sphere {
            centre: fx.finite(&need(&s.centre, "centre")?, &field("centre"))?,
            radius: radius(s)?,
        },
        SurfaceKind::ConcaveCylinder => SurfaceGeometry::ConcaveCylinder {
            axis_point: fx.finite(&need(&s.axis_point, "axis_point")?, &field("axis_point"))?,
            direction: fx.unit(&need(&s.direction, "direction")?, &field("direction"))?,
            radius: radius(s)?,
        },
    };
    let (support, span) = match &s.support_compliance {
        Some(v) => (support(ctx, v, &field("support_compliance"), true)?, v.span()),
        None => (Support::default(), s.kind.span()),
    };
    let own_axis = match geometry {
        SurfaceGeometry::Cylinder { direction, .. }
        | SurfaceGeometry::ConcaveCylinder { direction, .. } => Some(direction),
        SurfaceGeometry::Plane { .. } | SurfaceGeometry::Sphere { .. } => None,
    };
    let tangential_support =
        support.oriented(own_axis, ctx, &span, &field("support_compliance"))?;
    Ok(Surface {
        geometry,
        material: fx.material(&s.material, &field("material"))?,
        ball: ball as usize - 1,
        line: ctx.line_of(&s.kind.span()),
        support_compliance: support.normal,
        tangential_support,
        moving: moving_patch(s, i, fx)?,
    })
}

/// A key of another surface type given to `s` (a `radius` on a plane):
/// refused, since it would have no effect.
fn unused_keys(
    s: &SurfaceFile,
    ctx: &ErrorContext,
    field: &dyn Fn(&str) -> String,
) -> Result<(), SceneError> {
    let (name, takes): (&str, &[&str]) = match s.kind.get_ref() {
        SurfaceKind::Plane => ("plane", &["point", "normal"]),
        SurfaceKind::Cylinder | SurfaceKind::ConcaveCylinder => {
            ("cylinder", &["axis_point", "direction", "radius"])
        }
        SurfaceKind::Sphere => ("sphere", &["centre", "radius"]),
    };
    let numbers = |v: &Option<Spanned<Numbers>>| v.as_ref().map(|x| x.span());
    let given = [
        ("point", numbers(&s.point)),
        ("normal", numbers(&s.normal)),
        ("axis_point", numbers(&s.axis_point)),
        ("direction", numbers(&s.direction)),
        ("centre", numbers(&s.centre)),
        ("radius", s.radius.as_ref().map(|x| x.span())),
    ];
    for (key, span) in given {
        if let Some(span) = span
            && !takes.contains(&key)
        {
            let why = format!(
                "a {name} takes {}, not {key}: remove it (it would have no effect)",
                takes.join(", ")
            );
            return Err(ctx.error(Some(&span), field(key), why));
        }
    }
    Ok(())
}

/// The moving element's own patch at surface `i`: `moving_centre` and
/// `moving_radius`, both or neither.
fn moving_patch(s: &SurfaceFile, i: usize, fx: &Fields) -> Result<Option<MovingPatch>, SceneError> {
    let field = |k: &str| format!("surfaces[{}].{k}", i + 1);
    match (&s.moving_centre, &s.moving_radius) {
        (None, None) => match &s.moving_direction {
            None => Ok(None),
            Some(d) => Err(fx.ctx.error(
                Some(&d.span()),
                field("moving_centre"),
                "missing: a moving pin needs `moving_centre` (a point of its axis) and \
                 `moving_radius`",
            )),
        },
        (Some(c), Some(r)) => Ok(Some(MovingPatch {
            centre: fx.finite(c, &field("moving_centre"))?,
            radius: fx.positive(r, &field("moving_radius"), "m")?,
            axis: match &s.moving_direction {
                Some(d) => Some(fx.unit(d, &field("moving_direction"))?),
                None => None,
            },
        })),
        (Some(c), None) => Err(fx.ctx.error(
            Some(&c.span()),
            field("moving_radius"),
            "missing: a moving patch needs both `moving_centre` and `moving_radius`",
        )),
        (None, Some(r)) => Err(fx.ctx.error(
            Some(&r.span()),
            field("moving_centre"),
            "missing: a moving patch needs both `moving_centre` and `moving_radius`",
        )),
    }
}

fn missing(s: &SurfaceFile, ctx: &ErrorContext, field: &str, key: &str) -> SceneError {
    let kind = s.kind.get_ref().name();
    ctx.error(Some(&s.kind.span()), field, format!("missing: a {kind} needs `{key}`"))
}
