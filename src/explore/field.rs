//! The fields a sweep may set, by their TOML path in the high-level scene
//! (docs/scenes.md), and setting one in the parsed scene document.
//!
//! Numeric fields: `coupling.{diameter, ball_diameter,
//! groove_element_diameter, groove_radius, canoe_radius, opening_angle_deg,
//! support_compliance}`, `preload.{force, ramp_time}`, `friction.{mu_static,
//! spread, dynamic_ratio, decay_coefficient}` and
//! `materials.NAME.{youngs_modulus, poisson_ratio, allowable_pressure,
//! allowable_shear_stress}` (NAME: a `[[materials]]` entry of the scene or
//! a built-in material; setting a built-in's constant adds an entry with
//! `override = true` holding the built-in's other constants). Material
//! fields: `coupling.ball_material`, `coupling.groove_material`. String
//! fields (concept sweeps): `coupling.{arrangement, groove, ball_shape, seat}`,
//! `friction.{distribution, tangential_law}`; their values are not checked
//! here but by the scene loader at each design point, so every value the
//! scene format accepts can be swept and any other makes that point
//! invalid. Not sweepable: `[variation]` (a sweep varies the friction
//! only) and the study settings (`[study]`: given as options).

use serde::{Deserialize, Serialize};
use thiserror::Error;
use toml::{Table, Value};

use super::ExploreError;
use crate::material::Material;

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

/// Why a `--set` field cannot be swept in this scene.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum FieldError {
    #[error("not a sweepable field; sweepable: {}", sweepable())]
    NotSweepable,
    /// The scene holds a value of another type (its TOML type and value).
    #[error("the scene gives it as {type_name} ({value}), not as {}", kind_text(*kind))]
    WrongType {
        type_name: &'static str,
        value: String,
        kind: FieldKind,
    },
    #[error("[{0}] is not a table in the scene")]
    NotATable(String),
    #[error("the scene has no [{0}] table")]
    NoTable(String),
    #[error("not a sweepable field")]
    BadPath,
    #[error(
        "the scene has no [[materials]] entry named \"{0}\" and there is no such built-in material"
    )]
    NoMaterial(String),
    #[error("not present in the scene")]
    NotPresent,
}

const NUMBERS: [(&str, &[&str]); 3] = [
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
        &["mu_static", "spread", "dynamic_ratio", "decay_coefficient"],
    ),
];
const MATERIAL_NUMBERS: [&str; 4] = [
    "youngs_modulus",
    "poisson_ratio",
    "allowable_pressure",
    "allowable_shear_stress",
];
const MATERIALS: [&str; 2] = ["coupling.ball_material", "coupling.groove_material"];
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
    let mut all: Vec<String> = NUMBERS
        .iter()
        .flat_map(|(t, ks)| ks.iter().map(move |k| format!("{t}.{k}")))
        .collect();
    all.extend(
        MATERIAL_NUMBERS
            .iter()
            .map(|k| format!("materials.NAME.{k}")),
    );
    all.extend(MATERIALS.iter().chain(&TEXTS).map(|s| s.to_string()));
    all.join(", ")
}

/// The kind of the field at `path`, checked against the sweepable fields
/// and against `scene` (its table must exist, an existing value must have
/// the field's type).
pub fn kind_of(path: &str, scene: &Table) -> Result<FieldKind, ExploreError> {
    let err = |reason: FieldError| ExploreError::Field {
        path: path.to_string(),
        reason,
    };
    let unknown = || err(FieldError::NotSweepable);
    let seg: Vec<&str> = path.split('.').collect();
    let kind = match seg.as_slice() {
        ["materials", _, key] if MATERIAL_NUMBERS.contains(key) => FieldKind::Number,
        [table, key] if NUMBERS.iter().any(|(t, ks)| t == table && ks.contains(key)) => {
            FieldKind::Number
        }
        _ if MATERIALS.contains(&path) => FieldKind::Material,
        _ if TEXTS.contains(&path) => FieldKind::Text,
        _ => return Err(unknown()),
    };
    match lookup(scene, &seg).map_err(err)? {
        Some(v) if !type_fits(v, kind) => Err(err(FieldError::WrongType {
            type_name: v.type_str(),
            value: v.to_string(),
            kind,
        })),
        _ => Ok(kind),
    }
}

