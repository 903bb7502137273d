//! Running a sweep ([`run`]: the design points in parallel, each point's
//! study by the study's own machinery) into its document (`kinrepro sweep
//! --format json`, docs/output.md, "Sweeps"): one entry per design point
//! with its swept values, its status, the study statistics of every
//! evaluation point exactly as a study's `points`, the nominal seating's
//! stiffness, safety factor, friction limit and approach, and the Pareto
//! mark. Shard merging: [`super::merge`]; table, CSV and charts:
//! `report::sweep::text`, `report::sweep::plot`.

use rayon::prelude::*;
use serde::{Deserialize, Serialize};
use thiserror::Error;

pub use super::design_report::{DesignReport, design_report};
use super::goal::Goals;
use super::pareto::{Objectives, front_of};
use super::{DesignKind, FieldKind, SweepSpec};
use super::{ExploreError, evaluate, point_file};
use crate::assembly::Coupling;
use crate::param::Param;
use crate::scene::Scene;
use crate::study::provenance::{Fingerprint, SCHEMA_VERSION, VERSION, fnv1a64, produced_by};
use crate::study::{Sampler, Shard, StudyError, StudyOptions, StudyPlan};

/// One `--set` as given.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SetRecord {
    /// TOML path of the field.
    pub field: String,
    /// The VALUES as written.
    pub values: String,
    pub kind: FieldKind,
}

/// What a sweep's numbers depend on (`merge` compares it).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepFingerprint {
    /// FNV-1a 64 of the base scene text as read.
    pub scene_content: String,
    pub sets: Vec<SetRecord>,
    pub design: DesignKind,
    pub design_points: usize,
    pub pareto_point: String,
    /// The study settings of every design point (the base scene's).
    pub study: Fingerprint,
    /// The objectives and constraints of the front.
    #[serde(default, flatten)]
    pub goals: Goals,
}

/// The whole sweep document.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SweepReport {
    pub schema_version: u32,
    pub kinrepro_version: String,
    /// Always `sweep` (tells a sweep from a study document).
    pub document: String,
    pub solver: String,
    pub sampler: Sampler,
    pub seed: u64,
    /// Samples per design point.
    pub samples: usize,
    pub vary: Vec<String>,
    pub scene: String,
    pub name: String,
    pub design: DesignKind,
    /// Design points of the whole sweep (all shards).
    pub design_points: usize,
    pub sets: Vec<SetRecord>,
    /// The evaluation point whose sigma is the Pareto objective.
    pub pareto_point: String,
    /// `--objective` and `--constraint` (explore::goal): the front is on
    /// these objectives among the designs that meet these constraints
    /// (none given: the largest translational sigma at `pareto_point`,
    /// k_min and SF_p).
    #[serde(default, flatten)]
    pub goals: Goals,
    pub fingerprint: SweepFingerprint,
    pub shard: Shard,
    /// This shard's design points (all of them when `shard` is 1/1).
    pub designs: Vec<DesignReport>,
}

/// A sweep that cannot run.
#[derive(Debug, Error)]
pub enum SweepError {
    #[error(transparent)]
    Explore(#[from] ExploreError),
    /// The study of the base scene cannot be planned.
    #[error(transparent)]
    Study(#[from] StudyError),
    /// No design point of a whole sweep was evaluated: each is invalid,
    /// cannot seat or failed.
    #[error(
        "{file}: none of the {points} design points was evaluated (each is listed with its status: \
         invalid, cannot seat or failed)"
    )]
    NoValidDesign { file: String, points: usize },
    /// The optimisation's search failed (argmin's message).
    #[error("optimisation: {0}")]
    Optimize(String),
    /// `pareto_point` names no evaluation point of the base scene.
    #[error("{file}: {}: no such evaluation point (the scene has {have})", Param::ParetoPoint.with(point))]
    ParetoPoint { file: String, point: String, have: String },
}

/// The plan of every design point's study: `options` for the base scene
/// `scene` (assembled as `coupling`), the whole design (a sweep's shards
/// split its design points, not a point's samples).
pub fn study_plan(
    scene: Scene,
    coupling: Coupling,
    options: &StudyOptions,
) -> Result<StudyPlan, StudyError> {
    let whole = StudyOptions { shard: Shard::whole(), ..options.clone() };
    StudyPlan::keeping_records(vec![(scene, coupling)], &whole)
}

