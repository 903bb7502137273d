//! The values a study reports per sample and per DOF: [`StudyRecord`] (one
//! sample: physical inputs, design coordinates, outputs, all SI) and
//! [`PointStats`] (statistics in nm and nrad, [`Dofs`]). Field meanings:
//! docs/output.md.

use serde::{Deserialize, Serialize};

use super::runner::Variation;
use super::stats::SampleRecord;
use super::variant::Variant;

pub use crate::dof::Dofs;

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
    /// The record of a seated sample of `v`, with the physical values its
    /// design row maps to under `variation`.
    pub fn new(v: &Variant, variation: &Variation, r: SampleRecord) -> Self {
        StudyRecord {
            index: r.index,
            physical: variation.sample(&v.scene, &v.coupling, &r.inputs).physical,
            inputs: r.inputs,
            outputs: r.outputs,
        }
    }

    /// False for a seating that did not centre (varied start; no outputs).
    pub fn centred(&self) -> bool {
        !self.outputs.is_empty()
    }

    /// The statistics' view of this record (design coordinates and outputs).
    pub fn sample(&self) -> SampleRecord {
        SampleRecord {
            index: self.index,
            inputs: self.inputs.clone(),
            outputs: self.outputs.clone(),
        }
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
    /// The point's named directions (`directions`, `frame`): the same
    /// statistics of the translation along each (or rotation about it).
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub directions: Vec<DirectionStats>,
    /// A scene with `[thermal]`: the drift of this point from each
    /// sample's own seated pose at each cycle point, over the samples.
    #[serde(default, skip_serializing_if = "Vec::is_empty")]
    pub thermal: Vec<CycleStats>,
}

/// Statistics of the translation of a point along a named direction (or
/// its rotation about one), in `unit` (nm or nrad): the projection of each
/// sample's pose onto the direction's unit vector, summarised as every DOF.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DirectionStats {
    pub name: String,
    /// `along` (translation, nm) or `about` (rotation, nrad).
    pub kind: String,
    /// The unit vector (the scene's vector normalised; absent in documents
    /// that do not carry their evaluation points).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub vector: Option<[f64; 3]>,
    /// `nm` or `nrad`: the unit of every value below.
    pub unit: String,
    pub sigma: f64,
    pub sigma_ci90_low: Option<f64>,
    pub sigma_ci90_high: Option<f64>,
    pub three_sigma: f64,
    pub mean: f64,
    pub min: f64,
    pub max: f64,
}

impl DirectionStats {
    /// `along <name>` or `about <name>`: table and chart labels.
    pub fn label(&self) -> String {
        format!("{} {}", self.kind, self.name)
    }

    /// `along/<name>` or `about/<name>`: the CSV `dof` column.
    pub fn key(&self) -> String {
        format!("{}/{}", self.kind, self.name)
    }

    /// `m` or `rad`.
    pub fn si_unit(&self) -> &'static str {
        if self.unit == "nrad" { "rad" } else { "m" }
    }

    /// The 90 % interval of sigma, if the design gives one.
    pub fn interval(&self) -> Option<[f64; 2]> {
        Some([self.sigma_ci90_low?, self.sigma_ci90_high?])
    }
}

/// One cycle point's drift statistics of an evaluation point (nm, nrad):
/// the drift of each sample from its own seated pose (rigid motion of the
/// moving half and the body's expansion), its mean, sigma with the
/// interval of the design, +- 3 sigma, min and max.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct CycleStats {
    /// Temperature changes of the moving and the fixed body from the
    /// seating temperature [K].
    pub delta_t_k: [f64; 2],
    #[serde(flatten)]
    pub drift: PointStats,
}
