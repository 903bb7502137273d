//! Sampling designs over the unit hypercube [0, 1]^d.
//!
//! The caller maps each coordinate `u` to its physical range, e.g. a friction coefficient
//! `mu = mu0 + spread * (2 u - 1)` (uniform in mu0 +- spread). Three designs:
//!
//! * [`Sampler::Lhs`]: Latin hypercube, random within strata, optimised for space filling
//!   with the enhanced stochastic evolutionary algorithm — see [`lhs`] and [`ese`].
//! * [`Sampler::MonteCarlo`]: independent uniform points; row `i` depends only on
//!   `(seed, i)` — see [`monte_carlo`].
//! * [`Sampler::Corners`]: the 2^d full-factorial extremes — see [`corners`].
//!
//! Every design is a pure function of `(sampler, dims, n, seed, replicates)`, captured by
//! [`DesignSpec`], which shard files carry so that [`super::stats::merge`] can check that they
//! belong together.
//!
//! Replicated LHS ([`DesignSpec::replicates`] = r > 1): the n rows are r independent optimised
//! Latin hypercubes of m = n / r points each, replicate j being rows `j m .. (j+1) m`, drawn
//! with the seed [`replicate_seed`]`(seed, j)`. The spread between replicates gives a valid
//! sampling interval of sigma ([`super::stats::interval`]); a single LHS has none (resampling
//! its rows breaks the stratification).

pub mod corners;
pub mod ese;
pub mod lhs;
pub mod monte_carlo;
pub mod shard;

use std::ops::Range;

use serde::{Deserialize, Serialize};

use super::error::{Result, StudyError};
use super::rng::{DOMAIN_REPLICATE, splitmix64};
use crate::param::Param;
pub use crate::scene::Sampler;

/// Everything a design depends on. Shard files carry it to be validated on merge.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct DesignSpec {
    pub sampler: Sampler,
    pub dims: usize,
    pub n: usize,
    pub seed: u64,
    /// Number of independent LHS replicates the n rows consist of (1: a single design; always 1
    /// for Monte Carlo and corners). Files without the field are single designs.
    #[serde(default = "one")]
    pub replicates: usize,
}

/// The serde default of a replicate count.
pub(crate) fn one() -> usize {
    1
}

/// Default number of LHS replicates: 5 (the largest divisor of n in 2..=5 leaving at least 2
/// points per replicate, when 5 does not divide n).
pub const DEFAULT_LHS_REPLICATES: usize = 5;

/// The default replicate count of an LHS of `n` points, if n has a divisor in 2..=5 that leaves
/// at least 2 points per replicate.
pub fn default_replicates(n: usize) -> Option<usize> {
    (2..=DEFAULT_LHS_REPLICATES).rev().find(|&r| n.is_multiple_of(r) && n / r >= 2)
}

/// Seed of LHS replicate `j` of a design with seed `seed` (SplitMix64 of both; replicate 0 of
/// a single design uses `seed` itself, see [`DesignSpec::rows`]).
pub fn replicate_seed(seed: u64, j: usize) -> u64 {
    let mut state = seed ^ DOMAIN_REPLICATE.wrapping_add(j as u64);
    splitmix64(&mut state)
}

impl DesignSpec {
    /// Validated spec. For corners, `n = None` means 2^dims; for LHS and MC `n` is required.
    pub fn new(sampler: Sampler, dims: usize, n: Option<usize>, seed: u64) -> Result<Self> {
        let n = match (sampler, n) {
            (Sampler::Corners, None) => corners::corner_count(dims)?,
            (_, Some(n)) => n,
            (_, None) => return Err(StudyError::ZeroSamples),
        };
        validate(sampler, dims, n)?;
        Ok(DesignSpec { sampler, dims, n, seed, replicates: 1 })
    }

    /// The same design split into `replicates` independent LHS (LHS only; `replicates` must
    /// divide n and leave at least 2 points each; 1 is a single design).
    pub fn with_replicates(self, replicates: usize) -> Result<Self> {
        let spec = DesignSpec { replicates, ..self };
        spec.check_replicates()?;
        Ok(spec)
    }

