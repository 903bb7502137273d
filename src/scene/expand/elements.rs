//! The `[coupling]` table checked: dimensions, the elements of the grooves
//! and of the Kelvin seat, and the moving elements (balls, canoe balls or
//! crossed pins), with errors naming the high-level fields.

use toml::Spanned;

use crate::material::Material;
use crate::scene::error::{ErrorContext, SceneError};
use crate::scene::file::{Arrangement, BallShape, CouplingFile, GrooveKind, SceneFile};
use crate::scene::plausible;

/// The checked dimensions of a `[coupling]` table.
pub(super) struct Dimensions {
    /// Circle of ball centres [m].
    pub(super) diameter: f64,
    /// Ball radius and pin or fixed-ball radius (0 if neither is used) [m].
    pub(super) r_ball: f64,
    pub(super) r_elem: f64,
    /// Gothic-arch flank radius (0 if none is used) [m].
    pub(super) r_groove: f64,
    /// The elements of the grooves and of the Kelvin seat.
    pub(super) groove: GrooveKind,
    pub(super) seat: GrooveKind,
    /// The moving elements' contact surfaces.
    pub(super) moving: Moving,
    /// Angle between a contact normal and z: 90 deg - opening/2 [rad].
    pub(super) alpha: f64,
}

/// `[coupling]` checked, with errors naming its high-level fields.
pub(super) fn check_coupling(
    raw: &SceneFile,
    c: &CouplingFile,
    ctx: &ErrorContext,
) -> Result<Dimensions, SceneError> {
    if !raw.balls.is_empty() || !raw.surfaces.is_empty() {
        return Err(ctx.error(
            None,
            "coupling",
            "give either the high-level [coupling] table or explicit [[balls]] and [[surfaces]], not both",
        ));
    }
    let positive = |v: &Spanned<f64>, field: &str| ctx.positive(v, field, "a length in m");
    // Materials are checked here so that errors name the high-level field.
    for (m, field) in [
        (&c.ball_material, "coupling.ball_material"),
        (&c.groove_material, "coupling.groove_material"),
    ] {
        let name = m.get_ref();
        if !raw.materials.iter().any(|u| u.name.get_ref() == name) {
            Material::builtin(name)
                .map_err(|e| ctx.error(Some(&m.span()), field, e.to_string()))?;
        }
    }
    if let Some(v) = &c.support_compliance {
        crate::scene::resolve::support(ctx, v, "coupling.support_compliance", false)?;
    }
    let diameter = positive(&c.diameter, "coupling.diameter")?;
    plausible::check_coupling(c, raw.allow_large_values, ctx)?;
    let r_ball = positive(&c.ball_diameter, "coupling.ball_diameter")? / 2.0;
    let (groove, seat) = kinds(c);
    let (r_elem, r_groove) = element_radii(c, groove, seat, r_ball, ctx)?;
    let moving = moving(c, (r_ball, r_groove), groove, ctx)?;
    let opening = *c.opening_angle_deg.get_ref();
    if !(opening > 0.0 && opening < 180.0) {
        return Err(ctx.error(
            Some(&c.opening_angle_deg.span()),
            "coupling.opening_angle_deg",
            format!("{opening} must lie strictly between 0 and 180 degrees"),
        ));
    }
    let alpha = (90.0 - opening / 2.0).to_radians();
    fixed_elements_apart(c, (groove, seat), (r_ball, r_elem), alpha, ctx)?;
    // Balls 120 deg apart on the circle of radius D/2 are D sqrt(3)/2 apart
    // (centre to centre); two touch when their diameter reaches that.
    let spacing = diameter * 3f64.sqrt() / 2.0;
    if 2.0 * r_ball >= spacing {
        return Err(ctx.error(
            Some(&c.ball_diameter.span()),
            "coupling.ball_diameter",
            format!(
                "{} m: the balls overlap: it must be smaller than {spacing:.6} m, the distance \
                 between ball centres 120 deg apart on the {diameter} m circle (diameter x sqrt(3)/2)",
                2.0 * r_ball
            ),
        ));
    }
    Ok(Dimensions { diameter, r_ball, r_elem, r_groove, groove, seat, moving, alpha })
}

