//! Output files, signals, size bounds and panics (issue 28 items 1-2).

use std::fs;
use std::io::Read;
use std::os::unix::fs::FileTypeExt;
use std::path::Path;
use std::process::{Command, Stdio};

use crate::common;

const SCENE: &str = "01_maxwell_vgroove_steel.toml";

fn scene() -> String {
    common::scene(SCENE).display().to_string()
}

/// The names in `dir` that start with a dot (the temporaries of atomic writes).
pub(crate) fn hidden(dir: &Path) -> Vec<String> {
    fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with('.'))
        .collect()
}

/// Wait until a run writes into a temporary in `dir` (at most 60 s), and
/// 300 ms more, so that a signal sent next meets the write under way.
pub(crate) fn wait_for_temporary(dir: &Path) {
    let start = std::time::Instant::now();
    while hidden(dir).is_empty() {
        assert!(start.elapsed().as_secs() < 60, "no temporary appeared");
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    std::thread::sleep(std::time::Duration::from_millis(300));
}

fn mkfifo(path: &Path) {
    let ok = Command::new("mkfifo").arg(path).status().unwrap().success();
    assert!(ok, "mkfifo {}", path.display());
}

/// Read a FIFO to its end on a thread (the writer's open blocks until then).
fn drain(path: &Path) -> std::thread::JoinHandle<String> {
    let path = path.to_path_buf();
    std::thread::spawn(move || {
        let mut s = String::new();
        fs::File::open(path).unwrap().read_to_string(&mut s).unwrap();
        s
    })
}

#[test]
fn html_into_dev_null_keeps_the_device() {
    let (ok, _, err) = common::kinrepro(&["study", &scene(), "--html", "/dev/null"]);
    assert!(!ok, "a device without --force is refused");
    assert!(
        err.contains("/dev/null") && err.contains("character device") && err.contains("--force"),
        "{err}"
    );
    let (ok, _, err) = common::kinrepro(&["study", &scene(), "--html", "/dev/null", "--force"]);
    assert!(ok, "{err}");
    let t = fs::symlink_metadata("/dev/null").unwrap().file_type();
    assert!(t.is_char_device(), "/dev/null is still a character device");
}

#[test]
fn trace_to_dev_stdout_writes_to_stdout() {
    let (ok, out, err) = common::kinrepro(&[
        "run",
        &scene(),
        "--solver",
        "dynamic",
        "--trace",
        "/dev/stdout",
        "--force",
    ]);
    assert!(ok, "{err}");
    assert!(out.contains("\ntime_s,load_fraction,x_m"), "the trace header on stdout");
    let rows = out.lines().filter(|l| l.starts_with(|c: char| c.is_ascii_digit())).count();
    assert!(rows > 100, "the trace rows on stdout: {rows}");
    assert!(fs::symlink_metadata("/dev/stdout").unwrap().file_type().is_symlink());
}

#[test]
fn symlink_to_a_regular_file_is_replaced_at_its_target() {
    let dir = tempfile::tempdir().unwrap();
    let real = dir.path().join("real.html");
    let link = dir.path().join("link.html");
    fs::write(&real, "old").unwrap();
    std::os::unix::fs::symlink("real.html", &link).unwrap();
    let l = link.display().to_string();
    let (ok, _, err) = common::kinrepro(&["study", &scene(), "--html", &l]);
    assert!(!ok && err.contains("exists"), "an existing target needs --force: {err}");
    let (ok, _, err) = common::kinrepro(&["study", &scene(), "--html", &l, "--force"]);
    assert!(ok, "{err}");
    assert!(fs::symlink_metadata(&link).unwrap().file_type().is_symlink(), "the link stays");
    let text = fs::read_to_string(&real).unwrap();
    assert!(text.contains("<html"), "the target holds the report");
    assert!(hidden(dir.path()).is_empty(), "no temporary left");
}

#[test]
fn dangling_symlink_creates_its_target() {
    let dir = tempfile::tempdir().unwrap();
    let link = dir.path().join("link.html");
    std::os::unix::fs::symlink("new.html", &link).unwrap();
    let l = link.display().to_string();
    let (ok, _, err) = common::kinrepro(&["study", &scene(), "--html", &l]);
    assert!(ok, "{err}");
    assert!(fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
    assert!(fs::read_to_string(dir.path().join("new.html")).unwrap().contains("<html"));
}

#[test]
fn fifo_and_link_to_fifo_are_written_through() {
    let dir = tempfile::tempdir().unwrap();
    let fifo = dir.path().join("trace.fifo");
    let link = dir.path().join("trace.link");
    mkfifo(&fifo);
    std::os::unix::fs::symlink("trace.fifo", &link).unwrap();
    let f = fifo.display().to_string();
    let (ok, _, err) = common::kinrepro(&["run", &scene(), "--solver", "dynamic", "--trace", &f]);
    assert!(!ok && err.contains("FIFO") && err.contains("--force"), "{err}");
    for path in [&fifo, &link] {
        let reader = drain(&fifo);
        let p = path.display().to_string();
        let args = ["run", &scene(), "--solver", "dynamic", "--trace", &p, "--force"];
        let (ok, _, err) = common::kinrepro(&args);
        assert!(ok, "{err}");
        let text = reader.join().unwrap();
        assert!(text.contains("\ntime_s,load_fraction"), "the trace went through {p}");
        assert!(fs::symlink_metadata(&fifo).unwrap().file_type().is_fifo());
    }
    assert!(fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
    assert!(hidden(dir.path()).is_empty(), "no temporary left");
}

#[test]
fn folder_as_output_file_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path().display().to_string();
    let (ok, _, err) = common::kinrepro(&["study", &scene(), "--html", &d, "--force"]);
    assert!(!ok && err.contains("is a folder"), "{err}");
    assert!(dir.path().is_dir());
}

/// The name and content of every file in `dir`.
fn contents(dir: &Path) -> Vec<(String, Vec<u8>)> {
    let mut v: Vec<_> = fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap())
        .map(|e| (e.file_name().to_string_lossy().into_owned(), fs::read(e.path()).unwrap()))
        .collect();
    v.sort();
    v
}

/// A signal during a streamed `study --out DIR --force` (its per-sample
/// CSV under a temporary name in DIR) leaves DIR as it was, without a
/// temporary, and exits 128 + the signal: SIGTERM and SIGINT, and SIGHUP
/// (a closed terminal), SIGQUIT, SIGUSR1 and SIGUSR2 the same way.
#[test]
fn signal_during_study_leaves_out_folder_as_it_was() {
    let signals = [("TERM", 143), ("INT", 130), ("HUP", 129), ("QUIT", 131), ("USR1", 138)];
    for (signal, code) in signals.into_iter().chain([("USR2", 140)]) {
        let dir = tempfile::tempdir().unwrap();
        let d = dir.path().display().to_string();
        let small = ["study", &scene(), "--sampler", "mc", "--samples", "40", "--out", &d];
        let (ok, _, err) = common::kinrepro(&small);
        assert!(ok, "{err}");
        let before = contents(dir.path());
        assert!(before.len() >= 2 && hidden(dir.path()).is_empty());
        let child = Command::new(env!("CARGO_BIN_EXE_kinrepro"))
            .args(["study", &scene(), "--sampler", "mc", "--samples", "3000000"])
            .args(["--out", &d, "--force"])
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // Wait until the run streams its samples into its temporary.
        wait_for_temporary(dir.path());
        let pid = child.id().to_string();
        let sent = Command::new("kill").args([&format!("-{signal}"), &pid]).status();
        assert!(sent.unwrap().success());
        let out = child.wait_with_output().unwrap();
        let err = String::from_utf8_lossy(&out.stderr);
        assert_eq!(out.status.code(), Some(code), "SIG{signal}: {err}");
        assert!(err.contains("interrupted"), "{err}");
        assert!(hidden(dir.path()).is_empty(), "SIG{signal} left {:?}", hidden(dir.path()));
        assert!(contents(dir.path()) == before, "SIG{signal}: the earlier files are intact");
    }
}

/// A signal during `sweep --out DIR --html FILE --force` leaves DIR and
/// FILE as an earlier sweep wrote them (no output of interrupted design
/// points, no "wrote"), without a temporary, and exits 128 + the signal.
#[test]
fn signal_during_sweep_leaves_its_outputs_as_they_were() {
    for (signal, code) in [("TERM", 143), ("INT", 130), ("HUP", 129)] {
        let dir = tempfile::tempdir().unwrap();
        let out = dir.path().join("charts");
        let html = dir.path().join("sweep.html");
        let (o, h) = (out.display().to_string(), html.display().to_string());
        let base = ["sweep", &scene(), "--set", "preload.force=10,20", "--sampler", "mc"];
        let files = ["--out", &o, "--html", &h];
        let (ok, _, err) =
            common::kinrepro(&[&base[..], &["--samples", "10"], &files[..]].concat());
        assert!(ok, "{err}");
        let (charts, page) = (contents(&out), fs::read(&html).unwrap());
        assert!(!charts.is_empty());
        let child = Command::new(env!("CARGO_BIN_EXE_kinrepro"))
            .args([&base[..], &["--samples", "2000000"], &files[..], &["--force"]].concat())
            .stdout(Stdio::null())
            .stderr(Stdio::piped())
            .spawn()
            .unwrap();
        // The run is under way well before its 4 million seatings end.
        std::thread::sleep(std::time::Duration::from_millis(1500));
        let pid = child.id().to_string();
        let sent = Command::new("kill").args([&format!("-{signal}"), &pid]).status();
        assert!(sent.unwrap().success());
        let done = child.wait_with_output().unwrap();
        let err = String::from_utf8_lossy(&done.stderr);
        assert_eq!(done.status.code(), Some(code), "SIG{signal}: {err}");
        assert!(err.contains("interrupted") && !err.contains("wrote"), "{err}");
        assert!(hidden(&out).is_empty() && hidden(dir.path()).is_empty(), "SIG{signal}");
        assert!(contents(&out) == charts, "SIG{signal}: the earlier charts are intact");
        assert!(fs::read(&html).unwrap() == page, "SIG{signal}: the earlier page is intact");
    }
}

/// A run killed outright (SIGKILL) leaves its temporary; the next run
/// writing the same output names it (modified before that run started),
/// and `kinrepro clean DIR` removes it once untouched for a minute, while
/// keeping a fresh one (a live run's) and every other file.
#[test]
fn a_killed_runs_temporaries_are_named_and_cleaned() {
    let dir = tempfile::tempdir().unwrap();
    let d = dir.path().display().to_string();
    let mut child = Command::new(env!("CARGO_BIN_EXE_kinrepro"))
        .args(["study", &scene(), "--sampler", "mc", "--samples", "3000000", "--out", &d])
        .stdout(Stdio::null())
        .stderr(Stdio::null())
        .spawn()
        .unwrap();
    wait_for_temporary(dir.path());
    child.kill().unwrap();
    child.wait().unwrap();
    let left = hidden(dir.path());
    assert_eq!(left.len(), 1, "{left:?}");
    assert!(left[0].contains(".kinrepro-") && left[0].ends_with(".tmp"), "{left:?}");
    let (ok, _, err) =
        common::kinrepro(&["study", &scene(), "--samples", "10", "--out", &d, "--force"]);
    assert!(ok, "{err}");
    assert!(err.contains(&left[0]) && err.contains("kinrepro clean"), "{err}");
    // Untouched for two hours, as after a night: removed; a fresh one kept.
    let stale = dir.path().join(&left[0]);
    let aged = Command::new("touch").args(["-d", "2 hours ago"]).arg(&stale).status();
    assert!(aged.unwrap().success());
    let fresh = dir.path().join(".other.csv.kinrepro-abcdef.tmp");
    fs::write(&fresh, "in use").unwrap();
    let before = contents(dir.path()).len();
    let (ok, out, err) = common::kinrepro(&["clean", &d]);
    assert!(ok, "{err}");
    assert!(out.contains("removed") && out.contains(&left[0]), "{out}");
    assert!(err.contains("kept") && err.contains(".other.csv.kinrepro-abcdef.tmp"), "{err}");
    assert!(!stale.exists() && fresh.exists());
    assert_eq!(contents(dir.path()).len(), before - 1);
}

/// A 1 GB history file (sparse: zeros) is refused at the input-file
/// bound before it is read: in well under a second, in bounded memory.
#[test]
fn huge_history_file_is_refused_at_its_size_bound() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("history.csv");
    fs::File::create(&path).unwrap().set_len(1 << 30).unwrap();
    let p = path.display().to_string();
    let start = std::time::Instant::now();
    let (ok, _, err) = common::kinrepro(&[
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
        "0.3",
        "--history",
        &p,
    ]);
    let seconds = start.elapsed().as_secs_f64();
    assert!(!ok, "refused");
    assert!(err.contains(&p) && err.contains("1073741824 bytes"), "{err}");
    assert!(err.contains(&kinrepro::input::MAX_INPUT_BYTES.to_string()), "{err}");
    assert!(seconds < 0.5, "refused in {seconds} s");
}

