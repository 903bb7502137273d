//! The increment's tangential stiffness of a contact law: the effective
//! semi-axis a_eff of an increment from the committed and the trial
//! normal force, and Mindlin's K_t from it, in series with the support's
//! tangential compliance (module docs of `solve::contact_layer`), over
//! lanes ([`crate::lane`]) and, as their f64 form, for one seating.

use nalgebra::{Matrix3, Vector3};

use super::{ContactLaw, PrincipalStiffness};
use crate::lane::{Both, Lane, branch, lift, splat};

impl ContactLaw {
    /// The increment's effective semi-axis for K_t and its relative
    /// derivative: a_eff = (2/3) (a0^2 + a0 a1 + a1^2) / (a0 + a1) from
    /// a0 = a(`committed_fn`) and a1 = a(`fn_`) (the fast cube root), and
    /// d(ln a_eff)/dF_n (module docs of `solve::contact_layer`). It is the
    /// long-latency part of [`Self::increment_stiffness`], which the solver
    /// forms for all contacts before the rest.
    #[inline]
    pub fn increment_semi_axis(&self, committed_fn: f64, fn_: f64) -> (f64, f64) {
        let hertz = &self.hertz;
        self.increment_semi_axis_of(
            hertz.major_semi_axis_fast(committed_fn),
            hertz.major_semi_axis_fast(fn_),
            fn_,
        )
    }

    /// [`Self::increment_semi_axis`] from both semi-axes already formed
    /// (the contact layer's: a0 once per increment, a1 from the Hertz
    /// law's root).
    #[inline]
    pub fn increment_semi_axis_of<T: Lane>(&self, a0: T, a1: T, fn_: T) -> (T, T) {
        let sum = a0 + a1;
        let Both(a_eff, dlog) = branch::<T, _>(
            sum.simd_le(T::zero()) | fn_.simd_le(T::zero()),
            |_| Both(splat::<T>(0.5) * sum, T::zero()),
            |_| {
                let q = a0 * a0 + a0 * a1 + a1 * a1;
                let a_eff = splat::<T>(2.0 / 3.0) * q / sum;
                // d a_eff / d a1 = (2/3) (2 a0 a1 + a1^2) / (a0 + a1)^2, d a1 / dF = a1 / (3 F).
                let dlog = (splat::<T>(2.0) * a0 + a1) * a1 * a1 / (sum * q * splat(3.0) * fn_);
                Both(a_eff, dlog)
            },
        );
        (a_eff, dlog)
    }

    /// K_t of an increment from its effective semi-axis and the relative
    /// derivative ([`Self::increment_semi_axis`]): Mindlin's principal
    /// stiffnesses k = coef a_eff about `major_axis` (zero: circular), the
    /// 3x3 tensor in the plane of `normal`, and, if `tangent`,
    /// dK_t/dF_n = K_t d(ln a_eff)/dF_n (zero otherwise, or unloaded).
    /// Without `tangent` a circular contact's tensor is left at zero: the
    /// laws read it only for the tangent (the Coulomb law applies a
    /// circle's K_t by its value k, `coulomb::Circle`; Mindlin-Deresiewicz
    /// reads its shape).
    #[inline(always)]
    pub fn increment_stiffness(
        &self,
        a_eff: f64,
        dlog: f64,
        normal: &Vector3<f64>,
        major_axis: &Vector3<f64>,
        tangent: bool,
    ) -> (PrincipalStiffness, Matrix3<f64>, Matrix3<f64>) {
        match self.increment_stiffness_lanes(a_eff, dlog, normal, major_axis, tangent) {
            Some(k) => k,
            None => unreachable!("one lane takes one form"),
        }
    }

    /// [`Self::increment_stiffness`] over lanes; `None` where the lanes
    /// differ in the form of K_t (circle or ellipse), and for an
    /// anisotropic support compliance (its series stiffness, an
    /// eigen-decomposition, is f64's alone: one lane only).
    #[inline(always)]
    pub fn increment_stiffness_lanes<T: Lane>(
        &self,
        a_eff: T,
        dlog: T,
        normal: &Vector3<T>,
        major_axis: &Vector3<f64>,
        tangent: bool,
    ) -> Option<(PrincipalStiffness<T>, Matrix3<T>, Matrix3<T>)> {
        let k = self.mindlin.map(|c| splat::<T>(c) * a_eff);
        let support = &self.tangential_support;
        if !support.is_isotropic() {
            if T::LANES > 1 {
                return None;
            }
            // One lane: f64's own form, read out of and back into the lane.
            let one = |x: &T| x.extract(0);
            let n = normal.map(|x| x.extract(0));
            let series = support.series(k.map(|x| one(&x)), &n, major_axis);
            let dkt = if tangent { series.derivative * one(&dlog) } else { Matrix3::zeros() };
            let p = series.principal;
            let principal = PrincipalStiffness {
                k: p.k.map(splat),
                axes: p.axes.map(|axes| axes.map(|e| lift(&e))),
            };
            return Some((principal, lift(&series.tensor), lift(&dkt)));
        }
        let c_t = support.along;
        // In series with the support: k' = k / (1 + k c_t) per principal
        // axis (the increment's, since the support is linear), and
        // dk'/dF_n = (dk/dF_n) / (1 + k c_t)^2 with dk/dF_n = k dlog.
        let (one, c) = (T::one(), splat::<T>(c_t));
        let series = if c_t > 0.0 { k.map(|k| k / (one + k * c)) } else { k };
        let principal = PrincipalStiffness::of_lanes(series, normal, major_axis)?;
        let kt = if tangent || principal.axes.is_some() {
            principal.tensor(normal)
        } else {
            Matrix3::zeros()
        };
        let dkt = match (tangent, c_t > 0.0) {
            (false, _) => Matrix3::zeros(),
            (true, false) => kt * dlog,
            (true, true) => {
                let d = k.map(|k| k * dlog / ((one + k * c) * (one + k * c)));
                PrincipalStiffness::of_lanes(d, normal, major_axis)?.tensor(normal)
            }
        };
        Some((principal, kt, dkt))
    }
}
