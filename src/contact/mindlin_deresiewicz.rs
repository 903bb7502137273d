//! Mindlin-Deresiewicz partial slip for any history of normal and tangential
//! load, by the method of dimensionality reduction (MDR).
//!
//! Popov & Hess, *Method of Dimensionality Reduction in Contact Mechanics and
//! Friction* (Springer 2015), ch. 3 and 7; Mindlin & Deresiewicz (1953);
//! Johnson, *Contact Mechanics* (1985), §7.3-7.4. An axisymmetric contact
//! of radius a is mapped to a row of independent springs on the 1-D profile
//! g(x) = x^2 / R, each with its own Coulomb limit. With 1/G* = sum (2 - nu)/G
//! (so that k_t = 8 G* a) and the row's normal line load of a Hertz contact,
//!
//! ```text
//! tangential line stiffness 4 G*,   line load p(x) = 3 P / (4 a) (1 - x^2/a^2)
//! |u(x)| <= mu p(x) / (4 G*) = delta* (1 - x^2/a^2),   delta* = 3 mu P / (16 G* a)
//! Q = 4 G* int_-a^a u(x) dx
//! ```
//!
//! A spring entering the contact (a grows) starts with u = 0; one leaving it
//! (a shrinks) loses its displacement; a spring whose limit falls below |u|
//! slides to the limit. This is exact for axisymmetric contacts under
//! arbitrary P-Q histories of fixed direction (Popov & Hess 2015, §7.2),
//! and reproduces Cattaneo's curve, the Masing loop of Mindlin & Deresiewicz
//! and s = 1.5 Q / (8 G* a) for proportional loading from zero.
//!
//! Approximations, stated:
//! - Direction: each spring carries a 2-D displacement with a circular
//!   Coulomb limit (closest-point return in the complementary-energy norm of its
//!   stiffness: radial for a circle). For a tangential load that changes
//!   direction this is the MDR's usual extension, not an exact solution.
//! - Ellipse: the row keeps the equal-area radius a = sqrt(a b) (so the
//!   limits sum to mu P exactly) and its springs get the anisotropic
//!   stiffness 4 G* C, C = K_t / (8 G* sqrt(a b)) from Mindlin's exact 2x2
//!   elliptical stiffness K_t (`contact::mindlin`); the friction limit stays
//!   circular. For a circle C = I and the law is the MDR exactly.
//! - Space: the row on 0 <= x <= a (the problem is symmetric in x) is cut
//!   into `SPRINGS` equal cells of width h, each a spring at its cell
//!   average of u, weighted by the fraction of the cell in contact, with its
//!   limit integrated exactly over that fraction. h is fixed at first
//!   contact so that a fills 3/4 of the row; when a outgrows the row, cells
//!   are merged in pairs (which keeps Q exactly). So N/2 to N springs carry
//!   a loaded contact (fewer after a large unloading). The error is that of
//!   lumping each cell's slip: largest when the slip annulus is about one
//!   cell wide (tests/it/contact_laws.rs prints the measured errors).
//! - Time: a step from P_old to P with increment du is split as
//!   normal(P_old -> P), then tangential(du) at P, each spring taking its
//!   share of du ([`Row::share`]: all of it if it was in contact at the
//!   start, (a1^2 - x^2)/(a1^2 - a0^2) if it entered during the step):
//!   exact along a proportional increment (P and Q linear in the step) for
//!   a sticking contact, exact for a sliding one (Q = mu P at the end of
//!   the step). A
//!   split with the tangential stage at the mid load is second order but
//!   leaves a spring that slid at the mid load below its end limit
//!   (Q = mu (P - dP/2) in a sliding V groove), and pinning it there makes
//!   the law discontinuous for Newton's method.
//! - Static to dynamic: the limits use mu_s until every spring slides in
//!   the tangential stage of a step (gross slip), then mu_d (the sudden
//!   switch of the Coulomb law), and mu_s again once a spring sticks.

