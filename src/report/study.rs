//! Study results: the JSON document (SI records plus nm/nrad statistics),
//! the Table 2 style text table, CSV, shard merging and the files of `--out`.

use std::fmt::Write;
use std::path::Path;

use serde::{Deserialize, Serialize};

use crate::assembly::Coupling;
use crate::contact::FrictionLaw;
use crate::scene::{DEFAULT_RAMP_TIME, VariationBounds};
use crate::study::plot::{
    ConvergenceSeries, Dof, VariantScatter, VariantSigma, plot_convergence, plot_sigma_bars,
    plot_xy_scatter,
};
use crate::study::runner::{
    COMPONENTS, INTERCHANGE_PREFIX, StartBounds, StudyOptions, VariantRun, Variation,
};
use crate::study::sensitivity::{self, SensitivityBlock};
use crate::study::stats::{
    SampleRecord, ShardFile, SigmaMethod, Summary, merge, sigma_convergence, summarize_outputs,
    verify_inputs,
};
use crate::study::{DesignSpec, Sampler, Shard, StudyError};

/// Five DOFs in human units: x, y, z [nm], phi_x, phi_y [nrad].
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Dofs {
    pub x_nm: f64,
    pub y_nm: f64,
    pub z_nm: f64,
    pub phi_x_nrad: f64,
    pub phi_y_nrad: f64,
}

impl Dofs {
    /// From five SI values (m, m, m, rad, rad).
    fn from_si(v: [f64; 5]) -> Self {
        Dofs {
            x_nm: v[0] * 1e9,
            y_nm: v[1] * 1e9,
            z_nm: v[2] * 1e9,
            phi_x_nrad: v[3] * 1e9,
            phi_y_nrad: v[4] * 1e9,
        }
    }

    pub fn values(&self) -> [f64; 5] {
        [
            self.x_nm,
            self.y_nm,
            self.z_nm,
            self.phi_x_nrad,
            self.phi_y_nrad,
        ]
    }
}

/// Statistics of one evaluation point over the samples (relative to the
/// nominal-mu pose; sigma with divisor n - 1).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct PointStats {
    pub name: String,
    pub n: usize,
    pub sigma: Dofs,
    /// 90 % interval of sigma by `sigma_interval_method` (null where the
    /// design admits none: corners, a single LHS).
    pub sigma_ci90_low: Option<Dofs>,
    pub sigma_ci90_high: Option<Dofs>,
    /// How sigma and its interval were computed, valid for the design.
    #[serde(default)]
    pub sigma_interval_method: String,
    /// Reproducibility +- 3 sigma.
    pub three_sigma: Dofs,
    pub mean: Dofs,
    pub min: Dofs,
    pub max: Dofs,
}

/// One scene's study.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct VariantReport {
    pub scene: String,
    pub name: String,
    /// Samples in the whole design.
    pub samples: usize,
    pub sampler: Sampler,
    pub seed: u64,
    pub mu_static: f64,
    pub spread: f64,
    pub dynamic_ratio: f64,
    /// Sliding coefficient: the sudden switch or the decay law
    /// (`{"law": "switch"}` or `{"law": "decay", "coefficient": c}`, c in s/m).
    #[serde(default)]
    pub friction_law: FrictionLaw,
    /// Preload ramp duration [s] (the time base of the decay law's slip velocity).
    #[serde(default = "default_ramp_time")]
    pub ramp_time_s: f64,
    /// The seating solver.
    pub solver: String,
    /// What varied: the names of the design dimensions, in row order.
    pub inputs: Vec<String>,
    /// Start-pose bounds when the start varied: offset half-widths (z: largest
    /// height) [m] and tilt half-widths [rad].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start_bounds: Option<[[f64; 3]; 2]>,
    /// The scene's `[variation]` bounds when preload or tolerances varied.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub variation_bounds: Option<VariationBounds>,
    /// True for one shard of several: statistics wait for `kinrepro merge`.
    pub partial: bool,
    /// Re-seating scatter of one pair of halves: statistics per evaluation
    /// point, the centre of the moving half first (empty when only
    /// tolerances vary).
    pub points: Vec<PointStats>,
    /// Interchangeability (tolerances varied): statistics of the seated pose
    /// of each perturbed coupling at nominal friction and preload, relative
    /// to the nominal geometry's seating, per evaluation point.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub interchangeability: Vec<PointStats>,
    /// `--sensitivity`: SRC tables of the first evaluation point's DOFs.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sensitivity: Option<Vec<SensitivityBlock>>,
    pub design: DesignSpec,
    pub shard: Shard,
    pub output_names: Vec<String>,
    /// Per sample: index, design row in [0, 1]^6, outputs in SI (see output_names).
    pub records: Vec<SampleRecord>,
}

