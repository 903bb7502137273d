//! `kinrepro study`: the interval method in every output, `--replicates`, corners without an
//! interval, and `--sensitivity` with Sobol indices.

use crate::common::{kinrepro, scene};

fn s1() -> String {
    scene("01_maxwell_vgroove_steel.toml").display().to_string()
}

fn json(args: &[&str]) -> serde_json::Value {
    let (ok, out, err) = kinrepro(args);
    assert!(ok, "{err}");
    serde_json::from_str(&out).unwrap()
}

#[test]
fn default_lhs_is_replicated_and_says_so() {
    let d = json(&["study", &s1(), "--format", "json"]);
    let v = &d["variants"][0];
    assert_eq!(v["design"]["replicates"], 5);
    let p = &v["points"][0];
    let method = p["sigma_interval_method"].as_str().unwrap();
    assert!(method.contains("replicated-lhs") && method.contains("5 replicates"), "{method}");
    let (lo, s, hi) = (
        p["sigma_ci90_low"]["x_nm"].as_f64().unwrap(),
        p["sigma"]["x_nm"].as_f64().unwrap(),
        p["sigma_ci90_high"]["x_nm"].as_f64().unwrap(),
    );
    assert!(lo < s && s < hi, "{lo} {s} {hi}");
    let (ok, table, _) = kinrepro(&["study", &s1()]);
    assert!(
        ok && table
            .contains("90 % interval of sigma, by a method valid for the design: replicated-lhs")
    );
}

#[test]
fn replicates_that_do_not_fit_are_one_clear_error() {
    for args in [
        vec!["--samples", "23"],
        vec!["--samples", "25", "--replicates", "4"],
        vec!["--sampler", "mc", "--replicates", "5"],
    ] {
        let mut a = vec!["study".to_string(), s1()];
        a.extend(args.iter().map(|s| s.to_string()));
        let a: Vec<&str> = a.iter().map(String::as_str).collect();
        let (ok, out, err) = kinrepro(&a);
        assert!(!ok && out.is_empty(), "{args:?}");
        assert_eq!(err.trim().lines().count(), 1, "{err}");
        assert!(err.contains("--replicates") && err.contains("01_maxwell"), "{err}");
    }
    // --replicates 1: a single LHS, printed without an interval.
    let d = json(&["study", &s1(), "--samples", "23", "--replicates", "1", "--format", "json"]);
    assert!(d["variants"][0]["points"][0]["sigma_ci90_low"].is_null());
}

#[test]
fn corners_have_no_interval() {
    let d = json(&["study", &s1(), "--sampler", "corners", "--format", "json"]);
    let p = &d["variants"][0]["points"][0];
    assert!(p["sigma_ci90_low"].is_null() && p["sigma_ci90_high"].is_null());
    assert!(p["sigma_interval_method"].as_str().unwrap().contains("deterministic"));
    let (ok, table, _) = kinrepro(&["study", &s1(), "--sampler", "corners"]);
    assert!(ok && table.contains("(no interval: none (corner design"));
    let (ok, csv, _) = kinrepro(&["study", &s1(), "--sampler", "corners", "--format", "csv"]);
    // The two interval columns (the last but one and two) are empty; the
    // method column says why.
    assert!(ok, "{csv}");
    assert!(
        csv.lines()
            .next()
            .unwrap()
            .ends_with("sigma_ci90_low,sigma_ci90_high,sigma_interval_method")
    );
    let row = csv.lines().nth(1).unwrap();
    assert!(row.ends_with(",,,\"none (corner design: deterministic, not a sample)\""), "{row}");
}

#[test]
fn sensitivity_prints_sobol_indices_with_their_base_size() {
    let (ok, table, err) = kinrepro(&[
        "study",
        &s1(),
        "--sampler",
        "mc",
        "--samples",
        "100",
        "--sensitivity",
        "--sobol-samples",
        "256",
    ]);
    assert!(ok, "{err}");
    assert!(table.contains("Sobol indices of the reseating scatter"), "{table}");
    assert!(table.contains("base sample size N = 256, 2048 seatings"), "{table}");
    let (ok, _, err) = kinrepro(&["study", &s1(), "--sensitivity", "--sobol-samples", "1"]);
    assert!(!ok && err.contains("--sobol-samples"), "{err}");
}

/// An LHS count with no divisor in 2..=5 names the nearest counts that
/// split, and those counts run with the replicates named.
#[test]
fn an_lhs_count_that_does_not_split_names_the_counts_that_do() {
    let (ok, out, err) = kinrepro(&["study", &s1(), "--samples", "7"]);
    assert!(!ok && out.is_empty(), "{out}");
    assert!(err.contains("--samples 6 (3 replicates) or --samples 8 (4 replicates)"), "{err}");
    for (n, r) in [(6, 3), (8, 4)] {
        let d = json(&["study", &s1(), "--samples", &n.to_string(), "--format", "json"]);
        assert_eq!(d["variants"][0]["design"]["replicates"], r);
    }
}

/// The study header describes the estimate of the design that ran: the
/// replicated-LHS estimate for an LHS only, divisor n-1 for Monte Carlo.
#[test]
fn the_header_describes_the_estimate_of_the_sampler_that_ran() {
    let (ok, lhs, _) = kinrepro(&["study", &s1()]);
    assert!(ok);
    let head = lhs.lines().nth(1).unwrap();
    assert!(head.contains("replicated LHS: the unbiased estimate over its 5 replicates"));
    assert!(head.contains("t on 4 df") && head.contains("narrower than Monte Carlo"));
    let (ok, mc, _) = kinrepro(&["study", &s1(), "--sampler", "mc", "--samples", "30"]);
    assert!(ok);
    let head = mc.lines().nth(1).unwrap();
    assert!(head.contains("Monte Carlo: divisor n-1"), "{head}");
    assert!(!head.contains("replicat"), "{head}");
}

/// The remaining time is shown only after 3 s and 5 % of the work, from
/// the mean rate since the start.
#[test]
fn the_remaining_time_waits_until_it_means_something() {
    use kinrepro::report::progress::remaining;
    use std::time::Duration;
    let s = Duration::from_secs;
    // The first seatings of a 5-second job: no "2h".
    assert_eq!(remaining(Duration::from_millis(400), 1, 1000), None);
    assert_eq!(remaining(s(10), 40, 1000), None);
    assert_eq!(remaining(s(2), 500, 1000), None);
    assert_eq!(remaining(s(10), 1000, 1000), None);
    // 100 of 1000 in 10 s: 90 s left at the same rate.
    let left = remaining(s(10), 100, 1000).unwrap();
    assert!((left.as_secs_f64() - 90.0).abs() < 1e-9, "{left:?}");
}
