//! Unit tests of design sweeps: swept fields, value sets, grid and LHS designs, the Pareto front.

mod field {
    use kinrepro::explore::field::*;
    use kinrepro::scene::SceneFile;

    /// The scene text: a high-level scene (the typed scene needs the
    /// coupling's arrangement, groove and materials, the preload and
    /// friction) with a `[[materials]]` entry.
    const TEXT: &str = "[coupling]\narrangement = \"maxwell\"\nball_material = \"steel\"\n\
         diameter = 0.08\nball_diameter = 0.01\ngroove = \"planes\"\ngroove_material = \"steel\"\n\
         [preload]\nforce = 20\n[friction]\nmu_static = 0.5\n\
         [[materials]]\nname = \"probe\"\nyoungs_modulus = 2e11\npoisson_ratio = 0.3\n";

    fn scene() -> SceneFile {
        SceneFile::parse(TEXT, "scene.toml").unwrap()
    }

    #[test]
    fn known_fields_have_their_kind() {
        let s = scene();
        assert_eq!(kind_of("preload.force", &s).unwrap(), FieldKind::Number);
        // No [friction] here: the typed scene has no friction field to sweep
        // (it is refused before any field is looked up).
        let no_friction = TEXT.replace("[friction]\nmu_static = 0.5\n", "");
        assert_eq!(
            SceneFile::parse(&no_friction, "scene.toml").ok().map(|s| kind_of(
                "friction.mu_static",
                &s
            )
            .ok()),
            None
        );
        assert_eq!(kind_of("coupling.ball_material", &s).unwrap(), FieldKind::Material);
        assert_eq!(kind_of("materials.probe.youngs_modulus", &s).unwrap(), FieldKind::Number);
    }

    #[test]
    fn unknown_paths_and_wrong_types_are_named() {
        let s = scene();
        for bad in [
            "preload.forse",
            "coupling",
            "materials.other.youngs_modulus",
            "study.samples",
            "variation.surface_tilt",
            "materials.unobtainium.allowable_shear_stress",
        ] {
            let e = kind_of(bad, &s).unwrap_err().to_string();
            assert!(e.contains(bad), "{e}");
        }
        // A value of the wrong type: the typed scene refuses it when it is
        // read (before any field is swept), naming the file, the line and
        // the type the field takes.
        let big = TEXT.replace("diameter = 0.08", "diameter = \"big\"");
        let e = SceneFile::parse(&big, "scene.toml")
            .map(|s| kind_of("coupling.diameter", &s))
            .unwrap_err()
            .to_string();
        let line = 1 + TEXT.lines().position(|l| l.contains("diameter = 0.08")).unwrap();
        assert!(e.starts_with(&format!("scene.toml:{line}:")), "{e}");
        assert!(e.contains("invalid type: string \"big\", expected f64"), "{e}");
    }

    #[test]
    fn string_fields_and_built_in_materials() {
        let s = scene();
        for path in ["coupling.arrangement", "coupling.groove", "coupling.ball_shape"] {
            assert_eq!(kind_of(path, &s).ok(), Some(FieldKind::Text), "{path}");
        }
        // A built-in material's constants are sweepable without an entry.
        assert_eq!(
            kind_of("materials.steel.allowable_shear_stress", &s).unwrap(),
            FieldKind::Number
        );
        let mut t = scene();
        set(&mut t, "materials.steel.poisson_ratio", &SweptValue::Number(0.25)).unwrap();
        set(&mut t, "materials.steel.youngs_modulus", &SweptValue::Number(2e11)).unwrap();
        // One override entry holding the built-in's other constants.
        let entries = &t.materials;
        assert_eq!(entries.len(), 2);
        let steel = &entries[1];
        assert_eq!(steel.name.get_ref().as_str(), "steel");
        assert_eq!(steel.replaces.as_ref().map(|r| *r.get_ref()), Some(true));
        assert_eq!(*steel.youngs_modulus.get_ref(), 2e11);
        assert_eq!(*steel.poisson_ratio.get_ref(), 0.25);
        let builtin = kinrepro::Material::builtin("steel").unwrap();
        assert_eq!(
            steel.allowable_pressure.as_ref().map(|p| *p.get_ref()),
            builtin.allowable_pressure
        );
    }

