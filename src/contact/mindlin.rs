//! Mindlin's tangential stiffness of a Hertz contact without slip, exact for
//! an ellipse, as a 2x2 stiffness aligned with the ellipse axes.
//!
//! Mindlin (1949); Johnson, *Contact Mechanics* (1985), §7.2: a tangential
//! force Q along an axis of the contact ellipse (semi-axes a >= b, k' = b/a,
//! m = 1 - k'^2) with the traction q = Q / (2 pi a b) (1 - x^2/a^2 - y^2/b^2)^(-1/2)
//! displaces the contact area rigidly. Superposing Cerruti's point-force
//! displacement u_x = Q/(2 pi G r) [(1 - nu) + nu cos^2 theta] over the ellipse
//! gives, per body, the compliance
//!
//! ```text
//! C = 1/(8 pi a b G) int_0^2pi R(theta) [(1 - nu) + nu cos^2 theta] dtheta     (along a)
//!   = K(m) / (2 pi a G) [(1 - nu) + nu (K - E)/(m K)]
//! C = K(m) / (2 pi a G) [1 - nu (K - E)/(m K)]                                 (along b)
//! ```
//!
//! (R(theta) the ellipse's radius in direction theta; the integrals
//! int R dtheta = 4 b K and int R cos^2 theta dtheta = 4 b (K - E)/m).
//! The pair's stiffness is 1 / (C_1 + C_2). For a circle (K = pi/2,
//! (K - E)/(m K) -> 1/2) both give k_t = 8 G* a with 1/G* = sum (2 - nu)/G.
//! The contact is stiffer across its minor axis: for the 5 mm steel ball on
//! the 2 mm steel pin (b/a = 0.436) k_minor = 1.08 and k_major = 1.008 times
//! the equal-area circle's 8 G* sqrt(a b), 7 % apart.

use nalgebra::{Matrix2, Matrix3, Vector2, Vector3};
use simba::simd::SimdBool;
use std::f64::consts::PI;

use super::elliptic::EllipticIntegrals;
use crate::lane::{Both, Lane, Mask, branch, lift, splat};
use crate::material::Material;

/// k_t / a along the major and the minor axis [N/m^2] for the materials of
/// a pair and the ellipse shape k' = b/a (1: circle), so that k_t = coef a.
pub fn mindlin_axis_coefficients(m1: &Material, m2: &Material, kp: f64) -> [f64; 2] {
    let ell = EllipticIntegrals::from_kp(kp.min(1.0));
    let s = ell.s_over_m; // (K - E) / (m K)
    let per_body = |m: &Material| {
        let (g, nu) = (m.shear_modulus(), m.poisson_ratio);
        let c = ell.k / (2.0 * PI * g);
        [c * ((1.0 - nu) + nu * s), c * (1.0 - nu * s)]
    };
    let (c1, c2) = (per_body(m1), per_body(m2));
    [1.0 / (c1[0] + c2[0]), 1.0 / (c1[1] + c2[1])]
}

/// The 3x3 tangential stiffness k_major e1 e1^T + k_minor e2 e2^T in the
/// tangent plane of the unit normal `n`, e1 the major axis (`major_axis`
/// projected into the plane; any direction for a circle), e2 = n x e1.
pub fn tangential_tensor(k: [f64; 2], n: &Vector3<f64>, major_axis: &Vector3<f64>) -> Matrix3<f64> {
    PrincipalStiffness::new(k, n, major_axis).tensor(n)
}

/// Mindlin's tangential stiffness by its principal values and axes, as
/// [`tangential_tensor`] builds it, so that the return mapping needs no
/// eigen-decomposition: `axes` is `None` for a circular contact
/// (K_t = k (I - n n^T), equal principal values), else the unit axes
/// (e1, e2) in the tangent plane with K_t = k_1 e1 e1^T + k_2 e2 e2^T.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PrincipalStiffness<T: Lane = f64> {
    pub k: [T; 2],
    pub axes: Option<[Vector3<T>; 2]>,
}

