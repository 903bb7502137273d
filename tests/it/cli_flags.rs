//! Every flag checked by the command line's one place of checks
//! (src/bin/kinrepro/flags/high.rs): a bad value, or flags that do not go
//! together, fail before anything runs, with one line `error: ...` that
//! names the flag.

use crate::common::{kinrepro, scene};

#[test]
fn a_bad_value_of_each_checked_flag_is_one_line_naming_it() {
    let s01 = scene("01_maxwell_vgroove_steel.toml");
    let s02 = scene("02_maxwell_pins_steel.toml");
    let (s01, s02) = (s01.to_str().unwrap(), s02.to_str().unwrap());
    let history = std::env::temp_dir().join("kinrepro_cli_flags_history.csv");
    std::fs::write(&history, "P_N,Qx_N,Qy_N\n10,0,0\n").unwrap();
    let history = history.to_str().unwrap();
    let contact = [
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
        "10",
    ];
    let with_history = |extra: &[&'static str]| -> Vec<&str> {
        // Without --load: --history takes the normal loads from its file.
        let mut v: Vec<&str> = contact[..contact.len() - 2].to_vec();
        v.extend(["--history", history]);
        v.extend(extra);
        v
    };
    // (arguments, the flag the error names)
    let cases: Vec<(Vec<&str>, &str)> = vec![
        (with_history(&["--mu", "-0.2"]), "--mu"),
        (with_history(&["--mu", "0.2", "--dynamic-ratio", "1.5"]), "--dynamic-ratio"),
        ([&contact[..8], &["unobtainium", "--load", "10"]].concat(), "--material2"),
        (vec!["run", s01, "--increments", "0"], "--increments"),
        (vec!["run", s01, "--trace", "t.csv"], "--trace"),
        (vec!["run", s01, "--solver", "dynamic", "--offset", "0,1e-6"], "--offset"),
        (vec!["run", s01, "--solver", "dynamic", "--tilt", "0"], "--tilt"),
        (vec!["stiffness", s01, "--at", "0,0"], "--at"),
        (vec!["stiffness", s01, "--at", "0,nan,0"], "--at"),
        (vec!["load", s01, "--force", "1,0", "--at", "0,0,0"], "--force"),
        (vec!["load", s01, "--force", "1,0,0", "--at", "inf,0,0"], "--at"),
        (vec!["load", s01, "--force", "1,0,0", "--at", "0,0,0", "--moment", "1"], "--moment"),
        (vec!["load", s01, "--force", "0,0,0", "--at", "0,0,0"], "--force"),
        (vec!["study", s01, "--increments", "100001"], "--increments"),
        (vec!["study", s01, "--jobs", "0"], "--jobs"),
        (vec!["study", s01, "--sampler", "corners", "--samples", "8"], "--samples"),
        (vec!["study", s01, "--offset-bounds", "0,0,1e-6"], "--offset-bounds"),
        (
            vec!["study", s01, "--solver", "dynamic", "--vary", "start", "--tilt-bounds", "0,-1,0"],
            "--tilt-bounds",
        ),
        (
            vec!["study", s01, "--solver", "dynamic", "--vary", "start", "--offset-bounds", "1,1"],
            "--offset-bounds",
        ),
        (vec!["study", s01, "--sensitivity", "--sobol-samples", "1"], "--sobol-samples"),
        (vec!["sweep", s01, "--set", "preload.force=5,10", "--increments", "0"], "--increments"),
        (vec!["sweep", s01, "--set", "preload.force=5,10", "--points", "4"], "--points"),
        (vec!["sweep", s01, "--set", "preload.force=5:10", "--design", "lhs"], "--design"),
        (vec!["sweep", s01, "--set", "preload.force=5,10", "--jobs", "0"], "--jobs"),
        (
            vec![
                "sweep",
                s01,
                "--set",
                "preload.force=5,10",
                "--sampler",
                "corners",
                "--samples",
                "8",
            ],
            "--samples",
        ),
        (vec!["validate-hertz", s01, "--convergence", "0.3,-0.2"], "--convergence"),
        (vec!["calibrate", s02, "--measured", "m.csv", "--model-samples", "99"], "--model-samples"),
        (vec!["calibrate", s02, "--measured", "m.csv", "--noise", "x=1parsec"], "--noise"),
        (vec!["calibrate", s02, "--measured", "m.csv", "--delimiter", ";;"], "--delimiter"),
        (vec!["calibrate", s02, "--measured", "m.csv", "--jobs", "0"], "--jobs"),
        (vec!["predict", s02, "--calibration", "c.json", "--samples", "10"], "--samples"),
        (vec!["predict", s02, "--calibration", "c.json", "--jobs", "0"], "--jobs"),
    ];
    for (args, flag) in &cases {
        let (ok, out, err) = kinrepro(args);
        let lines: Vec<&str> = err.lines().collect();
        assert!(!ok && out.is_empty(), "{args:?} succeeded: {out}");
        assert_eq!(lines.len(), 1, "{args:?}: {err}");
        assert!(
            lines[0].starts_with("error: ") && lines[0].contains(flag),
            "{args:?} should name {flag}: {err}"
        );
    }
}

/// `report --help` states where a report reads the studies' scenes from
/// (the current folder or the JSON's, nowhere else), as docs/guide-studies.md does.
#[test]
fn report_help_states_the_folder_rule() {
    let (ok, out, _) = kinrepro(&["report", "--help"]);
    assert!(ok);
    let text = out.split_whitespace().collect::<Vec<_>>().join(" ");
    assert!(text.contains("only from the current folder or the JSON's folder"), "{out}");
    assert!(text.contains("a scene elsewhere is refused"), "{out}");
}
