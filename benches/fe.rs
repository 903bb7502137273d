//! One sphere-cylinder (steel/steel) FE validation at the default mesh.
use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::fe::{FeCase, Gap, MeshOptions, solve_case};
use kinrepro::material::{Material, effective_modulus};
use std::hint::black_box;

fn bench(c: &mut Criterion) {
    let case = FeCase {
        rx: 1.0 / (1.0 / 5e-3 + 1.0 / 2e-3),
        ry: 5e-3,
        e_star: effective_modulus(
            &Material::builtin("steel").unwrap(),
            &Material::builtin("steel").unwrap(),
        ),
        load: 20.0 / (6.0 * std::f64::consts::FRAC_1_SQRT_2),
        gap: Gap::Quadratic,
    };
    let mesh = MeshOptions::default();
    c.bench_function("sphere_cylinder_steel_default_mesh", |b| {
        b.iter(|| solve_case(black_box(&case), black_box(&mesh)).unwrap())
    });
}

criterion_group! {
    name = benches;
    config = Criterion::default().sample_size(10);
    targets = bench
}
criterion_main!(benches);
