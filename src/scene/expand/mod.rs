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

mod elements;

use nalgebra::Vector3;
use toml::Spanned;

use super::error::{ErrorContext, SceneError};
use super::file::{
    Arrangement, BallFile, CouplingFile, EvaluationPointFile, GrooveKind, Numbers, SceneFile,
    SurfaceFile, SurfaceKind,
};
use elements::{Dimensions, Moving, check_coupling};

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
    let contact = |ball, normal, axis, role| ContactSpec { ball, normal, axis, role };
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
        support_compliance: c.support_compliance.as_ref().map(|v| oriented(v, k, ck)),
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

/// A support compliance with `along` and `across` gets the axis of
/// `along`: the groove's (a V's, a pin's, a gothic arch's), a trihedral
/// element's horizontal line, or for Kelvin's flat the radial direction of
/// its ball (docs/scenes.md).
fn oriented(v: &Spanned<toml::Value>, k: &ContactSpec, ck: &Vector3<f64>) -> Spanned<toml::Value> {
    let toml::Value::Table(t) = v.get_ref() else {
        return v.clone();
    };
    if !(t.contains_key("along") || t.contains_key("across")) {
        return v.clone();
    }
    let axis = match k.role {
        Role::Flat => Vector3::new(ck.x, ck.y, 0.0).normalize(),
        Role::Groove | Role::Seat => k.axis,
    };
    let mut t = t.clone();
    let numbers = [axis.x, axis.y, axis.z].map(toml::Value::Float);
    t.insert("axis".into(), toml::Value::Array(numbers.to_vec()));
    Spanned::new(v.span(), toml::Value::Table(t))
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
            name: Spanned::new(0..0, "centre".to_string()),
            position: Spanned::new(0..0, Numbers::of(&[0.0; 3])),
            directions: Vec::new(),
            frame: None,
        });
        if c.arrangement == Arrangement::Kelvin {
            let c1 = centres[0];
            points.push(EvaluationPointFile {
                name: Spanned::new(0..0, "trihedral ball".to_string()),
                position: Spanned::new(0..0, Numbers::of(&[c1.x, c1.y, c1.z])),
                directions: Vec::new(),
                frame: None,
            });
        }
    }
    points
}

fn rotate_z(v: &Vector3<f64>, angle: f64) -> Vector3<f64> {
    let (s, c) = angle.sin_cos();
    Vector3::new(c * v.x - s * v.y, s * v.x + c * v.y, v.z)
}