/// `--sobol-samples 2^64 - 1`: N (d + 2) overflows; a clear error naming the
/// option and the bound, not a panic.
#[test]
fn sobol_samples_beyond_memory_is_a_clear_error() {
    for n in ["18446744073709551615", "10000000"] {
        let args = ["study", &scene(), "--sensitivity", "--sobol-samples", n];
        let (ok, _, err) = common::kinrepro(&args);
        assert!(!ok && !err.contains("panicked"), "{err}");
        let bound = kinrepro::study::bounds::MAX_KEPT_SEATINGS.to_string();
        assert!(err.starts_with("error: --sobol-samples:") && err.contains(&bound), "{err}");
    }
}

/// `predict --samples 1e9`, `calibrate --model-samples 1e9` and a sweep of
/// 1e9 Monte Carlo samples per point keep their records: each is refused
/// at the bound before anything is drawn (it grew to gigabytes before).
#[test]
fn studies_that_keep_their_records_are_bounded() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let s02 = root.join("scenes/02_maxwell_pins_steel.toml");
    let cal = root.join("docs/calibration/calibration_02.json");
    let measured = root.join("docs/calibration/measured_02.csv");
    let (s02, cal, measured) =
        (s02.to_str().unwrap(), cal.to_str().unwrap(), measured.to_str().unwrap());
    let bound = kinrepro::study::bounds::MAX_KEPT_SEATINGS.to_string();
    let s01 = scene();
    let cases: [&[&str]; 3] = [
        &["predict", s02, "--calibration", cal, "--samples", "1000000000"],
        &["calibrate", s02, "--measured", measured, "--model-samples", "1000000000"],
        &[
            "sweep",
            &s01,
            "--set",
            "preload.force=10,20",
            "--sampler",
            "mc",
            "--samples",
            "1000000000",
        ],
    ];
    for args in cases {
        let (ok, out, err) = common::kinrepro(args);
        assert!(!ok && !err.contains("panicked"), "{args:?}: {err}");
        assert!((out + &err).contains(&bound), "{args:?}: {err}");
    }
}

