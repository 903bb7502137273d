//! The fields a sweep may set, by their TOML path in the high-level scene
//! (docs/scenes.md), and setting one in the parsed scene document.
//!
//! A design point is the base scene's typed form ([`SceneFile`]) with its
//! swept fields set ([`set`]): each field is set by its path, so the field
//! of a value the scene loader refuses is known, not looked for in text.
//!
//! Numeric fields: `coupling.{diameter, ball_diameter,
//! groove_element_diameter, groove_radius, canoe_radius, opening_angle_deg,
//! support_compliance}`, `preload.{force, ramp_time}`, `friction.{mu_static,
//! spread, sd, correlation, dynamic_ratio, decay_coefficient}` and
//! `materials.NAME.{youngs_modulus, poisson_ratio, allowable_pressure,
//! allowable_shear_stress, thermal_expansion}` (NAME: a `[[materials]]` entry of the scene or
//! a built-in material; setting a built-in's constant adds an entry with
//! `override = true` holding the built-in's other constants). Material
//! fields: `coupling.ball_material`, `coupling.groove_material`. String
//! fields (concept sweeps): `coupling.{arrangement, groove, ball_shape, seat}`,
//! `friction.{distribution, tangential_law}`; their values are not checked
//! here but by the scene loader at each design point, so every value the
//! scene format accepts can be swept and any other makes that point
//! invalid. Not sweepable: `[variation]` (a sweep varies the friction
//! only) and the study settings (`[study]`: given as options).

use serde::de::value::{Error as ValueError, StrDeserializer};
use serde::{Deserialize, Serialize};
use thiserror::Error;
use toml::Spanned;

use super::ExploreError;
use crate::material::Material;
use crate::scene::file::{CouplingFile, MaterialFile, SceneFile};

/// What a field holds.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum FieldKind {
    /// A number (SI unit of the scene format).
    Number,
    /// A material name (built-in or a `[[materials]]` entry).
    Material,
    /// A keyword of the scene format (`coupling.groove = "planes"`, ...).
    #[serde(rename = "string")]
    Text,
}

/// One value of a swept field.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(untagged)]
pub enum SweptValue {
    Number(f64),
    Name(String),
}

impl std::fmt::Display for SweptValue {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        match self {
            SweptValue::Number(x) => write!(f, "{x}"),
            SweptValue::Name(s) => write!(f, "{s}"),
        }
    }
}

/// Why a field cannot be swept in this scene, or a value set in it.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FieldError {
    #[error("not a sweepable field; sweepable: {}", sweepable())]
    NotSweepable,
    #[error("the scene has no [{0}] table")]
    NoTable(String),
    #[error(
        "the scene has no [[materials]] entry named \"{0}\" and there is no such built-in material"
    )]
    NoMaterial(String),
    /// A keyword the field does not take (the scene format's message).
    #[error("{0}")]
    Keyword(String),
}

const NUMBERS: [(&str, &[&str]); 4] = [
    (
        "coupling",
        &[
            "diameter",
            "ball_diameter",
            "groove_element_diameter",
            "groove_radius",
            "canoe_radius",
            "opening_angle_deg",
            "support_compliance",
        ],
    ),
    ("preload", &["force", "ramp_time"]),
    (
        "friction",
        &["mu_static", "spread", "sd", "correlation", "dynamic_ratio", "decay_coefficient"],
    ),
    ("thermal", &["path_tolerance"]),
];
const MATERIAL_NUMBERS: [&str; 5] = [
    "youngs_modulus",
    "poisson_ratio",
    "allowable_pressure",
    "allowable_shear_stress",
    "thermal_expansion",
];
const MATERIALS: [&str; 4] = [
    "coupling.ball_material",
    "coupling.groove_material",
    "thermal.moving_body",
    "thermal.fixed_body",
];
const TEXTS: [&str; 6] = [
    "coupling.arrangement",
    "coupling.groove",
    "coupling.ball_shape",
    "coupling.seat",
    "friction.distribution",
    "friction.tangential_law",
];

