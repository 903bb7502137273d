//! Design analysis against independent values: the stiffness of the
//! frictionless V-groove coupling by hand from the six Hertz contact
//! stiffnesses, a finite-difference check of the matrix through the
//! nonlinear solver, the separation load from six-constraint statics, the
//! slip envelope bracketed by full load paths, the statics of an off-centre
//! preload, and the Hertz subsurface shear stress against a brute-force scan.

use crate::common;
use crate::common::load;
use std::path::Path;

use kinrepro::analysis::load::{envelope, load_path};
use kinrepro::analysis::stiffness::CouplingStiffness;
use kinrepro::assembly::Coupling;
use kinrepro::contact::stress::{circular_axis_shear, circular_max_shear, max_shear_ratio};
use kinrepro::solve::quasistatic::{ExternalLoad, LoadEventKind, seat};
use kinrepro::solve::{Load, PointPose, SolverOptions};
use nalgebra::{Matrix6, Vector3, Vector6};

/// The paper's variants and the explicit Kelvin scene.
fn all_scenes() -> impl Iterator<Item = &'static str> {
    crate::common::PAPER_SCENES.into_iter().chain(["custom_kelvin_explicit.toml"])
}

/// (normal, ball centre) of the 90-degree Maxwell V-groove of scene 01
/// (`common::maxwell_contacts`, from docs/model.md's axes and contact numbering, by hand).
fn maxwell_by_hand(alpha: f64) -> Vec<(Vector3<f64>, Vector3<f64>)> {
    common::maxwell_contacts(alpha).into_iter().map(|(c, n)| (n, c)).collect()
}

/// Frictionless contact forces that balance the wrench (F at point p, M):
/// sum_i f_i [n_i; c_i x n_i] + [F; p x F + M] = 0, solved by LU.
fn statics(
    rows: &[(Vector3<f64>, Vector3<f64>)],
    f: Vector3<f64>,
    p: Vector3<f64>,
    m: Vector3<f64>,
) -> Vector6<f64> {
    let a = Matrix6::from_fn(|r, c| {
        let (n, centre) = rows[c];
        if r < 3 { n[r] } else { centre.cross(&n)[r - 3] }
    });
    let mom = p.cross(&f) + m;
    a.lu().solve(&-Vector6::new(f.x, f.y, f.z, mom.x, mom.y, mom.z)).unwrap()
}

#[test]
fn frictionless_vgroove_stiffness_equals_the_hand_closed_form() {
    let (scene, c) = load("01_maxwell_vgroove_steel.toml");
    let mu = Load::nominal(&scene).with_mu(&[0.0; 6]);
    let s = seat(&c, &mu, &SolverOptions::default()).unwrap();
    let k = CouplingStiffness::new(&c, &s, &mu).unwrap();
    // By hand: each contact carries F = 20 / (6 cos a); Hertz sphere-plane,
    // R = 5 mm, E* = 210 GPa / (2 (1 - 0.3^2)): K = 4/3 E* sqrt(R),
    // delta = (F/K)^(2/3), k_n = 3/2 K delta^(1/2). Six springs along the
    // normals: k_z = sum k_n n_z^2 = 6 k_n cos^2 a; k_x = sum k_n n_x^2 =
    // k_n sin^2 a sum_k 2 s_kx^2 = 3 k_n sin^2 a (= k_y); no coupling
    // between translation and rotation at the centre (the s_k sum to zero).
    let alpha = 45f64.to_radians();
    let f = 20.0 / (6.0 * alpha.cos());
    let e_star = 210e9 / (2.0 * (1.0 - 0.09));
    let kh = 4.0 / 3.0 * e_star * 5e-3f64.sqrt();
    let kn = 1.5 * kh * (f / kh).powf(1.0 / 3.0);
    let kz = 6.0 * kn * alpha.cos().powi(2);
    let kx = 3.0 * kn * alpha.sin().powi(2);
    let q = s.pose().apply(&Vector3::zeros());
    let m = k.matrix_at(&q);
    assert!((m[(2, 2)] / kz - 1.0).abs() < 1e-6, "{} vs {kz}", m[(2, 2)]);
    assert!((m[(0, 0)] / kx - 1.0).abs() < 1e-6, "{} vs {kx}", m[(0, 0)]);
    assert!((m[(1, 1)] / kx - 1.0).abs() < 1e-6, "{} vs {kx}", m[(1, 1)]);
    let p = k.principal_at(&q).unwrap();
    let t = p.translational;
    assert!((t[0].0 / kx - 1.0).abs() < 1e-6 && (t[1].0 / kx - 1.0).abs() < 1e-6);
    assert!((t[2].0 / kz - 1.0).abs() < 1e-6);
    assert!(t[2].1.z.abs() > 1.0 - 1e-9, "the stiffest direction is z: {:?}", t[2].1);
    // Rotational stiffness about x by hand: sum k_n (c x n)_x^2 over the contacts.
    let krx: f64 =
        maxwell_by_hand(alpha).iter().map(|(n, centre)| kn * centre.cross(n).x.powi(2)).sum();
    assert!((m[(3, 3)] / krx - 1.0).abs() < 1e-6, "{} vs {krx}", m[(3, 3)]);
    for sp in &k.springs {
        assert!((sp.normal_stiffness / kn - 1.0).abs() < 1e-6);
        assert_eq!(sp.tangential_stiffness, 0.0);
    }
}

