//! Bundled scenes: load, expand and load back identically; exactly
//! constrained; contact normals at the angles of MODEL.md §1a; balls touch
//! at zero gap; parry's contact geometry equals the closed forms.

use std::path::{Path, PathBuf};

use kinrepro::assembly::geometry::closed_form;
use kinrepro::assembly::{BodyPose, Coupling, constraint};
use kinrepro::scene::{Scene, SurfaceGeometry};
use nalgebra::Vector3;

const PAPER_SCENES: [&str; 7] = [
    "01_maxwell_vgroove_steel.toml",
    "02_maxwell_pins_steel.toml",
    "03_maxwell_pins_sic.toml",
    "04_maxwell_balls_steel.toml",
    "05_maxwell_balls_sic.toml",
    "06_kelvin_steel.toml",
    "07_kelvin_sic.toml",
];

fn scene_path(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
}

fn all_scenes() -> Vec<PathBuf> {
    let mut v: Vec<PathBuf> = PAPER_SCENES.iter().map(|n| scene_path(n)).collect();
    v.push(scene_path("custom_kelvin_explicit.toml"));
    v
}

/// Scenes compare equal apart from source lines (which differ between the
/// high-level file and its expansion).
fn strip_lines(mut s: Scene) -> Scene {
    s.balls.iter_mut().for_each(|b| b.line = None);
    s.surfaces.iter_mut().for_each(|b| b.line = None);
    s
}

#[test]
fn every_scene_loads_expands_and_loads_back_identically() {
    for path in all_scenes() {
        let file = path.display().to_string();
        let source = std::fs::read_to_string(&path).unwrap();
        let scene = Scene::parse(&source, &file).unwrap();
        let text = Scene::expand_text(&source, &file).unwrap();
        let back = Scene::parse(&text, &file).unwrap();
        assert_eq!(
            strip_lines(scene.clone()),
            strip_lines(back.clone()),
            "{file}"
        );
        // Expanding the explicit form again is a fixed point.
        assert_eq!(Scene::expand_text(&text, &file).unwrap(), text);
        let c = Coupling::new(&scene).unwrap();
        let report = constraint::analyse(&c);
        assert!(report.exactly_constrained, "{file}: {}", report.describe());
        assert!(report.condition_number < 10.0);
    }
}

#[test]
fn balls_touch_every_surface_at_zero_gap() {
    for path in all_scenes() {
        let c = kinrepro::error::load_coupling(&path).unwrap();
        for i in 0..6 {
            let g = c.geometry(i, &c.touching_pose);
            assert!(
                g.gap.abs() < 1e-15,
                "{path:?} contact {}: gap {:e}",
                i + 1,
                g.gap
            );
        }
    }
}

#[test]
fn contact_normals_follow_the_conventions() {
    let alpha = 45f64.to_radians();
    let ez = Vector3::z();
    for name in PAPER_SCENES {
        let c = kinrepro::error::load_coupling(&scene_path(name)).unwrap();
        let centre = |k: usize| c.balls[k].centre;
        // Ball azimuths 90, 210, 330 degrees on the 80 mm circle.
        for (k, az) in [90.0f64, 210.0, 330.0].iter().enumerate() {
            let t = az.to_radians();
            let expect = Vector3::new(t.cos(), t.sin(), 0.0) * 0.040;
            assert!((centre(k) - expect).norm() < 1e-17);
        }
        let n = |i: usize| c.geometry(i, &BodyPose::identity()).normal;
        let kelvin = name.contains("kelvin");
        let vees: Vec<(usize, usize, Vector3<f64>)> = if kelvin {
            // Ball 2's V points at ball 1: contacts 4, 5 with e_r -> unit(c1 - c2).
            vec![(3, 1, (centre(0) - centre(1)).normalize())]
        } else {
            (0..3).map(|k| (2 * k, k, centre(k).normalize())).collect()
        };
        for (first, _ball, er) in vees {
            let s = ez.cross(&er);
            let n1 = s * alpha.sin() + ez * alpha.cos();
            let n2 = -s * alpha.sin() + ez * alpha.cos();
            assert!(
                (n(first) - n1).norm() < 1e-15,
                "{name}: contact {}",
                first + 1
            );
            assert!(
                (n(first + 1) - n2).norm() < 1e-15,
                "{name}: contact {}",
                first + 2
            );
        }
        if kelvin {
            // Trihedral seat: first element radially inward, then +120, +240 deg
            // counter-clockwise; each normal 45 deg from z, pointing from the element
            // into the ball.
            let er = centre(0).normalize();
            for j in 0..3 {
                let a = (120.0 * j as f64).to_radians();
                let d = Vector3::new(
                    -er.x * a.cos() + er.y * a.sin(),
                    -er.x * a.sin() - er.y * a.cos(),
                    0.0,
                );
                let expect = -d * alpha.sin() + ez * alpha.cos();
                assert!(
                    (n(j) - expect).norm() < 1e-15,
                    "{name}: trihedral contact {}",
                    j + 1
                );
            }
            assert!((n(5) - ez).norm() < 1e-15);
        }
        for i in 0..6 {
            let angle = n(i).dot(&ez).acos();
            let expect = if kelvin && i == 5 { 0.0 } else { alpha };
            assert!((angle - expect).abs() < 1e-12, "{name} contact {}", i + 1);
        }
    }
}

