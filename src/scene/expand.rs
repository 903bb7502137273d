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
//! groove, a fixed ball centred at c - (r + R_ball) n.

use nalgebra::Vector3;

use crate::material::Material;
use toml::Spanned;

use super::error::{ErrorContext, SceneError};
use super::file::{
    Arrangement, BallFile, CouplingFile, EvaluationPointFile, GrooveKind, Numbers, SceneFile,
    SurfaceFile, SurfaceKind,
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
    /// Ball radius and pin or fixed-ball radius (0 for planes) [m].
    r_ball: f64,
    r_elem: f64,
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
    let r_elem = match (c.groove, &c.groove_element_diameter) {
        (GrooveKind::Planes, _) => 0.0,
        (_, Some(d)) => positive(d, "coupling.groove_element_diameter")? / 2.0,
        (kind, None) => {
            return Err(ctx.error(
                None,
                "coupling.groove_element_diameter",
                format!(
                    "missing: groove = \"{}\" needs the pin or ball diameter",
                    groove_name(kind)
                ),
            ));
        }
    };
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
        alpha: (90.0 - opening / 2.0).to_radians(),
    })
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
    /// The Kelvin flat: a plane whatever the groove kind.
    flat: bool,
}

/// The contacts, ball by ball, with the normals of the module docs.
fn contacts(arrangement: Arrangement, centres: &[Vector3<f64>], alpha: f64) -> Vec<ContactSpec> {
    let ez = Vector3::z();
    let tilt = |horizontal: Vector3<f64>| horizontal * alpha.sin() + ez * alpha.cos();
    let contact = |ball, normal, axis, flat| ContactSpec {
        ball,
        normal,
        axis,
        flat,
    };
    let mut out = Vec::new();
    match arrangement {
        Arrangement::Maxwell => {
            for (k, ck) in centres.iter().enumerate() {
                let er = Vector3::new(ck.x, ck.y, 0.0).normalize();
                let s = ez.cross(&er);
                out.push(contact(k, tilt(s), er, false));
                out.push(contact(k, tilt(-s), er, false));
            }
        }
        Arrangement::Kelvin => {
            let er = Vector3::new(centres[0].x, centres[0].y, 0.0).normalize();
            for j in 0..3 {
                let ang = (120.0 * j as f64).to_radians();
                // direction from ball 1 to fixed element j: -e_r rotated by +120 j about z
                let d = rotate_z(&(-er), ang);
                // pins of the trihedral seat lie horizontal, across the element direction
                out.push(contact(0, tilt(-d), ez.cross(&d), false));
            }
            let u = (centres[0] - centres[1]).normalize();
            let s = ez.cross(&u);
            out.push(contact(1, tilt(s), u, false));
            out.push(contact(1, tilt(-s), u, false));
            out.push(contact(2, ez, Vector3::x(), true));
        }
    }
    out
}

/// The fixed element of contact `k`, touching its ball (centre `ck`) at zero gap.
fn surface(c: &CouplingFile, dims: &Dimensions, k: &ContactSpec, ck: &Vector3<f64>) -> SurfaceFile {
    let arr = |v: Vector3<f64>| Some(Spanned::new(0..0, Numbers::of(&[v.x, v.y, v.z])));
    let (n, r_ball, r_elem) = (k.normal, dims.r_ball, dims.r_elem);
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
    };
    match (c.groove, k.flat) {
        (GrooveKind::Planes, _) | (_, true) => {
            s.point = arr(ck - n * r_ball);
            s.normal = arr(n);
        }
        (GrooveKind::Cylinders, false) => {
            s.kind = Spanned::new(0..0, SurfaceKind::Cylinder);
            s.axis_point = arr(ck - n * (r_ball + r_elem));
            s.direction = arr(k.axis);
            s.radius = Some(Spanned::new(0..0, r_elem));
        }
        (GrooveKind::Balls, false) => {
            s.kind = Spanned::new(0..0, SurfaceKind::Sphere);
            s.centre = arr(ck - n * (r_ball + r_elem));
            s.radius = Some(Spanned::new(0..0, r_elem));
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
    }
}
