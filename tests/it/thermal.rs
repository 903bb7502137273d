//! Thermal drift along a temperature cycle (docs/model.md, "Thermal
//! drift"), checked against values derived without the thermal path:
//! the homothety of one material at one temperature, the symmetry of a
//! Maxwell coupling, Kelvin's fixed point bounded by its trihedral
//! contacts' stiffness, and the agreement of the error-controlled path
//! with a finer fixed path. The elastic (sticking) solution and the first
//! slip from the seated forces are in `cli_thermal` (built from the
//! `stiffness` and `run` commands' output).

use kinrepro::assembly::Coupling;
use kinrepro::material::Material;
use kinrepro::scene::{Scene, Temperatures};
use kinrepro::solve::quasistatic::seat_and_cycle;
use kinrepro::solve::thermal::ThermalPath;
use kinrepro::solve::{Load, Seating, SolverOptions};
use nalgebra::Vector3;

use crate::common;

/// Points off every symmetry axis, in the moving half [m].
const POINTS: &str = "
[[evaluation_points]]
name = \"centre\"
position = [0.0, 0.0, 0.0]

[[evaluation_points]]
name = \"off axis\"
position = [0.05, -0.03, 0.02]

[[evaluation_points]]
name = \"below\"
position = [-0.02, 0.04, -0.01]
";

/// A bundled scene with a `[thermal]` table (and `extra` TOML after it).
pub fn thermal_scene(name: &str, table: &str, extra: &str) -> (Scene, Coupling) {
    let text = std::fs::read_to_string(common::scene(name)).unwrap();
    let text = format!("{text}\n{extra}\n[thermal]\n{table}\n");
    let scene = Scene::parse(&text, name).unwrap();
    let coupling = Coupling::new(&scene).unwrap();
    (scene, coupling)
}

/// The seating and the cycle of the scene's load with `mu` at every contact
/// (or its nominal), the default (error-controlled) solver.
fn cycle(scene: &Scene, c: &Coupling, mu: Option<&[f64]>) -> (Seating, ThermalPath) {
    let nominal = Load::nominal(scene);
    let load = mu.map_or(nominal.clone(), |mu| nominal.with_mu(mu));
    seat_and_cycle(c, &load, &SolverOptions::default()).unwrap()
}

fn alpha(name: &str) -> f64 {
    Material::builtin(name).unwrap().thermal_expansion.unwrap()
}

/// Displacement and rotation of body point `p` at cycle point `k`.
fn drift(
    c: &Coupling,
    path: &ThermalPath,
    k: usize,
    p: &Vector3<f64>,
) -> (Vector3<f64>, Vector3<f64>) {
    let q = path.drift(c.thermal.as_ref().unwrap(), k, p).components();
    (Vector3::new(q[0], q[1], q[2]), Vector3::new(q[3], q[4], q[5]))
}

/// One material and one temperature everywhere, the origins together:
/// everything grows by 1 + alpha dT about the origin, so every point of
/// the moving half moves by alpha dT p, up to two effects of the size of
/// the Hertz approach delta (not of the coupling): at constant force the
/// approach goes as R^(-1/3) (a change of delta alpha dT / 3 along each
/// normal, lifting the half by at most that over the smallest z-component
/// of a normal), and the seated half's body origin sits the seated
/// settlement h below the fixed body's, so the two bodies grow about
/// points h apart (alpha dT h). With 10 K of steel: about 0.1 nm.
#[test]
fn homothety_moves_every_point_with_the_bodies() {
    for name in
        ["01_maxwell_vgroove_steel.toml", "06_kelvin_steel.toml", "04_maxwell_balls_steel.toml"]
    {
        let table =
            "moving_body = \"steel\"\nfixed_body = \"steel\"\ncycle = [[10.0, 10.0], [0.0, 0.0]]";
        let (scene, c) = thermal_scene(name, table, POINTS);
        let (seating, path) = cycle(&scene, &c, None);
        let eps = alpha("steel") * 10.0;
        let approach = seating.contacts.iter().map(|k| k.approach_m).fold(0.0, f64::max);
        let nz = seating.contacts.iter().map(|k| k.normal[2].abs()).fold(1.0, f64::min);
        let h = (path.start.translation - c.touching_pose.translation).norm();
        let bound = eps * h + 2.0 * approach * eps / 3.0 / nz;
        assert!(bound < 0.3e-9, "{name}: bound {bound}");
        let length = c.length_scale();
        let mut largest = 0.0f64;
        for p in &scene.evaluation_points {
            let (d, phi) = drift(&c, &path, 0, &p.position);
            let expected = p.position * eps;
            assert!((d - expected).norm() <= bound, "{name}: {}: {d:?} vs {expected:?}", p.name);
            assert!(phi.norm() * length <= bound, "{name}: {}: rotation {phi:?}", p.name);
            largest = largest.max(d.norm());
            let (back, turn) = drift(&c, &path, 1, &p.position);
            assert!(back.norm() <= 1e-3 * largest.max(1e-9), "{name}: residual {back:?}");
            assert!(turn.norm() * length <= 1e-3 * largest.max(1e-9), "{name}: {turn:?}");
        }
        assert!(path.points.iter().all(|k| k.slipping.is_empty()), "{name}: a contact slid");
        assert_eq!(path.first_slip, None, "{name}");
    }
}

