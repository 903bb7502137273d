//! Measured re-seating data (docs/measurements.md): a cycles file (one row
//! per re-seating cycle, one column per measured DOF with its unit) or a
//! summary file (one row per DOF: its sigma and the number of cycles).
//! `#` lines carry metadata (`# key: value`); `# noise: x=1nm, ...` gives
//! the sensor noise per DOF. Every other line is one CSV record, read by
//! [`crate::delimited`] (delimiter detected from the header line unless given).

use std::path::Path;

use nalgebra::DMatrix;

use super::error::CalibrateError;
use super::units::{dof_index, dof_name, example_header, parse_column, parse_noise};
use crate::dof::Dof;

/// Fewest re-seating cycles a measurement may have.
pub const MIN_CYCLES: usize = 3;

/// Most re-seating cycles a summary may claim: ten million (a rig at one
/// cycle per second runs for four months).
pub const MAX_CYCLES: usize = 10_000_000;

/// Largest measured sigma of a translation [m] and a rotation [rad]: a
/// coupling scattering by a millimetre or ten milliradians is not seated.
pub const MAX_SIGMA: [f64; 2] = [1e-3, 1e-2];

/// Largest reading of a cycles file, translation [m] and rotation [rad]:
/// gauge readings may carry an offset, but a seated coupling's pose lies
/// within a metre and within pi.
pub const MAX_READING: [f64; 2] = [1.0, std::f64::consts::PI];

#[derive(Debug, Clone, PartialEq)]
pub enum MeasuredData {
    /// One row per cycle, one value per measured DOF [SI].
    Cycles(Vec<Vec<f64>>),
    /// Per measured DOF: sample sigma (divisor n - 1) [SI] and cycle count.
    Summary { sigma: Vec<f64>, cycles: Vec<usize> },
}

/// A measurement of one evaluation point.
#[derive(Debug, Clone, PartialEq)]
pub struct Measurement {
    pub file: String,
    /// The evaluation point (None: the scene's first).
    pub point: Option<String>,
    /// Measured DOFs (indices into [`Dof::ALL`]), file order.
    pub dofs: Vec<usize>,
    pub data: MeasuredData,
    /// Sensor noise sigma per DOF from `# noise:` [SI].
    pub noise: [Option<f64>; 6],
    /// Other `# key: value` lines.
    pub metadata: Vec<(String, String)>,
}

impl Measurement {
    /// Read a measurement file with fields separated by `delimiter` (None:
    /// detected from the header line).
    pub fn load(path: &Path, delimiter: Option<u8>) -> Result<Self, CalibrateError> {
        let file = path.display().to_string();
        let text = crate::input::read_to_string(path)
            .map_err(|e| CalibrateError::Read { file: file.clone(), reason: e.to_string() })?;
        Self::parse(&text, &file, delimiter)
    }

    /// Parse the text of a measurement file named `file` (see [`Self::load`]).
    pub fn parse(text: &str, file: &str, delimiter: Option<u8>) -> Result<Self, CalibrateError> {
        let read = crate::delimited::read(text, delimiter);
        let mut noise = [None; 6];
        let mut metadata = Vec::new();
        for (line, c) in &read.comments {
            if let Some((k, v)) = c.split_once(':') {
                let (k, v) = (k.trim().to_lowercase(), v.trim().to_string());
                if k == "noise" {
                    parse_noise(&v, &mut noise).map_err(|reason| CalibrateError::Noise {
                        origin: format!("{file}: line {line}: # noise"),
                        reason,
                    })?;
                }
                metadata.push((k, v));
            }
        }
        let Some(header) = read.records.first() else {
            return Err(CalibrateError::File {
                file: file.into(),
                line: text.lines().count().max(1),
                reason: format!("no header line (e.g. `{}`)", example_header()),
            });
        };
        let header_line = header.line;
        let records: Vec<(usize, Vec<String>)> =
            (read.records.iter()).map(|r| (r.line, r.cells.clone())).collect();
        let names = records[0].1.clone();
        let base = Measurement {
            file: file.into(),
            point: None,
            dofs: Vec::new(),
            data: MeasuredData::Cycles(Vec::new()),
            noise,
            metadata,
        };
        if names.iter().any(|n| n == "sigma") {
            base.parse_summary(header_line, &names, &records[1..])
        } else {
            base.parse_cycles(header_line, &names, &records[1..])
        }
    }

