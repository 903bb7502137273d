//! One Hertz + Coulomb stick/slip update per iteration, for each contact shape.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::contact::{
    ContactPair, ContactShape, Friction, TangentialInput, TangentialLaw, TangentialState,
};
use kinrepro::material::Material;
use nalgebra::Vector3;

fn contact_update(c: &mut Criterion) {
    let steel = Material::builtin("steel").unwrap();
    for shape in ContactShape::ALL {
        let law = ContactPair {
            shape,
            radius1: 5e-3,
            radius2: Some(if shape == ContactShape::SphereSeat {
                6e-3
            } else {
                2e-3
            }),
            material1: steel.clone(),
            material2: steel.clone(),
        }
        .law()
        .unwrap();
        let state = TangentialState::new(Vector3::z());
        let normal = Vector3::new(0.0, 1.0, 1.0).normalize();
        c.bench_function(&format!("hertz+coulomb update/{}", shape.name()), |b| {
            b.iter(|| {
                let delta = black_box(5e-7);
                let fn_ = law.hertz.force(delta);
                let [a, bb] = law.hertz.semi_axes(fn_);
                let kt = kinrepro::contact::mindlin_stiffness(law.g_star, [a, bb]);
                let dkt = kt / (3.0 * fn_);
                let input = TangentialInput {
                    normal: black_box(normal),
                    du: black_box(Vector3::new(1e-8, 2e-9, -3e-9)),
                    normal_force: fn_,
                    stiffness: kt,
                    d_stiffness_d_fn: dkt,
                    contact_radius: (a * bb).sqrt(),
                    g_star: law.g_star,
                    friction: Friction::switch(0.5, 0.4),
                };
                black_box(state.update(TangentialLaw::Coulomb, &input))
            })
        });
    }
}

criterion_group!(benches, contact_update);
criterion_main!(benches);
