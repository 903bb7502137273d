//! Linear elasticity: isoparametric Lagrange hexahedra, sparse assembly of the
//! free-DOF stiffness matrix and its sparse Cholesky factorization (faer, AMD
//! ordering).
//!
//! Element stiffness `K_e = ∫ Bᵀ D B dV` evaluated by `(p+1)³`-point Gauss–Legendre
//! quadrature (Zienkiewicz & Taylor vol. 1, ch. 6 and 9); `D` is the isotropic
//! Hooke matrix in Voigt order `(xx, yy, zz, xy, yz, zx)` with engineering shear
//! strains: `λ = E ν/((1+ν)(1-2ν))`, `G = E/(2(1+ν))`.

use crate::fe::FeError;
use crate::fe::mesh::HexMesh;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::perm::PermRef;
use faer::sparse::linalg::cholesky::{
    LltRef, SymbolicCholesky, SymmetricOrdering, factorize_symbolic_cholesky,
};
use faer::sparse::{SparseColMat, SymbolicSparseColMat};
use faer::{Conj, MatMut, Par, Side};
use std::collections::HashMap;

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
                dnd.push([
                    d0[a] * n1[b] * n2[c],
                    n0[a] * d1[b] * n2[c],
                    n0[a] * n1[b] * d2[c],
                ]);
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
        return Err(FeError::InvalidInput(format!(
            "element with non-positive Jacobian {det}"
        )));
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
    Ok(std::array::from_fn(|r| {
        (0..6).map(|s| d[r][s] * eps[s]).sum()
    }))
}

/// Free-DOF system: lower triangle of `K_ff` and the load `-K_fp u_p` from the
/// prescribed displacements.
pub struct FreeSystem {
    /// Equation number of each DOF (`3·node + comp`), `usize::MAX` if prescribed.
    pub eq_of_dof: Vec<usize>,
    /// Number of free equations.
    pub n_eq: usize,
    /// Lower triangle of the free stiffness matrix.
    pub matrix: SparseColMat<usize, f64>,
    /// `-K_fp u_p` for the prescribed values given to [`assemble`].
    pub rhs_fixed: Vec<f64>,
}

/// Assembles the free-DOF stiffness matrix. `fixed[d]` marks prescribed DOFs with
/// value `fixed_values[d]`.
pub fn assemble(
    mesh: &HexMesh,
    mat: &Material,
    fixed: &[bool],
    fixed_values: &[f64],
) -> Result<FreeSystem, FeError> {
    let nn = mesh.nodes.len();
    let ndof = 3 * nn;
    if fixed.len() != ndof || fixed_values.len() != ndof {
        return Err(FeError::InvalidInput("BC vector length".into()));
    }
    let mut eq_of_dof = vec![usize::MAX; ndof];
    let mut n_eq = 0;
    for d in 0..ndof {
        if !fixed[d] {
            eq_of_dof[d] = n_eq;
            n_eq += 1;
        }
    }
    if n_eq == 0 {
        return Err(FeError::InvalidInput("no free DOF".into()));
    }
    // Node adjacency (nodes sharing an element), sorted.
    let mut adj: Vec<Vec<u32>> = vec![Vec::new(); nn];
    let mut en = Vec::new();
    for e in 0..mesh.n_elements() {
        mesh.element_nodes(e, &mut en);
        for &a in &en {
            adj[a].extend(en.iter().map(|&b| b as u32));
        }
    }
    for a in adj.iter_mut() {
        a.sort_unstable();
        a.dedup();
    }
    // Lower-triangular CSC pattern over free equations (rows >= column).
    let mut col_ptr = Vec::with_capacity(n_eq + 1);
    let mut row_idx = Vec::new();
    col_ptr.push(0usize);
    for (node, nb) in adj.iter().enumerate() {
        for c in 0..3 {
            let ec = eq_of_dof[3 * node + c];
            if ec == usize::MAX {
                continue;
            }
            for &m in nb {
                for c2 in 0..3 {
                    let er = eq_of_dof[3 * m as usize + c2];
                    if er != usize::MAX && er >= ec {
                        row_idx.push(er);
                    }
                }
            }
            col_ptr.push(row_idx.len());
        }
    }
    drop(adj);
    let mut val = vec![0.0; row_idx.len()];
    let mut rhs_fixed = vec![0.0; n_eq];
    // Element loop, element matrices cached by quantized relative node coordinates.
    let quantum = mesh
        .edges
        .iter()
        .flat_map(|e| e.windows(2).map(|w| w[1] - w[0]))
        .fold(f64::INFINITY, f64::min)
        * 1e-9;
    let mut cache: HashMap<Vec<i64>, Vec<f64>> = HashMap::new();
    let mut coords = Vec::new();
    let mut key = Vec::new();
    for e in 0..mesh.n_elements() {
        mesh.element_nodes(e, &mut en);
        coords.clear();
        coords.extend(en.iter().map(|&a| mesh.nodes[a]));
        let x0 = coords[0];
        key.clear();
        for x in &coords {
            for d in 0..3 {
                key.push(((x[d] - x0[d]) / quantum).round() as i64);
            }
        }
        if !cache.contains_key(&key) {
            let ke = element_stiffness(mesh.order, &coords, mat)?;
            cache.insert(key.clone(), ke);
        }
        let ke = &cache[&key];
        let nd = 3 * en.len();
        let dofs: Vec<usize> = en
            .iter()
            .flat_map(|&a| (0..3).map(move |c| 3 * a + c))
            .collect();
        for (lc, &dc) in dofs.iter().enumerate() {
            let ec = eq_of_dof[dc];
            if ec == usize::MAX {
                // prescribed column: move to the right-hand side
                let uc = fixed_values[dc];
                if uc != 0.0 {
                    for (lr, &dr) in dofs.iter().enumerate() {
                        let er = eq_of_dof[dr];
                        if er != usize::MAX {
                            rhs_fixed[er] -= ke[lr * nd + lc] * uc;
                        }
                    }
                }
                continue;
            }
            let rows = &row_idx[col_ptr[ec]..col_ptr[ec + 1]];
            for (lr, &dr) in dofs.iter().enumerate() {
                let er = eq_of_dof[dr];
                if er == usize::MAX || er < ec {
                    continue;
                }
                let pos = rows
                    .binary_search(&er)
                    .map_err(|_| FeError::InvalidInput("sparsity pattern".into()))?;
                val[col_ptr[ec] + pos] += ke[lr * nd + lc];
            }
        }
    }
    let symbolic = SymbolicSparseColMat::new_checked(n_eq, n_eq, col_ptr, None, row_idx);
    let matrix = SparseColMat::new(symbolic, val);
    Ok(FreeSystem {
        eq_of_dof,
        n_eq,
        matrix,
        rhs_fixed,
    })
}

