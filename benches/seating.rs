//! One quasi-static seating of scenes 01 (Maxwell, V-grooves), 02 (Maxwell,
//! pins) and 06 (Kelvin) on each path: `seat` (the uniform fast path, which
//! serves these friction vectors) and `seat_adaptive` (the adaptive path
//! alone: today's algorithm, the reference of the fast one); and the fast
//! path with the coupling's set-up shared as in a study (`seat_prepared`),
//! and as a study runs it: set-up shared and the buffers of one reused
//! workspace, pose only (`seat_in`).

use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::solve::quasistatic::{
    SeatingSetup, Workspace, seat, seat_adaptive, seat_in, seat_prepared,
};
use kinrepro::solve::{SeatingPath, SolverOptions};

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
    }
}

criterion_group!(benches, seating);
criterion_main!(benches);
