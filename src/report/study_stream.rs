//! Statistics of large Monte Carlo studies from streaming moments.
//!
//! Above [`STREAM_ABOVE`] Monte Carlo samples a study keeps no per-sample
//! records: each chunk of samples is pushed, in sample-index order, into
//! one [`Moments`] per output (Welford/Pebay one-pass update, see
//! `study::stats::moments`) and appended to the per-sample CSV, so memory
//! stays bounded. The same rule decides how a merged study of that design is
//! summarised (records pushed in index order), so shards + merge equal one
//! run bit for bit. The interval of sigma is Bonett's (2006) from the
//! moments (`study::stats::sigma_interval_from_moments`), valid for
//! independent samples.

use crate::report::study::{Dofs, PointStats};
use crate::study::runner::{COMPONENTS, INTERCHANGE_PREFIX};
use crate::study::stats::{Moments, SampleRecord, sigma_interval_from_moments};
use crate::study::{DesignSpec, Sampler, StudyError};

/// Monte Carlo studies of more samples than this are summarised from
/// streaming moments and keep no records in memory.
pub const STREAM_ABOVE: usize = 100_000;

/// Level of the printed interval of sigma.
const LEVEL: f64 = 0.90;

/// True if a study of this design is summarised from streaming moments.
pub fn streams(design: &DesignSpec) -> bool {
    design.sampler == Sampler::MonteCarlo && design.n > STREAM_ABOVE
}

/// One accumulator per output, fed in sample-index order.
#[derive(Debug, Clone)]
pub struct StreamStats {
    pub moments: Vec<Moments>,
}

impl StreamStats {
    pub fn new(outputs: usize) -> Self {
        StreamStats {
            moments: vec![Moments::new(); outputs],
        }
    }

    /// Push records (sorted by index); a non-finite output is an error
    /// naming the sample and the output.
    pub fn push(&mut self, records: &[SampleRecord], names: &[String]) -> Result<(), StudyError> {
        for r in records {
            check_record(r.index, &r.outputs, names)?;
            for (m, &x) in self.moments.iter_mut().zip(&r.outputs) {
                m.push(x);
            }
        }
        Ok(())
    }
}

/// A NaN or infinite output is an error naming the sample.
pub fn check_record(index: usize, outputs: &[f64], names: &[String]) -> Result<(), StudyError> {
    match outputs.iter().position(|x| !x.is_finite()) {
        None => Ok(()),
        Some(k) => Err(StudyError::NonFinite {
            what: format!(
                "sample {index}: output {} = {}",
                names.get(k).map_or("?", |s| s.as_str()),
                outputs[k]
            ),
        }),
    }
}

/// Re-seating and interchangeability statistics from the moments of every
/// output (in `names` order).
pub fn split_moment_stats(
    names: &[String],
    moments: &[Moments],
) -> Result<(Vec<PointStats>, Vec<PointStats>), StudyError> {
    let k = names
        .iter()
        .position(|n| n.starts_with(INTERCHANGE_PREFIX))
        .unwrap_or(names.len());
    Ok((
        moment_point_stats(&names[..k], &moments[..k])?,
        moment_point_stats(&names[k..], &moments[k..])?,
    ))
}

/// Statistics per evaluation point from the moments of its six outputs.
fn moment_point_stats(
    names: &[String],
    moments: &[Moments],
) -> Result<Vec<PointStats>, StudyError> {
    let mut out = Vec::new();
    for (c, ms) in names
        .chunks(COMPONENTS.len())
        .zip(moments.chunks(COMPONENTS.len()))
    {
        let name = c[0]
            .trim_start_matches(INTERCHANGE_PREFIX)
            .rsplit_once('/')
            .map_or(c[0].clone(), |(p, _)| p.to_string());
        let mut sigma = [0.0; 6];
        let mut lo = [0.0; 6];
        let mut hi = [0.0; 6];
        for (k, m) in ms.iter().enumerate() {
            sigma[k] = m.sigma();
            if !(m.mean.is_finite() && sigma[k].is_finite()) {
                return Err(StudyError::NonFinite {
                    what: format!("{}: mean or sigma (overflow)", c[k]),
                });
            }
            let iv = sigma_interval_from_moments(m, LEVEL)?;
            (lo[k], hi[k]) = (iv.lower, iv.upper);
        }
        let pick = |f: &dyn Fn(&Moments) -> f64| Dofs::from_si(std::array::from_fn(|k| f(&ms[k])));
        out.push(PointStats {
            name,
            n: ms[0].n as usize,
            sigma: Dofs::from_si(sigma),
            sigma_ci90_low: Some(Dofs::from_si(lo)),
            sigma_ci90_high: Some(Dofs::from_si(hi)),
            sigma_interval_method: crate::study::stats::interval::METHOD_BONETT.to_string(),
            three_sigma: Dofs::from_si(sigma.map(|s| 3.0 * s)),
            mean: pick(&|m| m.mean),
            min: pick(&|m| m.min),
            max: pick(&|m| m.max),
        });
    }
    Ok(out)
}