/// The whole study document (`--format json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StudyReport {
    /// The seed and sampler of every variant (null if the variants differ).
    pub seed: Option<u64>,
    pub sampler: Option<Sampler>,
    pub shard: Shard,
    pub variants: Vec<VariantReport>,
}

/// Point names, in output order.
fn point_names(output_names: &[String]) -> Vec<String> {
    output_names
        .chunks(COMPONENTS.len())
        .map(|c| {
            c[0].rsplit_once('/')
                .map_or(c[0].clone(), |(p, _)| p.to_string())
        })
        .collect()
}

/// Statistics of the re-seating and of the interchangeability outputs.
fn split_stats(
    output_names: &[String],
    records: &[SampleRecord],
    method: SigmaMethod,
) -> Result<(Vec<PointStats>, Vec<PointStats>), StudyError> {
    let k = output_names
        .iter()
        .position(|n| n.starts_with(INTERCHANGE_PREFIX))
        .unwrap_or(output_names.len());
    let part =
        |range: std::ops::Range<usize>, strip: bool| -> Result<Vec<PointStats>, StudyError> {
            if range.is_empty() {
                return Ok(Vec::new());
            }
            let names: Vec<String> = output_names[range.clone()]
                .iter()
                .map(|n| {
                    if strip {
                        n.trim_start_matches(INTERCHANGE_PREFIX).to_string()
                    } else {
                        n.clone()
                    }
                })
                .collect();
            let recs: Vec<SampleRecord> = records
                .iter()
                .map(|r| SampleRecord {
                    index: r.index,
                    inputs: Vec::new(),
                    outputs: r.outputs[range.clone()].to_vec(),
                })
                .collect();
            point_stats(&names, &recs, method)
        };
    Ok((part(0..k, false)?, part(k..output_names.len(), true)?))
}

/// True for the names of tolerance inputs.
fn is_tolerance_input(name: &str) -> bool {
    ["ball_", "surface_", "groove_"]
        .iter()
        .any(|p| name.starts_with(p))
}

/// SRC tables of the first evaluation point: re-seating outputs on the
/// friction, preload and start inputs; interchangeability outputs on the
/// tolerance inputs.
pub fn sensitivity_blocks(v: &VariantReport) -> Vec<SensitivityBlock> {
    let samples: Vec<(&[f64], &[f64])> = v
        .records
        .iter()
        .map(|r| (r.inputs.as_slice(), r.outputs.as_slice()))
        .collect();
    let mut blocks = Vec::new();
    for (kind, tolerance) in [("reseating", false), ("interchangeability", true)] {
        let inputs: Vec<(usize, String)> = v
            .inputs
            .iter()
            .enumerate()
            .filter(|(_, n)| is_tolerance_input(n) == tolerance)
            .map(|(j, n)| (j, n.clone()))
            .collect();
        let first = v
            .output_names
            .iter()
            .position(|n| n.starts_with(INTERCHANGE_PREFIX) == tolerance);
        let (Some(first), false) = (first, inputs.is_empty()) else {
            continue;
        };
        let outputs: Vec<(usize, String)> = (first..first + COMPONENTS.len())
            .map(|k| (k, v.output_names[k].clone()))
            .collect();
        blocks.push(sensitivity::block(kind, &inputs, &outputs, &samples));
    }
    blocks
}

