//! Tests of the assembled linear-elastic system: the patch test on a
//! distorted mesh and uniform-pressure states against closed forms.

use crate::fe::elasticity::{Material, element_stress};
use crate::fe::mesh::HexMesh;
use crate::fe::system::{Factor, assemble};
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
