//! A support compliance in series with the Hertz contact (normal direction):
//! the bulk of the two halves, the bending of a pin on its supports, the
//! mounting of a fixed ball, as one linear spring of compliance c [m/N].
//!
//! The approach of the rigid bodies (the closure of their gap) is shared:
//! ```text
//! delta(F) = delta_H(F) + c F,      delta_H(F) = (F / K)^(2/3)        (Hertz, Johnson eq. 4.23)
//! d delta / dF = 2 / (3 K^(2/3) F^(1/3)) + c = 1 / k_H + c            (springs in series)
//! ```
//! F(delta) from t = F^(1/3), q = K^(-2/3): h(t) = c t^3 + q t^2 - delta = 0.
//! h is increasing and convex for t > 0, and t0 = min(sqrt(delta/q),
//! cbrt(delta/c)) is an upper bound of the root (either term alone reaches
//! delta there), so Newton from t0 descends monotonically onto the root
//! (quadratic convergence; a handful of steps). With c = 0 the Hertz law
//! is used as it is.

use simba::simd::SimdBool;

use super::hertz::{HertzLaw, load_roots};
use crate::lane::{Both, Lane, Mask, branch, splat};

/// The normal law of one contact: Hertz plus a series support compliance.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeriesNormal {
    pub hertz: HertzLaw,
    /// Support compliance c >= 0 [m/N].
    pub compliance: f64,
    /// q = K^(-2/3) of `hertz`, computed once in [`Self::new`] (the Newton
    /// iteration of [`Self::force_and_stiffness`] reads it at every
    /// evaluation; it depends on `hertz` alone, so a change of `compliance`
    /// keeps it valid, and a new Hertz law needs a new `SeriesNormal`).
    q: f64,
    /// K^(1/3) of `hertz`: F^(1/3) = K^(1/3) delta^(1/2) of the Hertz law.
    force_root: f64,
}

impl SeriesNormal {
    pub fn new(hertz: HertzLaw, compliance: f64) -> Self {
        SeriesNormal {
            hertz,
            compliance,
            q: hertz.hertz_constant.powf(-2.0 / 3.0),
            force_root: hertz.hertz_constant.cbrt(),
        }
    }

    /// Total approach delta(F) = (F/K)^(2/3) + c F for a load F >= 0.
    pub fn approach(&self, load: f64) -> f64 {
        self.hertz.approach(load) + self.support_approach(load)
    }

    /// The support part c F of the approach.
    pub fn support_approach(&self, load: f64) -> f64 {
        self.compliance * load.max(0.0)
    }

    /// Normal force F(delta) (0 for delta <= 0) and stiffness dF/d delta.
    #[inline]
    pub fn force_and_stiffness(&self, approach: f64) -> (f64, f64) {
        if self.compliance == 0.0 || approach <= 0.0 {
            let (f, k, _) = self.hertz_alone(approach);
            return (f, k);
        }
        self.series_force_and_stiffness(approach, true)
    }

    /// [`Self::force_and_stiffness`] and F^(1/3) (the contact layer's
    /// a = c_a F^(1/3) at every evaluation, `solve::contact_layer`). For the
    /// Hertz law alone it is formed from the law's own square root,
    /// F^(1/3) = K^(1/3) delta^(1/2) (Johnson eq. 4.23), within a few ulps
    /// of a cube root of F and off the evaluation's longest chain; with a
    /// support compliance it is the cube root of F ([`load_root`]), as
    /// before: the series law's t (F = t^3) agrees with it to a few ulps
    /// too, but the flexure-groove scene's sigma moved by 3e-10 between the
    /// two (measured), where the Hertz law's root moves the paper scenes'
    /// by at most 4e-13.
    #[inline]
    pub fn force_stiffness_and_root<T: Lane>(&self, approach: T) -> (T, T, T) {
        let hertz_alone = |_| {
            let (f, k, root) = self.hertz_alone(approach);
            Both(f, Both(k, splat::<T>(self.force_root) * root))
        };
        if self.compliance == 0.0 {
            let Both(f, Both(k, root)) = hertz_alone(approach.simd_le(T::zero()));
            return (f, k, root);
        }
        let Both(f, Both(k, root)) =
            branch::<T, _>(approach.simd_le(T::zero()), hertz_alone, |closed| {
                let (f, k) = self.series_force_and_stiffness(approach, closed);
                Both(f, Both(k, load_roots(f)))
            });
        (f, k, root)
    }

    /// The Hertz law alone (no compliance, or delta <= 0): F = K delta^1.5,
    /// dF/d delta = 1.5 K delta^0.5 (`HertzLaw::force` and `::stiffness`, one
    /// square root) and delta^0.5; zeros for delta <= 0.
    #[inline]
    fn hertz_alone<T: Lane>(&self, approach: T) -> (T, T, T) {
        let Both(f, Both(k, root)) = branch::<T, _>(
            approach.simd_gt(T::zero()),
            |_| {
                let (k, root) = (self.hertz.hertz_constant, approach.simd_sqrt());
                Both(splat::<T>(k) * approach * root, Both(splat::<T>(1.5 * k) * root, root))
            },
            |_| Both(T::zero(), Both(T::zero(), T::zero())),
        );
        (f, k, root)
    }