/// Statistics per evaluation point; sigma and its interval by the method
/// valid for the design (`method`, [`SigmaMethod::for_design`]).
fn point_stats(
    output_names: &[String],
    records: &[SampleRecord],
    method: SigmaMethod,
) -> Result<Vec<PointStats>, StudyError> {
    let summaries = summarize_outputs(records, method)?;
    let pick = |chunk: &[Summary], f: &dyn Fn(&Summary) -> f64| {
        Dofs::from_si([
            f(&chunk[0]),
            f(&chunk[1]),
            f(&chunk[2]),
            f(&chunk[3]),
            f(&chunk[4]),
        ])
    };
    Ok(point_names(output_names)
        .into_iter()
        .zip(summaries.chunks(COMPONENTS.len()))
        .map(|(name, c)| PointStats {
            name,
            n: c[0].n,
            sigma: pick(c, &|s| s.sigma),
            sigma_ci90_low: c
                .iter()
                .all(|s| s.sigma_interval.is_some())
                .then(|| pick(c, &|s| s.sigma_interval.map_or(f64::NAN, |i| i.lower))),
            sigma_ci90_high: c
                .iter()
                .all(|s| s.sigma_interval.is_some())
                .then(|| pick(c, &|s| s.sigma_interval.map_or(f64::NAN, |i| i.upper))),
            sigma_interval_method: c[0].sigma_interval_method.clone(),
            three_sigma: pick(c, &|s| s.three_sigma),
            mean: pick(c, &|s| s.mean),
            min: pick(c, &|s| s.min),
            max: pick(c, &|s| s.max),
        })
        .collect())
}

impl VariantReport {
    /// Build from a run; statistics only when the run holds every sample.
    pub fn new(
        coupling: &Coupling,
        run: VariantRun,
        opts: &StudyOptions,
    ) -> Result<Self, StudyError> {
        let f = &coupling.scene.friction;
        let var = &opts.variation;
        let mut v = VariantReport {
            scene: coupling.scene.file.clone(),
            name: coupling.scene.name.clone(),
            samples: run.design.n,
            sampler: run.design.sampler,
            seed: run.design.seed,
            mu_static: f.mu_static,
            spread: f.spread,
            dynamic_ratio: f.dynamic_ratio,
            friction_law: f.law,
            ramp_time_s: coupling.scene.preload.ramp_time,
            solver: opts.method.name().to_string(),
            inputs: var.input_names(coupling),
            start_bounds: var.start.map(|b| [b.offset.into(), b.tilt.into()]),
            variation_bounds: (var.preload || var.tolerances).then_some(coupling.scene.variation),
            partial: run.shard.count > 1,
            points: Vec::new(),
            interchangeability: Vec::new(),
            sensitivity: opts.sensitivity.then(Vec::new),
            design: run.design,
            shard: run.shard,
            output_names: run.output_names,
            records: run.records,
        };
        if !v.partial {
            v.finish()?;
        }
        Ok(v)
    }
}

impl VariantReport {
    /// Statistics (and sensitivity, if asked for) from the records.
    fn finish(&mut self) -> Result<(), StudyError> {
        let method = SigmaMethod::for_design(&self.design);
        (self.points, self.interchangeability) =
            split_stats(&self.output_names, &self.records, method)?;
        if self.sensitivity.is_some() {
            self.sensitivity = Some(sensitivity_blocks(self));
        }
        Ok(())
    }

    /// The variation this study used (to map design rows to inputs).
    pub fn variation(&self) -> Variation {
        Variation {
            friction: self.inputs.iter().any(|n| n.starts_with("mu_")),
            preload: self.inputs.iter().any(|n| n.starts_with("preload_")),
            tolerances: self.inputs.iter().any(|n| is_tolerance_input(n)),
            start: self.start_bounds.map(|[o, t]| StartBounds {
                offset: o.into(),
                tilt: t.into(),
            }),
        }
    }
}

impl StudyReport {
    pub fn new(variants: Vec<VariantReport>, shard: Shard) -> Self {
        let same = |f: &dyn Fn(&VariantReport) -> String| {
            variants.windows(2).all(|w| f(&w[0]) == f(&w[1]))
        };
        let seed =
            (!variants.is_empty() && same(&|v| v.seed.to_string())).then(|| variants[0].seed);
        let sampler =
            (!variants.is_empty() && same(&|v| v.sampler.to_string())).then(|| variants[0].sampler);
        StudyReport {
            seed,
            sampler,
            shard,
            variants,
        }
    }

