//! Tests of the samplers against independently computed properties.

use std::collections::HashSet;

use kinrepro::study::sampling::corners::corner_count;
use kinrepro::study::sampling::lhs::{optimised_lhs, random_lhs};
use kinrepro::study::{
    DesignSpec, Sampler, Shard, StudyError, design, sample_range, sampling::ese::EseParams,
    shard_range,
};
use proptest::prelude::*;

/// Stratum of `x` among n: the number of interior boundaries j/n (j = 1..n-1) not above x.
fn stratum(x: f64, n: usize) -> usize {
    (1..n).filter(|&j| x >= j as f64 / n as f64).count()
}

fn min_distance(rows: &[Vec<f64>]) -> f64 {
    let mut m = f64::INFINITY;
    for i in 0..rows.len() {
        for j in i + 1..rows.len() {
            let d2: f64 = rows[i].iter().zip(&rows[j]).map(|(a, b)| (a - b) * (a - b)).sum();
            m = m.min(d2.sqrt());
        }
    }
    m
}

fn assert_latin(rows: &[Vec<f64>], dims: usize, n: usize) {
    assert_eq!(rows.len(), n);
    for k in 0..dims {
        let mut strata: Vec<usize> = rows
            .iter()
            .map(|r| {
                assert_eq!(r.len(), dims);
                assert!((0.0..1.0).contains(&r[k]), "value {} outside [0,1)", r[k]);
                stratum(r[k], n)
            })
            .collect();
        strata.sort_unstable();
        assert_eq!(strata, (0..n).collect::<Vec<_>>(), "column {k} is not Latin");
    }
}

fn bits(rows: &[Vec<f64>]) -> Vec<Vec<u64>> {
    rows.iter().map(|r| r.iter().map(|v| v.to_bits()).collect()).collect()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(64))]

    /// Every stratum of every dimension holds exactly one sample (start and optimised design),
    /// and optimisation never lowers the minimum pairwise distance.
    #[test]
    fn lhs_is_latin_and_not_worse_than_start(dims in 1usize..8, n in 2usize..60, seed in any::<u64>()) {
        let start = random_lhs(dims, n, seed).unwrap();
        let opt = design(Sampler::Lhs, dims, n, seed).unwrap();
        assert_latin(&start, dims, n);
        assert_latin(&opt, dims, n);
        prop_assert!(min_distance(&opt) >= min_distance(&start),
            "optimised {} < start {}", min_distance(&opt), min_distance(&start));
    }
}

#[test]
fn lhs_optimisation_improves_maximin_for_d6_n25() {
    for seed in 0..8 {
        let start = random_lhs(6, 25, seed).unwrap();
        let opt = design(Sampler::Lhs, 6, 25, seed).unwrap();
        assert!(
            min_distance(&opt) > min_distance(&start),
            "seed {seed}: {} vs {}",
            min_distance(&opt),
            min_distance(&start)
        );
    }
}

#[test]
fn lhs_without_outer_iterations_is_the_start() {
    let params = EseParams { outer_iterations: 0, ..EseParams::default() };
    let a = optimised_lhs(4, 10, 3, &params).unwrap();
    assert_eq!(bits(&a), bits(&random_lhs(4, 10, 3).unwrap()));
}

#[test]
fn lhs_one_sample_and_one_dimension() {
    assert_latin(&design(Sampler::Lhs, 3, 1, 9).unwrap(), 3, 1);
    assert_latin(&design(Sampler::Lhs, 1, 17, 9).unwrap(), 1, 17);
}

#[test]
fn lhs_range_is_slice_of_design() {
    let full = design(Sampler::Lhs, 5, 30, 11).unwrap();
    let part = sample_range(Sampler::Lhs, 5, 30, 11, 7..19).unwrap();
    assert_eq!(bits(&part), bits(&full[7..19]));
}

#[test]
fn mc_ranges_concatenate_to_the_design() {
    let (dims, n, seed) = (6, 103, 42);
    let full = design(Sampler::MonteCarlo, dims, n, seed).unwrap();
    assert_eq!(full.len(), n);
    for r in &full {
        assert_eq!(r.len(), dims);
        assert!(r.iter().all(|v| (0.0..1.0).contains(v)));
    }
    let cuts = [0, 1, 17, 17, 50, 99, 103];
    let mut joined = Vec::new();
    for w in cuts.windows(2) {
        joined.extend(sample_range(Sampler::MonteCarlo, dims, n, seed, w[0]..w[1]).unwrap());
    }
    assert_eq!(bits(&joined), bits(&full));
    // Row i depends only on (seed, i): a longer design starts with the same rows.
    let longer = design(Sampler::MonteCarlo, dims, 2 * n, seed).unwrap();
    assert_eq!(bits(&longer[..n]), bits(&full));
}

#[test]
fn mc_is_roughly_uniform() {
    // Independent sanity check: mean of 20 000 uniforms is 0.5 +- 4 standard errors.
    let rows = design(Sampler::MonteCarlo, 2, 10_000, 5).unwrap();
    let mean = rows.iter().flatten().sum::<f64>() / 20_000.0;
    assert!((mean - 0.5).abs() < 4.0 * (1.0f64 / 12.0 / 20_000.0).sqrt());
}

