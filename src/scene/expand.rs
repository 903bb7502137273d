//! Expansion of the high-level form into the explicit one, following the
//! axes and contact numbering of docs/model.md.
//!
//! With alpha = 90 deg - opening/2 the angle between a contact normal and z:
//! - Maxwell, ball k with radial unit vector e_r and s = e_z x e_r: contact
//!   2k-1 has normal sin(alpha) s + cos(alpha) e_z, contact 2k has
//!   -sin(alpha) s + cos(alpha) e_z.
//! - Kelvin: ball 1 in a trihedral seat whose elements lie radially inward
//!   and at +120, +240 deg around the ball (counter-clockwise seen from +z),
//!   each normal tilted by alpha towards the ball; ball 2 in a V whose axis
//!   points at ball 1 (as Maxwell with e_r replaced by the unit vector from
//!   ball 2 to ball 1); ball 3 on a flat (normal e_z).
//!
//! Each fixed element is placed so that its ball touches it at zero gap:
//! a plane through c - r n, a pin axis through c - (r + R_pin) n along the
//! groove, a fixed ball centred at c - (r + R_ball) n, a gothic-arch flank
//! (concave cylinder of radius R_g > r) with its axis through
//! c + (R_g - r) n along the groove. A canoe ball's patch of radius R_c at
//! each contact touches there too: its centre of curvature is
//! c + (R_c - r) n, on the contact normal through the ball's contact point
//! c - r n. Crossed pins put at each contact a pin of radius r whose axis
//! passes through c along n x (the fixed pin's axis).

use nalgebra::Vector3;

use crate::material::Material;
use toml::Spanned;

use super::error::{ErrorContext, SceneError};
use super::file::{
    Arrangement, BallFile, BallShape, CouplingFile, EvaluationPointFile, GrooveKind, Numbers,
    SceneFile, SurfaceFile, SurfaceKind,
};
use super::plausible;

/// Azimuths of balls 1, 2, 3 [deg].
pub const BALL_AZIMUTHS_DEG: [f64; 3] = [90.0, 210.0, 330.0];

/// The explicit form of a scene file (unchanged if it is explicit already).
pub fn to_explicit(raw: &SceneFile, ctx: &ErrorContext) -> Result<SceneFile, SceneError> {
    let Some(c) = &raw.coupling else {
        return Ok(raw.clone());
    };
    let dims = check_coupling(raw, c, ctx)?;
    let centres = ball_centres(dims.diameter);
    let balls = centres
        .iter()
        .map(|ck| BallFile {
            centre: Spanned::new(0..0, Numbers::of(&[ck.x, ck.y, ck.z])),
            radius: Spanned::new(0..0, dims.r_ball),
            material: c.ball_material.clone(),
        })
        .collect();
    let surfaces = contacts(c.arrangement, &centres, dims.alpha)
        .into_iter()
        .map(|k| surface(c, &dims, &k, &centres[k.ball]))
        .collect();
    Ok(SceneFile {
        coupling: None,
        balls,
        surfaces,
        evaluation_points: evaluation_points(raw, c, &centres),
        ..raw.clone()
    })
}

/// The checked dimensions of a `[coupling]` table.
struct Dimensions {
    /// Circle of ball centres [m].
    diameter: f64,
    /// Ball radius and pin or fixed-ball radius (0 if neither is used) [m].
    r_ball: f64,
    r_elem: f64,
    /// Gothic-arch flank radius (0 if none is used) [m].
    r_groove: f64,
    /// The elements of the grooves and of the Kelvin seat.
    groove: GrooveKind,
    seat: GrooveKind,
    /// The moving elements' contact surfaces.
    moving: Moving,
    /// Angle between a contact normal and z: 90 deg - opening/2 [rad].
    alpha: f64,
}

