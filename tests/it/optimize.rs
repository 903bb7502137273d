//! `kinrepro optimize` against optima known independently (issue 44, item
//! 4): the largest preload under a bound on sigma_x, from sigma ~ F^(2/3)
//! at common random numbers (Hertz: contact stiffness ~ F^(1/3), friction
//! forces ~ F); a two-dimensional optimum against a fine grid of the same
//! studies; constraints met at the optimum; the same seed, the same
//! optimum; goals that cannot be read are refused.

use crate::common::{kinrepro, scene};
use kinrepro::explore::goal::{Constraint, Objective};
use kinrepro::explore::run::study_plan;
use kinrepro::explore::{Set, SweptValue, evaluate, point_file};
use kinrepro::scene::SceneFile;
use kinrepro::study::{Sampler, StudyOptions};

fn s01() -> String {
    scene("01_maxwell_vgroove_steel.toml").to_str().unwrap().to_string()
}

fn optimize(args: &[&str]) -> serde_json::Value {
    let s = s01();
    let base = ["optimize", &s, "--sampler", "mc", "--samples", "20", "--seed", "1", "--json"];
    let (ok, out, err) = kinrepro(&[&base[..], args].concat());
    assert!(ok, "{err}");
    serde_json::from_str(&out).unwrap()
}

/// sigma_x of scene 01 at preload `force` (the same 20 Monte Carlo draws).
fn sigma_x(force: f64) -> f64 {
    let text = std::fs::read_to_string(s01()).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("s.toml");
    let set = text.replacen("force = 20.0 ", &format!("force = {force} "), 1);
    assert_ne!(set, text);
    std::fs::write(&p, set).unwrap();
    let args = ["study", p.to_str().unwrap(), "--sampler", "mc", "--samples", "20", "--seed", "1"];
    let (ok, out, err) = kinrepro(&[&args[..], &["--format", "json"]].concat());
    assert!(ok, "{err}");
    let r: serde_json::Value = serde_json::from_str(&out).unwrap();
    r["variants"][0]["points"][0]["sigma"]["x_nm"].as_f64().unwrap() * 1e-9
}

#[test]
fn the_largest_preload_under_a_bound_on_sigma_follows_the_hertz_power() {
    let target = 6e-9;
    let bound = format!("sigma:centre:x<={target:e}");
    let args = [
        "--vary",
        "preload.force=5:40",
        "--objective",
        "preload.force:max",
        "--constraint",
        &bound,
    ];
    let r = optimize(&args);
    // sigma = sigma_0 (F / F_0)^(2/3): F* = F_0 (target / sigma_0)^(3/2).
    let f0 = 20.0;
    let closed = f0 * (target / sigma_x(f0)).powf(1.5);
    let found = r["optimum"]["fields"]["preload.force"].as_f64().unwrap();
    assert!((found / closed - 1.0).abs() < 0.01, "optimum {found} N, closed form {closed} N");
    let margin = r["optimum"]["constraint_margins"][0]["margin"].as_f64().unwrap();
    assert!(margin >= 0.0, "the optimum breaks its constraint by {margin}");
    // The same seed, the same optimum and history.
    let again = optimize(&args);
    assert_eq!(r["optimum"], again["optimum"]);
    assert_eq!(r["history"], again["history"]);
    // The HTML page: the optimum's force, its margin, the convergence plot
    // with one marker per candidate that gave an objective.
    let dir = tempfile::tempdir().unwrap();
    let html = dir.path().join("o.html");
    let s = s01();
    let base = ["optimize", &s, "--sampler", "mc", "--samples", "20", "--seed", "1"];
    let (ok, _, err) =
        kinrepro(&[&base[..], &args[..], &["--html", html.to_str().unwrap()]].concat());
    assert!(ok, "{err}");
    let page = std::fs::read_to_string(&html).unwrap();
    assert!(page.contains(&format!("<td class=\"l\">{found}</td>")), "the optimum's force");
    assert!(
        page.contains("margin of sigma:centre:x&lt;=6e-9") && page.contains("data-check=\"chart\"")
    );
    let history = r["history"].as_array().unwrap();
    let feasible = history.iter().filter(|c| c["feasible"] == true).count();
    assert_eq!(page.matches("<circle").count(), feasible, "one dot per feasible candidate");
}

