//! `kinrepro calibrate` and `kinrepro predict`: fit the friction spread (and
//! optionally mu_static, dynamic_ratio, support_compliance) to a measured
//! scatter, and predict other designs with it (docs/measurements.md).

use std::path::PathBuf;

use clap::{Args, ValueEnum};
use kinrepro::calibrate::fit::{CalibrateOptions, Calibration};
use kinrepro::calibrate::model::{MODEL_SAMPLES, MODEL_SEED};
use kinrepro::calibrate::units::parse_noise;
use kinrepro::calibrate::{Measurement, calibrate, predict};
use kinrepro::report::calibration::{PredictionReport, calibration_table};
use kinrepro::solve::Method;

use super::{emit, print_json, set_jobs};
use crate::error::CliError;

/// Fewest model samples accepted (`--model-samples`, `predict --samples`).
const MIN_MODEL_SAMPLES: usize = 100;

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum TextFormat {
    /// Human table (nm, nrad).
    Table,
    /// JSON (calibration: SI; predict: the study schema, nm and nrad).
    Json,
}

#[derive(Args)]
pub struct CalibrateArgs {
    /// Scene file (TOML) of the measured coupling.
    pub scene: PathBuf,
    /// Measurement file: one row per re-seating cycle (columns such as
    /// x_nm, phi_x_nrad), or a summary (dof,unit,sigma,cycles).
    #[arg(long)]
    pub measured: PathBuf,
    /// Field separator of the measurement file: `,`, `;`, `tab` (or any one
    /// ASCII character); default: detected from its header line.
    #[arg(long, value_parser = parse_delimiter)]
    pub delimiter: Option<u8>,
    /// Parameters to fit, comma-separated: any of spread, mu_static,
    /// dynamic_ratio, support_compliance (the others held at the scene's
    /// values; docs/calibration.md gives the searched ranges).
    #[arg(long, value_delimiter = ',', default_value = "spread")]
    pub fit: Vec<String>,
    /// Sensor noise sigma per DOF, e.g. x=1nm,y=1nm,phi_x=20nrad (a number
    /// without unit is SI: m or rad); overrides the file's `# noise:`.
    #[arg(long)]
    pub noise: Option<String>,
    /// Evaluation point measured (default: the file's `point` column, else
    /// the scene's first).
    #[arg(long)]
    pub point: Option<String>,
    /// Samples of each Monte Carlo model study.
    #[arg(long, default_value_t = MODEL_SAMPLES)]
    pub model_samples: usize,
    /// Seed of the model studies.
    #[arg(long, default_value_t = MODEL_SEED)]
    pub seed: u64,
    #[arg(long, value_enum, default_value_t = TextFormat::Table)]
    pub format: TextFormat,
    /// Write the calibration file (JSON) here.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Replace an existing --out file.
    #[arg(long)]
    pub force: bool,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub jobs: Option<usize>,
}

#[derive(Args)]
pub struct PredictArgs {
    /// Scene files (TOML) to predict.
    #[arg(required = true)]
    pub scenes: Vec<PathBuf>,
    /// Calibration file written by `kinrepro calibrate --out`.
    #[arg(long)]
    pub calibration: PathBuf,
    /// Samples of each Monte Carlo study (per scene: one at the estimate
    /// and one per point of the calibration's parameter region).
    #[arg(long, default_value_t = MODEL_SAMPLES)]
    pub samples: usize,
    /// Seed of the studies.
    #[arg(long, default_value_t = MODEL_SEED)]
    pub seed: u64,
    #[arg(long, value_enum, default_value_t = TextFormat::Table)]
    pub format: TextFormat,
    /// Also draw the predicted intervals into this SVG.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Replace an existing --plot file.
    #[arg(long)]
    pub force: bool,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub jobs: Option<usize>,
}

/// `--delimiter`: one ASCII character, or `tab`, `comma`, `semicolon`.
fn parse_delimiter(s: &str) -> Result<u8, String> {
    match s {
        "tab" | "\\t" => Ok(b'\t'),
        "comma" => Ok(b','),
        "semicolon" => Ok(b';'),
        _ if s.len() == 1 && s.is_ascii() && s != "\"" && s != "#" => Ok(s.as_bytes()[0]),
        _ => Err(format!(
            "`{s}`: give one character such as `,` or `;`, or `tab` (not `\"` or `#`)"
        )),
    }
}

fn check_samples(flag: &str, n: usize) -> Result<(), CliError> {
    if n < MIN_MODEL_SAMPLES {
        return Err(CliError::Usage(format!(
            "{flag} {n}: need at least {MIN_MODEL_SAMPLES} samples"
        )));
    }
    Ok(())
}

pub fn calibrate_cmd(args: CalibrateArgs) -> Result<(), CliError> {
    check_samples("--model-samples", args.model_samples)?;
    let mut noise = [None; 6];
    if let Some(n) = &args.noise {
        parse_noise(n, &mut noise).map_err(|e| CliError::Usage(format!("--noise: {e}")))?;
    }
    let coupling = kinrepro::error::read_coupling(&args.scene)?;
    let m = Measurement::load(&args.measured, args.delimiter)?;
    if let Some(out) = &args.out {
        kinrepro::report::atomic::check_overwrite(out, args.force)?;
    }
    set_jobs(args.jobs, args.model_samples)?;
    let opts = CalibrateOptions {
        fit: args.fit.iter().map(|s| s.trim().to_string()).collect(),
        noise,
        point: args.point.clone(),
        samples: args.model_samples,
        seed: args.seed,
        method: Method::default(),
    };
    let cal = calibrate(&coupling, &m, &opts)?;
    let json = serde_json::to_string_pretty(&cal)?;
    match args.format {
        TextFormat::Table => emit(&calibration_table(&cal))?,
        TextFormat::Json => emit(&format!("{json}\n"))?,
    }
    if let Some(out) = &args.out {
        kinrepro::report::atomic::write_file(out, &format!("{json}\n"), args.force)?;
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

pub fn predict_cmd(args: PredictArgs) -> Result<(), CliError> {
    check_samples("--samples", args.samples)?;
    let file = args.calibration.display().to_string();
    let text = std::fs::read_to_string(&args.calibration)
        .map_err(|e| CliError::file(&file, "cannot read: ", e))?;
    let cal = Calibration::parse(&text, &file)?;
    if let Some(p) = &args.plot {
        kinrepro::report::atomic::check_overwrite(p, args.force)?;
    }
    let couplings = args
        .scenes
        .iter()
        .map(|p| kinrepro::error::read_coupling(p))
        .collect::<Result<Vec<_>, _>>()?;
    set_jobs(args.jobs, args.samples)?;
    let predictions = couplings
        .iter()
        .map(|c| predict(c, &cal, args.samples, args.seed, Method::default()))
        .collect::<Result<Vec<_>, _>>()?;
    let report = PredictionReport {
        calibration_file: file,
        calibration: cal,
        predictions,
    };
    match args.format {
        TextFormat::Table => emit(&report.table())?,
        TextFormat::Json => print_json(&report.json()?)?,
    }
    if let Some(p) = &args.plot {
        kinrepro::report::calibration_plot::plot_predictions(p, &report, args.force)?;
        eprintln!("wrote {}", p.display());
    }
    if !report.calibration.goodness_of_fit.ok {
        eprintln!(
            "warning: the calibration is a poor fit; these predictions rest on a spread the model could not reconcile with the data"
        );
    }
    Ok(())
}
