//! Measured degrees of freedom and their units: the column names of a
//! measurement file (`<dof>_<unit>`, e.g. `x_nm`) and `--noise` values
//! (`<dof>=<value><unit>`, e.g. `x=1nm`, or plain SI numbers).

use thiserror::Error;

use crate::dof::Dof;

/// Units of translations and their factor to metres.
const LENGTH_UNITS: [(&str, f64); 4] = [("m", 1.0), ("mm", 1e-3), ("um", 1e-6), ("nm", 1e-9)];
/// Units of rotations and their factor to radians.
const ANGLE_UNITS: [(&str, f64); 4] =
    [("rad", 1.0), ("mrad", 1e-3), ("urad", 1e-6), ("nrad", 1e-9)];

/// The name of DOF `dof` (an index into [`Dof::ALL`]).
pub fn dof_name(dof: usize) -> &'static str {
    Dof::ALL[dof].name()
}

/// Index (0..6) of a DOF name.
pub fn dof_index(name: &str) -> Option<usize> {
    Dof::from_name(name).map(Dof::index)
}

/// A measurement file's header, for messages (two translations, a rotation).
pub fn example_header() -> String {
    [Dof::X, Dof::Y, Dof::PhiX].map(Dof::key).join(",")
}

/// Two `--noise` values, for messages (a translation, a rotation).
fn noise_example() -> String {
    format!("{}=1nm or {}=20nrad", Dof::X.name(), Dof::PhiX.name())
}

/// The units a DOF accepts, as text for messages.
pub fn unit_names(dof: usize) -> String {
    units(dof).map(|(u, _)| u).join(", ")
}

fn units(dof: usize) -> [(&'static str, f64); 4] {
    if Dof::ALL[dof].is_rotation() { ANGLE_UNITS } else { LENGTH_UNITS }
}

/// Factor from `unit` to SI for this DOF, or None if the unit does not fit it.
pub fn unit_factor(dof: usize, unit: &str) -> Option<f64> {
    units(dof).into_iter().find(|(u, _)| *u == unit).map(|(_, f)| f)
}

/// Why a column header, a value or a `--noise` entry was not understood.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum UnitError {
    /// A bare DOF name as a column header: `x` instead of `x_nm`.
    #[error("`{header}` has no unit: write {}", with_units(header, *dof))]
    NoUnit { header: String, dof: usize },
    /// A column header whose unit does not fit its DOF (`z_nrad`).
    #[error("`{header}`: unit `{unit}` does not fit {} (use {})", dof_name(*dof), unit_names(*dof))]
    ColumnUnit { header: String, unit: String, dof: usize },
    /// A column header that names no DOF.
    #[error(
        "`{header}`: unknown DOF (columns are <dof>_<unit> with dof one of {} and a unit such as nm or nrad, or `point`)",
        Dof::names()
    )]
    UnknownColumn { header: String },
    /// A value whose unit does not fit its DOF (`1 nrad` for x).
    #[error("`{text}`: unit `{unit}` does not fit {} (use {})", dof_name(*dof), unit_names(*dof))]
    ValueUnit { text: String, unit: String, dof: usize },
    #[error("`{text}` is not a number (with an optional unit)")]
    NotANumber { text: String },
    /// A value that is negative, infinite or NaN.
    #[error("`{text}`: need a finite value >= 0")]
    OutOfRange { text: String },
    /// A `--noise` entry without `=`.
    #[error("`{entry}`: write DOF=VALUE, e.g. {}", noise_example())]
    NoiseSyntax { entry: String },
    /// A `--noise` entry naming no DOF.
    #[error("`{entry}`: unknown DOF `{name}` (one of {})", Dof::names())]
    NoiseDof { entry: String, name: String },
    /// A DOF given twice in one `--noise` list (`x=1nm,x=2nm`): only one
    /// value could take effect.
    #[error("`{entry}`: {name} is given twice (once per DOF)")]
    NoiseTwice { entry: String, name: String },
}

