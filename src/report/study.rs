//! Study results: the JSON document (SI records plus nm/nrad statistics,
//! docs/output.md) and the Table 2 style text table. The CSV and the files
//! of `--out` are in `study_files`, shard merging in `merge`, table helpers
//! in `study_text`, result checks in `study_checks`.

use std::fmt::Write;

use serde::{Deserialize, Serialize};

use crate::assembly::Coupling;
use crate::contact::FrictionLaw;
use crate::report::provenance::{Fingerprint, SCHEMA_VERSION, VERSION, produced_by};
use crate::report::study_checks::{check_finite_records, zero_scatter};
pub use crate::report::study_record::{Dofs, StudyRecord};
use crate::report::study_stream::{StreamStats, split_moment_stats, streams};
pub use crate::report::study_text::varied_kinds;
use crate::report::study_text::{bounds_text, detail, sigma_table, varied};
pub(crate) use crate::report::study_text::{csv_field, truncate};
use crate::scene::{DEFAULT_RAMP_TIME, VariationBounds};
use crate::study::runner::{
    COMPONENTS, INTERCHANGE_PREFIX, StartBounds, StudyOptions, VariantRun, Variation,
};
use crate::study::sensitivity::{self, SensitivityBlock};
use crate::study::stats::{SampleRecord, SigmaMethod, Summary, summarize_outputs};
use crate::study::{DesignSpec, Sampler, Shard, StudyError};

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
    /// The settings this variant's numbers depend on (`merge` compares them).
    pub fingerprint: Fingerprint,
    /// True if the statistics come from streaming moments (Monte Carlo above
    /// `study_stream::STREAM_ABOVE` samples; see docs/output.md).
    #[serde(default)]
    pub streamed: bool,
    /// Set when the coupling could not seat (nothing slid): the reason.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cannot_seat: Option<String>,
    /// Sample seatings per solver path (absent from `merge` output).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seating_paths: Option<crate::study::paths::SeatingPaths>,
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
    /// `point/component` of every output, unit as suffix (`_m`, `_rad`).
    pub output_names: Vec<String>,
    /// Per sample: index, physical inputs (SI), design row, outputs (SI).
    pub records: Vec<StudyRecord>,
}

/// The whole study document (`--format json`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StudyReport {
    /// Version of this document's layout (docs/output.md); 0: written before
    /// schema versions existed.
    #[serde(default)]
    pub schema_version: u32,
    /// The kinrepro that wrote it.
    #[serde(default)]
    pub kinrepro_version: String,
    /// Solver, seed, sampler and sample count of every variant (null if the
    /// variants differ).
    #[serde(default)]
    pub solver: Option<String>,
    pub seed: Option<u64>,
    pub sampler: Option<Sampler>,
    #[serde(default)]
    pub samples: Option<usize>,
    /// What varied (friction, preload, start, tolerances).
    #[serde(default)]
    pub vary: Vec<String>,
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
    records: &[StudyRecord],
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
        Dofs::from_si(std::array::from_fn(|k| f(&chunk[k])))
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
        let mut v = Self::unfinished(coupling, run, opts);
        if !v.partial {
            v.finish()?;
        }
        Ok(v)
    }

    /// The report of a run without its statistics (a streamed study sets
    /// them with [`VariantReport::set_moment_stats`]).
    pub fn unfinished(coupling: &Coupling, run: VariantRun, opts: &StudyOptions) -> Self {
        let f = &coupling.scene.friction;
        let var = &opts.variation;
        let records = run
            .records
            .into_iter()
            .map(|r| StudyRecord {
                index: r.index,
                physical: var.sample(coupling, &r.inputs).physical,
                inputs: r.inputs,
                outputs: r.outputs,
            })
            .collect();
        VariantReport {
            fingerprint: Fingerprint::new(coupling, opts, &run.design),
            streamed: false,
            cannot_seat: None,
            seating_paths: None,
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
            records,
        }
    }
}

