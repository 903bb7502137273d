//! Functions written over `kinrepro::lane::Lane`: each lane of four is,
//! bit for bit, the f64 function of that lane's inputs, also where the
//! lanes take different branches of it or stop their iterations at
//! different steps.

use kinrepro::assembly::{BodyPose, ContactGeometry};
use kinrepro::contact::mindlin::{PrincipalStiffness, equal_to_rounding, project_on_circle};
use kinrepro::contact::{Friction, FrictionLaw, TangentialState};
use kinrepro::lane::F64x4;
use nalgebra::{Matrix3, Vector2, Vector3};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use simba::simd::SimdValue;

/// Four scalars as lanes.
fn lanes(x: [f64; 4]) -> F64x4 {
    F64x4::from(x)
}

/// Four vectors as a vector of lanes.
fn vector_lanes(v: [Vector2<f64>; 4]) -> Vector2<F64x4> {
    Vector2::from_fn(|i, _| lanes(v.map(|v| v[i])))
}

/// Whether lane `i` of a matrix of lanes has exactly the bits of `m`.
fn same_bits<const R: usize, const C: usize>(
    lanes: &nalgebra::SMatrix<F64x4, R, C>,
    i: usize,
    m: &nalgebra::SMatrix<f64, R, C>,
) -> bool {
    lanes.iter().zip(m.iter()).all(|(l, x)| l.extract(i).to_bits() == x.to_bits())
}

/// One lane's inputs of the return map: the branch it takes is drawn, so
/// that a set of four mixes the frictionless limit, circles (equal values,
/// and values equal but for rounding), and ellipses from barely to far
/// outside the limit (one to a few tens of Newton steps).
fn return_map_case(rng: &mut ChaCha8Rng) -> ([f64; 2], Vector2<f64>, f64) {
    let k0 = 3e7 * rng.random_range(0.5..2.0);
    let k1 = match rng.random_range(0..4) {
        0 => k0,
        1 => k0 * (1.0 + 1e-13),
        _ => k0 * rng.random_range(0.2..5.0),
    };
    let limit: f64 = match rng.random_range(0..6) {
        0 => 0.0,
        _ => rng.random_range(0.01..2.0),
    };
    let angle = rng.random_range(0.0..std::f64::consts::TAU);
    let excess = 10f64.powf(rng.random_range(-9.0..1.0));
    let r = limit.max(0.1) * (1.0 + excess);
    ([k0, k1], Vector2::new(r * angle.cos(), r * angle.sin()), limit)
}

/// The elliptical return map of four lanes at once against the f64 map
/// of each: force, dF/dF_trial and dF/dL bit for bit, over 4000 lanes
/// whose branches and Newton step counts differ within a set of four.
#[test]
fn the_return_map_in_lanes_is_the_scalar_map_of_each_lane() {
    let mut rng = ChaCha8Rng::seed_from_u64(41);
    let mut mixed = 0;
    for _ in 0..1000 {
        let cases: [_; 4] = std::array::from_fn(|_| return_map_case(&mut rng));
        let k = [0, 1].map(|j| lanes(cases.map(|c| c.0[j])));
        let trial = vector_lanes(cases.map(|c| c.1));
        let limit = lanes(cases.map(|c| c.2));
        let (f, d, dl) = project_on_circle(k, &trial, limit);
        let kinds = cases.map(|c| (c.2 <= 0.0, equal_to_rounding(c.0)));
        mixed += usize::from(kinds.iter().any(|&x| x != kinds[0]));
        for (i, (k, trial, limit)) in cases.iter().enumerate() {
            let (fs, ds, dls) = project_on_circle(*k, trial, *limit);
            assert!(same_bits(&f, i, &fs), "lane {i} of {cases:?}: F");
            assert!(same_bits::<2, 2>(&d, i, &ds), "lane {i} of {cases:?}: dF/dF_trial");
            assert!(same_bits(&dl, i, &dls), "lane {i} of {cases:?}: dF/dL");
            assert!(fs.iter().all(|x| x.is_finite()), "{cases:?}");
        }
    }
    // Most sets of four lanes take more than one branch.
    assert!(mixed > 600, "{mixed} mixed sets");
}

