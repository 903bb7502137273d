//! Text and JSON of `kinrepro calibrate` and `kinrepro predict`
//! (docs/measurements.md), and the plot of predictions ([`plot`]). Every
//! number comes from `calibrate`; nothing here computes statistics.

pub mod plot;

use std::collections::BTreeMap;

use serde::Serialize;

use crate::calibrate::fit::{Calibration, Correlation, DofFit, Parameter};
use crate::calibrate::predict::Prediction;
use crate::dof::{Dof, nano};
use crate::report::table::{Cell, Column, Table, cells};
use crate::study::provenance::VERSION;
use crate::study::{Shard, StudyDocument, StudyReport, VariantReport};

/// The first line of a calibration's table.
pub fn calibration_produced_by(c: &Calibration) -> String {
    format!(
        "kinrepro {VERSION} (calibration schema {}), model: solver {}, sampler {}, seed {}, samples {}, vary friction",
        c.schema_version, c.model.solver, c.model.sampler, c.model.seed, c.model.samples
    )
}

/// A value in nm or nrad with its unit.
fn human(dof: Dof, si: f64) -> String {
    format!("{:.3} {}", nano(si), dof.unit())
}

/// `model.grid.check` above which the table warns (a sigma difference of 2 %
/// is a tenth of a 50-cycle measurement's own sigma error).
pub const GRID_CHECK_WARN: f64 = 0.02;

/// A parameter value with its unit (support compliance in m/N).
fn value(name: &str, v: f64) -> String {
    if name == "support_compliance" { format!("{v:.4e} m/N") } else { format!("{v:.5}") }
}

/// One line per fitted parameter: estimate, interval, flags.
fn parameter_lines(c: &Calibration) -> String {
    let mut s = String::new();
    for (name, p) in &c.parameters {
        let alone = name == "spread" && c.parameters.len() == 1;
        let low = match (p.low_at_bound, name == "spread" || name == "sd") {
            (false, _) => "",
            (true, true) => "  (low end: no lower bound)",
            (true, false) => "  (low end: at the range end)",
        };
        let high = match (p.high_at_bound, alone) {
            (false, _) => "",
            (true, true) => "  (high end: at mu_static)",
            (true, false) => "  (high end: at the range end)",
        };
        s += &format!(
            "{name}: {}   {:.0} % interval [{}, {}]{low}{high}   ({})\n",
            value(name, p.estimate),
            p.level * 100.0,
            value(name, p.low),
            value(name, p.high),
            p.method
        );
        if !alone && (p.low_at_bound || p.high_at_bound) {
            let r = p.range.map_or(String::new(), |[a, b]| {
                format!(" [{}, {}]", value(name, a), value(name, b))
            });
            s += &format!(
                "  NOT DETERMINED: the data do not determine {name}: its interval reaches the end of the searched range{r}\n"
            );
        }
    }
    s
}

/// The correlation matrix of the estimates (more than one parameter).
fn correlation_lines(r: &Correlation) -> String {
    if r.parameters.len() < 2 {
        return String::new();
    }
    let params = r.parameters.iter().map(|n| Column::right(n).fixed(3));
    let mut t = Table::new("<").with(params).indent(2);
    for (n, row) in r.parameters.iter().zip(&r.matrix) {
        t.row(std::iter::once(n.into()).chain(row.iter().map(|v| Cell::Num(*v))).collect());
    }
    "correlation of the estimates (sandwich covariance at the estimate):\n".to_string() + &t.text()
}

/// The fitted parameters with their intervals on one line, e.g.
/// `spread 0.08000 [0.07000, 0.09000] (90 %)`.
pub fn parameters_summary(c: &Calibration) -> String {
    let level = c.parameters.values().next().map_or(0.0, |p| p.level);
    let items: Vec<String> = c
        .parameters
        .iter()
        .map(|(n, p)| {
            format!("{n} {} [{}, {}]", value(n, p.estimate), value(n, p.low), value(n, p.high))
        })
        .collect();
    format!("{} ({:.0} %)", items.join(", "), level * 100.0)
}