#[test]
fn corners_are_all_distinct_extremes_in_bit_order() {
    for dims in 1..=10 {
        let n = 1usize << dims;
        let rows = design(Sampler::Corners, dims, n, 0).unwrap();
        assert_eq!(rows.len(), n);
        let set: HashSet<Vec<u64>> = bits(&rows).into_iter().collect();
        assert_eq!(set.len(), n);
        for (r, row) in rows.iter().enumerate() {
            for (k, &v) in row.iter().enumerate() {
                assert!(v == 0.0 || v == 1.0);
                assert_eq!(v == 1.0, (r >> k) & 1 == 1);
            }
        }
    }
    assert_eq!(
        design(Sampler::Corners, 2, 4, 0).unwrap(),
        vec![vec![0.0, 0.0], vec![1.0, 0.0], vec![0.0, 1.0], vec![1.0, 1.0]]
    );
}

#[test]
fn corners_reject_other_n_and_too_many_dims() {
    assert!(matches!(
        design(Sampler::Corners, 3, 25, 0),
        Err(StudyError::CornerCount { expected: 8, got: 25, .. })
    ));
    assert!(corner_count(17).is_err());
    assert_eq!(DesignSpec::new(Sampler::Corners, 6, None, 1).unwrap().n, 64);
    assert!(DesignSpec::new(Sampler::Lhs, 6, None, 1).is_err());
}

#[test]
fn same_seed_same_bits_different_seed_different_design() {
    for s in [Sampler::Lhs, Sampler::MonteCarlo] {
        let a = design(s, 6, 25, 1234).unwrap();
        let b = design(s, 6, 25, 1234).unwrap();
        let c = design(s, 6, 25, 1235).unwrap();
        assert_eq!(bits(&a), bits(&b), "{s}");
        assert_ne!(bits(&a), bits(&c), "{s}");
    }
}

#[test]
fn bad_inputs_are_errors() {
    for s in [Sampler::Lhs, Sampler::MonteCarlo, Sampler::Corners] {
        assert!(matches!(design(s, 0, 4, 1), Err(StudyError::ZeroDims)));
        assert!(sample_range(s, 2, 4, 1, 3..5).is_err());
        #[allow(clippy::reversed_empty_ranges)]
        let backwards = 3..2;
        assert!(sample_range(s, 2, 4, 1, backwards).is_err());
    }
    assert!(matches!(design(Sampler::Lhs, 2, 0, 1), Err(StudyError::ZeroSamples)));
    assert!(matches!(design(Sampler::MonteCarlo, 2, 0, 1), Err(StudyError::ZeroSamples)));
    assert!(matches!(design(Sampler::Lhs, 2, 5000, 1), Err(StudyError::LhsTooLarge { .. })));
    assert!(sample_range(Sampler::MonteCarlo, 2, 4, 1, 4..4).unwrap().is_empty());
}

#[test]
fn shard_ranges_cover_balanced_in_order() {
    for n in 0..40 {
        for count in 1..12 {
            let mut next = 0;
            for i in 1..=count {
                let r = shard_range(n, i, count).unwrap();
                assert_eq!(r.start, next);
                let len = r.len();
                assert!(len == n / count || len == n / count + 1);
                next = r.end;
            }
            assert_eq!(next, n);
        }
    }
    assert_eq!(shard_range(25, 1, 4).unwrap(), 0..7);
    assert_eq!(shard_range(25, 4, 4).unwrap(), 19..25);
    assert!(shard_range(25, 0, 4).is_err());
    assert!(shard_range(25, 5, 4).is_err());
    assert!(shard_range(25, 1, 0).is_err());
}

#[test]
fn shard_and_sampler_parse() {
    let s: Shard = "3/8".parse().unwrap();
    assert_eq!((s.index, s.count), (3, 8));
    assert_eq!(s.to_string(), "3/8");
    for bad in ["0/8", "9/8", "3", "a/b", "3/0", ""] {
        assert!(bad.parse::<Shard>().is_err(), "{bad}");
    }
    assert_eq!("lhs".parse::<Sampler>().unwrap(), Sampler::Lhs);
    assert_eq!("mc".parse::<Sampler>().unwrap(), Sampler::MonteCarlo);
    // Spelt exactly, as every keyword of a scene.
    assert!("MC".parse::<Sampler>().is_err());
    assert_eq!("corners".parse::<Sampler>().unwrap(), Sampler::Corners);
    assert!("sobol".parse::<Sampler>().is_err());
}

#[test]
fn sampler_serde_names() {
    for (s, name) in [
        (Sampler::Lhs, "\"lhs\""),
        (Sampler::MonteCarlo, "\"mc\""),
        (Sampler::Corners, "\"corners\""),
    ] {
        assert_eq!(serde_json::to_string(&s).unwrap(), name);
        assert_eq!(serde_json::from_str::<Sampler>(name).unwrap(), s);
    }
}
