//! More of the command lines replayed: the decay law's transition
//! warning (item 6), calibration errors naming the calibration file
//! (item 7), signals during a trace (item 1) and flags or values the
//! other part files do not yet cover.

use std::path::Path;

use kinrepro::assembly::Coupling;
use kinrepro::contact::FrictionLaw;
use kinrepro::contact::friction::{TRANSITION, in_transition};
use kinrepro::scene::Scene;
use kinrepro::solve::dynamic::{self, DynamicOptions};
use kinrepro::solve::{Load, SolverOptions, quasistatic};

use crate::common;
use crate::files::{hidden, wait_for_temporary};
use crate::verdicts::{run_in, variant};

/// Scene 01 with the decay law at coefficient `c` [s/m].
fn decay_scene(dir: &Path, c: &str) -> std::path::PathBuf {
    variant(
        dir,
        &format!("decay_{c}.toml"),
        &[(
            "tangential_law = \"coulomb\"",
            &format!("tangential_law = \"coulomb\"\nlaw = \"decay\"\ndecay_coefficient = {c}"),
        )],
    )
}

/// Scene 01 with the decay law at coefficient `c` [s/m], assembled.
fn decay_coupling(c: f64) -> (Scene, Coupling) {
    let (mut scene, _) = common::load("01_maxwell_vgroove_steel.toml");
    scene.friction.law = FrictionLaw::Decay { coefficient: c };
    let cp = Coupling::new(&scene).unwrap();
    (scene, cp)
}

/// The dynamic solver's c v_slip at nominal friction for coefficient `c`.
fn decay_cv(c: f64) -> f64 {
    let (scene, cp) = decay_coupling(c);
    let s = dynamic::seat(&cp, &Load::nominal(&scene), &DynamicOptions::default()).unwrap();
    s.seated.decay_cv.unwrap()
}

/// The quasi-static solver's c v_slip at nominal friction for `c`.
fn quasi_static_cv(c: f64) -> f64 {
    let (scene, cp) = decay_coupling(c);
    let s = quasistatic::seat(&cp, &Load::nominal(&scene), &SolverOptions::default()).unwrap();
    s.seated.decay_cv.unwrap()
}

#[test]
fn quasi_static_decay_cv_is_the_slip_path_over_the_ramp() {
    // docs/scenes.md: the grooves of scene 01 slip about 0.5 um over the
    // 1 s ramp, so c v_slip is about c 5e-7 m/s. In the large-c limit
    // (mu = mu_d for any slip) the slip path does not depend on c, so
    // c v_slip grows as c.
    let (a, b) = (quasi_static_cv(1e9), quasi_static_cv(1e10));
    assert!((b / a / 10.0 - 1.0).abs() < 1e-6, "{a:e} {b:e}");
    let v_slip = a / 1e9;
    assert!((1e-7..2e-6).contains(&v_slip), "v_slip {v_slip:e} m/s");
    let (scene, cp) = common::load("01_maxwell_vgroove_steel.toml");
    let s = quasistatic::seat(&cp, &Load::nominal(&scene), &SolverOptions::default()).unwrap();
    assert_eq!(s.seated.decay_cv, None);
}

#[test]
fn decay_cv_is_the_coefficient_times_a_slip_speed() {
    // In the large-c limit mu = mu_d for any slip, so the slip path, and
    // with it v_slip, does not depend on c: c v_slip grows as c (to the
    // 1e-3 the last steps of the settling allow).
    let (a, b) = (decay_cv(1e9), decay_cv(1e10));
    assert!((b / a / 10.0 - 1.0).abs() < 1e-3, "{a:e} {b:e}");
    // The switch law has none.
    let (scene, cp) = common::load("01_maxwell_vgroove_steel.toml");
    let s = dynamic::seat(&cp, &Load::nominal(&scene), &DynamicOptions::default()).unwrap();
    assert_eq!(s.seated.decay_cv, None);
}

/// Whether `run` and `study` of `scene` warn, with the dynamic solver and
/// with the quasi-static one (and exit 0 either way).
fn warns(dir: &Path, scene: &Path) -> [bool; 4] {
    let s = scene.to_str().unwrap();
    let warned = |args: &[&str]| {
        let (code, _, err) = run_in(dir, args);
        assert_eq!(code, 0, "{args:?}: {err}");
        let hit = err.contains("warning:") && err.contains("decay law in its transition");
        assert!(!hit || err.contains(s) && err.contains("c v_slip"), "{err}");
        hit
    };
    [
        warned(&["run", "--solver", "dynamic", s]),
        warned(&["study", "--solver", "dynamic", "--samples", "4", s]),
        warned(&["run", s]),
        warned(&["study", "--samples", "4", s]),
    ]
}