impl PrincipalStiffness {
    /// Principal values `k` (major, minor) about the unit normal `n`, the
    /// major axis along `major_axis` projected into the tangent plane.
    #[inline(always)]
    pub fn new(k: [f64; 2], n: &Vector3<f64>, major_axis: &Vector3<f64>) -> Self {
        match Self::of_lanes(k, n, major_axis) {
            Some(p) => p,
            None => unreachable!("one lane takes one form"),
        }
    }
}

impl<T: Lane> PrincipalStiffness<T> {
    /// [`PrincipalStiffness::new`] over lanes, one stiffness per lane;
    /// `None` where some lanes are circles and others ellipses (the form
    /// is the contact's: a lane that differs is reseated alone).
    #[inline(always)]
    pub fn of_lanes(k: [T; 2], n: &Vector3<T>, major_axis: &Vector3<f64>) -> Option<Self> {
        // A circular contact: equal principal values (to rounding: the two
        // may be computed by different formulas), or no major axis to orient
        // an ellipse by. Both values are then the mean, K_t = k (I - n n^T)
        // (0.5 (k + k) is k exactly).
        let circle = PrincipalStiffness { k: [splat::<T>(0.5) * (k[0] + k[1]); 2], axes: None };
        let round = equal_to_rounding(k);
        if round.all() || *major_axis == Vector3::zeros() {
            // (The zero axis would fail the length test below as well.)
            return Some(circle);
        }
        if round.any() {
            return None;
        }
        let major = lift(major_axis);
        let in_plane = major - n * n.dot(&major);
        let length = in_plane.norm();
        let short = length.simd_le(splat(1e-12 * major_axis.norm()));
        if short.all() {
            return Some(circle);
        }
        if short.any() {
            return None;
        }
        let e1 = in_plane / length;
        Some(PrincipalStiffness { k, axes: Some([e1, n.cross(&e1)]) })
    }

    /// The 3x3 tensor K_t in the tangent plane of `n`.
    #[inline]
    pub fn tensor(&self, n: &Vector3<T>) -> Matrix3<T> {
        let delta = |i, j| splat::<T>(if i == j { 1.0 } else { 0.0 });
        match self.axes {
            // k (I - n n^T) and k1 e1 e1^T + k2 e2 e2^T, entry by entry.
            None => Matrix3::from_fn(|i, j| self.k[0] * (delta(i, j) - n[i] * n[j])),
            Some([e1, e2]) => {
                Matrix3::from_fn(|i, j| self.k[0] * e1[i] * e1[j] + self.k[1] * e2[i] * e2[j])
            }
        }
    }

    /// The closest point to `trial` on |F| = `limit` in the
    /// complementary-energy norm of K_t (in the tangent plane of `n`). For a circular contact this is the radial return in closed form
    /// (the map of [`project_on_circle`] with equal k, where g = (T/L - 1)/k
    /// and A = L/T exactly):
    /// ```text
    /// F = L t,   dF/dF_trial = (L/T) (I - n n^T - t t^T),   dF/dL = t
    /// T = |F_trial - n (n . F_trial)|,  t = (F_trial - n (n . F_trial)) / T
    /// ```
    /// An elliptical contact projects in its principal axes by
    /// [`project_on_circle`]. Returns (F, dF/dF_trial, dF/dL).
    #[inline(always)]
    pub fn project(
        &self,
        n: &Vector3<T>,
        trial: &Vector3<T>,
        limit: T,
    ) -> (Vector3<T>, Matrix3<T>, Vector3<T>) {
        match self.axes {
            None => {
                let r = RadialReturn::new(n, trial, limit);
                (r.force(), r.scaled_plane(n, r.ratio), r.t)
            }
            Some([e1, e2]) => {
                let local = Vector2::new(e1.dot(trial), e2.dot(trial));
                let (f, d, d_limit) = project_on_circle(self.k, &local, limit);
                // E f, E d E^T and E d_limit with E = [e1 e2] (3x2):
                // (E d)_ik = e1_i d_0k + e2_i d_1k, then
                // (E d E^T)_ij = (E d)_i0 e1_j + (E d)_i1 e2_j.
                let in_3d = |v: &Vector2<T>| Vector3::from_fn(|i, _| e1[i] * v.x + e2[i] * v.y);
                let column = |k: usize| Vector2::new(d[(0, k)], d[(1, k)]);
                let ed = [in_3d(&column(0)), in_3d(&column(1))];
                let d_trial = Matrix3::from_fn(|i, j| ed[0][i] * e1[j] + ed[1][i] * e2[j]);
                (in_3d(&f), d_trial, in_3d(&d_limit))
            }
        }
    }
}

