//! The plan of a study: the options checked once ([`Settings`]) and, per
//! scene, its coupling, its design and this shard's samples
//! ([`Variant`]), with the run's size bounded before anything is seated.
//! Every runner (kept records, streamed moments, Sobol matrices, a sweep's
//! design points, a calibration's model studies) takes a plan's variant
//! and settings and never derives a design or checks an option again.

use super::bounds::{self, MAX_KEPT_SEATINGS, MAX_STREAMED_SAMPLES};
use super::options::{Settings, StudyOptions};
use super::sampling::{DEFAULT_LHS_REPLICATES, default_replicates};
use super::stream::{STREAM_ABOVE, streams};
pub use super::variant::Variant;
use super::variation::Variation;
use super::{DesignSpec, Sampler, StudyError};
use crate::assembly::Coupling;
use crate::param::{Param, ParamError};
use crate::scene::Scene;
use crate::solve::Method;

/// A checked study of one or several scenes, ready to run.
#[derive(Debug, Clone)]
pub struct StudyPlan {
    pub settings: Settings,
    pub variants: Vec<Variant>,
    /// Base sample size of the Sobol indices (only for a whole design:
    /// the Saltelli matrices are not sharded).
    pub sobol: Option<usize>,
    /// Seatings of this run in all: the shard's samples of every scene and
    /// the Saltelli matrices.
    pub seatings: usize,
}

impl StudyPlan {
    /// Check `options` against every scene (each `(scene, its coupling)`)
    /// and draw up its design; the run's size is bounded here. A whole
    /// Monte Carlo design above `stream::STREAM_ABOVE` samples is streamed
    /// by [`StudyPlan::run`].
    pub fn new(models: Vec<(Scene, Coupling)>, options: &StudyOptions) -> Result<Self, StudyError> {
        Self::planned(models, options, true)
    }

    /// [`StudyPlan::new`] for runs that keep every record (a sweep's design
    /// points, a calibration's or prediction's model studies): nothing
    /// streams, and the records are bounded as kept ones.
    pub fn keeping_records(
        models: Vec<(Scene, Coupling)>,
        options: &StudyOptions,
    ) -> Result<Self, StudyError> {
        Self::planned(models, options, false)
    }

    fn planned(
        models: Vec<(Scene, Coupling)>,
        options: &StudyOptions,
        may_stream: bool,
    ) -> Result<Self, StudyError> {
        let settings = options.settings()?;
        let sobol = settings.sobol_samples.filter(|_| settings.shard.count == 1);
        let mut plan =
            StudyPlan { settings, variants: Vec::with_capacity(models.len()), sobol, seatings: 0 };
        if let Some(n @ 0..=1) = options.samples
            && options.sampler != Some(Sampler::Corners)
        {
            let why = "a study needs at least 2 samples (a sigma needs two)";
            return Err(ParamError::new(
                Param::Samples,
                format!("{}: {why}", Param::Samples.with(n)),
            )
            .into());
        }
        let mut kept = 0usize;
        for (scene, coupling) in models {
            let mut v = plan.variant(scene, coupling, options)?;
            v.streamed &= may_stream;
            let run = v.samples.len();
            let rows = sobol.map_or(Some(0), |n| n.checked_mul(v.design.dims + 2));
            let sobol_rows = bounds::check("Sobol seatings N (d + 2)", rows, MAX_KEPT_SEATINGS)
                .map_err(|e| e.at(Param::SobolSamples))?;
            if v.streamed {
                bounds::check("samples", Some(run), MAX_STREAMED_SAMPLES)
                    .map_err(|e| e.in_file(v.file()))?;
            } else {
                kept = kept.saturating_add(run);
            }
            // Named after the larger part: the samples, or the Sobol rows.
            let (what, param) = if sobol_rows > kept {
                ("seatings kept in memory (mostly the Sobol rows N (d + 2))", Param::SobolSamples)
            } else {
                ("seatings kept in memory (mostly the samples)", Param::Samples)
            };
            kept = bounds::check(what, kept.checked_add(sobol_rows), MAX_KEPT_SEATINGS)
                .map_err(|e| e.at(param))?;
            plan.seatings += run + sobol_rows;
            plan.variants.push(v);
        }
        if plan.streamed() && settings.sensitivity {
            let p = Param::Sensitivity;
            return Err(ParamError::new(p, format!(
                "{p} keeps every sample in memory: not available for Monte Carlo studies above {STREAM_ABOVE} samples"
            )).into());
        }
        Ok(plan)
    }

    /// True if any scene streams (keeps no records in memory).
    pub fn streamed(&self) -> bool {
        self.variants.iter().any(|v| v.streamed)
    }

    /// The seating method of every sample.
    pub fn method(&self) -> &Method {
        &self.settings.method
    }

