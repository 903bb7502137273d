//! Frictionless unilateral (Signorini) contact of a rigid indenter with gap profile
//! `h(x, y)` (Hertz's `x²/(2Rx) + y²/(2Ry)` or an exact gap, [`crate::fe::gap`]) on the top surface, force controlled, solved by a
//! primal–dual active-set method on the contact-candidate nodes.
//!
//! The elastic block is linear, so the downward displacement `w` of the candidate
//! nodes is condensed (static condensation / flexibility method):
//! `w = C f + F w_B`, where `C = S K⁻¹ Sᵀ` is the compliance of the candidate nodes
//! for downward nodal forces `f` (quarter model), `w_B` the response to the unit
//! Boussinesq far-field boundary condition and `F = 4 Σ f` the total load (quarter
//! symmetry). Signorini conditions on node `i` with indenter approach `δ`:
//! `g_i = h_i - δ + w_i ≥ 0`, `f_i ≥ 0`, `f_i g_i = 0` (Kikuchi & Oden 1988;
//! Wriggers, *Computational Contact Mechanics*, 2006, §6.3 for active-set strategies).
//!
//! Constraints and multipliers live on nodes; with 27-node (or 8-node) Lagrange
//! elements the consistent nodal forces of a non-negative pressure are non-negative
//! (tributary weights are positive), unlike the 20-node serendipity element.

use crate::fe::FeError;
use faer::Mat;
use faer::linalg::solvers::Solve;

/// Condensed contact problem on the candidate nodes.
#[derive(Debug, Clone)]
pub struct ContactModel {
    /// Gap profile `h` at the candidates.
    pub h: Vec<f64>,
    /// Compliance matrix `C` (candidates × candidates), m/N.
    pub c: Mat<f64>,
    /// Downward displacement of the candidates per unit total load (Boussinesq BC).
    pub w_unit: Vec<f64>,
    /// Gap profile at the remaining top nodes (checked, not constrained).
    pub h_other: Vec<f64>,
    /// Compliance rows of the remaining top nodes (others × candidates).
    pub c_other: Mat<f64>,
    /// Unit-load Boussinesq response at the remaining top nodes.
    pub w_unit_other: Vec<f64>,
    /// True for candidates on the edge of the candidate zone.
    pub on_zone_edge: Vec<bool>,
}

/// Converged contact state at one load.
#[derive(Debug, Clone)]
pub struct ContactState {
    /// Indenter approach `δ`, m.
    pub approach: f64,
    /// Downward nodal contact forces on the candidates (quarter model), N.
    pub forces: Vec<f64>,
    /// Gaps at the candidates, m.
    pub gaps: Vec<f64>,
}

impl ContactModel {
    /// Solves the Signorini problem for total load `load`, starting from the active
    /// set `init` (candidates with `h_i < δ0` if `None`, `δ0` a guess of the approach).
    pub fn solve(
        &self,
        load: f64,
        delta_guess: f64,
        init: Option<&[bool]>,
    ) -> Result<ContactState, FeError> {
        if !(load.is_finite() && load > 0.0) {
            return Err(FeError::InvalidInput(format!("load must be positive, got {load}")));
        }
        let n = self.h.len();
        let mut active: Vec<bool> = match init {
            Some(a) if a.len() == n && a.iter().any(|&b| b) => a.to_vec(),
            _ => self.h.iter().map(|&h| h < 0.5 * delta_guess).collect(),
        };
        if !active.iter().any(|&b| b) {
            active[0] = true;
        }
        const MAX_IT: usize = 200;
        for it in 1..=MAX_IT {
            let (delta, mut forces, gaps) = self.solve_active(load, &active)?;
            let tol_g = 1e-9 * delta.abs();
            let tol_f = 1e-12 * load;
            let new: Vec<bool> = (0..n)
                .map(|i| if active[i] { forces[i] > -tol_f } else { gaps[i] < -tol_g })
                .collect();
            if new == active {
                if delta.is_nan() || delta <= 0.0 {
                    return Err(FeError::NonFinite("non-positive approach"));
                }
                for (i, f) in forces.iter_mut().enumerate() {
                    if !active[i] {
                        *f = 0.0;
                    }
                }
                self.check_zone(load, delta, &forces, &active, tol_g)?;
                return Ok(ContactState { approach: delta, forces, gaps });
            }
            active = new;
            if !active.iter().any(|&b| b) {
                return Err(FeError::ContactNotConverged(it));
            }
        }
        Err(FeError::ContactNotConverged(MAX_IT))
    }

