//! `[thermal]`: the two bodies (materials with a thermal expansion), their
//! origins, the cycle, and the expansion of every element's material.

use nalgebra::Vector3;
use toml::Spanned;

use super::fields::Fields;
use crate::material::Material;
use crate::scene::error::SceneError;
use crate::scene::file::{Numbers, SceneFile, ThermalFile};
use crate::scene::thermal::{
    Body, DEFAULT_THERMAL_TOLERANCE, THERMAL_TOLERANCE_RANGE, Temperatures, Thermal, ThermalBodies,
    cycle_problem,
};
use crate::scene::{Ball, Surface};

/// `[thermal]`, if the scene has one; every element of `balls` and
/// `surfaces` must then have a material with a thermal expansion.
pub fn thermal(
    f: &SceneFile,
    fx: &Fields,
    balls: &[Ball],
    surfaces: &[Surface],
) -> Result<Option<Thermal>, SceneError> {
    let Some(t) = &f.thermal else {
        return Ok(None);
    };
    let moving = body(fx, &t.moving_body, t.moving_origin.as_ref(), "moving")?;
    let fixed = body(fx, &t.fixed_body, t.fixed_origin.as_ref(), "fixed")?;
    let element = |m: &Material, what: String| element_expansion(f, fx, m, &what);
    let balls = (balls.iter().enumerate())
        .map(|(k, b)| element(&b.material, format!("ball {}", k + 1)))
        .collect::<Result<Vec<_>, _>>()?;
    let surfaces = (surfaces.iter().enumerate())
        .map(|(i, s)| element(&s.material, format!("contact {}'s surface", i + 1)))
        .collect::<Result<Vec<_>, _>>()?;
    Ok(Some(Thermal {
        bodies: ThermalBodies { moving, fixed, balls, surfaces },
        cycle: cycle(t, fx, f.allow_large_values)?,
        path_tolerance: tolerance(t, fx)?,
    }))
}

/// One body: its material's expansion and its origin.
fn body(
    fx: &Fields,
    name: &Spanned<String>,
    origin: Option<&Spanned<Numbers>>,
    which: &str,
) -> Result<Body, SceneError> {
    let field = format!("thermal.{which}_body");
    let material = fx.material(name, &field)?;
    let Some(alpha) = material.thermal_expansion else {
        return Err(fx.ctx.error(
            Some(&name.span()),
            field,
            format!(
                "material `{}` has no thermal_expansion: give `thermal_expansion` [1/K] in its \
                 [[materials]] entry",
                material.name
            ),
        ));
    };
    let origin = match origin {
        Some(o) => fx.finite(o, &format!("thermal.{which}_origin"))?,
        None => Vector3::zeros(),
    };
    Ok(Body { material: material.name, thermal_expansion: alpha, origin })
}

/// The expansion of an element's material `m` (`what` names the element);
/// only a scene's own material can lack one, and the error names its entry.
fn element_expansion(
    f: &SceneFile,
    fx: &Fields,
    m: &Material,
    what: &str,
) -> Result<f64, SceneError> {
    if let Some(alpha) = m.thermal_expansion {
        return Ok(alpha);
    }
    let entry = f.materials.iter().enumerate().rev().find(|(_, e)| *e.name.get_ref() == m.name);
    let (field, span) = match entry {
        Some((i, e)) => (format!("materials[{}].thermal_expansion", i + 1), Some(e.name.span())),
        None => ("thermal".to_string(), None),
    };
    Err(fx.ctx.error(
        span.as_ref(),
        field,
        format!(
            "missing: [thermal] needs the thermal expansion [1/K] of `{}`, the material of {what}",
            m.name
        ),
    ))
}

/// `thermal.path_tolerance`, in [`THERMAL_TOLERANCE_RANGE`] (default
/// [`DEFAULT_THERMAL_TOLERANCE`]).
fn tolerance(t: &ThermalFile, fx: &Fields) -> Result<f64, SceneError> {
    let Some(v) = &t.path_tolerance else {
        return Ok(DEFAULT_THERMAL_TOLERANCE);
    };
    let x = *v.get_ref();
    if THERMAL_TOLERANCE_RANGE.contains(&x) {
        return Ok(x);
    }
    let (lo, hi) = (THERMAL_TOLERANCE_RANGE.start(), THERMAL_TOLERANCE_RANGE.end());
    let reason = format!("{x} is outside {lo:e}..={hi:e} (a relative error of the thermal path)");
    Err(fx.ctx.error(Some(&v.span()), "thermal.path_tolerance", reason))
}

/// `thermal.cycle` ([`cycle_problem`]), each error at its point's line.
fn cycle(t: &ThermalFile, fx: &Fields, allow_large: bool) -> Result<Vec<Temperatures>, SceneError> {
    let points = t.cycle.get_ref();
    let mut values = Vec::with_capacity(points.len());
    for (i, p) in points.iter().enumerate() {
        let field = format!("thermal.cycle[{}]", i + 1);
        values.push(fx.ctx.numbers::<2>(p, &field, "[moving, fixed] in K")?);
    }
    match cycle_problem(&values, allow_large) {
        Some((Some(k), reason)) => {
            let field = format!("thermal.cycle[{}]", k + 1);
            Err(fx.ctx.error(Some(&points[k].span()), field, reason))
        }
        Some((None, reason)) => Err(fx.ctx.error(Some(&t.cycle.span()), "thermal.cycle", reason)),
        None => Ok(values.iter().map(|&[m, f]| Temperatures::new(m, f)).collect()),
    }
}
