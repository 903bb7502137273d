//! Plausibility of a scene's magnitudes: values that look like millimetres
//! (or newtons off by orders of magnitude) typed into an SI file, and below
//! their range values that look like micrometres, GPa or MPa typed as SI,
//! or a support compliance in um/N.
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
use super::file::{CouplingFile, Numbers, SceneFile, SurfaceKind, number};

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

/// Smallest plausible moving-ball diameter [m] (micro-couplings have balls
/// of tens of micrometres; below, a value in nm or um typed as m).
pub const BALL_DIAMETER_MIN: f64 = 1.0e-5;
/// Smallest plausible pin or fixed-ball diameter [m].
pub const ELEMENT_DIAMETER_MIN: f64 = 1.0e-5;
/// Smallest plausible diameter of the circle of ball centres [m].
pub const CIRCLE_DIAMETER_MIN: f64 = 1.0e-4;
/// Smallest plausible total preload [N] (a micronewton: far below the
/// solver's force scale a preload of 1e-300 N is rounding noise).
pub const PRELOAD_MIN: f64 = 1.0e-6;
/// Largest plausible support compliance [m/N]: a millimetre per newton is
/// a soft spring, not a support (um/N typed as m/N is a million times more).
pub const SUPPORT_COMPLIANCE_MAX: f64 = 1.0e-3;
/// Smallest plausible Young's modulus [Pa] (10 MPa, below any polymer a
/// coupling is made of; 200 typed for 200 GPa is far below).
pub const YOUNGS_MODULUS_MIN: f64 = 1.0e7;
/// Smallest plausible allowable stress [Pa] (1 MPa; 1500 typed for
/// 1500 MPa is far below).
pub const ALLOWABLE_STRESS_MIN: f64 = 1.0e6;

/// `x` as typed in a message: plain, or with an exponent when very large
/// or small.
pub fn as_typed(x: f64) -> String {
    if x == 0.0 || (1e-4..1e7).contains(&x.abs()) { format!("{x}") } else { format!("{x:e}") }
}

/// The key that accepts values beyond these bounds.
pub const ALLOW_KEY: &str = "allow_large_values";

/// A value below its plausible range: the hint names the unit it was
/// probably given in.
fn too_small(
    ctx: &ErrorContext,
    span: Option<&std::ops::Range<usize>>,
    field: &str,
    what: String,
    hint: &str,
) -> SceneError {
    ctx.error(
        span,
        field,
        format!(
            "{what}: {hint} scene files are in SI (m, N, Pa); if the value is intended, set \
             `{ALLOW_KEY} = true` at the top of the file"
        ),
    )
}

/// `v` [unit] of `field` below `min`: an error with `hint`.
fn at_least(
    ctx: &ErrorContext,
    v: &Spanned<f64>,
    field: &str,
    (min, unit, what, hint): (f64, &str, &str, &str),
) -> Result<(), SceneError> {
    let x = *v.get_ref();
    if x > 0.0 && x < min {
        return Err(too_small(
            ctx,
            Some(&v.span()),
            field,
            format!(
                "{} {unit} is implausibly small for {what} (limit {} {unit})",
                as_typed(x),
                as_typed(min)
            ),
            hint,
        ));
    }
    Ok(())
}

/// A support compliance [m/N] (either part of it) above
/// [`SUPPORT_COMPLIANCE_MAX`]; its syntax is checked where it is read.
fn support_compliance(
    ctx: &ErrorContext,
    v: &Spanned<toml::Value>,
    field: &str,
) -> Result<(), SceneError> {
    let parts: Vec<f64> = match v.get_ref() {
        toml::Value::Table(t) => t.values().filter_map(number).collect(),
        x => number(x).into_iter().collect(),
    };
    let Some(c) = parts.into_iter().reduce(f64::max) else {
        return Ok(());
    };
    if c > SUPPORT_COMPLIANCE_MAX {
        return Err(ctx.error(
            Some(&v.span()),
            field,
            format!(
                "{} m/N is an implausibly large support compliance (limit \
                 {SUPPORT_COMPLIANCE_MAX} m/N, already a soft spring): did you give um/N or \
                 nm/N? scene files are in SI (m/N); if the value is intended, set \
                 `{ALLOW_KEY} = true` at the top of the file",
                as_typed(c)
            ),
        ));
    }
    Ok(())
}

