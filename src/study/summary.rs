//! The statistics of a study's variant: sigma, its interval and the
//! extremes per evaluation point, built from one [`Summary`] per output
//! whether the summaries come from the records (two passes) or from
//! streamed moments; the check of non-finite outputs before them; the regression sensitivity of the
//! first point and the Sobol indices attached to it.

use super::StudyError;
use super::inputs::Input;
use super::record::{CycleStats, DirectionStats, Dofs, PointStats, StudyRecord};
use super::result::VariantReport;
use super::runner::{INTERCHANGE_PREFIX, THERMAL_PREFIX};
use super::sensitivity::sobol::SobolRun;
use super::sensitivity::{self, SensitivityBlock};
use super::stats::{SampleRecord, SigmaMethod, Summary, summarize_moments, summarize_outputs};
use super::stream::{StreamStats, check_record, streams};
use crate::dof::{Dof, nano};
use crate::scene::EvaluationPoint;
use crate::scene::point::{ABOUT, ALONG, Measure, split_output};

/// Re-seating statistics per evaluation point from one summary per output
/// (in `names` order), each with its thermal drift statistics from the
/// `thermal/<k>/...` outputs after them (at the cycle's temperatures
/// `cycle`), and interchangeability statistics from the `interchange/...`
/// outputs after those.
fn split_points(
    names: &[String],
    summaries: &[Summary],
    cycle: &[[f64; 2]],
    scene_points: &[EvaluationPoint],
) -> (Vec<PointStats>, Vec<PointStats>) {
    let first = |prefix: &str| names.iter().position(|n| n.starts_with(prefix));
    let k = first(INTERCHANGE_PREFIX).unwrap_or(names.len());
    let t = first(THERMAL_PREFIX).unwrap_or(k);
    let mut points = point_stats(&names[..t], &summaries[..t], scene_points);
    let drift = point_stats(&names[t..k], &summaries[t..k], scene_points);
    if !points.is_empty() {
        for (j, mut d) in drift.into_iter().enumerate() {
            let (point, cycle_point) = (j % points.len(), j / points.len());
            d.name.clone_from(&points[point].name);
            let delta_t_k = cycle.get(cycle_point).copied().unwrap_or([f64::NAN; 2]);
            points[point].thermal.push(CycleStats { delta_t_k, drift: d });
        }
    }
    (points, point_stats(&names[k..], &summaries[k..], scene_points))
}

/// One [`PointStats`] per evaluation point: its six outputs
/// (`point/<dof>_<SI unit>` over [`Dof::ALL`]) and the directions after
/// them (`point/along/...`, `point/about/...`), in nm and nrad; an
/// interval of sigma only where every DOF has one. `points` gives the
/// directions' vectors (empty for a document that does not carry them).
fn point_stats(
    names: &[String],
    summaries: &[Summary],
    points: &[EvaluationPoint],
) -> Vec<PointStats> {
    let mut out = Vec::new();
    let mut i = 0;
    while i + Dof::ALL.len() <= names.len() {
        let dofs = i..i + Dof::ALL.len();
        let (head, end) = point_outputs(names, i);
        let c = &summaries[dofs.clone()];
        let pick = |f: &dyn Fn(&Summary) -> f64| Dofs::from_si(std::array::from_fn(|k| f(&c[k])));
        let bound = |f: fn(&super::stats::Interval) -> f64| {
            c.iter()
                .all(|s| s.sigma_interval.is_some())
                .then(|| pick(&|s| s.sigma_interval.as_ref().map_or(f64::NAN, f)))
        };
        let name = point_name(head).to_string();
        let scene_point = points.iter().find(|p| p.name == name);
        let directions = (dofs.end..end)
            .map(|j| direction_stats(&names[j][head.len() + 1..], &summaries[j], scene_point))
            .collect();
        out.push(PointStats {
            name,
            n: c[0].n,
            sigma: pick(&|s| s.sigma),
            sigma_ci90_low: bound(|i| i.lower),
            sigma_ci90_high: bound(|i| i.upper),
            sigma_interval_method: c[0].sigma_interval_method.clone(),
            three_sigma: pick(&|s| s.three_sigma),
            mean: pick(&|s| s.mean),
            min: pick(&|s| s.min),
            max: pick(&|s| s.max),
            directions,
            thermal: Vec::new(),
        });
        i = end;
    }
    out
}

