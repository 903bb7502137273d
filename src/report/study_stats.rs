//! The statistics of a study report: sigma, its interval and the extremes
//! per evaluation point (from the records, or from streamed moments), and
//! the regression sensitivity of the first point.

use crate::report::study::{PointStats, StudyRecord, VariantReport, is_tolerance_input};
use crate::report::study_checks::{check_finite_records, zero_scatter};
use crate::report::study_record::Dofs;
use crate::report::study_stream::{StreamStats, split_moment_stats, streams};
use crate::study::StudyError;
use crate::study::runner::{COMPONENTS, INTERCHANGE_PREFIX};
use crate::study::sensitivity::{self, SensitivityBlock};
use crate::study::stats::{SampleRecord, SigmaMethod, Summary, summarize_outputs};

/// Point names, in output order.
fn point_names(output_names: &[String]) -> Vec<String> {
    output_names
        .chunks(COMPONENTS.len())
        .map(|c| {
            c[0].rsplit_once('/')
                .map_or(c[0].clone(), |(p, _)| p.to_string())
        })
        .collect()
}

/// Statistics of the re-seating and of the interchangeability outputs.
fn split_stats(
    output_names: &[String],
    records: &[StudyRecord],
    method: SigmaMethod,
) -> Result<(Vec<PointStats>, Vec<PointStats>), StudyError> {
    let k = output_names
        .iter()
        .position(|n| n.starts_with(INTERCHANGE_PREFIX))
        .unwrap_or(output_names.len());
    let part =
        |range: std::ops::Range<usize>, strip: bool| -> Result<Vec<PointStats>, StudyError> {
            if range.is_empty() {
                return Ok(Vec::new());
            }
            let names: Vec<String> = output_names[range.clone()]
                .iter()
                .map(|n| {
                    if strip {
                        n.trim_start_matches(INTERCHANGE_PREFIX).to_string()
                    } else {
                        n.clone()
                    }
                })
                .collect();
            let recs: Vec<SampleRecord> = records
                .iter()
                .map(|r| SampleRecord {
                    index: r.index,
                    inputs: Vec::new(),
                    outputs: r.outputs[range.clone()].to_vec(),
                })
                .collect();
            point_stats(&names, &recs, method)
        };
    Ok((part(0..k, false)?, part(k..output_names.len(), true)?))
}

/// SRC tables of the first evaluation point: re-seating outputs on the
/// friction, preload and start inputs; interchangeability outputs on the
/// tolerance inputs.
pub fn sensitivity_blocks(v: &VariantReport) -> Vec<SensitivityBlock> {
    let samples: Vec<(&[f64], &[f64])> = v
        .records
        .iter()
        .map(|r| (r.inputs.as_slice(), r.outputs.as_slice()))
        .collect();
    let mut blocks = Vec::new();
    for (kind, tolerance) in [("reseating", false), ("interchangeability", true)] {
        let inputs: Vec<(usize, String)> = v
            .inputs
            .iter()
            .enumerate()
            .filter(|(_, n)| is_tolerance_input(n) == tolerance)
            .map(|(j, n)| (j, n.clone()))
            .collect();
        let first = v
            .output_names
            .iter()
            .position(|n| n.starts_with(INTERCHANGE_PREFIX) == tolerance);
        let (Some(first), false) = (first, inputs.is_empty()) else {
            continue;
        };
        let outputs: Vec<(usize, String)> = (first..first + COMPONENTS.len())
            .map(|k| (k, v.output_names[k].clone()))
            .collect();
        blocks.push(sensitivity::block(kind, &inputs, &outputs, &samples));
    }
    blocks
}

/// Statistics per evaluation point; sigma and its interval by the method
/// valid for the design (`method`, [`SigmaMethod::for_design`]).
fn point_stats(
    output_names: &[String],
    records: &[SampleRecord],
    method: SigmaMethod,
) -> Result<Vec<PointStats>, StudyError> {
    let summaries = summarize_outputs(records, method)?;
    let pick = |chunk: &[Summary], f: &dyn Fn(&Summary) -> f64| {
        Dofs::from_si(std::array::from_fn(|k| f(&chunk[k])))
    };
    Ok(point_names(output_names)
        .into_iter()
        .zip(summaries.chunks(COMPONENTS.len()))
        .map(|(name, c)| PointStats {
            name,
            n: c[0].n,
            sigma: pick(c, &|s| s.sigma),
            sigma_ci90_low: c
                .iter()
                .all(|s| s.sigma_interval.is_some())
                .then(|| pick(c, &|s| s.sigma_interval.map_or(f64::NAN, |i| i.lower))),
            sigma_ci90_high: c
                .iter()
                .all(|s| s.sigma_interval.is_some())
                .then(|| pick(c, &|s| s.sigma_interval.map_or(f64::NAN, |i| i.upper))),
            sigma_interval_method: c[0].sigma_interval_method.clone(),
            three_sigma: pick(c, &|s| s.three_sigma),
            mean: pick(c, &|s| s.mean),
            min: pick(c, &|s| s.min),
            max: pick(c, &|s| s.max),
        })
        .collect())
}

impl VariantReport {
    /// Statistics (and sensitivity, if asked for) from the records.
    pub(crate) fn finish(&mut self) -> Result<(), StudyError> {
        check_finite_records(&self.records, &self.output_names)?;
        if streams(&self.design) {
            let mut st = StreamStats::new(self.output_names.len());
            for r in &self.records {
                st.push(std::slice::from_ref(&r.sample()), &self.output_names)?;
            }
            self.set_moment_stats(&st)?;
        } else {
            let method = SigmaMethod::for_design(&self.design);
            (self.points, self.interchangeability) =
                split_stats(&self.output_names, &self.records, method)?;
            self.cannot_seat = self.zero_scatter();
        }
        if self.sensitivity.is_some() {
            self.sensitivity = Some(sensitivity_blocks(self));
        }
        Ok(())
    }

    /// Statistics of a streamed study from its moments.
    pub fn set_moment_stats(&mut self, st: &StreamStats) -> Result<(), StudyError> {
        (self.points, self.interchangeability) =
            split_moment_stats(&self.output_names, &st.moments)?;
        self.streamed = true;
        self.cannot_seat = self.zero_scatter();
        Ok(())
    }

    /// The reason the coupling did not seat, if every re-seating sigma is
    /// exactly zero although the inputs vary (friction with a spread, or
    /// anything else): every sample stopped at the nominal pose.
    fn zero_scatter(&self) -> Option<String> {
        let var = self.variation();
        let varies = (var.friction && self.spread > 0.0) || var.preload || var.start.is_some();
        if varies {
            zero_scatter(&self.points)
        } else {
            None
        }
    }
}
