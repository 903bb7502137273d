//! Case runner: builds the graded quarter-block mesh around the Hertz contact,
//! applies the symmetry and Boussinesq far-field conditions, condenses the contact
//! candidates, solves the Signorini problem at several load levels and compares with
//! Hertz; plus the mesh-convergence study.

use crate::fe::contact::{ContactModel, contact_extent};
use crate::fe::elasticity::{Factor, Material, assemble};
use crate::fe::hertz_ref::hertz;
use crate::fe::mesh::{HexMesh, graded_edges};
use crate::fe::{FeCase, FeError, FeResult, MeshOptions, boussinesq};
use faer::Mat;
use std::time::Instant;

/// Number of right-hand sides solved at once when building the compliance matrix.
const BATCH: usize = 48;

/// Solves one contact case with the FE model (see [`crate::fe::solve_case`]).
pub fn run_case(case: &FeCase, opt: &MeshOptions) -> Result<FeResult, FeError> {
    let t0 = Instant::now();
    case.check()?;
    opt.check()?;
    let hz = hertz(case.rx, case.ry, case.e_star, case.load)?;
    let [ax, ay] = hz.semi_axes;
    let amin = ax.min(ay);
    let amax = ax.max(ay);
    let nu = opt.poisson;
    // Rigid indenter, frictionless: only E/(1-ν²) = E* enters the normal problem.
    let mat = Material {
        e: case.e_star * (1.0 - nu * nu),
        nu,
    };

    // ---- mesh: uniform fine zone over the contact, geometric grading outside ----
    let rel = opt.element_size_rel;
    let n_fine = (opt.fine_zone_rel / rel).ceil() as usize;
    let size = opt.domain_rel * amax;
    let xe = graded_edges(rel * ax, n_fine, opt.growth, size)?;
    let ye = graded_edges(rel * ay, n_fine, opt.growth, size)?;
    let de = graded_edges(rel * amin, n_fine, opt.growth, size)?;
    let ze: Vec<f64> = de.iter().rev().map(|d| -d).collect();
    let mesh = HexMesh::structured(opt.order, &xe, &ye, &ze)?;
    let [nx, ny, nz] = mesh.dims;
    let nn = mesh.nodes.len();

    // ---- boundary conditions: rollers on x=0, y=0; Boussinesq (unit load) outside ----
    let mut fixed = vec![false; 3 * nn];
    let mut vals = vec![0.0; 3 * nn];
    for k in 0..nz {
        for j in 0..ny {
            for i in 0..nx {
                let a = mesh.node_index(i, j, k);
                if i == nx - 1 || j == ny - 1 || k == 0 {
                    let u = boussinesq::displacement(1.0, mat.e, mat.nu, mesh.nodes[a])
                        .ok_or(FeError::InvalidInput("Boussinesq at origin".into()))?;
                    for c in 0..3 {
                        fixed[3 * a + c] = true;
                        vals[3 * a + c] = u[c];
                    }
                } else {
                    if i == 0 {
                        fixed[3 * a] = true;
                    }
                    if j == 0 {
                        fixed[3 * a + 1] = true;
                    }
                }
            }
        }
    }
    let sys = assemble(&mesh, &mat, &fixed, &vals)?;
    let fac = Factor::nested_dissection(&sys, &mesh)?;

    // ---- top nodes: candidates (fine zone) and the rest ----
    let top = nz - 1;
    // candidates: free top nodes inside the ellipse (x/ax)² + (y/ay)² ≤ fine_zone_rel²
    let is_cand = |i: usize, j: usize| {
        if i >= nx || j >= ny {
            return false;
        }
        let x = mesh.nodes[mesh.node_index(i, j, top)];
        let free = sys.eq_of_dof[3 * mesh.node_index(i, j, top) + 2] != usize::MAX;
        free && (x[0] / ax).powi(2) + (x[1] / ay).powi(2)
            <= opt.fine_zone_rel.powi(2) * (1.0 + 1e-12)
    };
    let mut cand = Vec::new(); // (i, j)
    let mut other = Vec::new();
    for j in 0..ny {
        for i in 0..nx {
            if is_cand(i, j) {
                cand.push((i, j));
            } else {
                other.push((i, j));
            }
        }
    }
    let profile = |i: usize, j: usize| {
        let x = mesh.nodes[mesh.node_index(i, j, top)];
        x[0] * x[0] / (2.0 * case.rx) + x[1] * x[1] / (2.0 * case.ry)
    };
    let zeq = |i: usize, j: usize| sys.eq_of_dof[3 * mesh.node_index(i, j, top) + 2];
    let wval = |sol: &Mat<f64>, col: usize, i: usize, j: usize| {
        let e = zeq(i, j);
        if e == usize::MAX { 0.0 } else { sol[(e, col)] }
    };

    // unit Boussinesq response (downward displacement w = -u_z)
    let mut ub = Mat::<f64>::zeros(sys.n_eq, 1);
    for e in 0..sys.n_eq {
        ub[(e, 0)] = sys.rhs_fixed[e];
    }
    fac.solve_in_place(ub.as_mut());
    let w_b = |i: usize, j: usize| {
        let e = zeq(i, j);
        if e == usize::MAX {
            -vals[3 * mesh.node_index(i, j, top) + 2]
        } else {
            -ub[(e, 0)]
        }
    };

    // compliance columns: unit downward force at candidate j gives w = K⁻¹ e_j
    let nc = cand.len();
    let mut c = Mat::<f64>::zeros(nc, nc);
    let mut c_other = Mat::<f64>::zeros(other.len(), nc);
    let mut rhs = Mat::<f64>::zeros(sys.n_eq, BATCH);
    for start in (0..nc).step_by(BATCH) {
        let cols = BATCH.min(nc - start);
        rhs.fill(0.0);
        for q in 0..cols {
            let (i, j) = cand[start + q];
            rhs[(zeq(i, j), q)] = 1.0;
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
    let model = ContactModel {
        h: cand.iter().map(|&(i, j)| profile(i, j)).collect(),
        c,
        w_unit: cand.iter().map(|&(i, j)| w_b(i, j)).collect(),
        h_other: other.iter().map(|&(i, j)| profile(i, j)).collect(),
        c_other,
        w_unit_other: other.iter().map(|&(i, j)| w_b(i, j)).collect(),
        on_zone_edge: cand
            .iter()
            .map(|&(i, j)| !is_cand(i + 1, j) || !is_cand(i, j + 1))
            .collect(),
    };

    // ---- force–approach curve ----
    let levels = opt.curve_levels.max(1);
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

    // ---- outputs at the target load ----
    let trib = mesh.top_tributary_areas();
    let axis = |along_x: bool| {
        let mut xs = Vec::new();
        let mut fs = Vec::new();
        let mut gs = Vec::new();
        for (r, &(i, j)) in cand.iter().enumerate() {
            if (along_x && j == 0) || (!along_x && i == 0) {
                let x = mesh.nodes[mesh.node_index(i, j, top)];
                xs.push(if along_x { x[0] } else { x[1] });
                fs.push(st.forces[r]);
                gs.push(st.gaps[r]);
            }
        }
        contact_extent(&xs, &fs, &gs).ok_or(FeError::CandidateZoneTooSmall)
    };
    let semi_axes = [axis(true)?, axis(false)?];
    let origin = cand
        .iter()
        .position(|&(i, j)| i == 0 && j == 0)
        .ok_or(FeError::CandidateZoneTooSmall)?;
    let peak_pressure = st.forces[origin] / trib[0];
    let min_pressure = cand
        .iter()
        .zip(&st.forces)
        .map(|(&(i, j), f)| f / trib[i + nx * j])
        .fold(f64::INFINITY, f64::min);
    let result = FeResult {
        curve,
        approach: st.approach,
        semi_axes,
        peak_pressure,
        min_pressure,
        element_size: rel * amin,
        dofs: sys.n_eq,
        seconds: t0.elapsed().as_secs_f64(),
    };
    if !(result.approach.is_finite() && result.peak_pressure.is_finite()) {
        return Err(FeError::NonFinite("result"));
    }
    Ok(result)
}

/// Mesh-convergence study: runs [`run_case`] at each relative element size in
/// `levels` (element size at the contact / Hertz semi-axis) with otherwise default
/// options, and reports the relative errors against Hertz.
pub fn run_convergence(
    case: &FeCase,
    levels: &[f64],
) -> Result<Vec<crate::fe::ConvergenceRow>, FeError> {
    run_convergence_with(case, levels, &MeshOptions::default())
}

/// As [`run_convergence`], with the other mesh options taken from `base`.
pub fn run_convergence_with(
    case: &FeCase,
    levels: &[f64],
    base: &MeshOptions,
) -> Result<Vec<crate::fe::ConvergenceRow>, FeError> {
    let hz = hertz(case.rx, case.ry, case.e_star, case.load)?;
    levels
        .iter()
        .map(|&rel| {
            let opt = MeshOptions {
                element_size_rel: rel,
                ..*base
            };
            let r = run_case(case, &opt)?;
            Ok(crate::fe::ConvergenceRow {
                element_size: r.element_size,
                element_size_over_a: rel,
                dofs: r.dofs,
                approach_error_rel: r.approach / hz.approach - 1.0,
                semi_axis_error_rel: [
                    r.semi_axes[0] / hz.semi_axes[0] - 1.0,
                    r.semi_axes[1] / hz.semi_axes[1] - 1.0,
                ],
                seconds: r.seconds,
            })
        })
        .collect()
}