const LENGTH_HINT: &str = "did you give micrometres or nanometres?";

/// The `[[materials]]` entries: a Young's modulus or an allowable stress
/// that looks like GPa or MPa typed as Pa.
fn check_materials(f: &SceneFile, ctx: &ErrorContext) -> Result<(), SceneError> {
    for (i, m) in f.materials.iter().enumerate() {
        let field = |k: &str| format!("materials[{}].{k}", i + 1);
        let e = *m.youngs_modulus.get_ref();
        at_least(
            ctx,
            &m.youngs_modulus,
            &field("youngs_modulus"),
            (
                YOUNGS_MODULUS_MIN,
                "Pa",
                "a Young's modulus",
                &format!("did you give GPa? {e} GPa is {} Pa;", as_typed(e * 1e9)),
            ),
        )?;
        let allowables = [
            (&m.allowable_pressure, "allowable_pressure"),
            (&m.allowable_shear_stress, "allowable_shear_stress"),
        ];
        for (v, key) in allowables {
            let Some(v) = v else { continue };
            let x = *v.get_ref();
            let hint = format!("did you give MPa? {x} MPa is {} Pa;", as_typed(x * 1e6));
            let what = (ALLOWABLE_STRESS_MIN, "Pa", "an allowable stress", hint.as_str());
            at_least(ctx, v, &field(key), what)?;
        }
    }
    Ok(())
}

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
    limit(&c.diameter, CIRCLE_DIAMETER_MAX, "coupling.diameter", "the circle of ball centres")?;
    limit(&c.ball_diameter, BALL_DIAMETER_MAX, "coupling.ball_diameter", "a ball diameter")?;
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
        limit(r, CANOE_RADIUS_MAX, "coupling.canoe_radius", "a canoe radius")?;
    }
    check_coupling_small(c, ctx)
}