/// A rotation vector of a turn drawn over 1e-18 to 1 rad: the three
/// forms of `rotation_exp` (none, the series, nalgebra's) in one set.
fn turn(rng: &mut ChaCha8Rng) -> Vector3<f64> {
    let axis = Vector3::from_fn(|_, _| rng.random_range(-1.0..1.0)).normalize();
    axis * 10f64.powf(rng.random_range(-18.0..0.0))
}

/// Four poses moved by four twists at once (`BodyPose::moved`: the exact
/// finite rotation exp(w) about the origin, then the translation): each
/// lane's rotation and translation bit for bit the f64 move of its own.
#[test]
fn poses_move_in_lanes_as_each_lane_alone() {
    let mut rng = ChaCha8Rng::seed_from_u64(42);
    for _ in 0..1000 {
        let cases: [(BodyPose, Vector3<f64>, Vector3<f64>); 4] = std::array::from_fn(|_| {
            let start =
                BodyPose::identity().moved(&Vector3::new(1e-3, -2e-4, 5e-5), &turn(&mut rng));
            (start, Vector3::from_fn(|_, _| rng.random_range(-1e-6..1e-6)), turn(&mut rng))
        });
        let pose = pose_lanes(&cases.map(|c| c.0));
        let v = Vector3::from_fn(|i, _| lanes(cases.map(|c| c.1[i])));
        let w = Vector3::from_fn(|i, _| lanes(cases.map(|c| c.2[i])));
        let moved = pose.moved(&v, &w);
        for (i, (start, v, w)) in cases.iter().enumerate() {
            let alone = start.moved(v, w);
            assert!(same_bits(&moved.rotation.coords, i, &alone.rotation.coords), "{cases:?}");
            assert!(same_bits(&moved.translation, i, &alone.translation), "{cases:?}");
        }
    }
}

/// Four poses as one pose of lanes.
fn pose_lanes(p: &[BodyPose; 4]) -> BodyPose<F64x4> {
    BodyPose::from_lanes(p)
}

/// The geometry of every contact of every bundled scene (balls on planes,
/// pins, balls and grooves, canoe patches, crossed pins) at four poses
/// about the touching pose at once: each lane's gap, normal and point bit
/// for bit the f64 geometry at its own pose.
#[test]
fn contact_geometry_in_lanes_is_each_lanes_own() {
    let mut rng = ChaCha8Rng::seed_from_u64(43);
    let mut pins = 0;
    for (path, c) in bundled_couplings() {
        for _ in 0..50 {
            let poses: [BodyPose; 4] = std::array::from_fn(|_| {
                let v = Vector3::from_fn(|_, _| rng.random_range(-2e-6..2e-6));
                c.touching_pose.moved(&v, &(turn(&mut rng) * 1e-4))
            });
            let at = pose_lanes(&poses);
            for i in 0..c.contacts.len() {
                pins += usize::from(c.contacts[i].axis.is_some());
                let g = c.geometry(i, &at);
                for (lane, pose) in poses.iter().enumerate() {
                    let alone = c.geometry(i, pose);
                    let what = format!("{path} contact {i} lane {lane}");
                    assert_eq!(g.gap.extract(lane).to_bits(), alone.gap.to_bits(), "{what}");
                    assert!(same_bits(&g.normal, lane, &alone.normal), "{what}");
                    assert!(same_bits(&g.point, lane, &alone.point), "{what}");
                }
            }
        }
    }
    assert!(pins > 0, "a scene with moving pins");
}