#[test]
fn stiffness_is_symmetric_positive_definite_for_every_bundled_scene() {
    for name in all_scenes() {
        let (scene, c) = load(name);
        let mu = Load::nominal(&scene);
        let s = seat(&c, &mu, &SolverOptions::default()).unwrap();
        let k = CouplingStiffness::new(&c, &s, &mu).unwrap();
        for p in &scene.evaluation_points {
            let m = k.matrix_at(&s.pose().apply(&p.position));
            assert!((m - m.transpose()).amax() <= 1e-12 * m.amax(), "{name}");
            let eig = m.symmetric_eigen();
            assert!(eig.eigenvalues.min() > 0.0, "{name}: {:?}", eig.eigenvalues);
            assert!(m.cholesky().is_some(), "{name}");
        }
        // With friction every contact sticks: k_t > 0 at each.
        assert!(k.springs.iter().all(|sp| sp.tangential_stiffness > 0.0), "{name}");
    }
}

/// Deflection [u; phi] of body point `q` between two poses.
fn deflection(
    from: &kinrepro::assembly::BodyPose,
    to: &kinrepro::assembly::BodyPose,
    q: &Vector3<f64>,
) -> Vector6<f64> {
    let d = PointPose::between(from, to, q);
    Vector6::new(d.x_m, d.y_m, d.z_m, d.phi_x_rad, d.phi_y_rad, d.phi_z_rad)
}

#[test]
fn a_small_load_through_the_nonlinear_solver_deflects_by_the_compliance() {
    for (name, mu) in [
        ("01_maxwell_vgroove_steel.toml", vec![0.5; 6]),
        ("01_maxwell_vgroove_steel.toml", vec![0.0; 6]),
        ("02_maxwell_pins_steel.toml", vec![0.45, 0.55, 0.5, 0.52, 0.48, 0.5]),
        ("06_kelvin_steel.toml", vec![0.5; 6]),
        ("custom_kelvin_explicit.toml", vec![0.15; 6]),
    ] {
        let (scene, c) = load(name);
        let mu = Load::nominal(&scene).with_mu(&mu);
        let s = seat(&c, &mu, &SolverOptions::default()).unwrap();
        let k = CouplingStiffness::new(&c, &s, &mu).unwrap();
        let q_body = scene.evaluation_points.last().unwrap().position;
        let q = s.pose().apply(&q_body);
        let comp = k.compliance_at(&q).unwrap();
        // 5 mN forces and 0.2 mN m moments, one axis at a time, at q.
        for axis in 0..6 {
            let mut w = Vector6::zeros();
            w[axis] = if axis < 3 { 5e-3 } else { 2e-4 };
            let load = ExternalLoad {
                force: w.fixed_rows::<3>(0).into(),
                point: q_body,
                moment: w.fixed_rows::<3>(3).into(),
            };
            let path = load_path(&c, &mu, &s, &load, 1.0, &SolverOptions::default()).unwrap();
            assert!(path.first_event.is_none(), "{name} {:?}: {:?}", mu.mu, path.first_event);
            let nonlinear = deflection(&s.pose(), &path.pose, &q_body);
            let linear = comp * w;
            let (lt, lr) = (linear.fixed_rows::<3>(0).norm(), linear.fixed_rows::<3>(3).norm());
            for r in 0..6 {
                // Rotations converted at 40 mm, so that no scale is zero.
                let scale = if r < 3 { lt + 0.04 * lr } else { lr + lt / 0.04 };
                assert!(
                    (nonlinear[r] - linear[r]).abs() < 0.01 * scale,
                    "{name} {:?} load axis {axis} dof {r}: nonlinear {:e} vs K^-1 W {:e}",
                    mu.mu,
                    nonlinear[r],
                    linear[r]
                );
            }
        }
    }
}

