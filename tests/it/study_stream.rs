//! A streamed study (chunks of samples seated in parallel, each chunk's
//! records pushed into one-pass moments and then dropped) gives the
//! statistics of the whole sample computed in two passes: the same records
//! whatever the chunk size (each sample depends only on its design row),
//! the mean, sigma, extremes and kurtosis of every output equal to those
//! computed here from all the records at once (mean first, then the sum of
//! squared deviations), to rounding.

use crate::common::{load, plan};

use kinrepro::study::runner::{output_names, run_chunked, run_variant};
use kinrepro::study::stats::SampleRecord;
use kinrepro::study::stream::StreamStats;
use kinrepro::study::{Sampler, StudyOptions, StudyPlan};

fn mc(samples: usize) -> StudyOptions {
    StudyOptions {
        sampler: Some(Sampler::MonteCarlo),
        samples: Some(samples),
        seed: Some(16),
        ..StudyOptions::default()
    }
}

/// The plan of scene `name` under `opts`.
fn plan_of(name: &str, opts: &StudyOptions) -> StudyPlan {
    plan(vec![load(name)], opts)
}

/// The records of a run in chunks of `chunk`, in the order the sink saw them,
/// and the streamed moments of them.
fn streamed(name: &str, samples: usize, chunk: usize) -> (Vec<SampleRecord>, StreamStats) {
    let p = plan_of(name, &mc(samples));
    let (s, c) = (&p.settings, &p.variants[0]);
    let names = output_names(&c.scene);
    let mut stats = StreamStats::new(names.len());
    let mut seen = Vec::new();
    let mut largest_chunk = 0;
    run_chunked(s, c, chunk, &|| {}, &mut |records| {
        largest_chunk = largest_chunk.max(records.len());
        stats.push(&records, &names).unwrap();
        seen.extend(records);
        Ok(())
    })
    .unwrap();
    assert!(largest_chunk <= chunk, "a chunk of {largest_chunk} > {chunk}");
    (seen, stats)
}

/// Two-pass statistics of column `k`: (mean, sigma, min, max, kurtosis).
fn two_pass(records: &[SampleRecord], k: usize) -> (f64, f64, f64, f64, f64) {
    let x: Vec<f64> = records.iter().map(|r| r.outputs[k]).collect();
    let n = x.len() as f64;
    let mean = x.iter().sum::<f64>() / n;
    let m2: f64 = x.iter().map(|v| (v - mean).powi(2)).sum();
    let m4: f64 = x.iter().map(|v| (v - mean).powi(4)).sum();
    let sigma = (m2 / (n - 1.0)).sqrt();
    let min = x.iter().copied().fold(f64::INFINITY, f64::min);
    let max = x.iter().copied().fold(f64::NEG_INFINITY, f64::max);
    // Population kurtosis m4 / m2^2 (n m4 / m2^2 with sums).
    (mean, sigma, min, max, n * m4 / (m2 * m2))
}

#[test]
fn streamed_statistics_equal_the_two_pass_statistics() {
    for name in ["01_maxwell_vgroove_steel.toml", "06_kelvin_steel.toml"] {
        let samples = 300;
        let p = plan_of(name, &mc(samples));
        let whole = run_variant(&p.settings, &p.variants[0], &|| {}).unwrap().records;
        assert_eq!(whole.len(), samples);
        for chunk in [1, 64, 1000] {
            let (records, stats) = streamed(name, samples, chunk);
            // In index order, and the same samples as one unchunked run.
            assert!(records.iter().enumerate().all(|(i, r)| r.index == i));
            assert_eq!(records, whole, "{name}: chunks of {chunk}");
            for (k, m) in stats.moments.iter().enumerate() {
                let (mean, sigma, min, max, kurt) = two_pass(&whole, k);
                assert_eq!(m.n as usize, samples);
                let scale = sigma.max(f64::MIN_POSITIVE);
                assert!(
                    (m.mean - mean).abs() <= 1e-12 * scale + 1e-13 * mean.abs(),
                    "{name} output {k}: mean {} vs {mean}",
                    m.mean
                );
                assert!(
                    (m.sigma() - sigma).abs() <= 1e-10 * scale,
                    "{name} output {k}: sigma {} vs {sigma}",
                    m.sigma()
                );
                assert_eq!((m.min, m.max), (min, max), "{name} output {k}");
                if sigma > 0.0 {
                    assert!(
                        (m.kurtosis() - kurt).abs() <= 1e-8 * kurt,
                        "{name} output {k}: kurtosis {} vs {kurt}",
                        m.kurtosis()
                    );
                }
            }
            // Scatter there is: the comparison is not of zeros.
            assert!(stats.moments.iter().any(|m| m.sigma() > 0.0), "{name}");
        }
    }
}