use nalgebra::{Matrix2, Matrix3, Matrix3x2, Vector2, Vector3};

use super::mindlin::{project_on_circle, symmetric_eigen2};
pub use super::tangential_types::{SPRINGS, SpringRow};
use super::tangential_types::{SlipState, TangentialInput, TangentialResponse, TangentialState};

/// The fraction of the row that the contact fills at first contact.
const FIRST_FILL: f64 = 0.75;

/// The contact during one update: its constants and the row being updated
/// with the derivative of each cell's q by the tangential increment.
struct Row {
    q: [Vector2<f64>; SPRINGS],
    d: [Matrix2<f64>; SPRINGS],
    h: f64,
    /// Equal-area radius at the current stage [m].
    a: f64,
    /// Current friction coefficient.
    mu: f64,
    g_star: f64,
    /// Principal values and axes (columns) of the shape C in the frame.
    c: [f64; 2],
    axes: Matrix2<f64>,
    /// Each cell's share of the step's tangential increment and its limit
    /// at the end of the normal stage (the tangential stage, at the same
    /// load and radius, reads them): the share is the cell's weight, less
    /// for the springs that entered during the step ([`Row::share`]).
    stage: [(f64, f64); SPRINGS],
    /// The radius at the start of the step [m].
    a_start: f64,
    /// The step's tangential increment in the frame, C du.
    increment: Vector2<f64>,
}

impl Row {
    /// Fraction of cell j inside 0 <= x <= a.
    fn weight(&self, j: usize, a: f64) -> f64 {
        ((a - j as f64 * self.h) / self.h).clamp(0.0, 1.0)
    }

    /// Cell j's share of a step's tangential increment when the radius grows
    /// from `a0` to `a1` along a proportional increment (P and Q linear in
    /// the step): a spring at x < a0 takes all of it; one at a0 < x < a1
    /// enters when a = x, after the part w(x) = (x^2 - a0^2)/(a1^2 - a0^2)
    /// of the displacement (du ~ dP / a under force control, and P^(2/3) ~
    /// a^2), so it takes (a1^2 - x^2)/(a1^2 - a0^2). Averaged over the cell
    /// (width h, exact integral). From zero this gives Q = (16/3) G* a du,
    /// s = 1.5 Q / (8 G* a), Mindlin's proportional loading exactly.
    fn share(&self, j: usize, a0: f64, a1: f64) -> f64 {
        let (x0, x1) = (j as f64 * self.h, ((j + 1) as f64 * self.h).min(a1));
        if x1 <= x0 {
            return 0.0;
        }
        if a1 <= a0 {
            return (x1 - x0) / self.h;
        }
        let inside = (x1.min(a0) - x0).max(0.0);
        let (r0, r1) = (x0.max(a0), x1);
        let ring = if r1 > r0 {
            let f = |x: f64| a1 * a1 * x - x * x * x / 3.0;
            (f(r1) - f(r0)) / (a1 * a1 - a0 * a0)
        } else {
            0.0
        };
        (inside + ring) / self.h
    }

    /// Cell j's limit of |q| at load p and radius a: delta* times the cell
    /// average of (1 - x^2/a^2) over its part in contact.
    fn limit(&self, j: usize, p: f64, a: f64) -> f64 {
        self.limit_at(j, a, self.delta_star(p, a))
    }

    /// delta* = 3 mu p / (16 G* a), the part of [`Self::limit`] common to
    /// all cells (computed once per sweep over the row).
    fn delta_star(&self, p: f64, a: f64) -> f64 {
        3.0 * self.mu * p / (16.0 * self.g_star * a)
    }

    /// [`Self::limit`] with delta* given.
    fn limit_at(&self, j: usize, a: f64, delta_star: f64) -> f64 {
        let x0 = j as f64 * self.h;
        let x1 = ((j + 1) as f64 * self.h).min(a);
        if x1 <= x0 {
            return 0.0;
        }
        let integral = (x1 - x0) - (x1.powi(3) - x0.powi(3)) / (3.0 * a * a);
        delta_star * integral / self.h
    }

