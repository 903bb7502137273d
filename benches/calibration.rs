//! `calibrate` of the worked example's 50-cycle measurement of scene 02
//! with one fitted parameter (three 2000-sample model studies; issue 15
//! asks for under 10 s on 2 cores) and with two (spread, mu_static: two passes
//! of a 9-node grid plus one direct study, 19 studies of 2000 samples).

use std::path::Path;

use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::calibrate::fit::CalibrateOptions;
use kinrepro::calibrate::model::{MODEL_SAMPLES, MODEL_SEED};
use kinrepro::calibrate::{Measurement, calibrate};
use kinrepro::solve::Solver;

fn calibration(c: &mut Criterion) {
    let root = Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/.."));
    let (scene, coupling) =
        kinrepro::error::read_scene(&root.join("scenes/02_maxwell_pins_steel.toml")).unwrap();
    let m = Measurement::load(&root.join("docs/calibration/measured_02.csv"), None).unwrap();
    let opts = CalibrateOptions {
        fit: vec!["spread".into()],
        noise: [None; 6],
        point: None,
        samples: MODEL_SAMPLES,
        seed: MODEL_SEED,
        solver: Solver::QuasiStatic,
    };
    let two = CalibrateOptions { fit: vec!["spread".into(), "mu_static".into()], ..opts.clone() };
    let mut g = c.benchmark_group("calibration");
    g.sample_size(10);
    g.bench_function("scene 02, 50 cycles, fit spread", |b| {
        b.iter(|| calibrate(&scene, &coupling, &m, &opts).unwrap())
    });
    g.bench_function("scene 02, 50 cycles, fit spread,mu_static", |b| {
        b.iter(|| calibrate(&scene, &coupling, &m, &two).unwrap())
    });
    g.finish();
}

criterion_group!(benches, calibration);
criterion_main!(benches);
