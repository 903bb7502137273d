//! A small finite-element contact solver that validates Hertz
//! theory for the contact types of kinematic couplings.
//!
//! Model: a rigid indenter with the combined gap profile
//! `h(x, y) = x²/(2Rx) + y²/(2Ry)` (or, on request, the exact separation of
//! the pair's two surfaces, [`gap`]) is pressed, frictionless, into an elastic quarter
//! block (symmetry rollers on `x = 0`, `y = 0`) whose outer faces carry the
//! Boussinesq point-load displacement field of the total load, so that the block
//! represents a half-space and the approach is measured from infinity, as in Hertz
//! theory. The block gets `E = E*(1-ν²)` with `ν` = [`MeshOptions::poisson`]
//! (default 0.3): with a rigid frictionless indenter only `E/(1-ν²)` enters the
//! normal problem (Johnson 1985 §3.4), so the result depends only on `E*`.
//!
//! Modules: [`mesh`] (graded hexahedral mesh), [`elasticity`] (elements),
//! [`system`] (assembly, sparse Cholesky), [`boussinesq`] (far field), [`contact`] (Signorini active set),
//! [`hertz_ref`] (kinrepro's Hertz law, the reference), [`validate`] (case runner, convergence study),
//! [`gap`] (quadratic or exact gap), [`pairs`] (the pairs of scenes), [`conformity`] (exact against
//! quadratic gap as a groove closes on its ball).

pub mod boussinesq;
pub mod conformity;
pub mod contact;
pub mod elasticity;
pub mod gap;
pub mod hertz_ref;
pub mod mesh;
pub mod pairs;
pub mod system;
pub mod validate;

pub use gap::{Gap, Surface};
pub use hertz_ref::{HertzSolution, hertz};
pub use validate::{convergence_study, solve_case};

/// Errors of the FE contact solver.
#[derive(Debug, thiserror::Error)]
pub enum FeError {
    /// Bad input (non-positive radius, load, modulus, invalid mesh options...).
    #[error("invalid input: {0}")]
    InvalidInput(String),
    /// The sparse Cholesky factorization failed (matrix not positive definite).
    #[error("sparse factorization failed: {0}")]
    Factorization(String),
    /// The contact active set did not converge.
    #[error("contact active set did not converge after {0} iterations")]
    ContactNotConverged(usize),
    /// The contact zone reached the edge of the candidate (fine) zone.
    #[error("contact zone reaches the edge of the candidate zone; increase fine_zone_rel")]
    CandidateZoneTooSmall,
    /// The exact gap is not defined where the case needs it.
    #[error("exact gap undefined: {0}")]
    GapUndefined(String),
    /// The mesh would need more memory than one machine has (`MAX_NODES`).
    #[error(
        "the mesh at element size {element_size_rel:e} x the contact semi-axis would have \
         {nodes:.3e} nodes (about {gb:.3e} GB to solve); the bound is {max} nodes (about \
         {max_gb:.0} GB)"
    )]
    MeshTooLarge { element_size_rel: f64, nodes: f64, gb: f64, max: usize, max_gb: f64 },
    /// A non-finite or non-physical value appeared.
    #[error("non-finite or non-physical value in {0}")]
    NonFinite(&'static str),
}

/// One contact case: profile radii of the combined gap `h = x²/(2rx) + y²/(2ry)`,
/// which size the mesh and give the Hertz reference, and the gap profile the
/// indenter has (that quadratic one by default, or the exact separation).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FeCase {
    /// Effective radius in the x–z plane (m).
    pub rx: f64,
    /// Effective radius in the y–z plane (m).
    pub ry: f64,
    /// Effective modulus `E* = 1/((1-ν1²)/E1 + (1-ν2²)/E2)` (Pa).
    pub e_star: f64,
    /// Normal load (N).
    pub load: f64,
    /// The gap profile of the indenter.
    pub gap: Gap,
}

/// Mesh and model options.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MeshOptions {
    /// Element size at the contact divided by the Hertz semi-axis along the same
    /// direction (in depth: by the smaller semi-axis).
    pub element_size_rel: f64,
    /// Element order: 2 = 27-node Lagrange (default), 1 = 8-node.
    pub order: usize,
    /// Extent of the uniform fine zone (= contact candidates) / Hertz semi-axis.
    pub fine_zone_rel: f64,
    /// Block size (x, y and depth) / larger Hertz semi-axis.
    pub domain_rel: f64,
    /// Geometric growth ratio of the element sizes outside the fine zone.
    pub growth: f64,
    /// Poisson's ratio of the block (`E = E*(1-ν²)`).
    pub poisson: f64,
    /// Number of load levels of the force–approach curve.
    pub curve_levels: usize,
}

/// Most nodes of an FE mesh: 2.5 times the default mesh's 24 389 nodes.
/// The default mesh takes 1.3 GB to solve; the sparse factor of a 3-D mesh
/// grows as nodes^(4/3) (nested dissection), so the bound is about 4.3 GB.
pub const MAX_NODES: usize = 60_000;

