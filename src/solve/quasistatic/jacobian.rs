//! A contact's columns of the Newton corrector's Jacobian (`super::solver`),
//! over lanes ([`crate::lane`]) and, as their f64 form, for one seating.

use std::ops::{AddAssign, SubAssign};

use nalgebra::{Matrix3, Matrix6, Vector3};

use crate::lane::Lane;

/// Add one contact to the Jacobian: force rows K dp, moment rows
/// p x (K dp) + dp_moving x f, with dp = v - [p]x w at the contact point p
/// and at the ball centre `moving` (the point the force's line moves with):
/// ```text
/// [ K        -K [p]x                      ]
/// [ [p]x K - [f]x    -[p]x K [p]x + m f^T - (f . m) I ]
/// ```
/// ([f]x [m]x = m f^T - (f . m) I), column by column on 3-vectors (no 3x3
/// products formed): column c of -K [p]x is -K (p x e_c), a combination of
/// two columns of K, and those of [p]x K and [p]x (-K [p]x) are p x the
/// columns of K and of -K [p]x.
#[inline(always)]
pub(super) fn add_contact<T: Lane>(
    j: &mut Matrix6<T>,
    k: &Matrix3<T>,
    f: &Vector3<T>,
    p: &Vector3<T>,
    moving: &Vector3<T>,
) {
    // (Written out: an array `map` here was left out of line, 14 % of a
    // seating in lanes.)
    let kc = [k.column(0).into_owned(), k.column(1).into_owned(), k.column(2).into_owned()];
    let kp = [kc[2] * p.y - kc[1] * p.z, kc[0] * p.z - kc[2] * p.x, kc[1] * p.x - kc[0] * p.y];
    let fx = f.cross_matrix();
    let dot = f.dot(moving);
    let columns = &mut j.data.0;
    for c in 0..3 {
        let pk = p.cross(&kc[c]) - fx.column(c);
        let mut fm = moving * f[c];
        fm[c] -= dot;
        let pkp = p.cross(&kp[c]) + fm;
        let (left, right) = columns.split_at_mut(3);
        add3(&mut left[c], &kc[c], &pk);
        add3(&mut right[c], &kp[c], &pkp);
    }
}

/// Column `col` of the Jacobian += (top, bottom).
#[inline(always)]
fn add3<T: Lane>(col: &mut [T; 6], top: &Vector3<T>, bottom: &Vector3<T>) {
    for r in 0..3 {
        col[r] += top[r];
        col[r + 3] += bottom[r];
    }
}

/// Add a force of fixed direction `f` at a point `p` of the body (K = 0):
/// moment rows only, d(p x f) = dp x f = -[f]x (v - [p]x w).
#[inline(always)]
pub(super) fn add_fixed_force<T: Lane>(j: &mut Matrix6<T>, f: &Vector3<T>, p: &Vector3<T>) {
    let fx = f.cross_matrix();
    j.fixed_view_mut::<3, 3>(3, 0).sub_assign(&fx);
    j.fixed_view_mut::<3, 3>(3, 3).add_assign(&(fx * p.cross_matrix()));
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One contact added to the Jacobian over lanes: lane i bit for bit
    /// the f64 columns of lane i's stiffness, force and points.
    #[test]
    fn a_contact_joins_the_jacobian_in_lanes_as_in_f64() {
        use crate::lane::F64x4;
        use rand::{Rng, SeedableRng};
        use simba::simd::SimdValue;
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(8);
        for _ in 0..200 {
            let mut draw = |scale: f64| rng.random_range(-scale..scale);
            // (K, [f, p, moving], the Jacobian before) of each lane.
            type Case = (Matrix3<f64>, [Vector3<f64>; 3], Matrix6<f64>);
            let cases: [Case; 4] = std::array::from_fn(|_| {
                let k = Matrix3::from_fn(|_, _| draw(1e8));
                let v = [0; 3].map(|_| Vector3::from_fn(|_, _| draw(1.0)));
                (k, v, Matrix6::from_fn(|_, _| draw(1e7)))
            });
            let m3 = |f: &dyn Fn(usize) -> Matrix3<f64>| {
                Matrix3::from_fn(|r, c| F64x4::from([0, 1, 2, 3].map(|l| f(l)[(r, c)])))
            };
            let v3 = |f: &dyn Fn(usize) -> Vector3<f64>| {
                Vector3::from_fn(|r, _| F64x4::from([0, 1, 2, 3].map(|l| f(l)[r])))
            };
            let mut j = Matrix6::from_fn(|r, c| F64x4::from(cases.each_ref().map(|x| x.2[(r, c)])));
            let k = m3(&|l| cases[l].0);
            let [f, p, m] = [0, 1, 2].map(|q| v3(&|l| cases[l].1[q]));
            add_contact(&mut j, &k, &f, &p, &m);
            for (l, (k, [f, p, m], j0)) in cases.iter().enumerate() {
                let mut js = *j0;
                add_contact(&mut js, k, f, p, m);
                assert!(
                    j.iter().zip(js.iter()).all(|(a, b)| a.extract(l).to_bits() == b.to_bits())
                );
            }
        }
    }
}
