//! Design exploration: `kinrepro sweep`. A sweep sets fields of a
//! high-level scene by their TOML path ([`field`]) to the values of a grid
//! or a Latin hypercube over the swept ranges ([`values`], [`design`]),
//! validates every design point exactly like a scene file (its typed form
//! goes through [`crate::scene::Scene::from_file`]) and evaluates it
//! ([`evaluate`]): the reproducibility study of the sweep's study plan with
//! the same design (same seed: common random numbers across the designs), plus
//! the nominal seating's principal stiffnesses, smallest safety factor
//! against the allowable pressure, friction limit and approach. [`pareto`]
//! marks the designs no other design beats. [`run`] runs the design points
//! (rayon across them) into the sweep's document; [`merge`] joins its
//! shards.
//!
//! Data flow: scene -> assembly -> solve -> study -> explore; the sweep's
//! tables, CSV and charts are in `report::sweep::text` and
//! `report::sweep::plot`.

pub mod design;
pub mod design_report;
pub mod evaluate;
pub mod field;
pub mod goal;
pub mod merge;
pub mod optimize;
pub mod pareto;
pub mod run;
pub mod values;

use thiserror::Error;

use crate::param::Param;
use crate::scene::{SceneError, SceneFile};
pub use design::{DesignKind, DesignPoint, design_points};
pub use evaluate::{Evaluation, Nominal, Outcome, evaluate, point_file};
pub use field::{FieldError, FieldKind, SweptValue};
pub use merge::{SweepMergeError, merge_sweeps};
pub use run::{DesignReport, SweepError, SweepReport};
pub use values::{Levels, Set, ValuesError};

/// A sweep that cannot be set up (the whole command fails with this line;
/// a bad design point is reported in the output instead).
#[derive(Debug, Error)]
pub enum ExploreError {
    #[error("{}: {reason}", Param::Sets.with(path))]
    Field { path: String, reason: FieldError },
    #[error("{}: {reason}", Param::Sets.with(format!("{path}={spec}")))]
    Values { path: String, spec: String, reason: ValuesError },
    #[error("{}: expected FIELD=VALUES, e.g. preload.force=5,10,20", Param::Sets.with(arg))]
    SetSyntax { arg: String },
    #[error(transparent)]
    Scene(#[from] SceneError),
    #[error("{file}: a sweep needs the high-level form of a scene ([coupling] table)")]
    NotHighLevel { file: String },
    #[error("sweep design: {0}")]
    Design(String),
    /// An optimisation's `FIELD=VALUES` not understood.
    #[error("{}: {reason}", Param::Vary.with(format!("{path}={spec}")))]
    Vary { path: String, spec: String, reason: String },
    /// An objective or a constraint not understood.
    #[error(transparent)]
    Goal(#[from] goal::GoalError),
}

/// A sweep as asked for: the base scene and what to vary how.
#[derive(Debug, Clone)]
pub struct SweepSpec {
    /// The scene file (for messages and the output).
    pub file: String,
    /// Its text as read (its hash enters the fingerprint).
    pub text: String,
    /// Its typed form (each design point sets fields in a copy).
    pub base: SceneFile,
    pub sets: Vec<Set>,
    pub design: DesignKind,
}

impl SweepSpec {
    /// Parse the base scene text and the swept fields (`FIELD=VALUES`
    /// each). The base scene must be a high-level scene; whether it
    /// validates is checked by the caller (it loads it like any scene).
    pub fn new(
        file: &str,
        text: &str,
        set_args: &[String],
        design: DesignKind,
    ) -> Result<Self, ExploreError> {
        let base = SceneFile::parse(text, file)?;
        if base.coupling.is_none() {
            return Err(ExploreError::NotHighLevel { file: file.to_string() });
        }
        let sets = set_args.iter().map(|a| Set::parse(a, &base)).collect::<Result<Vec<_>, _>>()?;
        Ok(SweepSpec { file: file.to_string(), text: text.to_string(), base, sets, design })
    }

    /// The design points.
    pub fn points(&self) -> Result<Vec<DesignPoint>, ExploreError> {
        design_points(&self.sets, self.design)
    }

    /// The swept fields, by path.
    pub fn paths(&self) -> Vec<String> {
        self.sets.iter().map(|s| s.path.clone()).collect()
    }

    /// The label of design point `p` in messages: `FILE [a = 1, b = 2]`.
    pub fn label(&self, p: &DesignPoint) -> String {
        let v: Vec<String> =
            self.sets.iter().zip(&p.values).map(|(s, v)| format!("{} = {v}", s.path)).collect();
        format!("{} [{}]", self.file, v.join(", "))
    }
}
