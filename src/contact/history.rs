//! One contact driven through a prescribed history of normal and tangential
//! load (force control), as `kinrepro contact --history` does it.
//!
//! Frame: the contact normal is z, x the major axis of the contact ellipse
//! (along the pin for sphere-cylinder), y the minor axis; Q = (Qx, Qy) is
//! the tangential force the ball exerts on the fixed body and s = (sx, sy)
//! the tangential displacement of the ball relative to the fixed body. Each
//! step solves F_t(s) = Q for the increment of s by Newton's method with the
//! law's consistent tangent, starting from the committed state (the laws are
//! displacement driven). The solvers' contact layer makes the same choices
//! (K_t integrated over the step's change of normal force; `solve::contact_layer`).
//!
//! Convergence: on a partial-slip branch Q(s) is concave along the motion,
//! so Newton from the elastic predictor approaches the root from below; a
//! step is converged when |F_t - Q| <= 1e-12 max(|Q|, mu P).

use nalgebra::{Matrix2, Matrix3, Vector2, Vector3};
use thiserror::Error;

use super::{
    ContactLaw, Friction, SlipState, TangentialInput, TangentialLaw, TangentialResponse,
    TangentialState,
};

/// One row of a load history: P [N] and Q = (Qx, Qy) [N].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LoadStep {
    pub normal_force: f64,
    pub tangential_force: [f64; 2],
}

/// The state after one step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HistoryStep {
    pub load: LoadStep,
    /// Tangential displacement (sx, sy) [m].
    pub displacement: [f64; 2],
    pub slip: SlipState,
}

/// Why a history cannot be followed. `step` counts from 1.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum HistoryError {
    #[error("step {step}: P_N = {value} N is invalid: the normal load must be positive and finite")]
    BadNormal { step: usize, value: f64 },
    #[error("step {step}: Q_N = {value} N is not finite")]
    BadTangential { step: usize, value: f64 },
    #[error(
        "step {step}: |Q| = {q} N reaches the friction limit {mu} P = {limit} N; under force control the contact would slide without bound"
    )]
    Slides { step: usize, q: f64, mu: f64, limit: f64 },
    #[error("step {step}: the tangential displacement did not converge (residual {residual} N)")]
    NoConvergence { step: usize, residual: f64 },
}

/// Drive one contact with Hertz/Mindlin law `law`, tangential law
/// `tangential` and friction `friction` through `history`, from the unloaded
/// state.
pub fn drive(
    law: &ContactLaw,
    tangential: TangentialLaw,
    friction: Friction,
    history: &[LoadStep],
) -> Result<Vec<HistoryStep>, HistoryError> {
    let n = Vector3::z();
    let mut state = TangentialState::new(n);
    let mut s = Vector3::zeros();
    let mut out = Vec::with_capacity(history.len());
    for (k, load) in history.iter().enumerate() {
        let step = k + 1;
        let p = load.normal_force;
        if !(p.is_finite() && p > 0.0) {
            return Err(HistoryError::BadNormal { step, value: p });
        }
        if let Some(&value) = load.tangential_force.iter().find(|q| !q.is_finite()) {
            return Err(HistoryError::BadTangential { step, value });
        }
        let q = Vector3::new(load.tangential_force[0], load.tangential_force[1], 0.0);
        let mu = if state.sliding { friction.mu_d } else { friction.mu_s };
        if q.norm() >= mu * p {
            return Err(HistoryError::Slides { step, q: q.norm(), mu, limit: mu * p });
        }
        let input = step_input(law, tangential, &state, p, friction);
        let (du, response) = solve_step(&state, tangential, &input, &q, mu * p)
            .map_err(|residual| HistoryError::NoConvergence { step, residual })?;
        state = response.state;
        state.normal_force = p;
        s += du;
        out.push(HistoryStep { load: *load, displacement: [s.x, s.y], slip: response.slip });
    }
    Ok(out)
}

/// The law's input at load `p` from `state` (zero increment), K_t of the
/// step from the committed to the new normal force as the solvers' contact
/// layer forms it.
fn step_input(
    law: &ContactLaw,
    tangential: TangentialLaw,
    state: &TangentialState,
    p: f64,
    friction: Friction,
) -> TangentialInput {
    let (n, x) = (Vector3::z(), Vector3::x());
    let (a_eff, dlog) = law.increment_semi_axis(state.normal_force, p);
    let (principal, stiffness, d_stiffness_d_fn) =
        law.increment_stiffness(a_eff, dlog, &n, &x, true);
    let (contact_radius, mindlin_shape) = law.mindlin_deresiewicz_inputs(tangential, p, &n, &x);
    TangentialInput {
        normal: n,
        du: Vector3::zeros(),
        normal_force: p,
        stiffness,
        principal,
        d_stiffness_d_fn,
        contact_radius,
        g_star: law.g_star,
        mindlin_shape,
        friction,
    }
}