    fn check_replicates(&self) -> Result<()> {
        let (r, n) = (self.replicates, self.n);
        let ok = match self.sampler {
            Sampler::Lhs => r == 1 || (r >= 2 && n.is_multiple_of(r) && n / r >= 2),
            _ => r == 1,
        };
        if ok {
            return Ok(());
        }
        Err(StudyError::InvalidParameter(match self.sampler {
            Sampler::Lhs => format!(
                "{}: an LHS of {n} samples needs a replicate count that divides {n} and leaves at least 2 points per replicate (1 = a single LHS, no interval)",
                Param::Replicates.with(r)
            ),
            s => format!("{}: only an LHS is replicated, not {s}", Param::Replicates.with(r)),
        }))
    }

    /// The whole design, `n` rows of `dims` coordinates.
    pub fn rows(&self) -> Result<Vec<Vec<f64>>> {
        self.range(0..self.n)
    }

    pub fn range(&self, range: Range<usize>) -> Result<Vec<Vec<f64>>> {
        self.check_replicates()?;
        let (dims, n, seed) = (self.dims, self.n, self.seed);
        validate(self.sampler, dims, n)?;
        if range.start > range.end || range.end > n {
            return Err(StudyError::RangeOutOfBounds { start: range.start, end: range.end, n });
        }
        let ese = ese::EseParams::default();
        let mut rows = match self.sampler {
            Sampler::MonteCarlo => {
                return Ok(range.map(|i| monte_carlo::mc_row(dims, seed, i)).collect());
            }
            Sampler::Corners => return Ok(range.map(|i| corners::corner_row(dims, i)).collect()),
            Sampler::Lhs if self.replicates == 1 => lhs::optimised_lhs(dims, n, seed, &ese)?,
            Sampler::Lhs => (0..self.replicates)
                .map(|j| {
                    lhs::optimised_lhs(dims, n / self.replicates, replicate_seed(seed, j), &ese)
                })
                .collect::<Result<Vec<_>>>()?
                .concat(),
        };
        rows.truncate(range.end);
        rows.drain(..range.start);
        Ok(rows)
    }
}

/// Checks `(sampler, dims, n)` without drawing anything.
///
/// Corners: `n` must equal 2^dims (we error rather than silently ignore a different `n`, so that
/// `n` in a shard file is always the number of records; use [`corners::corner_count`] or
/// [`DesignSpec::new`] with `None` to get it).
pub fn validate(sampler: Sampler, dims: usize, n: usize) -> Result<()> {
    if dims == 0 {
        return Err(StudyError::ZeroDims);
    }
    match sampler {
        Sampler::Corners => {
            let expected = corners::corner_count(dims)?;
            if n != expected {
                return Err(StudyError::CornerCount { dims, expected, got: n });
            }
        }
        _ if n == 0 => return Err(StudyError::ZeroSamples),
        Sampler::Lhs if n > lhs::MAX_LHS_SAMPLES => {
            return Err(StudyError::LhsTooLarge { n, max: lhs::MAX_LHS_SAMPLES });
        }
        _ => {}
    }
    Ok(())
}

/// The full design: `n` rows, each with `dims` coordinates in [0, 1].
///
/// LHS and MC values lie in [0, 1); corners are exactly 0 or 1.
pub fn design(sampler: Sampler, dims: usize, n: usize, seed: u64) -> Result<Vec<Vec<f64>>> {
    sample_range(sampler, dims, n, seed, 0..n)
}

/// Rows `range` of the design `(sampler, dims, n, seed)`: `design(..)[range]`, computed the same way.
///
/// MC and corners compute only the requested rows. An LHS design depends as a whole on
/// `(seed, n)`, so it is computed completely and sliced (cheap for the sizes LHS is used for).
pub fn sample_range(
    sampler: Sampler,
    dims: usize,
    n: usize,
    seed: u64,
    range: Range<usize>,
) -> Result<Vec<Vec<f64>>> {
    let replicates = 1;
    DesignSpec { sampler, dims, n, seed, replicates }.range(range)
}
