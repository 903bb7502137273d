//! Study results: the JSON document (SI records plus nm/nrad statistics),
//! the Table 2 style text table, CSV, shard merging and the files of `--out`.

use std::fmt::Write;

use serde::{Deserialize, Serialize};

use crate::assembly::Coupling;
use crate::report::provenance::{Fingerprint, SCHEMA_VERSION, VERSION, produced_by};
use crate::report::study_stream::{StreamStats, check_record, split_moment_stats, streams};
use crate::scene::VariationBounds;
use crate::study::runner::{
    COMPONENTS, INTERCHANGE_PREFIX, StartBounds, StudyOptions, VariantRun, Variation,
};
use crate::study::sensitivity::{self, SensitivityBlock};
use crate::study::stats::{BootstrapConfig, SampleRecord, Summary, summarize_outputs};
use crate::study::{DesignSpec, Sampler, Shard, StudyError};

/// Six DOFs in human units: x, y, z [nm], phi_x, phi_y, phi_z [nrad]
/// (phi_z: clocking about z).
#[derive(Debug, Clone, Copy, PartialEq, Serialize, Deserialize)]
pub struct Dofs {
    pub x_nm: f64,
    pub y_nm: f64,
    pub z_nm: f64,
    pub phi_x_nrad: f64,
    pub phi_y_nrad: f64,
    pub phi_z_nrad: f64,
}

impl Dofs {
    /// From six SI values (m, m, m, rad, rad, rad).
    pub fn from_si(v: [f64; 6]) -> Self {
        Dofs {
            x_nm: v[0] * 1e9,
            y_nm: v[1] * 1e9,
            z_nm: v[2] * 1e9,
            phi_x_nrad: v[3] * 1e9,
            phi_y_nrad: v[4] * 1e9,
            phi_z_nrad: v[5] * 1e9,
        }
    }

    /// The six values in nm and nrad, in the order of `COMPONENTS`.
    pub fn values(&self) -> [f64; 6] {
        [
            self.x_nm,
            self.y_nm,
            self.z_nm,
            self.phi_x_nrad,
            self.phi_y_nrad,
            self.phi_z_nrad,
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
    /// Bootstrap 90 % percentile interval of sigma.
    pub sigma_ci90_low: Dofs,
    pub sigma_ci90_high: Dofs,
    /// Reproducibility +- 3 sigma.
    pub three_sigma: Dofs,
    pub mean: Dofs,
    pub min: Dofs,
    pub max: Dofs,
}

/// One sample of a study as written to JSON: the physical values of the
/// varied inputs (SI), the design coordinates in [0, 1] and the outputs (SI).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StudyRecord {
    /// Row of the design, 0-based.
    pub index: usize,
    /// Physical input values in the order of the variant's `inputs`: mu_s
    /// per contact (dimensionless), offsets [m], tilts [rad].
    #[serde(rename = "inputs_si")]
    pub physical: Vec<f64>,
    /// Design coordinates of this row (unit hypercube, before mapping).
    #[serde(rename = "design_u")]
    pub inputs: Vec<f64>,
    /// One value per `output_names` entry [m or rad].
    #[serde(rename = "outputs_si")]
    pub outputs: Vec<f64>,
}

impl StudyRecord {
    /// The statistics' view of this record (design coordinates and outputs).
    pub fn sample(&self) -> SampleRecord {
        SampleRecord {
            index: self.index,
            inputs: self.inputs.clone(),
            outputs: self.outputs.clone(),
        }
    }
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
    pub scene: String,
    pub name: String,
    /// Samples in the whole design.
    pub samples: usize,
    pub sampler: Sampler,
    pub seed: u64,
    pub mu_static: f64,
    pub spread: f64,
    pub dynamic_ratio: f64,
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
            point_stats(&names, &recs)
        };
    Ok((part(0..k, false)?, part(k..output_names.len(), true)?))
}

/// Every output finite, and no column so large that its sum of squares
/// overflows (that would make sigma NaN): otherwise an error naming the
/// sample.
fn check_finite_records(records: &[StudyRecord], names: &[String]) -> Result<(), StudyError> {
    for r in records {
        check_record(r.index, &r.outputs, names)?;
    }
    let n = records.len() as f64;
    for (k, name) in names.iter().enumerate() {
        let worst = records
            .iter()
            .max_by(|a, b| a.outputs[k].abs().total_cmp(&b.outputs[k].abs()));
        if let Some(r) = worst
            && !(r.outputs[k] * r.outputs[k] * n).is_finite()
        {
            return Err(StudyError::NonFinite {
                what: format!(
                    "sample {}: output {} = {:e} overflows the variance",
                    r.index, name, r.outputs[k]
                ),
            });
        }
    }
    Ok(())
}