/// sigma_x of scene 01 grows with the preload and falls with the ball
/// diameter (about F^(2/3) D^(-1/3): a scales as (F D)^(1/3)), k_min grows
/// with both: the optimum lies on the stiffness bound at the largest
/// ball. A 36 x 36 grid of the same studies (the same draws) finds no
/// feasible design better by more than 1 %, and its best lies next to the
/// optimum.
#[test]
fn a_two_dimensional_optimum_is_no_worse_than_a_fine_grid_of_the_same_studies() {
    let (force, ball) = ("preload.force=5:40", "coupling.ball_diameter=0.006:0.016");
    let r = optimize(&[
        "--vary",
        force,
        "--vary",
        ball,
        "--objective",
        "sigma:centre:x:min",
        "--constraint",
        "k_min>=6e7",
    ]);
    let best = r["optimum"]["objective"].as_f64().unwrap();
    let margin = r["optimum"]["constraint_margins"][0]["margin"].as_f64().unwrap();
    assert!(margin >= 0.0, "k_min below its bound at the optimum");
    let d = r["optimum"]["fields"]["coupling.ball_diameter"].as_f64().unwrap();
    let f = r["optimum"]["fields"]["preload.force"].as_f64().unwrap();
    // The grid, by the library's own evaluation of a design point.
    let text = std::fs::read_to_string(s01()).unwrap();
    let (sc, coupling) = kinrepro::error::parse_scene(&text, "01").unwrap();
    let options = StudyOptions {
        sampler: Some(Sampler::MonteCarlo),
        samples: Some(20),
        seed: Some(1),
        ..StudyOptions::default()
    };
    let plan = study_plan(sc, coupling, &options).unwrap();
    let base = SceneFile::parse(&text, "01").unwrap();
    let sets: Vec<Set> = [force, ball].iter().map(|a| Set::parse(a, &base).unwrap()).collect();
    let objective = Objective::parse("sigma:centre:x:min").unwrap();
    let constraint = Constraint::parse("k_min>=6e7").unwrap();
    let n = 36;
    let (mut grid_best, mut at) = (f64::INFINITY, (0.0, 0.0));
    for i in 0..n {
        for j in 0..n {
            let x =
                (5.0 + 35.0 * i as f64 / (n - 1) as f64, 0.006 + 0.01 * j as f64 / (n - 1) as f64);
            let values = [SweptValue::Number(x.0), SweptValue::Number(x.1)];
            let file = point_file(&base, &sets, &values);
            let e = evaluate(file, &text, "grid", &plan, (&plan.variants[0], false), &|| {});
            let d = kinrepro::explore::run::design_report(0, Default::default(), e);
            let value = objective.output.value(&d).unwrap_or(f64::INFINITY);
            if constraint.margin(&d).is_some_and(|m| m >= 0.0) && value < grid_best {
                (grid_best, at) = (value, x);
            }
        }
    }
    assert!(grid_best.is_finite());
    assert!(best <= grid_best * 1.01, "optimum {best:e} m, best of the grid {grid_best:e} m");
    // Next to the grid's best: within two grid steps.
    assert!(
        (f - at.0).abs() <= 2.0 * 35.0 / 35.0 && (d - at.1).abs() <= 2.0 * 0.01 / 35.0,
        "{f} N, {d} m; grid {at:?}"
    );
}

#[test]
fn goals_that_cannot_be_read_are_refused_naming_them() {
    let s = s01();
    let cases: [(&[&str], &str); 6] = [
        (&["--objective", "sigma:centre:x"], "OUTPUT:min or OUTPUT:max"),
        (&["--objective", "sigma:tip:x:min"], "no evaluation point `tip`"),
        (&["--objective", "sigma:centre:beam:min"], "neither a DOF"),
        (&["--objective", "coupling.diameter:max"], "not among those varied"),
        (&["--objective", "k_min:max", "--constraint", "sf_p=3"], "OUTPUT<=VALUE"),
        (&["--objective", "k_min:max", "--constraint", "sf_p>=x"], "not a finite number"),
    ];
    for (args, says) in cases {
        let base = ["optimize", &s, "--vary", "preload.force=5:40", "--samples", "4"];
        let (ok, _, err) = kinrepro(&[&base[..], args].concat());
        assert!(!ok && err.contains(says), "{args:?}: {err}");
        assert!(!err.contains("panicked"), "{err}");
    }
    // No feasible design: exit 1, the history printed.
    let args = ["optimize", &s, "--vary", "preload.force=5:40", "--samples", "4"];
    let (ok, out, err) = kinrepro(
        &[&args[..], &["--objective", "k_min:max", "--constraint", "sigma:centre:x<=1e-15"]]
            .concat(),
    );
    assert!(!ok && err.contains("no feasible design"), "{err}");
    assert!(out.contains("NO FEASIBLE DESIGN") && out.contains("history"), "{out}");
}