    /// Cap cell j at `limit`, chaining the derivative: the closest point in
    /// the complementary-energy norm of C (`mindlin::project_on_circle`), so
    /// that a spring slides opposite to its force (for a circle the radial
    /// return, which the map forms in closed form).
    /// Returns whether it capped, and |q| before.
    fn cap(&mut self, j: usize, limit: f64) -> (bool, f64) {
        let norm = self.q[j].norm();
        if norm <= limit {
            return (false, norm);
        }
        if limit <= 0.0 {
            self.q[j] = Vector2::zeros();
            self.d[j] = Matrix2::zeros();
            return (true, norm);
        }
        let r = self.axes;
        let (f, m, _) = project_on_circle(self.c, &(r.transpose() * self.q[j]), limit);
        self.q[j] = r * f;
        self.d[j] = r * m * r.transpose() * self.d[j];
        (true, norm)
    }

    /// Merge cells in pairs until the row (width SPRINGS h) holds radius a.
    fn fit(&mut self, a: f64) {
        while a > SPRINGS as f64 * self.h {
            for j in 0..SPRINGS {
                let (q, d) = if 2 * j + 1 < SPRINGS {
                    (
                        0.5 * (self.q[2 * j] + self.q[2 * j + 1]),
                        0.5 * (self.d[2 * j] + self.d[2 * j + 1]),
                    )
                } else {
                    (Vector2::zeros(), Matrix2::zeros())
                };
                self.q[j] = q;
                self.d[j] = d;
            }
            self.h *= 2.0;
        }
    }

    /// Normal stage: the radius goes from `self.a` to `a` at load `p`.
    fn normal(&mut self, p: f64, a: f64) {
        self.fit(a);
        let delta_star = self.delta_star(p, a);
        self.a_start = self.a;
        for j in 0..SPRINGS {
            let (w_old, w_new) = (self.weight(j, self.a), self.weight(j, a));
            self.stage[j].0 = self.share(j, self.a, a);
            if w_new == 0.0 {
                self.q[j] = Vector2::zeros();
                self.d[j] = Matrix2::zeros();
                continue;
            }
            if w_new < w_old {
                // The part leaving the contact takes its share of u along.
                let s = w_new / w_old;
                self.q[j] *= s;
                self.d[j] *= s;
            }
            let l = self.limit_at(j, a, delta_star);
            self.stage[j].1 = l;
            self.cap(j, l);
        }
        self.a = a;
    }

    /// Tangential stage, after [`Self::normal`] (whose end load and radius
    /// it keeps: each cell's share and limit are the normal stage's):
    /// every cell in contact moves by its share of C du. Returns whether
    /// every cell in contact is then at its limit (gross slip).
    fn tangential(&mut self, c: &Matrix2<f64>, du: &Vector2<f64>) -> bool {
        self.increment = c * du;
        let mut all_capped = true;
        for j in 0..SPRINGS {
            let (w, l) = self.stage[j];
            if w == 0.0 {
                continue;
            }
            self.q[j] += w * c * du;
            self.d[j] += w * c;
            let (capped, norm) = self.cap(j, l);
            all_capped &= capped || norm >= l * (1.0 - 1e-12);
        }
        all_capped
    }

    /// The sudden static-to-dynamic switch: every spring's value (and its
    /// derivative) scaled by mu_d / mu_s = `scale`, the limits to `mu_d`.
    fn switch_to(&mut self, scale: f64, mu_d: f64) {
        self.q.iter_mut().for_each(|q| *q *= scale);
        self.d.iter_mut().for_each(|d| *d *= scale);
        self.mu = mu_d;
    }

    /// Q in the frame: 8 G* h sum q, and its derivative by du.
    fn force(&self) -> (Vector2<f64>, Matrix2<f64>) {
        let k = 8.0 * self.g_star * self.h;
        let q: Vector2<f64> = self.q.iter().sum();
        let d: Matrix2<f64> = self.d.iter().sum();
        (k * q, k * d)
    }
}

