//! `[preload]`: the single central force (the paper's, the default), or
//! `[[preload.forces]]` (constant forces and springs), plus the weight of
//! the moving half with `gravity = true` (docs/scenes.md).

use nalgebra::Vector3;
use toml::Spanned;

use super::fields::Fields;
use crate::scene::error::SceneError;
use crate::scene::file::{DynamicsFile, Numbers, PreloadFile, PreloadForceFile};
use crate::scene::plausible::CIRCLE_DIAMETER_MAX;
use crate::scene::preload::{GRAVITY_MAX, MagnetLaw, STANDARD_GRAVITY};
use crate::scene::{DEFAULT_RAMP_TIME, ForceLaw, Preload, PreloadForce};

/// `[preload]`: `force` (positive; point and direction default to the
/// centre and -z) or `forces`, not both; `gravity` adds the weight, with
/// the mass from `[preload] mass` or else `[dynamics] mass`.
pub fn preload(
    p: &PreloadFile,
    dynamics: Option<&DynamicsFile>,
    fx: &Fields,
    allow_large: bool,
) -> Result<Preload, SceneError> {
    let mut forces = match (&p.force, p.forces.is_empty()) {
        (Some(f), true) => vec![single(p, f, fx)?],
        (Some(f), false) => {
            return Err(fx.ctx.error(
                Some(&f.span()),
                "preload.force",
                "give either the single force or [[preload.forces]], not both",
            ));
        }
        (None, _) => listed(p, fx)?,
    };
    if let Some(g) = gravity(p, fx, allow_large)? {
        forces.push(weight(p, g, dynamics, fx)?);
    } else if let Some(m) = &p.mass {
        return Err(fx.ctx.error(
            Some(&m.span()),
            "preload.mass",
            "the mass is read only with gravity = true (or a gravity vector)",
        ));
    }
    if forces.is_empty() {
        return Err(fx.ctx.error(
            None,
            "preload.force",
            "missing: give force, [[preload.forces]] or gravity = true",
        ));
    }
    check_geometry(p, dynamics, &forces, fx, allow_large)?;
    Ok(Preload {
        forces,
        ramp_time: match &p.ramp_time {
            Some(v) => fx.positive(v, "preload.ramp_time", "s")?,
            None => DEFAULT_RAMP_TIME,
        },
    })
}

/// The single `force` at `point` (default the origin) along `direction`
/// (default -z).
fn single(p: &PreloadFile, f: &Spanned<f64>, fx: &Fields) -> Result<PreloadForce, SceneError> {
    Ok(PreloadForce::constant(
        fx.positive(f, "preload.force", "N")?,
        match &p.point {
            Some(v) => fx.finite(v, "preload.point")?,
            None => Vector3::zeros(),
        },
        match &p.direction {
            Some(v) => fx.unit(v, "preload.direction")?,
            None => -Vector3::z(),
        },
    ))
}

/// `[[preload.forces]]`, in file order; `[preload] point` and `direction`
/// belong to the single force and are refused beside them.
fn listed(p: &PreloadFile, fx: &Fields) -> Result<Vec<PreloadForce>, SceneError> {
    for (v, name) in [(&p.point, "preload.point"), (&p.direction, "preload.direction")] {
        if let Some(v) = v.as_ref().filter(|_| !p.forces.is_empty()) {
            return Err(fx.ctx.error(
                Some(&v.span()),
                name,
                "belongs to the single force; give each force's own in [[preload.forces]]",
            ));
        }
    }
    p.forces
        .iter()
        .enumerate()
        .map(|(i, f)| entry(f, &format!("preload.forces[{}]", i + 1), fx))
        .collect()
}

