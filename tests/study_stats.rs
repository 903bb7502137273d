//! Tests of the statistics, bootstrap, convergence and shard merging against hand values.

use approx::assert_relative_eq;
use kinrepro::study::stats::{
    BootstrapConfig, MergedStudy, SampleRecord, ShardFile, bootstrap_sigma, mean_sigma, merge,
    sigma_convergence, summarize, summarize_outputs, verify_inputs,
};
use kinrepro::study::{DesignSpec, Sampler, Shard, StudyError};

#[test]
fn summary_of_one_to_five() {
    let s = summarize(&[1.0, 2.0, 3.0, 4.0, 5.0], &BootstrapConfig::default()).unwrap();
    assert_eq!(s.n, 5);
    assert_eq!(s.mean, 3.0);
    assert_eq!((s.min, s.max), (1.0, 5.0));
    assert_relative_eq!(s.sigma, 2.5f64.sqrt(), max_relative = 1e-15);
    assert_relative_eq!(s.three_sigma, 3.0 * 2.5f64.sqrt(), max_relative = 1e-15);
    assert_relative_eq!(
        s.lower_3sigma,
        3.0 - 3.0 * 2.5f64.sqrt(),
        max_relative = 1e-15
    );
    assert_relative_eq!(
        s.upper_3sigma,
        3.0 + 3.0 * 2.5f64.sqrt(),
        max_relative = 1e-15
    );
}

#[test]
fn sigma_hand_values_and_large_offset() {
    // Sum of squared deviations 32, n - 1 = 7.
    let (m, s) = mean_sigma(&[2.0, 4.0, 4.0, 4.0, 5.0, 5.0, 7.0, 9.0]).unwrap();
    assert_eq!(m, 5.0);
    assert_relative_eq!(s, (32.0f64 / 7.0).sqrt(), max_relative = 1e-15);
    // Nanometre scatter on a large offset: the naive sum-of-squares formula loses it all.
    let x: Vec<f64> = (1..=5).map(|k| 1e9 + f64::from(k)).collect();
    let (m, s) = mean_sigma(&x).unwrap();
    assert_eq!(m, 1e9 + 3.0);
    assert_relative_eq!(s, 2.5f64.sqrt(), max_relative = 1e-12);
    // Constant data: sigma exactly 0.
    assert_eq!(mean_sigma(&[0.1; 7]).unwrap().1, 0.0);
}

#[test]
fn too_few_or_non_finite_samples_are_errors() {
    let b = BootstrapConfig::default();
    assert!(matches!(
        summarize(&[], &b),
        Err(StudyError::TooFewSamples { n: 0 })
    ));
    assert!(matches!(
        summarize(&[1.0], &b),
        Err(StudyError::TooFewSamples { n: 1 })
    ));
    assert!(matches!(
        summarize(&[1.0, f64::NAN], &b),
        Err(StudyError::NonFinite { .. })
    ));
    assert!(sigma_convergence(&[1.0]).is_err());
    assert!(
        bootstrap_sigma(
            &[1.0, 2.0],
            &BootstrapConfig {
                resamples: 1,
                ..b.clone()
            }
        )
        .is_err()
    );
    assert!(bootstrap_sigma(&[1.0, 2.0], &BootstrapConfig { level: 1.0, ..b }).is_err());
}

#[test]
fn bootstrap_contains_sigma_and_is_deterministic() {
    let x: Vec<f64> = (0..25)
        .map(|i| ((i * 37 % 25) as f64 * 0.7).sin() * 3.0)
        .collect();
    let b = BootstrapConfig::default();
    let (_, s) = mean_sigma(&x).unwrap();
    let i1 = bootstrap_sigma(&x, &b).unwrap();
    let i2 = bootstrap_sigma(&x, &b).unwrap();
    assert_eq!(i1, i2);
    assert!(i1.lower < s && s < i1.upper, "{i1:?} vs {s}");
    assert_eq!(i1.level, 0.9);
    let other = bootstrap_sigma(&x, &BootstrapConfig { seed: 1, ..b }).unwrap();
    assert_ne!(i1, other);
}

#[test]
fn bootstrap_of_two_points_matches_exact_distribution() {
    // Resampling {0, 1} twice gives sd 0 (prob 1/2) or 1/sqrt(2) (prob 1/2): the 5 % and 95 %
    // quantiles of the bootstrap distribution are exactly 0 and 1/sqrt(2).
    let i = bootstrap_sigma(&[0.0, 1.0], &BootstrapConfig::default()).unwrap();
    assert_eq!(i.lower, 0.0);
    assert_relative_eq!(i.upper, 0.5f64.sqrt(), max_relative = 1e-15);
    let c = bootstrap_sigma(&[4.0; 6], &BootstrapConfig::default()).unwrap();
    assert_eq!((c.lower, c.upper), (0.0, 0.0));
}