/// Every bundled scene's couplings (`Coupling::new` of each file).
fn bundled_couplings() -> Vec<(String, kinrepro::assembly::Coupling)> {
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    let mut paths: Vec<_> = std::fs::read_dir(dir).unwrap().map(|e| e.unwrap().path()).collect();
    paths.sort();
    paths
        .into_iter()
        .map(|p| {
            let scene = kinrepro::scene::Scene::load(&p).unwrap();
            (p.display().to_string(), kinrepro::assembly::Coupling::new(&scene).unwrap())
        })
        .collect()
}

/// The normal part of every contact of every bundled scene (Hertz alone,
/// or in series with a support compliance: its Newton iteration) at four
/// approaches at once, some open, from committed forces some zero: each
/// lane bit for bit its f64 value.
#[test]
fn the_normal_part_in_lanes_is_each_lanes_own() {
    use kinrepro::solve::contact_layer::NormalPart;
    let mut rng = ChaCha8Rng::seed_from_u64(44);
    let mut compliant = 0;
    for (name, c) in bundled_couplings() {
        for i in 0..c.contacts.len() {
            compliant += usize::from(c.contacts[i].normal.compliance > 0.0);
            for _ in 0..50 {
                let cases: [(f64, f64); 4] = std::array::from_fn(|_| {
                    let approach = match rng.random_range(0..5) {
                        0 => -1e-7,
                        1 => 0.0,
                        _ => 10f64.powf(rng.random_range(-9.0..-5.0)),
                    };
                    let root = [0.0, rng.random_range(0.1..3.0)][rng.random_range(0..2)];
                    (approach, root)
                });
                let geometry = |gap| ContactGeometry { gap, ..Default::default() };
                let g = ContactGeometry::<F64x4> {
                    gap: lanes(cases.map(|x| -x.0)),
                    normal: Vector3::zeros(),
                    point: Vector3::zeros(),
                };
                let p = NormalPart::of_root(&c, i, &g, || lanes(cases.map(|x| x.1)));
                for (lane, (approach, root)) in cases.iter().enumerate() {
                    let s = NormalPart::of_root(&c, i, &geometry(-approach), || *root);
                    let what = format!("{name} contact {i} lane {lane}: {cases:?}");
                    for (l, x) in [
                        (p.approach, s.approach),
                        (p.normal_force, s.normal_force),
                        (p.normal_stiffness, s.normal_stiffness),
                        (p.dlog, s.dlog),
                        (p.a_eff, s.a_eff),
                    ] {
                        assert_eq!(l.extract(lane).to_bits(), x.to_bits(), "{what}");
                    }
                }
            }
        }
    }
    assert!(compliant > 0, "a scene with a support compliance");
}

/// One lane's input of the Coulomb law: a contact that sticks or slips
/// (the old force from inside to twice outside the cone), was sliding or
/// not, on a circle (`ratio` 1) or an ellipse about the x axis.
fn coulomb_case(
    rng: &mut ChaCha8Rng,
    ratio: f64,
    law: FrictionLaw,
) -> kinrepro::contact::coulomb::CoulombInput<f64> {
    let n = Vector3::from_fn(|_, _| rng.random_range(-1.0..1.0)).normalize();
    let k0 = rng.random_range(1e7..5e7);
    let k = [k0, k0 * ratio];
    let major = if ratio == 1.0 { Vector3::zeros() } else { Vector3::x() };
    let principal = PrincipalStiffness::new([k[0], k[1]], &n, &major);
    let scaled = PrincipalStiffness::new([0.3 * k[0], 0.3 * k[1]], &n, &major);
    let (normal_force, mu_s) = (rng.random_range(1.0..100.0), rng.random_range(0.1..0.5));
    let push = Vector3::from_fn(|_, _| rng.random_range(-1.0..1.0));
    let old = (push - n * n.dot(&push)).normalize() * mu_s * normal_force;
    kinrepro::contact::coulomb::CoulombInput {
        old_force: old * rng.random_range(0.0..1.2),
        was_sliding: rng.random_bool(0.5),
        previous_velocity: rng.random_range(0.0..1e-5),
        normal: n,
        du: Vector3::from_fn(|_, _| rng.random_range(-1e-6..1e-6)),
        normal_force,
        stiffness: principal.tensor(&n),
        principal,
        d_stiffness_d_fn: scaled.tensor(&n),
        mu_s,
        mu_d: 0.8 * mu_s,
        law,
        duration: 0.1,
    }
}

