//! The calibration file (docs/measurements.md, schema
//! [`CALIBRATION_SCHEMA_VERSION`]) and the parts of it the fit
//! ([`super::fit`]) fills in: the options, the observation, the evaluation
//! point, the sensor noise and the measured-against-fitted table.

use std::collections::BTreeMap;

use nalgebra::DMatrix;
use serde::{Deserialize, Serialize};

use super::error::CalibrateError;
use super::grid::GridInfo;
use super::likelihood::{GoodnessOfFit, Observed};
use super::measurement::{MeasuredData, Measurement};
use crate::dof::Dof;
use crate::scene::{Sampler, Scene, StudyDefaults};
use crate::solve::Solver;
use crate::study::provenance::{Fingerprint, VERSION, content_hash};

/// Version of the calibration file's schema (docs/measurements.md).
pub const CALIBRATION_SCHEMA_VERSION: u32 = 2;

/// Calibration schema versions `predict` reads (1: spread only, no `region`).
pub const READABLE_SCHEMA_VERSIONS: [u32; 2] = [1, 2];

pub use super::params::PARAMETERS;

#[derive(Debug, Clone, PartialEq)]
pub struct CalibrateOptions {
    /// Parameters to fit (any of [`PARAMETERS`], each once).
    pub fit: Vec<String>,
    /// Sensor noise per DOF [SI], overriding the file's `# noise:`.
    pub noise: [Option<f64>; 6],
    /// Evaluation point (overrides the file's `point` column).
    pub point: Option<String>,
    pub samples: usize,
    pub seed: u64,
    /// The solver of the model studies.
    pub solver: Solver,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Parameter {
    pub estimate: f64,
    pub low: f64,
    pub high: f64,
    pub level: f64,
    pub method: String,
    /// Sandwich factor k of the adjusted likelihood ratio (1: normal scatter).
    pub sandwich_factor: f64,
    /// Standard deviation of ln(estimate) due to the finite model study,
    /// added to the interval in quadrature on ln s.
    pub model_error: f64,
    /// The interval reached the end of the searched range (`range`).
    pub low_at_bound: bool,
    pub high_at_bound: bool,
    /// The searched range [low, high] (schema 2).
    #[serde(default)]
    pub range: Option<[f64; 2]>,
    /// False when an end of the interval is a range end: the data do not
    /// determine the parameter there (schema 2).
    #[serde(default)]
    pub determined: bool,
}

/// Correlation of the estimates (schema 2), from the sandwich covariance
/// H^-1 J H^-1 at the estimate.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Correlation {
    pub parameters: Vec<String>,
    pub matrix: Vec<Vec<f64>>,
}

/// Measured against fitted sigma of one DOF [SI].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct DofFit {
    pub dof: Dof,
    pub unit: String,
    pub cycles: usize,
    pub measured_sigma: f64,
    pub noise_sigma: f64,
    /// Model plus noise at the estimate: sqrt(Sigma_jj).
    pub fitted_sigma: f64,
    /// The coupling's own scatter at the estimate (no sensor noise).
    pub model_sigma: f64,
}

/// The model studies behind the fit.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ModelInfo {
    pub solver: String,
    pub sampler: String,
    pub seed: u64,
    pub samples: usize,
    /// The scale parameter of the friction distribution that
    /// `reference_spread` and the grid's `spread` give: `spread` (uniform)
    /// or `sd` (normal, lognormal); older files have none (`spread`).
    #[serde(default = "spread_name")]
    pub scale: String,
    /// The reference value of the scale parameter (`scale`).
    pub reference_spread: f64,
    /// Largest relative change over the measured DOFs of sigma / spread
    /// between the reference (the first model grid, at the reference
    /// spread) and the direct study at the estimate.
    pub linearity: f64,
    /// The model grid over the fitted parameters other than the spread.
    #[serde(default)]
    pub grid: Option<GridInfo>,
}