/// `--convergence 1e-300` asks for an infinite mesh, 0.001 for 1.8e10
/// nodes: both refused before any FE solve, naming the option.
#[test]
fn convergence_mesh_beyond_memory_is_a_clear_error() {
    for level in ["1e-300", "0.001"] {
        let start = std::time::Instant::now();
        let (ok, _, err) = common::kinrepro(&["validate-hertz", "--convergence", level]);
        assert!(!ok && !err.contains("panicked"), "{err}");
        assert!(err.starts_with("error: --convergence:") && err.contains("nodes"), "{err}");
        assert!(start.elapsed().as_secs_f64() < 5.0, "refused before any solve");
    }
}

/// The node estimate behind the FE bound counts the nodes of the mesh
/// actually built (circular contact, a = 1), at several element sizes.
#[test]
fn mesh_node_estimate_counts_the_built_mesh() {
    use kinrepro::fe::MeshOptions;
    for rel in [0.3, 0.18, 0.12, 0.07] {
        let opt = MeshOptions { element_size_rel: rel, ..MeshOptions::default() };
        let mesh = kinrepro::fe::validate::build_mesh(1.0, 1.0, &opt).unwrap();
        let built = mesh.nodes.len() as f64;
        let est = opt.estimated_nodes();
        assert!((est / built - 1.0).abs() < 0.25, "h = {rel}: estimate {est}, built {built}");
    }
}

