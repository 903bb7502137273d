//! A prediction document (`kinrepro predict --format json`) in the report:
//! the study schema plus a top-level `calibration` block (the calibrated
//! parameters with their intervals) and, per variant, the `measured` sigma
//! where the variant is the calibrated design (docs/output.md,
//! docs/calibration.md).
//!
//! The scenes of a prediction ran with the calibrated parameters in place
//! of the file's, so the report applies the same estimates
//! ([`crate::calibrate::params::apply_named`]) before it checks the
//! scene file against the prediction's `scene_content` hash and seats it.

use std::collections::BTreeMap;
use std::fmt::Write as _;
use std::path::Path;

use serde::Deserialize;

use crate::assembly::Coupling;
use crate::calibrate::params::apply_named;
use crate::dof::Dof;
use crate::report::study::reference::ReferenceRow;
use crate::report::table::escape;
use crate::scene::Scene;

/// The `calibration` block of a prediction.
#[derive(Debug, Clone, PartialEq, Deserialize)]
pub struct CalibrationBlock {
    /// The calibration file the prediction read.
    pub file: String,
    /// The calibrated (measured) scene and evaluation point.
    pub scene: String,
    pub point: String,
    pub parameters: BTreeMap<String, CalibratedParameter>,
    pub goodness_of_fit_ok: bool,
}

/// One calibrated parameter: estimate and interval at `level`.
#[derive(Debug, Clone, PartialEq, Deserialize)]
pub struct CalibratedParameter {
    pub estimate: f64,
    pub low: f64,
    pub high: f64,
    pub level: f64,
    /// False where the data do not determine the parameter (schema 2).
    #[serde(default = "yes")]
    pub determined: bool,
}

fn yes() -> bool {
    true
}

/// The measured sigma of a variant that is the calibrated design.
#[derive(Debug, Clone, PartialEq, Deserialize)]
struct MeasuredBlock {
    point: String,
    cycles: Option<usize>,
    /// Per DOF, keyed by [`Dof::key`] (nm, nrad).
    sigma: BTreeMap<String, f64>,
}

#[derive(Deserialize)]
struct VariantExtras {
    #[serde(default)]
    measured: Option<MeasuredBlock>,
    scene: String,
}

#[derive(Deserialize)]
struct Extras {
    #[serde(default)]
    calibration: Option<CalibrationBlock>,
    #[serde(default)]
    variants: Vec<VariantExtras>,
}

/// What a prediction adds to a study document: its calibration, and the
/// measured sigma as reference rows.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct PredictionInput {
    pub calibration: Option<CalibrationBlock>,
    pub measured: Vec<ReferenceRow>,
}

impl PredictionInput {
    /// The prediction parts of a study JSON text (none for a plain study).
    pub fn parse(text: &str) -> Result<Self, serde_json::Error> {
        let extras: Extras = serde_json::from_str(text)?;
        let measured = extras
            .variants
            .iter()
            .filter_map(|v| v.measured.as_ref().map(|m| measured_row(&v.scene, m)))
            .collect();
        Ok(PredictionInput { calibration: extras.calibration, measured })
    }

    /// The scene and coupling as the prediction ran them: the calibrated
    /// estimates in place of the scene's values.
    pub fn apply(&self, scene: &mut Scene, coupling: &mut Coupling) {
        if let Some(c) = &self.calibration {
            let values: BTreeMap<String, f64> =
                c.parameters.iter().map(|(k, p)| (k.clone(), p.estimate)).collect();
            apply_named(scene, coupling, &values);
        }
    }

    /// The "Run" section's paragraph on the calibration (empty for a study).
    pub fn html(&self) -> String {
        let Some(c) = &self.calibration else {
            return String::new();
        };
        let mut s = format!(
            "<p class=\"note\">Prediction with the parameters calibrated on the measured scatter of {} (point {}; calibration file {}):",
            escape(&c.scene),
            escape(&c.point),
            escape(&c.file)
        );
        for (name, p) in &c.parameters {
            let _ = write!(
                s,
                " {} = {} ({:.0} % interval [{}, {}]{});",
                escape(name),
                number(p.estimate),
                100.0 * p.level,
                number(p.low),
                number(p.high),
                if p.determined { "" } else { ", NOT DETERMINED by the data" }
            );
        }
        let _ = write!(
            s,
            " goodness of fit {}. The σ intervals are prediction intervals: the range of σ over the parameters' region and the sampling error of the study.",
            if c.goodness_of_fit_ok {
                "ok"
            } else {
                "POOR: the model does not explain the measured scatter"
            }
        );
        if !self.measured.is_empty() {
            s.push_str(
                " Highlighted rows and black ticks: the measured σ of the calibrated design.",
            );
        }
        s.push_str("</p>\n");
        s
    }
}

/// A fitted value or an interval end: 4 significant digits.
fn number(v: f64) -> String {
    crate::report::table::significant(v, 4)
}

/// The measured block as a reference row (nm, nrad).
fn measured_row(scene: &str, m: &MeasuredBlock) -> ReferenceRow {
    let sigma = std::array::from_fn(|i| m.sigma.get(&Dof::ALL[i].key()).copied());
    ReferenceRow {
        label: match m.cycles {
            Some(n) => format!("measured ({n} cycles)"),
            None => "measured".into(),
        },
        scene: Path::new(scene)
            .file_stem()
            .map_or_else(|| scene.to_string(), |s| s.to_string_lossy().into_owned()),
        point: m.point.clone(),
        sigma,
    }
}
