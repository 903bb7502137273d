//! Large Monte Carlo studies streamed in bounded memory.
//!
//! Above [`STREAM_ABOVE`] Monte Carlo samples a study keeps no per-sample
//! records: the samples are seated in chunks ([`run_streamed`]), each
//! chunk's records are pushed, in sample-index order, into one [`Moments`]
//! per output (Welford/Pebay one-pass update, see `study::stats::moments`)
//! and handed to a [`RecordSink`] (the per-sample CSV), then dropped. The
//! same rule decides how a merged study of that design is summarised
//! (records pushed in index order), so shards + merge equal one run. The
//! interval of sigma is Bonett's (2006) from the moments
//! (`study::stats::summarize_moments`), valid for independent samples.

use super::options::Settings;
use super::record::StudyRecord;
use super::result::VariantReport;
use super::runner::{PathTally, Progress, VariantRun, recorded_output_names, run_chunked};
use super::stats::{Moments, SampleRecord};
use super::variant::Variant;
use super::{DesignSpec, Sampler, StudyError};

/// Monte Carlo studies of more samples than this are summarised from
/// streaming moments and keep no records in memory.
pub const STREAM_ABOVE: usize = 100_000;

/// Rows seated per chunk of a streamed study.
const CHUNK: usize = 8192;

/// True if a study of this design is summarised from streaming moments.
pub fn streams(design: &DesignSpec) -> bool {
    design.sampler == Sampler::MonteCarlo && design.n > STREAM_ABOVE
}

/// One accumulator per output, fed in sample-index order.
#[derive(Debug, Clone)]
pub struct StreamStats {
    pub moments: Vec<Moments>,
    /// Samples pushed whose seating did not centre (varied start): counted,
    /// not in the moments.
    pub not_centred: usize,
    /// Samples pushed.
    pub samples: usize,
}

impl StreamStats {
    pub fn new(outputs: usize) -> Self {
        StreamStats { moments: vec![Moments::new(); outputs], not_centred: 0, samples: 0 }
    }

    /// Push records (sorted by index); a non-finite output is an error
    /// naming the sample and the output.
    pub fn push(&mut self, records: &[SampleRecord], names: &[String]) -> Result<(), StudyError> {
        for r in records {
            self.samples += 1;
            if !r.centred() {
                self.not_centred += 1;
                continue;
            }
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

/// Where the records of a streamed study go as they are seated, in
/// sample-index order (e.g. the per-sample CSV of `kinrepro study --out`).
pub trait RecordSink {
    type Error: std::error::Error + Send + Sync + 'static;
    fn push(&mut self, record: &StudyRecord) -> Result<(), Self::Error>;
}

/// One scene's Monte Carlo study streamed in chunks of [`CHUNK`] rows
/// (rayon within a chunk): moments in sample order, and every record handed
/// to the sink that `open` gives for the report (before any sample is
/// seated; `None`: records are dropped). Returns the report with its
/// statistics and the sink, still to be completed by the caller.
pub fn run_streamed<S: RecordSink>(
    s: &Settings,
    v: &Variant,
    tick: &(dyn Fn() + Sync),
    open: impl FnOnce(&VariantReport) -> Result<Option<S>, S::Error>,
) -> Result<(VariantReport, Option<S>), StudyError> {
    let in_file = |e: StudyError| e.in_file(v.file());
    let names = recorded_output_names(&v.scene, &s.variation);
    let shell = VariantRun {
        design: v.design,
        shard: s.shard,
        output_names: names.clone(),
        records: Vec::new(),
        cannot_seat: super::verdict::cannot_seat(&v.scene, &v.coupling, &s.method)?,
    };
    let mut r = VariantReport::unfinished(s, v, shell);
    let mut sink = open(&r).map_err(StudyError::sink)?;
    let mut st = StreamStats::new(names.len());
    let tally = PathTally::default();
    run_chunked(s, v, CHUNK, Progress::with_tally(tick, &tally), &mut |records| {
        st.push(&records, &names).map_err(in_file)?;
        match sink.as_mut() {
            Some(k) => records.into_iter().try_for_each(|rec| {
                k.push(&StudyRecord::new(v, &s.variation, rec)).map_err(StudyError::sink)
            }),
            None => Ok(()),
        }
    })?;
    r.seating_paths = Some(tally.counts());
    r.unconverged = tally.unconverged();
    r.load_path = tally.load_path();
    r.set_moment_stats(&st).map_err(in_file)?;
    Ok((r, sink))
}
