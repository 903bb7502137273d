//! Cattaneo-Mindlin partial slip: a sticking core and a slipping annulus,
//! with Masing's rule on load reversal.
//!
//! Cattaneo (1938), Mindlin (1949), Mindlin & Deresiewicz (1953); Johnson,
//! *Contact Mechanics* (1985), eqs. 7.48-7.60. For a constant normal load P
//! and a tangential displacement s growing in one direction (virgin curve):
//! ```text
//! Q(s)  = mu P (1 - (1 - s/delta*)^(3/2)),   s < delta* = 3 mu P / (16 G* a)
//! dQ/ds = 8 G* a (1 - s/delta*)^(1/2)       (Mindlin's k_t at s = 0)
//! ```
//! After a reversal at (s_r, Q_r) the branch follows Masing's rule,
//! Q = Q_r + 2 Q((s - s_r)/2), until gross slip, where the Coulomb law with
//! the sudden static-to-dynamic switch takes over. mu is mu_s on the
//! partial-slip branches. Simplifications, stated: the branch is applied in
//! vector form along the displacement since the last reversal (exact for a
//! straight tangential path), and P and a are the current values (exact for
//! a constant normal load; Mindlin & Deresiewicz treat varying P).

use nalgebra::{Matrix3, Vector3};

use super::tangential::{
    SlipState, TangentialInput, TangentialResponse, TangentialState, slide_response,
};

/// Virgin curve Q(x) / (mu P) and its slope, for x = s / delta*.
fn virgin(x: f64) -> (f64, f64) {
    let r = (1.0 - x).max(0.0);
    (1.0 - r * r.sqrt(), 1.5 * r.sqrt())
}

pub(super) fn update(
    old: &TangentialState,
    proj: &Matrix3<f64>,
    du: &Vector3<f64>,
    input: &TangentialInput,
) -> TangentialResponse {
    let fn_ = input.normal_force;
    let mu_s = input.friction.mu_s;
    let k0 = input.stiffness;
    // The branch this increment continues, or a new one after a reversal.
    let (base, s_old, c) = if old.sliding {
        let trial = old.force + k0 * du;
        if trial.norm() > input.friction.mu_d * fn_ {
            return slide_response(old, proj, &trial, k0, du, input);
        }
        (old.force, Vector3::zeros(), 2.0)
    } else if old.since_reversal.norm() > 0.0 && old.since_reversal.dot(du) < 0.0 {
        (old.force, Vector3::zeros(), 2.0)
    } else {
        (old.reversal_force, old.since_reversal, old.masing)
    };
    let s = s_old + du;
    let s_norm = s.norm();
    let delta_star = 3.0 * mu_s * fn_ / (16.0 * input.g_star * input.contact_radius);
    let x = s_norm / c / delta_star;
    if s_norm == 0.0 {
        return TangentialResponse {
            force: base,
            state: TangentialState {
                force: base,
                sliding: false,
                reversal_force: base,
                since_reversal: s,
                masing: c,
                ..*old
            },
            slip: SlipState::Stick,
            d_force_d_du: k0 * proj,
            d_force_d_fn: Vector3::zeros(),
        };
    }
    let dir = s / s_norm;
    let (q, dq) = virgin(x);
    let force = base + c * mu_s * fn_ * q * dir;
    if x >= 1.0 || force.norm() > mu_s * fn_ {
        return slide_response(old, proj, &force, k0, du, input);
    }
    // dF/ds = Q'(s/c) d d^T + c Q(s/c)/|s| (P - d d^T);  Q'(s/c) = mu P dq / delta*.
    let ddt = dir * dir.transpose();
    let slope = mu_s * fn_ * dq / delta_star;
    let tangent = slope * ddt + (c * mu_s * fn_ * q / s_norm) * (proj - ddt);
    // dQ/dP at fixed s with delta* ~ P^(2/3) (a ~ P^(1/3)): mu (q - x dq 2/3).
    let d_fn = c * mu_s * (q - x * dq * 2.0 / 3.0) * dir;
    TangentialResponse {
        force,
        state: TangentialState {
            force,
            sliding: false,
            reversal_force: base,
            since_reversal: s,
            masing: c,
            ..*old
        },
        slip: SlipState::Stick,
        d_force_d_du: tangent,
        d_force_d_fn: d_fn,
    }
}
