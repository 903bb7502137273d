//! Text and JSON of `kinrepro calibrate` and `kinrepro predict`
//! (docs/measurements.md). Every number comes from `calibrate`; nothing
//! here computes statistics.

use serde_json::{Map, Value, json};

use crate::calibrate::fit::{Calibration, DofFit};
use crate::calibrate::predict::Prediction;
use crate::calibrate::units::{DOFS, dof_index, human_unit};
use crate::report::provenance::VERSION;
use crate::report::study::StudyReport;
use crate::study::Shard;

/// The first line of a calibration's table.
pub fn calibration_produced_by(c: &Calibration) -> String {
    format!(
        "kinrepro {VERSION} (calibration schema {}), model: solver {}, sampler {}, seed {}, samples {}, vary friction",
        c.schema_version, c.model.solver, c.model.sampler, c.model.seed, c.model.samples
    )
}

/// A value in nm or nrad with its unit.
fn human(dof: &str, si: f64) -> String {
    let u = dof_index(dof).map_or("?", human_unit);
    format!("{:.3} {u}", si * 1e9)
}

/// The calibration as a human table.
pub fn calibration_table(c: &Calibration) -> String {
    let mut s = format!("{}\n", calibration_produced_by(c));
    s += &format!(
        "scene {} ({}), point `{}`, measured {} ({})\n\n",
        c.scene, c.scene_name, c.point, c.measured_file, c.data
    );
    for (name, p) in &c.parameters {
        s += &format!(
            "{name}: {:.5}   {:.0} % interval [{:.5}, {:.5}]{}{}   ({})\n",
            p.estimate,
            p.level * 100.0,
            p.low,
            p.high,
            if p.low_at_bound {
                "  (low end: no lower bound)"
            } else {
                ""
            },
            if p.high_at_bound {
                "  (high end: at mu_static)"
            } else {
                ""
            },
            p.method
        );
    }
    for (name, v) in &c.fixed {
        s += &format!("{name}: {v} (held at the scene's value)\n");
    }
    s += &format!(
        "model: reference spread {}, sigma/spread changed by {:.2} % from it to the estimate\n\n",
        c.model.reference_spread,
        100.0 * c.model.linearity
    );
    s += "dof      cycles  measured sigma   noise sigma      fitted sigma     model sigma (no noise)\n";
    for d in &c.dofs {
        s += &format!(
            "{:<8} {:>6}  {:>15}  {:>15}  {:>15}  {:>15}\n",
            d.dof,
            d.cycles,
            human(&d.dof, d.measured_sigma),
            human(&d.dof, d.noise_sigma),
            human(&d.dof, d.fitted_sigma),
            human(&d.dof, d.model_sigma)
        );
    }
    let g = &c.goodness_of_fit;
    s += &format!(
        "\ngoodness of fit: {}; p = {}{}\n\n",
        g.test,
        g.p_value.map_or("n/a".into(), |p| format!("{p:.4}")),
        if g.ok {
            String::new()
        } else {
            format!(
                "\n  POOR FIT (p < {}): no friction spread explains the measured shape (DOF ratios, correlations); do not use this spread",
                g.threshold
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

/// Measured values of DOF fits, keyed `<dof>_<nm|nrad>`.
fn measured_block(point: &str, dofs: &[DofFit]) -> Value {
    let key = |d: &DofFit| format!("{}_{}", d.dof, dof_index(&d.dof).map_or("?", human_unit));
    let map = |f: &dyn Fn(&DofFit) -> f64| {
        Value::Object(
            dofs.iter()
                .map(|d| (key(d), json!(f(d) * 1e9)))
                .collect::<Map<_, _>>(),
        )
    };
    json!({
        "point": point,
        "cycles": dofs.first().map(|d| d.cycles),
        "sigma": map(&|d| d.measured_sigma),
        "noise_sigma": map(&|d| d.noise_sigma),
        "fitted_sigma": map(&|d| d.fitted_sigma),
    })
}

impl PredictionReport {
    /// The study report (schema 2) of the predictions.
    pub fn study(&self) -> StudyReport {
        StudyReport::new(
            self.predictions.iter().map(|p| p.variant.clone()).collect(),
            Shard::whole(),
        )
    }

    /// JSON: the study schema, plus `calibration` at the top and `measured`
    /// in each variant (null unless it is the calibrated design).
    pub fn json(&self) -> Result<Value, serde_json::Error> {
        let mut v = serde_json::to_value(self.study())?;
        let c = &self.calibration;
        v["calibration"] = json!({
            "file": self.calibration_file,
            "scene": c.scene,
            "point": c.point,
            "spread": c.spread(),
            "goodness_of_fit_ok": c.goodness_of_fit.ok,
            "kinrepro_version": c.kinrepro_version,
        });
        if let Some(vars) = v["variants"].as_array_mut() {
            for (var, p) in vars.iter_mut().zip(&self.predictions) {
                var["measured"] = p
                    .measured
                    .as_ref()
                    .map_or(Value::Null, |(pt, d)| measured_block(pt, d));
            }
        }
        Ok(v)
    }

    /// Human table: sigma with its prediction interval per scene, point and
    /// DOF (nm, nrad), the measured sigma beside the calibrated design.
    pub fn table(&self) -> String {
        let study = self.study();
        let sp = self.calibration.spread();
        let mut s = format!(
            "{}\ncalibration {}: spread {:.5} [{:.5}, {:.5}] ({:.0} %) from scene {}{}\n",
            study.produced_by(),
            self.calibration_file,
            sp.estimate,
            sp.low,
            sp.high,
            sp.level * 100.0,
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
            s += "  point           dof      sigma        90 % interval           measured (raw, noise)\n";
            for pt in &v.points {
                let (m, lo, hi) = (
                    pt.sigma.values(),
                    pt.sigma_ci90_low.map(|d| d.values()),
                    pt.sigma_ci90_high.map(|d| d.values()),
                );
                for j in 0..6 {
                    let meas = p
                        .measured
                        .as_ref()
                        .filter(|(name, _)| *name == pt.name)
                        .and_then(|(_, d)| d.iter().find(|d| d.dof == DOFS[j]))
                        .map_or(String::new(), |d| {
                            format!("{:.3} ({:.3})", d.measured_sigma * 1e9, d.noise_sigma * 1e9)
                        });
                    s += &format!(
                        "  {:<15} {:<6} {:>9.3} {:<4} [{:>9.3}, {:>9.3}]   {meas}\n",
                        pt.name,
                        DOFS[j],
                        m[j],
                        human_unit(j),
                        lo.map_or(f64::NAN, |l| l[j]),
                        hi.map_or(f64::NAN, |h| h[j]),
                    );
                }
            }
            s.push('\n');
        }
        s
    }
}
