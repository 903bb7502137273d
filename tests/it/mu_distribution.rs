//! `[friction] distribution = "normal" | "lognormal" | "empirical"`: each
//! contact's mu_s drawn by the quantile of its distribution at the design
//! coordinate. Checked against the distributions' own moments (closed
//! forms, within 3 standard errors of the drawn values), the Latin
//! hypercube's stratification of each marginal (exact counts), and the
//! inputs a distribution refuses.

use crate::common::{self, kinrepro};
use kinrepro::scene::Scene;

/// Scene 01 with its `[friction]` coefficients and distribution replaced.
fn scene01(friction: &str) -> String {
    let text = std::fs::read_to_string(common::scene("01_maxwell_vgroove_steel.toml")).unwrap();
    let start = text.find("mu_static = ").unwrap();
    let line = start + text[start..].find("distribution").unwrap();
    let end = line + text[line..].find('\n').unwrap();
    format!("{}{friction}{}", &text[..start], &text[end..])
}

/// The mu_s of every contact of every sample of a `sampler` study of
/// `samples` of the scene with `friction`, and the study's JSON.
fn drawn(
    name: &str,
    friction: &str,
    sampler: &str,
    samples: &str,
) -> (Vec<f64>, serde_json::Value) {
    let path = std::env::temp_dir().join(format!("kinrepro_mu_distribution_{name}.toml"));
    std::fs::write(&path, scene01(friction)).unwrap();
    let file = path.display().to_string();
    let args = ["study", &file, "--samples", samples, "--sampler", sampler, "--format", "json"];
    let (ok, out, err) = kinrepro(&args);
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let records = v["variants"][0]["records"].as_array().unwrap();
    let mu = records
        .iter()
        .flat_map(|r| r["inputs_si"].as_array().unwrap()[..6].to_vec())
        .map(|x| x.as_f64().unwrap())
        .collect();
    (mu, v)
}

fn mean_sd(x: &[f64]) -> (f64, f64) {
    let n = x.len() as f64;
    let m = x.iter().sum::<f64>() / n;
    (m, (x.iter().map(|v| (v - m).powi(2)).sum::<f64>() / (n - 1.0)).sqrt())
}

/// Sample mean and sd of `x`, independent normal draws of mean `mu` and
/// sd `sd`, each within 3 standard errors (sd/sqrt(n) and
/// sd/sqrt(2(n - 1))).
fn normal_moments_hold(x: &[f64], mu: f64, sd: f64, what: &str) {
    let n = x.len() as f64;
    let (m, s) = mean_sd(x);
    assert!((m - mu).abs() < 3.0 * sd / n.sqrt(), "{what}: mean {m} vs {mu}");
    assert!((s - sd).abs() < 3.0 * sd / (2.0 * (n - 1.0)).sqrt(), "{what}: sd {s} vs {sd}");
}

/// A normal of mean 0.5 and sd 0.05 (its truncation to [0, 2] removes
/// 8e-24 of it): the drawn coefficients have its mean and sd.
#[test]
fn normal_draws_have_the_mean_and_sd() {
    let friction = "mu_static = 0.5\ndistribution = \"normal\"\nsd = 0.05";
    let (mu, v) = drawn("normal", friction, "mc", "400");
    assert_eq!(mu.len(), 2400);
    normal_moments_hold(&mu, 0.5, 0.05, "normal");
    let d = &v["variants"][0]["mu_distribution"];
    assert_eq!(d["kind"], "normal");
    assert_eq!(d["sd"], serde_json::json!(vec![0.05; 6]));
}

/// A lognormal of mean 0.3 and sd 0.15 of mu itself: ln mu is normal with
/// s^2 = ln(1 + sd^2/mean^2) and m = ln(mean) - s^2/2 (the lognormal's
/// moments; its truncation above 2 removes 1e-5, below the 3-SE band).
#[test]
fn lognormal_draws_are_normal_in_log_space() {
    let friction = "mu_static = 0.3\ndistribution = \"lognormal\"\nsd = 0.15";
    let (mu, _) = drawn("lognormal", friction, "mc", "400");
    assert!(mu.iter().all(|&m| m > 0.0 && m <= 2.0));
    let s2 = (1.0f64 + 0.25).ln();
    let logs: Vec<f64> = mu.iter().map(|m| m.ln()).collect();
    normal_moments_hold(&logs, 0.3f64.ln() - 0.5 * s2, s2.sqrt(), "ln mu");
}

