//! Latin hypercube sampling (McKay, Beckman & Conover 1979), random within strata,
//! optimised for space filling.
//!
//! Construction: for each dimension `k` an independent random permutation `pi_k` of 0..n
//! assigns row `i` to stratum `pi_k(i)`, i.e. the interval `[pi_k(i)/n, (pi_k(i)+1)/n)`; the
//! point lies **uniformly at random within its stratum** (not at the centre), so every one of
//! the n strata of every dimension holds exactly one sample and all values lie in [0, 1).
//!
//! Optimisation: the maximin criterion (Johnson, Moore & Ylvisaker 1990) — maximise the
//! smallest pairwise Euclidean distance — searched with the enhanced stochastic evolutionary
//! algorithm (ESE, Jin, Chen & Sudjianto 2005) on the Morris & Mitchell (1995) `phi_p`
//! criterion, see [`super::ese`]. ESE only swaps two values within one column, which keeps the
//! Latin property. The returned design is never worse in minimum distance than the random
//! start returned by [`random_lhs`] for the same `(dims, n, seed)`.
//!
//! Both the start and the optimisation consume one ChaCha8 stream keyed by `(seed, DOMAIN_LHS)`,
//! so the design is a deterministic function of `(dims, n, seed)` (and of [`super::ese::EseParams`]).

use rand_chacha::ChaCha8Rng;

use super::super::error::{Result, StudyError};
use super::super::rng::{DOMAIN_LHS, DOMAIN_STARTS, chacha, shuffle, unit_f64};
use super::ese::{EseParams, optimise};

/// Largest n accepted: the optimiser keeps n x n distance matrices and its cost grows ~n^2.
pub const MAX_LHS_SAMPLES: usize = 1000;

/// The unoptimised random Latin hypercube: the optimiser's starting design.
pub fn random_lhs(dims: usize, n: usize, seed: u64) -> Result<Vec<Vec<f64>>> {
    check(dims, n)?;
    let mut rng = chacha(seed, DOMAIN_LHS);
    Ok(to_rows(&start_design(&mut rng, dims, n), dims))
}

/// The optimised Latin hypercube used by [`super::Sampler::Lhs`] (with default parameters).
pub fn optimised_lhs(
    dims: usize,
    n: usize,
    seed: u64,
    params: &EseParams,
) -> Result<Vec<Vec<f64>>> {
    optimised_lhs_in(dims, n, seed, params, DOMAIN_LHS)
}

/// The starting points of an optimisation's searches beyond the first
/// (`kinrepro optimize --starts`): the optimised Latin hypercube of `n`
/// points in `dims` dimensions from a stream of their own (`seed`, the
/// domain [`DOMAIN_STARTS`]), so they spread over the box like the study's
/// designs without sharing its draws.
pub fn start_points(dims: usize, n: usize, seed: u64) -> Result<Vec<Vec<f64>>> {
    optimised_lhs_in(dims, n, seed, &EseParams::default(), DOMAIN_STARTS)
}

fn optimised_lhs_in(
    dims: usize,
    n: usize,
    seed: u64,
    params: &EseParams,
    domain: u64,
) -> Result<Vec<Vec<f64>>> {
    check(dims, n)?;
    params.validate()?;
    let mut rng = chacha(seed, domain);
    let start = start_design(&mut rng, dims, n);
    let best = if n >= 2 && dims >= 2 {
        // With one dimension every swap only relabels rows: nothing to optimise.
        optimise(start, n, dims, &mut rng, params)
    } else {
        start
    };
    Ok(to_rows(&best, dims))
}

fn check(dims: usize, n: usize) -> Result<()> {
    if dims == 0 {
        return Err(StudyError::ZeroDims);
    }
    if n == 0 {
        return Err(StudyError::ZeroSamples);
    }
    if n > MAX_LHS_SAMPLES {
        return Err(StudyError::LhsTooLarge { n, max: MAX_LHS_SAMPLES });
    }
    Ok(())
}

/// Random LHS, row-major `n x dims`: first all permutations (column by column), then the
/// within-stratum offsets (row by row).
fn start_design(rng: &mut ChaCha8Rng, dims: usize, n: usize) -> Vec<f64> {
    let perms: Vec<Vec<usize>> = (0..dims)
        .map(|_| {
            let mut p: Vec<usize> = (0..n).collect();
            shuffle(rng, &mut p);
            p
        })
        .collect();
    let mut x = vec![0.0; n * dims];
    for i in 0..n {
        for k in 0..dims {
            x[i * dims + k] = stratum_value(perms[k][i], unit_f64(rng), n);
        }
    }
    x
}

/// Point at relative position `u` in [0, 1) of stratum `s` of `n`, guaranteed to satisfy
/// `s/n <= x < (s+1)/n` in floating point (rounding could otherwise reach the upper edge).
fn stratum_value(s: usize, u: f64, n: usize) -> f64 {
    let n = n as f64;
    let lo = s as f64 / n;
    let hi = (s as f64 + 1.0) / n;
    let x = lo + u * (hi - lo);
    if x >= hi { hi.next_down().max(lo) } else { x }
}

fn to_rows(x: &[f64], dims: usize) -> Vec<Vec<f64>> {
    x.chunks_exact(dims).map(<[f64]>::to_vec).collect()
}
