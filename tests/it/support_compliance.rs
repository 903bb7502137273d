//! Series support compliance (`support_compliance`, m/N): the normal law
//! delta = (F/K)^(2/3) + c F against its closed form both ways, the scene
//! keys (high-level, explicit, the expand round trip, errors), and the
//! scatter of scene 01 against the factor the linearised compliance predicts.

use crate::common;
use crate::common::load;

use kinrepro::assembly::Coupling;
use kinrepro::contact::{HertzLaw, SeriesNormal};
use kinrepro::scene::Scene;
use kinrepro::solve::quasistatic::seat;
use kinrepro::solve::{Load, PointPose, SolverOptions};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

/// Steel ball R = 5 mm on a steel plane: K = 4/3 E* sqrt(R) (Johnson eq. 4.22).
fn steel_k() -> f64 {
    let e_star = common::E_STAR_STEEL;
    4.0 / 3.0 * e_star * 5e-3_f64.sqrt()
}

#[test]
fn series_law_inverts_the_closed_form_both_ways() {
    let k = steel_k();
    let hertz = HertzLaw::circular(5e-3, 210e9 / (2.0 * (1.0 - 0.09)));
    for c in [1e-10, 3.6e-8, 1e-6] {
        let law = SeriesNormal::new(hertz, c);
        for f in [1e-6, 0.01, 3.37, 20.0, 1e4] {
            // delta from F by the closed form, then F back from delta by the law.
            let delta = (f / k).powf(2.0 / 3.0) + c * f;
            let (f_back, kn) = law.force_and_stiffness(delta);
            assert!((f_back / f - 1.0).abs() < 1e-12, "c {c} F {f}: {f_back}");
            // Springs in series: 1/k = 1/k_H + c, k_H = 3/2 K^(2/3) F^(1/3).
            let k_hertz = 1.5 * k.powf(2.0 / 3.0) * f.cbrt();
            let expect = 1.0 / (1.0 / k_hertz + c);
            assert!((kn / expect - 1.0).abs() < 1e-10, "c {c} F {f}: {kn} {expect}");
            // The law's own split adds up to the closed form.
            assert!((law.approach(f) / delta - 1.0).abs() < 1e-12);
            assert!((law.support_approach(f) / (c * f) - 1.0).abs() < 1e-15);
        }
        // Support-dominated limit: F -> delta / c.
        let delta = 1e-3;
        let (f, _) = law.force_and_stiffness(delta);
        assert!(((k.powf(-2.0 / 3.0) * f.powf(2.0 / 3.0) + c * f) / delta - 1.0).abs() < 1e-12);
    }
    let zero = SeriesNormal::new(hertz, 0.0);
    for d in [-1e-9, 0.0, 1e-9, 3e-7] {
        assert_eq!(zero.force_and_stiffness(d), (hertz.force(d), hertz.stiffness(d)));
    }
}

fn high_level(extra: &str) -> String {
    format!(
        "[coupling]\narrangement = \"maxwell\"\ndiameter = 0.08\nball_diameter = 0.01\n\
         ball_material = \"steel\"\ngroove = \"cylinders\"\ngroove_element_diameter = 0.004\n\
         groove_material = \"steel\"\n{extra}\n[preload]\nforce = 20.0\n[friction]\nmu_static = 0.5\n"
    )
}

#[test]
fn support_compliance_goes_to_every_contact_and_survives_expand() {
    let src = high_level("support_compliance = 2.5e-8");
    let scene = Scene::parse(&src, "h.toml").unwrap();
    assert!(scene.surfaces.iter().all(|s| s.support_compliance == 2.5e-8));
    let explicit = Scene::expand_text(&src, "h.toml").unwrap();
    assert_eq!(explicit.matches("support_compliance = ").count(), 6);
    let back = Scene::parse(&explicit, "e.toml").unwrap();
    let key = |s: &Scene| -> Vec<_> {
        s.surfaces.iter().map(|x| (x.geometry, x.ball, x.support_compliance)).collect()
    };
    common::assert_close_debug(&key(&back), &key(&scene), "expanded surfaces");
    // Per contact in the explicit form: change one surface only.
    let mut text = explicit.clone();
    let at = text.rfind("support_compliance = ").unwrap();
    let end = at + text[at..].find('\n').unwrap();
    text.replace_range(at..end, "support_compliance = 1e-7");
    let one = Scene::parse(&text, "e.toml").unwrap();
    let c: Vec<f64> = one.surfaces.iter().map(|s| s.support_compliance).collect();
    assert_eq!(c, [2.5e-8, 2.5e-8, 2.5e-8, 2.5e-8, 2.5e-8, 1e-7]);
    // Without the key: none.
    let none = Scene::parse(&high_level(""), "h.toml").unwrap();
    assert!(none.surfaces.iter().all(|s| s.support_compliance == 0.0));
    assert!(!Scene::expand_text(&high_level(""), "h.toml").unwrap().contains("support"));
}