/// A unit vector perpendicular to `n`, preferring `hint` projected.
fn tangent_frame(n: &Vector3<f64>, hint: &Vector3<f64>) -> Vector3<f64> {
    let p = hint - n * n.dot(hint);
    if p.norm() > 1e-9 * hint.norm() && hint.norm() > 0.0 {
        return p.normalize();
    }
    let e = if n.x.abs() < 0.9 { Vector3::x() } else { Vector3::y() };
    (e - n * n.dot(&e)).normalize()
}

/// The row's response to a trial increment (module docs) into `out`, with
/// its consistent tangent if `tangent`; the increment is `input.du`
/// without its normal part.
pub(super) fn update(
    old: &TangentialState,
    input: &TangentialInput,
    tangent: bool,
    out: &mut TangentialResponse,
) {
    let n = input.normal;
    let proj = &(Matrix3::identity() - n * n.transpose());
    let du = &(proj * input.du);
    let p = input.normal_force;
    let a_now = input.contact_radius;
    let radius_at = |load: f64| a_now * (load.max(0.0) / p).cbrt();
    let (st, fresh) = committed_row(old, du, a_now);
    let t1 = tangent_frame(&n, &st.frame);
    let basis = Matrix3x2::from_columns(&[t1, n.cross(&t1)]);
    let c = basis.transpose() * input.mindlin_shape * basis;
    let (c_principal, c_axes) = symmetric_eigen2(&c);
    let du2 = basis.transpose() * du;
    let friction = input.friction;
    let mut row = Row {
        q: st.q.map(|q| Vector2::new(q[0], q[1])),
        d: [Matrix2::zeros(); SPRINGS],
        h: st.h,
        a: radius_at(old.normal_force),
        mu: if old.sliding { friction.mu_d } else { friction.mu_s },
        g_star: input.g_star,
        c: c_principal,
        axes: c_axes,
        stage: [(0.0, 0.0); SPRINGS],
        a_start: 0.0,
        increment: Vector2::zeros(),
    };
    if fresh && old.force.norm() > 0.0 {
        rebuild(&mut row, &(basis.transpose() * old.force), old.normal_force);
    }
    // The normal load first, then the tangential increment at the end load
    // (so a sliding spring ends exactly at its limit mu p(x)).
    row.normal(p, a_now);
    let gross = row.tangential(&c, &du2);
    if gross && !old.sliding && friction.mu_d < friction.mu_s {
        row.switch_to(friction.mu_d / friction.mu_s, friction.mu_d);
    }
    let (f2, d2) = row.force();
    let force = basis * f2;
    let (d_force_d_du, d_fn) = tangent_of(tangent, &row, p, &basis, &d2, proj);
    let mut q = [[0.0; 2]; SPRINGS];
    for (dst, src) in q.iter_mut().zip(&row.q) {
        *dst = [src.x, src.y];
    }
    *out = TangentialResponse {
        force,
        state: TangentialState {
            force,
            sliding: gross,
            row: Some(Box::new(SpringRow { frame: t1, h: row.h, q })),
            normal_force: p,
            ..TangentialState::new(n)
        },
        slip: if gross { SlipState::Slip } else { SlipState::Stick },
        d_force_d_du,
        d_force_d_fn: d_fn,
    };
}

/// The committed spring row of `old`, and whether it is fresh: at first
/// contact a row with its frame along the old force (or the increment
/// `du`) and cells so wide that the contact of radius `a_now` fills
/// `FIRST_FILL` of it.
fn committed_row(old: &TangentialState, du: &Vector3<f64>, a_now: f64) -> (SpringRow, bool) {
    let mut st = old.row.as_deref().copied().unwrap_or_default();
    let fresh = st.h == 0.0;
    if fresh {
        let hint = if old.force.norm() > 0.0 { old.force } else { *du };
        st.frame = tangent_frame(&old.normal, &hint);
        st.h = a_now / (FIRST_FILL * SPRINGS as f64);
    }
    (st, fresh)
}

