//! One full quasi-static seating of scenes 01 (Maxwell, planes) and 06 (Kelvin).

use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::solve::SolverOptions;
use kinrepro::solve::quasistatic::seat;

fn seating(c: &mut Criterion) {
    for name in ["01_maxwell_vgroove_steel.toml", "06_kelvin_steel.toml"] {
        let path = Path::new(env!("CARGO_MANIFEST_DIR"))
            .join("scenes")
            .join(name);
        let coupling = kinrepro::error::load_coupling(&path).unwrap();
        let mu = [0.46, 0.53, 0.51, 0.47, 0.545, 0.455];
        c.bench_function(&format!("quasi-static seating/{name}"), |b| {
            b.iter(|| {
                seat(
                    black_box(&coupling),
                    black_box(&mu),
                    &SolverOptions::default(),
                )
                .unwrap()
            })
        });
    }
}

criterion_group!(benches, seating);
criterion_main!(benches);