    fn parse_cycles(
        mut self,
        header_line: usize,
        names: &[String],
        rows: &[(usize, Vec<String>)],
    ) -> Result<Self, CalibrateError> {
        let mut columns = Vec::new();
        let mut point_col = None;
        for (c, name) in names.iter().enumerate() {
            if name == "point" {
                point_col = Some(c);
                continue;
            }
            let (d, f) = parse_column(name)
                .map_err(|r| self.err(header_line, c, name, with_hint(r.to_string(), name)))?;
            if self.dofs.contains(&d) {
                let r = format!("{} measured twice", dof_name(d));
                return Err(self.err(header_line, c, name, r));
            }
            self.dofs.push(d);
            columns.push((c, f));
        }
        if self.dofs.is_empty() {
            return Err(self.whole(header_line, "no measured DOF column".into()));
        }
        let mut data = Vec::new();
        for (line, cells) in rows {
            let line = *line;
            self.check_length(line, cells, names)?;
            if let Some(pc) = point_col {
                self.check_point(line, pc, &cells[pc])?;
            }
            let mut row = Vec::with_capacity(columns.len());
            for (k, &(c, f)) in columns.iter().enumerate() {
                let v = self.number(line, c, &names[c], &cells[c])? * f;
                if let Some(r) = reading_out_of_range(self.dofs[k], v) {
                    let r = format!("`{}` is {r} (check the column's unit)", cells[c]);
                    return Err(self.err(line, c, &names[c], r));
                }
                row.push(v);
            }
            data.push(row);
        }
        let last = rows.last().map_or(header_line, |r| r.0);
        if data.len() < MIN_CYCLES {
            // Every DOF column is short by the same count: name the first.
            let c = columns[0].0;
            let r =
                format!("{} cycle(s), need at least {MIN_CYCLES} re-seating cycles", data.len());
            return Err(self.err(last, c, &names[c], r));
        }
        self.data = MeasuredData::Cycles(data);
        // A column in the wrong unit (nm values under `x_mm`) scatters by
        // millimetres: no seated coupling does (the summary's bound).
        for ((&(c, _), &d), s) in columns.iter().zip(&self.dofs).zip(self.sigma()) {
            let (max, si) = sigma_bound(d);
            if s > max {
                let r = format!(
                    "the readings scatter by sigma = {s:e} {si}, above any seated coupling's \
                     {max:e} {si}: check the column's unit (values in nm under a `_mm` header?)"
                );
                return Err(self.err(header_line, c, &names[c], r));
            }
        }
        Ok(self)
    }

    fn parse_summary(
        mut self,
        header_line: usize,
        names: &[String],
        rows: &[(usize, Vec<String>)],
    ) -> Result<Self, CalibrateError> {
        let col = |n: &str| names.iter().position(|h| h == n);
        let (Some(cd), Some(cu), Some(cs), Some(cn)) =
            (col("dof"), col("unit"), col("sigma"), col("cycles"))
        else {
            let r = "a summary file needs the columns dof,unit,sigma,cycles (and optionally point)";
            return Err(self.whole(header_line, r.into()));
        };
        let cp = col("point");
        let known = ["dof", "unit", "sigma", "cycles", "point"];
        if let Some(c) = names.iter().position(|n| !known.contains(&n.as_str())) {
            let r = format!("unknown column (a summary has {})", known.join(", "));
            return Err(self.err(header_line, c, &names[c], r));
        }
        let (mut sigma, mut cycles) = (Vec::new(), Vec::new());
        for (line, cells) in rows {
            let line = *line;
            self.check_length(line, cells, names)?;
            if let Some(pc) = cp {
                self.check_point(line, pc, &cells[pc])?;
            }
            let d = dof_index(&cells[cd]).ok_or_else(|| {
                let r = format!("unknown DOF `{}` (one of {})", cells[cd], Dof::names());
                self.err(line, cd, "dof", r)
            })?;
            if self.dofs.contains(&d) {
                return Err(self.err(line, cd, "dof", format!("{} given twice", dof_name(d))));
            }
            let unit = cells[cu].as_str();
            if unit.is_empty() {
                return Err(self.err(line, cu, "unit", "missing unit".into()));
            }
            let s = self.number(line, cs, "sigma", &cells[cs])?;
            let f = super::units::unit_factor(d, unit).ok_or_else(|| {
                let r = format!(
                    "unit `{unit}` does not fit {} (use {})",
                    dof_name(d),
                    super::units::unit_names(d)
                );
                self.err(line, cu, "unit", r)
            })?;
            let n: usize = cells[cn].parse().map_err(|_| {
                let r = format!("`{}` is not a whole number of cycles", cells[cn]);
                self.err(line, cn, "cycles", r)
            })?;
            if !(MIN_CYCLES..=MAX_CYCLES).contains(&n) {
                let r =
                    format!("{n} cycle(s), need at least {MIN_CYCLES} and at most {MAX_CYCLES}");
                return Err(self.err(line, cn, "cycles", r));
            }
            let (max, si) = sigma_bound(d);
            if !(s * f > 0.0 && s * f <= max) {
                let r = format!(
                    "{s} {unit} = {:e} {si}: a measured sigma lies in (0, {max:e}] {si} (zero is below any sensor's noise)",
                    s * f
                );
                return Err(self.err(line, cs, "sigma", r));
            }
            self.dofs.push(d);
            sigma.push(s * f);
            cycles.push(n);
        }
        if self.dofs.is_empty() {
            return Err(self.whole(header_line, "no DOF rows".into()));
        }
        self.data = MeasuredData::Summary { sigma, cycles };
        Ok(self)
    }