#[test]
fn decay_law_in_its_transition_warns() {
    // docs/scenes.md calls c = 2e6 s/m non-converged; the warning follows
    // the criterion c v_slip in TRANSITION, evaluated here with the library.
    let dir = tempfile::tempdir().unwrap();
    for (c, text) in [(2e6, "2e6"), (20.0, "20.0"), (1e10, "1e10")] {
        let expect = in_transition(decay_cv(c));
        let quasi = in_transition(quasi_static_cv(c));
        assert_eq!(
            warns(dir.path(), &decay_scene(dir.path(), text)),
            [expect, expect, quasi, quasi],
            "c = {c}"
        );
        if c == 2e6 {
            assert!(
                expect && quasi,
                "c = 2e6 s/m: {} and {} outside {TRANSITION:?}",
                decay_cv(c),
                quasi_static_cv(c)
            );
        } else {
            assert!(!expect && !quasi, "c = {c}");
        }
    }
    // The default scene (switch law) never warns.
    assert_eq!(warns(dir.path(), &common::scene("01_maxwell_vgroove_steel.toml")), [false; 4]);
}

/// The bundled calibration of scene 02 with `edit` applied, written as `dir/name`.
fn calibration(dir: &Path, name: &str, edit: &dyn Fn(&mut serde_json::Value)) -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let text = std::fs::read_to_string(root.join("docs/calibration/calibration_02.json")).unwrap();
    let mut v: serde_json::Value = serde_json::from_str(&text).unwrap();
    edit(&mut v);
    std::fs::write(dir.join(name), v.to_string()).unwrap();
    name.to_string()
}

/// A fitted parameter `name` at `estimate` in [low, high], like the spread's entry.
fn add_parameter(v: &mut serde_json::Value, name: &str, [estimate, low, high]: [f64; 3]) {
    let mut p = v["parameters"]["spread"].clone();
    p["estimate"] = estimate.into();
    p["low"] = low.into();
    p["high"] = high.into();
    v["parameters"][name] = p;
}

#[test]
fn calibration_errors_name_the_calibration_file_the_field_and_the_reason() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::copy(common::scene("02_maxwell_pins_steel.toml"), d.join("s02.toml")).unwrap();
    type Edit = Box<dyn Fn(&mut serde_json::Value)>;
    // (case, edit, what the one error line must name besides the file)
    let cases: Vec<(&str, Edit, &[&str])> = vec![
        // A value no scene allows: mu_d above mu_s, mu_s above MU_MAX.
        (
            "ratio",
            Box::new(|v| add_parameter(v, "dynamic_ratio", [1.5, 1.4, 1.6])),
            &["`parameters.dynamic_ratio.estimate`", "(0, 1]"],
        ),
        (
            "mu",
            Box::new(|v| add_parameter(v, "mu_static", [3.0, 2.9, 3.1])),
            &["`parameters.mu_static.estimate`", "[0, 2]"],
        ),
        // A region point whose spread leaves mu_s in [0, 2] with the scene's mu_static 0.5.
        (
            "region",
            Box::new(|v| v["region"][1]["spread"] = 0.9.into()),
            &["`region[1]`", "s02.toml", "spread 0.9", "mu_static 0.5"],
        ),
        // Estimates that make the scene's mu_s negative (spread > mu_static).
        (
            "estimate",
            Box::new(|v| add_parameter(v, "mu_static", [0.05, 0.04, 0.06])),
            &["`parameters` estimates", "s02.toml", "mu_static 0.05"],
        ),
        // Estimates at which the scene cannot seat (mu_static 1.9).
        (
            "cannot seat",
            Box::new(|v| add_parameter(v, "mu_static", [1.9, 1.85, 1.95])),
            &["`parameters` estimates", "s02.toml", "cannot seat"],
        ),
    ];
    for (what, edit, names) in cases {
        let cal = calibration(d, &format!("{}.json", what.replace(' ', "_")), &edit);
        let (rc, out, err) =
            run_in(d, &["predict", "s02.toml", "--calibration", &cal, "--samples", "100"]);
        assert_eq!(rc, 1, "{what}: {out}");
        assert_eq!(err.lines().count(), 1, "{what}: {err}");
        assert!(err.starts_with(&format!("error: {cal}: ")), "{what}: {err}");
        for n in names {
            assert!(err.contains(n), "{what}: {n}: {err}");
        }
    }
}