/// Run shard `shard` of the design points of `spec` (rayon across designs
/// and samples), each point's study the base scene's in `plan` (from
/// [`study_plan`]); `pareto_point` names the evaluation point of the
/// default Pareto objective (None: the first); `goals` the front's
/// objectives and constraints (empty: the default objectives).
pub fn run(
    spec: &SweepSpec,
    plan: &StudyPlan,
    shard: Shard,
    (pareto_point, goals): (Option<&str>, &Goals),
    tick: &(dyn Fn() + Sync),
) -> Result<SweepReport, SweepError> {
    let base = &plan.variants[0];
    let points = spec.points()?;
    let pareto_point = pareto_point_of(&spec.file, &base.scene, pareto_point)?;
    let range = shard.range(points.len()).map_err(|e| e.at(Param::Shard))?;
    let designs: Vec<DesignReport> = points[range]
        .par_iter()
        .map(|p| {
            let file = point_file(&spec.base, &spec.sets, &p.values);
            let e = evaluate(file, &spec.text, &spec.label(p), plan, (base, true), tick);
            let values =
                spec.sets.iter().map(|s| s.path.clone()).zip(p.values.iter().cloned()).collect();
            design_report(p.index, values, e)
        })
        .collect();
    let sets: Vec<SetRecord> = spec
        .sets
        .iter()
        .map(|s| SetRecord { field: s.path.clone(), values: s.spec.clone(), kind: s.kind })
        .collect();
    let mut report = SweepReport {
        schema_version: SCHEMA_VERSION,
        kinrepro_version: VERSION.to_string(),
        document: "sweep".to_string(),
        solver: plan.method().name().to_string(),
        sampler: base.design.sampler,
        seed: base.design.seed,
        samples: base.design.n,
        vary: vec!["friction".to_string()],
        scene: spec.file.clone(),
        name: base.scene.name.clone(),
        design: spec.design,
        design_points: points.len(),
        sets: sets.clone(),
        pareto_point: pareto_point.clone(),
        goals: goals.clone(),
        fingerprint: SweepFingerprint {
            scene_content: format!("{:016x}", fnv1a64(spec.text.as_bytes())),
            sets,
            design: spec.design,
            design_points: points.len(),
            pareto_point,
            study: Fingerprint::new(&base.scene, &plan.settings, &base.design),
            goals: goals.clone(),
        },
        shard,
        designs,
    };
    report.mark_pareto();
    Ok(report)
}

/// The evaluation point of the Pareto objective: `asked`, or the first.
fn pareto_point_of(file: &str, base: &Scene, asked: Option<&str>) -> Result<String, SweepError> {
    let names: Vec<&str> = base.evaluation_points.iter().map(|p| p.name.as_str()).collect();
    match asked {
        None => Ok(names[0].to_string()),
        Some(p) if names.contains(&p) => Ok(p.to_string()),
        Some(p) => Err(SweepError::ParetoPoint {
            file: file.to_string(),
            point: p.to_string(),
            have: names.join(", "),
        }),
    }
}

impl SweepReport {
    /// Set each evaluated design's broken constraints, and each design's
    /// Pareto mark (only when this document holds every design; a shard's
    /// marks stay null until `merge`): the front among the designs that
    /// meet every constraint, on the chosen objectives (or the default).
    pub fn mark_pareto(&mut self) {
        for d in self.designs.iter_mut().filter(|d| d.status == "ok") {
            d.broken_constraints = self.goals.broken(d);
        }
        if self.shard.count != 1 {
            return;
        }
        let values: Vec<Option<Vec<f64>>> =
            self.designs.iter().map(|d| self.front_values(d)).collect();
        for (d, on) in self.designs.iter_mut().zip(front_of(&values)) {
            d.pareto = Some(on);
        }
    }

    /// The values the front compares of design `d`, larger is better (None:
    /// not evaluated, breaking a constraint, or without every objective).
    pub fn front_values(&self, d: &DesignReport) -> Option<Vec<f64>> {
        if d.status != "ok" || !d.broken_constraints.is_empty() {
            return None;
        }
        if self.goals.objectives.is_empty() {
            let with_safety = self.designs.iter().any(|d| d.min_pressure_safety_factor.is_some());
            return Some(self.objectives(d)?.values(with_safety));
        }
        self.goals.objectives.iter().map(|o| o.better(d)).collect()
    }

    /// The Pareto objectives of an evaluated design (None otherwise).
    pub fn objectives(&self, d: &DesignReport) -> Option<Objectives> {
        let p = d.points.iter().find(|p| p.name == self.pareto_point)?;
        let s = p.sigma.values();
        Some(Objectives {
            sigma_max: s[0].max(s[1]).max(s[2]) * 1e-9,
            stiffness_min: d.principal_stiffness_n_per_m?[0],
            safety_factor: d.min_pressure_safety_factor,
        })
    }

    /// [`SweepError::NoValidDesign`] if this document holds the whole
    /// sweep (not one shard of several) and none of its design points was
    /// evaluated (status `ok`): no point gives a result, as a study of a
    /// coupling that cannot seat gives none; a shard cannot tell, its
    /// `merge` does.
    pub fn check_any_valid(&self) -> Result<(), SweepError> {
        let whole = self.shard.count == 1;
        match whole && self.designs.iter().all(|d| d.status != "ok") {
            true => Err(SweepError::NoValidDesign {
                file: self.scene.clone(),
                points: self.designs.len(),
            }),
            false => Ok(()),
        }
    }

    /// The line naming what produced this document.
    pub fn produced_by(&self) -> String {
        format!(
            "{}, sweep of {} ({} design, {} points), shard {}",
            produced_by(
                &self.solver,
                &self.sampler.to_string(),
                &self.seed.to_string(),
                &self.samples.to_string(),
                &self.vary.join("+")
            ),
            self.scene,
            self.design.name(),
            self.design_points,
            self.shard
        )
    }
}