/// A study's statistics from its records (two passes) and from the same
/// records streamed into moments (one pass) are one set of evaluation
/// points: the same names in the same order, re-seating and
/// interchangeability split alike, and equal n, mean, extremes and sigma
/// to rounding (the two summaries are computed independently).
#[test]
fn kept_and_streamed_statistics_give_the_same_points() {
    use kinrepro::study::{StudyRecord, Varied};
    let tolerances = vec![Varied::Friction, Varied::Tolerances];
    for (name, vary) in [
        ("01_maxwell_vgroove_steel.toml", vec![Varied::Friction]),
        ("tolerances_maxwell_vgroove.toml", tolerances),
    ] {
        let opts = StudyOptions { vary, ..mc(200) };
        let kept = crate::common::report(&plan_of(name, &opts));
        let mut stats = StreamStats::new(kept.output_names.len());
        let samples: Vec<SampleRecord> = kept.records.iter().map(StudyRecord::sample).collect();
        stats.push(&samples, &kept.output_names).unwrap();
        let mut streamed = kept.clone();
        streamed.set_moment_stats(&stats).unwrap();
        assert!(streamed.streamed && !kept.streamed);
        assert_eq!(kept.interchangeability.is_empty(), name.starts_with("01"), "{name}");
        let pairs = kept
            .points
            .iter()
            .zip(&streamed.points)
            .chain(kept.interchangeability.iter().zip(&streamed.interchangeability));
        assert_eq!(streamed.points.len(), kept.points.len());
        assert_eq!(streamed.interchangeability.len(), kept.interchangeability.len());
        for (a, b) in pairs {
            assert_eq!((&a.name, a.n), (&b.name, b.n), "{name}");
            assert_eq!(a.sigma_interval_method, b.sigma_interval_method);
            let (sa, sb) = (a.sigma.values(), b.sigma.values());
            for k in 0..6 {
                let scale = sa[k].max(f64::MIN_POSITIVE);
                let close = |x: f64, y: f64, tol: f64| (x - y).abs() <= tol * scale;
                assert!(close(sa[k], sb[k], 1e-10), "{name} {} dof {k}: sigma", a.name);
                let mean = a.mean.values()[k].abs();
                assert!(
                    (a.mean.values()[k] - b.mean.values()[k]).abs() <= 1e-12 * (scale + mean),
                    "{name} {} dof {k}: mean",
                    a.name
                );
                assert_eq!(a.min.values()[k], b.min.values()[k]);
                assert_eq!(a.max.values()[k], b.max.values()[k]);
                assert!(close(a.three_sigma.values()[k], 3.0 * sb[k], 1e-10));
                // Each route's interval brackets its sigma.
                for p in [a, b] {
                    let (lo, hi) = (p.sigma_ci90_low.unwrap(), p.sigma_ci90_high.unwrap());
                    assert!(lo.values()[k] <= p.sigma.values()[k]);
                    assert!(p.sigma.values()[k] <= hi.values()[k]);
                }
            }
        }
        assert!(kept.points.iter().any(|p| p.sigma.x_nm > 0.0), "{name}");
    }
}