#[test]
fn frictionless_separation_load_equals_six_constraint_statics() {
    let (scene, c) = load("01_maxwell_vgroove_steel.toml");
    let mu = Load::nominal(&scene).with_mu(&[0.0; 6]);
    let s = seat(&c, &mu, &SolverOptions::default()).unwrap();
    // 1 N along x, 50 mm above the centre: it tips the coupling about y.
    let (f, p) = (Vector3::new(1.0, 0.0, 0.0), Vector3::new(0.0, 0.0, 0.05));
    let load = ExternalLoad { force: f, point: p, moment: Vector3::zeros() };
    // Statics by hand: f(lambda) = f_pre + lambda g, linear in the load; the
    // first contact to reach 0 separates at lambda* = min f_pre,i / (-g_i).
    let rows = maxwell_by_hand(45f64.to_radians());
    let f_pre = statics(&rows, Vector3::new(0.0, 0.0, -20.0), Vector3::zeros(), Vector3::zeros());
    let g = statics(&rows, f, p, Vector3::zeros());
    let (first, lambda) = (0..6)
        .filter(|&i| g[i] < 0.0)
        .map(|i| (i + 1, f_pre[i] / -g[i]))
        .min_by(|a, b| a.1.total_cmp(&b.1))
        .unwrap();
    let env = envelope(&c, &mu, &s, &load, &SolverOptions::default()).unwrap();
    let e = env.event.expect("the load separates a contact");
    assert_eq!(e.kind, LoadEventKind::Separation);
    // Contacts 1/2 and 3..6 pair up by symmetry only where g ties; compare
    // the factor, and the contact where the hand solution is unique.
    let factor = env.factor().unwrap();
    assert!((factor / lambda - 1.0).abs() < 0.01, "{factor} vs statics {lambda} (contact {first})");
    let ties =
        (0..6).filter(|&i| g[i] < 0.0 && (f_pre[i] / -g[i] / lambda - 1.0).abs() < 1e-9).count();
    if ties == 1 {
        assert_eq!(e.contact, first);
    }
    assert!((e.factor - e.previous) <= 1e-4 * e.factor);
    // Just below: no event; just above: the separation.
    let below = load_path(&c, &mu, &s, &load, 0.99 * factor, &SolverOptions::default()).unwrap();
    assert!(below.first_event.is_none(), "{:?}", below.first_event);
    let above = load_path(&c, &mu, &s, &load, 1.01 * factor, &SolverOptions::default()).unwrap();
    let ev = above.first_event.expect("separation just above");
    assert_eq!((ev.contact, ev.kind), (e.contact, e.kind));
}

#[test]
fn slip_envelope_is_bracketed_by_full_load_paths() {
    for (name, force, point) in [
        ("01_maxwell_vgroove_steel.toml", Vector3::new(1.0, 0.0, 0.0), Vector3::zeros()),
        ("06_kelvin_steel.toml", Vector3::new(0.3, 0.4, -1.0), Vector3::new(0.0, 0.0, 0.02)),
    ] {
        let (scene, c) = load(name);
        let mu = Load::nominal(&scene);
        let s = seat(&c, &mu, &SolverOptions::default()).unwrap();
        let load = ExternalLoad { force, point, moment: Vector3::zeros() };
        let env = envelope(&c, &mu, &s, &load, &SolverOptions::default()).unwrap();
        let e = env.event.expect("an event");
        let factor = env.factor().unwrap();
        assert!((e.factor - e.previous) <= 1e-4 * e.factor, "{name}: {e:?}");
        let below =
            load_path(&c, &mu, &s, &load, 0.99 * factor, &SolverOptions::default()).unwrap();
        assert!(below.first_event.is_none(), "{name}: {:?}", below.first_event);
        // Below the envelope every contact is closed and inside its cone.
        for r in &below.contacts {
            assert!(r.normal_force_n > 0.0);
            assert!(r.tangential_force_n < r.mu_static * r.normal_force_n);
        }
        let above =
            load_path(&c, &mu, &s, &load, 1.01 * factor, &SolverOptions::default()).unwrap();
        let ev = above.first_event.expect("the event just above");
        assert_eq!((ev.contact, ev.kind), (e.contact, e.kind), "{name}");
        if e.kind == LoadEventKind::Slip {
            // Just below the bracket the named contact is at its static limit.
            let at = load_path(&c, &mu, &s, &load, 0.999 * e.previous, &SolverOptions::default())
                .unwrap();
            let r = &at.contacts[e.contact - 1];
            let ratio = r.tangential_force_n / (r.mu_static * r.normal_force_n);
            assert!(ratio > 0.99 && ratio <= 1.0, "{name}: |F_t|/(mu_s F_n) = {ratio}");
        }
    }
}

