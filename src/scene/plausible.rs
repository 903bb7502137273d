//! Plausibility of a scene's magnitudes: values that look like millimetres
//! (or newtons off by orders of magnitude) typed into an SI file.
//!
//! Kinematic couplings are built from balls of millimetres to a few
//! centimetres on circles of centimetres to a metre, preloaded with newtons
//! to kilonewtons. A value far outside that, e.g. `diameter = 80` (80 mm
//! meant), is an error with a hint, unless the scene says
//! `allow_large_values = true` at its top. The bounds are generous
//! (an order of magnitude beyond the largest couplings in Slocum 1992 and
//! Hale 1999) so that no real design trips them.

use nalgebra::Vector3;
use toml::Spanned;

use super::error::{ErrorContext, SceneError};
use super::file::{CouplingFile, SceneFile, SurfaceKind};

/// Largest plausible moving-ball diameter [m].
pub const BALL_DIAMETER_MAX: f64 = 0.5;
/// Largest plausible pin or fixed-ball diameter [m].
pub const ELEMENT_DIAMETER_MAX: f64 = 0.5;
/// Largest plausible radius of a canoe ball's patch [m] (Slocum's canoe
/// balls have radii of a quarter to about one metre).
pub const CANOE_RADIUS_MAX: f64 = 10.0;
/// Largest plausible diameter of the circle of ball centres [m].
pub const CIRCLE_DIAMETER_MAX: f64 = 5.0;
/// Largest plausible total preload [N].
pub const PRELOAD_MAX: f64 = 1.0e6;

/// The key that accepts values beyond these bounds.
pub const ALLOW_KEY: &str = "allow_large_values";

fn too_large(
    ctx: &ErrorContext,
    span: Option<&std::ops::Range<usize>>,
    field: &str,
    what: String,
) -> SceneError {
    ctx.error(
        span,
        field,
        format!(
            "{what}: did you give millimetres? scene files are in SI (m, N, Pa); if the \
             value is intended, set `{ALLOW_KEY} = true` at the top of the file"
        ),
    )
}

/// The high-level `[coupling]` table (checked before expansion, so that the
/// error names the key as written).
pub fn check_coupling(c: &CouplingFile, allow: bool, ctx: &ErrorContext) -> Result<(), SceneError> {
    if allow {
        return Ok(());
    }
    let limit = |v: &Spanned<f64>, max: f64, field: &str, what: &str| {
        let x = *v.get_ref();
        if x > max {
            Err(too_large(
                ctx,
                Some(&v.span()),
                field,
                format!("{x} m is implausibly large for {what} (limit {max} m)"),
            ))
        } else {
            Ok(())
        }
    };
    limit(
        &c.diameter,
        CIRCLE_DIAMETER_MAX,
        "coupling.diameter",
        "the circle of ball centres",
    )?;
    limit(
        &c.ball_diameter,
        BALL_DIAMETER_MAX,
        "coupling.ball_diameter",
        "a ball diameter",
    )?;
    if let Some(d) = &c.groove_element_diameter {
        limit(
            d,
            ELEMENT_DIAMETER_MAX,
            "coupling.groove_element_diameter",
            "a pin or fixed-ball diameter",
        )?;
    }
    if let Some(r) = &c.groove_radius {
        limit(
            r,
            ELEMENT_DIAMETER_MAX / 2.0,
            "coupling.groove_radius",
            "a gothic-arch flank radius",
        )?;
    }
    if let Some(r) = &c.canoe_radius {
        limit(
            r,
            CANOE_RADIUS_MAX,
            "coupling.canoe_radius",
            "a canoe radius",
        )?;
    }
    Ok(())
}

/// The explicit form: ball and element radii, the ball centres' distance
/// from the origin (the centre of the circle of balls), the preload.
/// `centres` are the resolved ball centres, in the order of `f.balls`.
pub fn check_explicit(
    f: &SceneFile,
    centres: &[Vector3<f64>],
    ctx: &ErrorContext,
) -> Result<(), SceneError> {
    if f.allow_large_values {
        return Ok(());
    }
    for (i, (b, c)) in f.balls.iter().zip(centres).enumerate() {
        let d = 2.0 * b.radius.get_ref();
        if d > BALL_DIAMETER_MAX {
            return Err(too_large(
                ctx,
                Some(&b.radius.span()),
                &format!("balls[{}].radius", i + 1),
                format!(
                    "a ball diameter of {d} m is implausibly large (limit {BALL_DIAMETER_MAX} m)"
                ),
            ));
        }
        let r = c.norm();
        if 2.0 * r > CIRCLE_DIAMETER_MAX {
            return Err(too_large(
                ctx,
                Some(&b.centre.span()),
                &format!("balls[{}].centre", i + 1),
                format!(
                    "the ball centre lies {r} m from the origin, a circle of balls of {} m \
                     (limit {CIRCLE_DIAMETER_MAX} m)",
                    2.0 * r
                ),
            ));
        }
    }
    check_surfaces(f, ctx)?;
    let p = &f.preload;
    let listed = p.forces.iter().enumerate();
    let forces = listed.map(|(i, e)| (&e.force, format!("preload.forces[{}].force", i + 1)));
    let single = p.force.iter().map(|v| (v, "preload.force".to_string()));
    for (v, field) in single.chain(forces) {
        let force = *v.get_ref();
        if force > PRELOAD_MAX {
            return Err(too_large(
                ctx,
                Some(&v.span()),
                &field,
                format!("{force} N is an implausibly large preload (limit {PRELOAD_MAX} N)"),
            ));
        }
    }
    Ok(())
}

/// The explicit surfaces' radii: pins, fixed balls and gothic-arch flanks,
/// and the moving patches (canoe faces, moving pins).
fn check_surfaces(f: &SceneFile, ctx: &ErrorContext) -> Result<(), SceneError> {
    for (i, s) in f.surfaces.iter().enumerate() {
        let (Some(r), SurfaceKind::Cylinder | SurfaceKind::Sphere | SurfaceKind::ConcaveCylinder) =
            (&s.radius, s.kind.get_ref())
        else {
            continue;
        };
        let d = 2.0 * r.get_ref();
        if d > ELEMENT_DIAMETER_MAX {
            return Err(too_large(
                ctx,
                Some(&r.span()),
                &format!("surfaces[{}].radius", i + 1),
                format!(
                    "a pin or fixed-ball diameter of {d} m is implausibly large (limit \
                     {ELEMENT_DIAMETER_MAX} m)"
                ),
            ));
        }
    }
    for (i, s) in f.surfaces.iter().enumerate() {
        let Some(r) = &s.moving_radius else { continue };
        if *r.get_ref() > CANOE_RADIUS_MAX {
            return Err(too_large(
                ctx,
                Some(&r.span()),
                &format!("surfaces[{}].moving_radius", i + 1),
                format!(
                    "a moving patch radius of {} m is implausibly large (limit {CANOE_RADIUS_MAX} m)",
                    r.get_ref()
                ),
            ));
        }
    }
    Ok(())
}
