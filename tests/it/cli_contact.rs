//! `kinrepro contact`: JSON keys against the closed form, and bad input gets
//! a clear message and a non-zero exit code.

use crate::common;
use crate::common::kinrepro;

/// `contact --json` for a 10 mm steel ball on a steel plane at 20 N.
fn steel_ball_on_plane_json() -> (bool, String, String) {
    kinrepro(&[
        "contact",
        "--shape",
        "sphere-plane",
        "--radius1",
        "5e-3",
        "--material1",
        "steel",
        "--material2",
        "steel",
        "--load",
        "20",
        "--json",
    ])
}

#[test]
fn json_output_has_the_documented_keys_and_hertz_values() {
    let (ok, out, _) = steel_ball_on_plane_json();
    assert!(ok);
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    // Closed form: E* = 210e9 / (2 (1 - 0.09)), a = (3 F R / 4 E*)^(1/3), delta = a^2/R.
    let e_star: f64 = common::E_STAR_STEEL;
    let a = (3.0 * 20.0 * 5e-3 / (4.0 * e_star)).cbrt();
    let get = |k: &str| v[k].as_f64().unwrap_or_else(|| panic!("missing {k}"));
    assert!((get("approach_m") / (a * a / 5e-3) - 1.0).abs() < 1e-12);
    assert!((v["semi_axes_m"][0].as_f64().unwrap() / a - 1.0).abs() < 1e-12);
    assert!(
        (get("max_pressure_pa") / (3.0 * 20.0 / (2.0 * std::f64::consts::PI * a * a)) - 1.0).abs()
            < 1e-12
    );
    assert!((get("hertz_constant") / (4.0 / 3.0 * e_star * 5e-3_f64.sqrt()) - 1.0).abs() < 1e-12);
    assert!((get("normal_stiffness_n_per_m") / (2.0 * e_star * a) - 1.0).abs() < 1e-12);
    assert!(get("tangential_stiffness_n_per_m") > 0.0);
}

#[test]
fn bad_input_is_a_clear_error_with_nonzero_exit() {
    let base = ["contact", "--material1", "steel", "--material2", "steel"];
    let cases: &[(&[&str], &str)] = &[
        (&["--shape", "sphere-plane", "--radius1", "-5e-3", "--load", "1"], "radius1"),
        (
            &["--shape", "sphere-sphere", "--radius1", "5e-3", "--radius2", "0", "--load", "1"],
            "radius2",
        ),
        (&["--shape", "sphere-cylinder", "--radius1", "5e-3", "--load", "1"], "needs radius2"),
        (&["--shape", "sphere-plane", "--radius1", "5e-3", "--load", "0"], "load"),
        (&["--shape", "sphere-plane", "--radius1", "5e-3", "--load", "-3"], "load"),
        (
            &["--shape", "sphere-seat", "--radius1", "5e-3", "--radius2", "4e-3", "--load", "1"],
            "seat",
        ),
        (&["--shape", "sphere-cone", "--radius1", "5e-3", "--load", "1"], "sphere-cone"),
    ];
    for (args, needle) in cases {
        let mut all: Vec<&str> = base.to_vec();
        all.extend_from_slice(args);
        let (ok, _, err) = kinrepro(&all);
        assert!(!ok, "{args:?} should fail");
        assert!(err.contains(needle), "{args:?}: stderr lacks `{needle}`: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    let (ok, _, err) = kinrepro(&[
        "contact",
        "--shape",
        "sphere-plane",
        "--radius1",
        "5e-3",
        "--material1",
        "unobtainium",
        "--material2",
        "steel",
        "--load",
        "1",
    ]);
    assert!(!ok && err.contains("unknown material `unobtainium`") && err.contains("--material1"));
}

/// tau_max/p0 and z/a on the axis of a circular Hertz contact by a fine scan
/// of Johnson's closed form (eq. 3.45).
fn circle_tau(nu: f64) -> (f64, f64) {
    (1..200_000)
        .map(|k| k as f64 * 1e-5)
        .map(|z: f64| {
            let q = 1.0 + z * z;
            let sr = -(1.0 + nu) * (1.0 - z * (1.0 / z).atan()) + 0.5 / q;
            (0.5 * (sr + 1.0 / q).abs(), z)
        })
        .max_by(|a, b| a.0.total_cmp(&b.0))
        .unwrap()
}

#[test]
fn json_reports_axis_stiffnesses_and_tau_max() {
    let (ok, out, err) = steel_ball_on_plane_json();
    assert!(ok, "{err}");
    let v: serde_json::Value = serde_json::from_str(&out).unwrap();
    let get = |k: &str| v[k].as_f64().unwrap_or_else(|| panic!("missing {k}"));
    // Circle: k_t = 8 G* a along both axes (Mindlin 1949), G* = 1/(2 (2 - nu)/G).
    let (e, nu) = (210e9_f64, 0.3_f64);
    let g_star = e / (2.0 * (1.0 + nu)) / (2.0 * (2.0 - nu));
    let e_star = e / (2.0 * (1.0 - nu * nu));
    let a = (3.0 * 20.0 * 5e-3 / (4.0 * e_star)).cbrt();
    for k in [
        "tangential_stiffness_major_n_per_m",
        "tangential_stiffness_minor_n_per_m",
        "tangential_stiffness_n_per_m",
    ] {
        assert!((get(k) / (8.0 * g_star * a) - 1.0).abs() < 1e-12, "{k}");
    }
    let (ratio, depth) = circle_tau(0.3);
    assert!((get("max_shear_stress_pa") / (ratio * get("max_pressure_pa")) - 1.0).abs() < 1e-9);
    assert!((get("max_shear_depth_m") / (depth * a) - 1.0).abs() < 1e-4);
}