/// The fixed pins or balls of one ball must not overlap. Each touches the
/// ball (radius r) at zero gap, so its axis or centre lies r + R from the
/// ball's centre along the contact normal, alpha from z. The two of a V
/// are 2 (r + R) sin(alpha) apart; the three balls of Kelvin's trihedral
/// seat sqrt(3) (r + R) sin(alpha). Apart means at least 2R, i.e.
/// R <= r s / (1 - s) for a V and R <= sqrt(3) r s / (2 - sqrt(3) s) for
/// the seat (s = sin(alpha)). (A seat of three pins is not checked: its
/// pins, finite in a real seat, are lines here that cross.)
fn fixed_elements_apart(
    c: &CouplingFile,
    (groove, seat): (GrooveKind, GrooveKind),
    (r, big_r): (f64, f64),
    alpha: f64,
    ctx: &ErrorContext,
) -> Result<(), SceneError> {
    let s = alpha.sin();
    let element = |k: GrooveKind| if k == GrooveKind::Balls { "balls" } else { "pins" };
    let pinned = |k: GrooveKind| matches!(k, GrooveKind::Cylinders | GrooveKind::Balls);
    let mut limits = Vec::new();
    if pinned(groove) {
        limits.push((format!("the two {} of each V", element(groove)), 2.0, r * s / (1.0 - s)));
    }
    if c.arrangement == Arrangement::Kelvin && seat == GrooveKind::Balls {
        let k = 3f64.sqrt();
        limits.push(("the three balls of the trihedral seat".into(), k, k * r * s / (2.0 - k * s)));
    }
    for (what, factor, max_r) in limits {
        if big_r > max_r {
            let d = c.groove_element_diameter.as_ref();
            return Err(ctx.error(
                d.map(|d| d.span()).as_ref(),
                "coupling.groove_element_diameter",
                format!(
                    "{} m: {what} overlap: touching a {} m ball they stand {:.6} m apart \
                     (centre to centre, at opening_angle_deg {}), less than their diameter; \
                     it must be at most {:.6} m",
                    2.0 * big_r,
                    2.0 * r,
                    factor * (r + big_r) * s,
                    c.opening_angle_deg.get_ref(),
                    2.0 * max_r
                ),
            ));
        }
    }
    Ok(())
}

/// The elements of the grooves and of the Kelvin seat (module docs of
/// `coupling.seat`: the groove's, or planes for a gothic-arch groove).
fn kinds(c: &CouplingFile) -> (GrooveKind, GrooveKind) {
    let seat = match (c.arrangement, c.seat, c.groove) {
        (Arrangement::Maxwell, _, g) => g,
        (Arrangement::Kelvin, Some(s), _) => s,
        (Arrangement::Kelvin, None, GrooveKind::GothicArch) => GrooveKind::Planes,
        (Arrangement::Kelvin, None, g) => g,
    };
    (c.groove, seat)
}

/// The moving element at each contact (`coupling.ball_shape`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub(super) enum Moving {
    Sphere,
    /// A canoe patch of this radius [m].
    Canoe(f64),
    /// A pin of the ball's radius across the fixed pin.
    Pins,
}

