//! `kinrepro calibrate` and `kinrepro predict`: fit the friction spread (and
//! optionally mu_static, dynamic_ratio, support_compliance) to a measured
//! scatter, and predict other designs with it (docs/measurements.md).

use std::path::PathBuf;

use kinrepro::calibrate::fit::{CalibrateOptions, Calibration};
use kinrepro::calibrate::model::check_model_samples;
use kinrepro::calibrate::units::parse_noise;
use kinrepro::calibrate::{Measurement, predict as predict_one};
use kinrepro::output::atomic::{check_overwrite, write_file};
use kinrepro::param::Param;
use kinrepro::report::calibration::{PredictionReport, calibration_table};
use kinrepro::solve::Solver;

use super::{check_jobs, emit, print_json, read_scene, read_text, set_jobs};
use crate::error::{Context, Error, Result};
use crate::flags::{CalibrateArgs, PredictArgs, TextFormat};

/// `kinrepro calibrate`: the measured scene, the measurement with its
/// delimiter, the calibration's options and the outputs.
pub struct Calibrate {
    scene: PathBuf,
    measured: PathBuf,
    delimiter: Option<u8>,
    options: CalibrateOptions,
    format: TextFormat,
    out: Option<PathBuf>,
    force: bool,
    jobs: Option<usize>,
}

impl TryFrom<CalibrateArgs> for Calibrate {
    type Error = Error;

    fn try_from(a: CalibrateArgs) -> Result<Calibrate> {
        let mut noise = [None; 6];
        if let Some(n) = &a.noise {
            parse_noise(n, &mut noise).context("--noise")?;
        }
        check_jobs(a.jobs)?;
        let delimiter =
            (a.delimiter.as_deref()).map(kinrepro::delimited::delimiter_named).transpose()?;
        Ok(Calibrate {
            options: CalibrateOptions {
                fit: a.fit.iter().map(|s| s.trim().to_string()).collect(),
                noise,
                point: a.point,
                samples: check_model_samples(Param::ModelSamples, a.model_samples)?,
                seed: a.seed,
                solver: Solver::QuasiStatic,
            },
            scene: a.scene,
            measured: a.measured,
            delimiter,
            format: a.format,
            out: a.out,
            force: a.force,
            jobs: a.jobs,
        })
    }
}

pub fn calibrate(c: Calibrate) -> Result {
    let (scene, coupling) = read_scene(&c.scene)?;
    let m = Measurement::load(&c.measured, c.delimiter)?;
    if let Some(out) = &c.out {
        check_overwrite(out, c.force)?;
    }
    set_jobs(c.jobs, c.options.samples)?;
    let cal = kinrepro::calibrate::calibrate(&scene, &coupling, &m, &c.options)?;
    let json = format!("{}\n", serde_json::to_string_pretty(&cal)?);
    match c.format {
        TextFormat::Table => emit(&calibration_table(&cal))?,
        TextFormat::Json => emit(&json)?,
    }
    if let Some(out) = &c.out {
        write_file(out, &json, c.force)?;
        eprintln!("wrote {}", out.display());
    }
    if !cal.goodness_of_fit.ok {
        eprintln!(
            "warning: poor fit (goodness-of-fit p < {}): the model cannot explain the measured scatter's shape",
            cal.goodness_of_fit.threshold
        );
    }
    Ok(())
}

/// `kinrepro predict`, its flags checked.
pub struct Predict(PredictArgs);

impl TryFrom<PredictArgs> for Predict {
    type Error = Error;

    fn try_from(a: PredictArgs) -> Result<Predict> {
        check_model_samples(Param::Samples, a.samples)?;
        check_jobs(a.jobs)?;
        Ok(Predict(a))
    }
}

pub fn predict(Predict(o): Predict) -> Result {
    let file = o.calibration.display().to_string();
    let cal = Calibration::parse(&read_text(&o.calibration)?, &file)?;
    if let Some(p) = &o.plot {
        check_overwrite(p, o.force)?;
    }
    let models = o.scenes.iter().map(|p| read_scene(p)).collect::<Result<Vec<_>>>()?;
    set_jobs(o.jobs, o.samples)?;
    let studies = (o.samples, o.seed, Solver::QuasiStatic);
    let predictions = models
        .iter()
        .map(|(s, c)| predict_one(s, c, &cal, &file, studies))
        .collect::<std::result::Result<Vec<_>, _>>()?;
    let report = PredictionReport { calibration_file: file, calibration: cal, predictions };
    match o.format {
        TextFormat::Table => emit(&report.table())?,
        TextFormat::Json => print_json(&report.document())?,
    }
    if let Some(p) = &o.plot {
        kinrepro::report::calibration::plot::plot_predictions(p, &report, o.force)?;
        eprintln!("wrote {}", p.display());
    }
    if !report.calibration.goodness_of_fit.ok {
        eprintln!(
            "warning: the calibration is a poor fit; these predictions rest on a spread the model could not reconcile with the data"
        );
    }
    Ok(())
}
