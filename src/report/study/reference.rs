//! Reference values of sigma (`kinrepro report --reference FILE`), drawn as
//! ticks on the sigma bars and listed under the sigma table.
//!
//! The file is CSV (docs/output.md, "Reference values"), read by
//! [`crate::delimited`] (comma, semicolon or tab; quoted fields; `#` and
//! blank lines ignored); the first record is the header: `label`, `scene`,
//! `point` and the six DOFs' [`Dof::key`]s (`x_nm`, ...), and each following
//! record gives one reference: `label` (where the values come from), `scene`
//! (the scene file stem, e.g. `01_maxwell_vgroove_steel`, or the scene's
//! `name`), `point` (evaluation point) and sigma per DOF in nm and nrad; an
//! empty cell means no value for that DOF.

use std::path::Path;

use crate::dof::Dof;

use crate::study::VariantReport;

/// A reference file that cannot be read or holds a bad row.
#[derive(Debug, thiserror::Error)]
pub enum ReferenceError {
    #[error("{file}:{line}: {field}: {reason}")]
    Row { file: String, line: usize, field: String, reason: String },
    #[error("{file}: {reason}")]
    File { file: String, reason: String },
}

/// The header a reference file must have.
pub fn reference_header() -> Vec<String> {
    let dofs = Dof::ALL.map(Dof::key);
    ["label", "scene", "point"].map(String::from).into_iter().chain(dofs).collect()
}

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
        let stem = Path::new(&v.scene).file_stem().map(|s| s.to_string_lossy().into_owned());
        rows.iter()
            .find(|r| (Some(&r.scene) == stem.as_ref() || r.scene == v.name) && r.point == point)
    }
}

/// The rows that no variant and evaluation point of `variants` shows: a
/// row whose scene or point is in none of them, or a second row (another
/// label) for a variant and point that already has one ([`ReferenceRow::find`]
/// shows the first).
pub fn unshown<'a>(rows: &'a [ReferenceRow], variants: &[&VariantReport]) -> Vec<&'a ReferenceRow> {
    let shown: Vec<&ReferenceRow> = variants
        .iter()
        .flat_map(|v| v.points.iter().filter_map(|p| ReferenceRow::find(rows, v, &p.name)))
        .collect();
    rows.iter().filter(|r| !shown.iter().any(|s| std::ptr::eq(*s, *r))).collect()
}

/// Parse reference text; `file` names it in errors.
pub fn parse_reference(text: &str, file: &str) -> Result<Vec<ReferenceRow>, ReferenceError> {
    let err = |line: usize, field: &str, reason: String| ReferenceError::Row {
        file: file.to_string(),
        line,
        field: field.to_string(),
        reason,
    };
    let names = reference_header();
    let records = crate::delimited::read(text, None).records;
    let Some((header, rows)) = records.split_first() else {
        return Err(err(1, "header", "no header line: the file is empty".into()));
    };
    if header.cells != names {
        let r = format!("expected `{}`, found `{}`", names.join(","), header.text);
        return Err(err(header.line, "header", r));
    }
    let mut out: Vec<ReferenceRow> = Vec::new();
    for r in rows {
        let row = reference_row(r, &names, &err)?;
        let same = |o: &&ReferenceRow| {
            (&o.label, &o.scene, &o.point) == (&row.label, &row.scene, &row.point)
        };
        if out.iter().any(|o| same(&o)) {
            let reason = format!(
                "`{}`, `{}`, `{}` given twice (one reference per label, scene and point)",
                row.label, row.scene, row.point
            );
            return Err(err(r.line, "row", reason));
        }
        out.push(row);
    }
    Ok(out)
}

/// Largest reference sigma: 1 mm in nm for a translation, 10 mrad in nrad
/// for a rotation (as for a measured sigma, `calibrate::measurement::MAX_SIGMA`).
const MAX_REFERENCE: [f64; 2] = [1e6, 1e7];

/// One record of a reference file (checked against the header `names`).
fn reference_row(
    r: &crate::delimited::Record,
    names: &[String],
    err: &dyn Fn(usize, &str, String) -> ReferenceError,
) -> Result<ReferenceRow, ReferenceError> {
    let f = &r.cells;
    if f.len() != names.len() {
        let reason = format!("{} fields, the header has {}", f.len(), names.len());
        return Err(err(r.line, "row", reason));
    }
    let mut sigma = [None; 6];
    for (k, s) in sigma.iter_mut().enumerate() {
        let (cell, name) = (&f[3 + k], &names[3 + k]);
        if cell.is_empty() {
            continue;
        }
        let v: f64 =
            (cell.parse()).map_err(|_| err(r.line, name, format!("`{cell}` is not a number")))?;
        let max = MAX_REFERENCE[usize::from(k >= 3)];
        if !(v.is_finite() && v >= 0.0 && v <= max) {
            let reason = format!("{cell}: a sigma must lie in [0, {max:e}] (nm or nrad)");
            return Err(err(r.line, name, reason));
        }
        *s = Some(v);
    }
    if let Some(k) = [1, 2].into_iter().find(|&k| f[k].is_empty()) {
        let reason = "empty: name the scene (file stem or name) and the evaluation point";
        return Err(err(r.line, &names[k], reason.into()));
    }
    Ok(ReferenceRow { label: f[0].clone(), scene: f[1].clone(), point: f[2].clone(), sigma })
}

/// Read and parse a reference file.
pub fn load_reference(path: &Path) -> Result<Vec<ReferenceRow>, ReferenceError> {
    let file = path.display().to_string();
    let text = crate::input::read_to_string(path).map_err(|e| ReferenceError::File {
        file: file.clone(),
        reason: format!("cannot read the file: {e}"),
    })?;
    parse_reference(&text, &file)
}
