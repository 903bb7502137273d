//! Deterministic random numbers.
//!
//! All randomness of the study module comes from ChaCha8 (rand_chacha 0.9), keyed from a `u64`
//! seed and a per-purpose domain constant through SplitMix64 (Steele, Lea & Flood 2014, the
//! generator behind Java's `SplittableRandom`): the 32-byte key is four successive SplitMix64
//! outputs, little-endian, from the state `seed ^ domain`. We do not use
//! `SeedableRng::seed_from_u64` nor rand's distributions: the conversions below are fixed here,
//! so designs stay bit-identical whatever rand version the host crate uses.

use rand_chacha::ChaCha8Rng;
use rand_chacha::rand_core::{RngCore, SeedableRng};

/// Domain constant of the Latin hypercube stream.
pub(crate) const DOMAIN_LHS: u64 = 0x4c48_535f_4553_4531; // "LHS_ESE1"
/// Domain constant of the Monte Carlo streams.
pub(crate) const DOMAIN_MC: u64 = 0x4d43_5f53_5452_4d31; // "MC_STRM1"
/// Domain constant of the LHS replicate seeds.
pub(crate) const DOMAIN_REPLICATE: u64 = 0x5245_504c_4943_4131; // "REPLICA1"
/// Domain constant of the Sobol (Saltelli) base matrices.
pub(crate) const DOMAIN_SOBOL: u64 = 0x534f_424f_4c5f_4d31; // "SOBOL_M1"
/// Domain constant of an optimisation's starting points.
pub(crate) const DOMAIN_STARTS: u64 = 0x4f50_5453_5452_5431; // "OPTSTRT1"
/// Domain constant of the bootstrap stream.
pub(crate) const DOMAIN_BOOT: u64 = 0x424f_4f54_5354_5231; // "BOOTSTR1"

/// One SplitMix64 step: advances `state` and returns the mixed output.
pub(crate) fn splitmix64(state: &mut u64) -> u64 {
    *state = state.wrapping_add(0x9e37_79b9_7f4a_7c15);
    let mut z = *state;
    z = (z ^ (z >> 30)).wrapping_mul(0xbf58_476d_1ce4_e5b9);
    z = (z ^ (z >> 27)).wrapping_mul(0x94d0_49bb_1331_11eb);
    z ^ (z >> 31)
}

/// ChaCha8 generator keyed from `(seed, domain)`, stream 0, position 0.
pub(crate) fn chacha(seed: u64, domain: u64) -> ChaCha8Rng {
    let mut state = seed ^ domain;
    let mut key = [0u8; 32];
    for chunk in key.chunks_exact_mut(8) {
        chunk.copy_from_slice(&splitmix64(&mut state).to_le_bytes());
    }
    ChaCha8Rng::from_seed(key)
}

/// Uniform double in [0, 1): the top 53 bits of one `u64`, times 2^-53 (exact).
pub(crate) fn unit_f64(rng: &mut impl RngCore) -> f64 {
    const SCALE: f64 = 1.0 / (1u64 << 53) as f64;
    (rng.next_u64() >> 11) as f64 * SCALE
}

/// Unbiased integer in 0..bound (bound > 0): Lemire's (2019) multiply-and-reject method.
pub(crate) fn below(rng: &mut impl RngCore, bound: usize) -> usize {
    debug_assert!(bound > 0);
    let bound = bound as u64;
    let mut m = u128::from(rng.next_u64()) * u128::from(bound);
    if (m as u64) < bound {
        let threshold = bound.wrapping_neg() % bound;
        while (m as u64) < threshold {
            m = u128::from(rng.next_u64()) * u128::from(bound);
        }
    }
    (m >> 64) as usize
}

/// Fisher–Yates shuffle driven by [`below`].
pub(crate) fn shuffle<T>(rng: &mut impl RngCore, items: &mut [T]) {
    for i in (1..items.len()).rev() {
        let j = below(rng, i + 1);
        items.swap(i, j);
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix64_reference_values() {
        // Reference outputs of SplitMix64 from state 0 (as in Vigna's splitmix64.c).
        let mut s = 0u64;
        assert_eq!(splitmix64(&mut s), 0xe220_a839_7b1d_cdaf);
        assert_eq!(splitmix64(&mut s), 0x6e78_9e6a_a1b9_65f4);
    }

    #[test]
    fn below_stays_in_range() {
        let mut rng = chacha(1, 2);
        for bound in 1..50 {
            for _ in 0..20 {
                assert!(below(&mut rng, bound) < bound);
            }
        }
    }
}