/// The high-level `[coupling]` lengths below their plausible range, and
/// its support compliance.
fn check_coupling_small(c: &CouplingFile, ctx: &ErrorContext) -> Result<(), SceneError> {
    let min = |v, field: &str, min, what| at_least(ctx, v, field, (min, "m", what, LENGTH_HINT));
    min(&c.diameter, "coupling.diameter", CIRCLE_DIAMETER_MIN, "the circle of ball centres")?;
    min(&c.ball_diameter, "coupling.ball_diameter", BALL_DIAMETER_MIN, "a ball diameter")?;
    if let Some(d) = &c.groove_element_diameter {
        min(
            d,
            "coupling.groove_element_diameter",
            ELEMENT_DIAMETER_MIN,
            "a pin or fixed-ball diameter",
        )?;
    }
    match &c.support_compliance {
        Some(v) => support_compliance(ctx, v, "coupling.support_compliance"),
        None => Ok(()),
    }
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
    check_materials(f, ctx)?;
    for (i, (b, c)) in f.balls.iter().zip(centres).enumerate() {
        let d = 2.0 * b.radius.get_ref();
        let field = format!("balls[{}].radius", i + 1);
        let what = "a ball radius";
        at_least(ctx, &b.radius, &field, (BALL_DIAMETER_MIN / 2.0, "m", what, LENGTH_HINT))?;
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
    for (i, e) in f.evaluation_points.iter().enumerate() {
        let r = e.position.get_ref().0.iter().filter_map(number).map(|x| x * x).sum::<f64>().sqrt();
        if r > CIRCLE_DIAMETER_MAX {
            return Err(too_large(
                ctx,
                Some(&e.position.span()),
                &format!("evaluation_points[{}].position", i + 1),
                format!("the point lies {r} m from the origin (limit {CIRCLE_DIAMETER_MAX} m)"),
            ));
        }
    }
    let p = &f.preload;
    let listed = p.forces.iter().enumerate();
    let forces = listed.filter_map(|(i, e)| {
        e.force.as_ref().map(|f| (f, format!("preload.forces[{}].force", i + 1)))
    });
    let single = p.force.iter().map(|v| (v, "preload.force".to_string()));
    for (v, field) in single.chain(forces) {
        let force = *v.get_ref();
        let what = "a preload force";
        at_least(ctx, v, &field, (PRELOAD_MIN, "N", what, "is it in newtons?"))?;
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
        let field = |k: &str| format!("surfaces[{}].{k}", i + 1);
        if let Some(c) = &s.support_compliance {
            support_compliance(ctx, c, &field("support_compliance"))?;
        }
        let (Some(r), SurfaceKind::Cylinder | SurfaceKind::Sphere | SurfaceKind::ConcaveCylinder) =
            (&s.radius, s.kind.get_ref())
        else {
            continue;
        };
        let what = (ELEMENT_DIAMETER_MIN / 2.0, "m", "a pin or fixed-ball radius", LENGTH_HINT);
        at_least(ctx, r, &field("radius"), what)?;
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

/// The largest plausible tolerance of a length, as a share of the smallest
/// moving ball's radius (0.5 mm for a 10 mm ball): beyond it the part is
/// another design, not the drawn one within its tolerance.
pub const TOLERANCE_SHARE_MAX: f64 = 0.1;
/// The largest plausible preload tilt [rad] (about 29 deg).
pub const PRELOAD_TILT_MAX: f64 = 0.5;
/// The largest plausible surface tilt tolerance [rad] (about 5.7 deg).
pub const SURFACE_TILT_MAX: f64 = 0.1;

/// `[variation]` bounds against the coupling's own size (unit slips:
/// millimetres for micrometres, degrees for radians): each length
/// tolerance at most [`TOLERANCE_SHARE_MAX`] of the smallest ball radius
/// `r_min`, the preload offset within the circle of ball centres (radius
/// `reach`), the tilts below [`PRELOAD_TILT_MAX`] and [`SURFACE_TILT_MAX`].
pub fn check_variation(
    v: &crate::scene::file::VariationFile,
    b: &crate::scene::VariationBounds,
    (r_min, reach): (f64, f64),
    ctx: &ErrorContext,
) -> Result<(), SceneError> {
    let tol = TOLERANCE_SHARE_MAX * r_min;
    let tolerance = format!(
        "a tolerance (limit {} m, {} % of the smallest ball radius {r_min} m)",
        as_typed(tol),
        100.0 * TOLERANCE_SHARE_MAX
    );
    let numbers = |s: &Option<Spanned<Numbers>>| s.as_ref().map(|s| s.span());
    let scalar = |s: &Option<Spanned<f64>>| s.as_ref().map(|s| s.span());
    let lengths = [
        ("ball_diameter", b.ball_diameter_m, scalar(&v.ball_diameter), tol, tolerance.as_str()),
        ("surface_normal", b.surface_normal_m, scalar(&v.surface_normal), tol, &tolerance),
        ("ball_position", max(&b.ball_position_m), numbers(&v.ball_position), tol, &tolerance),
        (
            "groove_position",
            max(&b.groove_position_m),
            numbers(&v.groove_position),
            tol,
            &tolerance,
        ),
    ];
    let offset =
        format!("a preload offset (limit {} m, the circle of ball centres)", as_typed(reach));
    let offsets = [(
        "preload_offset",
        max(&b.preload_offset_m),
        numbers(&v.preload_offset),
        reach,
        offset.as_str(),
    )];
    for (key, x, span, limit, what) in lengths.into_iter().chain(offsets) {
        if x > limit {
            let field = format!("variation.{key}");
            let what = format!("{} m is implausibly large for {what}", as_typed(x));
            return Err(too_large(ctx, span.as_ref(), &field, what));
        }
    }
    for (key, x, span, limit) in [
        ("preload_tilt", b.preload_tilt_rad, scalar(&v.preload_tilt), PRELOAD_TILT_MAX),
        ("surface_tilt", b.surface_tilt_rad, scalar(&v.surface_tilt), SURFACE_TILT_MAX),
    ] {
        if x > limit {
            return Err(ctx.error(
                span.as_ref(),
                format!("variation.{key}"),
                format!(
                    "{} rad ({:.1} deg) is implausibly large for a tilt tolerance (limit {limit} \
                     rad): did you give degrees? scene files are in SI (rad); if the value is \
                     intended, set `{ALLOW_KEY} = true` at the top of the file",
                    as_typed(x),
                    x.to_degrees()
                ),
            ));
        }
    }
    Ok(())
}

fn max(v: &[f64]) -> f64 {
    v.iter().copied().fold(0.0, f64::max)
}