fn write(dir: &std::path::Path, name: &str, text: &str) -> String {
    let p = dir.join(name);
    std::fs::write(&p, text).unwrap();
    p.display().to_string()
}

fn history_args<'a>(file: &'a str, law: &'a str) -> Vec<&'a str> {
    vec![
        "contact",
        "--shape",
        "sphere-plane",
        "--radius1",
        "5e-3",
        "--material1",
        "steel",
        "--material2",
        "steel",
        "--mu",
        "0.5",
        "--tangential-law",
        law,
        "--history",
        file,
    ]
}

#[test]
fn history_follows_cattaneo_and_prints_the_documented_csv() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let (p, mu, n) = (10.0, 0.5, 100);
    let mut text = String::from("P_N,Qx_N,Qy_N\n");
    for i in 0..=n {
        text += &format!("{p},0,{}\n", 0.9 * mu * p * i as f64 / n as f64);
    }
    let file = write(dir, "ramp.csv", &text);
    let (ok, out, err) = kinrepro(&history_args(&file, "mindlin-deresiewicz"));
    assert!(ok, "{err}");
    let mut lines = out.lines().filter(|l| !l.starts_with('#'));
    assert_eq!(lines.next(), Some("step,P_N,Qx_N,Qy_N,sx_m,sy_m,slip"));
    assert!(out.starts_with("# kinrepro ") && out.contains("mindlin-deresiewicz"));
    let (e, nu) = (210e9_f64, 0.3_f64);
    let g_star = e / (2.0 * (1.0 + nu)) / (2.0 * (2.0 - nu));
    let a = (3.0 * p * 5e-3 / (4.0 * e / (2.0 * (1.0 - nu * nu)))).cbrt();
    let rows: Vec<Vec<String>> = lines.map(|l| l.split(',').map(String::from).collect()).collect();
    assert_eq!(rows.len(), n + 1);
    for r in &rows[1..] {
        let f = |k: usize| r[k].parse::<f64>().unwrap();
        // Q along y (the minor axis): Cattaneo, Johnson eq. 7.49.
        let q = f(3) / (mu * p);
        let s = 3.0 * mu * p / (16.0 * g_star * a) * (1.0 - (1.0 - q).powf(2.0 / 3.0));
        assert!((f(5) / s - 1.0).abs() < 5e-3, "step {}: {} vs {s}", r[0], f(5));
        assert_eq!(f(4), 0.0);
        assert_eq!(r[6], "stick");
    }
    // Coulomb: one linear spring, s = Q / (8 G* a).
    let (ok, out, _) = kinrepro(&history_args(&file, "coulomb"));
    assert!(ok);
    let last = out.lines().last().unwrap().split(',').collect::<Vec<_>>();
    let q: f64 = last[3].parse().unwrap();
    let s: f64 = last[5].parse().unwrap();
    assert!((s / (q / (8.0 * g_star * a)) - 1.0).abs() < 1e-12);
}

#[test]
fn bad_history_is_one_clear_error_naming_file_line_and_column() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let cases: &[(&str, &[&str])] = &[
        ("P_N,Qx_N,Qy_N\n10,0,0\n10,abc,0\n", &[":3:", "Qx_N", "abc"]),
        ("P_N,Qx_N,Qy_N\n10,0,0\n-1,0,0\n", &[":3:", "P_N", "positive"]),
        ("P_N,Qx_N,Qy_N\n10,0,0\n10,0,nan\n", &[":3:", "Qy_N"]),
        ("P_N,Qx_N,Qy_N\n10,0\n", &[":2:", "2 fields"]),
        ("P,Qx,Qy\n10,0,0\n", &[":1:", "header", "P_N,Qx_N,Qy_N"]),
        ("P_N,Qx_N,Qy_N\n", &["no rows"]),
        ("P_N,Qx_N,Qy_N\n10,0,0\n10,4,0\n10,5.5,0\n", &[":4:", "friction limit", "slide"]),
    ];
    for (i, (text, needles)) in cases.iter().enumerate() {
        let file = write(dir, &format!("h{i}.csv"), text);
        for law in ["coulomb", "mindlin-deresiewicz"] {
            let (ok, out, err) = kinrepro(&history_args(&file, law));
            assert!(!ok && out.is_empty(), "{text}: should fail");
            assert!(err.contains(&format!("h{i}.csv")), "{err}");
            for n in *needles {
                assert!(err.contains(n), "{text}: stderr lacks `{n}`: {err}");
            }
            assert_eq!(err.trim().lines().count(), 1, "{err}");
            assert!(!err.contains("panicked"));
        }
    }
    // The removed law name explains itself.
    let file = write(dir, "ok.csv", "P_N,Qx_N,Qy_N\n10,0,0\n");
    let (ok, _, err) = kinrepro(&history_args(&file, "cattaneo-mindlin"));
    assert!(!ok && err.contains("mindlin-deresiewicz"), "{err}");
    // --history needs --mu.
    let mut args = history_args(&file, "coulomb");
    args.drain(9..11);
    let (ok, _, err) = kinrepro(&args);
    assert!(!ok && err.contains("--mu"), "{err}");
}