/// One `[[preload.forces]]` entry: a constant force, a spring if it
/// gives `stiffness` and `free_length` (both, positive, and a positive
/// length free_length - force / stiffness in the touching pose), or a
/// magnet if it gives `gap` and `force_table` (both; no `force`).
fn entry(f: &PreloadForceFile, at: &str, fx: &Fields) -> Result<PreloadForce, SceneError> {
    let point = fx.finite(&f.point, &format!("{at}.point"))?;
    let direction = fx.unit(&f.direction, &format!("{at}.direction"))?;
    let half = |span: std::ops::Range<usize>, key: &str, missing: &str| {
        let why = format!("a magnet needs both gap and force_table; {missing} is missing");
        Err(fx.ctx.error(Some(&span), format!("{at}.{key}"), why))
    };
    match (&f.gap, &f.force_table) {
        (Some(g), Some(t)) => return magnet(f, at, fx, (g, t), (point, direction)),
        (Some(g), None) => return half(g.span(), "gap", "force_table"),
        (None, Some(t)) => return half(t.span(), "force_table", "gap"),
        (None, None) => {}
    }
    let Some(given) = &f.force else {
        return Err(fx.ctx.error(
            Some(&f.point.span()),
            format!("{at}.force"),
            "missing: give the force [N] (or gap and force_table for a magnet)",
        ));
    };
    let force = fx.positive(given, &format!("{at}.force"), "N")?;
    let law = match (&f.stiffness, &f.free_length) {
        (None, None) => ForceLaw::Constant,
        (Some(k), Some(l)) => {
            let stiffness = fx.positive(k, &format!("{at}.stiffness"), "N/m")?;
            let free_length = fx.positive(l, &format!("{at}.free_length"), "m")?;
            let length = free_length - force / stiffness;
            if length <= 0.0 {
                return Err(fx.ctx.error(
                    Some(&l.span()),
                    format!("{at}.free_length"),
                    format!(
                        "{free_length} m is not longer than force / stiffness = {} m: the \
                         spring cannot give {force} N",
                        force / stiffness
                    ),
                ));
            }
            ForceLaw::Spring { stiffness, free_length }
        }
        (Some(k), None) => return Err(pair(fx, k, at, "stiffness", "free_length")),
        (None, Some(l)) => return Err(pair(fx, l, at, "free_length", "stiffness")),
    };
    Ok(PreloadForce { force, point, direction, law })
}

/// A magnet entry: `gap` (>= 0) inside its `force_table` of at least two
/// points [gap m, force N] with strictly increasing gaps >= 0 and finite
/// forces >= 0, a positive force at `gap`; neither `force` nor a spring's
/// keys beside them.
fn magnet(
    f: &PreloadForceFile,
    at: &str,
    fx: &Fields,
    (gap, table): (&Spanned<f64>, &Spanned<Vec<Spanned<Numbers>>>),
    (point, direction): (Vector3<f64>, Vector3<f64>),
) -> Result<PreloadForce, SceneError> {
    let err = |span: Option<std::ops::Range<usize>>, key: &str, why: String| {
        fx.ctx.error(span.as_ref(), format!("{at}.{key}"), why)
    };
    for (key, v) in
        [("force", &f.force), ("stiffness", &f.stiffness), ("free_length", &f.free_length)]
    {
        if let Some(v) = v {
            let why = format!("a magnet's force comes from its force_table: drop {key}");
            return Err(err(Some(v.span()), key, why));
        }
    }
    let mut rows: Vec<[f64; 2]> = Vec::with_capacity(table.get_ref().len());
    for (k, row) in table.get_ref().iter().enumerate() {
        let field = format!("{at}.force_table[{}]", k + 1);
        let [g, force] = fx.ctx.numbers::<2>(row, &field, "[gap m, force N]")?;
        let why = if !(g.is_finite() && force.is_finite()) {
            Some("gap and force must be finite numbers".to_string())
        } else if g < 0.0 || force < 0.0 {
            Some(format!(
                "[{g}, {force}]: gap and force must not be negative (the force pulls along direction)"
            ))
        } else if rows.last().is_some_and(|p| g <= p[0]) {
            Some(format!(
                "gap {g} m is not above the previous row's: give the rows by increasing gap"
            ))
        } else {
            None
        };
        if let Some(why) = why {
            return Err(fx.ctx.error(Some(&row.span()), field, why));
        }
        rows.push([g, force]);
    }
    if rows.len() < 2 {
        let why = format!("needs at least two rows [gap m, force N], found {}", rows.len());
        return Err(err(Some(table.span()), "force_table", why));
    }
    let g0 = *gap.get_ref();
    let (first, last) = (rows[0][0], rows[rows.len() - 1][0]);
    if !(first..=last).contains(&g0) {
        let why = format!("{g0} m is outside the force_table's gaps [{first}, {last}] m");
        return Err(err(Some(gap.span()), "gap", why));
    }
    let law = MagnetLaw::new(g0, rows);
    let force = law.force(g0).0;
    if force <= 0.0 {
        let why = format!("the force_table gives {force} N at the gap {g0} m: a magnet must pull");
        return Err(err(Some(gap.span()), "gap", why));
    }
    Ok(PreloadForce { force, point, direction, law: ForceLaw::Magnet(law) })
}