/// Newton on the in-plane increment du with F_t(du) = q.
fn solve_step(
    state: &TangentialState,
    law: TangentialLaw,
    input: &TangentialInput,
    q: &Vector3<f64>,
    limit: f64,
) -> Result<(Vector3<f64>, TangentialResponse), f64> {
    let tol = 1e-12 * q.norm().max(limit);
    let plane = |m: &Matrix3<f64>| Matrix2::new(m[(0, 0)], m[(0, 1)], m[(1, 0)], m[(1, 1)]);
    let mut du = Vector3::zeros();
    let mut residual = f64::INFINITY;
    let mut r = TangentialResponse::open(input.normal);
    for _ in 0..200 {
        state.update(law, &TangentialInput { du, ..*input }, true, &mut r);
        let res = q - r.force;
        residual = res.norm();
        if residual <= tol {
            return Ok((du, r));
        }
        let k = plane(&r.d_force_d_du);
        let Some(step) = k.try_inverse().map(|ki| ki * Vector2::new(res.x, res.y)) else {
            break;
        };
        du += Vector3::new(step.x, step.y, 0.0);
    }
    Err(residual)
}

/// The header a history file must start with.
pub const HISTORY_HEADER: [&str; 3] = ["P_N", "Qx_N", "Qy_N"];

/// One parsed history row and the file line it came from (1-based).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct HistoryRow {
    pub line: usize,
    pub load: LoadStep,
}

/// Why a history file cannot be read; each names the file and, where there
/// is one, the line and the column.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum HistoryCsvError {
    #[error("{file}: empty history (expected the header `{}`)", HISTORY_HEADER.join(","))]
    Empty { file: String },
    #[error("{file}:{line}: header `{header}` must be `{}`", HISTORY_HEADER.join(","))]
    Header { file: String, line: usize, header: String },
    #[error("{file}:{line}: {count} fields, expected 3 ({})", HISTORY_HEADER.join(","))]
    FieldCount { file: String, line: usize, count: usize },
    #[error("{file}:{line}: column {column}: `{text}` is not a finite number")]
    NotANumber { file: String, line: usize, column: &'static str, text: String },
    #[error("{file}:{line}: column P_N: {value} N: the normal load must be positive")]
    NormalLoad { file: String, line: usize, value: f64 },
    #[error("{file}: no rows after the header")]
    NoRows { file: String },
}

/// Parse a history CSV: the header `P_N,Qx_N,Qy_N`, then one row per step
/// (P > 0 and Q finite, in N), read by [`crate::delimited`] (comma,
/// semicolon or tab, quoted fields, a byte-order mark, blank and `#` lines
/// skipped). Errors name `file`, the line and the column.
pub fn parse_history_csv(text: &str, file: &str) -> Result<Vec<HistoryRow>, HistoryCsvError> {
    let file = || file.to_string();
    let records = crate::delimited::read(text, None).records;
    let Some((header, rows)) = records.split_first() else {
        return Err(HistoryCsvError::Empty { file: file() });
    };
    if header.cells != HISTORY_HEADER {
        return Err(HistoryCsvError::Header {
            file: file(),
            line: header.line,
            // Escaped, so that an invisible character (a byte-order mark
            // U+FEFF, a NUL) shows in the message.
            header: header.text.escape_debug().to_string(),
        });
    }
    let mut out = Vec::new();
    for r in rows {
        let line = r.line;
        if r.cells.len() != 3 {
            return Err(HistoryCsvError::FieldCount { file: file(), line, count: r.cells.len() });
        }
        let mut v = [0.0; 3];
        for (k, f) in r.cells.iter().enumerate() {
            v[k] = f.parse::<f64>().ok().filter(|x| x.is_finite()).ok_or_else(|| {
                HistoryCsvError::NotANumber {
                    file: file(),
                    line,
                    column: HISTORY_HEADER[k],
                    text: f.to_string(),
                }
            })?;
        }
        if v[0] <= 0.0 {
            return Err(HistoryCsvError::NormalLoad { file: file(), line, value: v[0] });
        }
        out.push(HistoryRow {
            line,
            load: LoadStep { normal_force: v[0], tangential_force: [v[1], v[2]] },
        });
    }
    if out.is_empty() {
        return Err(HistoryCsvError::NoRows { file: file() });
    }
    Ok(out)
}
