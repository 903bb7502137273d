//! A study document read back from a file (`merge`, `report`) is checked
//! like a scene before anything uses it: friction in its physical range
//! (the scene's own bounds), the sample count consistent with the design,
//! the shard and the records, every record's inputs inside the ranges its
//! variant draws from, and every statistic finite (sigma >= 0). An error
//! names the JSON field (`variants[0].records[3].inputs_si[0]`) and the
//! reason; the caller adds the file.

use thiserror::Error;

use super::inputs::Input;
use super::record::{PointStats, StudyRecord};
use super::result::{StudyReport, VariantReport};
use crate::scene::MuDistribution;
use crate::scene::resolve::MU_MAX;

/// A field of a study document that no study could have written.
#[derive(Debug, Clone, PartialEq, Error)]
#[error("{field}: {reason}")]
pub struct DocumentError {
    /// JSON path of the field, e.g. `variants[0].samples`.
    pub field: String,
    pub reason: String,
}

fn bad(field: String, reason: String) -> DocumentError {
    DocumentError { field, reason }
}

/// Check every variant of `report` (see the module notes).
pub fn check_document(report: &StudyReport) -> Result<(), DocumentError> {
    for (i, v) in report.variants.iter().enumerate() {
        let at = format!("variants[{i}]");
        check_friction(v, &at)?;
        check_samples(v, &at)?;
        check_load_path(v, &at)?;
        for (j, r) in v.records.iter().enumerate() {
            check_record(v, r, &format!("{at}.records[{j}]"))?;
        }
        for (j, p) in v.points.iter().chain(&v.interchangeability).enumerate() {
            check_point(v, p, &format!("{at}.points[{j}] ({})", p.name))?;
        }
        check_statistics(v, &at)?;
    }
    Ok(())
}

/// The statistics of a whole variant that holds every record, recomputed
/// from the records as `merge` does (`VariantReport::finish`) and compared
/// with the document's: a hand-edited sigma (or mean, min, max, interval)
/// that its records contradict is refused, naming it. A shard, or a
/// streamed study without records, has nothing to recompute from.
fn check_statistics(v: &VariantReport, at: &str) -> Result<(), DocumentError> {
    if v.partial || v.records.is_empty() || v.records.len() != v.samples {
        return Ok(());
    }
    let mut again = v.clone();
    if let Err(e) = again.finish() {
        return Err(bad(format!("{at}.records"), format!("give no statistics: {e}")));
    }
    let (given, computed) = (
        v.points.iter().chain(&v.interchangeability),
        again.points.iter().chain(&again.interchangeability),
    );
    for (j, (p, q)) in given.zip(computed).enumerate() {
        let (a, b) = (serde_json::to_value(p), serde_json::to_value(q));
        let (Ok(a), Ok(b)) = (a, b) else { continue };
        if let Some((path, x, y)) = first_difference(&a, &b, String::new()) {
            return Err(bad(
                format!("{at}.points[{j}] ({}){path}", p.name),
                format!("{x} disagrees with the records, which give {y}"),
            ));
        }
    }
    Ok(())
}

/// The first number of `a` that differs from `b`'s by more than 1e-9
/// relative (the JSON path below `path`, the two values).
fn first_difference(
    a: &serde_json::Value,
    b: &serde_json::Value,
    path: String,
) -> Option<(String, f64, f64)> {
    use serde_json::Value;
    match (a, b) {
        (Value::Number(x), Value::Number(y)) => {
            let (x, y) = (x.as_f64()?, y.as_f64()?);
            let close = (x - y).abs() <= 1e-9 * x.abs().max(y.abs()) || x == y;
            (!close).then_some((path, x, y))
        }
        (Value::Object(m), Value::Object(n)) => m.iter().find_map(|(k, x)| {
            n.get(k).and_then(|y| first_difference(x, y, format!("{path}.{k}")))
        }),
        (Value::Array(m), Value::Array(n)) => m
            .iter()
            .zip(n)
            .enumerate()
            .find_map(|(i, (x, y))| first_difference(x, y, format!("{path}[{i}]"))),
        _ => None,
    }
}

