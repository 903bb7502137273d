//! The model covariance per unit spread^2, G(phi), as a function of the
//! fitted parameters other than the spread (mu_static, dynamic_ratio,
//! support_compliance): Monte Carlo studies on a tensor grid of nodes over
//! their searched ranges (`params`), all with the same seed, so every node
//! seats the same design rows u (common random numbers) and the change of
//! G from node to node carries little sampling noise; between the nodes G
//! is interpolated entry by entry with Catmull-Rom cubics (exact for
//! quadratics; in the end intervals the missing outer node is the quadratic
//! extrapolation x_{-1} = 3 x_0 - 3 x_1 + x_2). With no grid parameter (the
//! spread alone) the grid is one study.
//!
//! Each node's study runs at spread s_g and G = C / s_g^2 (sigma close to
//! linear in the spread, within 1 % while spread <= 0.3 mu0; the
//! calibration re-runs the grid at the first estimate, so the linear law
//! spans only the interval). Where mu_static is a grid parameter, a node
//! runs at min(s_g, mu_node / 2), so that the low-mu nodes stay where the
//! linear law holds. The interpolation and the linear law together are
//! checked against a direct study at the final estimate (`GridInfo::check`).

use nalgebra::DMatrix;

use super::error::CalibrateError;
use super::model::StudySpec;
use super::params::{Param, with_values};

/// Nodes per parameter for 1, 2 and 3 grid parameters.
pub const NODES: [usize; 3] = [9, 6, 4];

/// G(phi) on a tensor grid.
#[derive(Debug, Clone)]
pub struct ModelGrid {
    /// The grid parameters (fitted, not the spread), in order.
    pub params: Vec<Param>,
    /// Node values per parameter (equally spaced over its range).
    pub nodes: Vec<Vec<f64>>,
    /// G of the measured DOFs at each node, the last parameter fastest.
    g: Vec<DMatrix<f64>>,
    /// The spread the node studies aimed at.
    pub spread: f64,
}

/// How the grid was built, for the calibration file.
#[derive(Debug, Clone, PartialEq, serde::Serialize, serde::Deserialize)]
pub struct GridInfo {
    pub parameters: Vec<String>,
    pub nodes: Vec<Vec<f64>>,
    /// The spread the node studies ran at (capped at mu_static / 2 per node
    /// where mu_static is a grid parameter).
    pub spread: f64,
    /// Largest relative difference, over the measured DOFs, between sigma
    /// from the interpolated grid (scaled by s^2) and sigma of a direct
    /// study (same seed) at the estimate and at each region point.
    pub check: f64,
}

impl ModelGrid {
    /// Run the node studies of `params` (each over `ranges`) aiming at `spread`.
    pub fn build(
        spec: &StudySpec,
        params: &[Param],
        ranges: &[(f64, f64)],
        spread: f64,
    ) -> Result<Self, CalibrateError> {
        let k = params.len().checked_sub(1).map_or(1, |i| NODES[i]);
        let cap = params.contains(&Param::MuStatic);
        let nodes: Vec<Vec<f64>> = ranges
            .iter()
            .map(|&(a, b)| (0..k).map(|i| a + (b - a) * i as f64 / (k - 1) as f64).collect())
            .collect();
        let mut g = Vec::new();
        for flat in 0..k.pow(params.len() as u32) {
            let values: Vec<f64> = (node_indices(nodes.len(), k, flat).iter().zip(&nodes))
                .map(|(&i, n)| n[i])
                .collect();
            let mut c = with_values(spec.base(), params, &values);
            let mu = c.scene.friction.mu_static;
            let reach = Param::scale_of(&c.scene).sds_inside();
            let s = if cap { spread.min(0.5 * mu / reach) } else { spread };
            c.scene.set_mu_scale(s);
            g.push(spec.run(&c)?.per_unit(spec.dofs));
        }
        Ok(ModelGrid { params: params.to_vec(), nodes, g, spread })
    }

    /// A grid of given node matrices (a closed-form G, or G from another model).
    pub fn from_parts(
        params: Vec<Param>,
        nodes: Vec<Vec<f64>>,
        g: Vec<DMatrix<f64>>,
        spread: f64,
    ) -> Self {
        ModelGrid { params, nodes, g, spread }
    }

    /// G at the grid-parameter values `phi` (interpolated): the sum over
    /// the nodes of G times the product of the per-parameter weights.
    pub fn at(&self, phi: &[f64]) -> DMatrix<f64> {
        let w: Vec<Vec<f64>> = (self.nodes.iter().zip(phi)).map(|(n, &v)| weights(n, v)).collect();
        let p = self.g[0].nrows();
        let mut out = DMatrix::zeros(p, p);
        for (flat, g) in self.g.iter().enumerate() {
            let idx = node_indices(self.nodes.len(), w.first().map_or(1, Vec::len), flat);
            let wf: f64 = idx.iter().zip(&w).map(|(&i, wd)| wd[i]).product();
            if wf != 0.0 {
                out += g * wf;
            }
        }
        out
    }
}

/// The node index per parameter of node number `flat` (`d` parameters of
/// `k` nodes each, the last parameter fastest).
fn node_indices(d: usize, k: usize, mut flat: usize) -> Vec<usize> {
    let mut idx = vec![0; d];
    for i in idx.iter_mut().rev() {
        *i = flat % k;
        flat /= k;
    }
    idx
}

/// Catmull-Rom weights of the nodes for the value `v` (clamped to the
/// nodes' range), one per node, summing to 1.
pub fn weights(nodes: &[f64], v: f64) -> Vec<f64> {
    let k = nodes.len();
    let h = (nodes[k - 1] - nodes[0]) / (k - 1) as f64;
    if h <= 0.0 {
        let mut w = vec![0.0; k];
        w[0] = 1.0;
        return w;
    }
    let x = ((v - nodes[0]) / h).clamp(0.0, (k - 1) as f64);
    let i = (x.floor() as usize).min(k - 2);
    let t = x - i as f64;
    let (t2, t3) = (t * t, t * t * t);
    let w = [
        0.5 * (-t3 + 2.0 * t2 - t),
        0.5 * (3.0 * t3 - 5.0 * t2 + 2.0),
        0.5 * (-3.0 * t3 + 4.0 * t2 + t),
        0.5 * (t3 - t2),
    ];
    let mut acc = vec![0.0; k];
    for (j, wj) in w.iter().enumerate() {
        let n = i as isize + j as isize - 1;
        if n < 0 {
            // Ghost node below: 3 x_0 - 3 x_1 + x_2.
            for (m, c) in [(0, 3.0), (1, -3.0), (2, 1.0)] {
                acc[m.min(k - 1)] += c * wj;
            }
        } else if n as usize >= k {
            // Ghost node above: 3 x_{k-1} - 3 x_{k-2} + x_{k-3}.
            for (m, c) in [(k - 1, 3.0), (k - 2, -3.0), (k.saturating_sub(3), 1.0)] {
                acc[m] += c * wj;
            }
        } else {
            acc[n as usize] += wj;
        }
    }
    acc
}
