//! `kinrepro thermal` and the study of a `[thermal]` scene, against values
//! built without the thermal path: the sticking (elastic) solution and its
//! first slip from the `stiffness` command's per-contact k_n, k_t and the
//! `run` command's seated contacts; the study's re-seating statistics
//! against the same scene without `[thermal]`, and its thermal statistics
//! against its own records; bad input.

use nalgebra::{Matrix3, Matrix6, Vector3, Vector6};
use serde_json::Value;

use crate::common::{self, kinrepro};

const SCENE: &str = "maxwell_thermal_alu_invar.toml";
const MU: &str = "0.45,0.5,0.55,0.48,0.52,0.47";

fn json(args: &[&str]) -> Value {
    let (ok, out, err) = kinrepro(args);
    assert!(ok, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

fn vec3(v: &Value) -> Vector3<f64> {
    Vector3::new(v[0].as_f64().unwrap(), v[1].as_f64().unwrap(), v[2].as_f64().unwrap())
}

fn alpha(name: &str) -> f64 {
    kinrepro::material::Material::builtin(name).unwrap().thermal_expansion.unwrap()
}

/// The scene's contacts at the seated state, from `run --json` and
/// `stiffness --json` at the same mu: point, normal (into the moving
/// half), normal force, tangential force on the moving half, k_n, k_t.
struct Contact {
    p: Vector3<f64>,
    n: Vector3<f64>,
    normal_force: f64,
    tangential: Vector3<f64>,
    k: Matrix3<f64>,
    mu_s: f64,
}

fn contacts(scene: &str) -> Vec<Contact> {
    let run = json(&["run", scene, "--mu", MU, "--json"]);
    let stiff = json(&["stiffness", scene, "--mu", MU, "--json"]);
    let mu: Vec<f64> = MU.split(',').map(|m| m.parse().unwrap()).collect();
    let (rc, sc) = (run["contacts"].as_array().unwrap(), stiff["contacts"].as_array().unwrap());
    assert_eq!(rc.len(), sc.len());
    rc.iter()
        .zip(sc)
        .zip(mu)
        .map(|((r, s), mu_s)| {
            let n = vec3(&r["normal"]);
            let (kn, kt) = (
                s["normal_stiffness_n_per_m"].as_f64().unwrap(),
                s["tangential_stiffness_n_per_m"].as_f64().unwrap(),
            );
            let nn = n * n.transpose();
            Contact {
                p: vec3(&r["point_m"]),
                n,
                normal_force: r["normal_force_n"].as_f64().unwrap(),
                tangential: vec3(&r["tangential_force"]),
                k: nn * kn + (Matrix3::identity() - nn) * kt,
                mu_s,
            }
        })
        .collect()
}

/// J q = v + w x p for the twist q = (v, w) of the moving half.
fn jacobian(p: &Vector3<f64>) -> nalgebra::Matrix3x6<f64> {
    let mut j = nalgebra::Matrix3x6::zeros();
    j.fixed_view_mut::<3, 3>(0, 0).copy_from(&Matrix3::identity());
    j.fixed_view_mut::<3, 3>(0, 3).copy_from(&(-p.cross_matrix()));
    j
}

/// The sticking solution per kelvin of the moving body (origin at the
/// scene origin, the fixed body at its temperature): each contact's
/// thermal mismatch u_i = alpha_m c_i - alpha_ball r n_i (the ball centre
/// carried by the carrier, the ball's radius grown towards the flat), and
/// K q = -sum J_i^T K_i u_i with K = sum J_i^T K_i J_i. Returns q per
/// kelvin and each contact's force change on the moving half per kelvin,
/// -K_i (J_i q + u_i).
fn sticking(c: &[Contact]) -> (Vector6<f64>, Vec<Vector3<f64>>) {
    let (a_m, a_ball, r) = (alpha("aluminium-6061"), alpha("steel"), 0.005);
    let mismatch = |c: &Contact| a_m * (c.p + c.n * r) - c.n * (a_ball * r);
    let mut k = Matrix6::zeros();
    let mut rhs = Vector6::zeros();
    for ci in c {
        let j = jacobian(&ci.p);
        k += j.transpose() * ci.k * j;
        rhs -= j.transpose() * (ci.k * mismatch(ci));
    }
    let q = k.lu().solve(&rhs).unwrap();
    let df = c.iter().map(|ci| -(ci.k * (jacobian(&ci.p) * q + mismatch(ci)))).collect();
    (q, df)
}

/// Centre displacement and rotation at cycle point `k` of a thermal JSON.
fn centre(v: &Value, k: usize) -> Vector6<f64> {
    let p = &v["cycle"][k]["points"][0];
    assert_eq!(p["name"], "centre");
    let (d, r) = (vec3(&p["displacement_m"]), vec3(&p["rotation_rad"]));
    Vector6::new(d.x, d.y, d.z, r.x, r.y, r.z)
}

/// |(v, w)| with the rotation scaled by the coupling radius.
fn size(q: &Vector6<f64>) -> f64 {
    let l = 0.04;
    q.fixed_rows::<3>(0).norm().hypot(l * q.fixed_rows::<3>(3).norm())
}

#[test]
fn a_small_mismatch_sticks_linearly_reversibly_and_as_the_elastic_solution() {
    let scene = common::scene(SCENE);
    let scene = scene.to_str().unwrap();
    let c = contacts(scene);
    let (q, _) = sticking(&c);
    let at = |dt: f64| {
        let cycle = format!("{dt},0;0,0");
        json(&["thermal", scene, "--mu", MU, "--cycle", &cycle, "--json"])
    };
    let (small, double) = (at(0.01), at(0.02));
    for v in [&small, &double] {
        assert!(
            v["first_slip_delta_t_k"].is_null(),
            "a contact slid: {}",
            v["first_slip_delta_t_k"]
        );
        assert_eq!(v["cycle"][0]["slipping_contacts"].as_array().unwrap().len(), 0);
    }
    let (d1, d2) = (centre(&small, 0), centre(&double, 0));
    // Linear in dT and back to the seated pose when the temperature is.
    assert!(size(&(d2 - 2.0 * d1)) <= 1e-3 * size(&d2), "{d1:?} {d2:?}");
    assert!(size(&centre(&double, 1)) <= 1e-3 * size(&d2), "{:?}", centre(&double, 1));
    // The elastic solution from the seated contact stiffnesses (measured:
    // 2.2e-4 apart; the rest is the change of the stiffnesses with the
    // normal forces and the grown radii, which the linear solution leaves
    // out).
    let expected = q * 0.02;
    assert!(
        size(&(d2 - expected)) <= 2e-3 * size(&expected),
        "{:?} vs {:?}",
        d2.transpose(),
        expected.transpose()
    );
    // The tool tip moves with the half and its own expansion.
    let tip = &double["cycle"][0]["points"][1];
    let e = Vector3::new(0.010, 0.0, -0.060);
    let rigid = expected.fixed_rows::<3>(0) + expected.fixed_rows::<3>(3).cross(&e);
    let own = e * (alpha("aluminium-6061") * 0.02);
    let got = vec3(&tip["displacement_m"]);
    assert!((got - rigid - own).norm() <= 2e-3 * rigid.norm(), "{got:?} vs {:?}", rigid + own);
}

#[test]
fn the_first_slip_is_where_the_sticking_forces_reach_mu_n() {
    let scene = common::scene(SCENE);
    let scene = scene.to_str().unwrap();
    let c = contacts(scene);
    let (_, df) = sticking(&c);
    // Per contact: |F_t0 + dT dF_t| = mu_s (N_0 + dT dN), smallest dT > 0.
    let first = c
        .iter()
        .zip(&df)
        .filter_map(|(ci, d)| {
            let (dn, dft) = (ci.n.dot(d), d - ci.n * ci.n.dot(d));
            let (f0, n0, m2) = (ci.tangential, ci.normal_force, ci.mu_s * ci.mu_s);
            let a = dft.norm_squared() - m2 * dn * dn;
            let b = f0.dot(&dft) - m2 * n0 * dn;
            let cc = f0.norm_squared() - m2 * n0 * n0;
            let disc = b * b - a * cc;
            (disc >= 0.0).then(|| (-b + disc.sqrt()) / a).filter(|t| *t > 0.0)
        })
        .fold(f64::INFINITY, f64::min);
    let v = json(&["thermal", scene, "--mu", MU, "--cycle", "1,0;0,0", "--json"]);
    let got = v["first_slip_delta_t_k"].as_f64().unwrap();
    // Measured 1.5e-3 apart (the linear solution's stiffnesses are the
    // seated ones).
    assert!((got / first - 1.0).abs() < 5e-3, "first slip {got} K vs {first} K");
    // It slides on the way, and a residual remains at the seating temperature.
    assert!(!v["cycle"][0]["slipping_contacts"].as_array().unwrap().is_empty());
    let (drift, residual) = (centre(&v, 0), centre(&v, 1));
    assert!(size(&residual) > 1e-2 * size(&drift), "{residual:?} vs {drift:?}");
}

#[test]
fn a_second_identical_cycle_adds_less_than_the_first() {
    let scene = common::scene(SCENE);
    let v = json(&[
        "thermal",
        scene.to_str().unwrap(),
        "--mu",
        MU,
        "--cycle",
        "5,0;0,0;5,0;0,0;5,0;0,0",
        "--json",
    ]);
    let r: Vec<Vector6<f64>> = [1, 3, 5].iter().map(|&k| centre(&v, k)).collect();
    let (first, second, third) = (size(&r[0]), size(&(r[1] - r[0])), size(&(r[2] - r[1])));
    // Shakedown: the first cycle settles the balls (measured: the second
    // adds 2e-4 nm to a 150 nm residual, the third nothing).
    assert!(second < 1e-2 * first && third < 1e-2 * first, "{first} {second} {third}");
}

#[test]
fn bad_thermal_input_is_a_clear_error() {
    let plain = common::scene("01_maxwell_vgroove_steel.toml");
    let (ok, _, err) = kinrepro(&["thermal", plain.to_str().unwrap()]);
    assert!(
        !ok && err.contains("[thermal]") && err.contains("01_maxwell_vgroove_steel.toml"),
        "{err}"
    );
    let scene = common::scene(SCENE);
    let scene = scene.to_str().unwrap();
    for (cycle, says) in
        [("5,0;x", "point 2"), ("500,0", "100 K"), ("", "point 1"), ("5", "point 1")]
    {
        let (ok, _, err) = kinrepro(&["thermal", scene, "--cycle", cycle]);
        assert!(!ok && err.contains("--cycle") && err.contains(says), "{cycle:?}: {err}");
    }
    let (ok, _, err) = kinrepro(&["study", scene, "--solver", "dynamic"]);
    assert!(!ok && err.contains("[thermal]") && err.contains("quasi-static"), "{err}");
}

/// The re-seating statistics of a `[thermal]` study are the scene's
/// without `[thermal]` (the same seatings), and each thermal statistic is
/// that of the study's own records of the drift.
#[test]
fn a_thermal_study_keeps_the_reseating_scatter_and_adds_the_drift() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(common::scene(SCENE)).unwrap();
    let start = text.find("[thermal]").unwrap();
    let end = start + text[start..].find("[[evaluation_points]]").unwrap();
    let plain = dir.path().join("plain.toml");
    std::fs::write(&plain, format!("{}{}", &text[..start], &text[end..])).unwrap();
    let scene = common::scene(SCENE);
    let study = |s: &str| {
        json(&["study", s, "--samples", "40", "--sampler", "mc", "--seed", "7", "--format", "json"])
    };
    let (with, without) = (study(scene.to_str().unwrap()), study(plain.to_str().unwrap()));
    let (w, p) = (&with["variants"][0], &without["variants"][0]);
    assert!(p.get("thermal").is_none() && w["thermal"]["cycle_delta_t_k"][0][0] == 5.0);
    for (a, b) in w["points"].as_array().unwrap().iter().zip(p["points"].as_array().unwrap()) {
        for key in ["sigma", "mean", "min", "max"] {
            for (k, x) in a[key].as_object().unwrap() {
                let (x, y) = (x.as_f64().unwrap(), b[key][k].as_f64().unwrap());
                assert!((x - y).abs() <= 1e-12 * y.abs().max(1e-300), "{key}.{k}: {x} vs {y}");
            }
        }
    }
    // Each thermal statistic from the records: outputs thermal/<k>/<point>/<dof>.
    let names: Vec<&str> =
        w["output_names"].as_array().unwrap().iter().map(|n| n.as_str().unwrap()).collect();
    let records = w["records"].as_array().unwrap();
    let column = |name: &str| -> Vec<f64> {
        let j = names.iter().position(|n| *n == name).unwrap_or_else(|| panic!("{name}"));
        records.iter().map(|r| r["outputs_si"][j].as_f64().unwrap()).collect()
    };
    for point in w["points"].as_array().unwrap() {
        let stats = point["thermal"].as_array().unwrap();
        assert_eq!(stats.len(), 2);
        for (k, s) in stats.iter().enumerate() {
            assert!(
                s["sigma_ci90_low"]["x_nm"].as_f64().unwrap()
                    < s["sigma"]["x_nm"].as_f64().unwrap()
            );
            for (dof, key, unit) in [("x_m", "x_nm", 1e9), ("phi_z_rad", "phi_z_nrad", 1e9)] {
                let name = format!("thermal/{}/{}/{dof}", k + 1, point["name"].as_str().unwrap());
                let x = column(&name);
                let n = x.len() as f64;
                let mean = x.iter().sum::<f64>() / n;
                let sd = (x.iter().map(|v| (v - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt();
                let (m, sigma) =
                    (s["mean"][key].as_f64().unwrap(), s["sigma"][key].as_f64().unwrap());
                assert!(
                    (m - mean * unit).abs() <= 1e-9 * (sd * unit),
                    "{name}: mean {m} vs {}",
                    mean * unit
                );
                assert!(
                    (sigma / (sd * unit) - 1.0).abs() < 1e-9,
                    "{name}: sigma {sigma} vs {}",
                    sd * unit
                );
            }
        }
    }
}

/// Every bundled scene with a `[thermal]` table added (a titanium carrier
/// on a granite base, warmed, the base warmed less, both back): `thermal
/// --json` follows the cycle with the documented keys, and the last point
/// back at the seating temperature holds the residual.
#[test]
fn every_bundled_scene_follows_a_cycle() {
    let dir = tempfile::tempdir().unwrap();
    let table = "\n[thermal]\nmoving_body = \"ti-6al-4v\"\nfixed_body = \"granite\"\ncycle = [[2.0, 0.5], [0.0, 0.0]]\n";
    for entry in std::fs::read_dir(common::scene("")).unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        let name = path.file_name().unwrap().to_string_lossy().into_owned();
        let file = dir.path().join(&name);
        let text = if text.contains("[thermal]") { text } else { text + table };
        std::fs::write(&file, text).unwrap();
        let v = json(&["thermal", file.to_str().unwrap(), "--json"]);
        let cycle = v["cycle"].as_array().unwrap();
        assert_eq!(cycle.len(), 2, "{name}");
        for c in cycle {
            assert!(c["delta_t_k"].is_array() && c["path_error"].is_f64(), "{name}: {c}");
            assert!(c["slipping_contacts"].is_array(), "{name}");
            for p in c["points"].as_array().unwrap() {
                assert!(p["name"].is_string(), "{name}");
                for key in ["displacement_m", "rotation_rad"] {
                    let x = p[key].as_array().unwrap();
                    assert!(
                        x.len() == 3 && x.iter().all(|v| v.as_f64().unwrap().is_finite()),
                        "{name}"
                    );
                }
            }
        }
        assert_eq!(cycle[1]["delta_t_k"], serde_json::json!([0.0, 0.0]), "{name}");
        assert!(
            v["first_slip_delta_t_k"].is_null() || v["first_slip_delta_t_k"].is_f64(),
            "{name}"
        );
    }
}

/// A sweep over the carrier's material: each design point's drift
/// statistics are those of a study of the scene with that material
/// written in (the same seatings), and the CSV names them
/// `thermal/<k>/<point>`; a scene without `[thermal]` has no such field.
#[test]
fn a_sweep_varies_the_bodies_and_reports_the_drift() {
    let scene = common::scene(SCENE);
    let scene = scene.to_str().unwrap();
    let common_args = ["--samples", "12", "--sampler", "mc", "--seed", "5"];
    let mut args = vec!["sweep", scene, "--set", "thermal.moving_body=invar-36,ti-6al-4v"];
    args.extend(common_args);
    let sweep = json(&[args.as_slice(), &["--format", "json"]].concat());
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(scene).unwrap();
    for (d, body) in sweep["designs"].as_array().unwrap().iter().zip(["invar-36", "ti-6al-4v"]) {
        let file = dir.path().join(format!("{body}.toml"));
        let moved =
            text.replace("moving_body = \"aluminium-6061\"", &format!("moving_body = \"{body}\""));
        std::fs::write(&file, moved).unwrap();
        let mut args = vec!["study", file.to_str().unwrap(), "--format", "json"];
        args.extend(common_args);
        let study = json(&args);
        let (a, b) = (&d["points"][0]["thermal"], &study["variants"][0]["points"][0]["thermal"]);
        assert_eq!(a.as_array().unwrap().len(), 2, "{body}");
        for k in 0..2 {
            for key in ["mean", "sigma"] {
                for (dof, x) in a[k][key].as_object().unwrap() {
                    let (x, y) = (x.as_f64().unwrap(), b[k][key][dof].as_f64().unwrap());
                    assert!((x - y).abs() <= 1e-12 * y.abs(), "{body} {k} {key}.{dof}: {x} vs {y}");
                }
            }
        }
    }
    let (z0, z1) = (
        sweep["designs"][0]["points"][0]["thermal"][0]["mean"]["z_nm"].as_f64().unwrap(),
        sweep["designs"][1]["points"][0]["thermal"][0]["mean"]["z_nm"].as_f64().unwrap(),
    );
    assert!((z0 - z1).abs() > 1.0, "the carrier's material moves the drift: {z0} vs {z1}");
    let (ok, csv, err) = kinrepro(&[args.as_slice(), &["--format", "csv"]].concat());
    assert!(ok, "{err}");
    assert!(csv.lines().any(|l| l.contains(",thermal/2/centre,z,m,")), "{csv}");
    let plain = common::scene("01_maxwell_vgroove_steel.toml");
    let (ok, _, err) =
        kinrepro(&["sweep", plain.to_str().unwrap(), "--set", "thermal.moving_body=invar-36"]);
    assert!(!ok && err.contains("thermal.moving_body") && err.contains("thermal"), "{err}");
}