    /// Merge shard documents (any order) into the document of one full run.
    pub fn merge(parts: Vec<StudyReport>) -> Result<StudyReport, StudyError> {
        let first = parts.first().ok_or(StudyError::EmptyMerge)?;
        let mut variants = Vec::new();
        for proto in &first.variants {
            let files: Vec<ShardFile> = parts
                .iter()
                .flat_map(|p| p.variants.iter())
                .filter(|v| v.scene == proto.scene && v.design == proto.design)
                .map(|v| ShardFile {
                    design: v.design,
                    shard: v.shard,
                    output_names: v.output_names.clone(),
                    records: v.records.clone(),
                })
                .collect();
            let merged = merge(files)?;
            verify_inputs(&merged)?;
            let mut v = proto.clone();
            v.partial = false;
            v.shard = Shard::whole();
            v.records = merged.records;
            v.finish()?;
            variants.push(v);
        }
        Ok(StudyReport::new(variants, Shard::whole()))
    }

    /// The text table: the variants side by side as in the paper's Table 2,
    /// then the full statistics of each variant.
    pub fn table(&self) -> String {
        let mut s = String::new();
        let sampler = self
            .sampler
            .map_or("per scene".to_string(), |x| x.to_string());
        let seed = self.seed.map_or("per scene".to_string(), |x| x.to_string());
        let _ = writeln!(
            s,
            "kinrepro study: sampler {sampler}, seed {seed}, shard {}",
            self.shard
        );
        if self
            .variants
            .iter()
            .any(|v| v.partial || !v.points.is_empty())
        {
            let _ = writeln!(
                s,
                "Standard deviation of the seated pose relative to the nominal seating (nominal friction and preload, touching start; divisor n-1, for a replicated LHS the unbiased replicate estimate); below each row the 90 % interval of sigma, by a method valid for the design: {}.",
                interval_methods(&self.variants)
            );
            let _ = writeln!(s);
            sigma_table(&mut s, &self.variants, |v| &v.points);
        }
        if self
            .variants
            .iter()
            .any(|v| !v.interchangeability.is_empty())
        {
            if self.variants.iter().any(|v| !v.points.is_empty()) {
                let _ = writeln!(s);
            }
            let _ = writeln!(
                s,
                "Interchangeability (manufacturing tolerances): standard deviation (and its interval) as above, of the seated pose of each perturbed coupling at nominal friction and preload, relative to the nominal geometry's seating."
            );
            let _ = writeln!(s);
            sigma_table(&mut s, &self.variants, |v| &v.interchangeability);
        }
        for v in self.variants.iter().filter(|v| !v.partial) {
            let _ = writeln!(s);
            let _ = writeln!(
                s,
                "{} ({}): {} samples, {} seed {}, mu_s = {} +- {} uniform, mu_d = {} mu_s, {}",
                v.name,
                v.scene,
                v.samples,
                v.sampler,
                v.seed,
                v.mu_static,
                v.spread,
                v.dynamic_ratio,
                friction_law_text(&v.friction_law, v.ramp_time_s)
            );
            let _ = writeln!(s, "  varied: {}", varied(v));
            if let Some(b) = &v.variation_bounds {
                let _ = writeln!(s, "  [variation] bounds: {}", bounds_text(b));
            }
            if !v.points.is_empty() {
                let _ = writeln!(s, "  re-seating scatter (one pair of halves):");
                detail(&mut s, &v.points);
            }
            if !v.interchangeability.is_empty() {
                let _ = writeln!(
                    s,
                    "  interchangeability (tolerances; nominal friction and preload):"
                );
                detail(&mut s, &v.interchangeability);
            }
            if let Some(blocks) = &v.sensitivity {
                for b in blocks {
                    sensitivity_table(&mut s, b);
                    super::sensitivity::sobol_table(&mut s, b);
                }
            }
        }
        s
    }

