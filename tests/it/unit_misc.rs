//! Unit tests of materials, scene table validation, the contact layer motion, the sweep number format and the HTML report sections.

mod material {
    use kinrepro::material::*;

    #[test]
    fn steel_pair_moduli_match_hand_values() {
        let s = Material::builtin("steel").unwrap();
        // E* = E / (2 (1 - v^2)) for identical materials.
        let e_star = 210e9 / (2.0 * (1.0 - 0.09));
        assert!((effective_modulus(&s, &s) / e_star - 1.0).abs() < 1e-15);
        // G* = G / (2 (2 - v)), G = E / 2.6.
        let g_star = (210e9 / 2.6) / (2.0 * 1.7);
        assert!((effective_shear_modulus(&s, &s) / g_star - 1.0).abs() < 1e-15);
        // 4 G*/E* for steel/steel is ~0.82 (docs/model.md, 'What to expect in a groove').
        let ratio = 4.0 * g_star / e_star;
        assert!((ratio - 0.8235).abs() < 1e-3, "{ratio}");
    }

    #[test]
    fn unknown_and_invalid_materials_are_errors() {
        let e = Material::builtin("unobtainium").unwrap_err();
        assert!(e.to_string().contains("unobtainium") && e.to_string().contains("steel"));
        assert!(Material::new("x", -1.0, 0.3, None).is_err());
        assert!(Material::new("x", 1e9, 0.5, None).is_err());
        assert!(Material::new("x", 1e9, 0.3, Some(0.0)).is_err());
        assert!(Material::new("x", f64::NAN, 0.3, None).is_err());
        let ok = Material::new("x", 1e9, 0.3, None).unwrap();
        assert!(ok.clone().with_allowable_shear_stress(Some(-1.0)).is_err());
        assert!(ok.clone().with_allowable_shear_stress(Some(f64::NAN)).is_err());
        assert!(ok.with_allowable_shear_stress(Some(1e9)).is_ok());
        for n in builtin_names() {
            Material::builtin(n).unwrap().validate().unwrap();
        }
    }
}

mod scene_tables {
    use kinrepro::scene::error::{ErrorContext, SceneError};
    use kinrepro::scene::file::{FrictionFile, StudyFile};
    use kinrepro::scene::resolve::tables::*;
    use kinrepro::scene::{FrictionSettings, Sampler};

    fn friction_of(text: &str) -> Result<FrictionSettings, SceneError> {
        let f: FrictionFile = toml::from_str(text).unwrap();
        friction(&f, &[0, 0, 1, 1, 2, 2], &ErrorContext::new("f.toml", text)).map(|(s, _, _)| s)
    }

    /// mu_s may vary in mu0 +- spread only while it stays in [0, MU_MAX]:
    /// the bounds spread = mu0 and mu0 + spread = MU_MAX pass, just past
    /// them fails, naming the line and field of the spread.
    #[test]
    fn friction_spread_keeps_mu_in_its_range() {
        let ok = friction_of("mu_static = 0.5\nspread = 0.5\n").unwrap();
        assert_eq!((ok.mu_static, ok.spread, ok.dynamic_ratio), (0.5, 0.5, 0.8));
        let e = friction_of("mu_static = 0.5\nspread = 0.51\n").unwrap_err();
        assert_eq!((e.line, e.field.as_str()), (Some(2), "friction.spread"));
        let (mu0, rest) = (0.75 * MU_MAX, 0.25 * MU_MAX);
        assert!(friction_of(&format!("mu_static = {mu0}\nspread = {rest}\n")).is_ok());
        let e = friction_of(&format!("mu_static = {mu0}\nspread = {}\n", rest + 1e-9)).unwrap_err();
        assert!(e.reason.contains("exceeds"), "{e}");
    }

    /// The sampler name is checked here, spelt exactly (`MC` is refused,
    /// as any other keyword spelt otherwise), and kept as plain data.
    #[test]
    fn study_sampler_is_checked_at_parse_time() {
        let study_of = |text: &str| {
            let st: StudyFile = toml::from_str(text).unwrap();
            study(&st, &ErrorContext::new("s.toml", text))
        };
        let s = study_of("samples = 8\nsampler = \"mc\"\n").unwrap();
        assert_eq!((s.samples, s.sampler), (8, Sampler::MonteCarlo));
        let e = study_of("samples = 8\nsampler = \"MC\"\n").unwrap_err();
        assert_eq!((e.line, e.field.as_str()), (Some(2), "study.sampler"));
        let e = study_of("samples = 8\nsampler = \"sobol\"\n").unwrap_err();
        assert_eq!((e.line, e.field.as_str()), (Some(2), "study.sampler"));
        assert!(e.reason.contains("lhs, mc or corners"), "{e}");
    }
}

mod contact_layer {
    use kinrepro::assembly::BodyPose;
    use kinrepro::solve::contact_layer::*;
    use nalgebra::UnitQuaternion;
    use nalgebra::Vector3;