/// `contact` for a 10 mm steel ball on a steel plane with mu_s = 0.5 (the
/// history tests' pair).
pub(crate) const STEEL_BALL_ON_PLANE: [&str; 11] = [
    "contact",
    "--shape",
    "sphere-plane",
    "--radius1",
    "0.005",
    "--material1",
    "steel",
    "--material2",
    "steel",
    "--mu",
    "0.5",
];

/// The form of the README: `--history` without `--load` (the file gives the
/// loads); `--load` beside it is not used, and says so; without either, the
/// error names `--load`.
#[test]
fn history_needs_no_load() {
    let tmp = tempfile::tempdir().unwrap();
    let file = write(tmp.path(), "h.csv", "P_N,Qx_N,Qy_N\n10,0,0\n10,1,0\n");
    let run = |extra: &[&str]| kinrepro(&[&STEEL_BALL_ON_PLANE[..], extra].concat());
    let (ok, out, err) = run(&["--history", &file]);
    assert!(ok, "{err}");
    assert!(err.is_empty(), "{err}");
    // Row 2: Q = 1 N sticks on one Coulomb spring, s = Q / (8 G* a).
    let (e, nu) = (210e9_f64, 0.3_f64);
    let g_star = e / (2.0 * (1.0 + nu)) / (2.0 * (2.0 - nu));
    let a = (3.0 * 10.0 * 5e-3 / (4.0 * e / (2.0 * (1.0 - nu * nu)))).cbrt();
    let last: Vec<&str> = out.lines().last().unwrap().split(',').collect();
    let sx: f64 = last[4].parse().unwrap();
    assert!((sx / (1.0 / (8.0 * g_star * a)) - 1.0).abs() < 1e-12, "{sx}");
    // --load 5 beside --history would have no effect: refused (it was a
    // warning, and the run went on).
    let (ok, out2, err) = run(&["--history", &file, "--load", "5"]);
    assert!(!ok && out2.is_empty(), "{out2}");
    assert!(err.contains("--load 5: has no effect with --history"), "{err}");
    let (ok, _, err) = run(&[]);
    assert!(!ok && err.contains("--load"), "{err}");
}

/// A tangential support compliance c_t behind the contact (a flexure):
/// under proportional loading below slip (Q = 0.2 P, P up to 10 N in 40
/// steps) the tangential displacement is Mindlin's 1.5 Q / (8 G* a) plus
/// the support's c_t Q (Johnson 1985, §7.3, in series with a linear
/// spring); with c_t = 0 it is Mindlin's alone.
#[test]
fn history_with_a_tangential_compliance_adds_c_t_q() {
    let tmp = tempfile::tempdir().unwrap();
    let rows: String = (1..=40)
        .map(|k| {
            let p = 10.0 * k as f64 / 40.0;
            format!("{p},{},0\n", 0.2 * p)
        })
        .collect();
    let file = write(tmp.path(), "prop.csv", &format!("P_N,Qx_N,Qy_N\n{rows}"));
    let (e, nu) = (210e9_f64, 0.3_f64);
    let g_star = e / (2.0 * (1.0 + nu)) / (2.0 * (2.0 - nu));
    let a = (3.0 * 10.0 * 5e-3 / (4.0 * e / (2.0 * (1.0 - nu * nu)))).cbrt();
    let q = 2.0;
    let history = ["--history", file.as_str(), "--tangential-compliance"];
    let base = [&STEEL_BALL_ON_PLANE[..], &history[..]].concat();
    for c_t in [0.0, 2e-7] {
        let c = format!("{c_t:e}");
        let (ok, out, err) = kinrepro(&[&base[..], &[c.as_str()]].concat());
        assert!(ok, "{err}");
        assert!(out.contains(&format!("tangential support compliance {c} m/N")), "{out}");
        let last: Vec<&str> = out.lines().last().unwrap().split(',').collect();
        let (sx, slip) = (last[4].parse::<f64>().unwrap(), last[6]);
        assert_eq!(slip, "stick");
        let expect = 1.5 * q / (8.0 * g_star * a) + c_t * q;
        assert!((sx / expect - 1.0).abs() < 1e-9, "c_t {c_t}: {sx} vs {expect}");
    }
    let md = ["1e-7", "--tangential-law", "mindlin-deresiewicz"];
    let (ok, _, err) = kinrepro(&[&base[..], &md[..]].concat());
    assert!(!ok && err.contains("--tangential-compliance"), "{err}");
}
