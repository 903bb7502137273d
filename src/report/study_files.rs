//! The study's CSV outputs and the files of `--out`: the summary CSV
//! (`--format csv`), the per-sample CSV (written as the samples arrive) and
//! the SVG plots. Every file is written whole or not at all ([`atomic`]).

use std::fmt::Write as _;
use std::io::Write as _;
use std::path::Path;

use crate::report::atomic::{self, AtomicFile, WriteError};
use crate::report::provenance::{SCHEMA_VERSION, VERSION, produced_by};
use crate::report::study::{Dofs, StudyRecord, StudyReport, VariantReport};
use crate::report::study_text::{csv_field, truncate};
use crate::study::plot::{
    ConvergenceSeries, Dof, VariantScatter, VariantSigma, plot_convergence, plot_sigma_bars,
    plot_xy_scatter,
};
use crate::study::runner::{COMPONENTS, INTERCHANGE_PREFIX};
use crate::study::stats::sigma_convergence;

/// Header of the summary CSV: provenance columns, then the statistics (SI).
pub const SUMMARY_HEADER: &str = "kinrepro_version,schema_version,solver,sampler,seed,samples,vary,scene,name,point,dof,unit,n,mean,min,max,sigma,three_sigma,sigma_ci90_low,sigma_ci90_high,sigma_interval_method";

impl StudyReport {
    /// Summary statistics as CSV, one row per variant, point and DOF (SI
    /// units); each row names the version, solver, sampler, seed, samples
    /// and the varied quantities.
    pub fn csv(&self) -> String {
        let mut s = format!("{SUMMARY_HEADER}\n");
        let vary = self.vary.join("+");
        for v in self.variants.iter().filter(|v| !v.partial) {
            let interchange = v.interchangeability.iter().map(|p| {
                let mut p = p.clone();
                p.name = format!("{INTERCHANGE_PREFIX}{}", p.name);
                p
            });
            for p in v.points.iter().cloned().chain(interchange) {
                let p = &p;
                for (k, comp) in COMPONENTS.iter().enumerate() {
                    let (dof, unit) = comp.rsplit_once('_').unwrap_or((comp, ""));
                    let si = |d: &Dofs| d.values()[k] * 1e-9;
                    // No interval (corners, single LHS): an empty field.
                    let ci = |d: &Option<Dofs>| {
                        d.as_ref().map_or(String::new(), |d| format!("{:e}", si(d)))
                    };
                    let _ = writeln!(
                        s,
                        "{VERSION},{SCHEMA_VERSION},{},{},{},{},{vary},{},{},{},{dof},{unit},{},{:e},{:e},{:e},{:e},{:e},{},{},{}",
                        v.solver,
                        v.sampler,
                        v.seed,
                        v.samples,
                        csv_field(&v.scene),
                        csv_field(&v.name),
                        csv_field(&p.name),
                        p.n,
                        si(&p.mean),
                        si(&p.min),
                        si(&p.max),
                        si(&p.sigma),
                        si(&p.three_sigma),
                        ci(&p.sigma_ci90_low),
                        ci(&p.sigma_ci90_high),
                        csv_field(&p.sigma_interval_method)
                    );
                }
            }
        }
        s
    }

    /// Write the per-sample CSV files (unless `samples_written`: a streamed
    /// study wrote them as it went) and the SVG plots into `dir`. Existing
    /// files are refused unless `force`.
    pub fn write_files(
        &self,
        dir: &Path,
        force: bool,
        samples_written: bool,
    ) -> Result<Vec<String>, WriteError> {
        std::fs::create_dir_all(dir).map_err(|e| WriteError::Io {
            path: dir.display().to_string(),
            reason: format!("cannot create the folder: {e}"),
        })?;
        let mut written = Vec::new();
        if !samples_written {
            for (i, v) in self.variants.iter().enumerate() {
                let path = dir.join(samples_file_name(i, v));
                let mut f = SamplesCsv::create(&path, v, force)?;
                for r in &v.records {
                    f.push(r)?;
                }
                f.commit()?;
                written.push(path.display().to_string());
            }
        }
        written.extend(self.write_plots(dir, force)?);
        Ok(written)
    }

