//! `kinrepro check` on many surfaces: parsing and validating a scene of m
//! surfaces, and the constraint analysis of m contacts. Both should grow
//! about linearly in m (issue 12: 3000 surfaces took 24 s when the analysis
//! decomposed the m x m matrix A A^T and line numbers were counted from the
//! file's start for every surface). And the friction limit for seating of
//! scenes 01, 02 and 06, solved anew (every study and `check` solves it
//! once per geometry).

use std::hint::black_box;
use std::path::Path;

use criterion::{BenchmarkId, Criterion, criterion_group, criterion_main};
use kinrepro::assembly::constraint::analyse;
use kinrepro::assembly::friction_limit::friction_limit_solved_anew;
use kinrepro::scene::Scene;

fn scene(name: &str) -> std::path::PathBuf {
    Path::new(concat!(env!("CARGO_MANIFEST_DIR"), "/..")).join("scenes").join(name)
}

fn scene01() -> std::path::PathBuf {
    scene("01_maxwell_vgroove_steel.toml")
}

/// Scene 01 in explicit form with its first surface repeated up to `m` surfaces.
fn many_surfaces(m: usize) -> String {
    let text = Scene::expand_text(&std::fs::read_to_string(scene01()).unwrap(), "01.toml").unwrap();
    let i = text.find("[[surfaces]]").unwrap();
    let j = text[i + 1..].find("[[surfaces]]").unwrap() + i + 1;
    let mut big = text.clone();
    for _ in 6..m {
        big.push_str(&text[i..j]);
    }
    big
}

fn check(c: &mut Criterion) {
    let (_, base) = kinrepro::error::read_scene(&scene01()).unwrap();
    let mut group = c.benchmark_group("check");
    group.sample_size(10);
    for m in [1000, 3000, 10000] {
        let text = many_surfaces(m);
        group.bench_with_input(BenchmarkId::new("parse", m), &text, |b, t| {
            b.iter(|| Scene::parse(black_box(t), "many.toml").unwrap())
        });
        let mut coupling = base.clone();
        while coupling.contacts.len() < m {
            coupling.contacts.push(base.contacts[0].clone());
        }
        group.bench_with_input(BenchmarkId::new("analyse", m), &coupling, |b, c| {
            b.iter(|| analyse(black_box(c)))
        });
    }
    group.finish();
}

fn limit(c: &mut Criterion) {
    let mut group = c.benchmark_group("friction limit");
    group.sample_size(10);
    for name in
        ["01_maxwell_vgroove_steel.toml", "02_maxwell_pins_steel.toml", "06_kelvin_steel.toml"]
    {
        let (s, coupling) = kinrepro::error::read_scene(&scene(name)).unwrap();
        group.bench_function(&name[..2], |b| {
            b.iter(|| friction_limit_solved_anew(black_box(&coupling), &s.preload))
        });
    }
    group.finish();
}

criterion_group!(benches, check, limit);
criterion_main!(benches);
