//! Sobol indices against closed forms: the Ishigami function (Ishigami & Homma 1990; indices
//! from Saltelli et al., "Global Sensitivity Analysis: The Primer", 2008, §3.6 / Sobol' &
//! Levitan 1999), implemented here independently of the estimator.

use crate::common;

use std::f64::consts::PI;

use kinrepro::study::sensitivity::sobol::{
    DEFAULT_BASE_SAMPLES, saltelli_rows, sobol_bootstrap, sobol_indices,
};
use kinrepro::study::sensitivity::sobol_run::run_sobol;
use kinrepro::study::summary::attach_sobol;
use kinrepro::study::{Sampler, StudyOptions, Varied};

const A: f64 = 7.0;
const B: f64 = 0.1;

/// f(x) = sin x1 + a sin^2 x2 + b x3^4 sin x1, x_i uniform in [-pi, pi].
fn ishigami(u: &[f64]) -> f64 {
    let x: Vec<f64> = u.iter().map(|u| -PI + 2.0 * PI * u).collect();
    x[0].sin() + A * x[1].sin().powi(2) + B * x[2].powi(4) * x[0].sin()
}

/// Closed-form (first-order, total) indices.
fn ishigami_exact() -> ([f64; 3], [f64; 3]) {
    let pi4 = PI.powi(4);
    let pi8 = PI.powi(8);
    let v1 = 0.5 * (1.0 + B * pi4 / 5.0).powi(2);
    let v2 = A * A / 8.0;
    let v13 = B * B * pi8 * (1.0 / 18.0 - 1.0 / 50.0);
    let v = v1 + v2 + v13;
    // Check of the decomposition: V = a^2/8 + b pi^4/5 + b^2 pi^8/18 + 1/2.
    let v_direct = A * A / 8.0 + B * pi4 / 5.0 + B * B * pi8 / 18.0 + 0.5;
    assert!((v - v_direct).abs() < 1e-12 * v);
    ([v1 / v, v2 / v, 0.0], [(v1 + v13) / v, v2 / v, v13 / v])
}

#[test]
fn ishigami_indices_within_0_02_at_the_default_size() {
    let (s_exact, t_exact) = ishigami_exact();
    let n = DEFAULT_BASE_SAMPLES;
    for seed in 1..=5 {
        let rows = saltelli_rows(3, n, seed).unwrap();
        let y: Vec<f64> = rows.iter().map(|r| ishigami(r)).collect();
        let s = sobol_indices(&y, 3, n, &sobol_bootstrap()).unwrap();
        for i in 0..3 {
            assert!(
                (s.first[i] - s_exact[i]).abs() < 0.02,
                "seed {seed}: S_{} = {} vs {}",
                i + 1,
                s.first[i],
                s_exact[i]
            );
            assert!(
                (s.total[i] - t_exact[i]).abs() < 0.02,
                "seed {seed}: ST_{} = {} vs {}",
                i + 1,
                s.total[i],
                t_exact[i]
            );
        }
    }
}

#[test]
fn ishigami_interval_coverage() {
    // 90 % percentile-bootstrap intervals at N = 1024 over 40 seeds: each of the six indices
    // is covered in 75-100 % of them (binomial 5-95 % range for p = 0.9 and 40 trials is 33-39).
    let (s_exact, t_exact) = ishigami_exact();
    let n = 1024;
    let seeds = 40;
    let mut covered = [0usize; 6];
    for seed in 0..seeds {
        let rows = saltelli_rows(3, n, 100 + seed).unwrap();
        let y: Vec<f64> = rows.iter().map(|r| ishigami(r)).collect();
        let s = sobol_indices(&y, 3, n, &sobol_bootstrap()).unwrap();
        for i in 0..3 {
            covered[i] += usize::from(
                s.first_ci90_low[i] <= s_exact[i] && s_exact[i] <= s.first_ci90_high[i],
            );
            covered[3 + i] += usize::from(
                s.total_ci90_low[i] <= t_exact[i] && t_exact[i] <= s.total_ci90_high[i],
            );
        }
    }
    for (k, c) in covered.iter().enumerate() {
        assert!(*c >= 30, "index {k}: covered {c} of {seeds}");
    }
}

#[test]
fn saltelli_rows_layout() {
    let (d, n) = (4, 16);
    let rows = saltelli_rows(d, n, 9).unwrap();
    assert_eq!(rows.len(), n * (d + 2));
    for i in 0..d {
        for j in 0..n {
            let ab = &rows[(2 + i) * n + j];
            for k in 0..d {
                let src = if k == i { &rows[n + j] } else { &rows[j] };
                assert_eq!(ab[k].to_bits(), src[k].to_bits());
            }
        }
    }
    // A pure function of (d, N, seed); a different seed gives a different design.
    assert_eq!(rows, saltelli_rows(d, n, 9).unwrap());
    assert_ne!(rows, saltelli_rows(d, n, 10).unwrap());
    assert!(sobol_indices(&[1.0; 6 * 16], d, n, &sobol_bootstrap()).is_err());
}