/// The Coulomb law of four contacts in lanes, against the f64 law of
/// each: force, stick or slip, slip velocity and the tangent bit for bit,
/// for circles and ellipses, the switch and the decay friction law, with
/// and without the tangent, lanes that stick beside lanes that slip.
#[test]
fn the_coulomb_law_in_lanes_is_each_lanes_own() {
    use kinrepro::contact::coulomb::{CoulombInput, coulomb};
    use kinrepro::lane::Mask;
    let mut rng = ChaCha8Rng::seed_from_u64(45);
    let (mut mixed, mut tangents) = (0, 0);
    for case in 0..2000 {
        let ratio = [1.0, 1.3][case % 2];
        let law = [FrictionLaw::Switch, FrictionLaw::Decay { coefficient: 1e3 }][(case / 2) % 2];
        let tangent = (case / 4) % 2 == 0;
        let x: [CoulombInput<f64>; 4] = std::array::from_fn(|_| coulomb_case(&mut rng, ratio, law));
        let v3 = |f: &dyn Fn(&CoulombInput<f64>) -> Vector3<f64>| {
            Vector3::from_fn(|i, _| lanes(x.each_ref().map(|c| f(c)[i])))
        };
        let m3 = |f: &dyn Fn(&CoulombInput<f64>) -> Matrix3<f64>| {
            Matrix3::from_fn(|i, j| lanes(x.each_ref().map(|c| f(c)[(i, j)])))
        };
        let s = |f: &dyn Fn(&CoulombInput<f64>) -> f64| lanes(x.each_ref().map(f));
        let normal = v3(&|c| c.normal);
        let principal = PrincipalStiffness::of_lanes(
            [s(&|c| c.principal.k[0]), s(&|c| c.principal.k[1])],
            &normal,
            &if ratio == 1.0 { Vector3::zeros() } else { Vector3::x() },
        )
        .expect("one form in every lane");
        let input = CoulombInput::<F64x4> {
            old_force: v3(&|c| c.old_force),
            was_sliding: <Mask<F64x4>>::from(x.each_ref().map(|c| c.was_sliding)),
            previous_velocity: s(&|c| c.previous_velocity),
            normal,
            du: v3(&|c| c.du),
            normal_force: s(&|c| c.normal_force),
            stiffness: m3(&|c| c.stiffness),
            principal,
            d_stiffness_d_fn: m3(&|c| c.d_stiffness_d_fn),
            mu_s: s(&|c| c.mu_s),
            mu_d: s(&|c| c.mu_d),
            law,
            duration: 0.1,
        };
        let (y, t) = coulomb(&input, tangent);
        let slid: Vec<bool> = (0..4).map(|i| y.sliding.extract(i)).collect();
        mixed += usize::from(slid.iter().any(|&b| b != slid[0]));
        for (i, xi) in x.iter().enumerate() {
            let (yi, ti) = coulomb(xi, tangent);
            let what = format!("case {case} lane {i}: {xi:?}");
            assert!(same_bits(&y.force, i, &yi.force), "{what}");
            assert_eq!(y.sliding.extract(i), yi.sliding, "{what}");
            assert_eq!(y.slip_velocity.extract(i).to_bits(), yi.slip_velocity.to_bits(), "{what}");
            assert_eq!(t.is_some(), ti.is_some());
            if let (Some((d_du, d_fn)), Some((di_du, di_fn))) = (t, ti) {
                tangents += 1;
                assert!(same_bits(&d_du, i, &di_du), "{what}");
                assert!(same_bits(&d_fn, i, &di_fn), "{what}");
            }
        }
    }
    assert!(mixed > 500 && tangents > 1000, "{mixed} mixed, {tangents} tangents");
}

