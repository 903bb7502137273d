//! The quasi-static seating solver against independent values: the
//! closed-form frictionless settlement, symmetry, statics of the reported
//! forces, a history-free all-sliding solve, increment halving and mirror
//! symmetry.

use crate::common;
use crate::common::load;
use std::path::Path;

use kinrepro::assembly::geometry::contact;
use kinrepro::assembly::{BodyPose, Coupling};
use kinrepro::contact::SlipState;
use kinrepro::scene::Scene;
use kinrepro::solve::quasistatic;
use kinrepro::solve::{Load, PointPose, Seating, SolveError, SolverOptions};
use nalgebra::{Matrix6, UnitQuaternion, Vector3, Vector6};

/// A scene and its coupling.
type Model = (Scene, Coupling);

/// The coupling seated under the scene's preload with the static
/// coefficients `mu`.
fn seat((scene, c): &Model, mu: &[f64], opts: &SolverOptions) -> Result<Seating, SolveError> {
    quasistatic::seat(c, &Load::nominal(scene).with_mu(mu), opts)
}

const MAXWELL: [&str; 5] = [
    "01_maxwell_vgroove_steel.toml",
    "02_maxwell_pins_steel.toml",
    "03_maxwell_pins_sic.toml",
    "04_maxwell_balls_steel.toml",
    "05_maxwell_balls_sic.toml",
];

fn centre_pose((_, c): &Model, s: &Seating) -> PointPose {
    PointPose::between(&c.touching_pose, &s.pose(), &Vector3::zeros())
}

#[test]
fn frictionless_seating_settles_straight_down_by_the_hertz_closed_form() {
    let c = load("01_maxwell_vgroove_steel.toml");
    let s = seat(&c, &[0.0; 6], &SolverOptions::default()).unwrap();
    let p = centre_pose(&c, &s);
    assert!(p.x_m.abs() < 1e-14 && p.y_m.abs() < 1e-14, "{p:?}");
    assert!(
        p.phi_x_rad.abs() < 1e-12 && p.phi_y_rad.abs() < 1e-12 && p.phi_z_rad.abs() < 1e-12,
        "{p:?}"
    );
    // By hand: six 45-degree plane contacts share the 20 N preload, so each
    // carries F = 20 / (6 cos 45); Hertz sphere-plane (R = 5 mm, steel/steel,
    // E* = 210 GPa / (2 (1 - 0.3^2))) gives delta = (F / K)^(2/3) with
    // K = 4/3 E* sqrt(R); a plane's gap changes by z cos 45 when the ball
    // moves by z, so z = -delta / cos 45 exactly.
    let cos_a = 45f64.to_radians().cos();
    let f = 20.0 / (6.0 * cos_a);
    let e_star = 210e9 / (2.0 * (1.0 - 0.09));
    let k = 4.0 / 3.0 * e_star * 5e-3f64.sqrt();
    let z = -(f / k).powf(2.0 / 3.0) / cos_a;
    assert!((p.z_m / z - 1.0).abs() < 1e-6, "z {} vs {}", p.z_m, z);
    for r in &s.contacts {
        assert!((r.normal_force_n / f - 1.0).abs() < 1e-9);
        assert_eq!(r.tangential_force_n, 0.0);
    }
}

#[test]
fn equal_friction_keeps_every_maxwell_scene_centred() {
    for name in MAXWELL {
        let c = load(name);
        for mu in [0.0, 0.3, 0.6] {
            let s = seat(&c, &[mu; 6], &SolverOptions::default()).unwrap();
            let p = centre_pose(&c, &s);
            assert!(p.x_m.abs() < 1e-14 && p.y_m.abs() < 1e-14, "{name} mu {mu}: {p:?}");
            assert!(
                p.phi_x_rad.abs() < 1e-12 && p.phi_y_rad.abs() < 1e-12,
                "{name} mu {mu}: {p:?}"
            );
            assert!(p.z_m < 0.0);
        }
    }
}