fn pair(fx: &Fields, v: &Spanned<f64>, at: &str, given: &str, missing: &str) -> SceneError {
    fx.ctx.error(
        Some(&v.span()),
        format!("{at}.{given}"),
        format!("a spring needs both stiffness and free_length; {missing} is missing"),
    )
}

/// A gravity vector [m/s^2] and the place of `[preload] gravity` in the file.
type Gravity = (Vector3<f64>, std::ops::Range<usize>);

/// `[preload] gravity`: `true` (standard gravity along -z), `false` or
/// absent (no weight), or a gravity vector [gx, gy, gz] in m/s^2 (finite,
/// nonzero, at most [`GRAVITY_MAX`] in size unless `allow_large`); the
/// vector and the field's place in the file.
fn gravity(p: &PreloadFile, fx: &Fields, allow_large: bool) -> Result<Option<Gravity>, SceneError> {
    let Some(g) = &p.gravity else {
        return Ok(None);
    };
    let (span, field) = (g.span(), "preload.gravity");
    let vector = match g.get_ref() {
        toml::Value::Boolean(false) => return Ok(None),
        toml::Value::Boolean(true) => -Vector3::z() * STANDARD_GRAVITY,
        toml::Value::Array(items) => {
            let numbers = Spanned::new(span.clone(), Numbers(items.clone()));
            fx.finite(&numbers, field)?
        }
        other => {
            return Err(fx.ctx.error(
                Some(&span),
                field,
                format!(
                    "expected true, false or a gravity vector [gx, gy, gz] in m/s^2, found {}",
                    other.type_str()
                ),
            ));
        }
    };
    let size = vector.norm();
    if size == 0.0 {
        return Err(fx.ctx.error(
            Some(&span),
            field,
            "the gravity vector [0, 0, 0] has no direction: give false (or leave gravity out) \
             for no weight",
        ));
    }
    if size > GRAVITY_MAX && !allow_large {
        return Err(fx.ctx.error(
            Some(&span),
            field,
            format!(
                "|g| = {size} m/s^2 is implausibly large (limit {GRAVITY_MAX} m/s^2): did you \
                 give mm/s^2? scene files are in SI (m/s^2, standard gravity 9.80665); if the \
                 value is intended, set `allow_large_values = true` at the top of the file"
            ),
        ));
    }
    Ok(Some((vector, span)))
}

/// The weight of the moving half under the gravity vector `g`:
/// `[preload] mass` and `centre_of_mass` (default the origin), else
/// `[dynamics] mass` and `centre_of_mass`.
fn weight(
    p: &PreloadFile,
    (g, span): Gravity,
    dynamics: Option<&DynamicsFile>,
    fx: &Fields,
) -> Result<PreloadForce, SceneError> {
    let (mass, com, field) = match (&p.mass, dynamics) {
        (Some(m), _) => (m, &p.centre_of_mass, "preload"),
        (None, Some(d)) => (&d.mass, &d.centre_of_mass, "dynamics"),
        (None, None) => {
            return Err(fx.ctx.error(
                Some(&span),
                "preload.gravity",
                "needs the mass of the moving half: give [preload] mass (and centre_of_mass) \
                 or a [dynamics] table",
            ));
        }
    };
    if let (Some(c), None) = (&p.centre_of_mass, &p.mass) {
        return Err(fx.ctx.error(
            Some(&c.span()),
            "preload.centre_of_mass",
            "given without [preload] mass: the weight's mass and centre come from one table",
        ));
    }
    let mass = fx.positive(mass, &format!("{field}.mass"), "kg")?;
    let centre = match com {
        Some(c) => fx.finite(c, &format!("{field}.centre_of_mass"))?,
        None => Vector3::zeros(),
    };
    Ok(PreloadForce::weight(mass, centre, g))
}

