//! Linear elasticity of one element: isoparametric Lagrange hexahedra, their
//! stiffness and stress. The global system and its factorization are in
//! [`super::system`].
//!
//! Element stiffness `K_e = ∫ Bᵀ D B dV` evaluated by `(p+1)³`-point Gauss–Legendre
//! quadrature (Zienkiewicz & Taylor vol. 1, ch. 6 and 9); `D` is the isotropic
//! Hooke matrix in Voigt order `(xx, yy, zz, xy, yz, zx)` with engineering shear
//! strains: `λ = E ν/((1+ν)(1-2ν))`, `G = E/(2(1+ν))`.

use crate::fe::FeError;

/// Isotropic linear-elastic material.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Material {
    /// Young's modulus (Pa).
    pub e: f64,
    /// Poisson's ratio.
    pub nu: f64,
}

impl Material {
    /// Hooke matrix `D` (Voigt, engineering shear strain).
    pub fn d_matrix(&self) -> [[f64; 6]; 6] {
        let (e, nu) = (self.e, self.nu);
        let lam = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
        let g = e / (2.0 * (1.0 + nu));
        let mut d = [[0.0; 6]; 6];
        for (i, row) in d.iter_mut().enumerate().take(3) {
            for (j, v) in row.iter_mut().enumerate().take(3) {
                *v = lam + if i == j { 2.0 * g } else { 0.0 };
            }
        }
        for (i, row) in d.iter_mut().enumerate().skip(3) {
            row[i] = g;
        }
        d
    }
}

/// 1-D Lagrange shape functions on equally spaced nodes in `[-1, 1]` and their
/// derivatives, for order 1 or 2.
fn shape_1d(order: usize, xi: f64) -> ([f64; 3], [f64; 3]) {
    if order == 1 {
        ([0.5 * (1.0 - xi), 0.5 * (1.0 + xi), 0.0], [-0.5, 0.5, 0.0])
    } else {
        (
            [0.5 * xi * (xi - 1.0), 1.0 - xi * xi, 0.5 * xi * (xi + 1.0)],
            [xi - 0.5, -2.0 * xi, xi + 0.5],
        )
    }
}

/// Gauss–Legendre points and weights on `[-1, 1]`.
fn gauss_1d(n: usize) -> (Vec<f64>, Vec<f64>) {
    match n {
        2 => {
            let g = 1.0 / 3f64.sqrt();
            (vec![-g, g], vec![1.0, 1.0])
        }
        _ => {
            let g = (0.6f64).sqrt();
            (vec![-g, 0.0, g], vec![5.0 / 9.0, 8.0 / 9.0, 5.0 / 9.0])
        }
    }
}

/// Shape-function derivatives w.r.t. x, y, z at local point `xi` and `det J`.
fn shape_gradients(
    order: usize,
    coords: &[[f64; 3]],
    xi: [f64; 3],
    dndx: &mut Vec<[f64; 3]>,
) -> Result<f64, FeError> {
    let p1 = order + 1;
    let (n0, d0) = shape_1d(order, xi[0]);
    let (n1, d1) = shape_1d(order, xi[1]);
    let (n2, d2) = shape_1d(order, xi[2]);
    let mut dnd = Vec::with_capacity(p1 * p1 * p1);
    for c in 0..p1 {
        for b in 0..p1 {
            for a in 0..p1 {
                dnd.push([d0[a] * n1[b] * n2[c], n0[a] * d1[b] * n2[c], n0[a] * n1[b] * d2[c]]);
            }
        }
    }
    // J[r][s] = ∂x_s/∂ξ_r
    let mut j = [[0.0; 3]; 3];
    for (g, x) in dnd.iter().zip(coords) {
        for r in 0..3 {
            for s in 0..3 {
                j[r][s] += g[r] * x[s];
            }
        }
    }
    let det = j[0][0] * (j[1][1] * j[2][2] - j[1][2] * j[2][1])
        - j[0][1] * (j[1][0] * j[2][2] - j[1][2] * j[2][0])
        + j[0][2] * (j[1][0] * j[2][1] - j[1][1] * j[2][0]);
    if !det.is_finite() || det <= 0.0 {
        return Err(FeError::InvalidInput(format!("element with non-positive Jacobian {det}")));
    }
    let inv = [
        [
            (j[1][1] * j[2][2] - j[1][2] * j[2][1]) / det,
            (j[0][2] * j[2][1] - j[0][1] * j[2][2]) / det,
            (j[0][1] * j[1][2] - j[0][2] * j[1][1]) / det,
        ],
        [
            (j[1][2] * j[2][0] - j[1][0] * j[2][2]) / det,
            (j[0][0] * j[2][2] - j[0][2] * j[2][0]) / det,
            (j[0][2] * j[1][0] - j[0][0] * j[1][2]) / det,
        ],
        [
            (j[1][0] * j[2][1] - j[1][1] * j[2][0]) / det,
            (j[0][1] * j[2][0] - j[0][0] * j[2][1]) / det,
            (j[0][0] * j[1][1] - j[0][1] * j[1][0]) / det,
        ],
    ];
    // ∂N/∂x_s = Σ_r (J⁻¹)[s][r] ∂N/∂ξ_r
    dndx.clear();
    for g in &dnd {
        let mut d = [0.0; 3];
        for (s, ds) in d.iter_mut().enumerate() {
            *ds = inv[s][0] * g[0] + inv[s][1] * g[1] + inv[s][2] * g[2];
        }
        dndx.push(d);
    }
    Ok(det)
}

