//! Studies: the seven bundled scenes at 25 LHS samples (a full Table 2
//! study), the seven at 2000 Monte Carlo samples, scenes 01, 02 and 06
//! each at 1000 Monte Carlo samples (by default, and one seating at a
//! time: `lanes` off), and 10^5 Monte Carlo
//! samples of scene 01 streamed into moments (chunks of 8192, the route of
//! large studies, `study::stream`). rayon uses every core.

use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::assembly::Coupling;
use kinrepro::scene::Scene;
use kinrepro::solve::quasistatic::Lanes;
use kinrepro::study::runner::{output_names, run_chunked, run_variant};
use kinrepro::study::stream::StreamStats;
use kinrepro::study::{Sampler, StudyOptions, StudyPlan};

const SCENES: [&str; 7] = [
    "01_maxwell_vgroove_steel.toml",
    "02_maxwell_pins_steel.toml",
    "03_maxwell_pins_sic.toml",
    "04_maxwell_balls_steel.toml",
    "05_maxwell_balls_sic.toml",
    "06_kelvin_steel.toml",
    "07_kelvin_sic.toml",
];

fn load(name: &str) -> (Scene, Coupling) {
    kinrepro::error::read_scene(
        &Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/..")).join("scenes").join(name),
    )
    .unwrap()
}

fn mc(samples: usize) -> StudyOptions {
    StudyOptions {
        sampler: Some(Sampler::MonteCarlo),
        samples: Some(samples),
        ..StudyOptions::default()
    }
}

/// The plan of the seven scenes under `opts` (checked once, outside the
/// timed runs).
fn plan(opts: &StudyOptions) -> StudyPlan {
    StudyPlan::new(SCENES.iter().map(|n| load(n)).collect(), opts).unwrap()
}

fn study(c: &mut Criterion) {
    let mut g = c.benchmark_group("study");
    g.sample_size(10);
    let lhs = plan(&StudyOptions::default());
    g.bench_function("seven scenes x 25 LHS samples", |b| {
        b.iter(|| {
            for v in &lhs.variants {
                run_variant(&lhs.settings, v, &|| {}).unwrap();
            }
        })
    });
    let mc2000 = plan(&mc(2000));
    g.bench_function("seven scenes x 2000 MC samples", |b| {
        b.iter(|| {
            for v in &mc2000.variants {
                run_variant(&mc2000.settings, v, &|| {}).unwrap();
            }
        })
    });
    // The default (`lanes` auto: four seatings at a time in lanes where the
    // build has AVX) and one seating at a time.
    for (i, name) in [(0, "01"), (1, "02"), (5, "06")] {
        for (lanes, how) in [(Lanes::Auto, ""), (Lanes::Off, ", lanes off")] {
            let opts = StudyOptions { lanes, ..mc(1000) };
            let one = StudyPlan::new(vec![load(SCENES[i])], &opts).unwrap();
            g.bench_function(format!("scene {name} x 1000 MC samples{how}"), |b| {
                b.iter(|| run_variant(&one.settings, &one.variants[0], &|| {}).unwrap())
            });
        }
    }
    let streamed = StudyPlan::new(vec![load(SCENES[0])], &mc(100_000)).unwrap();
    let scene01 = &streamed.variants[0];
    let names = output_names(&scene01.scene);
    g.bench_function("scene 01 x 10^5 MC samples, streamed", |b| {
        b.iter(|| {
            let mut stats = StreamStats::new(names.len());
            run_chunked(&streamed.settings, scene01, 8192, &|| {}, &mut |records| {
                stats.push(&records, &names).unwrap();
                Ok(())
            })
            .unwrap();
            stats
        })
    });
    g.finish();
}

criterion_group!(benches, study);
criterion_main!(benches);