/// The scene's `[friction]` bounds, and the fingerprint agreeing.
fn check_friction(v: &VariantReport, at: &str) -> Result<(), DocumentError> {
    let (mu, spread) = (v.mu_static, v.spread);
    if !(0.0..=MU_MAX).contains(&mu) {
        return Err(bad(format!("{at}.mu_static"), format!("{mu} is outside [0, {MU_MAX}]")));
    }
    if !(spread >= 0.0 && spread <= mu && mu + spread <= MU_MAX) {
        return Err(bad(
            format!("{at}.spread"),
            format!(
                "{spread} must lie in [0, mu_static = {mu}] with mu_static + spread <= {MU_MAX}"
            ),
        ));
    }
    if !(v.dynamic_ratio > 0.0 && v.dynamic_ratio <= 1.0) {
        let reason = format!("{} must lie in (0, 1]", v.dynamic_ratio);
        return Err(bad(format!("{at}.dynamic_ratio"), reason));
    }
    check_mu_distribution(v, at)?;
    let fp = &v.fingerprint;
    for (name, a, b) in [("mu_static", fp.mu_static, mu), ("spread", fp.spread, spread)] {
        if a.to_bits() != b.to_bits() {
            let reason = format!("{a} differs from the variant's {name} {b}");
            return Err(bad(format!("{at}.fingerprint.{name}"), reason));
        }
    }
    Ok(())
}

/// `mu_distribution` and `mu_correlation` as a scene gives them: an
/// empirical one with values in [0, MU_MAX], a normal or lognormal one
/// with a finite sd >= 0 per contact (as many as `contact_friction` has
/// pairs, where given), a correlation in [0, 1].
fn check_mu_distribution(v: &VariantReport, at: &str) -> Result<(), DocumentError> {
    let field = |name: &str| format!("{at}.mu_distribution.{name}");
    match &v.mu_distribution {
        MuDistribution::Uniform => {}
        MuDistribution::Empirical { values } => {
            if values.is_empty() {
                return Err(bad(field("values"), "is empty".into()));
            }
            if let Some(x) = values.iter().find(|x| !(0.0..=MU_MAX).contains(*x)) {
                return Err(bad(field("values"), format!("{x} is outside [0, {MU_MAX}]")));
            }
        }
        MuDistribution::Normal { sd } | MuDistribution::Lognormal { sd } => {
            if let Some(c) = v.contact_friction.as_ref().filter(|c| c.len() != sd.len()) {
                let reason =
                    format!("{} values for the {} contacts of contact_friction", sd.len(), c.len());
                return Err(bad(field("sd"), reason));
            }
            if let Some(x) = sd.iter().find(|x| !(x.is_finite() && **x >= 0.0)) {
                return Err(bad(field("sd"), format!("{x} must be finite and >= 0")));
            }
        }
    }
    if !(0.0..=1.0).contains(&v.mu_correlation) {
        let reason = format!("{} must lie in [0, 1]", v.mu_correlation);
        return Err(bad(format!("{at}.mu_correlation"), reason));
    }
    Ok(())
}

/// `samples` equal to the design's and the fingerprint's, and the records
/// (or, where none are kept, each point's sample count) consistent with it.
fn check_samples(v: &VariantReport, at: &str) -> Result<(), DocumentError> {
    let n = v.samples;
    let field = format!("{at}.samples");
    if n != v.design.n || n != v.fingerprint.samples {
        let reason = format!(
            "{n} differs from the design's {} or the fingerprint's {}",
            v.design.n, v.fingerprint.samples
        );
        return Err(bad(field, reason));
    }
    let range = v.shard.range(n).map_err(|e| bad(format!("{at}.shard"), e.to_string()))?;
    if !v.records.is_empty() && v.records.len() != range.len() {
        let reason = format!(
            "{n} samples (shard {}: {} of them), but the file holds {} records",
            v.shard,
            range.len(),
            v.records.len()
        );
        return Err(bad(field, reason));
    }
    let failed = v.seating_failures.unwrap_or(0);
    if failed > n {
        let reason = format!("{failed} failures of {n} samples");
        return Err(bad(format!("{at}.seating_failures"), reason));
    }
    if v.records.is_empty() && !v.partial {
        // Streamed or a prediction: no records, the points count the seated samples.
        if let Some(p) = v.points.iter().find(|p| p.n + failed != n) {
            let reason = format!(
                "{n}, but point `{}` has n = {} (and {failed} seatings failed)",
                p.name, p.n
            );
            return Err(bad(field, reason));
        }
    }
    Ok(())
}

/// `load_path`: at most two seatings per sample of the shard (a sample
/// with tolerances varied seats twice), a non-negative path error, and
/// the mean and maximum consistent with the total (`merge` recomputes the
/// mean from the integers, so a file must agree with them).
fn check_load_path(v: &VariantReport, at: &str) -> Result<(), DocumentError> {
    let Some(p) = v.load_path else {
        return Ok(());
    };
    let field = format!("{at}.load_path");
    let shard = v.shard.range(v.samples).map(|r| r.len()).unwrap_or(v.samples);
    let reason = if p.seatings > 2 * shard {
        format!("{} seatings for {shard} samples", p.seatings)
    } else if p.max_path_error.is_some_and(|e| !(e >= 0.0 && e.is_finite())) {
        "max_path_error must be a finite number >= 0".to_string()
    } else if (p.increments_max as u64) > p.increments_total
        || (p.seatings > 0 && p.increments_max == 0)
    {
        format!(
            "increments_max {} does not fit increments_total {}",
            p.increments_max, p.increments_total
        )
    } else if p.seatings > 0
        && p.increments_mean.to_bits() != (p.increments_total as f64 / p.seatings as f64).to_bits()
    {
        format!("increments_mean {} is not increments_total / seatings", p.increments_mean)
    } else {
        return Ok(());
    };
    Err(bad(field, reason))
}

