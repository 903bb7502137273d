//! An optimisation's searches (combinations of listed values x starts):
//! shards of them merge to the single run byte for byte; the starts beyond
//! the centre are a Latin hypercube of the box; search 1 is the
//! single-start search, so more starts are never worse; refusals name
//! what they refuse.

use crate::common::{kinrepro, scene};

const VARY: [&str; 4] =
    ["--vary", "preload.force=5:40", "--vary", "coupling.ball_diameter=0.006:0.016"];

/// `kinrepro optimize` of scene 01 with `args` (k_min:max under a bound on
/// sigma_x, 10 Monte Carlo samples): (success, stdout, stderr).
fn run(args: &[&str]) -> (bool, String, String) {
    let s = scene("01_maxwell_vgroove_steel.toml");
    let base = [
        "optimize",
        s.to_str().unwrap(),
        "--objective",
        "k_min:max",
        "--constraint",
        "sigma:centre:x<=5e-9",
        "--sampler",
        "mc",
        "--samples",
        "10",
        "--seed",
        "3",
        "--max-iterations",
        "30",
    ];
    kinrepro(&[&base[..], args].concat())
}

fn json(args: &[&str]) -> serde_json::Value {
    let (ok, out, err) = run(args);
    assert!(ok, "{err}");
    serde_json::from_str(&out).unwrap()
}

/// Two materials x two starts = four searches, in 3 and in 5 shards (one
/// of them empty): `kinrepro merge` prints the single run's JSON.
#[test]
fn shards_merge_to_the_single_run_byte_for_byte() {
    let materials = ["--vary", "coupling.ball_material=steel,silicon-carbide", "--starts", "2"];
    let args = [&VARY[..], &materials[..], &["--json"]].concat();
    let (ok, whole, err) = run(&args);
    assert!(ok, "{err}");
    let doc: serde_json::Value = serde_json::from_str(&whole).unwrap();
    assert_eq!(doc["searches"], 4);
    assert_eq!(doc["termination"].as_array().unwrap().len(), 4);
    let dir = tempfile::tempdir().unwrap();
    for n in [3, 5] {
        let mut parts = Vec::new();
        for i in 1..=n {
            let shard = format!("{i}/{n}");
            let (ok, out, err) = run(&[&args[..], &["--shard", &shard]].concat());
            assert!(ok, "shard {shard}: {err}");
            let part = dir.path().join(format!("part-{n}-{i}.json"));
            std::fs::write(&part, out).unwrap();
            parts.push(part.to_str().unwrap().to_string());
        }
        // Any order of the parts.
        parts.reverse();
        let merge: Vec<&str> =
            std::iter::once("merge").chain(parts.iter().map(|p| &p[..])).collect();
        let (ok, merged, err) = kinrepro(&merge);
        assert!(ok, "{err}");
        assert_eq!(merged, whole, "{n} shards");
        // A missing shard is named.
        let (ok, _, err) = kinrepro(&merge[..merge.len() - 1]);
        assert!(!ok && err.contains("shard 1/"), "{err}");
    }
    // A part of another optimisation (one more constraint) is refused,
    // naming the field.
    let other = dir.path().join("other.json");
    let (ok, out, err) = run(&[&args[..], &["--shard", "2/3", "--constraint", "sf_p>=1"]].concat());
    assert!(ok, "{err}");
    std::fs::write(&other, out).unwrap();
    let first = dir.path().join("part-3-1.json");
    let third = dir.path().join("part-3-3.json");
    let (ok, _, err) = kinrepro(&[
        "merge",
        first.to_str().unwrap(),
        other.to_str().unwrap(),
        third.to_str().unwrap(),
    ]);
    assert!(!ok && err.contains("constraints"), "{err}");
}

/// The unit coordinates of a candidate's fields in the two ranges of VARY.
fn unit(c: &serde_json::Value) -> [f64; 2] {
    let f = c["fields"]["preload.force"].as_f64().unwrap();
    let d = c["fields"]["coupling.ball_diameter"].as_f64().unwrap();
    [(f - 5.0) / 35.0, (d - 0.006) / 0.010]
}