    /// Summary statistics as CSV, one row per variant, point and DOF (SI units).
    pub fn csv(&self) -> String {
        let mut s = String::from(
            "scene,name,point,dof,unit,n,mean,min,max,sigma,three_sigma,sigma_ci90_low,sigma_ci90_high\n",
        );
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
                        "{},{},{},{dof},{unit},{},{:e},{:e},{:e},{:e},{:e},{},{}",
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
                        ci(&p.sigma_ci90_high)
                    );
                }
            }
        }
        s
    }

    /// Write per-sample CSV files and the SVG plots into `dir`.
    pub fn write_files(&self, dir: &Path, couplings: &[Coupling]) -> Result<Vec<String>, String> {
        std::fs::create_dir_all(dir)
            .map_err(|e| format!("{}: cannot create: {e}", dir.display()))?;
        let mut written = Vec::new();
        let mut write = |name: String, text: String| -> Result<(), String> {
            let path = dir.join(&name);
            std::fs::write(&path, text).map_err(|e| format!("{}: {e}", path.display()))?;
            written.push(path.display().to_string());
            Ok(())
        };
        for (i, (v, c)) in self.variants.iter().zip(couplings).enumerate() {
            let stem = Path::new(&v.scene)
                .file_stem()
                .map_or("scene".into(), |s| s.to_string_lossy().into_owned());
            let mut t = String::from("index");
            for name in &v.inputs {
                let _ = write!(t, ",{name}");
            }
            for n in &v.output_names {
                let _ = write!(t, ",{}", csv_field(n));
            }
            t.push('\n');
            for r in &v.records {
                let _ = write!(t, "{}", r.index);
                for m in v.variation().sample(c, &r.inputs).physical {
                    let _ = write!(t, ",{m:e}");
                }
                for o in &r.outputs {
                    let _ = write!(t, ",{o:e}");
                }
                t.push('\n');
            }
            write(format!("samples_{:02}_{stem}.csv", i + 1), t)?;
        }
        let full: Vec<&VariantReport> = self
            .variants
            .iter()
            .filter(|v| !v.partial && !v.points.is_empty())
            .collect();
        if full.is_empty() {
            return Ok(written);
        }
        // Scene file stems are short and tell the variants apart.
        let label = |_: usize, v: &VariantReport| {
            Path::new(&v.scene).file_stem().map_or_else(
                || truncate(&v.name, 30),
                |s| s.to_string_lossy().into_owned(),
            )
        };
        let sigmas: Vec<VariantSigma> = full
            .iter()
            .enumerate()
            .map(|(i, v)| VariantSigma {
                variant: label(i, v),
                sigma: v.points[0].sigma.values(),
            })
            .collect();
        let scatter: Vec<VariantScatter> = full
            .iter()
            .enumerate()
            .map(|(i, v)| VariantScatter {
                variant: label(i, v),
                xy: v
                    .records
                    .iter()
                    .map(|r| (r.outputs[0] * 1e9, r.outputs[1] * 1e9))
                    .collect(),
            })
            .collect();
        let mut conv = Vec::new();
        for (i, v) in full.iter().enumerate() {
            // One translation and one rotation per variant keeps the legend
            // readable; x and phi_x stand for the others (the per-sample CSV
            // has all five).
            for (k, dof) in [(0, &Dof::X), (3, &Dof::PhiX)] {
                let values: Vec<f64> = v.records.iter().map(|r| r.outputs[k] * 1e9).collect();
                conv.push(ConvergenceSeries {
                    variant: label(i, v),
                    dof: *dof,
                    points: sigma_convergence(&values).map_err(|e| e.to_string())?,
                });
            }
        }
        for (name, result) in [
            (
                "sigma_bars.svg",
                plot_sigma_bars(&dir.join("sigma_bars.svg"), &sigmas),
            ),
            (
                "scatter_xy.svg",
                plot_xy_scatter(&dir.join("scatter_xy.svg"), &scatter),
            ),
            (
                "sigma_convergence.svg",
                plot_convergence(&dir.join("sigma_convergence.svg"), &conv),
            ),
        ] {
            result.map_err(|e| format!("{}: {e}", dir.join(name).display()))?;
            written.push(dir.join(name).display().to_string());
        }
        Ok(written)
    }
}