/// Whether two principal values are equal but for rounding (within 1e-12
/// of the larger): the contact is then circular (the two may be computed
/// by different formulas that agree mathematically). Per lane for lanes.
#[inline]
pub fn equal_to_rounding<T: Lane>(k: [T; 2]) -> Mask<T> {
    let larger = k[0].simd_abs().simd_max(k[1].simd_abs());
    (k[0] - k[1]).simd_abs().simd_le(splat::<T>(1e-12) * larger)
}

/// The radial return of a circular contact onto |F| = L
/// ([`PrincipalStiffness::project`] without axes): the unit direction
/// t = (F_trial - n (n . F_trial)) / T of the trial force in the tangent
/// plane, T its length, the limit L (negative taken as 0) and the ratio
/// L/T, so that F = L t and dF/dF_trial = (L/T) (I - n n^T - t t^T).
#[derive(Debug, Clone, Copy)]
pub struct RadialReturn<T: Lane = f64> {
    pub t: Vector3<T>,
    pub limit: T,
    /// L / T.
    pub ratio: T,
}

impl<T: Lane> RadialReturn<T> {
    #[inline]
    pub fn new(n: &Vector3<T>, trial: &Vector3<T>, limit: T) -> Self {
        let in_plane = trial - n * n.dot(trial);
        let norm = in_plane.norm();
        let limit = limit.simd_max(T::zero());
        RadialReturn { t: in_plane / norm, limit, ratio: limit / norm }
    }

    /// F = L t.
    #[inline]
    pub fn force(&self) -> Vector3<T> {
        self.t * self.limit
    }

    /// s (I - n n^T - t t^T), entry by entry: the projector onto the
    /// tangent plane without t, scaled (s = L/T is dF/dF_trial).
    #[inline]
    pub fn scaled_plane(&self, n: &Vector3<T>, s: T) -> Matrix3<T> {
        let t = &self.t;
        let delta = |i, j| splat::<T>(if i == j { 1.0 } else { 0.0 });
        Matrix3::from_fn(|i, j| s * (delta(i, j) - n[i] * n[j] - t[i] * t[j]))
    }
}

/// Eigenvalues and unit eigenvectors (columns) of a symmetric 2x2 matrix.
pub fn symmetric_eigen2(m: &Matrix2<f64>) -> ([f64; 2], Matrix2<f64>) {
    let (a, b, c) = (m[(0, 0)], 0.5 * (m[(0, 1)] + m[(1, 0)]), m[(1, 1)]);
    if b.abs() <= 1e-15 * (a.abs() + c.abs()) {
        return ([a, c], Matrix2::identity());
    }
    let mean = 0.5 * (a + c);
    let r = (0.25 * (a - c) * (a - c) + b * b).sqrt();
    let l1 = mean + r;
    let v1 = Vector2::new(b, l1 - a).normalize();
    let v2 = Vector2::new(-v1.y, v1.x);
    ([l1, mean - r], Matrix2::from_columns(&[v1, v2]))
}