/// `run --solver dynamic --trace FILE --force` over an earlier FILE, stopped
/// by `signals` (sent to the stopped process at once when `together`) once
/// its temporary trace exists. Asserts no temporary is left and FILE is
/// intact; returns the exit code and stderr.
fn interrupted_trace(signals: &[&str], together: bool) -> (i32, String) {
    use std::process::{Command, Stdio};
    let dir = tempfile::tempdir().unwrap();
    // A small moment of inertia about z: a dynamic seating of some
    // 10^5 steps and a trace of some 100 MB, far longer than the test waits.
    let scene = variant(dir.path(), "slow.toml", &[]);
    let mut text = std::fs::read_to_string(&scene).unwrap();
    text.push_str("\n[dynamics]\nmass = 0.63\ninertia = [4.0e-4, 4.0e-4, 7.9e-8]\n");
    std::fs::write(&scene, text).unwrap();
    let trace = dir.path().join("trace.csv");
    std::fs::write(&trace, "the earlier trace\n").unwrap();
    let child = Command::new(env!("CARGO_BIN_EXE_kinrepro"))
        .args(["run", "--solver", "dynamic", "--force", "--trace"])
        .args([&trace, &scene])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    wait_for_temporary(dir.path());
    let pid = child.id().to_string();
    let kill =
        |sig: &str| assert!(Command::new("kill").args([sig, &pid]).status().unwrap().success());
    if together {
        kill("-STOP");
    }
    for s in signals {
        kill(&format!("-{s}"));
    }
    if together {
        kill("-CONT");
    }
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert!(hidden(dir.path()).is_empty(), "{signals:?} left {:?}: {err}", hidden(dir.path()));
    let now = std::fs::read(&trace).unwrap();
    assert!(now == b"the earlier trace\n", "{signals:?}: FILE now {} bytes: {err}", now.len());
    (out.status.code().unwrap_or(-1), err)
}

#[test]
fn signal_during_a_trace_leaves_no_temporary_and_the_old_trace() {
    for (signal, code) in [("TERM", 143), ("INT", 130)] {
        let (rc, err) = interrupted_trace(&[signal], false);
        assert_eq!(rc, code, "SIG{signal}: {err}");
        assert!(err.contains("interrupted"), "{err}");
    }
}

#[test]
fn a_second_signal_exits_at_once_and_still_removes_the_temporary() {
    // SIGINT then SIGTERM delivered together: the second stops the process
    // without unwinding (`kinrepro: SIGTERM: stopped`), unless the run
    // unwound first; either way no temporary is left. The hard exit must
    // happen in one of a few tries, else this tests nothing.
    let mut hard = 0;
    for _ in 0..5 {
        let (rc, err) = interrupted_trace(&["INT", "TERM"], true);
        assert!(rc == 130 || rc == 143, "{rc}: {err}");
        hard += usize::from(err.contains("SIGTERM: stopped"));
    }
    assert!(hard > 0, "the second signal never stopped the run itself");
}

#[test]
fn overlapping_balls_are_refused() {
    // Balls 120 deg apart on an 80 mm circle are 80 sqrt(3)/2 = 69.28 mm
    // apart: 79 mm balls (the case) and 69.3 mm ones overlap,
    // 69.2 mm ones do not.
    let dir = tempfile::tempdir().unwrap();
    let limit = 0.080 * 3f64.sqrt() / 2.0;
    for (d, overlap) in [(0.079, true), (limit * 1.0005, true), (limit * 0.9995, false)] {
        let text = std::fs::read_to_string(common::scene("04_maxwell_balls_steel.toml")).unwrap();
        let from = "ball_diameter = 0.008 ";
        assert!(text.contains(from));
        let p = dir.path().join("balls.toml");
        std::fs::write(&p, text.replace(from, &format!("ball_diameter = {d} "))).unwrap();
        let (rc, _, err) = run_in(dir.path(), &["check", "balls.toml"]);
        if overlap {
            assert_eq!(rc, 1, "{d}: {err}");
            assert!(err.contains("balls.toml") && err.contains("coupling.ball_diameter"), "{err}");
            assert!(err.contains("the balls overlap"), "{err}");
        } else {
            assert!(!err.contains("overlap"), "{d}: {err}");
        }
    }
}