    /// A data row has one cell per header name.
    fn check_length(
        &self,
        line: usize,
        cells: &[String],
        names: &[String],
    ) -> Result<(), CalibrateError> {
        if cells.len() == names.len() {
            return Ok(());
        }
        let r = format!("{} values, the header has {}", cells.len(), names.len());
        Err(self.whole(line, with_hint(r, &cells.join(""))))
    }

    /// A finite number in a cell.
    fn number(&self, line: usize, c: usize, name: &str, cell: &str) -> Result<f64, CalibrateError> {
        if cell.is_empty() {
            return Err(self.err(line, c, name, "empty value".into()));
        }
        let v: f64 = cell.parse().map_err(|_| {
            let comma =
                if cell.contains(',') { " (a decimal comma? write a decimal point)" } else { "" };
            self.err(line, c, name, format!("`{cell}` is not a number{comma}"))
        })?;
        if !v.is_finite() {
            let r = format!("`{cell}` is not a finite measured value");
            return Err(self.err(line, c, name, r));
        }
        Ok(v)
    }

    /// One evaluation point per file.
    fn check_point(&mut self, line: usize, c: usize, cell: &str) -> Result<(), CalibrateError> {
        if cell.is_empty() {
            return Err(self.err(line, c, "point", "empty point name".into()));
        }
        match &self.point {
            Some(p) if p != cell => {
                let r = format!(
                    "point `{cell}` differs from `{p}` above: one evaluation point per file"
                );
                Err(self.err(line, c, "point", r))
            }
            _ => {
                self.point = Some(cell.to_string());
                Ok(())
            }
        }
    }

    fn err(&self, line: usize, c: usize, name: &str, reason: String) -> CalibrateError {
        CalibrateError::Parse {
            file: self.file.clone(),
            line,
            column: format!("{} ({name})", c + 1),
            reason,
        }
    }

    fn whole(&self, line: usize, reason: String) -> CalibrateError {
        CalibrateError::File { file: self.file.clone(), line, reason }
    }

    /// Number of cycles per measured DOF.
    pub fn cycles(&self) -> Vec<usize> {
        match &self.data {
            MeasuredData::Cycles(rows) => vec![rows.len(); self.dofs.len()],
            MeasuredData::Summary { cycles, .. } => cycles.clone(),
        }
    }

    /// Sample sigma (divisor n - 1) per measured DOF [SI].
    pub fn sigma(&self) -> Vec<f64> {
        match &self.data {
            MeasuredData::Cycles(_) => {
                let s = self.covariance().unwrap_or_else(|| DMatrix::zeros(0, 0));
                (0..self.dofs.len()).map(|j| s[(j, j)].sqrt()).collect()
            }
            MeasuredData::Summary { sigma, .. } => sigma.clone(),
        }
    }

    /// Sample covariance S (divisor n - 1) of a cycles file [SI]; None for a summary.
    pub fn covariance(&self) -> Option<DMatrix<f64>> {
        let MeasuredData::Cycles(rows) = &self.data else {
            return None;
        };
        Some(super::model::covariance(rows))
    }
}

/// The largest measured sigma of DOF `dof` ([`MAX_SIGMA`]) and its SI unit.
fn sigma_bound(dof: usize) -> (f64, &'static str) {
    let rotation = usize::from(dof >= 3);
    (MAX_SIGMA[rotation], ["m", "rad"][rotation])
}

/// Why a reading `v` [SI] of DOF `dof` cannot be a seated coupling's
/// (`{v} m: a reading ... lies within 1 m`), or None.
pub(crate) fn reading_out_of_range(dof: usize, v: f64) -> Option<String> {
    let rotation = usize::from(dof >= 3);
    let (max, unit) = (MAX_READING[rotation], ["m", "rad"][rotation]);
    (v.abs() > max)
        .then(|| format!("{v:e} {unit}: a reading of a seated coupling lies within {max} {unit}"))
}

/// `reason`, with a hint at `delimiter` if `text` holds a delimiter other
/// than the one the file was split by.
fn with_hint(reason: String, text: &str) -> String {
    match [',', ';', '\t'].into_iter().find(|d| text.contains(*d)) {
        Some(d) => {
            let d = d.escape_default();
            format!(
                "{reason} (`{d}` in it: a file separated by `{d}`? see {})",
                crate::param::Param::Delimiter
            )
        }
        None => reason,
    }
}