/// Empirical values resampled by a Latin hypercube of 40 in 5 replicates:
/// each replicate stratifies every contact's coordinate into 8 strata, two
/// per value, so each of the 4 values is drawn exactly 10 times per
/// contact; and only those values are drawn.
#[test]
fn empirical_values_are_resampled_and_stratified_by_the_lhs() {
    let values = [0.3, 0.35, 0.42, 0.5];
    let friction = "mu_static = 0.4\ndistribution = \"empirical\"\nvalues = [0.42, 0.3, 0.5, 0.35]";
    let (mu, _) = drawn("empirical", friction, "lhs", "40");
    for contact in 0..6 {
        let column: Vec<f64> = mu.iter().skip(contact).step_by(6).copied().collect();
        for v in values {
            let count = column.iter().filter(|&&m| m == v).count();
            assert_eq!(count, 10, "contact {}: {v} drawn {count} times", contact + 1);
        }
    }
}

#[test]
fn distribution_keys_are_checked_at_their_line() {
    for (friction, field, says) in [
        (
            "mu_static = 0.5\ndistribution = \"normal\"\nspread = 0.05",
            "friction.spread",
            "takes sd",
        ),
        (
            "mu_static = 0.5\nspread = 0.05\nsd = 0.05\ndistribution = \"uniform\"",
            "friction.sd",
            "normal",
        ),
        (
            "mu_static = 0.5\nvalues = [0.4, 0.5]\ndistribution = \"normal\"",
            "friction.values",
            "empirical",
        ),
        ("mu_static = 0.5\nsd = -0.1\ndistribution = \"normal\"", "friction.sd", ">= 0"),
        ("mu_static = 0.0\nsd = 0.1\ndistribution = \"lognormal\"", "friction.mu_static", "> 0"),
        (
            "mu_static = 0.5\nvalues = [0.4]\ndistribution = \"empirical\"",
            "friction.values",
            "at least 2",
        ),
        (
            "mu_static = 0.5\nvalues = [0.4, 2.5]\ndistribution = \"empirical\"",
            "friction.values",
            "outside [0, 2]",
        ),
    ] {
        common::refused_at_key(&scene01(friction), field, says);
    }
    // A normal needs its sd; corners have no ends to draw; calibration
    // fits its sd, not a uniform's spread.
    let err = Scene::parse(&scene01("mu_static = 0.5\ndistribution = \"normal\""), "bad.toml")
        .unwrap_err()
        .to_string();
    assert!(err.contains("friction.sd") && err.contains("needs sd"), "{err}");
    let path = std::env::temp_dir().join("kinrepro_mu_distribution_corners.toml");
    std::fs::write(&path, scene01("mu_static = 0.5\ndistribution = \"normal\"\nsd = 0.05"))
        .unwrap();
    let file = path.display().to_string();
    let (ok, _, err) = kinrepro(&["study", &file, "--sampler", "corners"]);
    assert!(!ok && err.contains("corners") && err.contains("normal"), "{err}");
    let measured = common::worked_measurement();
    let measured = measured.to_str().unwrap();
    let (ok, _, err) = kinrepro(&["calibrate", &file, "--measured", measured, "--fit", "spread"]);
    assert!(!ok && err.contains("normal") && err.contains("`sd`"), "{err}");
}

fn pearson(a: &[f64], b: &[f64]) -> f64 {
    let ((ma, sa), (mb, sb)) = (mean_sd(a), mean_sd(b));
    let n = a.len() as f64;
    a.iter().zip(b).map(|(x, y)| (x - ma) * (y - mb)).sum::<f64>() / ((n - 1.0) * sa * sb)
}

/// Contact `k`'s coefficients (0-based) of the draws of 6 contacts.
fn contact(mu: &[f64], k: usize) -> Vec<f64> {
    mu.iter().skip(k).step_by(6).copied().collect()
}