    #[test]
    fn motion_is_the_committed_pose_of_the_material_point() {
        // du = p - T_c T^-1 p by the two rigid maps applied one after the other.
        let pose = BodyPose {
            rotation: UnitQuaternion::from_scaled_axis(Vector3::new(1e-3, -2e-3, 0.5)),
            translation: Vector3::new(1e-6, 2e-6, -3e-6),
        };
        let committed =
            pose.moved(&Vector3::new(2e-8, -1e-8, 3e-8), &Vector3::new(1e-7, 3e-7, -2e-7));
        let motion = Motion::between(&pose, &committed);
        for p in [Vector3::new(0.04, 0.0, 0.0), Vector3::new(-0.02, 0.035, -0.005)] {
            let body = pose.rotation.inverse() * (p - pose.translation);
            let direct = p - committed.apply(&body);
            assert!(direct.norm() > 1e-9);
            assert!((motion.displacement(&p) - direct).norm() < 1e-17, "{p}");
        }
    }
}

mod sweep_text {
    use kinrepro::report::sweep::text::short;

    #[test]
    fn short_numbers() {
        assert_eq!(short(5.0), "5");
        assert_eq!(short(16.666666666666664), "16.67");
        assert_eq!(short(0.005), "0.005");
        assert_eq!(short(0.0), "0");
        assert_eq!(short(-2.5), "-2.5");
        assert_eq!(short(2.1e11), "2.100e11");
    }
}

mod html {
    use kinrepro::report::html::*;

    /// A report of extra sections only (e.g. a sweep's charts): the sections
    /// in order, escaped titles, no study parts.
    #[test]
    fn sections_alone_make_a_report() {
        let svg = |w: u32| {
            format!(
                "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 {w} 10\"><rect width=\"{w}\" height=\"10\"/></svg>"
            )
        };
        let report = HtmlReport {
            sections: vec![
                Section { title: "σ vs preload <F>".into(), svg: svg(40) },
                Section {
                    title: "Pareto front".into(),
                    svg: format!("<?xml version=\"1.0\"?>\n{}", svg(50)),
                },
            ],
            ..Default::default()
        };
        let html = report.render().unwrap();
        let (a, b) =
            (html.find("σ vs preload &lt;F&gt;").unwrap(), html.find("Pareto front").unwrap());
        assert!(a < b);
        assert_eq!(html.matches("data-check=\"chart\"").count(), 2);
        assert!(
            !html.contains("<?xml") && !html.contains("σ tables") && !html.contains("id=\"run\"")
        );
        assert!(html.contains("viewBox=\"0 0 50 10\""));
    }
}

/// Pareto labels: for a tight cluster of markers and points at the plot's
/// edges, every label lies inside the plot and overlaps neither another
/// label nor a marker (radius 4 px).
#[test]
fn pareto_labels_are_placed_apart_and_inside() {
    use kinrepro::report::sweep::pareto::place_labels;
    let bounds = [0.0, 0.0, 400.0, 300.0];
    let mut points: Vec<(f64, f64)> =
        (0..12).map(|i| (200.0 + 3.0 * (i % 4) as f64, 150.0 + 3.0 * (i / 4) as f64)).collect();
    points.extend([(1.0, 1.0), (399.0, 299.0), (399.0, 1.0), (1.0, 299.0)]);
    let labelled: Vec<usize> = (0..points.len()).collect();
    let sizes = vec![(23.0, 14.0); points.len()];
    let boxes = place_labels(&points, &labelled, &sizes, bounds);
    let apart =
        |a: &[f64; 4], b: &[f64; 4]| a[2] <= b[0] || b[2] <= a[0] || a[3] <= b[1] || b[3] <= a[1];
    for (i, a) in boxes.iter().enumerate() {
        assert!(a[0] >= 0.0 && a[1] >= 0.0 && a[2] <= 400.0 && a[3] <= 300.0);
        assert!((a[2] - a[0] - 23.0).abs() < 1e-12 && (a[3] - a[1] - 14.0).abs() < 1e-12);
        for b in &boxes[i + 1..] {
            assert!(apart(a, b), "{a:?} {b:?}");
        }
        for &(x, y) in &points {
            assert!(apart(a, &[x - 4.0, y - 4.0, x + 4.0, y + 4.0]), "{a:?} on ({x}, {y})");
        }
    }
}

mod run_estimate {
    use kinrepro::solve::{Method, SolverOptions};
    use kinrepro::study::bounds::{estimate_note, seating_seconds};

    /// The estimate follows the fixed increments asked for: ten times the
    /// increments, ten times the time per seating (above the controlled
    /// path's floor), so `--increments 100000 --samples 1000` is announced
    /// before it starts, while the default path's 1000 seatings are not.
    #[test]
    fn the_estimate_scales_with_the_increments() {
        let fixed = |n| Method::QuasiStatic(SolverOptions::fixed(n));
        let (a, b) = (seating_seconds(&fixed(10_000)), seating_seconds(&fixed(100_000)));
        assert!((b / a - 10.0).abs() < 1e-12, "{a} {b}");
        assert!(estimate_note(1000, &fixed(100_000), 2).is_some());
        assert!(estimate_note(1000, &Method::QuasiStatic(SolverOptions::default()), 2).is_none());
    }
}