/// The closest point to a trial force on the friction circle |F| = L in the
/// complementary-energy norm of an elastic stiffness with principal values
/// `k` (in its principal axes): the return mapping of Coulomb slip with
/// anisotropic elasticity and associated slip. With F = F_trial - K dslip and
/// dslip = lambda F/|F| (the slip opposite the friction force on the body;
/// Simo & Hughes, *Computational Inelasticity*, 1998, §2.2; Wriggers,
/// *Computational Contact Mechanics*, 2006, §5.2):
///
/// ```text
/// F_i = F_trial,i / (1 + g k_i),   g = lambda/|F| >= 0 such that |F| = L
/// dF/dF_trial = A - (k A F)(A F)^T / h,   dF/dL = L (k A F) / h
/// A = diag(1/(1 + g k_i)), h = sum k_i A_i F_i^2
/// ```
///
/// For equal k_i (equal but for rounding, [`equal_to_rounding`]) it is the
/// radial return F = L F_trial/|F_trial|, formed in closed form. Requires
/// |F_trial| > L >= 0 (L = 0: F = 0). g by Newton from (|F_trial|/L - 1)/k_max, a lower
/// bound from which the convex, decreasing |F(g)|^2 - L^2 converges
/// monotonically. Returns (F, dF/dF_trial, dF/dL).
///
/// Written over [`Lane`]s: for f64 lanes, each lane takes the branch its
/// own values select ([`branch`]), and its Newton iteration stops where
/// that lane's would (a lane that has converged keeps its g while the
/// others go on), so that lane i is bit for bit the f64 map of lane i's
/// inputs.
#[inline]
pub fn project_on_circle<T: Lane>(
    k: [T; 2],
    trial: &Vector2<T>,
    limit: T,
) -> (Vector2<T>, Matrix2<T>, Vector2<T>) {
    let frictionless = limit.simd_le(T::zero());
    let Both(f, Both(d_trial, d_limit)) = branch::<T, _>(
        frictionless,
        // Frictionless: F = 0, and dF/dL along K^-1 F_trial (the limit g -> inf).
        |_| {
            let dir = Vector2::new(trial.x / k[0], trial.y / k[1]).normalize();
            Both(Vector2::zeros(), Both(Matrix2::zeros(), dir))
        },
        |limited| {
            branch::<T, _>(
                equal_to_rounding(k),
                // A circle: the radial return in closed form, F = L t with
                // t = F_trial/T, dF/dF_trial = (L/T) (I - t t^T), dF/dL = t.
                |_| {
                    let norm = trial.norm();
                    let t = trial / norm;
                    let d = (Matrix2::identity() - t * t.transpose()) * (limit / norm);
                    Both(t * limit, Both(d, t))
                },
                |ellipse| project_on_ellipse(k, trial, limit, limited & ellipse),
            )
        },
    );
    (f, d_trial, d_limit)
}

/// [`project_on_circle`] for unequal k, in the lanes of `active` (the
/// others' results are left to the caller to discard).
#[inline]
fn project_on_ellipse<T: Lane>(
    k: [T; 2],
    trial: &Vector2<T>,
    limit: T,
    mut active: Mask<T>,
) -> Both<Vector2<T>, Both<Matrix2<T>, Vector2<T>>> {
    let (one, k_max) = (T::one(), k[0].simd_max(k[1]));
    let mut g = (trial.norm() / limit - one) / k_max;
    for _ in 0..60 {
        let (mut phi, mut dphi) = (-limit * limit, T::zero());
        for i in 0..2 {
            let a = one / (one + g * k[i]);
            let f = a * trial[i];
            phi += f * f;
            dphi -= splat::<T>(2.0) * k[i] * a * f * f;
        }
        let step = phi / dphi;
        g = (g - step).select(active, g);
        // Converged once the step in u = g k_max is below 1e-9 (1 + u).
        // Newton's error after a step e is about 3 e^2 / (1 + u) in u
        // (phi''/(2 phi') of the curve above), so the step just taken
        // leaves an error below 3e-18 (1 + u): rounding, and no step is
        // needed to confirm it (the rule was 1e-15 (1 + u), one step more:
        // 2.78 steps a call in scene 02's seatings, now 1.91, and its
        // study 5 % faster). The rule is relative to 1 + u, not to g:
        // phi is known to a few ulps of L^2 only, so near the root g moves
        // by ~eps (1 + u) / k_max per step in that noise (a rule of 1e-15 g
        // ran to the 60-step cap where |F_trial| is within ~5 % of L).
        // A lane that has converged keeps its g from here on.
        let done = (step.simd_abs() * k_max).simd_le(splat::<T>(1e-9) * (one + g * k_max));
        active = active & !done;
        if active.none() {
            break;
        }
    }
    let a = Vector2::new(one / (one + g * k[0]), one / (one + g * k[1]));
    let f = a.component_mul(trial);
    let af = a.component_mul(&f);
    let kaf = Vector2::new(k[0] * af.x, k[1] * af.y);
    let h = kaf.dot(&f);
    let d_trial = Matrix2::from_diagonal(&a) - kaf * af.transpose() / h;
    Both(f, Both(d_trial, kaf * (limit / h)))
}