#[test]
fn reported_forces_balance_the_preload() {
    for (name, mu) in [
        ("01_maxwell_vgroove_steel.toml", [0.45, 0.55, 0.5, 0.52, 0.48, 0.5]),
        ("04_maxwell_balls_steel.toml", [0.53, 0.47, 0.46, 0.54, 0.5, 0.51]),
        ("06_kelvin_steel.toml", [0.45, 0.55, 0.5, 0.52, 0.48, 0.5]),
    ] {
        let c = load(name);
        let s = seat(&c, &mu, &SolverOptions::default()).unwrap();
        let pre = &c.0.preload.forces[0];
        let fp = pre.direction * pre.force;
        let pp = s.pose().apply(&pre.point);
        let mut f = fp;
        let mut m = pp.cross(&fp);
        for r in &s.contacts {
            let n = Vector3::from(r.normal);
            let ft = Vector3::from(r.tangential_force);
            let total = n * r.normal_force_n + ft;
            f += total;
            m += Vector3::from(r.point_m).cross(&total);
            // Coulomb: |F_t| never exceeds mu_s F_n; sliding contacts sit at mu_d F_n.
            assert!(r.tangential_force_n <= r.mu_static * r.normal_force_n * (1.0 + 1e-12));
            if r.state == SlipState::Slip {
                assert!((r.tangential_force_n - r.mu_dynamic * r.normal_force_n).abs() < 1e-12);
            }
            assert!(ft.dot(&n).abs() < 1e-12 * r.normal_force_n);
        }
        assert!(f.norm() < 1e-9 * pre.force, "{name}: force residual {f:?}");
        assert!(m.norm() < 1e-9 * pre.force * 0.04, "{name}: moment residual {m:?}");
    }
}

/// All-sliding equilibrium solved directly at full load, with no history:
/// each tangential force is mu_d F_n against the direction of the total slip
/// of the ball's material point since the touching pose. Closed-form plane
/// geometry, Hertz force, Newton with a finite-difference Jacobian.
fn all_sliding_equilibrium((scene, c): &Model, mu_d: &[f64], start: &BodyPose) -> BodyPose {
    let residual = |pose: &BodyPose| -> Vector6<f64> {
        let pre = &scene.preload.forces[0];
        let fp = pre.direction * pre.force;
        let pp = pose.apply(&pre.point);
        let mut r = Vector6::zeros();
        let mut add = |f: Vector3<f64>, at: Vector3<f64>| {
            let m = at.cross(&f);
            r += Vector6::new(f.x, f.y, f.z, m.x, m.y, m.z);
        };
        add(fp, pp);
        for (i, k) in c.contacts.iter().enumerate() {
            let ball = &c.balls[k.ball];
            let g = contact(&k.surface, &pose.apply(&ball.centre), ball.radius);
            let fn_ = k.law.hertz.force(-g.gap);
            let body = pose.rotation.inverse() * (g.point - pose.translation);
            let slip = g.point - c.touching_pose.apply(&body);
            let st = slip - g.normal * g.normal.dot(&slip);
            add(g.normal * fn_ - st.normalize() * (mu_d[i] * fn_), g.point);
        }
        r
    };
    let mut pose = *start;
    for _ in 0..50 {
        let r = residual(&pose);
        if r.fixed_rows::<3>(0).norm() < 1e-13 && r.fixed_rows::<3>(3).norm() < 1e-15 {
            break;
        }
        let mut j = Matrix6::zeros();
        for k in 0..6 {
            let h = if k < 3 { 1e-12 } else { 1e-11 };
            let mut d = Vector6::zeros();
            d[k] = h;
            let plus = pose.moved(&d.fixed_rows::<3>(0).into(), &d.fixed_rows::<3>(3).into());
            let minus = pose.moved(&(-d.fixed_rows::<3>(0)), &(-d.fixed_rows::<3>(3)));
            j.set_column(k, &((residual(&plus) - residual(&minus)) / (2.0 * h)));
        }
        let dx = j.lu().solve(&(-r)).unwrap();
        pose = pose.moved(&dx.fixed_rows::<3>(0).into(), &dx.fixed_rows::<3>(3).into());
    }
    pose
}

#[test]
fn sliding_seating_equals_the_history_free_all_sliding_equilibrium() {
    let c = load("01_maxwell_vgroove_steel.toml");
    let mu = [0.45, 0.55, 0.5, 0.52, 0.48, 0.5];
    let s = seat(&c, &mu, &SolverOptions::default()).unwrap();
    let mu_d: Vec<f64> = mu.iter().map(|m| 0.8 * m).collect();
    for r in &s.contacts {
        assert_eq!(r.state, SlipState::Slip);
        assert!((r.tangential_force_n / (r.mu_dynamic * r.normal_force_n) - 1.0).abs() < 1e-12);
    }
    // Start the direct solve from a pure frictionless-like settlement, not from the answer.
    let start = BodyPose {
        rotation: UnitQuaternion::identity(),
        translation: Vector3::new(0.0, 0.0, -6e-7),
    };
    let direct = all_sliding_equilibrium(&c, &mu_d, &start);
    for p in [Vector3::zeros(), c.1.balls[0].centre, c.1.balls[1].centre, c.1.balls[2].centre] {
        let a = s.pose().apply(&p);
        let b = direct.apply(&p);
        assert!((a - b).norm() < 1e-12, "point {p:?}: {:e} m apart", (a - b).norm());
    }
}