/// docs/guide-design.md shows the optimisation of the README's stage as
/// this command prints it.
#[test]
fn the_guide_optimisation_of_the_stage_reproduces() {
    let stage = scene("example_stage_mount.toml");
    let (ok, out, err) = kinrepro(&[
        "optimize",
        stage.to_str().unwrap(),
        "--vary",
        "preload.force=10:60",
        "--vary",
        "coupling.opening_angle_deg=70:120",
        "--objective",
        "pm3sigma:sample:ion beam:min",
        "--constraint",
        "sf_p>=3",
        "--constraint",
        "k_min>=6e7",
        "--samples",
        "100",
        "--sampler",
        "mc",
    ]);
    assert!(ok, "{err}");
    let guide = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/guide-design.md");
    let guide = std::fs::read_to_string(guide).unwrap();
    for starts in [
        "optimum (candidate",
        "  objective pm3sigma",
        "  constraint sf_p",
        "         along ion beam",
        "history (",
    ] {
        let line =
            out.lines().find(|l| l.starts_with(starts)).unwrap_or_else(|| panic!("{starts}"));
        assert!(guide.contains(line.trim_end()), "the guide lacks\n{line}");
    }
}

/// A scene's `[goals]` serve `optimize` and `sweep` where no objective or
/// constraint is given, the same as given on the command line; a goal the
/// scene cannot read is refused with its file, line and key.
#[test]
fn a_scenes_goals_are_the_command_lines() {
    let dir = tempfile::tempdir().unwrap();
    let text = std::fs::read_to_string(s01()).unwrap();
    let with = |goals: &str| {
        let p = dir.path().join("goals.toml");
        std::fs::write(&p, format!("{text}\n[goals]\n{goals}\n")).unwrap();
        p.to_str().unwrap().to_string()
    };
    let s = with("objectives = [\"preload.force:max\"]\nconstraints = [\"sigma:centre:x<=6e-9\"]");
    let args = [
        "--sampler",
        "mc",
        "--samples",
        "20",
        "--seed",
        "1",
        "--vary",
        "preload.force=5:40",
        "--json",
    ];
    let (ok, from_file, err) = kinrepro(&[&["optimize", &s][..], &args[..]].concat());
    assert!(ok, "{err}");
    let flags = ["--objective", "preload.force:max", "--constraint", "sigma:centre:x<=6e-9"];
    let (ok, given, err) = kinrepro(&[&["optimize", &s01()][..], &args[..], &flags[..]].concat());
    assert!(ok, "{err}");
    let (a, b): (serde_json::Value, serde_json::Value) =
        (serde_json::from_str(&from_file).unwrap(), serde_json::from_str(&given).unwrap());
    assert_eq!(a["optimum"], b["optimum"]);
    // The sweep takes them too.
    let (ok, sweep, err) = kinrepro(&[
        "sweep",
        &s,
        "--set",
        "preload.force=10,40",
        "--samples",
        "10",
        "--format",
        "json",
    ]);
    assert!(ok, "{err}");
    let sweep: serde_json::Value = serde_json::from_str(&sweep).unwrap();
    assert_eq!(sweep["objectives"][0]["path"], "preload.force");
    // A bad goal in the file: file, line, key.
    let bad = with("objectives = [\"sigma:tip:x:min\"]");
    let (ok, _, err) =
        kinrepro(&["optimize", &bad, "--vary", "preload.force=5:40", "--samples", "4"]);
    let line = text.lines().count() + 3;
    assert!(!ok && err.contains(&format!("goals.toml:{line}: goals.objectives[1]")), "{err}");
    assert!(err.contains("no evaluation point `tip`"), "{err}");
}

