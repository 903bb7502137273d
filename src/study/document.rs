//! A planned study run into one [`StudyReport`], as `kinrepro study` runs
//! it: each scene by its route, its records kept and summarised (with SRC
//! and Sobol sensitivity when asked), or, for a large unsharded Monte
//! Carlo design, streamed into moments ([`super::stream`]).

use rayon::prelude::*;

use super::StudyError;
use super::assessment::Assessment;
use super::plan::{StudyPlan, Variant};
use super::result::{StudyReport, VariantReport};
use super::runner::{PathTally, Progress, run_variant};
use super::sensitivity::sobol_run::run_sobol;
use super::stream::{RecordSink, run_streamed};
use super::summary::attach_sobol;

impl StudyPlan {
    /// Run every scene; `tick` is called once per seating. A streamed
    /// scene's records go to the sink that `open` gives for scene `i`'s
    /// report; the sinks are returned, to be completed once the results
    /// are safe.
    pub fn run<S: RecordSink>(
        &self,
        tick: &(dyn Fn() + Sync),
        mut open: impl FnMut(usize, &VariantReport) -> Result<Option<S>, S::Error>,
    ) -> Result<(StudyReport, Vec<S>), StudyError> {
        // The scenes' design checks (the friction limit's linear programs
        // above all) side by side: for a small study they take longer than
        // its seatings, which run in parallel within each scene.
        let assessments: Vec<Assessment> =
            self.variants.par_iter().map(|v| Assessment::new(&v.scene, &v.coupling)).collect();
        let mut variants = Vec::new();
        let mut sinks = Vec::new();
        for ((i, v), assessment) in self.variants.iter().enumerate().zip(assessments) {
            let mut r = if v.streamed {
                let (r, sink) = run_streamed(&self.settings, v, tick, |r| open(i, r))?;
                sinks.extend(sink);
                r
            } else {
                self.kept(v, tick)?
            };
            r.assessment = Some(assessment);
            variants.push(r);
        }
        Ok((StudyReport::new(variants, self.settings.shard), sinks))
    }

    /// One scene's study with its records kept: statistics from them (none
    /// for one shard of several), Sobol indices if planned. `v` is one of
    /// this plan's variants, or one made from it ([`Variant::with_model`]).
    pub fn kept(&self, v: &Variant, tick: &(dyn Fn() + Sync)) -> Result<VariantReport, StudyError> {
        let tally = PathTally::default();
        let run = run_variant(&self.settings, v, Progress::with_tally(tick, &tally))?;
        let mut r = VariantReport::new(&self.settings, v, run).map_err(|e| e.in_file(v.file()))?;
        r.seating_paths = Some(tally.counts());
        r.unconverged = tally.unconverged();
        r.load_path = tally.load_path();
        if let Some(n) = self.sobol {
            attach_sobol(&mut r, &run_sobol(&self.settings, v, n, tick)?);
        }
        Ok(r)
    }
}
