//! One dynamic seating of scene 01 (Maxwell, V-groove of planes, steel),
//! from the touching pose with the nominal friction and default options.

use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::solve::dynamic::{DynamicOptions, seat};

fn dynamic_seating(c: &mut Criterion) {
    let (scene, coupling) = kinrepro::error::read_scene(
        &Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
            .join("scenes/01_maxwell_vgroove_steel.toml"),
    )
    .unwrap();
    let mu = kinrepro::solve::Load::nominal(&scene);
    let opts = DynamicOptions::default();
    c.bench_function("dynamic seating, scene 01", |b| {
        b.iter(|| seat(black_box(&coupling), black_box(&mu), &opts).unwrap())
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = dynamic_seating
}
criterion_main!(benches);
