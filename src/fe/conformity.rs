//! The conformity study of a gothic-arch contact: a ball of radius r in a
//! concave cylinder of radius R_g, at a fixed load, for R_g / r closing
//! towards 1. At each ratio the FE solves the contact twice on the same
//! mesh, with the exact gap of the two surfaces ([`Gap::exact`]) and with
//! Hertz's quadratic gap, and both are compared with kinrepro's Hertz law.
//! The quadratic-gap FE reproduces the Hertz law up to the mesh's
//! discretisation error, so the ratio exact / quadratic - 1 (the gap
//! effect) is the error of Hertz's quadratic gap alone; the study finds
//! the ratio at which its approach part reaches [`LIMIT`], by bisection in
//! log(R_g / r - 1) and linear interpolation in the final bracket. The
//! approach, not a semi-axis: the FE resolves a contact edge only to the
//! node spacing (9 % of the semi-axis on the default mesh, where both
//! gaps can give the same semi-axis), while the approach converges
//! smoothly with the mesh; the semi-axis parts are reported beside it.
//!
//! What it cannot show: both FE bodies are half-spaces, so the study
//! measures where the quadratic gap fails, not where the half-space
//! assumption of Hertz fails (that needs the finite ball and groove).

use serde::Serialize;

use super::pairs::{PairCase, fe_case};
use super::{FeError, FeResult, MeshOptions, hertz, solve_case};
use crate::contact::hertz::CONFORMITY_LIMIT;
use crate::contact::{ContactPair, ContactShape};

/// The ratios R_g / r of the study's table.
pub const RATIOS: [f64; 8] = [1.5, 1.1, 1.01, 1.003, 1.001, 1.0003, 1.0001, 1.00005];
/// The difference the study looks for.
pub const LIMIT: f64 = 0.02;
/// Bisection steps between the last table ratio below [`LIMIT`] and the first above.
pub const BISECTIONS: usize = 3;

/// One ratio of the study (SI units). Errors are FE/Hertz - 1; semi-axes
/// [along the groove (x, radius R_x = r), across it (y)].
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConformityRow {
    pub groove_over_ball: f64,
    pub groove_radius_m: f64,
    /// Hertz's major semi-axis over the smaller relative radius R_x = r,
    /// the measure of kinrepro's conformity warning.
    pub conformity: f64,
    pub hertz_approach_m: f64,
    pub hertz_semi_axes_m: [f64; 2],
    /// FE with the exact gap against Hertz.
    pub approach_error_rel: f64,
    pub semi_axes_error_rel: [f64; 2],
    /// FE with the quadratic gap against Hertz: the mesh's own error.
    pub quadratic_approach_error_rel: f64,
    pub quadratic_semi_axes_error_rel: [f64; 2],
    /// Exact-gap FE / quadratic-gap FE - 1: [approach, semi-axis x, y].
    pub gap_effect_rel: [f64; 3],
    /// Added by the bisection (not a table ratio).
    pub bisection: bool,
    pub dofs: usize,
    pub seconds: f64,
}

/// The study of one sphere-groove pair at its load.
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ConformityStudy {
    pub ball_radius_m: f64,
    /// The scene's groove radius.
    pub groove_radius_m: f64,
    pub materials: [String; 2],
    pub scenes: Vec<String>,
    pub load_n: f64,
    /// By decreasing R_g / r.
    pub rows: Vec<ConformityRow>,
    /// R_g / r where the approach part of the gap effect reaches [`LIMIT`]
    /// (null if no ratio of the table reaches it, or the first already does).
    pub ratio_at_limit: Option<f64>,
    /// Hertz's a / R_x at that ratio.
    pub conformity_at_limit: Option<f64>,
    /// R_g / r below which kinrepro warns (a / R_x above the conformity limit).
    pub warning_ratio: Option<f64>,
}

/// The pair with the groove radius `ratio` r.
fn pair_at(case: &PairCase, ratio: f64) -> Result<ContactPair, FeError> {
    let p = &case.pair;
    let r = p.curvature.radii1[0];
    ContactPair::from_shape(
        ContactShape::SphereGroove,
        r,
        Some(ratio * r),
        p.material1.clone(),
        p.material2.clone(),
    )
    .map_err(|e| FeError::InvalidInput(e.to_string()))
}

/// The FE with the exact and the quadratic gap at one ratio.
pub fn study_row(
    case: &PairCase,
    ratio: f64,
    mesh: &MeshOptions,
) -> Result<ConformityRow, FeError> {
    let pair = pair_at(case, ratio)?;
    let exact = fe_case(&pair, case.load, true)?;
    let quadratic = fe_case(&pair, case.load, false)?;
    let hz = hertz(exact.rx, exact.ry, exact.e_star, case.load)?;
    let (fe, fq) = (solve_case(&exact, mesh)?, solve_case(&quadratic, mesh)?);
    let rel = |a: f64, b: f64| a / b - 1.0;
    let axes = |r: &FeResult| [0, 1].map(|k| rel(r.semi_axes[k], hz.semi_axes[k]));
    Ok(ConformityRow {
        groove_over_ball: ratio,
        groove_radius_m: -pair.curvature.radii2[0],
        conformity: hz.semi_axes[0].max(hz.semi_axes[1]) / exact.rx,
        hertz_approach_m: hz.approach,
        hertz_semi_axes_m: hz.semi_axes,
        approach_error_rel: rel(fe.approach, hz.approach),
        semi_axes_error_rel: axes(&fe),
        quadratic_approach_error_rel: rel(fq.approach, hz.approach),
        quadratic_semi_axes_error_rel: axes(&fq),
        gap_effect_rel: [
            rel(fe.approach, fq.approach),
            rel(fe.semi_axes[0], fq.semi_axes[0]),
            rel(fe.semi_axes[1], fq.semi_axes[1]),
        ],
        bisection: false,
        dofs: fe.dofs,
        seconds: fe.seconds + fq.seconds,
    })
}