/// Memory to solve a mesh of `nodes` nodes [GB]: 1.3 GB at 24 389 nodes,
/// scaled as nodes^(4/3).
fn solve_gb(nodes: f64) -> f64 {
    1.3 * (nodes / 24_389.0).powf(4.0 / 3.0)
}

impl Default for MeshOptions {
    /// The default mesh, meeting approach within 2 % and semi-axes within 5 % of
    /// Hertz for the kinrepro contact types. The relative sizes are chosen so that
    /// no node falls on the Hertz contact edge (node spacing `h/2 = 0.09 a`), which
    /// would flatter the semi-axis estimate.
    fn default() -> Self {
        Self {
            element_size_rel: 0.18,
            order: 2,
            fine_zone_rel: 1.3,
            domain_rel: 10.0,
            growth: 1.5,
            poisson: 0.3,
            curve_levels: 5,
        }
    }
}

impl MeshOptions {
    /// A coarse mesh for fast tests (seconds in release), within 5 % of Hertz.
    pub fn coarse() -> Self {
        Self { element_size_rel: 0.3, ..Self::default() }
    }

    fn check(&self) -> Result<(), FeError> {
        let ok = self.element_size_rel > 0.0
            && self.element_size_rel <= 1.0
            && (self.order == 1 || self.order == 2)
            && self.fine_zone_rel > 1.0
            && self.domain_rel > 2.0 * self.fine_zone_rel
            && self.growth >= 1.0
            && self.growth <= 3.0
            && self.poisson >= 0.0
            && self.poisson < 0.5;
        if !ok {
            return Err(FeError::InvalidInput(format!("mesh options {self:?}")));
        }
        self.check_size()
    }

    /// Refuse a mesh above [`MAX_NODES`] before anything is allocated.
    pub fn check_size(&self) -> Result<(), FeError> {
        let nodes = self.estimated_nodes();
        if nodes.is_nan() || nodes > MAX_NODES as f64 {
            return Err(FeError::MeshTooLarge {
                element_size_rel: self.element_size_rel,
                nodes,
                gb: solve_gb(nodes),
                max: MAX_NODES,
                max_gb: solve_gb(MAX_NODES as f64),
            });
        }
        Ok(())
    }

    /// The nodes of the mesh of a circular contact ([`validate::build_mesh`]
    /// with a = 1): per axis `n_f` = ceil(fine_zone_rel / h) uniform
    /// elements of size h, then the k graded ones, the fewest with
    /// h g + h g^2 + ... + h g^k at least R = domain_rel - n_f h, i.e.
    /// k = ceil(ln(1 + R (g - 1) / (h g)) / ln g); order (n_f + k) + 1 nodes
    /// per axis, cubed.
    pub fn estimated_nodes(&self) -> f64 {
        let h = self.element_size_rel;
        let n_fine = (self.fine_zone_rel / h).ceil();
        let rest = (self.domain_rel - n_fine * h).max(0.0);
        let g = self.growth;
        let graded = if g > 1.0 {
            ((1.0 + rest * (g - 1.0) / (h * g)).ln() / g.ln()).ceil()
        } else {
            (rest / h).ceil()
        };
        (self.order as f64 * (n_fine + graded) + 1.0).powi(3)
    }
}

/// Result of one FE contact solve.
#[derive(Debug, Clone, PartialEq)]
pub struct FeResult {
    /// Force–approach curve `(approach m, total force N)` at increasing load levels.
    pub curve: Vec<(f64, f64)>,
    /// Approach at the target load (m).
    pub approach: f64,
    /// Contact semi-axes `[along x, along y]` (m).
    pub semi_axes: [f64; 2],
    /// Peak pressure (Pa): nodal force / tributary area at the centre node.
    pub peak_pressure: f64,
    /// Least nodal pressure over the contact candidates (Pa), force / tributary
    /// area; the Signorini conditions require it to be >= 0.
    pub min_pressure: f64,
    /// Element size at the contact across the smaller semi-axis (m).
    pub element_size: f64,
    /// Number of free degrees of freedom.
    pub dofs: usize,
    /// Wall-clock time of the solve (s).
    pub seconds: f64,
}

/// One level of a mesh-convergence study. Errors are signed, `FE/Hertz - 1`.
#[derive(Debug, Clone, PartialEq, serde::Serialize)]
pub struct ConvergenceRow {
    /// Element size at the contact across the smaller semi-axis (m).
    pub element_size: f64,
    /// Element size / Hertz semi-axis.
    pub element_size_over_a: f64,
    /// Free DOFs.
    pub dofs: usize,
    /// Relative approach error.
    pub approach_error_rel: f64,
    /// Relative semi-axis errors `[x, y]`.
    pub semi_axis_error_rel: [f64; 2],
    /// Solve time (s).
    pub seconds: f64,
}