/// Every sweepable path, for messages (NAME stands for a material entry).
pub fn sweepable() -> String {
    let mut all: Vec<String> =
        NUMBERS.iter().flat_map(|(t, ks)| ks.iter().map(move |k| format!("{t}.{k}"))).collect();
    all.extend(MATERIAL_NUMBERS.iter().map(|k| format!("materials.NAME.{k}")));
    all.extend(MATERIALS.iter().chain(&TEXTS).map(|s| s.to_string()));
    all.join(", ")
}

/// A value the field at `path` does not take (a design point's invalid
/// reason: `FIELD: reason`).
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{path}: {reason}")]
pub struct SetError {
    pub path: String,
    pub reason: FieldError,
}

/// The kind of the field at `path`, checked against the sweepable fields
/// and against `scene` (a `coupling` field needs the high-level form, a
/// material constant a material of that name).
pub fn kind_of(path: &str, scene: &SceneFile) -> Result<FieldKind, ExploreError> {
    let err = |reason: FieldError| ExploreError::Field { path: path.to_string(), reason };
    let seg: Vec<&str> = path.split('.').collect();
    let kind = match seg.as_slice() {
        ["materials", _, key] if MATERIAL_NUMBERS.contains(key) => FieldKind::Number,
        [table, key] if NUMBERS.iter().any(|(t, ks)| t == table && ks.contains(key)) => {
            FieldKind::Number
        }
        _ if MATERIALS.contains(&path) => FieldKind::Material,
        _ if TEXTS.contains(&path) => FieldKind::Text,
        _ => return Err(err(FieldError::NotSweepable)),
    };
    match seg.as_slice() {
        ["coupling", ..] if scene.coupling.is_none() => {
            Err(err(FieldError::NoTable("coupling".into())))
        }
        ["thermal", ..] if scene.thermal.is_none() => {
            Err(err(FieldError::NoTable("thermal".into())))
        }
        ["materials", name, _] if material(scene, name).is_none() && !builtin(name) => {
            Err(err(FieldError::NoMaterial(name.to_string())))
        }
        _ => Ok(kind),
    }
}

fn builtin(name: &str) -> bool {
    Material::builtin(name).is_ok()
}

/// The `[[materials]]` entry named `name`.
fn material<'a>(scene: &'a SceneFile, name: &str) -> Option<&'a MaterialFile> {
    scene.materials.iter().find(|m| m.name.get_ref() == name)
}

/// A set value: no place in the scene file, so no line.
fn at<T>(v: T) -> Spanned<T> {
    Spanned::new(0..0, v)
}

/// Set the field at `path` (checked by [`kind_of`]) to `value`, as
/// [`kind_of`]'s kind says (a number for a numeric field, a name else). A
/// constant of a built-in material the scene does not define goes into a
/// new `[[materials]]` entry with `override = true` and the built-in's
/// other constants, so only that constant changes. A keyword the field
/// does not take is [`FieldError::Keyword`], in the scene format's words.
pub fn set(scene: &mut SceneFile, path: &str, value: &SweptValue) -> Result<(), FieldError> {
    let (x, name) = match value {
        SweptValue::Number(x) => (*x, String::new()),
        SweptValue::Name(s) => (f64::NAN, s.clone()),
    };
    let seg: Vec<&str> = path.split('.').collect();
    match seg.as_slice() {
        ["coupling", key] => {
            let c =
                scene.coupling.as_mut().ok_or_else(|| FieldError::NoTable("coupling".into()))?;
            return set_coupling(c, key, x, name);
        }
        ["preload", "force"] => scene.preload.force = Some(at(x)),
        ["preload", "ramp_time"] => scene.preload.ramp_time = Some(at(x)),
        ["friction", key] => return set_friction(scene, key, x, name),
        ["materials", m, key] => return set_material(scene, m, key, x),
        ["thermal", key] => {
            let t = scene.thermal.as_mut().ok_or_else(|| FieldError::NoTable("thermal".into()))?;
            match *key {
                "path_tolerance" => t.path_tolerance = Some(at(x)),
                "moving_body" => t.moving_body = at(name),
                "fixed_body" => t.fixed_body = at(name),
                _ => return Err(FieldError::NotSweepable),
            }
        }
        _ => return Err(FieldError::NotSweepable),
    }
    Ok(())
}