/// Sparse Cholesky factor `P K Pᵀ = L Lᵀ` (faer supernodal/simplicial), with a
/// fill-reducing ordering: geometric nested dissection of the structured mesh
/// ([`HexMesh::nested_dissection`]) or faer's AMD.
pub struct Factor {
    symbolic: SymbolicCholesky<usize>,
    values: Vec<f64>,
}

impl Factor {
    /// Factorizes the (lower-stored) free stiffness matrix with faer's AMD ordering.
    pub fn new(sys: &FreeSystem) -> Result<Self, FeError> {
        Self::with_ordering(sys, SymmetricOrdering::Amd)
    }

    /// Factorizes with the nested-dissection node ordering of `mesh`.
    pub fn nested_dissection(sys: &FreeSystem, mesh: &HexMesh) -> Result<Self, FeError> {
        let mut fwd = Vec::with_capacity(sys.n_eq);
        for a in mesh.nested_dissection() {
            for c in 0..3 {
                let e = sys.eq_of_dof[3 * a + c];
                if e != usize::MAX {
                    fwd.push(e);
                }
            }
        }
        let mut inv = vec![usize::MAX; sys.n_eq];
        for (new, &old) in fwd.iter().enumerate() {
            inv[old] = new;
        }
        if fwd.len() != sys.n_eq || inv.contains(&usize::MAX) {
            return Err(FeError::InvalidInput(
                "ordering is not a permutation".into(),
            ));
        }
        let perm = PermRef::new_checked(&fwd, &inv, sys.n_eq);
        Self::with_ordering(sys, SymmetricOrdering::Custom(perm))
    }

    fn with_ordering(sys: &FreeSystem, ord: SymmetricOrdering<'_, usize>) -> Result<Self, FeError> {
        let err = |e: &dyn std::fmt::Debug| FeError::Factorization(format!("{e:?}"));
        let symbolic = factorize_symbolic_cholesky(
            sys.matrix.symbolic(),
            Side::Lower,
            ord,
            Default::default(),
        )
        .map_err(|e| err(&e))?;
        let mut values = vec![0.0; symbolic.len_val()];
        let mut mem = MemBuffer::new(
            symbolic.factorize_numeric_llt_scratch::<f64>(Par::Seq, Default::default()),
        );
        symbolic
            .factorize_numeric_llt(
                &mut values,
                sys.matrix.as_ref(),
                Side::Lower,
                Default::default(),
                Par::Seq,
                MemStack::new(&mut mem),
                Default::default(),
            )
            .map_err(|e| err(&e))?;
        Ok(Self { symbolic, values })
    }

