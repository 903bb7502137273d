//! One quasi-static seating of scenes 01 (Maxwell, V-grooves), 02 (Maxwell,
//! pins) and 06 (Kelvin): `seat` (set-up, a fresh workspace and the
//! per-contact report included) and the seat kernel as a study runs it
//! (`seat_in`: set-up shared, the buffers of one reused workspace, pose
//! only), and four seatings of different mu as a study would seat them:
//! `seat_in` four times (`four seatings/f64`) against `seat4_in`, one
//! seating per SIMD lane (`four seatings/lanes`). And one contact's geometry (the first contact of each scene: a
//! plane, a pin, a seat plane) by the closed form the solvers call
//! (`assembly::geometry::contact`) and by parry's query, its reference.

use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::assembly::geometry::{contact, parry_shape};
use kinrepro::solve::quasistatic::{SeatingSetup, Workspace, seat, seat_in, seat4_in};
use kinrepro::solve::{Load, SeatingPath, SolverOptions};
use nalgebra::Vector3;
use parry3d_f64::math::{Pose, Vector};
use parry3d_f64::query;
use parry3d_f64::shape::Ball;

fn seating(c: &mut Criterion) {
    for name in
        ["01_maxwell_vgroove_steel.toml", "02_maxwell_pins_steel.toml", "06_kelvin_steel.toml"]
    {
        let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/..")).join("scenes").join(name);
        let (scene, coupling) = kinrepro::error::read_scene(&path).unwrap();
        let mu = Load::nominal(&scene).with_mu(&[0.46, 0.53, 0.51, 0.47, 0.545, 0.455]);
        let opts = SolverOptions::default();
        let served = seat(&coupling, &mu, &opts).unwrap().seated.path;
        assert_eq!(served, SeatingPath::Uniform, "{name}: an increment halved");
        c.bench_function(&format!("quasi-static seating/seat/{name}"), |b| {
            b.iter(|| seat(black_box(&coupling), black_box(&mu), &opts).unwrap())
        });
        let setup = SeatingSetup::new(&coupling, &scene.preload);
        let mut ws = Workspace::new();
        c.bench_function(&format!("quasi-static seating/workspace/{name}"), |b| {
            b.iter(|| seat_in(black_box(&setup), black_box(&mu), &opts, &mut ws).unwrap())
        });
        let four: Vec<Load> = [0.0, 0.02, -0.03, 0.05]
            .iter()
            .map(|d| {
                let mu = [0.46, 0.53, 0.51, 0.47, 0.545, 0.455].map(|m| m + d);
                Load::nominal(&scene).with_mu(&mu)
            })
            .collect();
        let four = [&four[0], &four[1], &four[2], &four[3]];
        c.bench_function(&format!("four seatings/f64/{name}"), |b| {
            b.iter(|| {
                four.map(|l| seat_in(black_box(&setup), black_box(l), &opts, &mut ws).unwrap())
            })
        });
        c.bench_function(&format!("four seatings/lanes/{name}"), |b| {
            b.iter(|| seat4_in(black_box(&setup), black_box(four), &opts, &mut ws))
        });
        // The ball pressed 0.5 um into its first surface and moved sideways.
        let k = &coupling.contacts[0];
        let ball = &coupling.balls[k.ball];
        let n = coupling.geometry(0, &coupling.touching_pose).normal;
        let centre = ball.centre - n * 5e-7 + Vector3::new(1e-7, -2e-7, 0.0);
        c.bench_function(&format!("contact geometry/closed form/{name}"), |b| {
            b.iter(|| contact(&k.surface, black_box(&centre), ball.radius))
        });
        let (shape, pose) = parry_shape(&k.surface, &ball.centre, 0.05);
        let sphere = Ball::new(ball.radius);
        c.bench_function(&format!("contact geometry/parry/{name}"), |b| {
            b.iter(|| {
                let at = black_box(&centre);
                let at = Pose::from_translation(Vector::new(at.x, at.y, at.z));
                query::contact(&pose, &*shape, &at, &sphere, 1e-2)
            })
        });
    }
}

criterion_group!(benches, seating);
criterion_main!(benches);
