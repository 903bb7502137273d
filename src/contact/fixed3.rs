//! The few 3x3 kernels of the contact laws' hot path, written out term by
//! term in nalgebra's own summation order, so that they give nalgebra's
//! results bit for bit (the seating's answers are unchanged) without its
//! generic column loops:
//!
//! ```text
//! (A x)_i  = (a_i0 x_0 + a_i1 x_1) + a_i2 x_2        (nalgebra's gemv: one column after the other)
//! (A B)_ij = (a_i0 b_0j + a_i1 b_1j) + a_i2 b_2j     (gemm: gemv per column of B)
//! P_ij     = delta_ij - n_i n_j                      (I - n n^T, the tangent-plane projector)
//! ```

use nalgebra::{Matrix3, Vector3};

/// A x, bit for bit as nalgebra's `a * x`.
#[inline]
pub fn mat_vec(a: &Matrix3<f64>, x: &Vector3<f64>) -> Vector3<f64> {
    Vector3::from_fn(|i, _| a[(i, 0)] * x[0] + a[(i, 1)] * x[1] + a[(i, 2)] * x[2])
}

/// A B, bit for bit as nalgebra's `a * b`.
#[inline]
pub fn mat_mat(a: &Matrix3<f64>, b: &Matrix3<f64>) -> Matrix3<f64> {
    Matrix3::from_fn(|i, j| a[(i, 0)] * b[(0, j)] + a[(i, 1)] * b[(1, j)] + a[(i, 2)] * b[(2, j)])
}

/// I - n n^T, bit for bit as nalgebra's `Matrix3::identity() - n * n.transpose()`.
#[inline]
pub fn tangent_projector(n: &Vector3<f64>) -> Matrix3<f64> {
    Matrix3::from_fn(|i, j| if i == j { 1.0 } else { 0.0 } - n[i] * n[j])
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A xorshift stream of values over many decades and both signs.
    fn values(seed: u64) -> impl FnMut() -> f64 {
        let mut s = seed;
        move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            let mantissa = (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5;
            mantissa * 10f64.powi((s % 17) as i32 - 8)
        }
    }

    /// The written-out kernels against nalgebra's generic products, bit for
    /// bit (a different summation order would differ in the last bits of
    /// most of these sums of mixed magnitudes and signs).
    #[test]
    fn kernels_are_nalgebras_products_bit_for_bit() {
        let mut v = values(0x2545_F491_4F6C_DD1D);
        for _ in 0..20_000 {
            let a = Matrix3::from_fn(|_, _| v());
            let b = Matrix3::from_fn(|_, _| v());
            let x = Vector3::from_fn(|_, _| v());
            let bits = |m: &[f64]| m.iter().map(|e| e.to_bits()).collect::<Vec<_>>();
            assert_eq!(bits(mat_vec(&a, &x).as_slice()), bits((a * x).as_slice()));
            assert_eq!(bits(mat_mat(&a, &b).as_slice()), bits((a * b).as_slice()));
            let n = x.normalize();
            let p = Matrix3::identity() - n * n.transpose();
            assert_eq!(bits(tangent_projector(&n).as_slice()), bits(p.as_slice()));
        }
    }
}