/// A Maxwell coupling has three planes of symmetry through z; with equal
/// friction at its six contacts the seating and the mismatch of an
/// aluminium carrier on an Invar base keep them, so the centre's x, y and
/// phi_z stay zero (to rounding) whatever slides. Unequal friction breaks
/// the symmetry: the centre then moves sideways and turns.
#[test]
fn maxwell_keeps_its_centre_with_equal_friction_only() {
    let table = "moving_body = \"aluminium-6061\"\nfixed_body = \"invar-36\"\ncycle = [[5.0, 0.0], [0.0, 0.0]]";
    let (scene, c) = thermal_scene("01_maxwell_vgroove_steel.toml", table, "");
    let centre = Vector3::zeros();
    let (_, equal) = cycle(&scene, &c, Some(&[0.5; 6]));
    for k in 0..2 {
        let (d, phi) = drift(&c, &equal, k, &centre);
        assert!(d.x.abs() < 1e-15 && d.y.abs() < 1e-15, "{k}: {d:?}");
        assert!(phi.z.abs() < 1e-13, "{k}: {phi:?}");
        assert!(d.z.abs() > 1e-8, "{k}: the centre moves along z: {d:?}");
    }
    assert_eq!(equal.points[0].slipping, vec![1, 2, 3, 4, 5, 6]);
    let (_, unequal) = cycle(&scene, &c, Some(&[0.55, 0.45, 0.5, 0.52, 0.47, 0.5]));
    let (d, phi) = drift(&c, &unequal, 1, &centre);
    let sideways = d.x.hypot(d.y).max(phi.z.abs() * c.length_scale());
    assert!(sideways > 1e-9, "unequal friction leaves the centre in place: {d:?} {phi:?}");
}

/// Kelvin: the trihedral seat holds ball 1 by three contacts, so the
/// moving half pivots about it while balls 2 and 3 slide in their groove
/// and on their flat. The point at ball 1 moves with the base's own
/// expansion there, alpha_f dT |c_1|, plus the deflection of its three
/// contacts under the friction the other balls pass on, at most
/// mu_s sum N (their friction limits) over the smallest stiffness of the
/// trihedral's contacts together (sum k_n n n^T + k_t (I - n n^T), Hertz
/// k_n = 2 a E* and Mindlin k_t = 8 a G* at the seated forces, steel ball
/// of 4 mm on steel balls of 3 mm). Far less than the mismatch
/// (alpha_m - alpha_f) dT |c| the other balls slide by.
#[test]
fn kelvin_pivots_about_its_trihedral_ball() {
    let table = "moving_body = \"aluminium-6061\"\nfixed_body = \"invar-36\"\ncycle = [[5.0, 0.0], [0.0, 0.0]]";
    let (scene, c) = thermal_scene("06_kelvin_steel.toml", table, "");
    let (seating, path) = cycle(&scene, &c, None);
    let ball1 = c.balls[0].centre;
    let (d, _) = drift(&c, &path, 0, &ball1);
    let base = ball1 * (alpha("invar-36") * 5.0);
    let mismatch = (alpha("aluminium-6061") - alpha("invar-36")) * 5.0 * c.balls[1].centre.norm();
    // The trihedral contacts' stiffness together, at their seated forces.
    let mut k = nalgebra::Matrix3::zeros();
    let (e, nu) = (210e9, 0.3);
    let e_star = e / (2.0 * (1.0 - nu * nu));
    let g_star = e / (2.0 * (1.0 + nu)) / (2.0 * (2.0 - nu));
    let radius = 1.0 / (1.0 / 4e-3 + 1.0 / 3e-3);
    for (i, _) in c.contacts.iter().enumerate().filter(|(_, k)| k.ball == 0) {
        let r = &seating.contacts[i];
        let n = Vector3::from(r.normal);
        let (a, _) = common::hertz_circle(r.normal_force_n, radius, e_star);
        let (kn, kt) = (2.0 * a * e_star, 8.0 * a * g_star);
        k += n * n.transpose() * kn + (nalgebra::Matrix3::identity() - n * n.transpose()) * kt;
    }
    let smallest = k.symmetric_eigenvalues().min();
    let others: f64 = (c.contacts.iter().zip(&seating.contacts))
        .filter(|(k, _)| k.ball != 0)
        .map(|(_, r)| r.mu_static * r.normal_force_n)
        .sum();
    let deflection = others / smallest;
    assert!((d - base).norm() <= deflection, "{d:?}: base {base:?}, bound {deflection}");
    assert!(d.norm() < 0.2 * mismatch, "{} vs mismatch {mismatch}", d.norm());
}