/// A tiny `[dynamics]` inertia makes dt tiny against the settling time: the
/// dynamic seating is refused at its step bound at once, naming the table.
#[test]
fn tiny_inertia_is_refused_at_the_dynamic_step_bound() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("tiny_inertia.toml");
    let mut text = fs::read_to_string(common::scene(SCENE)).unwrap();
    text.push_str("\n[dynamics]\nmass = 0.63\ninertia = [1e-12, 1e-12, 1e-12]\n");
    fs::write(&path, text).unwrap();
    let p = path.display().to_string();
    let start = std::time::Instant::now();
    let (ok, _, err) = common::kinrepro(&["run", &p, "--solver", "dynamic"]);
    assert!(!ok && err.contains("[dynamics]") && err.contains("inertia"), "{err}");
    let bound = kinrepro::solve::dynamic::MAX_STEPS.to_string();
    assert!(err.contains(&p) && err.contains(&bound), "{err}");
    assert!(start.elapsed().as_secs_f64() < 5.0, "refused before stepping");
}

/// A run estimated above a minute says so before it starts: 2e6
/// quasi-static seatings at 50 us on one core are 100 s (announced), 1e6
/// are 50 s (not); two threads halve the estimate.
#[test]
fn long_runs_announce_their_estimate() {
    use kinrepro::solve::Method;
    use kinrepro::study::bounds::estimate_note;
    let qs = Method::default();
    let note = estimate_note(2_000_000, &qs, 1).expect("100 s is announced");
    assert!(note.contains("2000000 seatings") && note.contains("2 min"), "{note}");
    assert!(estimate_note(1_000_000, &qs, 1).is_none());
    assert!(estimate_note(2_000_000, &qs, 2).is_none(), "50 s on two threads");
}