/// The calibration as a human table.
pub fn calibration_table(c: &Calibration) -> String {
    let mut s = format!("{}\n", calibration_produced_by(c));
    s += &format!(
        "scene {} ({}), point `{}`, measured {} ({})\n\n",
        c.scene, c.scene_name, c.point, c.measured_file, c.data
    );
    s += &parameter_lines(c);
    for (name, v) in &c.fixed {
        s += &format!("{name}: {} (held at the scene's value)\n", value(name, *v));
    }
    if !c.fixed.is_empty() {
        s += &format!(
            "  the intervals are conditional on the held values: a held value that is wrong \
             moves the fitted ones (a fitted support_compliance or mu_static can absorb a wrong \
             {}); fit them together to see whether the data separate them\n",
            c.model.scale
        );
    }
    if let Some(r) = &c.correlation {
        s += &correlation_lines(r);
    }
    match &c.model.grid {
        None => {
            s += &format!(
                "model: reference {0} {1}, sigma/{0} changed by {2:.2} % from it to the estimate\n\n",
                c.model.scale,
                c.model.reference_spread,
                100.0 * c.model.linearity
            )
        }
        Some(g) => {
            s += &format!(
                "model: {} node studies over {} ({4} {:.5}); grid and sigma ∝ {4} against direct studies at the estimate and the region points: largest sigma difference {:.2} %\n\n",
                g.nodes.iter().map(Vec::len).product::<usize>(),
                g.parameters.join(" x "),
                g.spread,
                100.0 * g.check,
                c.model.scale,
            );
            if g.check > GRID_CHECK_WARN {
                s += &format!(
                    "  WARNING: the grid's model covariance differs from a direct study at the estimate or a region point by more than {:.0} % (sigma ∝ spread fails near spread = mu_static, or the model changes between nodes, as where contacts begin to stick, and the grid is too coarse for it): read the intervals with care\n\n",
                    100.0 * GRID_CHECK_WARN
                );
            }
        }
    }
    let mut t = Table::new(
        "<dof; >cycles; >measured sigma; >noise sigma; >fitted sigma; >model sigma (no noise)",
    );
    for d in &c.dofs {
        t.row(cells![
            d.dof.name(),
            d.cycles,
            human(d.dof, d.measured_sigma),
            human(d.dof, d.noise_sigma),
            human(d.dof, d.fitted_sigma),
            human(d.dof, d.model_sigma),
        ]);
    }
    s += &t.text();
    let g = &c.goodness_of_fit;
    s += &format!(
        "\ngoodness of fit: {}; p = {}{}\n\n",
        g.test,
        g.p_value.map_or("n/a".into(), |p| format!("{p:.4}")),
        if g.ok {
            String::new()
        } else {
            format!(
                "\n  POOR FIT (p < {}): no friction {1} explains the measured shape (DOF ratios, correlations); do not use this {1}",
                g.threshold, c.model.scale
            )
        }
    );
    s
}

/// The predictions of several scenes with the calibration they used.
#[derive(Debug, Clone)]
pub struct PredictionReport {
    pub calibration_file: String,
    pub calibration: Calibration,
    pub predictions: Vec<Prediction>,
}

/// Values of DOF fits, keyed by [`Dof::key`] (nm, nrad).
fn by_dof(dofs: &[DofFit], f: impl Fn(&DofFit) -> f64) -> BTreeMap<String, f64> {
    dofs.iter().map(|d| (d.dof.key(), nano(f(d)))).collect()
}

/// The measured sigma of the calibrated design in a prediction (nm, nrad).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct MeasuredBlock {
    pub point: String,
    pub cycles: Option<usize>,
    pub sigma: BTreeMap<String, f64>,
    pub noise_sigma: BTreeMap<String, f64>,
    pub fitted_sigma: BTreeMap<String, f64>,
}

impl MeasuredBlock {
    fn new(point: &str, dofs: &[DofFit]) -> Self {
        MeasuredBlock {
            point: point.to_string(),
            cycles: dofs.first().map(|d| d.cycles),
            sigma: by_dof(dofs, |d| d.measured_sigma),
            noise_sigma: by_dof(dofs, |d| d.noise_sigma),
            fitted_sigma: by_dof(dofs, |d| d.fitted_sigma),
        }
    }
}