/// The error-controlled path (default tolerances) against the same path
/// on 1024 fixed increments per leg (and the seating on 1024): every cycle
/// point's drift agrees within its estimated error times the motion it
/// is relative to, and the estimate is within the tolerance per leg.
#[test]
fn the_controlled_path_agrees_with_a_fine_fixed_one() {
    let table = "moving_body = \"aluminium-6061\"\nfixed_body = \"invar-36\"\ncycle = [[2.0, 0.0], [0.0, 0.0]]";
    let (scene, c) = thermal_scene("02_maxwell_pins_steel.toml", table, POINTS);
    let load = Load::nominal(&scene).with_mu(&[0.55, 0.45, 0.5, 0.52, 0.47, 0.5]);
    let (s1, controlled) = seat_and_cycle(&c, &load, &SolverOptions::default()).unwrap();
    let (s2, fine) = seat_and_cycle(&c, &load, &SolverOptions::fixed(1024)).unwrap();
    let length = c.length_scale();
    let motion = (s1.pose().translation - c.touching_pose.translation).norm();
    for k in 0..2 {
        let error = controlled.points[k].path_error.unwrap();
        // Each leg within the tolerance; the error carries from leg to leg.
        assert!(error <= (k + 1) as f64 * load.thermal_tolerance, "{k}: {error}");
        for p in &scene.evaluation_points {
            let (d1, r1) = drift(&c, &controlled, k, &p.position);
            let (d2, r2) = drift(&c, &fine, k, &p.position);
            let gap = (d1 - d2).norm() + length * (r1 - r2).norm();
            let scale = motion.max(d2.norm());
            // The fine path's own error (first order in 1/1024) adds to the estimate.
            assert!(
                gap <= 4.0 * error * scale + 1e-11,
                "{k} {}: {gap} vs {error} x {scale}",
                p.name
            );
        }
    }
    assert!(s2.seated.path_error.is_none() && fine.points[0].path_error.is_none());
}

/// Both tangential laws and both friction readings follow a cycle on
/// every bundled scene's coupling, and a cycle point back at the seating
/// temperature with nothing sliding is where it started.
#[test]
fn every_law_and_reading_follows_a_cycle() {
    let table =
        "moving_body = \"ti-6al-4v\"\nfixed_body = \"granite\"\ncycle = [[0.5, 0.2], [0.0, 0.0]]";
    let laws = [
        "",
        "[friction]\nmu_static = 0.2\nspread = 0.02\ntangential_law = \"mindlin-deresiewicz\"\n",
        "[friction]\nmu_static = 0.2\nspread = 0.02\nlaw = \"decay\"\ndecay_coefficient = 1e4\n",
    ];
    for name in ["01_maxwell_vgroove_steel.toml", "06_kelvin_steel.toml"] {
        for law in laws {
            let text = std::fs::read_to_string(common::scene(name)).unwrap();
            let text = match law {
                "" => text,
                l => {
                    text.split("[friction]").next().unwrap().to_string()
                        + l
                        + "[study]\nsamples = 5\n"
                }
            };
            let text = format!("{text}\n[thermal]\n{table}\n");
            let scene = Scene::parse(&text, name).unwrap();
            let c = Coupling::new(&scene).unwrap();
            let (_, path) = cycle(&scene, &c, None);
            assert_eq!(path.points.len(), 2);
            for (k, p) in path.points.iter().enumerate() {
                let (d, phi) = drift(&c, &path, k, &Vector3::new(0.01, 0.02, 0.0));
                assert!(d.iter().chain(phi.iter()).all(|v| v.is_finite()), "{name} {law}: {d:?}");
                let bound = (k + 1) as f64 * scene.thermal.as_ref().unwrap().path_tolerance;
                assert!(p.path_error.unwrap() <= bound, "{name} {law}: {:?}", p.path_error);
            }
            assert_eq!(path.points[1].temperatures, Temperatures::ZERO);
        }
    }
}