/// The Table 2 style sigma table of `points(v)` for every variant.
fn sigma_table(
    s: &mut String,
    variants: &[VariantReport],
    points: impl Fn(&VariantReport) -> &Vec<PointStats>,
) {
    let _ = writeln!(
        s,
        "{:<4}{:<46}{:<16}{:>5} {:>13} {:>13} {:>13} {:>17} {:>17}",
        "#",
        "variant",
        "point",
        "n",
        "sigma_x [nm]",
        "sigma_y [nm]",
        "sigma_z [nm]",
        "sigma_phi_x[nrad]",
        "sigma_phi_y[nrad]"
    );
    for (i, v) in variants.iter().enumerate() {
        if v.partial {
            let _ = writeln!(
                s,
                "{:<4}{:<46}(shard {} of {} samples: run `kinrepro merge` for statistics)",
                i + 1,
                v.name,
                v.shard,
                v.samples
            );
            continue;
        }
        for p in points(v) {
            let sg = p.sigma.values();
            let _ = writeln!(
                s,
                "{:<4}{:<46}{:<16}{:>5} {:>13.3} {:>13.3} {:>13.3} {:>17.2} {:>17.2}",
                i + 1,
                truncate(&v.name, 45),
                p.name,
                p.n,
                sg[0],
                sg[1],
                sg[2],
                sg[3],
                sg[4]
            );
            let (Some(lo), Some(hi)) = (&p.sigma_ci90_low, &p.sigma_ci90_high) else {
                let _ = writeln!(s, "{:<71}(no interval: {})", "", p.sigma_interval_method);
                continue;
            };
            let (lo, hi) = (lo.values(), hi.values());
            let ci: Vec<String> = (0..5)
                .map(|k| {
                    let w = if k < 3 { 13 } else { 17 };
                    format!("{:>w$}", format!("[{:.2}, {:.2}]", lo[k], hi[k]))
                })
                .collect();
            let _ = writeln!(s, "{:<71}{}", "", ci.join(" "));
        }
    }
}

/// The distinct interval methods of the variants' points, in order.
fn interval_methods(variants: &[VariantReport]) -> String {
    let mut methods: Vec<&str> = Vec::new();
    for p in variants.iter().flat_map(|v| &v.points) {
        if !methods.contains(&p.sigma_interval_method.as_str()) {
            methods.push(&p.sigma_interval_method);
        }
    }
    if methods.is_empty() {
        "per variant, after merging".to_string()
    } else {
        methods.join("; ")
    }
}

/// Mean, min, max, sigma and 3 sigma of every DOF of each point.
fn detail(s: &mut String, points: &[PointStats]) {
    for p in points {
        let _ = writeln!(
            s,
            "  {:<16} {:<10} {:>12} {:>12} {:>12} {:>12} {:>12}",
            p.name, "", "mean", "min", "max", "sigma", "+-3 sigma"
        );
        let rows = [
            ("x [nm]", 0),
            ("y [nm]", 1),
            ("z [nm]", 2),
            ("phi_x [nrad]", 3),
            ("phi_y [nrad]", 4),
        ];
        for (label, k) in rows {
            let _ = writeln!(
                s,
                "  {:<16} {:<10} {:>12.3} {:>12.3} {:>12.3} {:>12.3} {:>12.3}",
                "",
                label,
                p.mean.values()[k],
                p.min.values()[k],
                p.max.values()[k],
                p.sigma.values()[k],
                p.three_sigma.values()[k]
            );
        }
    }
}

/// What varied, in words.
fn varied(v: &VariantReport) -> String {
    let var = v.variation();
    let mut parts = Vec::new();
    if var.friction {
        parts.push("friction");
    }
    if var.preload {
        parts.push("preload");
    }
    if var.start.is_some() {
        parts.push("start pose");
    }
    if var.tolerances {
        parts.push("tolerances");
    }
    format!("{} ({} inputs)", parts.join(", "), v.inputs.len())
}