/// A prediction's variant: the study's, and the measured sigma where it is
/// the calibrated design (null otherwise).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PredictedVariant {
    #[serde(flatten)]
    pub variant: VariantReport,
    pub measured: Option<MeasuredBlock>,
}

/// The `calibration` block of a prediction: the calibration it used.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct CalibrationBlock {
    pub file: String,
    pub scene: String,
    pub point: String,
    pub spread: Option<Parameter>,
    pub parameters: BTreeMap<String, Parameter>,
    pub region: Vec<BTreeMap<String, f64>>,
    pub goodness_of_fit_ok: bool,
    pub kinrepro_version: String,
}

/// The document of `predict --format json`: the study schema with the
/// measured sigma in each variant, and the calibration at the top.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct PredictionDocument {
    #[serde(flatten)]
    pub study: StudyDocument<PredictedVariant>,
    pub calibration: CalibrationBlock,
}

impl PredictionReport {
    /// The study report (schema 2) of the predictions.
    pub fn study(&self) -> StudyReport {
        StudyReport::new(
            self.predictions.iter().map(|p| p.variant.clone()).collect(),
            Shard::whole(),
        )
    }

    /// The document of `predict --format json` ([`PredictionDocument`]).
    pub fn document(&self) -> PredictionDocument {
        let c = &self.calibration;
        let mut measured = self
            .predictions
            .iter()
            .map(|p| p.measured.as_ref().map(|(point, dofs)| MeasuredBlock::new(point, dofs)));
        PredictionDocument {
            study: self.study().map_variants(|variant| PredictedVariant {
                variant,
                measured: measured.next().flatten(),
            }),
            calibration: CalibrationBlock {
                file: self.calibration_file.clone(),
                scene: c.scene.clone(),
                point: c.point.clone(),
                spread: c.spread().cloned(),
                parameters: c.parameters.clone(),
                region: c.region_points(),
                goodness_of_fit_ok: c.goodness_of_fit.ok,
                kinrepro_version: c.kinrepro_version.clone(),
            },
        }
    }

    /// Human table: sigma with its prediction interval per scene, point and
    /// DOF (nm, nrad), the measured sigma beside the calibrated design.
    pub fn table(&self) -> String {
        let study = self.study();
        let mut s = format!(
            "{}\ncalibration {}: {} from scene {}{}\n",
            study.produced_by(),
            self.calibration_file,
            parameters_summary(&self.calibration),
            self.calibration.scene,
            if self.calibration.goodness_of_fit.ok {
                ""
            } else {
                "  WARNING: the calibration is a POOR FIT"
            }
        );
        s += "predicted sigma: the coupling's own scatter (no sensor noise); interval: 90 % prediction interval\n\n";
        for p in &self.predictions {
            let v = &p.variant;
            s += &format!("{} ({})\n", v.scene, v.name);
            let mut t =
                Table::new("<point; <dof; >sigma:.3; <; >90 % interval; <measured (raw, noise)")
                    .indent(2);
            let measured = p.measured.as_ref();
            for pt in &v.points {
                let (m, lo, hi) = (pt.sigma, pt.sigma_ci90_low, pt.sigma_ci90_high);
                let bound =
                    |b: Option<crate::study::Dofs>, j: usize| b.map_or(f64::NAN, |b| b.values()[j]);
                for d in Dof::ALL {
                    let j = d.index();
                    let meas = (measured.filter(|(name, _)| *name == pt.name))
                        .and_then(|(_, fits)| fits.iter().find(|f| f.dof == d))
                        .map_or(String::new(), |f| {
                            format!("{:.3} ({:.3})", nano(f.measured_sigma), nano(f.noise_sigma))
                        });
                    let interval = format!("[{:>9.3}, {:>9.3}]", bound(lo, j), bound(hi, j));
                    t.row(cells![&pt.name, d.name(), m.values()[j], d.unit(), interval, meas]);
                }
            }
            s += &t.text();
            s.push('\n');
        }
        s
    }
}