/// 101 evaluation points are refused at the 101st, naming the field and the
/// bound; 100 load.
#[test]
fn evaluation_points_are_bounded() {
    let dir = tempfile::tempdir().unwrap();
    let base = std::fs::read_to_string(scene()).unwrap();
    let bound = kinrepro::scene::resolve::points::MAX_EVALUATION_POINTS;
    for n in [bound, bound + 1] {
        let mut text = base.clone();
        for i in 0..n {
            let x = i as f64 * 1e-4;
            text +=
                &format!("\n[[evaluation_points]]\nname = \"p{i}\"\nposition = [{x}, 0.0, 0.0]\n");
        }
        let p = dir.path().join(format!("s{n}.toml"));
        std::fs::write(&p, text).unwrap();
        let (ok, _, err) = common::kinrepro(&["check", p.to_str().unwrap()]);
        if n == bound {
            assert!(ok, "{err}");
        } else {
            assert!(!ok, "{err}");
            let field = format!("evaluation_points[{}]", bound + 1);
            assert!(err.contains(&field) && err.contains(&format!("at most {bound}")), "{err}");
        }
    }
}

/// An output that is an input of the same command is refused, `--force`
/// or not, by any path to it (its own, a symbolic link, a hard link), and
/// the input is left as it was: the scene under `study --html` and
/// `sweep --html`, the study JSON under `report --out`.
#[test]
fn an_output_onto_an_input_of_the_same_command_is_refused() {
    let dir = tempfile::tempdir().unwrap();
    let s = dir.path().join("s.toml");
    fs::copy(scene(), &s).unwrap();
    let (link, hard) = (dir.path().join("link.toml"), dir.path().join("hard.toml"));
    std::os::unix::fs::symlink(&s, &link).unwrap();
    fs::hard_link(&s, &hard).unwrap();
    let text = fs::read(&s).unwrap();
    let path = |p: &Path| p.display().to_string();
    let scene_path = path(&s);
    for out in [&s, &link, &hard] {
        for cmd in [["study", "--samples", "10"], ["sweep", "--set", "preload.force=10,20"]] {
            let out = path(out);
            let args = [cmd[0], &scene_path, cmd[1], cmd[2], "--html", &out, "--force"];
            let (ok, _, err) = common::kinrepro(&args);
            assert!(!ok, "{args:?}");
            assert!(err.contains("is an input of this command") && err.contains("s.toml"), "{err}");
            assert_eq!(fs::read(&s).unwrap(), text, "{args:?} kept the scene");
        }
    }
    let json = dir.path().join("in.json");
    let (ok, study, err) =
        common::kinrepro(&["study", &path(&s), "--samples", "10", "--format", "json"]);
    assert!(ok, "{err}");
    fs::write(&json, &study).unwrap();
    let (ok, _, err) =
        common::kinrepro(&["report", &path(&json), "--out", &path(&json), "--force"]);
    assert!(!ok && err.contains("is an input of this command"), "{err}");
    assert_eq!(fs::read_to_string(&json).unwrap(), study);
    // Another file is written as before.
    let html = path(&dir.path().join("report.html"));
    let (ok, _, err) = common::kinrepro(&["report", &path(&json), "--out", &html]);
    assert!(ok, "{err}");
}
