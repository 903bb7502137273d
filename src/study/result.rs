//! The study document (`kinrepro study --format json`, docs/output.md): one
//! [`VariantReport`] per scene (SI records, nm/nrad statistics) in a
//! [`StudyReport`]. The records and
//! statistics are in [`super::record`], their summarising in
//! [`super::summary`], streamed studies in [`super::stream`], shard merging
//! in [`super::merge`]; `report` renders the document.

use serde::{Deserialize, Serialize};

use super::inputs::Input;
use super::options::{Settings, Varied};
use super::provenance::{Fingerprint, SCHEMA_VERSION, VERSION, produced_by};
use super::record::{PointStats, StudyRecord};
use super::runner::{StartBounds, VariantRun, Variation};
use super::sensitivity::SensitivityBlock;
use super::variant::Variant;
use super::{DesignSpec, Sampler, Shard, StudyError};
use crate::contact::FrictionLaw;
use crate::scene::{DEFAULT_RAMP_TIME, EvaluationPoint, MuDistribution, VariationBounds};

/// One scene's study.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct VariantReport {
    /// The settings this variant's numbers depend on (`merge` compares them).
    pub fingerprint: Fingerprint,
    /// True if the statistics come from streaming moments (Monte Carlo above
    /// `stream::STREAM_ABOVE` samples; see docs/output.md).
    #[serde(default)]
    pub streamed: bool,
    /// Set when the coupling could not seat (nothing slid): the reason.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub cannot_seat: Option<String>,
    /// Sample seatings per solver path (absent from `merge` output).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seating_paths: Option<super::paths::SeatingPaths>,
    /// Sample seatings of the decay law in its transition (stderr only).
    #[serde(skip)]
    pub unconverged: Option<super::paths::Unconverged>,
    /// The load path of the quasi-static sample seatings: largest path
    /// error, increments taken (mean, max); `merge` combines the shards'.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub load_path: Option<super::paths::LoadPath>,
    pub scene: String,
    pub name: String,
    /// Samples in the whole design.
    pub samples: usize,
    pub sampler: Sampler,
    pub seed: u64,
    pub mu_static: f64,
    pub spread: f64,
    /// `[friction]` per contact: [mu_static, spread] of each contact, in
    /// contact order (absent where one pair holds for every contact;
    /// `mu_static` and `spread` above are then their means).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub contact_friction: Option<Vec<[f64; 2]>>,
    /// `[friction] distribution` where not uniform: `{"kind": "normal",
    /// "sd": [...]}` (one per contact), `lognormal` likewise, or
    /// `{"kind": "empirical", "values": [...]}` (ascending).
    #[serde(default, skip_serializing_if = "MuDistribution::is_uniform")]
    pub mu_distribution: MuDistribution,
    /// `[friction] correlation` between the coefficients of one ball's
    /// contacts (absent where 0).
    #[serde(default, skip_serializing_if = "crate::scene::is_zero")]
    pub mu_correlation: f64,
    pub dynamic_ratio: f64,
    /// Sliding coefficient: the sudden switch or the decay law
    /// (`{"law": "switch"}` or `{"law": "decay", "coefficient": c}`, c in s/m).
    #[serde(default)]
    pub friction_law: FrictionLaw,
    /// Preload ramp duration [s] (the time base of the decay law's slip velocity).
    #[serde(default = "default_ramp_time")]
    pub ramp_time_s: f64,
    pub solver: String,
    /// What varied: the design dimensions, in row order.
    pub inputs: Vec<Input>,
    /// Start-pose bounds when the start varied: offset half-widths (z: largest
    /// height) [m] and tilt half-widths [rad].
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub start_bounds: Option<[[f64; 3]; 2]>,
    /// The scene's `[variation]` bounds when preload or tolerances varied.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub variation_bounds: Option<VariationBounds>,
    /// Start varied: the sample seatings that did not centre (a contact
    /// still open at full preload), left out of the statistics, which are
    /// then conditional on centring; and their share of the samples.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seating_failures: Option<usize>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub seating_failure_share: Option<f64>,
    /// The friction limit against the coefficients drawn and the contact
    /// safety factors (`study::assessment`, the numbers of `kinrepro
    /// check`): set once per scene by the study run that reports it
    /// ([`StudyPlan::run`](super::StudyPlan::run), a prediction), not by the
    /// many model studies of a calibration or a sweep (its friction limit
    /// costs about 0.1 s); absent in documents written before it.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub assessment: Option<super::assessment::Assessment>,
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
    /// A scene with `[thermal]`: the bodies and the cycle every sample
    /// followed after its seating (the drift statistics are in each
    /// point's `thermal`).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub thermal: Option<ThermalStudy>,
    /// `--sensitivity`: SRC tables of the first evaluation point's DOFs.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub sensitivity: Option<Vec<SensitivityBlock>>,
    pub design: DesignSpec,
    pub shard: Shard,
    /// `point/component` of every output, unit as suffix (`_m`, `_rad`).
    pub output_names: Vec<String>,
    /// The scene's evaluation points: names, positions [m] and the
    /// directions each is read along (absent in documents written before).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub evaluation_points: Vec<EvaluationPoint>,
    /// Per sample: index, physical inputs (SI), design row, outputs (SI).
    pub records: Vec<StudyRecord>,
}

/// The whole study document (`--format json`): the header and one entry
/// per scene of type `V` ([`StudyReport`]: a study's [`VariantReport`]s; a
/// prediction's document adds to each its measured sigma:
/// `report::calibration`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct StudyDocument<V> {
    /// Version of this document's layout (docs/output.md); 0: written before
    /// schema versions existed.
    #[serde(default)]
    pub schema_version: u32,
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
    pub variants: Vec<V>,
}