/// The moving element, checked: a canoe needs `canoe_radius`, at least the
/// ball's radius `r_ball` (its faces are flatter than the ball it
/// replaces), and in a gothic arch a patch curved more than the flank
/// (R_c < R_g), or the two do not touch at a point; crossed pins need a fixed pin at every contact
/// (a pin on a plane touches along a line).
fn moving(
    c: &CouplingFile,
    (r_ball, r_groove): (f64, f64),
    groove: GrooveKind,
    ctx: &ErrorContext,
) -> Result<Moving, SceneError> {
    match c.ball_shape.unwrap_or_default() {
        BallShape::Sphere => Ok(Moving::Sphere),
        BallShape::Pins => {
            let pins = GrooveKind::Cylinders;
            if groove != pins || (c.arrangement == Arrangement::Kelvin) {
                let why = if groove != pins {
                    format!("groove = \"{}\"", groove_name(groove))
                } else {
                    "the Kelvin flat".to_string()
                };
                return Err(ctx.error(
                    None,
                    "coupling.ball_shape",
                    format!(
                        "crossed pins need a fixed pin at every contact (groove = \"cylinders\", \
                         Maxwell): a moving pin on {why} does not touch at a point"
                    ),
                ));
            }
            Ok(Moving::Pins)
        }
        BallShape::Canoe => {
            let Some(v) = &c.canoe_radius else {
                return Err(ctx.error(
                    None,
                    "coupling.canoe_radius",
                    "missing: ball_shape = \"canoe\" needs the patch radius `canoe_radius`",
                ));
            };
            let rc = ctx.positive(v, "coupling.canoe_radius", "a length in m")?;
            if rc < r_ball {
                return Err(ctx.error(
                    Some(&v.span()),
                    "coupling.canoe_radius",
                    format!(
                        "{rc} m is below the ball radius {r_ball} m (ball_diameter / 2): a canoe \
                         ball's faces are flatter than the ball they replace; a more curved face \
                         is a smaller ball (give that ball_diameter)"
                    ),
                ));
            }
            if r_groove > 0.0 && rc >= r_groove {
                return Err(ctx.error(
                    Some(&v.span()),
                    "coupling.canoe_radius",
                    format!(
                        "{rc} m must be smaller than groove_radius {r_groove} m: a canoe patch in \
                         a gothic arch touches it at a point only if the patch is curved more \
                         than the flank"
                    ),
                ));
            }
            Ok(Moving::Canoe(rc))
        }
    }
}

/// The pin or fixed-ball radius and the gothic-arch flank radius (each 0
/// when neither the grooves nor the Kelvin seat use it), checked.
fn element_radii(
    c: &CouplingFile,
    groove: GrooveKind,
    seat: GrooveKind,
    r_ball: f64,
    ctx: &ErrorContext,
) -> Result<(f64, f64), SceneError> {
    let positive = |v: &Spanned<f64>, field: &str| ctx.positive(v, field, "a length in m");
    // The first of groove and seat that is one of `want`, and the missing-field
    // error naming it.
    let needing = |want: [GrooveKind; 2]| {
        let key = |k: GrooveKind| if k == groove { "groove" } else { "seat" };
        [groove, seat].into_iter().find(|k| want.contains(k)).map(|k| {
            move |field: &str, what: &str| {
                ctx.error(
                    None,
                    field,
                    format!("missing: {} = \"{}\" needs {what}", key(k), groove_name(k)),
                )
            }
        })
    };
    let r_elem = match needing([GrooveKind::Cylinders, GrooveKind::Balls]) {
        None => 0.0,
        Some(missing) => {
            let d = (c.groove_element_diameter.as_ref()).ok_or_else(|| {
                missing("coupling.groove_element_diameter", "the pin or ball diameter")
            })?;
            positive(d, "coupling.groove_element_diameter")? / 2.0
        }
    };
    let r_groove = if let Some(missing) = needing([GrooveKind::GothicArch; 2]) {
        let g = (c.groove_radius.as_ref())
            .ok_or_else(|| missing("coupling.groove_radius", "the flank radius `groove_radius`"))?;
        let rg = positive(g, "coupling.groove_radius")?;
        if rg <= r_ball {
            return Err(ctx.error(
                Some(&g.span()),
                "coupling.groove_radius",
                format!(
                    "{rg} m must exceed the ball radius {r_ball} m: each gothic-arch flank is \
                     a concave arc that holds the ball inside it"
                ),
            ));
        }
        rg
    } else {
        0.0
    };
    Ok((r_elem, r_groove))
}

fn groove_name(k: GrooveKind) -> &'static str {
    match k {
        GrooveKind::Planes => "planes",
        GrooveKind::Cylinders => "cylinders",
        GrooveKind::Balls => "balls",
        GrooveKind::GothicArch => "gothic-arch",
    }
}
