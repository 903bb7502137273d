//! Studies: determinism, sharding, symmetry of the Maxwell scatter and a
//! mean near zero, through the library and the CLI.

use crate::common::kinrepro;
use crate::common::scene;

use kinrepro::study::VariantReport;
use kinrepro::study::{Sampler, Shard, StudyOptions};

#[test]
fn same_seed_same_json_bytes_and_four_shards_merge_to_one_run() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let s1 = scene("01_maxwell_vgroove_steel.toml");
    let s6 = scene("06_kelvin_steel.toml");
    let (s1, s6) = (s1.to_str().unwrap(), s6.to_str().unwrap());
    for sampler in ["lhs", "mc"] {
        let base = [
            "study",
            s1,
            s6,
            "--samples",
            "22",
            "--seed",
            "11",
            "--sampler",
            sampler,
            "--format",
            "json",
        ];
        let (ok, one, err) = kinrepro(&base);
        assert!(ok, "{err}");
        let (_, again, _) = kinrepro(&base);
        assert_eq!(one, again, "same seed must give the same bytes");
        let (_, other, _) = kinrepro(&[
            "study",
            s1,
            s6,
            "--samples",
            "22",
            "--seed",
            "12",
            "--sampler",
            sampler,
            "--format",
            "json",
        ]);
        assert_ne!(one, other);
        let mut parts = Vec::new();
        for i in [3, 1, 4, 2] {
            let shard = format!("{i}/4");
            let mut args = base.to_vec();
            args.extend(["--shard", &shard, "--jobs", "1"]);
            let (ok, part, err) = kinrepro(&args);
            assert!(ok, "{err}");
            let f = dir.join(format!("part_{sampler}_{i}.json"));
            std::fs::write(&f, part).unwrap();
            parts.push(f.display().to_string());
        }
        let mut args = vec!["merge"];
        args.extend(parts.iter().map(|s| s.as_str()));
        let (ok, merged, err) = kinrepro(&args);
        assert!(ok, "{err}");
        assert_eq!(merged, one, "{sampler}: 4 merged shards differ from one run");
        // A missing shard is an error, not a smaller study: parts hold shards
        // 3, 1, 4, 2; without the last, shard 2 of 22 samples in 4 (6, 6, 5, 5:
        // the first 22 mod 4 shards one larger) is samples 6..11.
        let (ok, _, err) = kinrepro(&["merge", &parts[0], &parts[1], &parts[2]]);
        assert!(!ok && err.contains("shard 2/4 (samples 6..11) missing"), "{err}");
    }
}

fn maxwell_mc(name: &str, n: usize) -> VariantReport {
    let c = kinrepro::error::read_scene(&scene(name)).unwrap();
    let opts = StudyOptions {
        sampler: Some(Sampler::MonteCarlo),
        samples: Some(n),
        seed: Some(2024),
        shard: Shard::whole(),
        ..Default::default()
    };
    crate::common::report(&crate::common::plan(vec![c], &opts))
}

#[test]
fn maxwell_scatter_is_symmetric_in_x_y_and_centred() {
    for name in [
        "01_maxwell_vgroove_steel.toml",
        "02_maxwell_pins_steel.toml",
        "03_maxwell_pins_sic.toml",
        "04_maxwell_balls_steel.toml",
        "05_maxwell_balls_sic.toml",
    ] {
        let v = maxwell_mc(name, 2000);
        let p = &v.points[0];
        let s = p.sigma;
        assert!(
            (s.x_nm / s.y_nm - 1.0).abs() < 0.05,
            "{name}: sigma_x {} sigma_y {}",
            s.x_nm,
            s.y_nm
        );
        assert!(
            (s.phi_x_nrad / s.phi_y_nrad - 1.0).abs() < 0.05,
            "{name}: {} {}",
            s.phi_x_nrad,
            s.phi_y_nrad
        );
        // sigma_z below sigma_x and sigma_y, the paper's trend (docs/paper.md, "What agrees").
        assert!(s.z_nm < s.x_nm.min(s.y_nm));
        // Mean displacement relative to nominal is small against sigma.
        let m = p.mean.values();
        let sg = s.values();
        for k in 0..5 {
            assert!(m[k].abs() < 0.5 * sg[k], "{name} dof {k}: mean {} sigma {}", m[k], sg[k]);
        }
    }
}

