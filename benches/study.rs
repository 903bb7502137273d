//! The seven bundled scenes at 25 LHS samples: a full Table 2 study.

use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::study::runner::{StudyOptions, run_variant};

fn study(c: &mut Criterion) {
    let couplings: Vec<_> = [
        "01_maxwell_vgroove_steel.toml",
        "02_maxwell_pins_steel.toml",
        "03_maxwell_pins_sic.toml",
        "04_maxwell_balls_steel.toml",
        "05_maxwell_balls_sic.toml",
        "06_kelvin_steel.toml",
        "07_kelvin_sic.toml",
    ]
    .iter()
    .map(|n| {
        kinrepro::error::load_coupling(
            &Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes").join(n),
        )
        .unwrap()
    })
    .collect();
    let mut g = c.benchmark_group("study");
    g.sample_size(20);
    g.bench_function("seven scenes x 25 LHS samples", |b| {
        b.iter(|| {
            for coupling in &couplings {
                run_variant(coupling, &StudyOptions::default(), &|| {}).unwrap();
            }
        })
    });
    g.finish();
}

criterion_group!(benches, study);
criterion_main!(benches);
