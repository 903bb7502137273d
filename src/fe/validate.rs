//! Case runner: builds the graded quarter-block mesh around the Hertz contact,
//! applies the symmetry and Boussinesq far-field conditions, condenses the contact
//! candidates, solves the Signorini problem at several load levels and compares with
//! Hertz; plus the mesh-convergence study.

use crate::fe::contact::{ContactModel, ContactState, contact_extent};
use crate::fe::elasticity::Material;
use crate::fe::hertz_ref::hertz;
use crate::fe::mesh::{HexMesh, graded_edges};
use crate::fe::system::{Factor, FreeSystem, assemble};
use crate::fe::{ConvergenceRow, FeCase, FeError, FeResult, MeshOptions, boussinesq};
use faer::Mat;
use std::time::Instant;

/// Number of right-hand sides solved at once when building the compliance matrix.
const BATCH: usize = 48;

/// Solves one contact case with the FE model: mesh, boundary conditions,
/// contact candidates, their compliance, the force-approach curve, and the
/// outputs at the target load. The case is checked by [`hertz`].
pub fn solve_case(case: &FeCase, opt: &MeshOptions) -> Result<FeResult, FeError> {
    let t0 = Instant::now();
    let hz = hertz(case.rx, case.ry, case.e_star, case.load)?;
    opt.check()?;
    let [ax, ay] = hz.semi_axes;
    let nu = opt.poisson;
    // Rigid indenter, frictionless: only E/(1-ν²) = E* enters the normal problem.
    let mat = Material { e: case.e_star * (1.0 - nu * nu), nu };
    let mesh = build_mesh(ax, ay, opt)?;
    let (fixed, vals) = boundary_conditions(&mesh, &mat)?;
    let sys = assemble(&mesh, &mat, &fixed, &vals)?;
    let top = TopNodes::new(&mesh, &sys, [ax, ay], opt.fine_zone_rel);
    // The gap at the candidates first: an exact gap undefined there is an
    // error before the costly factorisation.
    let h = top.cand.iter().map(|&(i, j)| top.profile(i, j, case)).collect::<Result<_, _>>()?;
    let fac = Factor::nested_dissection(&sys, &mesh)?;
    let model = contact_model(case, h, &top, &fac, &vals);
    let (curve, st) = load_curve(case, &model, opt.curve_levels)?;
    let (semi_axes, peak_pressure, min_pressure) = outputs(&top, &st)?;
    let result = FeResult {
        curve,
        approach: st.approach,
        semi_axes,
        peak_pressure,
        min_pressure,
        element_size: opt.element_size_rel * ax.min(ay),
        dofs: sys.n_eq,
        seconds: t0.elapsed().as_secs_f64(),
    };
    if !(result.approach.is_finite() && result.peak_pressure.is_finite()) {
        return Err(FeError::NonFinite("result"));
    }
    Ok(result)
}

/// The quarter-block mesh: a uniform fine zone over the contact (semi-axes
/// `ax`, `ay`), geometric grading outside.
pub fn build_mesh(ax: f64, ay: f64, opt: &MeshOptions) -> Result<HexMesh, FeError> {
    let rel = opt.element_size_rel;
    let n_fine = (opt.fine_zone_rel / rel).ceil() as usize;
    let size = opt.domain_rel * ax.max(ay);
    let xe = graded_edges(rel * ax, n_fine, opt.growth, size)?;
    let ye = graded_edges(rel * ay, n_fine, opt.growth, size)?;
    let de = graded_edges(rel * ax.min(ay), n_fine, opt.growth, size)?;
    let ze: Vec<f64> = de.iter().rev().map(|d| -d).collect();
    HexMesh::structured(opt.order, &xe, &ye, &ze)
}

/// Boundary conditions: rollers on x = 0 and y = 0, the Boussinesq
/// displacement of a unit load on the far faces. Returns (prescribed flag,
/// prescribed value) per DOF.
pub fn boundary_conditions(
    mesh: &HexMesh,
    mat: &Material,
) -> Result<(Vec<bool>, Vec<f64>), FeError> {
    let [nx, ny, nz] = mesh.dims;
    let nn = mesh.nodes.len();
    let mut fixed = vec![false; 3 * nn];
    let mut vals = vec![0.0; 3 * nn];
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                let a = mesh.node_index(i, j, k);
                if i == nx - 1 || j == ny - 1 || k == 0 {
                    let u = boussinesq::displacement(1.0, mat.e, mat.nu, mesh.nodes[a])
                        .ok_or(FeError::InvalidInput("Boussinesq at origin".into()))?;
                    fixed[3 * a..3 * a + 3].fill(true);
                    vals[3 * a..3 * a + 3].copy_from_slice(&u);
                } else {
                    fixed[3 * a] = i == 0;
                    fixed[3 * a + 1] = j == 0;
                }
            }
        }
    }
    Ok((fixed, vals))
}