#[test]
fn off_centre_preload_shifts_the_frictionless_forces_as_statics_says() {
    let mut scene = load("01_maxwell_vgroove_steel.toml").0;
    let offset = Vector3::new(0.006, -0.004, 0.0);
    scene.preload.forces[0].point = offset;
    let c = Coupling::new(&scene).unwrap();
    let s = seat(&c, &Load::nominal(&scene).with_mu(&[0.0; 6]), &SolverOptions::default()).unwrap();
    let hand = statics(
        &maxwell_by_hand(45f64.to_radians()),
        Vector3::new(0.0, 0.0, -20.0),
        offset,
        Vector3::zeros(),
    );
    let centred = statics(
        &maxwell_by_hand(45f64.to_radians()),
        Vector3::new(0.0, 0.0, -20.0),
        Vector3::zeros(),
        Vector3::zeros(),
    );
    for i in 0..6 {
        let f = s.contacts[i].normal_force_n;
        assert!((f / hand[i] - 1.0).abs() < 1e-5, "contact {}: {f} vs statics {}", i + 1, hand[i]);
        // The offset really changes the forces (by more than 10 %).
        assert!((hand[i] / centred[i] - 1.0).abs() > 0.1);
    }
}

#[test]
fn hertz_subsurface_shear_matches_johnson_and_a_brute_force_scan() {
    // Johnson (1985): tau_max = 0.31 p0 at z = 0.48 a for nu = 0.3.
    let (ratio, depth) = circular_max_shear(0.3);
    assert!((ratio - 0.31).abs() < 0.005, "{ratio}");
    assert!((depth - 0.48).abs() < 0.01, "{depth}");
    // Johnson (1985) eq. 3.45 on the axis, implemented here: with zeta = z/a,
    // sigma_r/p0 = -(1 + nu)(1 - zeta atan(1/zeta)) + 1/(2 (1 + zeta^2)),
    // sigma_z/p0 = -1/(1 + zeta^2), tau = |sigma_r - sigma_z| / 2.
    let johnson = |nu: f64, zeta: f64| {
        let sr = -(1.0 + nu) * (1.0 - zeta * (1.0 / zeta).atan()) + 0.5 / (1.0 + zeta * zeta);
        let sz = -1.0 / (1.0 + zeta * zeta);
        0.5 * (sr - sz).abs()
    };
    for nu in [0.14, 0.22, 0.27, 0.3, 0.45] {
        let scan = (1..=400_000)
            .map(|k| k as f64 * 1e-5)
            .map(|z| (johnson(nu, z), z))
            .max_by(|a, b| a.0.total_cmp(&b.0))
            .unwrap();
        for (r, z) in [circular_max_shear(nu), max_shear_ratio(nu, 1.0)] {
            assert!(
                (r - scan.0).abs() < 1e-9 && (z - scan.1).abs() < 1e-4,
                "nu {nu}: {r} at {z} vs {scan:?}"
            );
        }
        assert!((circular_axis_shear(nu, 0.7) - johnson(nu, 0.7)).abs() < 1e-12);
    }
    // In a seating: tau_max = ratio p0 and the steel pressure safety factor.
    let (scene, c) = load("01_maxwell_vgroove_steel.toml");
    let s = seat(&c, &Load::nominal(&scene).with_mu(&[0.5; 6]), &SolverOptions::default()).unwrap();
    for r in &s.contacts {
        assert!((r.max_shear_stress_pa / (ratio * r.max_pressure_pa) - 1.0).abs() < 1e-12);
        assert!(
            (r.pressure_safety_factor.unwrap() * r.max_pressure_pa / 4.2e9 - 1.0).abs() < 1e-12
        );
        assert_eq!(r.shear_safety_factor, None);
        assert_eq!(r.safety_factor, r.pressure_safety_factor);
    }
}

#[test]
fn scene_allowable_shear_stress_sets_the_shear_safety_factor_and_is_validated() {
    let base = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/01_maxwell_vgroove_steel.toml"),
    )
    .unwrap();
    let with = |tau: &str| {
        let text = base.replace("ball_material = \"steel\"", "ball_material = \"hard-steel\"")
            + &format!(
                "\n[[materials]]\nname = \"hard-steel\"\nyoungs_modulus = 210e9\npoisson_ratio = 0.3\nallowable_shear_stress = {tau}\n"
            );
        kinrepro::scene::Scene::parse(&text, "test.toml")
    };
    let scene = with("1.0e9").unwrap();
    let c = Coupling::new(&scene).unwrap();
    let s = seat(&c, &Load::nominal(&scene).with_mu(&[0.5; 6]), &SolverOptions::default()).unwrap();
    let (ratio, _) = circular_max_shear(0.3);
    for r in &s.contacts {
        let sf = 1.0e9 / (ratio * r.max_pressure_pa);
        assert!((r.shear_safety_factor.unwrap() / sf - 1.0).abs() < 1e-12);
        // Groove steel keeps its 4.2 GPa pressure allowable; the smaller factor wins.
        assert_eq!(r.safety_factor.unwrap(), sf.min(r.pressure_safety_factor.unwrap()));
    }
    for bad in ["-1.0", "0.0", "nan"] {
        let e = with(bad).unwrap_err().to_string();
        assert!(e.contains("allowable_shear_stress") && e.contains("test.toml"), "{e}");
    }
}