#[test]
fn table_csv_and_plots_are_written() {
    let tmp = tempfile::tempdir().unwrap();
    let dir = tmp.path();
    let s1 = scene("01_maxwell_vgroove_steel.toml");
    let (ok, table, err) =
        kinrepro(&["study", s1.to_str().unwrap(), "--out", dir.to_str().unwrap()]);
    assert!(ok, "{err}");
    assert!(
        table.contains("sigma_x [nm]")
            && table.contains("sigma_phi_x[nrad]")
            && table.contains("seed 1")
    );
    for f in [
        "samples_01_01_maxwell_vgroove_steel.csv",
        "sigma_bars.svg",
        "scatter_xy.svg",
        "sigma_convergence.svg",
    ] {
        let text = std::fs::read_to_string(dir.join(f)).unwrap();
        assert!(text.len() > 100, "{f}");
    }
    let samples =
        std::fs::read_to_string(dir.join("samples_01_01_maxwell_vgroove_steel.csv")).unwrap();
    // A provenance comment line, the header, 25 samples.
    assert_eq!(samples.lines().count(), 27);
    assert!(samples.starts_with("# kinrepro "));
    assert!(
        samples
            .lines()
            .nth(1)
            .unwrap()
            .starts_with("index,mu_1,mu_2,mu_3,mu_4,mu_5,mu_6,centre/x_m")
    );
    let (ok, csv, _) =
        kinrepro(&["study", s1.to_str().unwrap(), "--format", "csv", "--samples", "8"]);
    assert!(ok);
    assert_eq!(csv.lines().count(), 1 + 6);
    // The corners design has 2^6 samples, each mu at mu0 +- spread (scene 01:
    // 0.5 +- 0.05), every sign pattern once.
    let corners = dir.join("corners");
    let (ok, _, err) = kinrepro(&[
        "study",
        s1.to_str().unwrap(),
        "--sampler",
        "corners",
        "--out",
        corners.to_str().unwrap(),
    ]);
    assert!(ok, "{err}");
    let samples =
        std::fs::read_to_string(corners.join("samples_01_01_maxwell_vgroove_steel.csv")).unwrap();
    let mut patterns = std::collections::BTreeSet::new();
    for row in samples.lines().skip(2) {
        let mu: Vec<f64> = row.split(',').skip(1).take(6).map(|v| v.parse().unwrap()).collect();
        let mut bits = 0u32;
        for (k, m) in mu.iter().enumerate() {
            let high = (m - 0.55).abs() < 1e-12;
            assert!(high || (m - 0.45).abs() < 1e-12, "mu_{} = {m}", k + 1);
            bits |= u32::from(high) << k;
        }
        patterns.insert(bits);
    }
    assert_eq!(patterns.len(), 64, "{samples}");
    // Bad input: unknown sampler, bad shard.
    let (ok, _, err) = kinrepro(&["study", s1.to_str().unwrap(), "--sampler", "sobol"]);
    assert!(!ok && err.contains("sobol"));
    let (ok, _, err) = kinrepro(&["study", s1.to_str().unwrap(), "--shard", "5/4"]);
    assert!(!ok && !err.contains("panicked"), "{err}");
}