#[test]
fn parry_contact_matches_closed_form() {
    // One of each pair type, from the bundled scenes, with the ball moved
    // along the normal to separations and penetrations from 1 nm to 1 um,
    // and sideways so the normal changes.
    for name in [
        "01_maxwell_vgroove_steel.toml",
        "02_maxwell_pins_steel.toml",
        "04_maxwell_balls_steel.toml",
    ] {
        let c = kinrepro::error::load_coupling(&scene_path(name)).unwrap();
        for (i, contact) in c.contacts.iter().enumerate() {
            let ball = &c.balls[contact.ball];
            let n0 = closed_form(&contact.surface, &ball.centre, ball.radius).normal;
            let side = n0.cross(&Vector3::z()).normalize();
            for d in [1e-9, 1e-8, 1e-7, 1e-6, -1e-9, -1e-8, -1e-7, -1e-6] {
                for lateral in [0.0, 3e-7] {
                    let centre = ball.centre + n0 * d + side * lateral;
                    let exact = closed_form(&contact.surface, &centre, ball.radius);
                    let parry = contact.fixed.contact(&centre, ball.radius, 1e-3).unwrap();
                    assert!(
                        (parry.gap - exact.gap).abs() < 1e-12,
                        "{name} contact {}: d {d:e}: parry {:e} vs {:e}",
                        i + 1,
                        parry.gap,
                        exact.gap
                    );
                    assert!(
                        (parry.gap - exact.gap).abs() < 1e-16,
                        "{name}: {:e}",
                        parry.gap - exact.gap
                    );
                    assert!((parry.normal - exact.normal).norm() < 1e-12);
                    assert!((parry.point - exact.point).norm() < 1e-12);
                    if lateral == 0.0
                        && !matches!(contact.surface, SurfaceGeometry::Cylinder { .. })
                    {
                        assert!((exact.gap - d).abs() < 1e-17);
                    }
                }
            }
        }
    }
}

#[test]
fn friction_limit_is_scale_free_and_grows_with_groove_steepness() {
    let base = std::fs::read_to_string(scene_path("01_maxwell_vgroove_steel.toml")).unwrap();
    let limit = |src: &str| {
        let s = Scene::parse(src, "t.toml").unwrap();
        constraint::friction_limit(&Coupling::new(&s).unwrap()).mu_limit
    };
    let l0 = limit(&base);
    // Scale-free: preload and size do not change a friction coefficient.
    let scaled = base
        .replace("force = 20.0", "force = 500.0")
        .replace("diameter = 0.080", "diameter = 0.300")
        .replace("ball_diameter = 0.010", "ball_diameter = 0.0375");
    assert!(
        (limit(&scaled) - l0).abs() < 2e-4,
        "{} vs {l0}",
        limit(&scaled)
    );
    // Steeper flanks (smaller opening angle) centre better.
    let steep = base.replace("opening_angle_deg = 90.0", "opening_angle_deg = 70.0");
    let flat = base.replace("opening_angle_deg = 90.0", "opening_angle_deg = 120.0");
    assert!(limit(&steep) > l0 && l0 > limit(&flat));
    assert!(l0 > 0.0 && l0 < 1.0);
}