    /// The SVG plots of the complete variants with re-seating outputs.
    fn write_plots(&self, dir: &Path, force: bool) -> Result<Vec<String>, WriteError> {
        let full: Vec<&VariantReport> = self
            .variants
            .iter()
            .filter(|v| !v.partial && !v.points.is_empty())
            .collect();
        let mut written = Vec::new();
        if full.is_empty() {
            return Ok(written);
        }
        // Scene file stems are short and tell the variants apart.
        let label = |v: &VariantReport| {
            Path::new(&v.scene).file_stem().map_or_else(
                || truncate(&v.name, 30),
                |s| s.to_string_lossy().into_owned(),
            )
        };
        let sigmas: Vec<VariantSigma> = full
            .iter()
            .map(|v| VariantSigma {
                variant: label(v),
                sigma: v.points[0].sigma.values(),
            })
            .collect();
        let path = dir.join("sigma_bars.svg");
        atomic::write_with(&path, force, |p| plot_sigma_bars(p, &sigmas))?;
        written.push(path.display().to_string());
        // Scatter and convergence need the samples (not kept by a streamed study).
        let with_records: Vec<&&VariantReport> =
            full.iter().filter(|v| !v.records.is_empty()).collect();
        if with_records.is_empty() {
            return Ok(written);
        }
        let scatter: Vec<VariantScatter> = with_records
            .iter()
            .map(|v| VariantScatter {
                variant: label(v),
                xy: v
                    .records
                    .iter()
                    .map(|r| (r.outputs[0] * 1e9, r.outputs[1] * 1e9))
                    .collect(),
            })
            .collect();
        let mut conv = Vec::new();
        for v in &with_records {
            // One translation and one rotation per variant keeps the legend
            // readable; x and phi_x stand for the others (the per-sample CSV
            // has all six).
            for (k, dof) in [(0, Dof::X), (3, Dof::PhiX)] {
                let values: Vec<f64> = v.records.iter().map(|r| r.outputs[k] * 1e9).collect();
                let points = sigma_convergence(&values).map_err(|e| WriteError::Io {
                    path: dir.join("sigma_convergence.svg").display().to_string(),
                    reason: e.to_string(),
                })?;
                conv.push(ConvergenceSeries {
                    variant: label(v),
                    dof,
                    points,
                });
            }
        }
        let path = dir.join("scatter_xy.svg");
        atomic::write_with(&path, force, |p| plot_xy_scatter(p, &scatter))?;
        written.push(path.display().to_string());
        let path = dir.join("sigma_convergence.svg");
        atomic::write_with(&path, force, |p| plot_convergence(p, &conv))?;
        written.push(path.display().to_string());
        Ok(written)
    }
}

/// `samples_NN_<scene stem>.csv` of variant `i` (0-based).
pub fn samples_file_name(i: usize, v: &VariantReport) -> String {
    let stem = Path::new(&v.scene)
        .file_stem()
        .map_or("scene".into(), |s| s.to_string_lossy().into_owned());
    format!("samples_{:02}_{stem}.csv", i + 1)
}

/// The per-sample CSV of one variant, written row by row under a temporary
/// name and renamed when complete. First line: `# ` and the provenance;
/// then `index`, the physical inputs (SI), the outputs (SI).
pub struct SamplesCsv {
    file: AtomicFile,
    path: String,
}

impl SamplesCsv {
    /// Start the file with its provenance and header lines.
    pub fn create(path: &Path, v: &VariantReport, force: bool) -> Result<Self, WriteError> {
        let mut head = format!(
            "# {}, scene {}\nindex",
            produced_by(
                &v.solver,
                &v.sampler.to_string(),
                &v.seed.to_string(),
                &v.samples.to_string(),
                &crate::report::study::varied_kinds(&v.variation()).join("+"),
            ),
            v.scene
        );
        for name in &v.inputs {
            let _ = write!(head, ",{name}");
        }
        for n in &v.output_names {
            let _ = write!(head, ",{}", csv_field(n));
        }
        head.push('\n');
        let mut csv = SamplesCsv {
            file: AtomicFile::create(path, force)?,
            path: path.display().to_string(),
        };
        csv.write(head.as_bytes())?;
        Ok(csv)
    }

    fn write(&mut self, bytes: &[u8]) -> Result<(), WriteError> {
        self.file
            .writer()
            .write_all(bytes)
            .map_err(|e| WriteError::Io {
                path: self.path.clone(),
                reason: e.to_string(),
            })
    }

    /// One sample's row.
    pub fn push(&mut self, r: &StudyRecord) -> Result<(), WriteError> {
        let mut t = format!("{}", r.index);
        for m in &r.physical {
            let _ = write!(t, ",{m:e}");
        }
        for o in &r.outputs {
            let _ = write!(t, ",{o:e}");
        }
        t.push('\n');
        self.write(t.as_bytes())
    }

    /// Complete the file (rename over the target).
    pub fn commit(self) -> Result<(), WriteError> {
        self.file.commit()
    }
}