/// The study's criterion: the size of the approach part of a row's gap effect.
fn criterion(row: &ConformityRow) -> f64 {
    row.gap_effect_rel[0].abs()
}

/// log(R_g / r - 1), the bisection's variable.
fn log_excess(ratio: f64) -> f64 {
    (ratio - 1.0).ln()
}

/// The study of a sphere-groove pair at its load: the rows at `ratios`
/// (descending, each > 1) until the gap effect reaches [`LIMIT`], then
/// [`BISECTIONS`] steps in that bracket.
pub fn conformity_study(
    case: &PairCase,
    mesh: &MeshOptions,
    ratios: &[f64],
) -> Result<ConformityStudy, FeError> {
    if case.pair.shape != ContactShape::SphereGroove {
        return Err(FeError::InvalidInput(format!(
            "the conformity study needs a sphere-groove pair, not {}",
            case.pair.shape.name()
        )));
    }
    let (mut rows, at_limit) = find_crossing(ratios, |q| study_row(case, q, mesh))?;
    rows.sort_by(|a, b| b.groove_over_ball.total_cmp(&a.groove_over_ball));
    let law_at = |ratio: f64| -> Result<f64, FeError> {
        let law = pair_at(case, ratio)?.law().map_err(|e| FeError::InvalidInput(e.to_string()))?;
        Ok(law.hertz.conformity(case.load))
    };
    Ok(ConformityStudy {
        ball_radius_m: case.pair.curvature.radii1[0],
        groove_radius_m: -case.pair.curvature.radii2[0],
        materials: [case.pair.material1.name.clone(), case.pair.material2.name.clone()],
        scenes: case.scenes.clone(),
        load_n: case.load,
        rows,
        ratio_at_limit: at_limit,
        conformity_at_limit: at_limit.map(law_at).transpose()?,
        warning_ratio: warning_ratio(&law_at)?,
    })
}

/// The search of the study: `row` at each of `ratios` (descending) until
/// the [`criterion`] reaches [`LIMIT`], then [`BISECTIONS`] steps in
/// log(R_g / r - 1) inside that bracket. Returns the rows (in the order
/// solved) and, if a bracket was found, the interpolated ratio.
pub fn find_crossing(
    ratios: &[f64],
    mut row: impl FnMut(f64) -> Result<ConformityRow, FeError>,
) -> Result<(Vec<ConformityRow>, Option<f64>), FeError> {
    let mut rows: Vec<ConformityRow> = Vec::new();
    for &ratio in ratios {
        rows.push(row(ratio)?);
        if criterion(&rows[rows.len() - 1]) >= LIMIT {
            break;
        }
    }
    let crossing = rows.iter().position(|r| criterion(r) >= LIMIT);
    let Some(i) = crossing.filter(|&i| i > 0) else {
        return Ok((rows, None));
    };
    let (mut above, mut below) = (rows[i - 1].clone(), rows[i].clone());
    for _ in 0..BISECTIONS {
        let l = [&above, &below].map(|r| log_excess(r.groove_over_ball));
        let mut mid = row(1.0 + (0.5 * (l[0] + l[1])).exp())?;
        mid.bisection = true;
        rows.push(mid.clone());
        if criterion(&mid) >= LIMIT {
            below = mid;
        } else {
            above = mid;
        }
    }
    Ok((rows, Some(interpolate(&above, &below))))
}

/// The ratio where the [`criterion`] reaches [`LIMIT`], linear in
/// log(R_g / r - 1) between `above` (below the limit) and `below` (at or
/// over it).
fn interpolate(above: &ConformityRow, below: &ConformityRow) -> f64 {
    let (ca, cb) = (criterion(above), criterion(below));
    let (la, lb) = (log_excess(above.groove_over_ball), log_excess(below.groove_over_ball));
    let t = ((LIMIT - ca) / (cb - ca)).clamp(0.0, 1.0);
    1.0 + (la + t * (lb - la)).exp()
}

/// The ratio R_g / r at which Hertz's a / R_x reaches the conformity limit
/// of `check` and `contact` (a / R_x grows as the groove closes), by
/// bisection in log(R_g / r - 1) over 1e-9 .. 1e3; `None` outside.
fn warning_ratio(conformity: &dyn Fn(f64) -> Result<f64, FeError>) -> Result<Option<f64>, FeError> {
    let (mut lo, mut hi) = (1e-9f64.ln(), 1e3f64.ln());
    let at = |l: f64| conformity(1.0 + l.exp());
    if at(lo)? < CONFORMITY_LIMIT || at(hi)? > CONFORMITY_LIMIT {
        return Ok(None);
    }
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if at(mid)? > CONFORMITY_LIMIT {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(Some(1.0 + (0.5 * (lo + hi)).exp()))
}