/// `--starts 4`: search 1 is the single-start search (its candidates the
/// same, in the same order); searches 2 to 4 start (their first candidate,
/// the first vertex of the simplex) at three points of which every range's
/// thirds hold one each (a Latin hypercube); the optimum is the best
/// feasible candidate of all four, so no worse than the single start's.
#[test]
fn further_starts_are_a_latin_hypercube_and_never_worse() {
    let one = json(&[&VARY[..], &["--json"]].concat());
    let four = json(&[&VARY[..], &["--starts", "4", "--json"]].concat());
    assert_eq!((one["searches"].as_u64(), four["searches"].as_u64()), (Some(1), Some(4)));
    let strip = |c: &serde_json::Value| {
        let mut c = c.clone();
        c.as_object_mut().unwrap().remove("search");
        c
    };
    let history = four["history"].as_array().unwrap();
    let first: Vec<_> = history.iter().filter(|c| c["search"] == 1).map(strip).collect();
    let single: Vec<_> = one["history"].as_array().unwrap().iter().map(strip).collect();
    assert_eq!(first, single);
    let starts: Vec<[f64; 2]> = (2..=4)
        .map(|s| unit(history.iter().find(|c| c["search"] == s).expect("a search's candidates")))
        .collect();
    let centre = unit(&history[0]);
    assert!(centre.iter().all(|u| (u - 0.5).abs() < 1e-12), "search 1 starts at {centre:?}");
    for k in 0..2 {
        let mut thirds: Vec<usize> = starts.iter().map(|u| (u[k] * 3.0) as usize).collect();
        thirds.sort_unstable();
        assert_eq!(thirds, [0, 1, 2], "range {k}: starts {starts:?}");
    }
    // The optimum is the best feasible candidate of all searches.
    let best = (history.iter())
        .filter(|c| c["feasible"] == true)
        .map(|c| c["objective"].as_f64().unwrap())
        .fold(f64::NEG_INFINITY, f64::max);
    let optimum = four["optimum"]["objective"].as_f64().unwrap();
    assert_eq!(optimum, best);
    assert!(optimum >= one["optimum"]["objective"].as_f64().unwrap());
}

#[test]
fn bad_starts_and_shards_are_refused_naming_the_flag() {
    for (args, want) in [
        (&["--starts", "0"][..], "--starts"),
        (&["--starts", "1001"][..], "--starts"),
        (&["--shard", "3/2"][..], "--shard"),
        (&["--shard", "0/2"][..], "--shard"),
    ] {
        let (ok, _, err) = run(&[&VARY[..], args].concat());
        assert!(!ok && err.contains(want), "{args:?}: {err}");
    }
}

/// A shard run on an edited scene under the same file name, or with other
/// study settings, is not a part of the same optimisation: `merge` names
/// the fingerprint's field.
#[test]
fn parts_of_an_edited_scene_or_other_settings_are_refused() {
    let dir = tempfile::tempdir().unwrap();
    let file = dir.path().join("s.toml");
    let text = std::fs::read_to_string(scene("01_maxwell_vgroove_steel.toml")).unwrap();
    let part = |text: &str, shard: &str, extra: &[&str]| {
        std::fs::write(&file, text).unwrap();
        let f = file.to_str().unwrap();
        let args = [
            &["optimize", f, "--vary", "preload.force=5:40", "--starts", "2"][..],
            &["--objective", "k_min:max", "--samples", "10", "--sampler", "mc"],
            &["--max-iterations", "10", "--shard", shard, "--json"],
            extra,
        ]
        .concat();
        let (ok, out, err) = kinrepro(&args);
        assert!(ok, "{err}");
        let p = dir.path().join(format!("part-{}-{}.json", shard.replace('/', "-"), extra.len()));
        std::fs::write(&p, out).unwrap();
        p.to_str().unwrap().to_string()
    };
    let first = part(&text, "1/2", &[]);
    let edited = text.replacen("mu_static = 0.5 ", "mu_static = 0.4 ", 1);
    assert_ne!(edited, text);
    let second = part(&edited, "2/2", &[]);
    let (ok, _, err) = kinrepro(&["merge", &first, &second]);
    assert!(!ok && err.contains("fingerprint.scene_content"), "{err}");
    let second = part(&text, "2/2", &["--path-tolerance", "1e-6"]);
    let (ok, _, err) = kinrepro(&["merge", &first, &second]);
    assert!(!ok && err.contains("fingerprint.study"), "{err}");
    let second = part(&text, "2/2", &[]);
    let (ok, _, err) = kinrepro(&["merge", &first, &second]);
    assert!(ok, "{err}");
}
