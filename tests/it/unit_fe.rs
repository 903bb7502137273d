//! Unit tests of the FE Hertz check: mesh, Boussinesq far field, Hertz reference, boundary conditions, the assembled system.

mod mesh {
    use kinrepro::fe::mesh::*;

    #[test]
    fn graded_edges_reach_total_and_grow() {
        let e = graded_edges(0.1, 5, 1.5, 10.0).unwrap();
        assert!((e[5] - 0.5).abs() < 1e-12);
        assert_eq!(*e.last().unwrap(), 10.0);
        let s: Vec<f64> = e.windows(2).map(|w| w[1] - w[0]).collect();
        assert!(s[5..].windows(2).all(|w| w[1] > w[0]));
    }

    #[test]
    fn structured_counts() {
        let m = HexMesh::structured(2, &[0.0, 1.0, 2.0], &[0.0, 1.0], &[-1.0, 0.0]).unwrap();
        assert_eq!(m.dims, [5, 3, 3]);
        assert_eq!(m.n_elements(), 2);
        let a: f64 = m.top_tributary_areas().iter().sum();
        assert!((a - 2.0).abs() < 1e-12);
    }
}

mod boussinesq {
    use approx::assert_relative_eq;
    use kinrepro::fe::boussinesq::*;
    use std::f64::consts::PI;

    #[test]
    fn surface_deflection_closed_form() {
        let (p, e, nu) = (10.0, 200e9, 0.3);
        let r = 1e-3;
        let u = displacement(p, e, nu, [r * 0.6, r * 0.8, 0.0]).unwrap();
        assert_relative_eq!(-u[2], p * (1.0 - nu * nu) / (PI * e * r), max_relative = 1e-12);
        // surface radial displacement: -(1-2ν)(1+ν) P /(2π E r)
        let ur = u[0].hypot(u[1]);
        assert_relative_eq!(
            ur,
            (1.0 - 2.0 * nu) * (1.0 + nu) * p / (2.0 * PI * e * r),
            max_relative = 1e-12
        );
        assert!(displacement(p, e, nu, [0.0; 3]).is_none());
    }

    /// The field satisfies Navier's equation `(λ+G) ∇(∇·u) + G ∇²u = 0`;
    /// checked by finite differences at an interior point.
    #[test]
    fn satisfies_navier_equation() {
        let (e, nu) = (1.0, 0.3);
        let g = e / (2.0 * (1.0 + nu));
        let lam = e * nu / ((1.0 + nu) * (1.0 - 2.0 * nu));
        let x0 = [0.7, -0.4, -0.9];
        let h = 1e-3;
        let u = |x: [f64; 3]| displacement(1.0, e, nu, x).unwrap();
        let shift = |x: [f64; 3], d: usize, s: f64| {
            let mut y = x;
            y[d] += s;
            y
        };
        // second derivatives ∂²u_i/∂x_j∂x_k by central differences
        let d2 = |i: usize, j: usize, k: usize| {
            (u(shift(shift(x0, j, h), k, h))[i]
                - u(shift(shift(x0, j, h), k, -h))[i]
                - u(shift(shift(x0, j, -h), k, h))[i]
                + u(shift(shift(x0, j, -h), k, -h))[i])
                / (4.0 * h * h)
        };
        for i in 0..3 {
            let grad_div: f64 = (0..3).map(|j| d2(j, j, i)).sum();
            let lap: f64 = (0..3).map(|j| d2(i, j, j)).sum();
            let res = (lam + g) * grad_div + g * lap;
            assert!(res.abs() < 1e-5, "component {i}: {res}");
        }
    }
}

mod hertz_ref {
    use kinrepro::fe::hertz_ref::*;