    #[test]
    fn set_replaces_or_inserts() {
        let mut s = scene();
        set(&mut s, "preload.force", &SweptValue::Number(5.0)).unwrap();
        set(&mut s, "coupling.opening_angle_deg", &SweptValue::Number(60.0)).unwrap();
        set(&mut s, "materials.probe.youngs_modulus", &SweptValue::Number(1e11)).unwrap();
        assert_eq!(s.preload.force.as_ref().map(|f| *f.get_ref()), Some(5.0));
        let coupling = s.coupling.as_ref().unwrap();
        assert_eq!(*coupling.opening_angle_deg.get_ref(), 60.0);
        assert_eq!(*s.materials[0].youngs_modulus.get_ref(), 1e11);
    }
}

mod values {
    use kinrepro::explore::ExploreError;
    use kinrepro::explore::SweptValue;
    use kinrepro::explore::values::*;
    use kinrepro::scene::SceneFile;

    fn scene() -> SceneFile {
        SceneFile::parse(
            "[coupling]\narrangement = \"maxwell\"\nball_material = \"steel\"\n\
             diameter = 0.08\nball_diameter = 0.01\ngroove = \"planes\"\n\
             groove_material = \"steel\"\n[preload]\nforce = 20.0\n[friction]\nmu_static = 0.5\n",
            "scene.toml",
        )
        .unwrap()
    }

    #[test]
    fn ranges_lists_and_names() {
        let s = scene();
        let lin = Set::parse("preload.force=5:40:8", &s).unwrap();
        assert_eq!(
            lin.levels,
            Levels::Numbers(vec![5.0, 10.0, 15.0, 20.0, 25.0, 30.0, 35.0, 40.0])
        );
        let log = Set::parse("preload.force=log:1:100:5", &s).unwrap();
        let Levels::Numbers(v) = log.levels else { panic!() };
        for (got, want) in v.iter().zip([1.0, 10f64.sqrt(), 10.0, 1000f64.sqrt(), 100.0]) {
            assert!((got / want - 1.0).abs() < 1e-14, "{got} vs {want}");
        }
        let list = Set::parse("preload.force=5,10,20", &s).unwrap();
        assert_eq!(list.levels, Levels::Numbers(vec![5.0, 10.0, 20.0]));
        assert_eq!(list.interval, None);
        let m = Set::parse("coupling.ball_material=steel,silicon-carbide", &s).unwrap();
        assert_eq!(m.levels.len(), 2);
    }

    #[test]
    fn items_are_numbers_unless_quoted_or_unparsable() {
        assert_eq!(item("20"), SweptValue::Number(20.0));
        assert_eq!(item("1e-3"), SweptValue::Number(1e-3));
        assert_eq!(item("planes"), SweptValue::Name("planes".into()));
        assert_eq!(item("\"20\""), SweptValue::Name("20".into()));
        assert_eq!(item("'gothic-arch'"), SweptValue::Name("gothic-arch".into()));
        assert_eq!(item("\""), SweptValue::Name("\"".into()));
        let s = scene();
        let g = Set::parse("coupling.groove=planes,'7',gothic-arch", &s).unwrap();
        assert_eq!(
            g.levels,
            Levels::Names(vec!["planes".into(), "7".into(), "gothic-arch".into()])
        );
        for bad in ["coupling.groove=planes,7", "coupling.groove=a:b", "coupling.groove=x,'x'"] {
            let e = Set::parse(bad, &s).unwrap_err().to_string();
            assert!(e.contains(bad), "{e}");
        }
    }

    #[test]
    fn bad_values_are_named() {
        let s = scene();
        for bad in [
            "preload.force=5,steel",
            "preload.force=40:5:3",
            "preload.force=log:0:10:3",
            "preload.force=1:2:1",
            "preload.force=5,5",
            "coupling.ball_material=1,2",
            "coupling.ball_material=1:2:3",
        ] {
            let e = Set::parse(bad, &s).unwrap_err().to_string();
            assert!(e.contains(bad), "{e}");
        }
        assert!(matches!(Set::parse("preload.force", &s), Err(ExploreError::SetSyntax { .. })));
        let e = Set::parse("preload.force=40:5:3", &s).unwrap_err();
        assert!(
            matches!(
                e,
                ExploreError::Values { reason: ValuesError::Reversed { lo: 40.0, hi: 5.0 }, .. }
            ),
            "{e:?}"
        );
        assert_eq!(e.to_string(), "sets=preload.force=40:5:3: the range needs a < b, got 40 and 5");
    }
}