/// The top face split into contact candidates (free top nodes in the fine
/// zone, the ellipse (x/ax)² + (y/ay)² ≤ fine_zone_rel²) and the rest.
pub struct TopNodes<'a> {
    mesh: &'a HexMesh,
    sys: &'a FreeSystem,
    semi_axes: [f64; 2],
    fine_zone_rel: f64,
    /// (i, j) of the candidates and of the other top nodes.
    pub cand: Vec<(usize, usize)>,
    pub other: Vec<(usize, usize)>,
}

impl<'a> TopNodes<'a> {
    pub fn new(
        mesh: &'a HexMesh,
        sys: &'a FreeSystem,
        semi_axes: [f64; 2],
        fine_zone_rel: f64,
    ) -> Self {
        let mut t =
            TopNodes { mesh, sys, semi_axes, fine_zone_rel, cand: Vec::new(), other: Vec::new() };
        let [nx, ny, _] = mesh.dims;
        let nodes = (0..ny).flat_map(|j| (0..nx).map(move |i| (i, j)));
        (t.cand, t.other) = nodes.partition(|&(i, j)| t.is_cand(i, j));
        t
    }

    fn node(&self, i: usize, j: usize) -> usize {
        self.mesh.node_index(i, j, self.mesh.dims[2] - 1)
    }

    /// Whether top node (i, j) is a contact candidate.
    pub fn is_cand(&self, i: usize, j: usize) -> bool {
        let [nx, ny, _] = self.mesh.dims;
        if i >= nx || j >= ny {
            return false;
        }
        let x = self.mesh.nodes[self.node(i, j)];
        let [ax, ay] = self.semi_axes;
        let free = self.zeq(i, j) != usize::MAX;
        free && (x[0] / ax).powi(2) + (x[1] / ay).powi(2)
            <= self.fine_zone_rel.powi(2) * (1.0 + 1e-12)
    }

    /// Equation number of the vertical DOF of top node (i, j).
    fn zeq(&self, i: usize, j: usize) -> usize {
        self.sys.eq_of_dof[3 * self.node(i, j) + 2]
    }

    /// The gap of the undeformed surface to the indenter at a contact
    /// candidate: an error where the case's exact gap is not defined.
    fn profile(&self, i: usize, j: usize, case: &FeCase) -> Result<f64, FeError> {
        let x = self.mesh.nodes[self.node(i, j)];
        case.gap.height_in_range(case.rx, case.ry, x[0], x[1])
    }

    /// The gap at another top node: infinite outside the footprint of an
    /// exact gap's curved body (no indenter there to touch).
    fn profile_other(&self, i: usize, j: usize, case: &FeCase) -> f64 {
        let x = self.mesh.nodes[self.node(i, j)];
        case.gap.height(case.rx, case.ry, x[0], x[1]).unwrap_or(f64::INFINITY)
    }
}

/// The contact candidates condensed: compliance columns (a unit downward
/// force at candidate j gives w = K⁻¹ e_j, solved [`BATCH`] at a time) and
/// the unit Boussinesq response (downward displacement w = -u_z), with the
/// gap `h` at the candidates and the case's gap at the other top nodes.
fn contact_model(
    case: &FeCase,
    h: Vec<f64>,
    top: &TopNodes,
    fac: &Factor,
    vals: &[f64],
) -> ContactModel {
    let sys = top.sys;
    let wval = |sol: &Mat<f64>, col: usize, i: usize, j: usize| {
        let e = top.zeq(i, j);
        if e == usize::MAX { 0.0 } else { sol[(e, col)] }
    };
    let mut ub = Mat::<f64>::from_fn(sys.n_eq, 1, |e, _| sys.rhs_fixed[e]);
    fac.solve_in_place(ub.as_mut());
    let w_b = |i: usize, j: usize| {
        let e = top.zeq(i, j);
        if e == usize::MAX { -vals[3 * top.node(i, j) + 2] } else { -ub[(e, 0)] }
    };
    let (cand, other) = (&top.cand, &top.other);
    let nc = cand.len();
    let mut c = Mat::<f64>::zeros(nc, nc);
    let mut c_other = Mat::<f64>::zeros(other.len(), nc);
    let mut rhs = Mat::<f64>::zeros(sys.n_eq, BATCH);
    for start in (0..nc).step_by(BATCH) {
        let cols = BATCH.min(nc - start);
        rhs.fill(0.0);
        for q in 0..cols {
            let (i, j) = cand[start + q];
            rhs[(top.zeq(i, j), q)] = 1.0;
        }
        fac.solve_in_place(rhs.as_mut());
        for q in 0..cols {
            for (r, &(i, j)) in cand.iter().enumerate() {
                c[(r, start + q)] = wval(&rhs, q, i, j);
            }
            for (r, &(i, j)) in other.iter().enumerate() {
                c_other[(r, start + q)] = wval(&rhs, q, i, j);
            }
        }
    }
    ContactModel {
        h,
        c,
        w_unit: cand.iter().map(|&(i, j)| w_b(i, j)).collect(),
        h_other: other.iter().map(|&(i, j)| top.profile_other(i, j, case)).collect(),
        c_other,
        w_unit_other: other.iter().map(|&(i, j)| w_b(i, j)).collect(),
        on_zone_edge: cand
            .iter()
            .map(|&(i, j)| !top.is_cand(i + 1, j) || !top.is_cand(i, j + 1))
            .collect(),
    }
}

