//! `kinrepro calibrate` and `kinrepro predict`: fit the friction spread (and
//! optionally mu_static, dynamic_ratio, support_compliance) to a measured
//! scatter, and predict other designs with it (docs/measurements.md).

use kinrepro::calibrate::fit::Calibration;
use kinrepro::calibrate::{Measurement, predict as predict_one};
use kinrepro::output::atomic::{check_overwrite, write_file};
use kinrepro::report::calibration::{PredictionReport, calibration_table};
use kinrepro::solve::Method;

use super::{emit, print_json, read_text, set_jobs};
use crate::error::CliError;
use crate::flags::high::{CalibrateInputs, Checked};
use crate::flags::low_study::{CalibrateArgs, PredictArgs, TextFormat};

pub fn calibrate(o: Checked<CalibrateArgs, CalibrateInputs>) -> Result<(), CliError> {
    let Checked { args: a, opts } = o;
    let coupling = kinrepro::error::read_coupling(&a.scene)?;
    let m = Measurement::load(&a.measured, opts.delimiter)?;
    if let Some(out) = &a.out {
        check_overwrite(out, a.force)?;
    }
    set_jobs(a.jobs, opts.options.samples)?;
    let cal = kinrepro::calibrate::calibrate(&coupling, &m, &opts.options)?;
    let json = format!("{}\n", serde_json::to_string_pretty(&cal)?);
    match a.format {
        TextFormat::Table => emit(&calibration_table(&cal))?,
        TextFormat::Json => emit(&json)?,
    }
    if let Some(out) = &a.out {
        write_file(out, &json, a.force)?;
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

pub fn predict(o: PredictArgs) -> Result<(), CliError> {
    let file = o.calibration.display().to_string();
    let cal = Calibration::parse(&read_text(&o.calibration)?, &file)?;
    if let Some(p) = &o.plot {
        check_overwrite(p, o.force)?;
    }
    let couplings = o
        .scenes
        .iter()
        .map(|p| kinrepro::error::read_coupling(p))
        .collect::<Result<Vec<_>, _>>()?;
    set_jobs(o.jobs, o.samples)?;
    let predictions = couplings
        .iter()
        .map(|c| predict_one(c, &cal, &file, o.samples, o.seed, Method::default()))
        .collect::<Result<Vec<_>, _>>()?;
    let report = PredictionReport {
        calibration_file: file,
        calibration: cal,
        predictions,
    };
    match o.format {
        TextFormat::Table => emit(&report.table())?,
        TextFormat::Json => print_json(&report.json()?)?,
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