#[test]
fn bad_support_compliance_is_an_error_naming_line_and_field() {
    let e = Scene::parse(&high_level("support_compliance = -1e-8"), "h.toml").unwrap_err();
    assert_eq!(e.line, Some(9), "{e}");
    assert_eq!(e.field, "coupling.support_compliance", "{e}");
    assert!(e.reason.contains(">= 0"), "{e}");
    let explicit = Scene::expand_text(&high_level("support_compliance = 1e-8"), "h.toml").unwrap();
    let at = explicit.find("support_compliance = ").unwrap();
    let end = at + explicit[at..].find('\n').unwrap();
    let mut bad = explicit.clone();
    bad.replace_range(at..end, "support_compliance = -inf");
    let e = Scene::parse(&bad, "e.toml").unwrap_err();
    assert_eq!(e.field, "surfaces[1].support_compliance", "{e}");
    assert!(e.to_string().starts_with("e.toml:"), "{e}");
}

/// sigma (n-1) of [x, y, z, phi_x, phi_y] at the centre over MC samples,
/// relative to the nominal seating.
fn sigmas((scene, c): &(Scene, Coupling), samples: &[Vec<f64>]) -> [f64; 5] {
    let opts = SolverOptions::default();
    let load = Load::nominal(scene);
    let nominal = seat(c, &load, &opts).unwrap();
    let poses: Vec<[f64; 5]> = samples
        .iter()
        .map(|mu| {
            let s = seat(c, &load.with_mu(mu), &opts).unwrap();
            PointPose::between(&nominal.pose(), &s.pose(), &nalgebra::Vector3::zeros()).evaluated()
        })
        .collect();
    let n = poses.len() as f64;
    std::array::from_fn(|k| {
        let mean = poses.iter().map(|p| p[k]).sum::<f64>() / n;
        (poses.iter().map(|p| (p[k] - mean).powi(2)).sum::<f64>() / (n - 1.0)).sqrt()
    })
}

#[test]
fn scene_01_scatter_rises_by_the_linearised_compliance_factor() {
    // Every groove contact slides (docs/model.md, "What to expect in a groove"). The pose follows from the
    // six gaps, W x = -delta(F), so a change of friction moves it by
    // dx = -W^-1 C dF, C = diag(1/k_n,i) with the total linearised normal
    // compliance 1/k_n = 1/k_H + c (springs in series). All six contacts of
    // scene 01 carry the same seated load F (symmetry).
    //
    // z, phi_x, phi_y (the balls move normal to the grooves' axes): the
    // sliding friction mu_d F_n keeps its direction (down the flank), so
    // statics fixes dF independently of any compliance, and every sigma
    // rises by (1/k_H + c) k_H = 1 + c k_H = 2 for c = d delta_H/dF = 1/k_H.
    //
    // x, y (a lateral translation moves balls 2 and 3 partly along their
    // grooves): the friction direction of a sliding flank turns by d_r /
    // delta towards an along-groove displacement d_r (45-degree flank: slip
    // down the flank = approach delta, the secant delta_H(F) + c F), which
    // gives two flanks an along-groove stiffness k_r = 2 mu_d F / delta;
    // across the groove a ball has k_s = 2 k_n sin45 (sin45 - mu_d cos45) =
    // (1 - mu_d) k_n (normal forces change +-, friction up the flank). The
    // lateral stiffness of the three balls, 3/2 (k_s + k_r) (sum of cos^2 at
    // 120 degrees), takes the same friction imbalance, so sigma_x, sigma_y
    // rise by (k_s + k_r)|_(c=0) / (k_s + k_r)|_c.
    let base = load("01_maxwell_vgroove_steel.toml");
    let nominal = seat(&base.1, &Load::nominal(&base.0), &SolverOptions::default()).unwrap();
    let f = nominal.contacts[0].normal_force_n;
    for r in &nominal.contacts {
        assert!((r.normal_force_n / f - 1.0).abs() < 1e-9);
    }
    let k = steel_k();
    let k_hertz = 1.5 * k.powf(2.0 / 3.0) * f.cbrt();
    let delta_h = (f / k).powf(2.0 / 3.0);
    let c = 1.0 / k_hertz;
    let mu_d = base.0.friction.dynamic_ratio * base.0.friction.mu_static;
    let lateral = |c: f64| (1.0 - mu_d) / (1.0 / k_hertz + c) + 2.0 * mu_d * f / (delta_h + c * f);
    let normal_factor = 1.0 + c * k_hertz;
    let lateral_factor = lateral(0.0) / lateral(c);
    let predicted = [lateral_factor, lateral_factor, normal_factor, normal_factor, normal_factor];
    // The same scene file with `[coupling] support_compliance = c`.
    let text = std::fs::read_to_string(common::scene("01_maxwell_vgroove_steel.toml")).unwrap();
    let text = text.replacen(
        "groove_material = \"steel\"",
        &format!("groove_material = \"steel\"\nsupport_compliance = {c:e}"),
        1,
    );
    let soft = kinrepro::error::parse_scene(&text, "01-soft.toml").unwrap();
    assert!(soft.1.contacts.iter().all(|k| k.normal.compliance == c));
    let fr = &base.0.friction;
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let samples: Vec<Vec<f64>> = (0..200)
        .map(|_| {
            (0..6).map(|_| fr.mu_static + fr.spread * (2.0 * rng.random::<f64>() - 1.0)).collect()
        })
        .collect();
    let (s0, s1) = (sigmas(&base, &samples), sigmas(&soft, &samples));
    for k in 0..5 {
        let ratio = s1[k] / s0[k];
        eprintln!("DOF {k}: sigma ratio {ratio:.5}, predicted {:.5}", predicted[k]);
        assert!((ratio / predicted[k] - 1.0).abs() < 0.03, "DOF {k}: {ratio}");
    }
}

