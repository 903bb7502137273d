//! Full-factorial corner design: all 2^d extremes of the unit hypercube.
//!
//! Order: row `r` has coordinate `k` equal to bit `k` of `r`, i.e. `((r >> k) & 1) as f64`.
//! Row 0 is all zeros, row 1 has only dimension 0 at 1, row 2^d - 1 is all ones.

use super::super::error::{Result, StudyError};

/// Largest number of dimensions accepted (2^16 = 65 536 rows).
pub const MAX_CORNER_DIMS: usize = 16;

/// Number of rows of the corner design, 2^dims.
pub fn corner_count(dims: usize) -> Result<usize> {
    if dims == 0 {
        return Err(StudyError::ZeroDims);
    }
    if dims > MAX_CORNER_DIMS {
        return Err(StudyError::TooManyCornerDims { dims, max: MAX_CORNER_DIMS });
    }
    Ok(1usize << dims)
}

/// Row `r` of the corner design (caller guarantees `r < 2^dims`).
pub(crate) fn corner_row(dims: usize, r: usize) -> Vec<f64> {
    (0..dims).map(|k| ((r >> k) & 1) as f64).collect()
}
