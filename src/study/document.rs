//! A study of several scenes into one [`StudyReport`], as `kinrepro study`
//! runs it: the plan (each scene's design checked, the seatings in all for
//! a progress bar and the thread pool), then each scene by its route: its
//! records kept and summarised (with SRC and Sobol sensitivity when asked),
//! or, for a large unsharded Monte Carlo design, streamed into moments
//! ([`super::stream`]).

use super::DesignSpec;
use super::bounds::{self, MAX_KEPT_SEATINGS, MAX_STREAMED_SAMPLES};
use super::request::OptionError;
use super::result::{StudyReport, StudyRunError, VariantReport};
use super::runner::{PathTally, Progress, StudyOptions, check_options, design_for, run_variant};
use super::sensitivity::sobol_run::run_sobol;
use super::stream::{RecordSink, STREAM_ABOVE, run_streamed, streams};
use super::summary::attach_sobol;
use crate::assembly::Coupling;

/// The scenes of a study, their checked designs and what the run will do.
#[derive(Debug)]
pub struct StudyPlan<'a> {
    couplings: &'a [Coupling],
    designs: Vec<DesignSpec>,
    opts: StudyOptions,
    /// Base sample size of the Sobol indices (only for a whole design: the
    /// Saltelli matrices are not sharded).
    sobol: Option<usize>,
    /// Seatings of this run in all: the shard's samples of every scene and
    /// the Saltelli matrices.
    pub seatings: usize,
}

impl<'a> StudyPlan<'a> {
    /// Check the options against every scene and draw up its design;
    /// `sobol_samples`: the base sample size of Sobol indices, if asked for
    /// (refused, like any sensitivity, on a streamed study: it keeps no
    /// samples).
    pub fn new(
        couplings: &'a [Coupling],
        opts: StudyOptions,
        sobol_samples: Option<usize>,
    ) -> Result<Self, StudyRunError> {
        let sobol = sobol_samples.filter(|_| opts.shard.count == 1);
        let mut designs = Vec::new();
        let mut seatings = 0;
        let mut kept = 0usize;
        for c in couplings {
            check_options(c, &opts)?;
            let d = design_for(c, &opts).map_err(StudyRunError::at(&c.scene.file))?;
            let run = opts
                .shard
                .range(d.n)
                .map_err(StudyRunError::at("--shard"))?
                .len();
            let rows = sobol.map_or(Some(0), |n| n.checked_mul(d.dims + 2));
            let sobol_rows = bounds::check("Sobol seatings N (d + 2)", rows, MAX_KEPT_SEATINGS)
                .map_err(StudyRunError::at("--sobol-samples"))?;
            if streams(&d) && opts.shard.count == 1 {
                bounds::check("samples", Some(run), MAX_STREAMED_SAMPLES)
                    .map_err(StudyRunError::at(&c.scene.file))?;
            } else {
                kept = kept.saturating_add(run);
            }
            kept = bounds::check(
                "seatings kept in memory",
                kept.checked_add(sobol_rows),
                MAX_KEPT_SEATINGS,
            )
            .map_err(StudyRunError::at("--samples"))?;
            seatings += run + sobol_rows;
            designs.push(d);
        }
        let plan = StudyPlan {
            couplings,
            designs,
            opts,
            sobol,
            seatings,
        };
        if plan.streamed() && opts.sensitivity {
            return Err(OptionError(format!(
                "--sensitivity keeps every sample in memory: not available for Monte Carlo studies above {STREAM_ABOVE} samples"
            ))
            .into());
        }
        Ok(plan)
    }

    /// True if scene `i` streams: a Monte Carlo design above
    /// `stream::STREAM_ABOVE` samples, run whole (a shard keeps its records
    /// for `merge`).
    fn streams(&self, i: usize) -> bool {
        streams(&self.designs[i]) && self.opts.shard.count == 1
    }

    /// True if any scene streams (keeps no records in memory).
    pub fn streamed(&self) -> bool {
        (0..self.designs.len()).any(|i| self.streams(i))
    }

    /// Run every scene; `tick` is called once per seating. A streamed
    /// scene's records go to the sink that `open` gives for scene `i`'s
    /// report; the sinks are returned, to be completed once the results
    /// are safe.
    pub fn run<S: RecordSink>(
        &self,
        tick: &(dyn Fn() + Sync),
        mut open: impl FnMut(usize, &VariantReport) -> Result<Option<S>, S::Error>,
    ) -> Result<(StudyReport, Vec<S>), StudyRunError> {
        let mut variants = Vec::new();
        let mut sinks = Vec::new();
        for (i, c) in self.couplings.iter().enumerate() {
            if self.streams(i) {
                let (v, sink) = run_streamed(c, &self.opts, tick, |v| open(i, v))?;
                variants.push(v);
                sinks.extend(sink);
            } else {
                variants.push(self.kept(c, tick)?);
            }
        }
        Ok((StudyReport::new(variants, self.opts.shard), sinks))
    }

    /// One scene's study with its records kept: statistics from them (none
    /// for one shard of several), Sobol indices if planned.
    fn kept(&self, c: &Coupling, tick: &(dyn Fn() + Sync)) -> Result<VariantReport, StudyRunError> {
        let tally = PathTally::default();
        let run = run_variant(c, &self.opts, Progress::with_tally(tick, &tally))?;
        let mut v =
            VariantReport::new(c, run, &self.opts).map_err(StudyRunError::at(&c.scene.file))?;
        v.seating_paths = Some(tally.counts());
        v.unconverged = tally.unconverged();
        v.load_path = tally.load_path();
        if let Some(n) = self.sobol {
            attach_sobol(&mut v, &run_sobol(c, &self.opts, n, tick)?);
        }
        Ok(v)
    }
}