    /// [`Self::force_and_stiffness`] with a compliance c > 0 and delta > 0:
    /// the Newton iteration of the module docs.
    /// Over lanes, in those of `active` (a lane stops where its f64
    /// iteration would and keeps its t while the others go on).
    fn series_force_and_stiffness<T: Lane>(&self, approach: T, mut active: Mask<T>) -> (T, T) {
        let c = splat::<T>(self.compliance);
        let q = splat::<T>(self.q);
        let mut t = (approach / q).simd_sqrt().simd_min((approach / c).simd_cbrt());
        for _ in 0..100 {
            let r = c * t * t * t + q * t * t - approach;
            let step = r / (splat::<T>(3.0) * c * t * t + splat::<T>(2.0) * q * t);
            active = active & !(step.simd_ne(step) | step.simd_le(T::zero()));
            if active.none() {
                break;
            }
            t = (t - step).select(active, t);
            active = active & !step.simd_le(splat::<T>(1e-16) * t);
            if active.none() {
                break;
            }
        }
        let f = t * t * t;
        // k_H = dF/d delta_H = 3 t / (2 q); in series with 1/c.
        let k_hertz = splat::<T>(1.5) * t / q;
        (f, k_hertz / (T::one() + c * k_hertz))
    }

    /// Elastic energy stored at approach delta: the Hertz part
    /// 2/5 K delta_H^(5/2) plus the spring's c F^2 / 2.
    pub fn energy(&self, approach: f64) -> f64 {
        let (f, _) = self.force_and_stiffness(approach);
        if f <= 0.0 {
            return 0.0;
        }
        let dh = self.hertz.approach(f);
        0.4 * self.hertz.hertz_constant * dh * dh * dh.sqrt() + 0.5 * self.compliance * f * f
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::contact::hertz::load_root;

    /// Without a compliance the law is Hertz's own F and dF/d delta (one
    /// square root shared instead of two; zero when open); with one, the
    /// stored q is K^(-2/3) and F solves the series equation.
    #[test]
    fn hertz_alone_and_the_series_root_on_its_equation() {
        let hertz = HertzLaw::circular(5e-3, 115.4e9);
        let alone = SeriesNormal::new(hertz, 0.0);
        let close = |a: f64, b: f64| (a.is_nan() && b.is_nan()) || (a - b).abs() <= 1e-12 * b.abs();
        for delta in [-1e-9, 0.0, 1e-12, 3.3e-7, 5e-7, 2e-6, f64::NAN] {
            let (f, k) = alone.force_and_stiffness(delta);
            assert!(close(f, hertz.force(delta)), "{delta}");
            assert!(close(k, hertz.stiffness(delta)), "{delta}");
        }
        let c = 2.5e-8;
        let series = SeriesNormal::new(hertz, c);
        assert!(close(series.q, hertz.hertz_constant.powf(-2.0 / 3.0)));
        for delta in [1e-9, 3.3e-7, 5e-7, 2e-6] {
            // delta(F) = (F/K)^(2/3) + c F, springs in series.
            let (f, k) = series.force_and_stiffness(delta);
            assert!((series.approach(f) / delta - 1.0).abs() < 1e-13, "{delta}");
            let k_hertz = hertz.stiffness(hertz.approach(f));
            assert!((k / (k_hertz / (1.0 + c * k_hertz)) - 1.0).abs() < 1e-12);
        }
    }

    /// F^(1/3) formed from the Hertz law's square root is the cube root of
    /// its force to a few ulps, for circular and elliptical contacts: with
    /// a = c_a F^(1/3) it is the closed form a = sqrt(R delta) of a circle
    /// (Johnson eq. 4.23); zero when open; the same F and dF/d delta as
    /// `force_and_stiffness`; with a compliance, exactly the cube root of F.
    #[test]
    fn the_force_root_is_the_cube_root_of_the_force() {
        let laws = [
            HertzLaw::circular(5e-3, 115.4e9),
            HertzLaw::elliptical(5e-3, 2.1e-2, 115.4e9),
            HertzLaw::elliptical(4e-2, 6e-3, 2.2e11),
        ];
        for hertz in laws {
            let alone = SeriesNormal::new(hertz, 0.0);
            for delta in [1e-12, 3.3e-9, 3.3e-7, 5e-7, 2e-6, 1e-4] {
                let (f, k, root) = alone.force_stiffness_and_root(delta);
                assert_eq!((f, k), alone.force_and_stiffness(delta));
                let cube = f.cbrt();
                assert!((root - cube).abs() <= 4.0 * f64::EPSILON * cube, "{delta}: {root} {cube}");
            }
            assert_eq!(alone.force_stiffness_and_root(-1e-9), (0.0, 0.0, 0.0));
            assert_eq!(alone.force_stiffness_and_root(0.0), (0.0, 0.0, 0.0));
            let series = SeriesNormal::new(hertz, 2.5e-8);
            for delta in [1e-9, 3.3e-7, 2e-6] {
                let (f, k, root) = series.force_stiffness_and_root(delta);
                assert_eq!((f, k), series.force_and_stiffness(delta));
                assert_eq!(root, load_root(f));
            }
        }
        // A circle's semi-axis from the root: a = sqrt(R delta).
        let (r, delta) = (5e-3, 3.3e-7);
        let circle = SeriesNormal::new(HertzLaw::circular(r, 115.4e9), 0.0);
        let a = circle.hertz.major_semi_axis_of_root(circle.force_stiffness_and_root(delta).2);
        assert!((a / (r * delta).sqrt() - 1.0).abs() < 1e-14);
    }
}
