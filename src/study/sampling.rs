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
//! Every design is a pure function of `(sampler, dims, n, seed)`, captured by [`DesignSpec`],
//! which shard files carry so that [`super::stats::merge`] can check that they belong together.

pub mod corners;
pub mod ese;
pub mod lhs;
pub mod monte_carlo;
pub mod shard;

use std::fmt;
use std::ops::Range;
use std::str::FromStr;

use serde::{Deserialize, Serialize};

use super::error::{Result, StudyError};

/// Which design to draw. Serialised (and parsed by [`FromStr`]) as `lhs`, `mc`, `corners`.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Sampler {
    /// Space-filling optimised Latin hypercube.
    #[serde(rename = "lhs")]
    Lhs,
    /// Plain Monte Carlo, independently computable per sample index.
    #[serde(rename = "mc")]
    MonteCarlo,
    /// All 2^d corners of the hypercube.
    #[serde(rename = "corners")]
    Corners,
}

impl Sampler {
    /// The name used in files and on the command line.
    pub fn name(self) -> &'static str {
        match self {
            Sampler::Lhs => "lhs",
            Sampler::MonteCarlo => "mc",
            Sampler::Corners => "corners",
        }
    }
}

impl fmt::Display for Sampler {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

impl FromStr for Sampler {
    type Err = StudyError;

    /// Accepts `lhs`, `mc`, `corners` (ASCII case-insensitive).
    fn from_str(s: &str) -> Result<Self> {
        match s.trim().to_ascii_lowercase().as_str() {
            "lhs" => Ok(Sampler::Lhs),
            "mc" => Ok(Sampler::MonteCarlo),
            "corners" => Ok(Sampler::Corners),
            _ => Err(StudyError::UnknownSampler(s.to_owned())),
        }
    }
}

/// Everything a design depends on. Shard files carry it to be validated on merge.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize, Deserialize)]
pub struct DesignSpec {
    pub sampler: Sampler,
    pub dims: usize,
    pub n: usize,
    pub seed: u64,
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
        Ok(DesignSpec {
            sampler,
            dims,
            n,
            seed,
        })
    }

    /// The whole design, `n` rows of `dims` coordinates.
    pub fn rows(&self) -> Result<Vec<Vec<f64>>> {
        design(self.sampler, self.dims, self.n, self.seed)
    }

    /// Rows `range` of the design.
    pub fn range(&self, range: Range<usize>) -> Result<Vec<Vec<f64>>> {
        sample_range(self.sampler, self.dims, self.n, self.seed, range)
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
                return Err(StudyError::CornerCount {
                    dims,
                    expected,
                    got: n,
                });
            }
        }
        Sampler::Lhs => {
            if n == 0 {
                return Err(StudyError::ZeroSamples);
            }
            if n > lhs::MAX_LHS_SAMPLES {
                return Err(StudyError::LhsTooLarge {
                    n,
                    max: lhs::MAX_LHS_SAMPLES,
                });
            }
        }
        Sampler::MonteCarlo => {
            if n == 0 {
                return Err(StudyError::ZeroSamples);
            }
        }
    }
    Ok(())
}

/// The full design: `n` rows, each with `dims` coordinates in [0, 1].
///
/// LHS and MC values lie in [0, 1); corners are exactly 0 or 1.
pub fn design(sampler: Sampler, dims: usize, n: usize, seed: u64) -> Result<Vec<Vec<f64>>> {
    sample_range(sampler, dims, n, seed, 0..n)
}

/// Rows `range` of the design `(sampler, dims, n, seed)`: equal to `design(..)[range]`, bit for bit.
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
    validate(sampler, dims, n)?;
    if range.start > range.end || range.end > n {
        return Err(StudyError::RangeOutOfBounds {
            start: range.start,
            end: range.end,
            n,
        });
    }
    match sampler {
        Sampler::Lhs => {
            let mut rows = lhs::optimised_lhs(dims, n, seed, &ese::EseParams::default())?;
            rows.truncate(range.end);
            rows.drain(..range.start);
            Ok(rows)
        }
        Sampler::MonteCarlo => Ok(range.map(|i| monte_carlo::mc_row(dims, seed, i)).collect()),
        Sampler::Corners => Ok(range.map(|i| corners::corner_row(dims, i)).collect()),
    }
}