#[test]
fn convergence_matches_prefix_sigma() {
    let x: Vec<f64> = (0..40).map(|i| (f64::from(i) * 1.3).cos() + 1e3).collect();
    let c = sigma_convergence(&x).unwrap();
    assert_eq!(c.len(), 39);
    for (p, k) in c.iter().zip(2..) {
        assert_eq!(p.k, k);
        let (_, s) = mean_sigma(&x[..k]).unwrap();
        assert_relative_eq!(p.sigma, s, max_relative = 1e-9);
    }
    assert_relative_eq!(
        c[0].sigma,
        (x[1] - x[0]).abs() / 2f64.sqrt(),
        max_relative = 1e-9
    );
}

/// Stand-in for the coupling model: 5 outputs depending on the 6 inputs.
fn model(u: &[f64]) -> Vec<f64> {
    let s: f64 = u.iter().sum();
    vec![
        3.0 * (u[0] - u[1]),
        2.0 * u[2] * u[3] - 0.5,
        s.sin(),
        1e3 * (u[4] - 0.5),
        (u[5] * 7.0).cos() * 40.0,
    ]
}

fn names() -> Vec<String> {
    ["x", "y", "z", "phi_x", "phi_y"].map(String::from).to_vec()
}

fn run_shard(spec: DesignSpec, shard: Shard) -> ShardFile {
    let range = shard.range(spec.n).unwrap();
    let rows = spec.range(range.clone()).unwrap();
    ShardFile {
        design: spec,
        shard,
        output_names: names(),
        records: range
            .zip(rows)
            .map(|(index, inputs)| SampleRecord {
                index,
                outputs: model(&inputs),
                inputs,
            })
            .collect(),
    }
}

fn shards(spec: DesignSpec, count: usize) -> Vec<ShardFile> {
    (1..=count)
        .map(|i| run_shard(spec, Shard::new(i, count).unwrap()))
        .collect()
}

#[test]
fn merge_of_four_shards_equals_one_run_bit_for_bit() {
    for sampler in [Sampler::Lhs, Sampler::MonteCarlo] {
        let spec = DesignSpec::new(sampler, 6, Some(25), 77).unwrap();
        let single = merge([run_shard(spec, Shard::whole())]).unwrap();
        let mut parts = shards(spec, 4);
        parts.reverse();
        // Through JSON, as the CLI would write and read the parts.
        let parts: Vec<ShardFile> = parts
            .iter()
            .map(|p| serde_json::from_str(&serde_json::to_string(p).unwrap()).unwrap())
            .collect();
        let merged = merge(parts).unwrap();
        assert_eq!(merged, single);
        let b = BootstrapConfig::default();
        let s1 = summarize_outputs(&single.records, &b).unwrap();
        let s2 = summarize_outputs(&merged.records, &b).unwrap();
        assert_eq!(s1.len(), 5);
        for (a, c) in s1.iter().zip(&s2) {
            assert_eq!(a.sigma.to_bits(), c.sigma.to_bits());
            assert_eq!(a, c);
        }
        verify_inputs(&merged).unwrap();
    }
}

#[test]
fn merge_rejects_duplicates_gaps_and_mismatches() {
    let spec = DesignSpec::new(Sampler::MonteCarlo, 6, Some(25), 5).unwrap();
    let parts = shards(spec, 4);

    let mut dup = parts.clone();
    dup.push(parts[2].clone());
    assert!(matches!(merge(dup), Err(StudyError::DuplicateSample(_))));

    let gap: Vec<ShardFile> = parts
        .iter()
        .filter(|p| p.shard.index != 2)
        .cloned()
        .collect();
    assert!(matches!(
        merge(gap),
        Err(StudyError::MissingSamples { first: 7, count: 6 })
    ));

    let mut truncated = parts.clone();
    truncated[3].records.pop();
    assert!(matches!(
        merge(truncated),
        Err(StudyError::MissingSamples {
            first: 24,
            count: 1
        })
    ));

    let other = DesignSpec::new(Sampler::MonteCarlo, 6, Some(25), 6).unwrap();
    let mut mixed = parts.clone();
    mixed[1] = run_shard(other, Shard::new(2, 4).unwrap());
    assert!(matches!(merge(mixed), Err(StudyError::DesignMismatch(_))));

    let mut renamed = parts.clone();
    renamed[0].output_names[0] = "dx".into();
    assert!(matches!(merge(renamed), Err(StudyError::DesignMismatch(_))));

    let mut stray = parts.clone();
    stray[0].records[0].index = 20; // belongs to shard 4
    assert!(matches!(
        merge(stray),
        Err(StudyError::IndexOutOfRange { .. })
    ));

    let mut short = parts.clone();
    short[1].records[0].outputs.pop();
    assert!(matches!(merge(short), Err(StudyError::RecordShape { .. })));

    assert!(matches!(merge(Vec::new()), Err(StudyError::EmptyMerge)));
}

#[test]
fn verify_inputs_detects_foreign_rows() {
    let spec = DesignSpec::new(Sampler::Lhs, 6, Some(10), 1).unwrap();
    let mut study: MergedStudy = merge(shards(spec, 2)).unwrap();
    verify_inputs(&study).unwrap();
    study.records[4].inputs[1] += 1e-12;
    assert!(matches!(
        verify_inputs(&study),
        Err(StudyError::InputsMismatch(4))
    ));
}
