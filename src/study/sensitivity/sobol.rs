//! Variance-based sensitivity: first-order and total Sobol indices.
//!
//! Sampling (Saltelli 2002; Saltelli et al. 2010, "Variance based sensitivity analysis of model
//! output. Design and estimator for the total sensitivity index", Comput. Phys. Commun. 181,
//! 259-270): two independent N x d Monte Carlo matrices A and B, and for every input i the
//! matrix A_B^(i), A with column i taken from B; N (d + 2) evaluations. Row j of A and B
//! depends only on `(seed, j)` (ChaCha8 stream j): the design is a pure function of
//! `(d, N, seed)`.
//!
//! Estimators (Saltelli et al. 2010, Table 2, the combination they recommend), with f
//! centred on the mean of f(A) and f(B) and `V` the variance of those 2N values:
//! ```text
//! S_i  = (1/N) sum_j f(B)_j (f(A_B^(i))_j - f(A)_j) / V          (Saltelli 2010, (b))
//! ST_i = (1/2N) sum_j (f(A)_j - f(A_B^(i))_j)^2 / V              (Jansen 1999, (f))
//! ```
//! Intervals: percentile bootstrap over the N independent base rows j (every index of one
//! output recomputed from the same resample; Archer, Saltelli & Sobol 1997).

use rand_chacha::ChaCha8Rng;
use serde::{Deserialize, Serialize};

use super::super::error::{Result, StudyError};
use super::super::rng::{DOMAIN_BOOT, DOMAIN_SOBOL, below, chacha, unit_f64};
use super::super::stats::bootstrap::quantile_sorted;
use super::super::stats::{BOOTSTRAP_SEED, BootstrapConfig};

/// Default base sample size N (the Ishigami indices are then within 0.02,
/// tests/it/sobol.rs): the study option's default.
pub use super::super::options::DEFAULT_BASE_SAMPLES;

/// Bootstrap resamples of the Sobol intervals.
pub const SOBOL_RESAMPLES: usize = 500;

/// The estimators, in words, as written into the output.
pub const ESTIMATOR: &str = "Saltelli et al. 2010 sampling (A, B, A_B^i; N (d+2) runs); \
    first order: Saltelli 2010 (b); total: Jansen 1999; percentile bootstrap over base rows";

/// The Saltelli matrices, N (d + 2) rows of d coordinates in [0, 1): rows `0..N` are A,
/// `N..2N` are B, `(2 + i) N .. (3 + i) N` are A_B^(i).
pub fn saltelli_rows(dims: usize, n: usize, seed: u64) -> Result<Vec<Vec<f64>>> {
    if dims == 0 {
        return Err(StudyError::ZeroDims);
    }
    if n < 2 {
        return Err(StudyError::TooFewSamples { n });
    }
    let base: Vec<(Vec<f64>, Vec<f64>)> = (0..n)
        .map(|j| {
            let mut rng: ChaCha8Rng = chacha(seed, DOMAIN_SOBOL);
            rng.set_stream(j as u64);
            let a: Vec<f64> = (0..dims).map(|_| unit_f64(&mut rng)).collect();
            let b: Vec<f64> = (0..dims).map(|_| unit_f64(&mut rng)).collect();
            (a, b)
        })
        .collect();
    let mut rows = Vec::with_capacity(n * (dims + 2));
    rows.extend(base.iter().map(|(a, _)| a.clone()));
    rows.extend(base.iter().map(|(_, b)| b.clone()));
    for i in 0..dims {
        rows.extend(base.iter().map(|(a, b)| {
            let mut r = a.clone();
            r[i] = b[i];
            r
        }));
    }
    Ok(rows)
}

/// Sobol indices of one output, with their intervals.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SobolIndices {
    /// First-order index S_i per input.
    pub first: Vec<f64>,
    pub first_ci90_low: Vec<f64>,
    pub first_ci90_high: Vec<f64>,
    /// Total index ST_i per input.
    pub total: Vec<f64>,
    pub total_ci90_low: Vec<f64>,
    pub total_ci90_high: Vec<f64>,
    /// Variance V of the output (its unit squared, SI).
    pub variance: f64,
}

/// Point estimates (S_i, ST_i) from the centred values over the base rows `rows`.
fn estimate(y: &[f64], dims: usize, n: usize, rows: &[usize]) -> (Vec<f64>, Vec<f64>) {
    let k = rows.len() as f64;
    let (fa, fb) = (&y[..n], &y[n..2 * n]);
    let mean = rows.iter().map(|&j| fa[j] + fb[j]).sum::<f64>() / (2.0 * k);
    let var = rows.iter().map(|&j| (fa[j] - mean).powi(2) + (fb[j] - mean).powi(2)).sum::<f64>()
        / (2.0 * k - 1.0);
    let mut first = Vec::with_capacity(dims);
    let mut total = Vec::with_capacity(dims);
    for i in 0..dims {
        let fab = &y[(2 + i) * n..(3 + i) * n];
        let (mut s, mut t) = (0.0, 0.0);
        for &j in rows {
            s += (fb[j] - mean) * (fab[j] - fa[j]);
            t += (fa[j] - fab[j]).powi(2);
        }
        first.push(s / k / var);
        total.push(0.5 * t / k / var);
    }
    (first, total)
}

