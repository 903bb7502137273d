//! `kinrepro study` and `kinrepro merge`: reproducibility studies.

use kinrepro::report::study_files::{SamplesCsv, samples_file_name};
use kinrepro::study::runner::{StartBounds, StudyOptions, Variation};
use kinrepro::study::stream::STREAM_ABOVE;
use kinrepro::study::{Shard, StudyPlan, StudyReport};

use super::*;
use crate::args::*;
use crate::error::CliError;

pub fn study(args: StudyArgs) -> Result<(), CliError> {
    let opts = options(&args)?;
    let couplings = args
        .scenes
        .iter()
        .map(|p| kinrepro::error::read_coupling(p))
        .collect::<Result<Vec<_>, _>>()?;
    if args.sensitivity && args.sobol_samples < 2 {
        return Err(CliError::Usage(
            "--sobol-samples: the base sample size must be at least 2".into(),
        ));
    }
    let plan = StudyPlan::new(
        &couplings,
        opts,
        args.sensitivity.then_some(args.sobol_samples),
    )?;
    if plan.streamed() && opts.sensitivity {
        return Err(CliError::Usage(format!(
            "--sensitivity keeps every sample in memory: not available for Monte Carlo studies above {STREAM_ABOVE} samples"
        )));
    }
    set_jobs(args.jobs, plan.seatings)?;
    let bar = progress(plan.seatings)?;
    // A streamed study writes its per-sample CSV as the samples arrive.
    let samples_dir = args.out.as_deref().filter(|_| plan.streamed());
    if let Some(dir) = samples_dir {
        std::fs::create_dir_all(dir)
            .map_err(|e| CliError::file(dir.display(), "cannot create the folder: ", e))?;
    }
    let (report, pending_csv) = plan.run(&|| bar.inc(1), |i, v| {
        samples_dir
            .map(|dir| SamplesCsv::create(&dir.join(samples_file_name(i, v)), v, args.force))
            .transpose()
    })?;
    bar.finish_and_clear();
    // Results first: a failed file write must not lose them.
    print_study(&report, args.format)?;
    for csv in pending_csv {
        csv.commit()?;
    }
    if let Some(dir) = &args.out {
        for f in report.write_files(dir, args.force, plan.streamed())? {
            eprintln!("wrote {f}");
        }
    }
    if let Some(path) = &args.html {
        super::report::study_html(
            &report,
            &couplings,
            args.reference.as_deref(),
            path,
            args.force,
        )?;
    }
    refuse_unseated(&report, args.allow_unseated)
}

/// A study whose coupling cannot seat fails unless `--allow-unseated`.
fn refuse_unseated(report: &StudyReport, allow: bool) -> Result<(), CliError> {
    let bad = report.cannot_seat();
    if bad.is_empty() {
        return Ok(());
    }
    if allow {
        for b in &bad {
            eprintln!("warning: cannot seat: {b}");
        }
        return Ok(());
    }
    Err(CliError::CannotSeat(bad.join("; ")))
}

/// The study options from the command line.
fn options(args: &StudyArgs) -> Result<StudyOptions, CliError> {
    if args.sampler == Some(kinrepro::study::Sampler::Corners) && args.samples.is_some() {
        return Err(CliError::Usage(
            "--samples does not apply to --sampler corners: the corner design has all 2^d extremes"
                .into(),
        ));
    }
    check_increments(args.increments)?;
    let vary = &args.vary;
    Ok(StudyOptions {
        sampler: args.sampler,
        samples: args.samples,
        seed: args.seed,
        shard: args.shard.unwrap_or_else(Shard::whole),
        method: match args.solver {
            SolverKind::QuasiStatic => {
                kinrepro::solve::Method::QuasiStatic(kinrepro::solve::SolverOptions {
                    increments: args.increments,
                    ..Default::default()
                })
            }
            SolverKind::Dynamic => kinrepro::solve::Method::Dynamic(Default::default()),
        },
        sensitivity: args.sensitivity,
        replicates: args.replicates,
        variation: Variation {
            friction: vary.contains(&VaryKind::Friction),
            preload: vary.contains(&VaryKind::Preload),
            tolerances: vary.contains(&VaryKind::Tolerances),
            start: if vary.contains(&VaryKind::Start) {
                let bounds = |name: &str, v: Option<Vec<f64>>| -> Result<_, CliError> {
                    let v = vector3(name, v)?;
                    if v.iter().any(|x| !x.is_finite() || *x < 0.0) {
                        return Err(CliError::Usage(format!(
                            "--{name}: bounds must be finite and >= 0"
                        )));
                    }
                    Ok(v)
                };
                Some(StartBounds {
                    offset: bounds("offset-bounds", args.offset_bounds.clone())?,
                    tilt: bounds("tilt-bounds", args.tilt_bounds.clone())?,
                })
            } else {
                if args.offset_bounds.is_some() || args.tilt_bounds.is_some() {
                    return Err(CliError::Usage(
                        "--offset-bounds and --tilt-bounds need --vary start".into(),
                    ));
                }
                None
            },
        },
    })
}

/// The progress bar (on a terminal only).
pub(super) fn progress(total: usize) -> Result<indicatif::ProgressBar, CliError> {
    if !std::io::IsTerminal::is_terminal(&std::io::stderr()) {
        return Ok(indicatif::ProgressBar::hidden());
    }
    let b = indicatif::ProgressBar::new(total as u64);
    b.set_style(indicatif::ProgressStyle::with_template(
        "{elapsed_precise} [{bar:40}] {pos}/{len} seatings ({eta})",
    )?);
    Ok(b)
}

pub fn merge(args: MergeArgs) -> Result<(), CliError> {
    let MergeArgs { parts, format } = args;
    // The first part says which kind of document is merged; it is read once.
    let first = match parts.first() {
        Some(p) => Some(
            std::fs::read_to_string(p)
                .map_err(|e| CliError::file(p.display(), "cannot read: ", e))?,
        ),
        None => None,
    };
    if first.as_deref().is_some_and(super::sweep::is_sweep) {
        return super::sweep::merge(&parts, first, format);
    }
    let docs = read_json_parts::<StudyReport>(&parts, first, "study")?;
    let merged = kinrepro::study::merge::merge_parts(docs)?;
    print_study(&merged, format)?;
    refuse_unseated(&merged, true)
}