#[test]
fn halving_the_load_increment_changes_the_pose_by_less_than_one_percent() {
    for (name, mu) in [
        ("01_maxwell_vgroove_steel.toml", [0.45, 0.55, 0.5, 0.52, 0.48, 0.5]),
        ("06_kelvin_steel.toml", [0.45, 0.55, 0.5, 0.52, 0.48, 0.5]),
    ] {
        let c = load(name);
        let nominal = [c.0.friction.mu_static; 6];
        let run =
            |increments: usize, m: &[f64]| seat(&c, m, &SolverOptions::fixed(increments)).unwrap();
        let (a, b) = (run(20, &mu), run(40, &mu));
        let (na, nb) = (run(20, &nominal), run(40, &nominal));
        for p in c.0.evaluation_points.iter().map(|e| e.position) {
            let ra = PointPose::between(&na.pose(), &a.pose(), &p).evaluated();
            let rb = PointPose::between(&nb.pose(), &b.pose(), &p).evaluated();
            let ta = PointPose::between(&c.1.touching_pose, &a.pose(), &p).evaluated();
            let tb = PointPose::between(&c.1.touching_pose, &b.pose(), &p).evaluated();
            let scale_t = (ra[0].hypot(ra[1])).max(1e-12);
            let scale_r = (ra[3].hypot(ra[4])).max(1e-12);
            for k in 0..5 {
                let scale = if k < 3 { scale_t } else { scale_r };
                assert!(
                    (ra[k] - rb[k]).abs() < 0.01 * scale,
                    "{name} dof {k}: {} vs {}",
                    ra[k],
                    rb[k]
                );
                assert!((ta[k] - tb[k]).abs() < 0.01 * ta[k].abs().max(scale), "{name} dof {k}");
            }
        }
    }
}

#[test]
fn mirrored_friction_mirrors_the_pose() {
    // Mirror x -> -x maps ball 1 to itself (contacts 1 <-> 2) and balls 2 <-> 3
    // (contacts 3 <-> 6, 4 <-> 5). A rotation vector is a pseudo-vector:
    // (phi_x, phi_y, phi_z) -> (phi_x, -phi_y, -phi_z).
    for name in [
        "01_maxwell_vgroove_steel.toml",
        "02_maxwell_pins_steel.toml",
        "04_maxwell_balls_steel.toml",
    ] {
        let c = load(name);
        let mu = [0.46, 0.53, 0.51, 0.47, 0.545, 0.455];
        let mirrored = [mu[1], mu[0], mu[5], mu[4], mu[3], mu[2]];
        let a = centre_pose(&c, &seat(&c, &mu, &SolverOptions::default()).unwrap());
        let b = centre_pose(&c, &seat(&c, &mirrored, &SolverOptions::default()).unwrap());
        let tol_t = 1e-14;
        let tol_r = 1e-12;
        assert!(a.x_m.abs() > 1e-10, "{name}: the test needs a lateral displacement");
        assert!((a.x_m + b.x_m).abs() < tol_t, "{name}: {} {}", a.x_m, b.x_m);
        assert!((a.y_m - b.y_m).abs() < tol_t, "{name}");
        assert!((a.z_m - b.z_m).abs() < tol_t, "{name}");
        assert!((a.phi_x_rad - b.phi_x_rad).abs() < tol_r, "{name}");
        assert!((a.phi_y_rad + b.phi_y_rad).abs() < tol_r, "{name}");
        assert!((a.phi_z_rad + b.phi_z_rad).abs() < tol_r, "{name}");
    }
}

#[test]
fn bad_mu_vectors_are_errors() {
    let c = load("01_maxwell_vgroove_steel.toml");
    let e = seat(&c, &[0.5; 5], &SolverOptions::default()).unwrap_err();
    assert!(e.to_string().contains("needs 6 values"));
    let e = seat(&c, &[0.5, 0.5, -0.1, 0.5, 0.5, 0.5], &SolverOptions::default()).unwrap_err();
    assert!(e.to_string().contains("contact 3 = -0.1"));
    let e = seat(&c, &[0.5, 0.5, f64::NAN, 0.5, 0.5, 0.5], &SolverOptions::default()).unwrap_err();
    assert!(e.to_string().contains("outside"));
}

