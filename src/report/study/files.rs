//! The study's CSV outputs and the files of `--out`: the summary CSV
//! (`--format csv`), the per-sample CSV (written as the samples arrive) and
//! the SVG plots. Every file is written whole or not at all ([`atomic`]).

use std::io::Write as _;
use std::path::Path;

use crate::delimited::csv_cell;
use crate::output::atomic::{AtomicFile, WriteError};
use crate::report::study::charts::study_charts;
use crate::report::study::text::point_csv_rows;
use crate::report::table::{Column, Table};
use crate::study::provenance::{SCHEMA_VERSION, VERSION, produced_by};
use crate::study::runner::INTERCHANGE_PREFIX;
use crate::study::stream::RecordSink;
use crate::study::{StudyRecord, StudyReport, VariantReport};

/// Header of the summary CSV: provenance columns, then the statistics (SI).
pub const SUMMARY_HEADER: &str = "kinrepro_version,schema_version,solver,sampler,seed,samples,vary,scene,name,point,dof,unit,n,mean,min,max,sigma,three_sigma,sigma_ci90_low,sigma_ci90_high,sigma_interval_method";

impl StudyReport {
    /// Summary statistics as CSV, one row per variant, point and DOF (SI
    /// units); each row names the version, solver, sampler, seed, samples
    /// and the varied quantities.
    pub fn csv(&self) -> String {
        let mut t = Table::of(SUMMARY_HEADER.split(',').map(Column::left));
        let vary = self.vary.join("+");
        for v in self.variants.iter().filter(|v| !v.partial) {
            let interchange = v.interchangeability.iter().map(|p| {
                let mut p = p.clone();
                p.name = format!("{INTERCHANGE_PREFIX}{}", p.name);
                p
            });
            let head = [
                VERSION.to_string(),
                SCHEMA_VERSION.to_string(),
                v.solver.clone(),
                v.sampler.to_string(),
                v.seed.to_string(),
                v.samples.to_string(),
                vary.clone(),
                v.scene.clone(),
                v.name.clone(),
            ];
            for p in v.points.iter().cloned().chain(interchange) {
                for stats in point_csv_rows(&p) {
                    t.row(head.iter().chain(&stats).map(Into::into).collect());
                }
            }
        }
        t.csv()
    }

    /// Write the per-sample CSV files (unless `samples_written`: a streamed
    /// study wrote them as it went) and the SVG plots into `dir`, each under
    /// its temporary name: nothing is renamed over a file of `dir` until the
    /// caller commits them all ([`atomic::commit_all`]), so an interrupted
    /// run leaves the folder as it was. Existing files are refused unless
    /// `force`.
    pub fn stage_files(
        &self,
        dir: &Path,
        force: bool,
        samples_written: bool,
    ) -> Result<Vec<AtomicFile>, WriteError> {
        std::fs::create_dir_all(dir)
            .map_err(|e| WriteError::io(dir, format!("cannot create the folder: {e}")))?;
        let mut staged = Vec::new();
        if !samples_written {
            for (i, v) in self.variants.iter().enumerate() {
                let path = dir.join(samples_file_name(i, v));
                let mut f = SamplesCsv::create(&path, v, force)?;
                for r in &v.records {
                    f.push(r)?;
                }
                staged.push(f.finish()?);
            }
        }
        let variants: Vec<&VariantReport> = self.variants.iter().collect();
        let charts = study_charts(&variants, &[]).map_err(|e| WriteError::io(dir, e))?;
        for c in charts {
            let path = dir.join(&c.file_name);
            let mut f = AtomicFile::create(&path, force)?;
            f.write_all(c.svg.as_bytes()).map_err(|e| WriteError::io(&path, e))?;
            staged.push(f);
        }
        Ok(staged)
    }
}

/// `samples_NN_<scene stem>.csv` of variant `i` (0-based).
pub fn samples_file_name(i: usize, v: &VariantReport) -> String {
    let stem = Path::new(&v.scene)
        .file_stem()
        .map_or("scene".into(), |s| s.to_string_lossy().into_owned());
    format!("samples_{:02}_{stem}.csv", i + 1)
}

/// The per-sample CSV of one variant, written row by row (the `csv`
/// crate) under a temporary name and renamed when complete. First line:
/// `# ` and the provenance; then `index`, the physical inputs (SI), the
/// outputs (SI), empty for a seating that did not centre.
pub struct SamplesCsv {
    out: csv::Writer<AtomicFile>,
    path: String,
    outputs: usize,
}

impl SamplesCsv {
    /// Start the file with its provenance and header lines.
    pub fn create(path: &Path, v: &VariantReport, force: bool) -> Result<Self, WriteError> {
        let mut file = AtomicFile::create(path, force)?;
        writeln!(
            file,
            "# {}, scene {}",
            produced_by(
                &v.solver,
                &v.sampler.to_string(),
                &v.seed.to_string(),
                &v.samples.to_string(),
                &crate::study::result::varied_kinds(&v.variation()).join("+"),
            ),
            crate::report::printable::printable(&v.scene)
        )
        .map_err(|e| WriteError::io(path, e))?;
        let mut csv = SamplesCsv {
            out: csv::Writer::from_writer(file),
            path: path.display().to_string(),
            outputs: v.output_names.len(),
        };
        let names = v.inputs.iter().map(|i| i.name());
        csv.record(std::iter::once("index".into()).chain(names).chain(v.output_names.clone()))?;
        Ok(csv)
    }

    fn record(&mut self, cells: impl IntoIterator<Item = String>) -> Result<(), WriteError> {
        let path = Path::new(&self.path);
        self.out
            .write_record(cells.into_iter().map(|c| csv_cell(&c).into_owned()))
            .map_err(|e| WriteError::io(path, e))
    }

    /// Complete the file (rename over the target).
    pub fn commit(self) -> Result<(), WriteError> {
        self.finish()?.commit()
    }

    /// The complete file, still under its temporary name.
    pub fn finish(self) -> Result<AtomicFile, WriteError> {
        let path = Path::new(&self.path);
        let file = self.out.into_inner();
        file.map_err(|e| WriteError::io(path, e.error()))
    }
}

impl RecordSink for SamplesCsv {
    type Error = WriteError;

    /// One sample's row.
    fn push(&mut self, r: &StudyRecord) -> Result<(), WriteError> {
        let values = r.physical.iter().chain(&r.outputs).map(|v| format!("{v:e}"));
        let missing = if r.centred() { 0 } else { self.outputs };
        let empty = std::iter::repeat_n(String::new(), missing);
        self.record(std::iter::once(r.index.to_string()).chain(values).chain(empty))
    }
}