#[test]
fn scene_01_indices_are_consistent_and_match_the_linear_shares() {
    // Scene 01 (six friction coefficients): the first-order indices of x sum to at most 1 and
    // every total index is at least its first-order index, both within the 90 % intervals; the
    // response is near-linear (R^2 > 0.99), so the first-order indices must also equal the
    // regression shares of an independent 2000-sample Monte Carlo study.
    let c = common::load("01_maxwell_vgroove_steel.toml");
    let opts = StudyOptions {
        sampler: Some(Sampler::MonteCarlo),
        samples: Some(2000),
        seed: Some(11),
        sensitivity: true,
        sobol_samples: Some(2048),
        ..Default::default()
    };
    let plan = common::plan(vec![c], &opts);
    let mut v = common::report(&plan);
    let run = run_sobol(&plan.settings, &plan.variants[0], 2048, &|| {}).unwrap();
    attach_sobol(&mut v, &run);
    let block = &v.sensitivity.as_ref().unwrap()[0];
    let sob = block.sobol.as_ref().unwrap();
    assert_eq!(sob.base_samples, 2048);
    assert_eq!(sob.evaluations, 2048 * 8);
    assert_eq!(block.inputs.len(), 6);
    for (k, d) in sob.dofs.iter().enumerate() {
        let x = d.indices.as_ref().unwrap();
        let lows: f64 = x.first_ci90_low.iter().sum();
        assert!(lows <= 1.0, "{}: sum of first-order lower bounds {lows}", d.output);
        for i in 0..6 {
            assert!(
                x.total_ci90_high[i] >= x.first_ci90_low[i],
                "{} input {i}: ST {:?} < S {:?}",
                d.output,
                (x.total_ci90_low[i], x.total_ci90_high[i]),
                (x.first_ci90_low[i], x.first_ci90_high[i])
            );
            assert!(x.first_ci90_low[i] <= x.first[i] && x.first[i] <= x.first_ci90_high[i]);
        }
        let src = &block.dofs[k];
        assert!(src.r_squared.unwrap() > 0.99);
        for i in 0..6 {
            assert!(
                (x.first[i] - src.share[i]).abs() < 0.05,
                "{} input {i}: S {} vs SRC share {}",
                d.output,
                x.first[i],
                src.share[i]
            );
        }
    }
    // x is driven by the two flanks of the V-groove on the x axis (contacts 1, 2).
    let x = sob.dofs[0].indices.as_ref().unwrap();
    assert!(x.first[0] > 0.25 && x.first[1] > 0.25, "{:?}", x.first);
    // The JSON carries the indices under the variant's sensitivity, SRC fields kept.
    let json = serde_json::to_value(&v).unwrap();
    let b = &json["sensitivity"][0];
    assert!(b["dofs"][0]["share"].is_array());
    assert_eq!(b["sobol"]["base_samples"], 2048);
    assert!(b["sobol"]["dofs"][0]["indices"]["total_ci90_high"].is_array());
}

#[test]
fn any_vary_set_gets_indices_per_input_deterministically() {
    // Friction and preload varied: the Sobol block covers all ten inputs; the preload offset
    // drives the tilts (as the SRC shares say), and the matrices are a pure function of the seed.
    let c = common::load("tolerances_maxwell_vgroove.toml");
    let opts = StudyOptions {
        sampler: Some(Sampler::MonteCarlo),
        samples: Some(100),
        sensitivity: true,
        sobol_samples: Some(256),
        vary: vec![Varied::Friction, Varied::Preload],
        ..Default::default()
    };
    let plan = common::plan(vec![c], &opts);
    let (s, c) = (&plan.settings, &plan.variants[0]);
    let mut v = common::report(&plan);
    let run = run_sobol(s, c, 256, &|| {}).unwrap();
    assert_eq!(run, run_sobol(s, c, 256, &|| {}).unwrap());
    attach_sobol(&mut v, &run);
    let block = &v.sensitivity.as_ref().unwrap()[0];
    let sob = block.sobol.as_ref().unwrap();
    assert_eq!(block.inputs.len(), 10);
    assert_eq!(sob.evaluations, 256 * 12);
    let phi_y = sob.dofs[4].indices.as_ref().unwrap();
    let px = block.inputs.iter().position(|n| n == "preload_x_m").unwrap();
    assert_eq!(phi_y.first.len(), 10);
    assert!(phi_y.total[px] > 0.7, "{:?}", phi_y.total);
}
