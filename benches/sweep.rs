//! A sweep of scene 01: an 8 x 8 grid (preload x opening angle) with 500
//! Monte Carlo samples per design point, 32 000 seatings (issue 14's
//! target: under 30 s on 2 cores), and a 4 x 4 grid at 25 LHS samples.

use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::explore::run::{run, study_plan};
use kinrepro::explore::{DesignKind, SweepSpec};
use kinrepro::study::{Sampler, Shard, StudyOptions, Varied};

fn sweep(c: &mut Criterion) {
    let path = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."))
        .join("scenes/01_maxwell_vgroove_steel.toml");
    let text = std::fs::read_to_string(&path).unwrap();
    let (scene, base) = kinrepro::error::read_scene(&path).unwrap();
    let mut g = c.benchmark_group("sweep");
    g.sample_size(10);
    for (label, grid, sampler, samples) in [
        (
            "4 x 4 grid x 25 LHS samples",
            ["preload.force=5:40:4", "coupling.opening_angle_deg=60:120:4"],
            Sampler::Lhs,
            25,
        ),
        (
            "8 x 8 grid x 500 MC samples",
            ["preload.force=5:40:8", "coupling.opening_angle_deg=60:120:8"],
            Sampler::MonteCarlo,
            500,
        ),
    ] {
        let sets: Vec<String> = grid.iter().map(|s| s.to_string()).collect();
        let spec = SweepSpec::new("scene01", &text, &sets, DesignKind::Grid).unwrap();
        let opts = StudyOptions {
            sampler: Some(sampler),
            samples: Some(samples),
            vary: vec![Varied::Friction],
            ..Default::default()
        };
        let plan = study_plan(scene.clone(), base.clone(), &opts).unwrap();
        g.bench_function(label, |b| {
            b.iter(|| {
                run(&spec, &plan, Shard::whole(), (None, &Default::default()), &|| {}).unwrap()
            })
        });
    }
    g.finish();
}

criterion_group!(benches, sweep);
criterion_main!(benches);
