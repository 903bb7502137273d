//! One dynamic seating of scenes 01 (Maxwell, V-groove of planes, steel)
//! and 06 (Kelvin, steel), from the touching pose with the nominal
//! friction and default options.

use std::hint::black_box;
use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::solve::dynamic::{DynamicOptions, seat};

fn dynamic_seating(c: &mut Criterion) {
    for name in ["01_maxwell_vgroove_steel", "06_kelvin_steel"] {
        let (scene, coupling) = kinrepro::error::read_scene(
            &Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
                .join(format!("scenes/{name}.toml")),
        )
        .unwrap();
        let mu = kinrepro::solve::Load::nominal(&scene);
        let opts = DynamicOptions::default();
        let id = format!("dynamic seating, scene {}", &name[..2]);
        c.bench_function(&id, |b| {
            b.iter(|| seat(black_box(&coupling), black_box(&mu), &opts).unwrap())
        });
    }
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = dynamic_seating
}
criterion_main!(benches);