#[test]
fn dynamic_studies_with_random_start_poses() {
    use kinrepro::solve::{Load, Solver};
    use kinrepro::study::runner::{StartBounds, Variation, lifted_clear};
    use kinrepro::study::{StudyPlan, Varied};
    use nalgebra::Vector3;
    // Below the friction limit (0.31 for this groove) an offset start centres.
    let text = std::fs::read_to_string(scene("01_maxwell_vgroove_steel.toml"))
        .unwrap()
        .replace("mu_static = 0.5 ", "mu_static = 0.2 ");
    let s = kinrepro::scene::Scene::parse(&text, "low_mu.toml").unwrap();
    let c = kinrepro::assembly::Coupling::new(&s).unwrap();
    let bounds = StartBounds {
        offset: Vector3::new(20e-6, 20e-6, 30e-6),
        tilt: Vector3::new(1e-4, 1e-4, 1e-4),
    };
    let variation = Variation { friction: false, start: Some(bounds), ..Default::default() };
    // Every drawn start lies above the seat: clear of all surfaces, within the bounds.
    for row in kinrepro::study::design(Sampler::Lhs, 6, 12, 3).unwrap() {
        let kinrepro::study::runner::Sample { load: Load { mu, start, .. }, .. } =
            variation.sample(&s, &c, &row);
        assert_eq!(mu, vec![0.2; 6]);
        assert!(start.offset.x.abs() <= 20e-6 && start.offset.y.abs() <= 20e-6);
        assert!(start.tilt.iter().all(|t| t.abs() <= 1e-4));
        let base = lifted_clear(
            &c,
            kinrepro::solve::dynamic::StartPose {
                offset: Vector3::new(start.offset.x, start.offset.y, 0.0),
                tilt: start.tilt,
            },
        );
        assert!(start.offset.z >= base.offset.z && start.offset.z <= base.offset.z + 30e-6 + 1e-12);
        let pose = c.touching_pose.moved(&base.offset, &base.tilt);
        let min_gap = (0..6).map(|i| c.geometry(i, &pose).gap).fold(f64::INFINITY, f64::min);
        assert!((min_gap - 1e-9).abs() < 1e-12, "{min_gap:e}");
    }
    // The same variation as options: the start alone, within the bounds.
    let start_only = StudyOptions {
        vary: vec![Varied::Start],
        offset_bounds: Some([20e-6, 20e-6, 30e-6]),
        tilt_bounds: Some([1e-4, 1e-4, 1e-4]),
        ..Default::default()
    };
    let opts = StudyOptions { samples: Some(6), solver: Solver::Dynamic, ..start_only.clone() };
    let plan = crate::common::plan(vec![(s.clone(), c.clone())], &opts);
    assert_eq!(plan.settings.variation, variation);
    let v = crate::common::report(&plan);
    assert_eq!(v.solver, "dynamic");
    assert_eq!(v.inputs.len(), 6);
    // With equal friction the start alone leaves a scatter (friction holds
    // each arrival slightly differently), but every sample centres: no pose
    // ends further than 100 nm from the nominal seating.
    let p = &v.points[0];
    assert!(p.max.x_nm.abs().max(p.min.x_nm.abs()) < 100.0, "{p:?}");
    // A varied start needs the dynamic solver; a study must vary something.
    let bad = start_only;
    assert!(
        StudyPlan::new(vec![(s.clone(), c.clone())], &bad)
            .unwrap_err()
            .to_string()
            .contains("solver=dynamic")
    );
    let none = StudyOptions { vary: vec![], ..Default::default() };
    assert!(
        StudyPlan::new(vec![(s, c)], &none).unwrap_err().to_string().contains("varies nothing")
    );
}

/// Seating four samples at a time in SIMD lanes changes no byte of a
/// study, nor does the number of jobs: the paper scenes (followed in lanes),
/// a magnet scene (its magnets' force table read lane by lane), a flexure
/// scene (an anisotropic support: the lanes hand its seatings to the f64
/// kernel), a varied preload (each lane its own preload: seated one by
/// one) and 22 samples (five sets of four and two left over).
#[test]
fn lanes_and_jobs_change_no_byte_of_a_study() {
    let names = [
        "01_maxwell_vgroove_steel.toml",
        "02_maxwell_pins_steel.toml",
        "06_kelvin_steel.toml",
        "kelvin_magnet_wall_mount.toml",
        "maxwell_flexure_grooves.toml",
    ];
    let paths: Vec<String> = names.iter().map(|n| scene(n).display().to_string()).collect();
    let preload = scene("tolerances_maxwell_vgroove.toml").display().to_string();
    let cases: [Vec<&str>; 2] = [
        paths.iter().map(String::as_str).collect(),
        vec![preload.as_str(), "--vary", "friction,preload"],
    ];
    for case in &cases {
        let run = |lanes: &str, jobs: &str| {
            let mut args = vec!["study"];
            args.extend(case.iter().copied());
            args.extend(["--samples", "22", "--seed", "5", "--format", "json"]);
            args.extend(["--lanes", lanes, "--jobs", jobs]);
            let (ok, out, err) = kinrepro(&args);
            assert!(ok, "{args:?}: {err}");
            out
        };
        let off = run("off", "1");
        assert_eq!(run("on", "1"), off, "{case:?}: lanes on");
        assert_eq!(run("on", "2"), off, "{case:?}: lanes on, 2 jobs");
        assert_eq!(run("auto", "2"), off, "{case:?}: lanes auto, 2 jobs");
    }
}