/// One record: its index inside the shard's samples, as many inputs as the
/// variant varies, design coordinates in [0, 1], mu_s inside mu0 +- spread
/// (within rounding), every value finite.
fn check_record(v: &VariantReport, r: &StudyRecord, at: &str) -> Result<(), DocumentError> {
    if r.index >= v.samples {
        let reason = format!("{} is not below samples = {}", r.index, v.samples);
        return Err(bad(format!("{at}.index"), reason));
    }
    let k = v.inputs.len();
    for (name, len) in [("inputs_si", r.physical.len()), ("design_u", r.inputs.len())] {
        if len != k {
            let reason = format!("{len} values, the variant varies {k} inputs");
            return Err(bad(format!("{at}.{name}"), reason));
        }
    }
    if !(r.outputs.is_empty() || r.outputs.len() == v.output_names.len()) {
        let reason =
            format!("{} values, output_names has {}", r.outputs.len(), v.output_names.len());
        return Err(bad(format!("{at}.outputs_si"), reason));
    }
    if let Some(j) = r.inputs.iter().position(|u| !(0.0..=1.0).contains(u)) {
        let reason = format!("{} is outside [0, 1]", r.inputs[j]);
        return Err(bad(format!("{at}.design_u[{j}]"), reason));
    }
    for (name, values) in [("inputs_si", &r.physical), ("outputs_si", &r.outputs)] {
        if let Some(j) = values.iter().position(|x| !x.is_finite()) {
            let reason = format!("{} is not a finite number", values[j]);
            return Err(bad(format!("{at}.{name}[{j}]"), reason));
        }
    }
    for (j, (input, mu)) in v.inputs.iter().zip(&r.physical).enumerate() {
        let Input::Mu(k) = input else { continue };
        let (mu0, spread) = match v.contact_friction.as_ref().and_then(|c| c.get(*k)) {
            Some(&[m, s]) => (m, s),
            None => (v.mu_static, v.spread),
        };
        // Where the distribution reaches: mu0 +- spread, its truncation to
        // [0, MU_MAX] (normal, lognormal) or its values (empirical).
        let (lo, hi, what) = match &v.mu_distribution {
            MuDistribution::Uniform => (mu0 - spread, mu0 + spread, "mu_static +- spread"),
            MuDistribution::Empirical { values } => {
                (values[0], values[values.len() - 1], "the empirical values")
            }
            _ => (0.0, MU_MAX, "the truncation of its distribution"),
        };
        let slack = 1e-9 * hi.max(1.0);
        if !(*mu >= lo - slack && *mu <= hi + slack) {
            let reason = format!("{} = {mu} is outside {what} = [{lo}, {hi}]", input.name());
            return Err(bad(format!("{at}.inputs_si[{j}]"), reason));
        }
    }
    Ok(())
}

/// One point's statistics: n at most the samples, every value finite,
/// sigma and its interval >= 0 with low <= high.
fn check_point(v: &VariantReport, p: &PointStats, at: &str) -> Result<(), DocumentError> {
    if p.n > v.samples {
        let reason = format!("{} is above samples = {}", p.n, v.samples);
        return Err(bad(format!("{at}.n"), reason));
    }
    let all = [p.sigma, p.three_sigma, p.mean, p.min, p.max];
    if all.iter().flat_map(|d| d.values()).any(|x| !x.is_finite()) {
        let reason = "a value is not a finite number".to_string();
        return Err(bad(at.to_string(), reason));
    }
    let low = p.sigma_ci90_low.map(|d| d.values());
    let high = p.sigma_ci90_high.map(|d| d.values());
    for (d, s) in p.sigma.values().iter().enumerate() {
        let (l, h) = (low.map_or(0.0, |x| x[d]), high.map_or(f64::INFINITY, |x| x[d]));
        if !(*s >= 0.0 && l >= 0.0 && l <= h) {
            let reason = format!(
                "sigma {s} with 90 % interval [{l}, {h}]: a sigma is >= 0 and its interval ordered"
            );
            return Err(bad(format!("{at}.sigma[{d}]"), reason));
        }
    }
    Ok(())
}
