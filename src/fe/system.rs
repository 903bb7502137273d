//! The global linear-elastic system: sparse assembly of the free-DOF
//! stiffness matrix (lower triangle, CSC) with the prescribed displacements
//! moved to the right-hand side, and its sparse Cholesky factorization
//! (faer; nested-dissection or AMD ordering).

use crate::fe::FeError;
use crate::fe::elasticity::{Material, element_stiffness};
use crate::fe::mesh::HexMesh;
use faer::dyn_stack::{MemBuffer, MemStack};
use faer::perm::PermRef;
use faer::sparse::linalg::cholesky::{
    LltRef, SymbolicCholesky, SymmetricOrdering, factorize_symbolic_cholesky,
};
use faer::sparse::{SparseColMat, SymbolicSparseColMat};
use faer::{Conj, MatMut, Par, Side};
use std::collections::HashMap;

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
    let ndof = 3 * mesh.nodes.len();
    if fixed.len() != ndof || fixed_values.len() != ndof {
        return Err(FeError::InvalidInput("BC vector length".into()));
    }
    let (eq_of_dof, n_eq) = number_equations(fixed);
    if n_eq == 0 {
        return Err(FeError::InvalidInput("no free DOF".into()));
    }
    let pattern = Pattern::lower(mesh, &eq_of_dof, n_eq);
    let mut val = vec![0.0; pattern.row_idx.len()];
    let mut rhs_fixed = vec![0.0; n_eq];
    let mut cache = ElementCache::new(mesh);
    let mut en = Vec::new();
    for e in 0..mesh.n_elements() {
        mesh.element_nodes(e, &mut en);
        let ke = cache.stiffness(mesh, &en, mat)?;
        let dofs: Vec<usize> = en.iter().flat_map(|&a| (0..3).map(move |c| 3 * a + c)).collect();
        pattern.scatter(&eq_of_dof, ke, &dofs, fixed_values, &mut val, &mut rhs_fixed)?;
    }
    let symbolic =
        SymbolicSparseColMat::new_checked(n_eq, n_eq, pattern.col_ptr, None, pattern.row_idx);
    let matrix = SparseColMat::new(symbolic, val);
    Ok(FreeSystem { eq_of_dof, n_eq, matrix, rhs_fixed })
}

/// Equation number of each free DOF, in DOF order (`usize::MAX` for the
/// prescribed ones), and the number of free equations.
fn number_equations(fixed: &[bool]) -> (Vec<usize>, usize) {
    let mut eq_of_dof = vec![usize::MAX; fixed.len()];
    let mut n_eq = 0;
    for (d, &f) in fixed.iter().enumerate() {
        if !f {
            eq_of_dof[d] = n_eq;
            n_eq += 1;
        }
    }
    (eq_of_dof, n_eq)
}

/// Lower-triangular CSC pattern over the free equations (rows >= column).
struct Pattern {
    col_ptr: Vec<usize>,
    row_idx: Vec<usize>,
}

impl Pattern {
    /// The pattern of the nodes that share an element.
    fn lower(mesh: &HexMesh, eq_of_dof: &[usize], n_eq: usize) -> Self {
        // Node adjacency (nodes sharing an element), sorted.
        let mut adj: Vec<Vec<u32>> = vec![Vec::new(); mesh.nodes.len()];
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
        Pattern { col_ptr, row_idx }
    }

    /// Adds the element matrix `ke` (row-major over `dofs`) into the values
    /// `val`; prescribed columns go to the right-hand side `rhs` instead.
    fn scatter(
        &self,
        eq_of_dof: &[usize],
        ke: &[f64],
        dofs: &[usize],
        fixed_values: &[f64],
        val: &mut [f64],
        rhs: &mut [f64],
    ) -> Result<(), FeError> {
        let nd = dofs.len();
        for (lc, &dc) in dofs.iter().enumerate() {
            let ec = eq_of_dof[dc];
            if ec == usize::MAX {
                // prescribed column: move to the right-hand side
                let uc = fixed_values[dc];
                if uc != 0.0 {
                    for (lr, &dr) in dofs.iter().enumerate() {
                        let er = eq_of_dof[dr];
                        if er != usize::MAX {
                            rhs[er] -= ke[lr * nd + lc] * uc;
                        }
                    }
                }
                continue;
            }
            let (start, end) = (self.col_ptr[ec], self.col_ptr[ec + 1]);
            let rows = &self.row_idx[start..end];
            for (lr, &dr) in dofs.iter().enumerate() {
                let er = eq_of_dof[dr];
                if er == usize::MAX || er < ec {
                    continue;
                }
                let pos = rows
                    .binary_search(&er)
                    .map_err(|_| FeError::InvalidInput("sparsity pattern".into()))?;
                val[start + pos] += ke[lr * nd + lc];
            }
        }
        Ok(())
    }
}

/// Element matrices cached by quantized relative node coordinates (the
/// structured mesh repeats few element shapes).
struct ElementCache {
    quantum: f64,
    matrices: HashMap<Vec<i64>, Vec<f64>>,
    coords: Vec<[f64; 3]>,
    key: Vec<i64>,
}

impl ElementCache {
    fn new(mesh: &HexMesh) -> Self {
        let quantum = mesh
            .edges
            .iter()
            .flat_map(|e| e.windows(2).map(|w| w[1] - w[0]))
            .fold(f64::INFINITY, f64::min)
            * 1e-9;
        ElementCache { quantum, matrices: HashMap::new(), coords: Vec::new(), key: Vec::new() }
    }

    /// The stiffness of the element with nodes `en`.
    fn stiffness(
        &mut self,
        mesh: &HexMesh,
        en: &[usize],
        mat: &Material,
    ) -> Result<&[f64], FeError> {
        self.coords.clear();
        self.coords.extend(en.iter().map(|&a| mesh.nodes[a]));
        let x0 = self.coords[0];
        self.key.clear();
        for x in &self.coords {
            for d in 0..3 {
                self.key.push(((x[d] - x0[d]) / self.quantum).round() as i64);
            }
        }
        if !self.matrices.contains_key(&self.key) {
            let ke = element_stiffness(mesh.order, &self.coords, mat)?;
            self.matrices.insert(self.key.clone(), ke);
        }
        Ok(&self.matrices[&self.key])
    }
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
            return Err(FeError::InvalidInput("ordering is not a permutation".into()));
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

    /// Solves `K X = B` in place for a block of right-hand sides.
    pub fn solve_in_place(&self, rhs: MatMut<'_, f64>) {
        let mut mem =
            MemBuffer::new(self.symbolic.solve_in_place_scratch::<f64>(rhs.ncols(), Par::Seq));
        LltRef::new(&self.symbolic, &self.values).solve_in_place_with_conj(
            Conj::No,
            rhs,
            Par::Seq,
            MemStack::new(&mut mem),
        );
    }
}
