//! One quasi-static seating of scenes 01 (Maxwell, V-grooves), 02 (Maxwell,
//! pins) and 06 (Kelvin) on each path: `seat` (the uniform fast path, which
//! serves these friction vectors) and `seat_adaptive` (the adaptive path
//! alone: today's algorithm, the reference of the fast one); and the fast
//! path with the coupling's set-up shared as in a study (`seat_prepared`),
//! and as a study runs it: set-up shared and the buffers of one reused
//! workspace, pose only (`seat_in`). And one contact's geometry (the first
//! contact of each scene: a plane, a pin, a seat plane) by parry's query
//! (the adaptive path's) and by parry's arithmetic written out
//! (`assembly::parry_inline`, the fast path's; the same bits).

use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::solve::quasistatic::{
    SeatingSetup, Workspace, seat, seat_adaptive, seat_in, seat_prepared,
};
use kinrepro::solve::{SeatingPath, SolverOptions};
use nalgebra::Vector3;

fn seating(c: &mut Criterion) {
    for name in [
        "01_maxwell_vgroove_steel.toml",
        "02_maxwell_pins_steel.toml",
        "06_kelvin_steel.toml",
    ] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("scenes")
            .join(name);
        let coupling = kinrepro::error::read_coupling(&path).unwrap();
        let mu = [0.46, 0.53, 0.51, 0.47, 0.545, 0.455];
        let opts = SolverOptions::default();
        let served = seat(&coupling, &mu, &opts).unwrap().path;
        assert_eq!(
            served,
            SeatingPath::Uniform,
            "{name}: the fast path declined"
        );
        c.bench_function(&format!("quasi-static seating/uniform/{name}"), |b| {
            b.iter(|| seat(black_box(&coupling), black_box(&mu), &opts).unwrap())
        });
        let setup = SeatingSetup::new(&coupling);
        c.bench_function(&format!("quasi-static seating/shared-setup/{name}"), |b| {
            b.iter(|| seat_prepared(black_box(&setup), black_box(&mu), &opts).unwrap())
        });
        let mut ws = Workspace::new();
        c.bench_function(&format!("quasi-static seating/workspace/{name}"), |b| {
            b.iter(|| seat_in(black_box(&setup), black_box(&mu), &opts, &mut ws).unwrap())
        });
        c.bench_function(&format!("quasi-static seating/adaptive/{name}"), |b| {
            b.iter(|| seat_adaptive(black_box(&coupling), black_box(&mu), &opts).unwrap())
        });
        // The ball pressed 0.5 um into its first surface and moved sideways.
        let ball = &coupling.balls[coupling.contacts[0].ball];
        let n = coupling.geometry(0, &coupling.touching_pose).normal;
        let centre = ball.centre - n * 5e-7 + Vector3::new(1e-7, -2e-7, 0.0);
        for (label, inline) in [("parry", false), ("inline", true)] {
            c.bench_function(&format!("contact geometry/{label}/{name}"), |b| {
                b.iter(|| {
                    let centre = black_box(&centre);
                    if inline {
                        coupling.geometry_inline_at(0, centre)
                    } else {
                        coupling.geometry_at(0, centre)
                    }
                })
            });
        }
    }
}

criterion_group!(benches, seating);
criterion_main!(benches);