#[test]
fn run_reports_the_approach_split_into_hertz_and_support() {
    let c = 2.0e-8;
    let text = std::fs::read_to_string(common::scene("01_maxwell_vgroove_steel.toml")).unwrap();
    let text = text.replacen(
        "groove_material = \"steel\"",
        &format!("groove_material = \"steel\"\nsupport_compliance = {c:e}"),
        1,
    );
    let tmp = tempfile::tempdir().unwrap();
    let path = tmp.path().join("support.toml");
    std::fs::write(&path, text).unwrap();
    let p = path.to_str().unwrap();
    let (ok, out, err) = common::kinrepro(&["run", p, "--json"]);
    let (ok_t, table, _) = common::kinrepro(&["run", p]);
    assert!(ok && ok_t, "{err}");
    assert!(table.contains("approach = Hertz + support"), "{table}");
    let json: serde_json::Value = serde_json::from_str(&out).unwrap();
    let k = steel_k();
    for contact in json["contacts"].as_array().unwrap() {
        let get = |key: &str| contact[key].as_f64().unwrap();
        let f = get("normal_force_n");
        // Independent closed forms: Hertz (F/K)^(2/3), support c F, and their sum.
        assert!((get("hertz_approach_m") / (f / k).powf(2.0 / 3.0) - 1.0).abs() < 1e-12);
        assert!((get("support_approach_m") / (c * f) - 1.0).abs() < 1e-12);
        assert_eq!(get("support_compliance_m_per_n"), c);
        let total = get("approach_m");
        assert!(((f / k).powf(2.0 / 3.0) + c * f - total).abs() < 1e-9 * total);
    }
}

/// Scene 01 with `support_compliance = VALUE` (TOML) in `[coupling]`.
fn scene01_with_support(value: &str) -> String {
    std::fs::read_to_string(common::scene("01_maxwell_vgroove_steel.toml")).unwrap().replace(
        "groove_material = \"steel\"",
        &format!("groove_material = \"steel\"\nsupport_compliance = {value}"),
    )
}

fn json_of(args: &[&str]) -> serde_json::Value {
    let (ok, out, err) = common::kinrepro(args);
    assert!(ok, "{args:?}: {err}");
    serde_json::from_str(&out).unwrap()
}

fn write_scene(name: &str, text: &str) -> String {
    let path = std::env::temp_dir().join(format!("kinrepro_support_{name}.toml"));
    std::fs::write(&path, text).unwrap();
    path.display().to_string()
}

/// `{ normal = c, tangential = 0 }` is the scalar c, exactly: the same
/// seatings, the same study.
#[test]
fn a_zero_tangential_compliance_is_todays_scalar() {
    let study = |text: &str, name: &str| {
        let file = write_scene(name, text);
        json_of(&["study", &file, "--samples", "30", "--sampler", "mc", "--format", "json"])["variants"][0]
            ["points"]
            .clone()
    };
    let (a, b) = (
        study(&scene01_with_support("3.6e-8"), "scalar"),
        study(&scene01_with_support("{ normal = 3.6e-8, tangential = 0.0 }"), "table"),
    );
    assert_eq!(a, b);
}

