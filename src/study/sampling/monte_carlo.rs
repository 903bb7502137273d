//! Plain Monte Carlo: independent uniform points in [0, 1)^d.
//!
//! Row `i` depends only on `(seed, i)`: it is drawn from ChaCha8 keyed by
//! `(seed, DOMAIN_MC)` (see the `rng` module) on **stream `i`** (`set_stream(i)`, word position 0),
//! coordinate `k` being the `k`-th 53-bit uniform of that stream. Any range of rows can thus be
//! computed on its own, e.g. by one shard of a batch job.

use rand_chacha::ChaCha8Rng;

use super::super::rng::{DOMAIN_MC, chacha, unit_f64};

/// Row `i` of the Monte Carlo design with `dims` coordinates.
pub(crate) fn mc_row(dims: usize, seed: u64, i: usize) -> Vec<f64> {
    let mut rng: ChaCha8Rng = chacha(seed, DOMAIN_MC);
    rng.set_stream(i as u64);
    (0..dims).map(|_| unit_f64(&mut rng)).collect()
}