impl UnitError {
    /// This error of a value, shown as the whole `--noise` entry
    /// (`x=nan`), so that the message names the DOF.
    fn in_entry(self, entry: &str) -> Self {
        let text = entry.to_string();
        match self {
            UnitError::ValueUnit { unit, dof, .. } => UnitError::ValueUnit { text, unit, dof },
            UnitError::NotANumber { .. } => UnitError::NotANumber { text },
            UnitError::OutOfRange { .. } => UnitError::OutOfRange { text },
            other => other,
        }
    }
}

/// `header_m, header_mm, ...`: the column names a bare DOF header could be.
fn with_units(header: &str, dof: usize) -> String {
    units(dof).map(|(u, _)| format!("{header}_{u}")).join(", ")
}

/// A column header `<dof>_<unit>`: the DOF index and the factor to SI, or
/// the reason it is not one.
pub fn parse_column(header: &str) -> Result<(usize, f64), UnitError> {
    if let Some(dof) = dof_index(header) {
        return Err(UnitError::NoUnit { header: header.to_string(), dof });
    }
    // The DOF is the longest known prefix followed by `_`.
    for d in [3, 4, 5, 0, 1, 2] {
        let name = dof_name(d);
        if let Some(unit) = header.strip_prefix(name).and_then(|r| r.strip_prefix('_')) {
            return unit_factor(d, unit).map(|f| (d, f)).ok_or_else(|| UnitError::ColumnUnit {
                header: header.to_string(),
                unit: unit.to_string(),
                dof: d,
            });
        }
    }
    Err(UnitError::UnknownColumn { header: header.to_string() })
}

/// One value with an optional unit suffix (`1nm`, `20 nrad`, `1e-9`): SI
/// if no unit is given. Finite and >= 0.
pub fn parse_value(dof: usize, text: &str) -> Result<f64, UnitError> {
    let t = text.trim();
    // `nan`, `inf` parse as numbers: out of range, not an unknown unit.
    if t.parse::<f64>().is_ok_and(|v| !v.is_finite()) {
        return Err(UnitError::OutOfRange { text: t.to_string() });
    }
    let split = t
        .char_indices()
        .find(|(i, c)| c.is_ascii_alphabetic() && !is_exponent(t, *i))
        .map_or(t.len(), |(i, _)| i);
    let (num, unit) = (t[..split].trim(), t[split..].trim());
    if num.is_empty() {
        return Err(UnitError::NotANumber { text: t.to_string() });
    }
    let factor = if unit.is_empty() {
        1.0
    } else {
        unit_factor(dof, unit).ok_or_else(|| UnitError::ValueUnit {
            text: t.to_string(),
            unit: unit.to_string(),
            dof,
        })?
    };
    let v: f64 = num.parse().map_err(|_| UnitError::NotANumber { text: t.to_string() })?;
    if !v.is_finite() || v < 0.0 {
        return Err(UnitError::OutOfRange { text: t.to_string() });
    }
    Ok(v * factor)
}

/// True if the letter at `i` is the `e` of an exponent (`1e-9`).
fn is_exponent(t: &str, i: usize) -> bool {
    let b = t.as_bytes();
    (b[i] == b'e' || b[i] == b'E')
        && i > 0
        && b[i - 1].is_ascii_digit()
        && b.get(i + 1).is_some_and(|c| c.is_ascii_digit() || *c == b'-' || *c == b'+')
}

/// Sensor noise per DOF from `DOF=VALUE,...` (SI numbers or with a unit
/// suffix, e.g. `x=1nm`). The entries override `into`'s; a DOF given twice
/// in `text` is an error.
pub fn parse_noise(text: &str, into: &mut [Option<f64>; 6]) -> Result<(), UnitError> {
    let mut seen = [false; 6];
    for entry in text.split(',').map(str::trim).filter(|e| !e.is_empty()) {
        let (name, value) = entry
            .split_once('=')
            .ok_or_else(|| UnitError::NoiseSyntax { entry: entry.to_string() })?;
        let d = dof_index(name.trim()).ok_or_else(|| UnitError::NoiseDof {
            entry: entry.to_string(),
            name: name.trim().to_string(),
        })?;
        if std::mem::replace(&mut seen[d], true) {
            return Err(UnitError::NoiseTwice {
                entry: entry.to_string(),
                name: dof_name(d).to_string(),
            });
        }
        into[d] = Some(parse_value(d, value).map_err(|e| e.in_entry(entry))?);
    }
    Ok(())
}
