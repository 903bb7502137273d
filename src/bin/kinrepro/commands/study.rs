//! `kinrepro study` and `kinrepro merge`: reproducibility studies.

use kinrepro::report::study::{StudyReport, VariantReport};
use kinrepro::study::Shard;
use kinrepro::study::runner::{StartBounds, StudyOptions, Variation, design_for, run_variant};

use super::*;
use crate::args::*;

pub fn study(args: StudyArgs) -> Result<(), String> {
    let StudyArgs {
        scenes,
        samples,
        sampler,
        seed,
        jobs,
        format,
        out,
        shard,
        increments,
        solver,
        vary,
        offset_bounds,
        tilt_bounds,
        sensitivity,
        sobol_samples,
        replicates,
    } = args;
    if let Some(j) = jobs {
        rayon::ThreadPoolBuilder::new()
            .num_threads(j.max(1))
            .build_global()
            .map_err(|e| format!("--jobs: {e}"))?;
    }
    if sampler == Some(kinrepro::study::Sampler::Corners) && samples.is_some() {
        return Err(
            "--samples does not apply to --sampler corners: the corner design has all 2^d extremes"
                .into(),
        );
    }
    let opts = StudyOptions {
        sampler,
        samples,
        seed,
        shard: shard.unwrap_or_else(Shard::whole),
        method: match solver {
            SolverKind::QuasiStatic => {
                kinrepro::solve::Method::QuasiStatic(kinrepro::solve::SolverOptions {
                    increments: increments.max(1),
                    ..Default::default()
                })
            }
            SolverKind::Dynamic => kinrepro::solve::Method::Dynamic(Default::default()),
        },
        sensitivity,
        replicates,
        variation: Variation {
            friction: vary.contains(&VaryKind::Friction),
            preload: vary.contains(&VaryKind::Preload),
            tolerances: vary.contains(&VaryKind::Tolerances),
            start: if vary.contains(&VaryKind::Start) {
                let bounds = |name: &str, v: Option<Vec<f64>>| -> Result<_, String> {
                    let v = vector3(name, v)?;
                    if v.iter().any(|x| !x.is_finite() || *x < 0.0) {
                        return Err(format!("--{name}: bounds must be finite and >= 0"));
                    }
                    Ok(v)
                };
                Some(StartBounds {
                    offset: bounds("offset-bounds", offset_bounds)?,
                    tilt: bounds("tilt-bounds", tilt_bounds)?,
                })
            } else {
                if offset_bounds.is_some() || tilt_bounds.is_some() {
                    return Err("--offset-bounds and --tilt-bounds need --vary start".into());
                }
                None
            },
        },
    };
    let couplings = scenes
        .iter()
        .map(|p| kinrepro::error::load_coupling(p).map_err(|e| e.to_string()))
        .collect::<Result<Vec<_>, _>>()?;
    if sensitivity && sobol_samples < 2 {
        return Err("--sobol-samples: the base sample size must be at least 2".into());
    }
    // Sobol indices need the whole design in one run (not per shard).
    let sobol = sensitivity && opts.shard.count == 1;
    let mut total = 0;
    for c in &couplings {
        kinrepro::study::runner::check_options(c, &opts).map_err(|e| e.to_string())?;
        let d = design_for(c, &opts).map_err(|e| format!("{}: {e}", c.scene.file))?;
        total += opts
            .shard
            .range(d.n)
            .map_err(|e| format!("--shard: {e}"))?
            .len();
        if sobol {
            total += sobol_samples * (d.dims + 2);
        }
    }
    let bar = if std::io::IsTerminal::is_terminal(&std::io::stderr()) {
        let b = indicatif::ProgressBar::new(total as u64);
        b.set_style(
            indicatif::ProgressStyle::with_template(
                "{elapsed_precise} [{bar:40}] {pos}/{len} seatings ({eta})",
            )
            .map_err(|e| e.to_string())?,
        );
        b
    } else {
        indicatif::ProgressBar::hidden()
    };
    let mut variants = Vec::new();
    for c in &couplings {
        let run = run_variant(c, &opts, &|| bar.inc(1)).map_err(|e| e.to_string())?;
        let mut v =
            VariantReport::new(c, run, &opts).map_err(|e| format!("{}: {e}", c.scene.file))?;
        if sobol {
            let r = kinrepro::study::sensitivity::sobol_run::run_sobol(
                c,
                &opts,
                sobol_samples,
                &|| bar.inc(1),
            )
            .map_err(|e| e.to_string())?;
            kinrepro::report::sensitivity::attach_sobol(&mut v, &r);
        }
        variants.push(v);
    }
    bar.finish_and_clear();
    let report = StudyReport::new(variants, opts.shard);
    if let Some(dir) = out {
        for f in report.write_files(&dir, &couplings)? {
            eprintln!("wrote {f}");
        }
    }
    print_study(&report, format)
}

pub fn merge(args: MergeArgs) -> Result<(), String> {
    let MergeArgs { parts, format } = args;
    let docs = parts
        .iter()
        .map(|p| {
            let text = std::fs::read_to_string(p)
                .map_err(|e| format!("{}: cannot read: {e}", p.display()))?;
            serde_json::from_str::<StudyReport>(&text)
                .map_err(|e| format!("{}: not a kinrepro study JSON: {e}", p.display()))
        })
        .collect::<Result<Vec<_>, _>>()?;
    let merged = StudyReport::merge(docs).map_err(|e| format!("merge: {e}"))?;
    print_study(&merged, format)
}