#[test]
fn failures_are_clear_errors_not_poses() {
    // Newton limited to one iteration cannot meet 1e-10 of the preload.
    let c = load("01_maxwell_vgroove_steel.toml");
    let opts = SolverOptions { max_newton: 1, max_splits: 2, ..Default::default() };
    let e = seat(&c, &[0.5; 6], &opts).unwrap_err();
    assert!(e.to_string().contains("did not converge"), "{e}");
    // A preload pulling sideways-up cannot seat the coupling: refused when
    // the scene is read, at its direction's line.
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/01_maxwell_vgroove_steel.toml"),
    )
    .unwrap()
    .replace("force = 20.0", "force = 20.0\ndirection = [1.0, 0.0, 0.2]");
    let line = text.lines().position(|l| l.starts_with("direction = [1.0")).unwrap() + 1;
    let err = kinrepro::scene::Scene::parse(&text, "lift.toml").unwrap_err().to_string();
    assert!(err.starts_with(&format!("lift.toml:{line}: preload.direction: ")), "{err}");
    assert!(err.contains("does not press the moving half"), "{err}");
    // A sideways preload with some -z passes the resultant check and is
    // refused by the statics at assembly.
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/01_maxwell_vgroove_steel.toml"),
    )
    .unwrap()
    .replace("force = 20.0", "force = 20.0\ndirection = [1.0, 0.0, -0.2]");
    let s = kinrepro::scene::Scene::parse(&text, "side.toml").unwrap();
    let err = Coupling::new(&s).unwrap_err().to_string();
    assert!(err.contains("preload cannot seat") && err.contains("pulling force"), "{err}");
    // A preload far outside the ball circle tips the half off a groove.
    let text = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/01_maxwell_vgroove_steel.toml"),
    )
    .unwrap()
    .replace("force = 20.0", "force = 20.0\npoint = [0.0, 0.5, 0.0]");
    let s = kinrepro::scene::Scene::parse(&text, "tip.toml").unwrap();
    assert!(Coupling::new(&s).unwrap_err().to_string().contains("preload cannot seat"));
}

/// Scene 01 with the circle of ball centres scaled to `diameter` [m].
fn scene01_with_diameter(diameter: f64) -> Model {
    let text = std::fs::read_to_string(common::scene("01_maxwell_vgroove_steel.toml")).unwrap();
    let line =
        text.lines().find(|l| l.starts_with("diameter")).expect("scene 01 gives coupling.diameter");
    let text = text.replace(line, &format!("diameter = {diameter}"));
    let scene = kinrepro::scene::Scene::parse(&text, "scene01_scaled.toml").unwrap();
    let c = Coupling::new(&scene).unwrap();
    (scene, c)
}

/// A coupling of metres (contact approaches of a micrometre computed from
/// positions of a metre: force rounding above 1e-10 of the preload) seats,
/// and seats right: frictionless, straight down by the same Hertz closed
/// form as at 80 mm (the contact forces do not depend on the diameter);
/// sliding, at the history-free all-sliding equilibrium.
#[test]
fn a_coupling_of_metres_seats_to_the_closed_form_and_the_sliding_equilibrium() {
    for diameter in [1.0, 2.0, 4.0] {
        let c = scene01_with_diameter(diameter);
        let s = seat(&c, &[0.0; 6], &SolverOptions::default()).unwrap();
        let p = centre_pose(&c, &s);
        let cos_a = 45f64.to_radians().cos();
        let f = 20.0 / (6.0 * cos_a);
        let k = 4.0 / 3.0 * common::E_STAR_STEEL * 5e-3f64.sqrt();
        let z = -(f / k).powf(2.0 / 3.0) / cos_a;
        assert!((p.z_m / z - 1.0).abs() < 1e-6, "D {diameter}: z {} vs {z}", p.z_m);
        let mu = [0.45, 0.55, 0.5, 0.52, 0.48, 0.5];
        let s = seat(&c, &mu, &SolverOptions::default())
            .unwrap_or_else(|e| panic!("D {diameter} m: {e}"));
        let mu_d: Vec<f64> = mu.iter().map(|m| 0.8 * m).collect();
        let start = BodyPose {
            rotation: UnitQuaternion::identity(),
            translation: Vector3::new(0.0, 0.0, -6e-7),
        };
        let direct = all_sliding_equilibrium(&c, &mu_d, &start);
        // Both solves resolve a pose of size D to about eps D.
        let resolution = 1e-12 * diameter / 0.08;
        for b in &c.1.balls {
            let gap = (s.pose().apply(&b.centre) - direct.apply(&b.centre)).norm();
            assert!(gap < resolution, "D {diameter} m: {gap:e} m apart");
        }
    }
}