/// Strain–displacement rows for node gradient `g` (Voigt, engineering shear):
/// columns (u_x, u_y, u_z).
#[inline]
fn b_block(g: [f64; 3]) -> [[f64; 3]; 6] {
    [
        [g[0], 0.0, 0.0],
        [0.0, g[1], 0.0],
        [0.0, 0.0, g[2]],
        [g[1], g[0], 0.0],
        [0.0, g[2], g[1]],
        [g[2], 0.0, g[0]],
    ]
}

/// Element stiffness matrix (row-major, size `3n × 3n`, DOF `3·node + comp`).
pub fn element_stiffness(
    order: usize,
    coords: &[[f64; 3]],
    mat: &Material,
) -> Result<Vec<f64>, FeError> {
    let n = coords.len();
    let nd = 3 * n;
    let d = mat.d_matrix();
    let (pts, wts) = gauss_1d(order + 1);
    let mut k = vec![0.0; nd * nd];
    let mut dndx = Vec::with_capacity(n);
    let mut db = vec![[0.0; 6]; nd]; // (D B)ᵀ rows per DOF
    let mut bt = vec![[0.0; 6]; nd];
    for (iz, &z) in pts.iter().enumerate() {
        for (iy, &y) in pts.iter().enumerate() {
            for (ix, &x) in pts.iter().enumerate() {
                let det = shape_gradients(order, coords, [x, y, z], &mut dndx)?;
                let w = wts[ix] * wts[iy] * wts[iz] * det;
                for (a, g) in dndx.iter().enumerate() {
                    let b = b_block(*g);
                    for c in 0..3 {
                        let col: [f64; 6] = std::array::from_fn(|r| b[r][c]);
                        bt[3 * a + c] = col;
                        db[3 * a + c] = std::array::from_fn(|r| {
                            w * (0..6).map(|s| d[r][s] * col[s]).sum::<f64>()
                        });
                    }
                }
                for r in 0..nd {
                    let br = &bt[r];
                    let row = &mut k[r * nd..(r + 1) * nd];
                    for (c, dc) in db.iter().enumerate().skip(r) {
                        row[c] += br[0] * dc[0]
                            + br[1] * dc[1]
                            + br[2] * dc[2]
                            + br[3] * dc[3]
                            + br[4] * dc[4]
                            + br[5] * dc[5];
                    }
                }
            }
        }
    }
    for r in 0..nd {
        for c in 0..r {
            k[r * nd + c] = k[c * nd + r];
        }
    }
    Ok(k)
}

/// Stress (Voigt) at local point `xi` of an element with nodal displacements `u`.
pub fn element_stress(
    order: usize,
    coords: &[[f64; 3]],
    u: &[[f64; 3]],
    xi: [f64; 3],
    mat: &Material,
) -> Result<[f64; 6], FeError> {
    let mut dndx = Vec::new();
    shape_gradients(order, coords, xi, &mut dndx)?;
    let mut eps = [0.0; 6];
    for (g, ua) in dndx.iter().zip(u) {
        let b = b_block(*g);
        for (r, e) in eps.iter_mut().enumerate() {
            *e += b[r][0] * ua[0] + b[r][1] * ua[1] + b[r][2] * ua[2];
        }
    }
    let d = mat.d_matrix();
    Ok(std::array::from_fn(|r| (0..6).map(|s| d[r][s] * eps[s]).sum()))
}