/// The outputs of the point whose six DOFs start at `names[i]`: its head
/// (`[prefix]<point>`) and the end of its outputs (after its directions,
/// `<head>/along/...` and `<head>/about/...`).
fn point_outputs(names: &[String], i: usize) -> (&str, usize) {
    let head = names[i].strip_suffix(&format!("/{}", Dof::X.si_key())).unwrap_or(&names[i]);
    let (along, about) = (format!("{head}/{ALONG}"), format!("{head}/{ABOUT}"));
    let end = (i + Dof::ALL.len()..names.len())
        .find(|&j| !(names[j].starts_with(&along) || names[j].starts_with(&about)))
        .unwrap_or(names.len());
    (head, end)
}

/// The evaluation point of an output's head: `<point>`,
/// `interchange/<point>` or `thermal/<k>/<point>`.
fn point_name(head: &str) -> &str {
    match head.strip_prefix(THERMAL_PREFIX) {
        Some(rest) => rest.split_once('/').map_or(rest, |(_, p)| p),
        None => head.trim_start_matches(INTERCHANGE_PREFIX),
    }
}

/// The statistics of the direction output `key` (`along/<name>_m` or
/// `about/<name>_rad`) of `point`, in nm or nrad.
fn direction_stats(key: &str, s: &Summary, point: Option<&EvaluationPoint>) -> DirectionStats {
    let rotation = key.starts_with(ABOUT);
    let (prefix, suffix) = if rotation { (ABOUT, "_rad") } else { (ALONG, "_m") };
    let name = key.trim_start_matches(prefix).trim_end_matches(suffix).to_string();
    let vector = point
        .and_then(|p| p.directions.iter().find(|d| d.name == name && d.rotation == rotation))
        .map(|d| d.vector.into());
    DirectionStats {
        kind: prefix.trim_end_matches('/').to_string(),
        vector,
        unit: if rotation { "nrad" } else { "nm" }.to_string(),
        sigma: nano(s.sigma),
        sigma_ci90_low: s.sigma_interval.as_ref().map(|i| nano(i.lower)),
        sigma_ci90_high: s.sigma_interval.as_ref().map(|i| nano(i.upper)),
        three_sigma: nano(s.three_sigma),
        mean: nano(s.mean),
        min: nano(s.min),
        max: nano(s.max),
        name,
    }
}

impl VariantReport {
    /// Statistics (and sensitivity, if asked for) from the records: from
    /// their moments in index order where the design streams
    /// ([`streams`]), so that merged shards equal one streamed run.
    pub(crate) fn finish(&mut self) -> Result<(), StudyError> {
        let centred: Vec<&StudyRecord> = self.records.iter().filter(|r| r.centred()).collect();
        check_finite_records(&centred, &self.output_names)?;
        if streams(&self.design) {
            let mut st = StreamStats::new(self.output_names.len());
            for r in &self.records {
                st.push(&[r.sample()], &self.output_names)?;
            }
            self.set_moment_stats(&st)?;
        } else {
            let samples: Vec<SampleRecord> = centred.iter().map(|r| r.sample()).collect();
            let failed = self.records.len() - samples.len();
            let summaries = summarize_outputs(&samples, self.sigma_method(failed))?;
            (self.points, self.interchangeability) = split_points(
                &self.output_names,
                &summaries,
                &self.thermal_cycle(),
                &self.evaluation_points,
            );
            self.count_failures(failed, self.records.len());
        }
        if self.sensitivity.is_some() {
            self.sensitivity = Some(sensitivity_blocks(self));
        }
        Ok(())
    }

    /// Statistics of a streamed study from its moments (one per output).
    pub fn set_moment_stats(&mut self, st: &StreamStats) -> Result<(), StudyError> {
        let summaries = self
            .output_names
            .iter()
            .zip(&st.moments)
            .map(|(name, m)| {
                summarize_moments(m).map_err(|e| match e {
                    StudyError::NonFinite { what } => {
                        StudyError::NonFinite { what: format!("{name}: {what}") }
                    }
                    e => e,
                })
            })
            .collect::<Result<Vec<_>, _>>()?;
        (self.points, self.interchangeability) = split_points(
            &self.output_names,
            &summaries,
            &self.thermal_cycle(),
            &self.evaluation_points,
        );
        self.count_failures(st.not_centred, st.samples);
        self.streamed = true;
        Ok(())
    }

    /// The estimate of sigma valid for the design and `failed` seatings
    /// that did not centre (an LHS with gaps has no interval).
    pub fn sigma_method(&self, failed: usize) -> SigmaMethod {
        match SigmaMethod::for_design(&self.design) {
            SigmaMethod::Replicated(_) | SigmaMethod::SingleLhs if failed > 0 => {
                SigmaMethod::IncompleteLhs
            }
            m => m,
        }
    }

