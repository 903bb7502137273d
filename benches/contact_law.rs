//! One Hertz + tangential update per iteration, for each contact shape and
//! law: Coulomb with the switch and the decay friction law, and
//! Mindlin-Deresiewicz with its 128 springs.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::contact::{
    ContactPair, ContactShape, Friction, FrictionLaw, PrincipalStiffness, TangentialInput,
    TangentialLaw, TangentialState, tangential_tensor,
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
        let normal = Vector3::new(0.0, 1.0, 1.0).normalize();
        let decay = Friction {
            law: FrictionLaw::Decay { coefficient: 1e6 },
            ..Friction::switch(0.5, 0.4)
        };
        let laws = [
            (
                TangentialLaw::Coulomb,
                Friction::switch(0.5, 0.4),
                "coulomb",
            ),
            (TangentialLaw::Coulomb, decay, "coulomb (decay friction)"),
            (
                TangentialLaw::MindlinDeresiewicz,
                Friction::switch(0.5, 0.4),
                "mindlin-deresiewicz",
            ),
        ];
        for (tl, friction, label) in laws {
            let fn0 = law.hertz.force(4.9e-7);
            let state = TangentialState {
                normal_force: fn0,
                ..TangentialState::new(normal)
            };
            let name = format!("hertz+{label} update/{}", shape.name());
            c.bench_function(&name, |b| {
                b.iter(|| {
                    let delta = black_box(5e-7);
                    let fn_ = law.hertz.force(delta);
                    let [a, bb] = law.hertz.semi_axes(fn_);
                    // K_t by its principal axes, as the contact layer passes it.
                    let principal = PrincipalStiffness::new(
                        law.tangential_stiffness_axes(fn_),
                        &normal,
                        &Vector3::x(),
                    );
                    let kt = principal.tensor(&normal);
                    let shape = law
                        .mindlin
                        .map(|c| c / (8.0 * law.g_star * law.hertz.axis_ratio.sqrt()));
                    let input = TangentialInput {
                        normal: black_box(normal),
                        du: black_box(Vector3::new(1e-8, 2e-9, -3e-9)),
                        normal_force: fn_,
                        stiffness: kt,
                        d_stiffness_d_fn: kt / (3.0 * fn_),
                        contact_radius: (a * bb).sqrt(),
                        g_star: law.g_star,
                        mindlin_shape: tangential_tensor(shape, &normal, &Vector3::x()),
                        friction: friction.during(0.05),
                    };
                    black_box(state.update_with(tl, &input, Some(&principal)))
                })
            });
        }
    }
}

criterion_group!(benches, contact_update);
criterion_main!(benches);