fn kind_text(kind: FieldKind) -> &'static str {
    match kind {
        FieldKind::Number => "a number",
        FieldKind::Material => "a material name",
        FieldKind::Text => "a string",
    }
}

fn type_fits(v: &Value, kind: FieldKind) -> bool {
    match kind {
        FieldKind::Number => v.is_float() || v.is_integer(),
        FieldKind::Material | FieldKind::Text => v.is_str(),
    }
}

/// The present value at `seg` (None if the field is absent but its table
/// exists).
fn lookup<'a>(scene: &'a Table, seg: &[&str]) -> Result<Option<&'a Value>, FieldError> {
    match seg {
        ["materials", name, key] => match material(scene, name) {
            Ok(t) => Ok(t.get(*key)),
            Err(_) if Material::builtin(name).is_ok() => Ok(None),
            Err(e) => Err(e),
        },
        [table, key] => match scene.get(*table) {
            Some(Value::Table(t)) => Ok(t.get(*key)),
            Some(_) => Err(FieldError::NotATable(table.to_string())),
            None => Err(FieldError::NoTable(table.to_string())),
        },
        _ => Err(FieldError::BadPath),
    }
}

/// The `[[materials]]` entry named `name`.
fn material<'a>(scene: &'a Table, name: &str) -> Result<&'a Table, FieldError> {
    scene
        .get("materials")
        .and_then(Value::as_array)
        .into_iter()
        .flatten()
        .filter_map(Value::as_table)
        .find(|t| t.get("name").and_then(Value::as_str) == Some(name))
        .ok_or_else(|| FieldError::NoMaterial(name.to_string()))
}

/// Set the field at `path` (checked by [`kind_of`]) to `value`. A
/// constant of a built-in material the scene does not define goes into a
/// new `[[materials]]` entry with `override = true` and the built-in's
/// other constants, so only that constant changes.
pub fn set(scene: &mut Table, path: &str, value: &SweptValue) -> Result<(), ExploreError> {
    let v = match value {
        SweptValue::Number(x) => Value::Float(*x),
        SweptValue::Name(s) => Value::String(s.clone()),
    };
    let seg: Vec<&str> = path.split('.').collect();
    if let ["materials", name, _] = seg.as_slice()
        && material(scene, name).is_err()
    {
        add_override(scene, name);
    }
    let target = match seg.as_slice() {
        ["materials", name, _] => scene
            .get_mut("materials")
            .and_then(Value::as_array_mut)
            .into_iter()
            .flatten()
            .filter_map(Value::as_table_mut)
            .find(|t| t.get("name").and_then(Value::as_str) == Some(*name)),
        [table, _] => scene
            .entry(table.to_string())
            .or_insert_with(|| Value::Table(Table::new()))
            .as_table_mut(),
        _ => None,
    };
    match target {
        Some(t) => {
            t.insert(seg[seg.len() - 1].to_string(), v);
            Ok(())
        }
        None => Err(ExploreError::Field {
            path: path.to_string(),
            reason: FieldError::NotPresent,
        }),
    }
}

/// Append `[[materials]] name = NAME, override = true` with the constants
/// of the built-in NAME (nothing if there is no such built-in: `set` then
/// reports the field as not present).
fn add_override(scene: &mut Table, name: &str) {
    let Ok(m) = Material::builtin(name) else {
        return;
    };
    let mut t = Table::new();
    t.insert("name".into(), Value::String(m.name));
    t.insert("override".into(), Value::Boolean(true));
    t.insert("youngs_modulus".into(), Value::Float(m.youngs_modulus));
    t.insert("poisson_ratio".into(), Value::Float(m.poisson_ratio));
    let optional = [
        ("allowable_pressure", m.allowable_pressure),
        ("allowable_shear_stress", m.allowable_shear_stress),
    ];
    for (key, x) in optional {
        if let Some(x) = x {
            t.insert(key.into(), Value::Float(x));
        }
    }
    let list = scene
        .entry("materials")
        .or_insert_with(|| Value::Array(Vec::new()));
    if let Some(list) = list.as_array_mut() {
        list.push(Value::Table(t));
    }
}