fn set_coupling(c: &mut CouplingFile, key: &str, x: f64, name: String) -> Result<(), FieldError> {
    match key {
        "diameter" => c.diameter = at(x),
        "ball_diameter" => c.ball_diameter = at(x),
        "groove_element_diameter" => c.groove_element_diameter = Some(at(x)),
        "groove_radius" => c.groove_radius = Some(at(x)),
        "canoe_radius" => c.canoe_radius = Some(at(x)),
        "opening_angle_deg" => c.opening_angle_deg = at(x),
        // The number is the normal compliance; it replaces a table.
        "support_compliance" => c.support_compliance = Some(at(toml::Value::Float(x))),
        "ball_material" => c.ball_material = at(name),
        "groove_material" => c.groove_material = at(name),
        "arrangement" => c.arrangement = keyword(&name)?,
        "groove" => c.groove = keyword(&name)?,
        "ball_shape" => c.ball_shape = Some(keyword(&name)?),
        "seat" => c.seat = Some(keyword(&name)?),
        _ => return Err(FieldError::NotSweepable),
    }
    Ok(())
}

fn set_friction(scene: &mut SceneFile, key: &str, x: f64, name: String) -> Result<(), FieldError> {
    let f = &mut scene.friction;
    match key {
        // A number sets every contact's (it replaces a per-contact list).
        "mu_static" => f.mu_static = at(toml::Value::Float(x)),
        "spread" => f.spread = at(toml::Value::Float(x)),
        "sd" => f.sd = Some(at(toml::Value::Float(x))),
        "correlation" => f.correlation = Some(at(x)),
        "dynamic_ratio" => f.dynamic_ratio = at(x),
        "decay_coefficient" => f.decay_coefficient = Some(at(x)),
        "distribution" => f.distribution = keyword(&name)?,
        "tangential_law" => f.tangential_law = keyword(&name)?,
        _ => return Err(FieldError::NotSweepable),
    }
    Ok(())
}

fn set_material(scene: &mut SceneFile, name: &str, key: &str, x: f64) -> Result<(), FieldError> {
    if material(scene, name).is_none() {
        let m = Material::builtin(name).map_err(|_| FieldError::NoMaterial(name.into()))?;
        scene.materials.push(MaterialFile {
            name: at(m.name),
            youngs_modulus: at(m.youngs_modulus),
            poisson_ratio: at(m.poisson_ratio),
            allowable_pressure: m.allowable_pressure.map(at),
            allowable_shear_stress: m.allowable_shear_stress.map(at),
            thermal_expansion: m.thermal_expansion.map(at),
            replaces: Some(at(true)),
        });
    }
    let m = (scene.materials.iter_mut())
        .find(|m| m.name.get_ref() == name)
        .ok_or_else(|| FieldError::NoMaterial(name.into()))?;
    match key {
        "youngs_modulus" => m.youngs_modulus = at(x),
        "poisson_ratio" => m.poisson_ratio = at(x),
        "allowable_pressure" => m.allowable_pressure = Some(at(x)),
        "allowable_shear_stress" => m.allowable_shear_stress = Some(at(x)),
        "thermal_expansion" => m.thermal_expansion = Some(at(x)),
        _ => return Err(FieldError::NotSweepable),
    }
    Ok(())
}

/// A keyword field's value read as the scene format reads it.
fn keyword<'de, T: Deserialize<'de>>(name: &'de str) -> Result<T, FieldError> {
    T::deserialize(StrDeserializer::<ValueError>::new(name))
        .map_err(|e| FieldError::Keyword(e.to_string()))
}