    /// With the start varied: `failed` of `samples` seatings did not centre.
    /// The statistics are over those that did (conditional on centring),
    /// and each point's interval method says so.
    fn count_failures(&mut self, failed: usize, samples: usize) {
        if self.start_bounds.is_none() {
            return;
        }
        self.seating_failures = Some(failed);
        self.seating_failure_share = Some(failed as f64 / samples.max(1) as f64);
        if failed == 0 {
            return;
        }
        for p in self.points.iter_mut().chain(&mut self.interchangeability) {
            p.sigma_interval_method += &format!(
                "; over the {} of {samples} seatings that centred ({failed} did not): conditional on centring",
                samples - failed
            );
        }
    }
}

/// Every output finite, and no column so large that its sum of squares
/// overflows (that would make sigma NaN): otherwise an error naming the
/// sample.
fn check_finite_records(records: &[&StudyRecord], names: &[String]) -> Result<(), StudyError> {
    for r in records {
        check_record(r.index, &r.outputs, names)?;
    }
    let n = records.len() as f64;
    for (k, name) in names.iter().enumerate() {
        let worst = records.iter().max_by(|a, b| a.outputs[k].abs().total_cmp(&b.outputs[k].abs()));
        if let Some(r) = worst
            && !(r.outputs[k] * r.outputs[k] * n).is_finite()
        {
            return Err(StudyError::NonFinite {
                what: format!(
                    "sample {}: output {} = {:e} overflows the variance",
                    r.index, name, r.outputs[k]
                ),
            });
        }
    }
    Ok(())
}

/// SRC tables of the first evaluation point and every point's directions:
/// re-seating outputs on the
/// friction, preload and start inputs; interchangeability outputs on the
/// tolerance inputs.
fn sensitivity_blocks(v: &VariantReport) -> Vec<SensitivityBlock> {
    let samples: Vec<(&[f64], &[f64])> = v
        .records
        .iter()
        .filter(|r| r.centred())
        .map(|r| (r.inputs.as_slice(), r.outputs.as_slice()))
        .collect();
    let mut blocks = Vec::new();
    for (kind, tolerance) in [("reseating", false), ("interchangeability", true)] {
        let inputs: Vec<(usize, Input)> = (v.inputs.iter().copied().enumerate())
            .filter(|(_, i)| i.is_tolerance() == tolerance)
            .collect();
        let first =
            v.output_names.iter().position(|n| n.starts_with(INTERCHANGE_PREFIX) == tolerance);
        let (Some(first), false) = (first, inputs.is_empty()) else {
            continue;
        };
        // The first point's six DOFs and its directions, then the other
        // points' directions (of the same kind: not their thermal drift).
        let (_, end) = point_outputs(&v.output_names, first);
        let names = v.output_names.iter().enumerate();
        let directions = names.skip(end).filter(|(_, n)| {
            let kind =
                n.starts_with(INTERCHANGE_PREFIX) == tolerance && !n.starts_with(THERMAL_PREFIX);
            kind && matches!(split_output(n), Some((_, Measure::Along(_) | Measure::About(_))))
        });
        let outputs: Vec<(usize, String)> = (first..end)
            .map(|k| (k, v.output_names[k].clone()))
            .chain(directions.map(|(k, n)| (k, n.clone())))
            .collect();
        blocks.push(sensitivity::block(kind, &inputs, &outputs, &samples));
    }
    blocks
}

/// Fill `sobol` of every sensitivity block of `v` (JSON
/// `variants[i].sensitivity[k].sobol`) from the seated Saltelli matrices
/// `run` (same outputs and inputs as the block's SRC table).
pub fn attach_sobol(v: &mut VariantReport, run: &SobolRun) {
    let inputs = v.inputs.clone();
    let Some(blocks) = v.sensitivity.as_mut() else {
        return;
    };
    for b in blocks.iter_mut() {
        let cols: Vec<usize> =
            b.inputs.iter().filter_map(|input| inputs.iter().position(|i| i == input)).collect();
        let outputs: Vec<(usize, String)> = b
            .dofs
            .iter()
            .filter_map(|d| {
                run.output_names.iter().position(|n| *n == d.output).map(|k| (k, d.output.clone()))
            })
            .collect();
        b.sobol = Some(run.block(&cols, &outputs));
    }
}