/// Sobol indices of the output `y`, evaluated on [`saltelli_rows`]`(dims, n, _)` in row order,
/// with percentile-bootstrap intervals (`boot`: resamples, level, seed).
pub fn sobol_indices(
    y: &[f64],
    dims: usize,
    n: usize,
    boot: &BootstrapConfig,
) -> Result<SobolIndices> {
    if y.len() != n * (dims + 2) || n < 2 || dims == 0 {
        return Err(StudyError::InvalidParameter(format!(
            "Sobol indices need N (d + 2) = {} values, got {}",
            n * (dims + 2),
            y.len()
        )));
    }
    if y.iter().any(|v| !v.is_finite()) {
        return Err(StudyError::NonFinite { what: "Sobol outputs".into() });
    }
    let all: Vec<usize> = (0..n).collect();
    let mean = y[..2 * n].iter().sum::<f64>() / (2 * n) as f64;
    let spread = y[..2 * n].iter().map(|v| (v - mean).abs()).fold(0.0, f64::max);
    if spread <= 1e-12 * mean.abs() {
        return Err(StudyError::InvalidParameter(
            "the output does not vary: no Sobol indices".into(),
        ));
    }
    let (first, total) = estimate(y, dims, n, &all);
    let variance = y[..2 * n].iter().map(|a| (a - mean).powi(2)).sum::<f64>() / (2 * n - 1) as f64;
    let mut rng = chacha(boot.seed, DOMAIN_BOOT);
    let mut reps_s = vec![Vec::with_capacity(boot.resamples); dims];
    let mut reps_t = vec![Vec::with_capacity(boot.resamples); dims];
    let mut rows = vec![0; n];
    for _ in 0..boot.resamples {
        rows.iter_mut().for_each(|r| *r = below(&mut rng, n));
        let (s, t) = estimate(y, dims, n, &rows);
        for i in 0..dims {
            reps_s[i].push(s[i]);
            reps_t[i].push(t[i]);
        }
    }
    let tail = 0.5 * (1.0 - boot.level);
    let bounds = |reps: &mut Vec<Vec<f64>>| -> (Vec<f64>, Vec<f64>) {
        reps.iter_mut()
            .map(|r| {
                r.sort_by(f64::total_cmp);
                (quantile_sorted(r, tail), quantile_sorted(r, 1.0 - tail))
            })
            .unzip()
    };
    let (first_ci90_low, first_ci90_high) = bounds(&mut reps_s);
    let (total_ci90_low, total_ci90_high) = bounds(&mut reps_t);
    Ok(SobolIndices {
        first,
        first_ci90_low,
        first_ci90_high,
        total,
        total_ci90_low,
        total_ci90_high,
        variance,
    })
}

/// The bootstrap settings of the Sobol intervals (90 %, [`SOBOL_RESAMPLES`]).
pub fn sobol_bootstrap() -> BootstrapConfig {
    BootstrapConfig { resamples: SOBOL_RESAMPLES, level: 0.90, seed: BOOTSTRAP_SEED }
}

/// Sobol indices of one output (one DOF) on the block's inputs.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SobolDof {
    /// Output name (`point/dof`).
    pub output: String,
    /// Indices per input of the block (None when `note` says why not).
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub indices: Option<SobolIndices>,
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub note: Option<String>,
}

/// First-order and total Sobol indices of a block of outputs, with how they were computed.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct SobolBlock {
    /// Sampling design and estimators ([`ESTIMATOR`]).
    pub estimator: String,
    /// Base sample size N.
    pub base_samples: usize,
    /// Seed of the Saltelli matrices (the study's seed).
    pub seed: u64,
    /// Seatings used: N (d + 2), d = all varied inputs.
    pub evaluations: usize,
    /// Level of the intervals (0.90) and bootstrap resamples.
    pub level: f64,
    pub resamples: usize,
    pub dofs: Vec<SobolDof>,
}

/// The outputs of every row of the Saltelli matrices of one study.
#[derive(Debug, Clone, PartialEq)]
pub struct SobolRun {
    pub base_samples: usize,
    pub seed: u64,
    /// Number of design inputs d.
    pub dims: usize,
    /// Names of the recorded outputs (columns of `outputs`).
    pub output_names: Vec<String>,
    /// Per row of [`saltelli_rows`], the recorded outputs (SI).
    pub outputs: Vec<Vec<f64>>,
}

impl SobolRun {
    /// The indices of the outputs `outputs` (column, name) on the inputs `inputs` (design
    /// column, name); a DOF that does not vary gets a note instead.
    pub fn block(&self, inputs: &[usize], outputs: &[(usize, String)]) -> SobolBlock {
        let boot = sobol_bootstrap();
        let (n, d) = (self.base_samples, self.dims);
        let dofs = outputs
            .iter()
            .map(|(k, name)| {
                let y: Vec<f64> = self.outputs.iter().map(|o| o[*k]).collect();
                match sobol_indices(&y, d, n, &boot) {
                    Ok(all) => SobolDof {
                        output: name.clone(),
                        indices: Some(pick(&all, inputs)),
                        note: None,
                    },
                    Err(e) => {
                        SobolDof { output: name.clone(), indices: None, note: Some(e.to_string()) }
                    }
                }
            })
            .collect();
        SobolBlock {
            estimator: ESTIMATOR.to_string(),
            base_samples: n,
            seed: self.seed,
            evaluations: n * (d + 2),
            level: boot.level,
            resamples: boot.resamples,
            dofs,
        }
    }
}

/// The indices of the inputs `cols` only.
fn pick(all: &SobolIndices, cols: &[usize]) -> SobolIndices {
    let p = |v: &[f64]| cols.iter().map(|&i| v[i]).collect();
    SobolIndices {
        first: p(&all.first),
        first_ci90_low: p(&all.first_ci90_low),
        first_ci90_high: p(&all.first_ci90_high),
        total: p(&all.total),
        total_ci90_low: p(&all.total_ci90_low),
        total_ci90_high: p(&all.total_ci90_high),
        variance: all.variance,
    }
}