    /// One scene's variant: the options checked against it, its design and
    /// this shard's samples.
    fn variant(
        &self,
        scene: Scene,
        coupling: Coupling,
        options: &StudyOptions,
    ) -> Result<Variant, StudyError> {
        let s = &self.settings;
        check_scene(&scene, s).map_err(|e| StudyError::from(e).in_file(&scene.file))?;
        let design =
            design_for(&scene, options, &s.variation).map_err(|e| e.in_file(&scene.file))?;
        let samples = s.shard.range(design.n).map_err(|e| e.at(Param::Shard))?;
        let streamed = streams(&design) && s.shard.count == 1;
        Ok(Variant { scene, coupling, design, samples, streamed })
    }
}

/// The design of `scene`'s study under `options`: sampler, samples and
/// seed given or the scene's `[study]`, one column per varied input.
fn design_for(
    scene: &Scene,
    options: &StudyOptions,
    variation: &Variation,
) -> Result<DesignSpec, StudyError> {
    let st = &scene.study;
    let sampler = options.sampler.unwrap_or(st.sampler);
    if sampler == Sampler::Corners && variation.friction && !scene.mu_distribution.is_uniform() {
        return Err(StudyError::InvalidParameter(format!(
            "the corners sampler draws each input at the ends of its range, which a {} \
             distribution of mu_s (friction.distribution) does not have: use lhs or mc",
            scene.mu_distribution.name()
        )));
    }
    let n = match sampler {
        Sampler::Corners => None,
        _ => Some(options.samples.unwrap_or(st.samples)),
    };
    let dims = variation.inputs(scene).len();
    let spec = DesignSpec::new(sampler, dims, n, options.seed.unwrap_or(st.seed))?;
    replicated(spec, options.replicates)
}

/// An LHS split into `replicates` (default: 5, or the largest divisor of n
/// in 2..=5) so that its interval of sigma is valid; other designs as they are.
fn replicated(spec: DesignSpec, replicates: Option<usize>) -> Result<DesignSpec, StudyError> {
    match (spec.sampler, replicates) {
        (_, Some(r)) => spec.with_replicates(r),
        (Sampler::Lhs, None) => match default_replicates(spec.n) {
            Some(r) => spec.with_replicates(r),
            None => Err(StudyError::InvalidParameter(format!(
                "an LHS of {} samples cannot be split into 2 to {DEFAULT_LHS_REPLICATES} replicates of at least 2 points (needed for its interval of sigma): give {}, or {} for a single LHS without an interval",
                spec.n,
                nearest_replicable(spec.n),
                Param::Replicates.with(1)
            ))),
        },
        _ => Ok(spec),
    }
}

/// The sample counts nearest to `n` (one below, one above) that the default
/// replicate rule splits, with their replicate counts, as advice.
fn nearest_replicable(n: usize) -> String {
    let fits = |m: usize| {
        default_replicates(m).map(|r| format!("{} ({r} replicates)", Param::Samples.with(m)))
    };
    let below = (1..n).rev().find_map(fits);
    let above = (n + 1..).find_map(fits);
    below.into_iter().chain(above).collect::<Vec<_>>().join(" or ")
}

/// Check that the settings can run on this scene: something varies, a
/// varied start has the dynamic solver, and the scene gives bounds for a
/// varied preload or tolerances.
fn check_scene(scene: &Scene, s: &Settings) -> Result<(), ParamError> {
    let var = s.variation;
    let vary = Param::Vary;
    let fail = |p: Param, m: String| Err(ParamError::new(p, m));
    if !var.reseating() && !var.tolerances {
        return fail(
            vary,
            "the study varies nothing: vary friction, preload, tolerances or the start pose".into(),
        );
    }
    if scene.thermal.is_some() && var.reseating() && matches!(s.method, Method::Dynamic(_)) {
        return fail(
            Param::Solver,
            format!(
                "the scene's [thermal] cycle is followed by the quasi-static solver only ({}; \
                 the dynamic solver seats only): drop --solver dynamic, or study the scene \
                 without its [thermal] table",
                Param::Solver.with("quasi-static")
            ),
        );
    }
    if var.start.is_some() && !matches!(s.method, Method::Dynamic(_)) {
        return fail(
            Param::Solver,
            format!(
                "a varied start pose needs the dynamic solver ({})",
                Param::Solver.with("dynamic")
            ),
        );
    }
    let bounds = scene.variation;
    if var.preload && !bounds.preload_varies() {
        return fail(
            vary,
            format!(
                "{}: the scene's [variation] table gives no preload bound (preload_offset, preload_tilt)",
                vary.with("preload")
            ),
        );
    }
    if var.preload && !scene.preload.forces.iter().any(|f| f.varies()) {
        return fail(
            vary,
            format!(
                "{}: the preload is only the weight, which is not varied",
                vary.with("preload")
            ),
        );
    }
    if var.tolerances && !bounds.tolerances_vary() {
        return fail(
            vary,
            format!(
                "{}: the scene's [variation] table gives no tolerance (ball_diameter, ball_position, surface_normal, surface_tilt, groove_position)",
                vary.with("tolerances")
            ),
        );
    }
    Ok(())
}