/// The non-zero `[variation]` bounds, in um and mrad.
fn bounds_text(b: &VariationBounds) -> String {
    let um = |x: f64| format!("{}", x * 1e6);
    let mut parts = Vec::new();
    if b.preload_offset_m.iter().any(|x| *x > 0.0) {
        parts.push(format!(
            "preload offset +-{}, +-{} um",
            um(b.preload_offset_m[0]),
            um(b.preload_offset_m[1])
        ));
    }
    if b.preload_tilt_rad > 0.0 {
        parts.push(format!(
            "preload tilt +-{} mrad per axis",
            b.preload_tilt_rad * 1e3
        ));
    }
    if b.ball_diameter_m > 0.0 {
        parts.push(format!("ball diameter +-{} um", um(b.ball_diameter_m)));
    }
    if b.ball_position_m.iter().any(|x| *x > 0.0) {
        let p = b.ball_position_m;
        parts.push(format!(
            "ball position +-{}, +-{}, +-{} um",
            um(p[0]),
            um(p[1]),
            um(p[2])
        ));
    }
    if b.surface_normal_m > 0.0 {
        parts.push(format!("surface normal +-{} um", um(b.surface_normal_m)));
    }
    if b.surface_tilt_rad > 0.0 {
        parts.push(format!("surface tilt +-{} mrad", b.surface_tilt_rad * 1e3));
    }
    if b.groove_position_m.iter().any(|x| *x > 0.0) {
        parts.push(format!(
            "groove position +-{}, +-{} um",
            um(b.groove_position_m[0]),
            um(b.groove_position_m[1])
        ));
    }
    if parts.is_empty() {
        "none".to_string()
    } else {
        parts.join("; ")
    }
}

/// One SRC table: inputs down, DOFs across.
fn sensitivity_table(s: &mut String, b: &SensitivityBlock) {
    let point = b
        .dofs
        .first()
        .and_then(|d| {
            d.output
                .trim_start_matches(INTERCHANGE_PREFIX)
                .rsplit_once('/')
        })
        .map_or(String::new(), |(p, _)| p.to_string());
    let _ = writeln!(
        s,
        "  sensitivity of the {} scatter at {point}: share of each DOF's variance per input (normalised SRC^2: R^2 SRC_j^2 / sum SRC^2; R^2 of the linear fit)",
        b.kind
    );
    let _ = writeln!(
        s,
        "  {:<22} {:>9} {:>9} {:>9} {:>9} {:>9}",
        "input", "x", "y", "z", "phi_x", "phi_y"
    );
    let cell = |d: &sensitivity::DofSensitivity, j: usize| {
        d.share
            .get(j)
            .map_or(format!("{:>9}", "-"), |v| format!("{v:>9.3}"))
    };
    for (j, name) in b.inputs.iter().enumerate() {
        let cells: Vec<String> = b.dofs.iter().map(|d| cell(d, j)).collect();
        let _ = writeln!(s, "  {:<22} {}", name, cells.join(" "));
    }
    let sums: Vec<String> = b
        .dofs
        .iter()
        .map(|d| {
            if d.share.is_empty() {
                format!("{:>9}", "-")
            } else {
                format!("{:>9.3}", d.share.iter().sum::<f64>())
            }
        })
        .collect();
    let _ = writeln!(s, "  {:<22} {}", "sum of shares", sums.join(" "));
    let r2: Vec<String> = b
        .dofs
        .iter()
        .map(|d| {
            d.r_squared
                .map_or(format!("{:>9}", "-"), |r| format!("{r:>9.3}"))
        })
        .collect();
    let _ = writeln!(s, "  {:<22} {}", "R^2", r2.join(" "));
    for d in &b.dofs {
        if let Some(n) = &d.note {
            let _ = writeln!(s, "  note, {}: {n}", d.output);
        }
    }
}

fn truncate(s: &str, n: usize) -> String {
    if s.chars().count() <= n {
        s.to_string()
    } else {
        s.chars().take(n - 1).collect::<String>() + "…"
    }
}

fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}

fn default_ramp_time() -> f64 {
    DEFAULT_RAMP_TIME
}

/// The friction reading in words, for the study header.
fn friction_law_text(law: &FrictionLaw, ramp_time: f64) -> String {
    match law {
        FrictionLaw::Switch => "sudden switch".to_string(),
        FrictionLaw::Decay { coefficient } => format!(
            "decay mu = mu_d + (mu_s - mu_d) exp(-{coefficient} s/m * v_slip), ramp {ramp_time} s"
        ),
    }
}