    /// Number of stored values of the factor.
    pub fn factor_len(&self) -> usize {
        self.values.len()
    }

    /// Solves `K X = B` in place for a block of right-hand sides.
    pub fn solve_in_place(&self, rhs: MatMut<'_, f64>) {
        let mut mem = MemBuffer::new(
            self.symbolic
                .solve_in_place_scratch::<f64>(rhs.ncols(), Par::Seq),
        );
        LltRef::new(&self.symbolic, &self.values).solve_in_place_with_conj(
            Conj::No,
            rhs,
            Par::Seq,
            MemStack::new(&mut mem),
        );
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::fe::mesh::HexMesh;
    use approx::assert_relative_eq;

    fn solve_with_bc(
        mesh: &HexMesh,
        mat: &Material,
        fixed: &[bool],
        vals: &[f64],
        loads: &[f64],
    ) -> Vec<f64> {
        let sys = assemble(mesh, mat, fixed, vals).unwrap();
        let fac = Factor::new(&sys).unwrap();
        let mut rhs = faer::Mat::<f64>::zeros(sys.n_eq, 1);
        for (&e, &l) in sys.eq_of_dof.iter().zip(loads) {
            if e != usize::MAX {
                rhs[(e, 0)] = sys.rhs_fixed[e] + l;
            }
        }
        fac.solve_in_place(rhs.as_mut());
        (0..fixed.len())
            .map(|d| {
                let e = sys.eq_of_dof[d];
                if e == usize::MAX {
                    vals[d]
                } else {
                    rhs[(e, 0)]
                }
            })
            .collect()
    }

    /// Patch test (Zienkiewicz & Taylor vol. 1 ch. 10): a linear displacement field
    /// prescribed on the boundary of a distorted mesh is reproduced exactly at the
    /// interior nodes, with constant stress.
    #[test]
    fn patch_test_distorted_mesh() {
        for order in [1, 2] {
            let e = [0.0, 0.4, 1.0];
            let mut mesh = HexMesh::structured(order, &e, &e, &e).unwrap();
            mesh.map_vertices(|x| {
                let inner = |v: f64| v > 0.0 && v < 1.0;
                let mut y = x;
                // move interior vertex and face-centre vertices (within their face)
                if inner(x[0]) {
                    y[0] += 0.13 * (x[1] - 0.3) + 0.05 * x[2];
                }
                if inner(x[1]) {
                    y[1] += -0.11 * (x[2] - 0.5) + 0.07 * x[0];
                }
                if inner(x[2]) {
                    y[2] += 0.09 * (x[0] - 0.2) - 0.04 * x[1];
                }
                y
            });
            let mat = Material { e: 200e9, nu: 0.3 };
            let lin = |x: [f64; 3]| {
                [
                    1e-3 * (1.0 + 2.0 * x[0] - 0.5 * x[1] + 0.3 * x[2]),
                    1e-3 * (-0.4 + 0.7 * x[0] + 1.5 * x[1] - 0.2 * x[2]),
                    1e-3 * (0.2 - 0.6 * x[0] + 0.1 * x[1] + 0.9 * x[2]),
                ]
            };
            let nn = mesh.nodes.len();
            let mut fixed = vec![false; 3 * nn];
            let mut vals = vec![0.0; 3 * nn];
            let [nx, ny, nz] = mesh.dims;
            for k in 0..nz {
                for j in 0..ny {
                    for i in 0..nx {
                        let a = mesh.node_index(i, j, k);
                        let bnd =
                            i == 0 || j == 0 || k == 0 || i == nx - 1 || j == ny - 1 || k == nz - 1;
                        if bnd {
                            let u = lin(mesh.nodes[a]);
                            for c in 0..3 {
                                fixed[3 * a + c] = true;
                                vals[3 * a + c] = u[c];
                            }
                        }
                    }
                }
            }
            let u = solve_with_bc(&mesh, &mat, &fixed, &vals, &vec![0.0; 3 * nn]);
            for a in 0..nn {
                let ex = lin(mesh.nodes[a]);
                for c in 0..3 {
                    assert!(
                        (u[3 * a + c] - ex[c]).abs() < 1e-12,
                        "order {order} node {a}"
                    );
                }
            }
            // Constant stress = D ε with ε from the linear field's gradient.
            let eps = [
                2e-3,
                1.5e-3,
                0.9e-3,
                -0.5e-3 + 0.7e-3,
                -0.2e-3 + 0.1e-3,
                0.3e-3 - 0.6e-3,
            ];
            let d = mat.d_matrix();
            let sig: [f64; 6] = std::array::from_fn(|r| (0..6).map(|s| d[r][s] * eps[s]).sum());
            let mut en = Vec::new();
            for el in 0..mesh.n_elements() {
                mesh.element_nodes(el, &mut en);
                let coords: Vec<[f64; 3]> = en.iter().map(|&a| mesh.nodes[a]).collect();
                let ue: Vec<[f64; 3]> = en
                    .iter()
                    .map(|&a| [u[3 * a], u[3 * a + 1], u[3 * a + 2]])
                    .collect();
                for xi in [[0.3, -0.7, 0.1], [-0.9, 0.9, 0.5]] {
                    let s = element_stress(order, &coords, &ue, xi, &mat).unwrap();
                    for r in 0..6 {
                        assert!((s[r] - sig[r]).abs() < 1e-6 * 1e9, "stress {r}");
                    }
                }
            }
        }
    }

    /// Uniaxial stress of a block on rollers with free lateral faces under a uniform
    /// pressure `p` on top: `u_z(top) = -p L / E` (closed form), and lateral
    /// expansion `ν p L / E`.
    #[test]
    fn uniform_pressure_uniaxial_stress() {
        let (lx, ly, lz) = (1.0, 0.7, 2.0);
        let mat = Material { e: 100.0, nu: 0.3 };
        let p = 2.0;
        for order in [1, 2] {
            let mesh = HexMesh::structured(
                order,
                &[0.0, 0.3, lx],
                &[0.0, 0.2, 0.45, ly],
                &[-lz, -1.2, -0.3, 0.0],
            )
            .unwrap();
            let nn = mesh.nodes.len();
            let mut fixed = vec![false; 3 * nn];
            for (a, x) in mesh.nodes.iter().enumerate() {
                if x[0] == 0.0 {
                    fixed[3 * a] = true;
                }
                if x[1] == 0.0 {
                    fixed[3 * a + 1] = true;
                }
                if x[2] == -lz {
                    fixed[3 * a + 2] = true;
                }
            }
            // consistent nodal loads of the uniform pressure = -p × tributary area
            let loads = top_pressure_loads(&mesh, p);
            let u = solve_with_bc(&mesh, &mat, &fixed, &vec![0.0; 3 * nn], &loads);
            for (a, x) in mesh.nodes.iter().enumerate() {
                let uz = -p * (x[2] + lz) / mat.e;
                assert_relative_eq!(u[3 * a + 2], uz, epsilon = 1e-12);
                assert_relative_eq!(u[3 * a], mat.nu * p * x[0] / mat.e, epsilon = 1e-12);
            }
        }
    }

    /// Consistent nodal loads of a uniform pressure p on the top face:
    /// -p times each top node's tributary area.
    fn top_pressure_loads(mesh: &HexMesh, p: f64) -> Vec<f64> {
        let trib = mesh.top_tributary_areas();
        let mut loads = vec![0.0; 3 * mesh.nodes.len()];
        let [nx, ny, nz] = mesh.dims;
        for j in 0..ny {
            for i in 0..nx {
                loads[3 * mesh.node_index(i, j, nz - 1) + 2] = -p * trib[i + nx * j];
            }
        }
        loads
    }

    /// Uniaxial strain (laterally constrained block):
    /// `u = p L (1+ν)(1-2ν) / (E (1-ν))`.
    #[test]
    fn uniform_pressure_uniaxial_strain() {
        let lz = 1.5;
        let mat = Material { e: 210e9, nu: 0.3 };
        let p = 1e6;
        let mesh = HexMesh::structured(2, &[0.0, 0.5], &[0.0, 0.5], &[-lz, -0.5, 0.0]).unwrap();
        let nn = mesh.nodes.len();
        let mut fixed = vec![false; 3 * nn];
        for (a, x) in mesh.nodes.iter().enumerate() {
            fixed[3 * a] = true;
            fixed[3 * a + 1] = true;
            if x[2] == -lz {
                fixed[3 * a + 2] = true;
            }
        }
        let loads = top_pressure_loads(&mesh, p);
        let u = solve_with_bc(&mesh, &mat, &fixed, &vec![0.0; 3 * nn], &loads);
        let nu = mat.nu;
        let expect = -p * lz * (1.0 + nu) * (1.0 - 2.0 * nu) / (mat.e * (1.0 - nu));
        let top = mesh.node_index(0, 0, mesh.dims[2] - 1);
        assert_relative_eq!(u[3 * top + 2], expect, max_relative = 1e-10);
    }
}