/// One lane of a contact evaluation: the committed pose and state (its
/// force inside or outside the cone, sliding or not, loaded or not), the
/// trial pose a small step away, and the friction.
fn contact_case(
    rng: &mut ChaCha8Rng,
    c: &kinrepro::assembly::Coupling,
    i: usize,
    law: FrictionLaw,
    loaded: bool,
) -> (BodyPose, BodyPose, TangentialState, Friction) {
    let step = |rng: &mut ChaCha8Rng, p: &BodyPose, size: f64| {
        let v = Vector3::from_fn(|_, _| rng.random_range(-size..size));
        p.moved(&v, &(turn(rng) * (size / 10.0).min(1e-4)))
    };
    let committed = step(rng, &c.touching_pose, 1e-6);
    let trial = step(rng, &committed, 2e-7);
    let n = c.geometry(i, &committed).normal;
    let mu_s = rng.random_range(0.1..0.5);
    let fc = if loaded { rng.random_range(1.0..50.0) } else { 0.0 };
    let push = Vector3::from_fn(|_, _| rng.random_range(-1.0..1.0));
    let state = TangentialState {
        force: (push - n * n.dot(&push)).normalize() * (mu_s * fc * rng.random_range(0.0..1.2)),
        sliding: rng.random_bool(0.5),
        normal_force: fc,
        slip_velocity: rng.random_range(0.0..1e-5),
        ..TangentialState::new(n)
    };
    let friction = Friction { mu_s, mu_d: 0.8 * mu_s, law, duration: 0.05 };
    (committed, trial, state, friction)
}

/// Every contact of every bundled scene with the Coulomb law evaluated
/// for four seatings at once (`solve::contact_lanes::evaluate_lanes`),
/// against the f64 contact layer of each (`contact_layer::evaluate_at`):
/// gap, normal force and stiffness, the contact's force and stiffness and
/// the trial state bit for bit, with and without the tangent, contacts
/// open and closed, sticking and slipping in the same set.
#[test]
fn contacts_evaluated_in_lanes_are_each_lanes_own() {
    use kinrepro::contact::hertz::load_roots;
    use kinrepro::solve::contact_lanes::{LaneFriction, LaneState, evaluate_lanes};
    use kinrepro::solve::contact_layer::{ContactEval, Motion, evaluate_at};
    let mut rng = ChaCha8Rng::seed_from_u64(46);
    let mut evaluated = 0;
    for (name, c) in bundled_couplings() {
        for i in 0..c.contacts.len() {
            for case in 0..40 {
                let law = [FrictionLaw::Switch, FrictionLaw::Decay { coefficient: 1e3 }][case % 2];
                let tangent = case % 4 < 2;
                let loaded = case % 8 < 6;
                let x: [_; 4] = std::array::from_fn(|_| contact_case(&mut rng, &c, i, law, loaded));
                let committed = pose_lanes(&x.each_ref().map(|x| x.0));
                let trial = pose_lanes(&x.each_ref().map(|x| x.1));
                let g = c.geometry(i, &trial);
                let du = Motion::between(&trial, &committed).displacement(&g.point);
                let states = LaneState::from_states(&x.each_ref().map(|x| &x.2));
                let friction = LaneFriction {
                    mu_s: lanes(x.each_ref().map(|x| x.3.mu_s)),
                    mu_d: lanes(x.each_ref().map(|x| x.3.mu_d)),
                    law,
                    duration: 0.05,
                };
                let root = load_roots(states.normal_force);
                let Some(e) = evaluate_lanes(&c, i, g, du, &states, root, &friction, tangent)
                else {
                    // Only what the lanes do not follow (module docs): the
                    // Mindlin-Deresiewicz law, an anisotropic support, and
                    // an ellipse unloaded (k = 0, a circle) in some lanes only.
                    let law = c.friction.tangential;
                    let anisotropic = !c.contacts[i].law.tangential_support.is_isotropic();
                    let open = (0..4).filter(|&l| g.gap.extract(l) >= 0.0).count();
                    let mixed = !loaded && open > 0 && open < 4;
                    assert!(
                        law != kinrepro::contact::TangentialLaw::Coulomb || anisotropic || mixed,
                        "{name} contact {i} case {case}"
                    );
                    continue;
                };
                evaluated += 1;
                for (lane, (committed, trial, state, friction)) in x.iter().enumerate() {
                    let mut s = ContactEval::empty();
                    let back = Motion::between(trial, committed);
                    evaluate_at(&mut s, &c, i, trial, &back, state, *friction, tangent);
                    let what = format!("{name} contact {i} case {case} lane {lane}");
                    let bits = |a: f64, b: f64| a.to_bits() == b.to_bits();
                    assert!(bits(e.geometry.gap.extract(lane), s.geometry.gap), "{what}");
                    assert!(bits(e.approach.extract(lane), s.approach), "{what}");
                    assert!(bits(e.normal_force.extract(lane), s.normal_force), "{what}");
                    assert!(bits(e.normal_stiffness.extract(lane), s.normal_stiffness), "{what}");
                    assert!(same_bits(&e.force, lane, &s.force), "{what}");
                    if tangent {
                        assert!(same_bits(&e.stiffness, lane, &s.stiffness), "{what}");
                    }
                    let (a, b) = (e.state.lane(lane), &s.tangential.state);
                    assert!(a.normal == b.normal && a.sliding == b.sliding, "{what}");
                    assert!(same_bits(&e.state.force, lane, &b.force), "{what}");
                    assert!(bits(a.normal_force, b.normal_force), "{what}");
                    assert!(bits(a.slip_velocity, b.slip_velocity), "{what}");
                }
            }
        }
    }
    assert!(evaluated > 1000, "{evaluated}");
}