/// Where each force's point and direction are written: field and place.
struct Place {
    point: (String, Option<std::ops::Range<usize>>),
    direction: (String, Option<std::ops::Range<usize>>),
}

/// The places of `forces` (the single force or the listed ones, then the
/// weight) in the file.
fn places(p: &PreloadFile, dynamics: Option<&DynamicsFile>, count: usize) -> Vec<Place> {
    let span = |v: &Option<Spanned<Numbers>>| v.as_ref().map(|v| v.span());
    let mut out: Vec<Place> = match &p.force {
        Some(_) => vec![Place {
            point: ("preload.point".into(), span(&p.point)),
            direction: ("preload.direction".into(), span(&p.direction)),
        }],
        None => (p.forces.iter().enumerate())
            .map(|(i, f)| Place {
                point: (format!("preload.forces[{}].point", i + 1), Some(f.point.span())),
                direction: (
                    format!("preload.forces[{}].direction", i + 1),
                    Some(f.direction.span()),
                ),
            })
            .collect(),
    };
    if out.len() < count {
        let (field, com) = match (&p.mass, dynamics) {
            (None, Some(d)) => ("dynamics.centre_of_mass", span(&d.centre_of_mass)),
            _ => ("preload.centre_of_mass", span(&p.centre_of_mass)),
        };
        let gravity = p.gravity.as_ref().map(|g| g.span());
        out.push(Place {
            point: (field.into(), com),
            direction: ("preload.gravity".into(), gravity),
        });
    }
    out
}

/// The preload's geometry: every point within [`CIRCLE_DIAMETER_MAX`] of
/// the origin (unless `allow_large`: a point in millimetres is metres
/// away), and a resultant that presses the moving half onto the fixed one
/// (z points from the fixed to the moving half, so it needs a component
/// along -z; the force that pulls most along +z is named).
fn check_geometry(
    p: &PreloadFile,
    dynamics: Option<&DynamicsFile>,
    forces: &[PreloadForce],
    fx: &Fields,
    allow_large: bool,
) -> Result<(), SceneError> {
    let places = places(p, dynamics, forces.len());
    for (f, place) in forces.iter().zip(&places) {
        let r = f.point.norm();
        if r > CIRCLE_DIAMETER_MAX && !allow_large {
            let (field, span) = &place.point;
            let why = format!(
                "the point lies {r} m from the origin (limit {CIRCLE_DIAMETER_MAX} m): did you \
                 give millimetres? scene files are in SI (m); if the value is intended, set \
                 `allow_large_values = true` at the top of the file"
            );
            return Err(fx.ctx.error(span.as_ref(), field.clone(), why));
        }
    }
    let z: f64 = forces.iter().map(|f| f.direction.z * f.force).sum();
    if z >= 0.0 {
        let worst = (0..forces.len())
            .max_by(|&a, &b| {
                let up = |i: usize| forces[i].direction.z * forces[i].force;
                up(a).total_cmp(&up(b))
            })
            .unwrap_or(0);
        let (field, span) = &places[worst].direction;
        let why = format!(
            "the preload's resultant has {z:.4} N along +z: it does not press the moving half \
             onto the fixed one (z points from the fixed to the moving half; a preload presses \
             along -z, e.g. direction = [0.0, 0.0, -1.0])"
        );
        return Err(fx.ctx.error(span.as_ref(), field.clone(), why));
    }
    Ok(())
}