/// The consistent tangent (dQ/d(du), dQ/dP) of the row at the end of the
/// step if `tangent` (zeros otherwise: a converged Newton iterate never
/// reads it): E D E^T P from the 2-D tangent D of the springs, and
/// [`d_force_d_load`].
fn tangent_of(
    tangent: bool,
    row: &Row,
    p: f64,
    basis: &Matrix3x2<f64>,
    d2: &Matrix2<f64>,
    proj: &Matrix3<f64>,
) -> (Matrix3<f64>, Vector3<f64>) {
    if !tangent {
        return (Matrix3::zeros(), Vector3::zeros());
    }
    (basis * d2 * basis.transpose() * proj, d_force_d_load(row, p, basis))
}

/// dQ/dP at fixed displacement: the springs at their limit at the end of
/// the step (their limit grows with P), and the others by their share of
/// the increment (it grows with the end radius for the springs that
/// entered during the step, [`Row::share`]). Central differences of the
/// closed-form cell limit and share.
fn d_force_d_load(row: &Row, p: f64, basis: &Matrix3x2<f64>) -> Vector3<f64> {
    let eps = 1e-6 * p;
    let (a_p, a_m) = (row.a * ((p + eps) / p).cbrt(), row.a * ((p - eps) / p).cbrt());
    let mut sum = Vector2::zeros();
    let delta_star =
        [row.delta_star(p, row.a), row.delta_star(p + eps, a_p), row.delta_star(p - eps, a_m)];
    for j in 0..SPRINGS {
        let l = row.limit_at(j, row.a, delta_star[0]);
        let norm = row.q[j].norm();
        if l > 0.0 && norm >= l * (1.0 - 1e-12) {
            let dl = (row.limit_at(j, a_p, delta_star[1]) - row.limit_at(j, a_m, delta_star[2]))
                / (2.0 * eps);
            sum += row.q[j] / norm * dl;
        } else if l > 0.0 {
            let a0 = row.a_start;
            let ds = (row.share(j, a0, a_p) - row.share(j, a0, a_m)) / (2.0 * eps);
            sum += row.increment * ds;
        }
    }
    basis * (8.0 * row.g_star * row.h * sum)
}

/// A row that carries `force` (in the frame) with no recorded history: the
/// state after a virgin (Cattaneo) loading at constant load `p` to that
/// force, found by bisection on the sticking displacement u (cell j carries
/// min(w_j u, L_j)); a force at or above the friction limit puts every cell
/// at its limit, scaled to the force.
fn rebuild(row: &mut Row, force: &Vector2<f64>, p: f64) {
    let q_total = force.norm();
    if p <= 0.0 || q_total == 0.0 {
        return;
    }
    let k = 8.0 * row.g_star * row.h;
    let cells: Vec<(f64, f64)> = (0..SPRINGS)
        .map(|j| (row.weight(j, row.a), row.limit(j, p, row.a)))
        .filter(|&(w, _)| w > 0.0)
        .collect();
    let carried = |u: f64| k * cells.iter().map(|&(w, l)| (w * u).min(l)).sum::<f64>();
    let u_all = cells.iter().map(|&(w, l)| l / w).fold(0.0, f64::max);
    let full = carried(u_all);
    let (u, scale) = if q_total >= full {
        (u_all, q_total / full)
    } else {
        let (mut lo, mut hi) = (0.0, u_all);
        for _ in 0..100 {
            let mid = 0.5 * (lo + hi);
            if carried(mid) < q_total {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        (0.5 * (lo + hi), 1.0)
    };
    let dir = force / q_total;
    for j in 0..SPRINGS {
        let (w, l) = (row.weight(j, row.a), row.limit(j, p, row.a));
        row.q[j] = dir * ((w * u).min(l) * scale);
    }
}