/// The force-approach curve at `levels` equal load steps up to the case's
/// load (each started from the previous active set); returns the curve
/// (approach, load) and the state at the full load.
fn load_curve(
    case: &FeCase,
    model: &ContactModel,
    levels: usize,
) -> Result<(Vec<(f64, f64)>, ContactState), FeError> {
    let levels = levels.max(1);
    let mut curve = Vec::with_capacity(levels);
    let mut active: Option<Vec<bool>> = None;
    let mut state = None;
    for l in 1..=levels {
        let f = case.load * l as f64 / levels as f64;
        let guess = hertz(case.rx, case.ry, case.e_star, f)?.approach;
        let st = model.solve(f, guess, active.as_deref())?;
        curve.push((st.approach, f));
        active = Some(st.forces.iter().map(|&v| v > 0.0).collect());
        state = Some(st);
    }
    let st = state.ok_or(FeError::NonFinite("no load level"))?;
    Ok((curve, st))
}

/// The outputs at the target load: the contact semi-axes along x and y,
/// the peak pressure at the origin and the least candidate pressure
/// (nodal force over tributary area).
fn outputs(top: &TopNodes, st: &ContactState) -> Result<([f64; 2], f64, f64), FeError> {
    let mesh = top.mesh;
    let nx = mesh.dims[0];
    let trib = mesh.top_tributary_areas();
    let axis = |along_x: bool| {
        let mut xs = Vec::new();
        let mut fs = Vec::new();
        let mut gs = Vec::new();
        for (r, &(i, j)) in top.cand.iter().enumerate() {
            if (along_x && j == 0) || (!along_x && i == 0) {
                let x = mesh.nodes[top.node(i, j)];
                xs.push(if along_x { x[0] } else { x[1] });
                fs.push(st.forces[r]);
                gs.push(st.gaps[r]);
            }
        }
        contact_extent(&xs, &fs, &gs).ok_or(FeError::CandidateZoneTooSmall)
    };
    let semi_axes = [axis(true)?, axis(false)?];
    let origin = top
        .cand
        .iter()
        .position(|&(i, j)| i == 0 && j == 0)
        .ok_or(FeError::CandidateZoneTooSmall)?;
    let peak_pressure = st.forces[origin] / trib[0];
    let min_pressure = top
        .cand
        .iter()
        .zip(&st.forces)
        .map(|(&(i, j), f)| f / trib[i + nx * j])
        .fold(f64::INFINITY, f64::min);
    Ok((semi_axes, peak_pressure, min_pressure))
}

/// Mesh-convergence study: [`solve_case`] at each relative element size in
/// `levels` (element size at the contact / Hertz semi-axis) with otherwise
/// default options, and the relative errors against Hertz.
pub fn convergence_study(case: &FeCase, levels: &[f64]) -> Result<Vec<ConvergenceRow>, FeError> {
    let hz = hertz(case.rx, case.ry, case.e_star, case.load)?;
    levels
        .iter()
        .map(|&rel| {
            let opt = MeshOptions { element_size_rel: rel, ..Default::default() };
            let r = solve_case(case, &opt)?;
            Ok(ConvergenceRow {
                element_size: r.element_size,
                element_size_over_a: rel,
                dofs: r.dofs,
                approach_error_rel: r.approach / hz.approach - 1.0,
                semi_axis_error_rel: [0, 1].map(|k| r.semi_axes[k] / hz.semi_axes[k] - 1.0),
                seconds: r.seconds,
            })
        })
        .collect()
}
