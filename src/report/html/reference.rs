//! Reference values of sigma (`kinrepro report --reference FILE`), drawn as
//! ticks on the sigma bars and listed under the sigma table.
//!
//! The file is CSV (docs/output.md, "Reference values"): lines starting with
//! `#` and blank lines are ignored; the first other line is the header
//!
//! ```text
//! label,scene,point,x_nm,y_nm,z_nm,phi_x_nrad,phi_y_nrad,phi_z_nrad
//! ```
//!
//! and each following line gives one reference: `label` (where the values
//! come from), `scene` (the scene file stem, e.g. `01_maxwell_vgroove_steel`,
//! or the scene's `name`), `point` (evaluation point) and sigma per DOF in nm
//! and nrad; an empty cell means no value for that DOF.

use std::path::Path;

use crate::report::html::HtmlError;
use crate::study::VariantReport;

/// The header a reference file must have.
pub const REFERENCE_HEADER: &str =
    "label,scene,point,x_nm,y_nm,z_nm,phi_x_nrad,phi_y_nrad,phi_z_nrad";

/// One row of a reference file.
#[derive(Debug, Clone, PartialEq)]
pub struct ReferenceRow {
    pub label: String,
    pub scene: String,
    pub point: String,
    /// Sigma per DOF in nm and nrad, where given.
    pub sigma: [Option<f64>; 6],
}

impl ReferenceRow {
    /// The first row for variant `v` (by scene file stem or name) and `point`.
    pub fn find<'a>(rows: &'a [ReferenceRow], v: &VariantReport, point: &str) -> Option<&'a Self> {
        let stem = Path::new(&v.scene)
            .file_stem()
            .map(|s| s.to_string_lossy().into_owned());
        rows.iter()
            .find(|r| (Some(&r.scene) == stem.as_ref() || r.scene == v.name) && r.point == point)
    }
}

/// Split one CSV line into fields (RFC 4180 quotes: `"a, b"`, `""` inside).
fn fields(line: &str) -> Vec<String> {
    let mut out = vec![String::new()];
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match (c, quoted) {
            ('"', true) if chars.peek() == Some(&'"') => {
                chars.next();
                if let Some(f) = out.last_mut() {
                    f.push('"');
                }
            }
            ('"', _) => quoted = !quoted,
            (',', false) => out.push(String::new()),
            (c, _) => {
                if let Some(f) = out.last_mut() {
                    f.push(c);
                }
            }
        }
    }
    out
}

/// Parse reference text; `file` names it in errors.
pub fn parse_reference(text: &str, file: &str) -> Result<Vec<ReferenceRow>, HtmlError> {
    let err = |line: usize, field: &str, reason: String| HtmlError::Reference {
        file: file.to_string(),
        line,
        field: field.to_string(),
        reason,
    };
    let names: Vec<&str> = REFERENCE_HEADER.split(',').collect();
    let mut header_seen = false;
    let mut rows = Vec::new();
    for (i, raw) in text.lines().enumerate() {
        let line = raw.trim();
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let f = fields(line);
        if !header_seen {
            let got: Vec<&str> = f.iter().map(|s| s.trim()).collect();
            if got != names {
                return Err(err(
                    i + 1,
                    "header",
                    format!("expected `{REFERENCE_HEADER}`, found `{line}`"),
                ));
            }
            header_seen = true;
            continue;
        }
        if f.len() != names.len() {
            return Err(err(
                i + 1,
                "row",
                format!("{} fields, the header has {}", f.len(), names.len()),
            ));
        }
        let mut sigma = [None; 6];
        for (k, s) in sigma.iter_mut().enumerate() {
            let cell = f[3 + k].trim();
            if cell.is_empty() {
                continue;
            }
            let v: f64 = cell
                .parse()
                .map_err(|_| err(i + 1, names[3 + k], format!("`{cell}` is not a number")))?;
            if !(v.is_finite() && v >= 0.0) {
                return Err(err(
                    i + 1,
                    names[3 + k],
                    format!("{cell}: a sigma must be finite and >= 0"),
                ));
            }
            *s = Some(v);
        }
        if f[1].trim().is_empty() || f[2].trim().is_empty() {
            return Err(err(
                i + 1,
                if f[1].trim().is_empty() {
                    "scene"
                } else {
                    "point"
                },
                "empty: name the scene (file stem or name) and the evaluation point".into(),
            ));
        }
        rows.push(ReferenceRow {
            label: f[0].trim().to_string(),
            scene: f[1].trim().to_string(),
            point: f[2].trim().to_string(),
            sigma,
        });
    }
    if !header_seen {
        return Err(err(1, "header", "no header line: the file is empty".into()));
    }
    Ok(rows)
}

/// Read and parse a reference file.
pub fn load_reference(path: &Path) -> Result<Vec<ReferenceRow>, HtmlError> {
    let file = path.display().to_string();
    let text = std::fs::read_to_string(path).map_err(|e| HtmlError::Input {
        file: file.clone(),
        reason: format!("cannot read the file: {e}"),
    })?;
    parse_reference(&text, &file)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_quotes_empty_cells_and_rejects_bad_numbers() {
        let text = "# paper\nlabel,scene,point,x_nm,y_nm,z_nm,phi_x_nrad,phi_y_nrad,phi_z_nrad\n\"paper, FE\",01_a,centre,6.2,6.2,3.8,139.7,139.7,\n";
        let rows = parse_reference(text, "r.csv").unwrap();
        assert_eq!(rows.len(), 1);
        assert_eq!(rows[0].label, "paper, FE");
        assert_eq!(rows[0].sigma[0], Some(6.2));
        assert_eq!(rows[0].sigma[5], None);
        let bad = text.replace("3.8", "abc");
        let e = parse_reference(&bad, "r.csv").unwrap_err().to_string();
        assert!(e.contains("r.csv:3") && e.contains("z_nm"), "{e}");
        let neg = text.replace("3.8", "-1");
        assert!(parse_reference(&neg, "r.csv").is_err());
        assert!(parse_reference("x,y\n", "r.csv").is_err());
    }
}