/// `[coupling]` checked, with errors naming its high-level fields.
fn check_coupling(
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
        super::resolve::compliance(ctx, v, "coupling.support_compliance")?;
    }
    let diameter = positive(&c.diameter, "coupling.diameter")?;
    plausible::check_coupling(c, raw.allow_large_values, ctx)?;
    let r_ball = positive(&c.ball_diameter, "coupling.ball_diameter")? / 2.0;
    let (groove, seat) = kinds(c);
    // The first of groove and seat that is one of `want`, and the missing-field
    // error naming it.
    let needing = |want: [GrooveKind; 2]| {
        let key = |k: GrooveKind| if k == groove { "groove" } else { "seat" };
        [groove, seat]
            .into_iter()
            .find(|k| want.contains(k))
            .map(|k| {
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
                missing(
                    "coupling.groove_element_diameter",
                    "the pin or ball diameter",
                )
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
    let moving = moving(c, r_groove, groove, ctx)?;
    let opening = *c.opening_angle_deg.get_ref();
    if !(opening > 0.0 && opening < 180.0) {
        return Err(ctx.error(
            Some(&c.opening_angle_deg.span()),
            "coupling.opening_angle_deg",
            format!("{opening} must lie strictly between 0 and 180 degrees"),
        ));
    }
    if r_ball >= diameter / 2.0 {
        return Err(ctx.error(
            Some(&c.ball_diameter.span()),
            "coupling.ball_diameter",
            "the balls overlap: ball diameter must be smaller than the coupling diameter",
        ));
    }
    Ok(Dimensions {
        diameter,
        r_ball,
        r_elem,
        r_groove,
        groove,
        seat,
        moving,
        alpha: (90.0 - opening / 2.0).to_radians(),
    })
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
enum Moving {
    Sphere,
    /// A canoe patch of this radius [m].
    Canoe(f64),
    /// A pin of the ball's radius across the fixed pin.
    Pins,
}

/// The moving element, checked: a canoe needs `canoe_radius`, and in a
/// gothic arch a patch curved more than the flank (R_c < R_g), or the two
/// do not touch at a point; crossed pins need a fixed pin at every contact
/// (a pin on a plane touches along a line).
fn moving(
    c: &CouplingFile,
    r_groove: f64,
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

/// Centres of balls 1, 2, 3 on the circle of `diameter`, at [`BALL_AZIMUTHS_DEG`].
fn ball_centres(diameter: f64) -> Vec<Vector3<f64>> {
    BALL_AZIMUTHS_DEG
        .iter()
        .map(|a| {
            let t = a.to_radians();
            Vector3::new(t.cos(), t.sin(), 0.0) * (diameter / 2.0)
        })
        .collect()
}

/// One contact of the expanded coupling.
struct ContactSpec {
    ball: usize,
    /// Contact normal (unit, from the fixed element to the ball).
    normal: Vector3<f64>,
    /// Groove axis direction (the pin's axis for cylinders).
    axis: Vector3<f64>,
    /// Which element: a groove's, the Kelvin seat's, or the Kelvin flat.
    role: Role,
}

/// The part of the coupling a contact belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
enum Role {
    Groove,
    Seat,
    Flat,
}

/// The contacts, ball by ball, with the normals of the module docs.
fn contacts(arrangement: Arrangement, centres: &[Vector3<f64>], alpha: f64) -> Vec<ContactSpec> {
    let ez = Vector3::z();
    let tilt = |horizontal: Vector3<f64>| horizontal * alpha.sin() + ez * alpha.cos();
    let contact = |ball, normal, axis, role| ContactSpec {
        ball,
        normal,
        axis,
        role,
    };
    let mut out = Vec::new();
    match arrangement {
        Arrangement::Maxwell => {
            for (k, ck) in centres.iter().enumerate() {
                let er = Vector3::new(ck.x, ck.y, 0.0).normalize();
                let s = ez.cross(&er);
                out.push(contact(k, tilt(s), er, Role::Groove));
                out.push(contact(k, tilt(-s), er, Role::Groove));
            }
        }
        Arrangement::Kelvin => {
            let er = Vector3::new(centres[0].x, centres[0].y, 0.0).normalize();
            for j in 0..3 {
                let ang = (120.0 * j as f64).to_radians();
                // direction from ball 1 to fixed element j: -e_r rotated by +120 j about z
                let d = rotate_z(&(-er), ang);
                // pins of the trihedral seat lie horizontal, across the element direction
                out.push(contact(0, tilt(-d), ez.cross(&d), Role::Seat));
            }
            let u = (centres[0] - centres[1]).normalize();
            let s = ez.cross(&u);
            out.push(contact(1, tilt(s), u, Role::Groove));
            out.push(contact(1, tilt(-s), u, Role::Groove));
            out.push(contact(2, ez, Vector3::x(), Role::Flat));
        }
    }
    out
}

/// The fixed element of contact `k`, touching its ball (centre `ck`) at
/// zero gap, with the canoe patch if the balls are canoes.
fn surface(c: &CouplingFile, dims: &Dimensions, k: &ContactSpec, ck: &Vector3<f64>) -> SurfaceFile {
    let arr = |v: Vector3<f64>| Some(Spanned::new(0..0, Numbers::of(&[v.x, v.y, v.z])));
    let length = |v: f64| Some(Spanned::new(0..0, v));
    let (n, r_ball) = (k.normal, dims.r_ball);
    let mut s = SurfaceFile {
        kind: Spanned::new(0..0, SurfaceKind::Plane),
        ball: Spanned::new(0..0, k.ball as i64 + 1),
        material: c.groove_material.clone(),
        point: None,
        normal: None,
        axis_point: None,
        direction: None,
        centre: None,
        radius: None,
        support_compliance: c.support_compliance.clone(),
        moving_centre: None,
        moving_radius: None,
        moving_direction: None,
    };
    let kind = match k.role {
        Role::Flat => GrooveKind::Planes,
        Role::Seat => dims.seat,
        Role::Groove => dims.groove,
    };
    match kind {
        GrooveKind::Planes => {
            s.point = arr(ck - n * r_ball);
            s.normal = arr(n);
        }
        GrooveKind::Cylinders => {
            s.kind = Spanned::new(0..0, SurfaceKind::Cylinder);
            s.axis_point = arr(ck - n * (r_ball + dims.r_elem));
            s.direction = arr(k.axis);
            s.radius = length(dims.r_elem);
        }
        GrooveKind::Balls => {
            s.kind = Spanned::new(0..0, SurfaceKind::Sphere);
            s.centre = arr(ck - n * (r_ball + dims.r_elem));
            s.radius = length(dims.r_elem);
        }
        GrooveKind::GothicArch => {
            s.kind = Spanned::new(0..0, SurfaceKind::ConcaveCylinder);
            s.axis_point = arr(ck + n * (dims.r_groove - r_ball));
            s.direction = arr(k.axis);
            s.radius = length(dims.r_groove);
        }
    }
    match dims.moving {
        Moving::Sphere => {}
        Moving::Canoe(rc) => {
            s.moving_centre = arr(ck + n * (rc - r_ball));
            s.moving_radius = length(rc);
        }
        Moving::Pins => {
            // A pin of the ball's radius touching at c - r n: its axis
            // passes through c, across the fixed pin (crossed at 90 deg).
            s.moving_centre = arr(*ck);
            s.moving_radius = length(r_ball);
            s.moving_direction = arr(n.cross(&k.axis).normalize());
        }
    }
    s
}

/// The file's evaluation points, or the centre (and, for Kelvin, the
/// trihedral ball) when it names none.
fn evaluation_points(
    raw: &SceneFile,
    c: &CouplingFile,
    centres: &[Vector3<f64>],
) -> Vec<EvaluationPointFile> {
    let mut points = raw.evaluation_points.clone();
    if points.is_empty() {
        points.push(EvaluationPointFile {
            name: "centre".to_string(),
            position: Spanned::new(0..0, Numbers::of(&[0.0; 3])),
        });
        if c.arrangement == Arrangement::Kelvin {
            let c1 = centres[0];
            points.push(EvaluationPointFile {
                name: "trihedral ball".to_string(),
                position: Spanned::new(0..0, Numbers::of(&[c1.x, c1.y, c1.z])),
            });
        }
    }
    points
}

fn rotate_z(v: &Vector3<f64>, angle: f64) -> Vector3<f64> {
    let (s, c) = angle.sin_cos();
    Vector3::new(c * v.x - s * v.y, s * v.x + c * v.y, v.z)
}

fn groove_name(k: GrooveKind) -> &'static str {
    match k {
        GrooveKind::Planes => "planes",
        GrooveKind::Cylinders => "cylinders",
        GrooveKind::Balls => "balls",
        GrooveKind::GothicArch => "gothic-arch",
    }
}
