//! Measured degrees of freedom and their units: the column names of a
//! measurement file (`x_nm`, `phi_x_urad`, ...) and `--noise` values
//! (`x=1nm`, `phi_x=20nrad`, or plain SI numbers).

/// The six DOFs in output order (x, y, z, phi_x, phi_y, phi_z).
pub const DOFS: [&str; 6] = ["x", "y", "z", "phi_x", "phi_y", "phi_z"];

/// Units of translations and their factor to metres.
const LENGTH_UNITS: [(&str, f64); 4] = [("m", 1.0), ("mm", 1e-3), ("um", 1e-6), ("nm", 1e-9)];
/// Units of rotations and their factor to radians.
const ANGLE_UNITS: [(&str, f64); 4] =
    [("rad", 1.0), ("mrad", 1e-3), ("urad", 1e-6), ("nrad", 1e-9)];

/// Index (0..6) of a DOF name.
pub fn dof_index(name: &str) -> Option<usize> {
    DOFS.iter().position(|d| *d == name)
}

/// True for the rotations phi_x, phi_y, phi_z.
pub fn is_rotation(dof: usize) -> bool {
    dof >= 3
}

/// The SI unit of a DOF: "m" or "rad".
pub fn si_unit(dof: usize) -> &'static str {
    if is_rotation(dof) { "rad" } else { "m" }
}

/// The human unit of a DOF: "nm" or "nrad".
pub fn human_unit(dof: usize) -> &'static str {
    if is_rotation(dof) { "nrad" } else { "nm" }
}

/// The units a DOF accepts, as text for messages.
pub fn unit_names(dof: usize) -> String {
    units(dof)
        .iter()
        .map(|(u, _)| *u)
        .collect::<Vec<_>>()
        .join(", ")
}

fn units(dof: usize) -> &'static [(&'static str, f64)] {
    if is_rotation(dof) {
        &ANGLE_UNITS
    } else {
        &LENGTH_UNITS
    }
}

/// Factor from `unit` to SI for this DOF, or None if the unit does not fit it.
pub fn unit_factor(dof: usize, unit: &str) -> Option<f64> {
    units(dof).iter().find(|(u, _)| *u == unit).map(|(_, f)| *f)
}

/// A column header `<dof>_<unit>`: the DOF index and the factor to SI, or
/// the reason it is not one.
pub fn parse_column(header: &str) -> Result<(usize, f64), String> {
    if let Some(d) = dof_index(header) {
        return Err(format!(
            "`{header}` has no unit: write {}",
            units(d)
                .iter()
                .map(|(u, _)| format!("{header}_{u}"))
                .collect::<Vec<_>>()
                .join(", ")
        ));
    }
    // The DOF is the longest known prefix followed by `_`.
    for d in [3, 4, 5, 0, 1, 2] {
        let name = DOFS[d];
        if let Some(unit) = header.strip_prefix(name).and_then(|r| r.strip_prefix('_')) {
            return unit_factor(d, unit).map(|f| (d, f)).ok_or_else(|| {
                format!(
                    "`{header}`: unit `{unit}` does not fit {name} (use {})",
                    unit_names(d)
                )
            });
        }
    }
    Err(format!(
        "`{header}`: unknown DOF (columns are <dof>_<unit> with dof one of {} and a unit such as nm or nrad, or `point`)",
        DOFS.join(", ")
    ))
}

/// One value with an optional unit suffix (`1nm`, `20 nrad`, `1e-9`): SI
/// if no unit is given. Finite and >= 0.
pub fn parse_value(dof: usize, text: &str) -> Result<f64, String> {
    let t = text.trim();
    let split = t
        .char_indices()
        .find(|(i, c)| c.is_ascii_alphabetic() && !is_exponent(t, *i))
        .map_or(t.len(), |(i, _)| i);
    let (num, unit) = (t[..split].trim(), t[split..].trim());
    let factor = if unit.is_empty() {
        1.0
    } else {
        unit_factor(dof, unit).ok_or_else(|| {
            format!(
                "`{t}`: unit `{unit}` does not fit {} (use {})",
                DOFS[dof],
                unit_names(dof)
            )
        })?
    };
    let v: f64 = num
        .parse()
        .map_err(|_| format!("`{t}` is not a number (with an optional unit)"))?;
    if !v.is_finite() || v < 0.0 {
        return Err(format!("`{t}`: need a finite value >= 0"));
    }
    Ok(v * factor)
}

/// True if the letter at `i` is the `e` of an exponent (`1e-9`).
fn is_exponent(t: &str, i: usize) -> bool {
    let b = t.as_bytes();
    (b[i] == b'e' || b[i] == b'E')
        && i > 0
        && b[i - 1].is_ascii_digit()
        && b.get(i + 1)
            .is_some_and(|c| c.is_ascii_digit() || *c == b'-' || *c == b'+')
}

/// Sensor noise per DOF from `DOF=VALUE,...` (SI numbers or with a unit
/// suffix: `x=1nm,phi_x=20nrad`). Later entries override `into`'s.
pub fn parse_noise(text: &str, into: &mut [Option<f64>; 6]) -> Result<(), String> {
    for entry in text.split(',').map(str::trim).filter(|e| !e.is_empty()) {
        let (name, value) = entry
            .split_once('=')
            .ok_or_else(|| format!("`{entry}`: write DOF=VALUE, e.g. x=1nm or phi_x=20nrad"))?;
        let d = dof_index(name.trim()).ok_or_else(|| {
            format!(
                "`{entry}`: unknown DOF `{}` (one of {})",
                name.trim(),
                DOFS.join(", ")
            )
        })?;
        into[d] = Some(parse_value(d, value)?);
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn columns_and_values() {
        assert_eq!(parse_column("phi_x_nrad").unwrap(), (3, 1e-9));
        assert_eq!(parse_column("x_um").unwrap(), (0, 1e-6));
        assert!(parse_column("x").unwrap_err().contains("no unit"));
        assert!(parse_column("w_nm").unwrap_err().contains("unknown DOF"));
        assert!(parse_column("z_nrad").unwrap_err().contains("does not fit"));
        assert_eq!(parse_value(0, "1nm").unwrap(), 1e-9);
        assert_eq!(parse_value(4, "20 nrad").unwrap(), 20e-9);
        assert_eq!(parse_value(0, "1e-9").unwrap(), 1e-9);
        assert!(parse_value(0, "1 nrad").is_err());
        assert!(parse_value(0, "NaN").is_err());
        let mut n = [None; 6];
        parse_noise("x=1nm, phi_z=2e-8", &mut n).unwrap();
        assert_eq!(n[0], Some(1e-9));
        assert_eq!(n[5], Some(2e-8));
        assert!(parse_noise("q=1nm", &mut n).is_err());
    }
}