/// A `[thermal]` scene's residual and drift are outputs: the optimum's
/// residual is the |mean drift| at the cycle's last point of a study of
/// the optimum's preload (the study's own JSON, read here), and its
/// largest drift bounds a constraint.
#[test]
fn thermal_residual_and_drift_are_objectives_and_constraints() {
    let th = scene("maxwell_thermal_alu_invar.toml");
    let th = th.to_str().unwrap();
    let args = ["--vary", "preload.force=20:120", "--samples", "12", "--sampler", "mc", "--json"];
    let goals =
        ["--objective", "residual:tool tip:x:min", "--constraint", "drift:tool tip:x<=1e-3"];
    let (ok, out, err) = kinrepro(&[&["optimize", th][..], &args[..], &goals[..]].concat());
    assert!(ok, "{err}");
    let r: serde_json::Value = serde_json::from_str(&out).unwrap();
    let f = r["optimum"]["fields"]["preload.force"].as_f64().unwrap();
    let residual = r["optimum"]["objective"].as_f64().unwrap();
    let text = std::fs::read_to_string(th).unwrap();
    let dir = tempfile::tempdir().unwrap();
    let p = dir.path().join("t.toml");
    let set = text.replacen("force = 20.0 ", &format!("force = {f} "), 1);
    assert_ne!(set, text);
    std::fs::write(&p, set).unwrap();
    let study =
        ["study", p.to_str().unwrap(), "--samples", "12", "--sampler", "mc", "--format", "json"];
    let (ok, out, err) = kinrepro(&study);
    assert!(ok, "{err}");
    let s: serde_json::Value = serde_json::from_str(&out).unwrap();
    let tip = s["variants"][0]["points"]
        .as_array()
        .unwrap()
        .iter()
        .find(|p| p["name"] == "tool tip")
        .unwrap();
    let cycle = tip["thermal"].as_array().unwrap();
    let last = cycle.last().unwrap()["mean"]["x_nm"].as_f64().unwrap().abs() * 1e-9;
    assert!((residual / last - 1.0).abs() < 1e-12, "{residual} vs {last}");
    let drift =
        cycle.iter().map(|c| c["mean"]["x_nm"].as_f64().unwrap().abs() * 1e-9).fold(0.0, f64::max);
    assert!(drift <= 1e-3 && drift >= residual);
    // A scene without [thermal] has no drift.
    let (ok, _, err) = kinrepro(&[
        "optimize",
        &s01(),
        "--vary",
        "preload.force=5:40",
        "--objective",
        "drift:centre:x:min",
        "--samples",
        "4",
    ]);
    assert!(!ok && err.contains("no [thermal] cycle"), "{err}");
}

/// Listed values are enumerated, one search each (in parallel): the best
/// of the searches, the same with one thread or two.
#[test]
fn listed_fields_are_enumerated_and_threads_do_not_change_the_result() {
    let s = s01();
    let run = |jobs: &str| {
        let (ok, out, err) = kinrepro(&[
            "optimize",
            &s,
            "--vary",
            "preload.force=5:40",
            "--vary",
            "coupling.ball_material=steel,silicon-carbide",
            "--objective",
            "k_min:max",
            "--constraint",
            "sigma:centre:x<=4e-9",
            "--samples",
            "10",
            "--sampler",
            "mc",
            "--jobs",
            jobs,
            "--json",
        ]);
        assert!(ok, "{err}");
        serde_json::from_str::<serde_json::Value>(&out).unwrap()
    };
    let (one, two) = (run("1"), run("2"));
    assert_eq!(one["optimum"], two["optimum"]);
    assert_eq!(one["history"], two["history"]);
    assert_eq!(one["termination"].as_array().unwrap().len(), 2, "one search per material");
    let materials: Vec<&str> = (one["history"].as_array().unwrap().iter())
        .map(|c| c["fields"]["coupling.ball_material"].as_str().unwrap())
        .collect();
    assert!(materials.contains(&"steel") && materials.contains(&"silicon-carbide"));
    // The optimum is the better of the two materials' best feasible candidates.
    let best = |m: &str| {
        (one["history"].as_array().unwrap().iter())
            .filter(|c| c["feasible"] == true && c["fields"]["coupling.ball_material"] == m)
            .map(|c| c["objective"].as_f64().unwrap())
            .fold(f64::NEG_INFINITY, f64::max)
    };
    let optimum = one["optimum"]["objective"].as_f64().unwrap();
    assert_eq!(optimum, best("steel").max(best("silicon-carbide")));
}