#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Calibration {
    pub schema_version: u32,
    pub kind: String,
    pub kinrepro_version: String,
    pub scene: String,
    pub scene_name: String,
    /// FNV-1a hash of the resolved scene without file, spread and study
    /// settings: `predict` recognises the calibrated design by it.
    pub scene_content: String,
    pub point: String,
    pub measured_file: String,
    /// `cycles` or `summary`.
    pub data: String,
    pub metadata: BTreeMap<String, String>,
    pub parameters: BTreeMap<String, Parameter>,
    /// Correlation of the estimates (None: H singular).
    #[serde(default)]
    pub correlation: Option<Correlation>,
    /// Points of the joint parameter region at its boundary (the profile
    /// interval ends, with the other parameters at their profile maximum,
    /// and the ends of its principal axes): `predict` takes the range of
    /// its prediction over them and the estimate.
    #[serde(default)]
    pub region: Vec<BTreeMap<String, f64>>,
    /// The parameters held at the scene's values.
    pub fixed: BTreeMap<String, f64>,
    pub goodness_of_fit: GoodnessOfFit,
    pub dofs: Vec<DofFit>,
    pub model: ModelInfo,
    pub fingerprint: Fingerprint,
}

fn spread_name() -> String {
    "spread".into()
}

/// The design hash of a scene: [`content_hash`] of the scene without its
/// file, name, spread and study defaults (the calibrated design,
/// whichever spread and study it is run with).
pub fn design_hash(scene: &Scene) -> String {
    let mut s = scene.clone();
    s.file = String::new();
    s.name = String::new();
    s.set_mu_scale(0.0);
    s.study = StudyDefaults { samples: 0, sampler: Sampler::MonteCarlo, seed: 0 };
    content_hash(&s)
}

/// Index of the evaluation point `name` (None: the first).
pub fn point_index(scene: &Scene, name: Option<&str>, file: &str) -> Result<usize, CalibrateError> {
    let pts = &scene.evaluation_points;
    match name {
        None => Ok(0),
        Some(n) => pts.iter().position(|p| p.name == n).ok_or_else(|| CalibrateError::Point {
            file: file.to_string(),
            point: n.to_string(),
            have: pts.iter().map(|p| format!("`{}`", p.name)).collect::<Vec<_>>().join(", "),
        }),
    }
}

/// The observation in the measurement's DOF order.
pub fn observed(m: &Measurement) -> Observed {
    match &m.data {
        MeasuredData::Cycles(rows) => Observed::Covariance {
            s: m.covariance().unwrap_or_else(|| DMatrix::zeros(0, 0)),
            n: rows.len(),
        },
        MeasuredData::Summary { sigma, cycles } => {
            Observed::Sigmas { sigma: sigma.clone(), cycles: cycles.clone() }
        }
    }
}

/// The sensor noise sigma per measured DOF: `--noise`, else the file's.
pub fn noise_of(m: &Measurement, opts: &CalibrateOptions) -> Vec<f64> {
    m.dofs.iter().map(|&d| opts.noise[d].or(m.noise[d]).unwrap_or(0.0)).collect()
}

/// A calibration file of measurement `m` with its goodness of fit and
/// model; `parameters`, `fixed`, `dofs`, `correlation` and `region` are
/// left empty for the caller.
pub fn skeleton(
    scene: &Scene,
    m: &Measurement,
    point: usize,
    gof: GoodnessOfFit,
    model: ModelInfo,
    fingerprint: Fingerprint,
) -> Calibration {
    Calibration {
        schema_version: CALIBRATION_SCHEMA_VERSION,
        kind: "calibration".into(),
        kinrepro_version: VERSION.into(),
        scene: scene.file.clone(),
        scene_name: scene.name.clone(),
        scene_content: design_hash(scene),
        point: scene.evaluation_points[point].name.clone(),
        measured_file: m.file.clone(),
        data: match m.data {
            MeasuredData::Cycles(_) => "cycles",
            MeasuredData::Summary { .. } => "summary",
        }
        .into(),
        metadata: m.metadata.iter().cloned().collect(),
        parameters: BTreeMap::new(),
        correlation: None,
        region: Vec::new(),
        fixed: BTreeMap::new(),
        goodness_of_fit: gof,
        dofs: Vec::new(),
        model,
        fingerprint,
    }
}

/// Measured against fitted sigma per measured DOF.
pub fn dof_fits(
    m: &Measurement,
    noise: &[f64],
    fitted: &DMatrix<f64>,
    g: &DMatrix<f64>,
    estimate: f64,
) -> Vec<DofFit> {
    let measured = m.sigma();
    let cycles = m.cycles();
    m.dofs
        .iter()
        .enumerate()
        .map(|(j, &d)| DofFit {
            dof: Dof::ALL[d],
            unit: Dof::ALL[d].si_unit().into(),
            cycles: cycles[j],
            measured_sigma: measured[j],
            noise_sigma: noise[j],
            fitted_sigma: fitted[(j, j)].sqrt(),
            model_sigma: estimate * g[(j, j)].sqrt(),
        })
        .collect()
}