/// A study's document.
pub type StudyReport = StudyDocument<VariantReport>;

impl<V> StudyDocument<V> {
    /// The same header over other entries: `f` of each variant.
    pub fn map_variants<W>(self, f: impl FnMut(V) -> W) -> StudyDocument<W> {
        StudyDocument {
            schema_version: self.schema_version,
            kinrepro_version: self.kinrepro_version,
            solver: self.solver,
            seed: self.seed,
            sampler: self.sampler,
            samples: self.samples,
            vary: self.vary,
            shard: self.shard,
            variants: self.variants.into_iter().map(f).collect(),
        }
    }
}

/// The names of what a variation varies ([`Varied::name`]), in the order
/// friction, preload, start, tolerances.
pub fn varied_kinds(var: &Variation) -> Vec<&'static str> {
    [
        (var.friction, Varied::Friction),
        (var.preload, Varied::Preload),
        (var.start.is_some(), Varied::Start),
        (var.tolerances, Varied::Tolerances),
    ]
    .into_iter()
    .filter_map(|(on, kind)| on.then_some(kind.name()))
    .collect()
}

impl VariantReport {
    /// Build from a run of `v`; statistics only when the run holds every
    /// sample.
    pub fn new(s: &Settings, v: &Variant, run: VariantRun) -> Result<Self, StudyError> {
        let mut r = Self::unfinished(s, v, run);
        if !r.partial {
            r.finish()?;
        }
        Ok(r)
    }

    /// The report of a run of `v` without its statistics (a streamed study
    /// sets them with [`VariantReport::set_moment_stats`]).
    pub fn unfinished(s: &Settings, v: &Variant, run: VariantRun) -> Self {
        let scene = &v.scene;
        let f = &scene.friction;
        let var = &s.variation;
        let records = run.records.into_iter().map(|r| StudyRecord::new(v, var, r)).collect();
        VariantReport {
            fingerprint: Fingerprint::new(scene, s, &run.design),
            streamed: false,
            cannot_seat: run.cannot_seat,
            seating_paths: None,
            unconverged: None,
            load_path: None,
            scene: scene.file.clone(),
            name: scene.name.clone(),
            samples: run.design.n,
            sampler: run.design.sampler,
            seed: run.design.seed,
            mu_static: f.mu_static,
            spread: f.spread,
            contact_friction: scene.contact_friction.clone(),
            mu_distribution: scene.mu_distribution.clone(),
            mu_correlation: scene.mu_correlation,
            dynamic_ratio: f.dynamic_ratio,
            friction_law: f.law,
            ramp_time_s: scene.preload.ramp_time,
            solver: s.method.name().to_string(),
            inputs: var.inputs(scene),
            start_bounds: var.start.map(|b| [b.offset.into(), b.tilt.into()]),
            variation_bounds: (var.preload || var.tolerances).then_some(scene.variation),
            seating_failures: None,
            seating_failure_share: None,
            assessment: None,
            partial: run.shard.count > 1,
            points: Vec::new(),
            interchangeability: Vec::new(),
            thermal: scene.thermal.as_ref().filter(|_| var.reseating()).map(ThermalStudy::of),
            sensitivity: s.sensitivity.then(Vec::new),
            design: run.design,
            shard: run.shard,
            output_names: run.output_names,
            evaluation_points: scene.evaluation_points.clone(),
            records,
        }
    }

    /// The temperature changes [moving, fixed] of each cycle point [K]
    /// (empty without `[thermal]`).
    pub fn thermal_cycle(&self) -> Vec<[f64; 2]> {
        self.thermal.as_ref().map_or_else(Vec::new, |t| t.cycle_delta_t_k.clone())
    }

    fn varies(&self, kind: Varied) -> bool {
        self.inputs.iter().any(|i| i.kind() == kind)
    }

    /// The variation this study used (to map design rows to inputs).
    pub fn variation(&self) -> Variation {
        Variation {
            friction: self.varies(Varied::Friction),
            preload: self.varies(Varied::Preload),
            tolerances: self.varies(Varied::Tolerances),
            start: self.start_bounds.map(|[o, t]| StartBounds { offset: o.into(), tilt: t.into() }),
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
        StudyDocument {
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
}

impl StudyReport {
    /// One warning per variant with seatings in the decay law's transition.
    pub fn unconverged(&self) -> Vec<String> {
        self.variants
            .iter()
            .filter_map(|v| {
                v.unconverged.map(|u| {
                    format!(
                        "{}: {} seatings: {}",
                        v.scene,
                        u.seatings,
                        crate::contact::friction::transition_warning(u.max_cv)
                    )
                })
            })
            .collect()
    }
}

fn default_ramp_time() -> f64 {
    DEFAULT_RAMP_TIME
}

/// The thermal set-up of a study (`[thermal]`): what each sample followed
/// after its seating.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ThermalStudy {
    pub moving_body: String,
    pub moving_thermal_expansion_per_k: f64,
    pub fixed_body: String,
    pub fixed_thermal_expansion_per_k: f64,
    /// Each cycle point's temperature changes [moving, fixed] [K].
    pub cycle_delta_t_k: Vec<[f64; 2]>,
    /// The legs' error tolerance (`[thermal] path_tolerance`).
    pub path_tolerance: f64,
}

impl ThermalStudy {
    fn of(t: &crate::scene::Thermal) -> Self {
        let b = &t.bodies;
        ThermalStudy {
            moving_body: b.moving.material.clone(),
            moving_thermal_expansion_per_k: b.moving.thermal_expansion,
            fixed_body: b.fixed.material.clone(),
            fixed_thermal_expansion_per_k: b.fixed.thermal_expansion,
            cycle_delta_t_k: t.cycle.iter().map(|c| [c.moving, c.fixed]).collect(),
            path_tolerance: t.path_tolerance,
        }
    }
}