/// The preload forces (springs, weights, constant forces, magnets) of
/// every bundled scene at four poses at once: each lane's force, point
/// and stiffness bit for bit its f64 value.
#[test]
fn preload_forces_in_lanes_are_each_lanes_own() {
    use kinrepro::solve::preload_forces::applied;
    let mut rng = ChaCha8Rng::seed_from_u64(47);
    let mut magnets = 0;
    for (name, c) in bundled_couplings() {
        let scene = kinrepro::scene::Scene::load(std::path::Path::new(&name)).unwrap();
        let preload = &scene.preload;
        magnets += preload
            .forces
            .iter()
            .filter(|f| matches!(f.law, kinrepro::scene::ForceLaw::Magnet(_)))
            .count();
        for _ in 0..20 {
            let poses: [BodyPose; 4] = std::array::from_fn(|_| {
                let v = Vector3::from_fn(|_, _| rng.random_range(-2e-6..2e-6));
                c.touching_pose.moved(&v, &(turn(&mut rng) * 1e-4))
            });
            let lambda = rng.random_range(0.0..1.0);
            let at = pose_lanes(&poses);
            let forces: Vec<_> = applied(&c, preload, &at, lambda).collect();
            for (l, pose) in poses.iter().enumerate() {
                for (a, s) in forces.iter().zip(applied(&c, preload, pose, lambda)) {
                    assert!(same_bits(&a.force, l, &s.force), "{name}");
                    assert!(same_bits(&a.point, l, &s.point), "{name}");
                    assert_eq!(a.stiffness.is_some(), s.stiffness.is_some());
                    if let (Some(a), Some(s)) = (a.stiffness, s.stiffness) {
                        assert!(same_bits(&a, l, &s), "{name}");
                    }
                }
            }
        }
    }
    assert!(magnets > 0, "a scene with a magnet");
}