/// Most points of a calibration's parameter region (`predict` runs one
/// Monte Carlo study per point; a fit of all four parameters has 3^4 = 81
/// at most).
pub const MAX_REGION: usize = 100;

/// One fitted parameter as a fit writes it: finite, 0 <= low <= estimate
/// <= high, a spread above zero, a level in (0, 1); what is wrong, if anything.
fn check_parameter(name: &str, p: &Parameter) -> Option<String> {
    let at = format!("`parameters.{name}`");
    let (e, lo, hi) = (p.estimate, p.low, p.high);
    if ![e, lo, hi, p.level].iter().all(|v| v.is_finite()) {
        return Some(format!(
            "{at}: estimate {e}, low {lo}, high {hi}, level {}: not finite",
            p.level
        ));
    }
    if !(0.0 <= lo && lo <= e && e <= hi) {
        return Some(format!(
            "{at}: estimate {e} with interval [{lo}, {hi}]: need 0 <= low <= estimate <= high"
        ));
    }
    for (field, v) in [("estimate", e), ("low", lo), ("high", hi)] {
        if let Err(r) = super::params::physical(name, v) {
            return Some(format!("`parameters.{name}.{field}`: {r}"));
        }
    }
    if (name == "spread" || name == "sd") && e <= 0.0 {
        return Some(format!("{at}: estimate {e}: a calibrated {name} is > 0"));
    }
    if !(p.level > 0.0 && p.level < 1.0) {
        return Some(format!("{at}: level {}: need a probability in (0, 1)", p.level));
    }
    None
}

impl Calibration {
    /// Parse a calibration file's text.
    pub fn parse(text: &str, file: &str) -> Result<Self, CalibrateError> {
        let bad = |reason: String| CalibrateError::Calibration { file: file.into(), reason };
        let c: Calibration = serde_json::from_str(text).map_err(|e| bad(e.to_string()))?;
        if c.kind != "calibration" || !READABLE_SCHEMA_VERSIONS.contains(&c.schema_version) {
            return Err(bad(format!(
                "kind `{}` schema {} (need kind `calibration`, schema 1 or {CALIBRATION_SCHEMA_VERSION})",
                c.kind, c.schema_version
            )));
        }
        if c.parameters.is_empty() {
            return Err(bad("no fitted parameter in `parameters`".into()));
        }
        if let Some(p) = c.parameters.keys().find(|k| !PARAMETERS.contains(&k.as_str())) {
            return Err(bad(format!("unknown parameter `{p}` in `parameters`")));
        }
        if let Some(reason) = c.parameters.iter().find_map(|(k, p)| check_parameter(k, p)) {
            return Err(bad(reason));
        }
        if c.region.len() > MAX_REGION {
            return Err(bad(format!(
                "`region`: {} points, at most {MAX_REGION} (predict runs one study per point)",
                c.region.len()
            )));
        }
        for (i, point) in c.region.iter().enumerate() {
            if let Some((k, v)) = point
                .iter()
                .find(|(k, v)| !c.parameters.contains_key(*k) || !v.is_finite() || **v < 0.0)
            {
                return Err(bad(format!(
                    "`region[{i}]`: `{k}` = {v} (need a fitted parameter with a finite value >= 0)"
                )));
            }
            for (k, v) in point {
                super::params::physical(k, *v)
                    .map_err(|r| bad(format!("`region[{i}].{k}`: {r}")))?;
            }
        }
        Ok(c)
    }

    /// The calibrated spread (None: the spread was held fixed).
    pub fn spread(&self) -> Option<&Parameter> {
        self.parameters.get("spread")
    }

    /// The points of the parameter region `predict` evaluates besides the
    /// estimate (a schema-1 file: the ends of the spread's interval).
    pub fn region_points(&self) -> Vec<BTreeMap<String, f64>> {
        if !self.region.is_empty() {
            return self.region.clone();
        }
        self.spread()
            .map(|p| {
                [(p.low > 0.0).then_some(p.low), Some(p.high)]
                    .into_iter()
                    .flatten()
                    .map(|v| BTreeMap::from([("spread".to_string(), v)]))
                    .collect()
            })
            .unwrap_or_default()
    }

    pub fn estimates(&self) -> BTreeMap<String, f64> {
        self.parameters.iter().map(|(k, p)| (k.clone(), p.estimate)).collect()
    }
}