    /// The approach, the candidate forces and the gaps with the candidates
    /// in `active` in contact (zero gap) and the others free of load:
    /// ```text
    /// [C_AA  -1] [f_A]   [-h_A - F w_B,A]
    /// [4·1ᵀ   0] [ δ ] = [      F       ]
    /// ```
    /// (4: the quarter model carries a quarter of the load).
    fn solve_active(
        &self,
        load: f64,
        active: &[bool],
    ) -> Result<(f64, Vec<f64>, Vec<f64>), FeError> {
        let n = self.h.len();
        let idx: Vec<usize> = (0..n).filter(|&i| active[i]).collect();
        let m = idx.len();
        let mut a = Mat::<f64>::zeros(m + 1, m + 1);
        let mut b = Mat::<f64>::zeros(m + 1, 1);
        for (r, &i) in idx.iter().enumerate() {
            for (s, &j) in idx.iter().enumerate() {
                a[(r, s)] = self.c[(i, j)];
            }
            a[(r, m)] = -1.0;
            a[(m, r)] = 4.0;
            b[(r, 0)] = -self.h[i] - load * self.w_unit[i];
        }
        b[(m, 0)] = load;
        let x = a.partial_piv_lu().solve(&b);
        let delta = x[(m, 0)];
        if !delta.is_finite() {
            return Err(FeError::NonFinite("contact system"));
        }
        let mut forces = vec![0.0; n];
        for (r, &i) in idx.iter().enumerate() {
            forces[i] = x[(r, 0)];
        }
        let gaps: Vec<f64> = (0..n)
            .map(|i| {
                let w: f64 = idx.iter().map(|&j| self.c[(i, j)] * forces[j]).sum::<f64>()
                    + load * self.w_unit[i];
                self.h[i] - delta + w
            })
            .collect();
        Ok((delta, forces, gaps))
    }

    /// The converged contact must lie inside the candidate zone: no active
    /// candidate on its edge, and no other top node penetrating.
    fn check_zone(
        &self,
        load: f64,
        delta: f64,
        forces: &[f64],
        active: &[bool],
        tol_g: f64,
    ) -> Result<(), FeError> {
        let n = self.h.len();
        if (0..n).any(|i| active[i] && self.on_zone_edge[i]) {
            return Err(FeError::CandidateZoneTooSmall);
        }
        // remaining top nodes must not penetrate
        for (r, &ho) in self.h_other.iter().enumerate() {
            let w: f64 = (0..n).map(|j| self.c_other[(r, j)] * forces[j]).sum::<f64>()
                + load * self.w_unit_other[r];
            if ho - delta + w < -tol_g {
                return Err(FeError::CandidateZoneTooSmall);
            }
        }
        Ok(())
    }
}

/// Contact extent along one axis from the nodes on that axis (sorted by coordinate):
/// the edge lies between the last contacting node `x_c` and the first free node
/// `x_f`. It is located from the two first free nodes using the generic gap
/// asymptotics at a smooth frictionless contact edge, `g ∝ (x - a)^{3/2}`
/// (Johnson 1985 §4.2; e.g. eq. 3.42 for the circular case), i.e. by linear
/// extrapolation of `g^{2/3}` to zero, clamped to `[x_c, x_f]`.
pub fn contact_extent(coords: &[f64], forces: &[f64], gaps: &[f64]) -> Option<f64> {
    let last = (0..coords.len()).rev().find(|&i| forces[i] > 0.0)?;
    if last + 1 >= coords.len() {
        return None;
    }
    let (xc, xf) = (coords[last], coords[last + 1]);
    let g1 = gaps[last + 1].max(0.0).powf(2.0 / 3.0);
    let est = if last + 2 < coords.len() {
        let g2 = gaps[last + 2].max(0.0).powf(2.0 / 3.0);
        let x2 = coords[last + 2];
        if g2 > g1 { xf - g1 * (x2 - xf) / (g2 - g1) } else { 0.5 * (xc + xf) }
    } else {
        0.5 * (xc + xf)
    };
    Some(est.clamp(xc, xf))
}