    #[test]
    fn johnson_table_and_axis_orientation() {
        // For b/a = 0.5 (m = 0.75): K(0.75) = 2.156515647499643,
        // E(0.75) = 1.211056027568459 (A&S table 17.1), so the curvature ratio
        // B/A = ((a/b)^2 E - K)/(K - E) is known independently of kinrepro's AGM.
        let (k, e) = (2.156_515_647_499_643, 1.211_056_027_568_459);
        let rho = (4.0 * e - k) / (k - e);
        let h = hertz(1.0 / (2.0 * 1.0), 1.0 / (2.0 * rho), 1.0, 1.0).unwrap();
        assert!((h.semi_axes[1] / h.semi_axes[0] - 0.5).abs() < 1e-9);
        let g = hertz(1.0 / (2.0 * rho), 1.0 / (2.0 * 1.0), 1.0, 1.0).unwrap();
        assert!((g.semi_axes[0] / h.semi_axes[1] - 1.0).abs() < 1e-12);
        assert!((g.approach / h.approach - 1.0).abs() < 1e-12);
        assert!(hertz(-1.0, 1.0, 1.0, 1.0).is_err());
        assert!(hertz(1.0, 1.0, 1.0, f64::NAN).is_err());
    }
}

mod validate {
    use kinrepro::fe::elasticity::Material;
    use kinrepro::fe::mesh::HexMesh;
    use kinrepro::fe::validate::*;

    /// Rollers on x = 0 and y = 0 fix one DOF each; the far faces (x, y
    /// maximal, the bottom) fix all three. Counted on a 3 x 4 x 3 node grid
    /// from the grid alone: (nx-1)(ny-1)(nz-1) nodes lie off the far faces,
    /// of which (ny-1)(nz-1) have x = 0 and (nx-1)(nz-1) have y = 0 (the
    /// z axis node counts in both).
    #[test]
    fn boundary_conditions_fix_rollers_and_far_faces() {
        let mesh =
            HexMesh::structured(1, &[0.0, 1.0, 2.0], &[0.0, 1.0, 2.0, 3.0], &[-2.0, -1.0, 0.0])
                .unwrap();
        let [nx, ny, nz] = mesh.dims;
        assert_eq!([nx, ny, nz], [3, 4, 3]);
        let mat = Material { e: 2e11, nu: 0.3 };
        let (fixed, vals) = boundary_conditions(&mesh, &mat).unwrap();
        let inner = (nx - 1) * (ny - 1) * (nz - 1);
        let far = nx * ny * nz - inner;
        let rollers = (ny - 1) * (nz - 1) + (nx - 1) * (nz - 1);
        assert_eq!(fixed.iter().filter(|&&f| f).count(), 3 * far + rollers);
        // A roller is held at zero; the far field moves (Boussinesq: the
        // surface sinks under a downward load, u_z < 0 on the top face).
        let roller = mesh.node_index(0, 1, nz - 1);
        assert!(fixed[3 * roller] && !fixed[3 * roller + 1] && vals[3 * roller] == 0.0);
        let far_top = mesh.node_index(nx - 1, 0, nz - 1);
        assert!(fixed[3 * far_top + 2] && vals[3 * far_top + 2] < 0.0);
    }
}

mod system {
    //! Tests of the assembled linear-elastic system: the patch test on a
    //! distorted mesh and uniform-pressure states against closed forms.

    use approx::assert_relative_eq;
    use kinrepro::fe::elasticity::{Material, element_stress};
    use kinrepro::fe::mesh::HexMesh;
    use kinrepro::fe::system::{Factor, assemble};

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
                if e == usize::MAX { vals[d] } else { rhs[(e, 0)] }
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
                    assert!((u[3 * a + c] - ex[c]).abs() < 1e-12, "order {order} node {a}");
                }
            }
            // Constant stress = D ε with ε from the linear field's gradient.
            let eps = [2e-3, 1.5e-3, 0.9e-3, -0.5e-3 + 0.7e-3, -0.2e-3 + 0.1e-3, 0.3e-3 - 0.6e-3];
            let d = mat.d_matrix();
            let sig: [f64; 6] = std::array::from_fn(|r| (0..6).map(|s| d[r][s] * eps[s]).sum());
            let mut en = Vec::new();
            for el in 0..mesh.n_elements() {
                mesh.element_nodes(el, &mut en);
                let coords: Vec<[f64; 3]> = en.iter().map(|&a| mesh.nodes[a]).collect();
                let ue: Vec<[f64; 3]> =
                    en.iter().map(|&a| [u[3 * a], u[3 * a + 1], u[3 * a + 2]]).collect();
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