mod design {
    use kinrepro::explore::design::*;
    use kinrepro::explore::field::SweptValue;
    use kinrepro::explore::values::Set;

    fn sets(args: &[&str]) -> Vec<Set> {
        let scene = kinrepro::scene::SceneFile::parse(
            "[coupling]\narrangement = \"maxwell\"\nball_material = \"steel\"\n\
             diameter = 0.08\nball_diameter = 0.01\ngroove = \"planes\"\n\
             groove_material = \"steel\"\n[preload]\nforce = 20.0\n[friction]\nmu_static = 0.5\n",
            "scene.toml",
        )
        .unwrap();
        args.iter().map(|a| Set::parse(a, &scene).unwrap()).collect()
    }

    #[test]
    fn grid_is_the_full_product_last_fastest() {
        let s = sets(&["preload.force=1,2,3", "coupling.diameter=0.05,0.1"]);
        let p = design_points(&s, DesignKind::Grid).unwrap();
        assert_eq!(p.len(), 6);
        assert_eq!(p[1].values, vec![SweptValue::Number(1.0), SweptValue::Number(0.1)]);
        assert_eq!(p[4].values, vec![SweptValue::Number(3.0), SweptValue::Number(0.05)]);
    }

    #[test]
    fn lhs_stratifies_every_range() {
        let s = sets(&["preload.force=log:1:100", "coupling.diameter=0.05:0.1"]);
        let n = 10;
        let p = design_points(&s, DesignKind::Lhs { points: n, seed: 3 }).unwrap();
        // One point in each of the n equal strata of each (log) range.
        for (k, to_u) in [
            (0, Box::new(|x: f64| x.log10() / 2.0) as Box<dyn Fn(f64) -> f64>),
            (1, Box::new(|x: f64| (x - 0.05) / 0.05)),
        ] {
            let mut strata: Vec<usize> = p
                .iter()
                .map(|d| match d.values[k] {
                    SweptValue::Number(x) => ((to_u(x) * n as f64) as usize).min(n - 1),
                    _ => unreachable!(),
                })
                .collect();
            strata.sort();
            assert_eq!(strata, (0..n).collect::<Vec<_>>());
        }
    }
}

mod pareto {
    use kinrepro::explore::pareto::*;

    fn o(s: f64, k: f64, sf: f64) -> Option<Objectives> {
        Some(Objectives { sigma_max: s, stiffness_min: k, safety_factor: Some(sf) })
    }

    /// The front of the default objectives (every design with a safety factor).
    fn front(d: &[Option<Objectives>]) -> Vec<bool> {
        front_of(&d.iter().map(|o| o.map(|o| o.values(true))).collect::<Vec<_>>())
    }

    #[test]
    fn a_hand_checked_front() {
        // 0: best sigma; 1: dominated by 0 (worse sigma, same k and SF);
        // 2: best stiffness; 3: equal to 0 on all (neither dominates);
        // 4: not evaluated.
        let d = [o(1.0, 5.0, 2.0), o(2.0, 5.0, 2.0), o(3.0, 9.0, 1.0), o(1.0, 5.0, 2.0), None];
        assert_eq!(front(&d), vec![true, false, true, true, false]);
    }

    #[test]
    fn every_dominated_design_is_beaten_by_one_on_the_front() {
        // A deterministic cloud of designs (a Weyl sequence).
        let d: Vec<_> = (0..60)
            .map(|i| {
                let f = |a: f64| (i as f64 * a).fract();
                o(f(0.618), f(0.414), f(0.732))
            })
            .collect();
        let on = front(&d);
        let v: Vec<Vec<f64>> = d.iter().map(|x| x.unwrap().values(true)).collect();
        for (i, a) in v.iter().enumerate() {
            if on[i] {
                assert!(!v.iter().any(|b| dominates(b, a)));
            } else {
                assert!(v.iter().zip(&on).any(|(b, f)| *f && dominates(b, a)));
            }
        }
        assert!(on.iter().any(|x| *x) && on.iter().any(|x| !*x));
    }
}