/// A tangential support compliance c_t in series with Mindlin: each
/// contact's k_t (`stiffness --json`) is 1 / (1 / (8 G* a) + c_t) with a
/// from Hertz's closed form at its normal force, and the scatter of scene
/// 01 falls as c_t lets the contacts take the seating's tangential motion
/// elastically instead of sliding (measured: 5.1 nm at 0, 0.47 nm at
/// 3e-7 m/N, 0.018 nm at 1e-6 m/N).
#[test]
fn a_tangential_compliance_is_in_series_with_mindlin() {
    let c_t = 3e-7;
    let file =
        write_scene("tangential", &scene01_with_support(&format!("{{ tangential = {c_t:e} }}")));
    let k = json_of(&["stiffness", &file, "--json"]);
    let (e, nu) = (210e9, 0.3);
    let e_star = e / (2.0 * (1.0 - nu * nu));
    let g_star = e / (2.0 * (1.0 + nu)) / (2.0 * (2.0 - nu));
    for c in k["contacts"].as_array().unwrap() {
        let f = c["normal_force_n"].as_f64().unwrap();
        let (a, _) = common::hertz_circle(f, 5e-3, e_star);
        let expect = 1.0 / (1.0 / (8.0 * g_star * a) + c_t);
        let got = c["tangential_stiffness_n_per_m"].as_f64().unwrap();
        assert!((got / expect - 1.0).abs() < 1e-9, "{got} vs {expect}");
    }
    let run = json_of(&["run", &file, "--json"]);
    assert_eq!(run["contacts"][0]["tangential_support_compliance_m_per_n"].as_f64(), Some(c_t));
    let sigma_x = |text: &str, name: &str| {
        let file = write_scene(name, text);
        let v = json_of(&[
            "study",
            &file,
            "--samples",
            "30",
            "--sampler",
            "mc",
            "--seed",
            "3",
            "--format",
            "json",
        ]);
        v["variants"][0]["points"][0]["sigma"]["x_nm"].as_f64().unwrap()
    };
    let rigid = sigma_x(
        &std::fs::read_to_string(common::scene("01_maxwell_vgroove_steel.toml")).unwrap(),
        "rigid",
    );
    let soft = sigma_x(&scene01_with_support("{ tangential = 1.0e-6 }"), "soft");
    assert!(soft < 0.05 * rigid, "{soft} vs {rigid}");
}

#[test]
fn bad_support_compliance_tables_are_refused() {
    for (value, field, says) in [
        ("{ normal = -1.0e-9 }", "coupling.support_compliance.normal", ">= 0"),
        ("{ tangetial = 1.0e-9 }", "coupling.support_compliance.tangetial", "unknown key"),
        (
            "{ tangential = \"soft\" }",
            "coupling.support_compliance.tangential",
            "expected a compliance",
        ),
        ("{ tangential = 0.5 }", "coupling.support_compliance", "implausibly large"),
    ] {
        let err = Scene::parse(&scene01_with_support(value), "bad.toml").unwrap_err().to_string();
        assert!(err.contains(field) && err.contains(says), "{value}: {err}");
    }
    let md = scene01_with_support("{ tangential = 1.0e-7 }")
        .replace("tangential_law = \"coulomb\"", "tangential_law = \"mindlin-deresiewicz\"");
    let err = Scene::parse(&md, "md.toml").unwrap_err().to_string();
    assert!(
        err.contains("friction.tangential_law") && err.contains("mindlin-deresiewicz"),
        "{err}"
    );
}

/// The bundled flexure example against scene 01, the same coupling on
/// rigid grooves: its contacts end the seating sticking below the limit,
/// and its scatter is far lower (measured 0.196 against 4.68 nm, 200 LHS).
#[test]
fn the_flexure_example_scatters_less_than_rigid_grooves() {
    let study = |name: &str| {
        let file = common::scene(name);
        let v = json_of(&[
            "study",
            file.to_str().unwrap(),
            "--samples",
            "30",
            "--sampler",
            "mc",
            "--format",
            "json",
        ]);
        v["variants"][0]["points"][0]["sigma"]["x_nm"].as_f64().unwrap()
    };
    let (flexure, rigid) =
        (study("maxwell_flexure_grooves.toml"), study("01_maxwell_vgroove_steel.toml"));
    assert!(flexure < 0.1 * rigid, "{flexure} vs {rigid}");
    let file = common::scene("maxwell_flexure_grooves.toml");
    let (ok, check, err) = common::kinrepro(&["check", file.to_str().unwrap()]);
    assert!(ok, "{err}");
    assert!(
        check.contains("support compliance behind contact(s) 1, 2, 3, 4, 5, 6: normal 9.1e-9 m/N, tangential 4.37e-7 m/N"),
        "{check}"
    );
    let run = json_of(&["run", file.to_str().unwrap(), "--json"]);
    for c in run["contacts"].as_array().unwrap() {
        assert_eq!(c["state"], "stick");
        assert!(
            c["tangential_force_n"].as_f64().unwrap() < 0.5 * c["normal_force_n"].as_f64().unwrap()
        );
    }
}