/// The reason a study's coupling did not seat: every re-seating sigma is
/// exactly zero, i.e. every sample stopped at the nominal pose and nothing
/// slid (above the friction limit every contact sticks from the first
/// load increment).
fn zero_scatter(points: &[PointStats]) -> Option<String> {
    let zero = !points.is_empty()
        && points
            .iter()
            .all(|p| p.sigma.values().iter().all(|s| *s == 0.0));
    zero.then(|| {
        "zero scatter: every sample seated at exactly the nominal pose, nothing slid; the coupling cannot seat (friction at or above its seating limit, see `kinrepro check`)".to_string()
    })
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

fn point_stats(
    output_names: &[String],
    records: &[SampleRecord],
) -> Result<Vec<PointStats>, StudyError> {
    let summaries = summarize_outputs(records, &BootstrapConfig::default())?;
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
            sigma_ci90_low: pick(c, &|s| s.sigma_interval.lower),
            sigma_ci90_high: pick(c, &|s| s.sigma_interval.upper),
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
            scene: coupling.scene.file.clone(),
            name: coupling.scene.name.clone(),
            samples: run.design.n,
            sampler: run.design.sampler,
            seed: run.design.seed,
            mu_static: f.mu_static,
            spread: f.spread,
            dynamic_ratio: f.dynamic_ratio,
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
            (self.points, self.interchangeability) =
                split_stats(&self.output_names, &self.records)?;
            self.cannot_seat = zero_scatter(&self.points);
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
        self.cannot_seat = zero_scatter(&self.points);
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
                "Standard deviation (n-1) of the seated pose relative to the nominal seating (nominal friction and preload, touching start); below each row the bootstrap 90 % interval of sigma."
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
                "Interchangeability (manufacturing tolerances): standard deviation (n-1) of the seated pose of each perturbed coupling at nominal friction and preload, relative to the nominal geometry's seating."
            );
            let _ = writeln!(s);
            sigma_table(&mut s, &self.variants, |v| &v.interchangeability);
        }
        for v in self.variants.iter().filter(|v| !v.partial) {
            let _ = writeln!(s);
            let _ = writeln!(
                s,
                "{} ({}): {} samples, {} seed {}, mu_s = {} +- {} uniform, mu_d = {} mu_s",
                v.name,
                v.scene,
                v.samples,
                v.sampler,
                v.seed,
                v.mu_static,
                v.spread,
                v.dynamic_ratio
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
                }
            }
        }
        s
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
        "{:<4}{:<46}{:<16}{:>5} {:>13} {:>13} {:>13} {:>17} {:>17} {:>17}",
        "#",
        "variant",
        "point",
        "n",
        "sigma_x [nm]",
        "sigma_y [nm]",
        "sigma_z [nm]",
        "sigma_phi_x[nrad]",
        "sigma_phi_y[nrad]",
        "sigma_phi_z[nrad]"
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
            let lo = p.sigma_ci90_low.values();
            let hi = p.sigma_ci90_high.values();
            let _ = writeln!(
                s,
                "{:<4}{:<46}{:<16}{:>5} {:>13.3} {:>13.3} {:>13.3} {:>17.2} {:>17.2} {:>17.2}",
                i + 1,
                truncate(&v.name, 45),
                p.name,
                p.n,
                sg[0],
                sg[1],
                sg[2],
                sg[3],
                sg[4],
                sg[5]
            );
            let ci: Vec<String> = (0..6)
                .map(|k| {
                    let w = if k < 3 { 13 } else { 17 };
                    format!("{:>w$}", format!("[{:.2}, {:.2}]", lo[k], hi[k]))
                })
                .collect();
            let _ = writeln!(s, "{:<71}{}", "", ci.join(" "));
        }
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
            ("phi_z [nrad]", 5),
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

/// The `--vary` names of what a variation varies.
pub fn varied_kinds(var: &Variation) -> Vec<&'static str> {
    let mut parts = Vec::new();
    if var.friction {
        parts.push("friction");
    }
    if var.preload {
        parts.push("preload");
    }
    if var.start.is_some() {
        parts.push("start");
    }
    if var.tolerances {
        parts.push("tolerances");
    }
    parts
}

/// What varied, in words.
fn varied(v: &VariantReport) -> String {
    let parts = varied_kinds(&v.variation());
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

pub(crate) fn truncate(s: &str, n: usize) -> String {
    if s.chars().count() <= n {
        s.to_string()
    } else {
        s.chars().take(n - 1).collect::<String>() + "…"
    }
}

pub(crate) fn csv_field(s: &str) -> String {
    if s.contains([',', '"', '\n']) {
        format!("\"{}\"", s.replace('"', "\"\""))
    } else {
        s.to_string()
    }
}