/// Correlation 1: the two contacts of each ball of scene 01 (contacts 1-2,
/// 3-4, 5-6) draw the same coefficient; the balls stay independent.
#[test]
fn correlation_one_gives_a_ball_one_coefficient() {
    let friction = "mu_static = 0.5\nspread = 0.05\ncorrelation = 1.0\ndistribution = \"uniform\"";
    let (mu, v) = drawn("corr1", friction, "mc", "200");
    for ball in 0..3 {
        assert_eq!(contact(&mu, 2 * ball), contact(&mu, 2 * ball + 1), "ball {}", ball + 1);
    }
    assert!(pearson(&contact(&mu, 0), &contact(&mu, 2)).abs() < 3.0 / 199f64.sqrt());
    assert_eq!(v["variants"][0]["mu_correlation"], 1.0);
}

/// Correlation 0.6 of normal coefficients (truncation negligible): the
/// standard scores of one ball's two contacts correlate by 0.6 within
/// 3 standard errors ((1 - rho^2)/sqrt(n - 1)), those of two balls by 0,
/// and the second contact keeps its normal marginal (mean, sd).
#[test]
fn a_gaussian_copula_correlates_a_ball_and_keeps_the_marginals() {
    let friction = "mu_static = 0.5\nsd = 0.05\ncorrelation = 0.6\ndistribution = \"normal\"";
    let (mu, _) = drawn("corr06", friction, "mc", "400");
    let n = 400.0f64;
    let r_ball = pearson(&contact(&mu, 0), &contact(&mu, 1));
    assert!((r_ball - 0.6).abs() < 3.0 * (1.0 - 0.36) / (n - 1.0).sqrt(), "one ball: {r_ball}");
    let r_balls = pearson(&contact(&mu, 1), &contact(&mu, 2));
    assert!(r_balls.abs() < 3.0 / (n - 1.0).sqrt(), "two balls: {r_balls}");
    normal_moments_hold(&contact(&mu, 1), 0.5, 0.05, "contact 2");
    normal_moments_hold(&contact(&mu, 3), 0.5, 0.05, "contact 4");
    let text =
        scene01("mu_static = 0.5\nspread = 0.05\ncorrelation = 1.5\ndistribution = \"uniform\"");
    let line = text.lines().position(|l| l.starts_with("correlation =")).unwrap() + 1;
    let err = Scene::parse(&text, "bad.toml").unwrap_err().to_string();
    assert!(err.starts_with(&format!("bad.toml:{line}: friction.correlation: ")), "{err}");
}

/// A normal whose truncation to [0, 2] removes more than 1 % is warned
/// about by `check` and `study`, with the share removed: sd 5 about 0.5
/// loses Phi(-0.1) + 1 - Phi(0.3) = 0.4602 + 0.3821 = 84.2 %; sd 0.05
/// loses nothing worth a warning.
#[test]
fn a_heavy_truncation_is_warned_about() {
    let write = |name: &str, friction: &str| {
        let path = std::env::temp_dir().join(format!("kinrepro_mu_truncation_{name}.toml"));
        std::fs::write(&path, scene01(friction)).unwrap();
        path.display().to_string()
    };
    let heavy = write("heavy", "mu_static = 0.5\ndistribution = \"normal\"\nsd = 5");
    let (ok, out, err) = kinrepro(&["check", &heavy]);
    assert!(ok, "{err}");
    assert!(out.contains("WARNING") && out.contains("84.2 %"), "{out}");
    let (ok, _, err) = kinrepro(&["study", &heavy, "--samples", "10", "--sampler", "mc"]);
    assert!(ok && err.contains("warning") && err.contains("84.2 %"), "{err}");
    let mild = write("mild", "mu_static = 0.5\ndistribution = \"normal\"\nsd = 0.05");
    let (ok, out, _) = kinrepro(&["check", &mild]);
    assert!(ok && !out.contains("mass to the truncation"), "{out}");
}

/// The keyword a message names is the one the scene file reads.
#[test]
fn distribution_names_are_the_scene_keywords() {
    use kinrepro::scene::file::Distribution;
    for d in [
        Distribution::Uniform,
        Distribution::Normal,
        Distribution::Lognormal,
        Distribution::Empirical,
    ] {
        assert_eq!(serde_json::to_string(&d).unwrap(), format!("\"{}\"", d.name()));
    }
}
