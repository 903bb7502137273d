//! The 6x6 solve of the Newton corrector, J dx = r, on the stack: Gaussian
//! elimination with partial pivoting (Golub & Van Loan, Matrix
//! Computations, 4th ed., Alg. 3.4.1), the forward substitution done in
//! the same sweep and the back substitution after it.
//!
//! The algorithm of nalgebra's `LU::new(J).solve(r)` (the pivot is the
//! first entry of largest |a| in the column; the multipliers are
//! a_ki (1/a_ii); each update is a_kj - u_ij l_ki; the back substitution
//! divides by u_ii), checked below against nalgebra, without forming the
//! LU and permutation objects or its dynamically sized views: a seating
//! takes 4 % fewer instructions than with nalgebra's LU (callgrind).

//!
//! Written over [`Lane`]s: each lane pivots on its own row (the swaps are
//! blends, made where some lane pivots on that row), so that lane i is bit
//! for bit the f64 solve of lane i's system; `None` if any lane's system
//! is singular.

use nalgebra::{Matrix6, Vector6};
use simba::simd::SimdBool;

use crate::lane::{Lane, splat};

/// The solution of `a x = b`, or `None` where `a` is singular (a column
/// with no non-zero pivot), as nalgebra's `a.lu().solve(b)`.
pub(super) fn solve6<T: Lane>(a: &Matrix6<T>, b: &Vector6<T>) -> Option<Vector6<T>> {
    // Column-major: m[c][r] is a_rc.
    let mut m = a.data.0;
    let mut x = b.data.0[0];
    // One function per elimination step: its bounds are constants, so
    // every loop unrolls without index checks.
    eliminate::<T, 0>(&mut m, &mut x)?;
    eliminate::<T, 1>(&mut m, &mut x)?;
    eliminate::<T, 2>(&mut m, &mut x)?;
    eliminate::<T, 3>(&mut m, &mut x)?;
    eliminate::<T, 4>(&mut m, &mut x)?;
    eliminate::<T, 5>(&mut m, &mut x)?;
    for i in (0..6).rev() {
        if m[i][i].simd_eq(T::zero()).any() {
            return None;
        }
        let c = x[i] / m[i][i];
        x[i] = c;
        for k in 0..i {
            x[k] -= c * m[i][k];
        }
    }
    Some(Vector6::from(x))
}

/// Step `I` of the elimination: pivot on column `I`, the multipliers
/// l_rI = a_rI / a_II of the rows below, their forward substitution into
/// `x`, and the update of the columns right of `I`. `None`: no pivot.
#[inline(always)]
fn eliminate<T: Lane, const I: usize>(m: &mut [[T; 6]; 6], x: &mut [T; 6]) -> Option<()> {
    // The pivot row of each lane (as a number: lanes hold f64).
    let mut piv = splat::<T>(I as f64);
    let mut max = m[I][I].simd_abs();
    for (r, v) in m[I].iter().enumerate().skip(I + 1) {
        let larger = v.simd_abs().simd_gt(max);
        max = v.simd_abs().select(larger, max);
        piv = splat::<T>(r as f64).select(larger, piv);
    }
    if max.simd_eq(T::zero()).any() {
        return None;
    }
    for r in I + 1..6 {
        let here = piv.simd_eq(splat::<T>(r as f64));
        if here.any() {
            // Swap rows I and r in the lanes that pivot on r.
            for col in m.iter_mut() {
                (col[I], col[r]) = (col[r].select(here, col[I]), col[I].select(here, col[r]));
            }
            (x[I], x[r]) = (x[r].select(here, x[I]), x[I].select(here, x[r]));
        }
    }
    let inv = T::one() / m[I][I];
    for r in I + 1..6 {
        m[I][r] *= inv;
        x[r] -= x[I] * m[I][r];
    }
    let l = m[I];
    for col in m.iter_mut().skip(I + 1) {
        let u = col[I];
        for r in I + 1..6 {
            col[r] -= u * l[r];
        }
    }
    Some(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use rand::{Rng, SeedableRng};
    use rand_chacha::ChaCha8Rng;

    #[test]
    fn equals_nalgebra_lu() {
        let mut rng = ChaCha8Rng::seed_from_u64(6);
        for k in 0..2000 {
            // Entries over many decades (as a Jacobian with N/m and N m
            // blocks), some rows swapped by the pivoting.
            let a = Matrix6::from_fn(|_, _| {
                rng.random_range(-1.0..1.0) * 10f64.powi(rng.random_range(-3..9))
            });
            let b = Vector6::from_fn(|_, _| rng.random_range(-1.0..1.0));
            let reference = a.lu().solve(&b).unwrap();
            let x = solve6(&a, &b).unwrap();
            let d = (x - reference).amax();
            assert!(d <= 1e-12 * reference.amax(), "case {k}: {d:e}");
            // and it solves the system (the residual of a backward-stable solve)
            let r = a * x - b;
            assert!(r.amax() < 1e-6 * (a.amax() * x.amax() + 1.0), "case {k}");
        }
    }

    /// Four systems in lanes, each lane pivoting on its own rows: lane i
    /// is bit for bit the f64 solve of system i.
    #[test]
    fn lanes_solve_each_lane_as_f64() {
        use crate::lane::F64x4;
        use simba::simd::SimdValue;
        let mut rng = ChaCha8Rng::seed_from_u64(7);
        for k in 0..500 {
            let systems: [(Matrix6<f64>, Vector6<f64>); 4] = std::array::from_fn(|_| {
                let a = Matrix6::from_fn(|_, _| {
                    rng.random_range(-1.0..1.0) * 10f64.powi(rng.random_range(-3..9))
                });
                (a, Vector6::from_fn(|_, _| rng.random_range(-1.0..1.0)))
            });
            let a = Matrix6::from_fn(|r, c| F64x4::from(systems.map(|s| s.0[(r, c)])));
            let b = Vector6::from_fn(|r, _| F64x4::from(systems.map(|s| s.1[r])));
            let x = solve6(&a, &b).unwrap();
            for (i, (a, b)) in systems.iter().enumerate() {
                let xs = solve6(a, b).unwrap();
                for r in 0..6 {
                    assert_eq!(x[r].extract(i).to_bits(), xs[r].to_bits(), "case {k} lane {i}");
                }
            }
        }
    }

    #[test]
    fn singular_is_none_as_in_nalgebra() {
        let mut a = Matrix6::from_fn(|r, c| (r * 6 + c) as f64 + 1.0);
        a.set_column(2, &Vector6::zeros());
        let b = Vector6::from_element(1.0);
        assert!(a.lu().solve(&b).is_none());
        assert!(solve6(&a, &b).is_none());
    }
}