impl VariantReport {
    /// Statistics (and sensitivity, if asked for) from the records.
    pub(crate) fn finish(&mut self) -> Result<(), StudyError> {
        check_finite_records(&self.records, &self.output_names)?;
        if streams(&self.design) {
            let mut st = StreamStats::new(self.output_names.len());
            for r in &self.records {
                st.push(std::slice::from_ref(&r.sample()), &self.output_names)?;
            }
            self.set_moment_stats(&st)?;
        } else {
            let method = SigmaMethod::for_design(&self.design);
            (self.points, self.interchangeability) =
                split_stats(&self.output_names, &self.records, method)?;
            self.cannot_seat = self.zero_scatter();
        }
        if self.sensitivity.is_some() {
            self.sensitivity = Some(sensitivity_blocks(self));
        }
        Ok(())
    }

    /// Statistics of a streamed study from its moments.
    pub fn set_moment_stats(&mut self, st: &StreamStats) -> Result<(), StudyError> {
        (self.points, self.interchangeability) =
            split_moment_stats(&self.output_names, &st.moments)?;
        self.streamed = true;
        self.cannot_seat = self.zero_scatter();
        Ok(())
    }

    /// The reason the coupling did not seat, if every re-seating sigma is
    /// exactly zero although the inputs vary (friction with a spread, or
    /// anything else): every sample stopped at the nominal pose.
    fn zero_scatter(&self) -> Option<String> {
        let var = self.variation();
        let varies = (var.friction && self.spread > 0.0) || var.preload || var.start.is_some();
        if varies {
            zero_scatter(&self.points)
        } else {
            None
        }
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
        let common = |f: &dyn Fn(&VariantReport) -> String| {
            let first = variants.first().map(f)?;
            variants.iter().all(|v| f(v) == first).then_some(())
        };
        let v0 = variants.first();
        let seed = common(&|v| v.seed.to_string()).and(v0.map(|v| v.seed));
        let sampler = common(&|v| v.sampler.to_string()).and(v0.map(|v| v.sampler));
        let solver = common(&|v| v.solver.clone()).and(v0.map(|v| v.solver.clone()));
        let samples = common(&|v| v.samples.to_string()).and(v0.map(|v| v.samples));
        let mut vary: Vec<String> = Vec::new();
        for v in &variants {
            for k in varied_kinds(&v.variation()) {
                if !vary.iter().any(|x| x == k) {
                    vary.push(k.to_string());
                }
            }
        }
        StudyReport {
            schema_version: SCHEMA_VERSION,
            kinrepro_version: VERSION.to_string(),
            solver,
            seed,
            sampler,
            samples,
            vary,
            shard,
            variants,
        }
    }

    /// The line naming what produced this document.
    pub fn produced_by(&self) -> String {
        let or_scene = |x: Option<String>| x.unwrap_or_else(|| "per scene".to_string());
        produced_by(
            &or_scene(self.solver.clone()),
            &or_scene(self.sampler.map(|x| x.to_string())),
            &or_scene(self.seed.map(|x| x.to_string())),
            &or_scene(self.samples.map(|x| x.to_string())),
            &self.vary.join("+"),
        )
    }

    /// Variants whose coupling could not seat, with the reason.
    pub fn cannot_seat(&self) -> Vec<String> {
        self.variants
            .iter()
            .filter_map(|v| v.cannot_seat.as_ref().map(|r| format!("{}: {r}", v.scene)))
            .collect()
    }

    /// The text table: the variants side by side as in the paper's Table 2,
    /// then the full statistics of each variant.
    pub fn table(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "{}, shard {}", self.produced_by(), self.shard);
        for w in self.cannot_seat() {
            let _ = writeln!(s, "CANNOT SEAT: {w}");
        }
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
            if v.streamed {
                let _ = writeln!(
                    s,
                    "  streamed: statistics from one-pass moments in sample order (no records kept); interval of sigma: {}",
                    crate::study::stats::interval::METHOD_BONETT
                );
            }
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
        "  {:<22} {:>9} {:>9} {:>9} {:>9} {:>9} {:>9}",
        "input", "x", "y", "z", "phi_x", "phi_y", "phi_z"
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