/// Four seatings at once (`quasistatic::seat4_in`: lanes, with the
/// error-controlled levels and the Richardson pose) against `seat_in` of
/// each load, for every paper scene: the same `SeatedPose` bit for bit
/// (pose, increments, Newton count, path error, slid), for sets the lanes
/// follow and for sets with a lane they cannot (a preload of its own, a
/// mu out of range: that lane seated alone, its error its own).
#[test]
fn four_seatings_at_once_are_each_seatings_own() {
    use kinrepro::solve::quasistatic::{SeatingSetup, Workspace, seat_in, seat4_in};
    use kinrepro::solve::{Load, SolverOptions};
    let mut rng = ChaCha8Rng::seed_from_u64(48);
    let dir = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes");
    for k in 1..=7 {
        let name = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().path())
            .find(|p| p.file_name().unwrap().to_str().unwrap().starts_with(&format!("0{k}_")))
            .unwrap();
        let scene = kinrepro::scene::Scene::load(&name).unwrap();
        let c = kinrepro::assembly::Coupling::new(&scene).unwrap();
        let nominal = Load::nominal(&scene);
        let setup = SeatingSetup::new(&c, &nominal.preload);
        for (set, opts) in [
            SolverOptions::default(),
            SolverOptions { path_tolerance: None, ..SolverOptions::default() },
        ]
        .iter()
        .cycle()
        .take(6)
        .enumerate()
        {
            let mut loads: Vec<Load> = (0..4)
                .map(|_| {
                    nominal
                        .with_mu(&(0..6).map(|_| rng.random_range(0.05..0.3)).collect::<Vec<_>>())
                })
                .collect();
            if set == 4 {
                loads[1].preload.ramp_time *= 2.0;
            }
            if set == 5 {
                loads[2] = nominal.with_mu(&[0.1, 0.1, 99.0, 0.1, 0.1, 0.1]);
            }
            let mut ws = Workspace::new();
            let four =
                seat4_in(&setup, [&loads[0], &loads[1], &loads[2], &loads[3]], opts, &mut ws);
            for (l, (got, load)) in four.iter().zip(&loads).enumerate() {
                let alone = seat_in(&setup, load, opts, &mut Workspace::new());
                let what = format!("{} set {set} lane {l}", name.display());
                match (got, &alone) {
                    (Ok(a), Ok(b)) => {
                        assert!(
                            same_bits(
                                &a.pose.rotation.coords.map(F64x4::splat),
                                0,
                                &b.pose.rotation.coords
                            ),
                            "{what}"
                        );
                        assert!(
                            same_bits(
                                &a.pose.translation.map(F64x4::splat),
                                0,
                                &b.pose.translation
                            ),
                            "{what}"
                        );
                        assert_eq!(
                            (a.increments, a.newton_iterations, a.path, a.slid),
                            (b.increments, b.newton_iterations, b.path, b.slid),
                            "{what}"
                        );
                        assert_eq!(
                            a.path_error.map(f64::to_bits),
                            b.path_error.map(f64::to_bits),
                            "{what}"
                        );
                        assert_eq!(
                            a.decay_cv.map(f64::to_bits),
                            b.decay_cv.map(f64::to_bits),
                            "{what}"
                        );
                    }
                    (Err(a), Err(b)) => assert_eq!(a.to_string(), b.to_string(), "{what}"),
                    _ => panic!("{what}: {got:?} against {alone:?}"),
                }
            }
        }
    }
}

/// A build runs on the machine it was built for: no instruction-set
/// extension it was compiled to use is missing here (the check the CLI
/// makes before anything else), and the study's `auto` lanes follow what
/// this build was compiled for.
#[test]
fn this_build_runs_here_and_auto_lanes_follow_the_build() {
    use kinrepro::solve::quasistatic::{LANES_ARE_FAST, Lanes};
    assert_eq!(kinrepro::lane::missing_cpu_features(), Vec::<&str>::new());
    assert_eq!(kinrepro::lane::cpu_mismatch(), None);
    assert_eq!(Lanes::Auto.used(), cfg!(target_feature = "avx"));
    assert_eq!(Lanes::Auto.used(), LANES_ARE_FAST);
    assert!(Lanes::On.used() && !Lanes::Off.used());
}
