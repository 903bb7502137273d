//! `[[evaluation_points]]`: names, positions and the directions each point
//! is read along (`directions`, `frame`).

use nalgebra::Vector3;

use super::fields::Fields;
use crate::dof::Dof;
use crate::scene::error::SceneError;
use crate::scene::file::{EvaluationPointFile, FrameFile, SceneFile};
use crate::scene::{Direction, EvaluationPoint};

/// Most `[[evaluation_points]]` of one scene: each adds six columns to the
/// per-sample CSV and a panel to every chart and drawing; a hundred points
/// already make a report no one reads.
pub const MAX_EVALUATION_POINTS: usize = 100;

/// Most directions of one point (a frame counts six): each adds a column
/// to the per-sample CSV and a row to every table of the point.
pub const MAX_DIRECTIONS: usize = 24;

/// Smallest angle between a frame's x and z [deg]: below it the x axis
/// made normal to z is mostly rounding.
pub const FRAME_AXES_MIN_DEG: f64 = 1.0;

/// `[[evaluation_points]]`, or the centre when there are none.
pub fn evaluation_points(f: &SceneFile, fx: &Fields) -> Result<Vec<EvaluationPoint>, SceneError> {
    let mut points = Vec::new();
    for (i, e) in f.evaluation_points.iter().enumerate() {
        if i == MAX_EVALUATION_POINTS {
            let field = format!("evaluation_points[{}]", i + 1);
            let reason = format!(
                "{} evaluation points: at most {MAX_EVALUATION_POINTS} per scene (docs/output.md, Bounds)",
                f.evaluation_points.len()
            );
            return Err(fx.ctx.error(Some(&e.name.span()), &field, reason));
        }
        let name = e.name.get_ref();
        // A point's name heads its CSV columns and table rows: it must
        // name one point.
        let reason = if name.trim().is_empty() {
            Some("empty: give the point a name".to_string())
        } else {
            (points.iter().position(|p: &EvaluationPoint| p.name == *name))
                .map(|k| format!("`{name}` is also the name of evaluation point {}", k + 1))
        };
        if let Some(reason) = reason {
            let field = format!("evaluation_points[{}].name", i + 1);
            return Err(fx.ctx.error(Some(&e.name.span()), &field, reason));
        }
        let field = format!("evaluation_points[{}]", i + 1);
        points.push(EvaluationPoint {
            name: name.clone(),
            position: fx.finite(&e.position, &format!("{field}.position"))?,
            directions: directions(e, fx, &field)?,
        });
    }
    if points.is_empty() {
        points.push(EvaluationPoint::at("centre", Vector3::zeros()));
    }
    Ok(points)
}

/// The point's `directions`, then its `frame`'s six.
fn directions(
    e: &EvaluationPointFile,
    fx: &Fields,
    point: &str,
) -> Result<Vec<Direction>, SceneError> {
    let mut out: Vec<Direction> = Vec::new();
    for (k, d) in e.directions.iter().enumerate() {
        let field = format!("{point}.directions[{}]", k + 1);
        let name = d.name.get_ref();
        let bad =
            |reason: String| fx.ctx.error(Some(&d.name.span()), format!("{field}.name"), reason);
        if let Some(reason) = name_problem(name) {
            return Err(bad(reason));
        }
        if let Some(j) = out.iter().position(|o| o.name == *name) {
            return Err(bad(format!("`{name}` is also the name of direction {}", j + 1)));
        }
        let unit = fx.unit(&d.vector, &format!("{field}.vector"))?;
        out.push(Direction { name: name.clone(), vector: unit, rotation: false });
    }
    if let Some(frame) = &e.frame {
        let axes = frame_axes(frame, fx, &format!("{point}.frame"))?;
        let name = frame.name.get_ref();
        for rotation in [false, true] {
            for (axis, unit) in ["x", "y", "z"].into_iter().zip(axes) {
                let name = format!("{name}.{axis}");
                if let Some(j) = out.iter().position(|o| o.name == name && o.rotation == rotation) {
                    let reason =
                        format!("its axis `{name}` is also the name of direction {}", j + 1);
                    let field = format!("{point}.frame.name");
                    return Err(fx.ctx.error(Some(&frame.name.span()), &field, reason));
                }
                out.push(Direction { name, vector: unit, rotation });
            }
        }
    }
    if out.len() > MAX_DIRECTIONS {
        let reason = format!(
            "{} directions (a frame counts six): at most {MAX_DIRECTIONS} per point",
            out.len()
        );
        return Err(fx.ctx.error(Some(&e.name.span()), point, reason));
    }
    Ok(out)
}

/// A frame's unit axes x, y, z: z as given, x made normal to it, y = z x x.
fn frame_axes(f: &FrameFile, fx: &Fields, field: &str) -> Result<[Vector3<f64>; 3], SceneError> {
    if let Some(reason) = name_problem(f.name.get_ref()) {
        return Err(fx.ctx.error(Some(&f.name.span()), format!("{field}.name"), reason));
    }
    let z = fx.unit(&f.z, &format!("{field}.z"))?;
    let x = fx.unit(&f.x, &format!("{field}.x"))?;
    let normal = x - z * z.dot(&x);
    let angle = normal.norm().asin().to_degrees();
    if angle < FRAME_AXES_MIN_DEG {
        let reason = format!(
            "x lies {angle:.3} deg from z: the axes must be at least {FRAME_AXES_MIN_DEG} deg apart"
        );
        return Err(fx.ctx.error(Some(&f.x.span()), format!("{field}.x"), reason));
    }
    let x = normal.normalize();
    Ok([x, z.cross(&x), z])
}

/// Why a direction's or frame's name cannot head an output column, if it
/// cannot: empty, holding `/`, or a DOF's name (`x`, ..., `phi_z`).
fn name_problem(name: &str) -> Option<String> {
    if name.trim().is_empty() {
        Some("empty: give the direction a name".to_string())
    } else if name.contains('/') {
        Some(format!("`{name}` holds `/`, which separates the parts of an output name"))
    } else if Dof::from_name(name).is_some() {
        Some(format!("`{name}` is the name of a DOF ({}): choose another", Dof::names()))
    } else {
        None
    }
}