/// `report --out` and `calibrate --out` into /dev/null (or a link to it)
/// with --force write through and leave the device; without --force they
/// refuse, naming it. A link to a regular file is replaced at its target.
#[test]
fn report_and_calibrate_outputs_never_replace_a_device() {
    use std::os::unix::fs::FileTypeExt;
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path();
    std::fs::copy(common::scene("02_maxwell_pins_steel.toml"), d.join("s.toml")).unwrap();
    let (rc, json, err) = run_in(d, &["study", "s.toml", "--format", "json"]);
    assert_eq!(rc, 0, "{err}");
    std::fs::write(d.join("s.json"), json).unwrap();
    std::os::unix::fs::symlink("/dev/null", d.join("null_link")).unwrap();
    std::fs::write(d.join("real.html"), "old").unwrap();
    std::os::unix::fs::symlink("real.html", d.join("html_link")).unwrap();
    let measured = Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/calibration/measured_02.csv");
    let m = measured.to_str().unwrap();
    fn report(out: &str) -> Vec<&str> {
        vec!["report", "s.json", "--out", out]
    }
    let calibrate = |out: &'static str| {
        vec!["calibrate", "s.toml", "--measured", m, "--model-samples", "100", "--out", out]
    };
    for out in ["/dev/null", "null_link"] {
        for mut args in [report(out), calibrate(out)] {
            let (rc, _, err) = run_in(d, &args);
            assert_eq!(rc, 1, "{args:?}: {err}");
            assert!(err.contains(out) && err.contains("--force"), "{args:?}: {err}");
            args.push("--force");
            let (rc, _, err) = run_in(d, &args);
            assert_eq!(rc, 0, "{args:?}: {err}");
            let t = std::fs::symlink_metadata("/dev/null").unwrap().file_type();
            assert!(t.is_char_device(), "{args:?} replaced /dev/null");
        }
    }
    assert!(std::fs::symlink_metadata(d.join("null_link")).unwrap().file_type().is_symlink());
    let (rc, _, err) = run_in(d, &["report", "s.json", "--out", "html_link", "--force"]);
    assert_eq!(rc, 0, "{err}");
    assert!(std::fs::symlink_metadata(d.join("html_link")).unwrap().file_type().is_symlink());
    assert!(std::fs::read_to_string(d.join("real.html")).unwrap().contains("<html"));
    assert!(hidden(d).is_empty(), "{:?}", hidden(d));
}

/// A run blocked opening a FIFO that has no reader (`--trace FIFO
/// --force`), whose stderr reader has gone away, still stops 3 s after
/// SIGTERM (the grace period): the stop's message to the closed stderr
/// must not end the thread that exits. Waits at most 20 s.
#[test]
fn a_run_blocked_on_a_fifo_stops_after_sigterm_with_stderr_closed() {
    use std::process::{Command, Stdio};
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("trace.fifo");
    assert!(Command::new("mkfifo").arg(&fifo).status().unwrap().success());
    let scene = variant(dir.path(), "s.toml", &[]);
    let mut child = Command::new(env!("CARGO_BIN_EXE_kinrepro"))
        .args(["run", "--solver", "dynamic", "--force", "--trace"])
        .args([&fifo, &scene])
        .stdout(Stdio::null())
        .stderr(Stdio::piped())
        .spawn()
        .unwrap();
    // The reader of its stderr dies.
    drop(child.stderr.take());
    std::thread::sleep(std::time::Duration::from_millis(500));
    let pid = child.id().to_string();
    assert!(Command::new("kill").args(["-TERM", &pid]).status().unwrap().success());
    let start = std::time::Instant::now();
    let status = loop {
        if let Some(s) = child.try_wait().unwrap() {
            break Some(s);
        }
        if start.elapsed().as_secs() > 20 {
            let _ = child.kill();
            let _ = child.wait();
            break None;
        }
        std::thread::sleep(std::time::Duration::from_millis(50));
    };
    let status = status.expect("still running 20 s after SIGTERM");
    assert_eq!(status.code(), Some(143), "{status:?}");
}
