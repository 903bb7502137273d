//! `kinrepro study` and `kinrepro merge`: reproducibility studies.

use kinrepro::assembly::Coupling;
use kinrepro::report::study::{StudyReport, VariantReport};
use kinrepro::report::study_files::{SamplesCsv, samples_file_name};
use kinrepro::report::study_stream::{STREAM_ABOVE, StreamStats, streams};
use kinrepro::study::Shard;
use kinrepro::study::runner::{
    PathTally, Progress, StartBounds, StudyOptions, VariantRun, Variation, design_for,
    recorded_output_names, run_chunked, run_variant,
};

use super::*;
use crate::args::*;
use crate::error::{CliError, Context};

/// Rows seated per chunk of a streamed study.
const CHUNK: usize = 8192;

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
    // Sobol indices need the whole design in one run (not per shard).
    let sobol = args.sensitivity && opts.shard.count == 1;
    let mut total = 0;
    let mut streamed = false;
    for c in &couplings {
        kinrepro::study::runner::check_options(c, &opts)?;
        let d = design_for(c, &opts).context(&c.scene.file)?;
        total += opts.shard.range(d.n).context("--shard")?.len();
        streamed |= streams(&d) && opts.shard.count == 1;
        if sobol {
            total += args.sobol_samples * (d.dims + 2);
        }
    }
    if streamed && opts.sensitivity {
        return Err(CliError::Usage(format!(
            "--sensitivity keeps every sample in memory: not available for Monte Carlo studies above {STREAM_ABOVE} samples"
        )));
    }
    set_jobs(args.jobs, total)?;
    let bar = progress(total)?;
    let mut variants = Vec::new();
    let mut pending_csv = Vec::new();
    for (i, c) in couplings.iter().enumerate() {
        let d = design_for(c, &opts).context(&c.scene.file)?;
        if streams(&d) && opts.shard.count == 1 {
            let (v, csv) = streamed_variant(i, c, &opts, &args, &|| bar.inc(1))?;
            variants.push(v);
            pending_csv.extend(csv);
        } else {
            let tally = PathTally::default();
            let run = run_variant(c, &opts, Progress::with_tally(&|| bar.inc(1), &tally))?;
            let mut v = VariantReport::new(c, run, &opts).context(&c.scene.file)?;
            v.seating_paths = Some(tally.counts());
            if sobol {
                let r = kinrepro::study::sensitivity::sobol_run::run_sobol(
                    c,
                    &opts,
                    args.sobol_samples,
                    &|| bar.inc(1),
                )?;
                kinrepro::report::sensitivity::attach_sobol(&mut v, &r);
            }
            variants.push(v);
        }
    }
    bar.finish_and_clear();
    let report = StudyReport::new(variants, opts.shard);
    // Results first: a failed file write must not lose them.
    print_study(&report, args.format)?;
    for csv in pending_csv {
        csv.commit()?;
    }
    if let Some(dir) = &args.out {
        for f in report.write_files(dir, args.force, streamed)? {
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

/// One scene's Monte Carlo study streamed in chunks: moments in sample
/// order, the per-sample CSV (if `--out`) written as it goes.
fn streamed_variant(
    i: usize,
    c: &Coupling,
    opts: &StudyOptions,
    args: &StudyArgs,
    tick: &(dyn Fn() + Sync),
) -> Result<(VariantReport, Option<SamplesCsv>), CliError> {
    let file = &c.scene.file;
    let d = design_for(c, opts).context(file)?;
    let names = recorded_output_names(c, &opts.variation);
    let shell = VariantRun {
        design: d,
        shard: opts.shard,
        output_names: names.clone(),
        records: Vec::new(),
    };
    let mut v = VariantReport::unfinished(c, shell, opts);
    let mut csv = match &args.out {
        Some(dir) => {
            std::fs::create_dir_all(dir)
                .map_err(|e| CliError::file(dir.display(), "cannot create the folder: ", e))?;
            let path = dir.join(samples_file_name(i, &v));
            Some(SamplesCsv::create(&path, &v, args.force)?)
        }
        None => None,
    };
    let mut st = StreamStats::new(names.len());
    let mut failure: Option<CliError> = None;
    let tally = PathTally::default();
    let progress = Progress::with_tally(tick, &tally);
    let run = run_chunked(c, opts, CHUNK, progress, &mut |records| {
        let step = st
            .push(&records, &names)
            .context(file)
            .and_then(|()| match csv.as_mut() {
                Some(w) => records.iter().try_for_each(|r| {
                    w.push(&kinrepro::report::study::StudyRecord {
                        index: r.index,
                        physical: opts.variation.sample(c, &r.inputs).physical,
                        inputs: r.inputs.clone(),
                        outputs: r.outputs.clone(),
                    })
                    .map_err(CliError::from)
                }),
                None => Ok(()),
            });
        if let Err(e) = step {
            failure = Some(e);
            return Err(kinrepro::study::runner::RunError::Options {
                file: file.clone(),
                reason: "stopped".into(),
            });
        }
        Ok(())
    });
    if let Err(e) = run {
        return Err(failure.take().unwrap_or_else(|| e.into()));
    }
    v.seating_paths = Some(tally.counts());
    v.set_moment_stats(&st).context(file)?;
    Ok((v, csv))
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
    let merged = kinrepro::report::merge::merge_parts(docs)?;
    print_study(&merged, format)?;
    refuse_unseated(&merged, true)
}
