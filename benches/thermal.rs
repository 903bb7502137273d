//! Thermal drift (issue 38): a study of the bundled aluminium-on-Invar
//! scene with its two-point `[thermal]` cycle against the same study of
//! the scene without `[thermal]` (2000 Monte Carlo samples each; the
//! issue asks for at most 4 times), and one thermal path of the
//! `thermal` command (seating, cycle, first slip located) at unequal mu.

use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::scene::Scene;
use kinrepro::solve::quasistatic::seat_and_cycle;
use kinrepro::solve::{Load, SolverOptions};
use kinrepro::study::runner::run_variant;
use kinrepro::study::{Sampler, StudyOptions, StudyPlan};

const SCENE: &str = "scenes/maxwell_thermal_alu_invar.toml";

/// The scene's text without its `[thermal]` table.
fn without_thermal(text: &str) -> String {
    let start = text.find("[thermal]").unwrap();
    let end = start + text[start..].find("[[evaluation_points]]").unwrap();
    format!("{}{}", &text[..start], &text[end..])
}

fn thermal(c: &mut Criterion) {
    let text =
        std::fs::read_to_string(Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/..")).join(SCENE))
            .unwrap();
    let opts = StudyOptions {
        sampler: Some(Sampler::MonteCarlo),
        samples: Some(2000),
        ..StudyOptions::default()
    };
    let plan = |t: &str| {
        let model = kinrepro::error::parse_scene(t, SCENE).unwrap();
        StudyPlan::new(vec![model], &opts).unwrap()
    };
    let (with, without) = (plan(&text), plan(&without_thermal(&text)));
    let mut g = c.benchmark_group("thermal");
    g.sample_size(10);
    for (name, p) in
        [("study 2000 MC, two-point cycle", &with), ("study 2000 MC, no [thermal]", &without)]
    {
        g.bench_function(name, |b| {
            b.iter(|| run_variant(&p.settings, &p.variants[0], &|| {}).unwrap())
        });
    }
    let scene = Scene::parse(&text, SCENE).unwrap();
    let coupling = kinrepro::assembly::Coupling::new(&scene).unwrap();
    let load = Load::nominal(&scene).with_mu(&[0.45, 0.5, 0.55, 0.48, 0.52, 0.47]);
    g.bench_function("one thermal path, unequal mu", |b| {
        b.iter(|| seat_and_cycle(&coupling, &load, &SolverOptions::default()).unwrap())
    });
    g.finish();
}

criterion_group!(benches, thermal);
criterion_main!(benches);
