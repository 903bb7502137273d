//! The contact laws, for each contact shape and law: Coulomb with the switch
//! and the decay friction law, and Mindlin-Deresiewicz with its 128 springs.
//!
//! - `hertz+LAW update/SHAPE`: Hertz force, semi-axes, K_t by its principal
//!   axes, the tensor and the tangential update, all in the timed loop (the
//!   figures of earlier notes refer to these names).
//! - `update alone/LAW/SHAPE/STATE`: only `TangentialState::update` into a
//!   fresh response, its input prepared once as the solver's contact layer
//!   prepares it (`solve::contact_layer::evaluate_into`), from a committed
//!   state that sticks (`stick`) or slides (`slide`: the trial force leaves
//!   the cone).
//! - `update in place/LAW/SHAPE/slide/{tangent,forces}`: the update as the
//!   quasi-static solver calls it, into a response slot reused from call to
//!   call, with its consistent tangent (`tangent`) or without it (`forces`:
//!   a Newton iterate that converges, see `solve/quasistatic/solver.rs`).
//! - `law work per evaluation/LAW/SHAPE/slide`: everything the contact layer
//!   asks of `contact` at one evaluation: F_n and k_n (Hertz in series with
//!   a support compliance), a = c_a F^(1/3) by the fast cube root, K_t by
//!   its principal axes, its tensor and dK_t/dF_n, and the update.

use std::hint::black_box;

use criterion::{Criterion, criterion_group, criterion_main};
use kinrepro::contact::{
    ContactLaw, ContactPair, ContactShape, Friction, FrictionLaw, PrincipalStiffness, SeriesNormal,
    TangentialInput, TangentialLaw, TangentialResponse, TangentialState, tangential_tensor,
};
use kinrepro::material::Material;
use nalgebra::Vector3;

/// The pair of each shape: a 5 mm steel ball on a flat, a 2 mm ball, a
/// 6 mm seat or groove, or a 2 mm pin (under the ball, or crossing a 5 mm pin).
fn law_of(shape: ContactShape) -> ContactLaw {
    let steel = Material::builtin("steel").unwrap();
    let r2 = if matches!(shape, ContactShape::SphereSeat | ContactShape::SphereGroove) {
        6e-3
    } else {
        2e-3
    };
    ContactPair::from_shape(shape, 5e-3, Some(r2), steel.clone(), steel).unwrap().law().unwrap()
}

/// The three laws benched: (tangential law, friction, label).
fn laws() -> [(TangentialLaw, Friction, &'static str); 3] {
    let decay =
        Friction { law: FrictionLaw::Decay { coefficient: 1e6 }, ..Friction::switch(0.5, 0.4) };
    [
        (TangentialLaw::Coulomb, Friction::switch(0.5, 0.4), "coulomb"),
        (TangentialLaw::Coulomb, decay, "coulomb (decay friction)"),
        (TangentialLaw::MindlinDeresiewicz, Friction::switch(0.5, 0.4), "mindlin-deresiewicz"),
    ]
}

fn contact_update(c: &mut Criterion) {
    for shape in ContactShape::ALL {
        let law = law_of(shape);
        let normal = Vector3::new(0.0, 1.0, 1.0).normalize();
        for (tl, friction, label) in laws() {
            let fn0 = law.hertz.force(4.9e-7);
            let state = TangentialState { normal_force: fn0, ..TangentialState::new(normal) };
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
                    let shape =
                        law.mindlin.map(|c| c / (8.0 * law.g_star * law.hertz.axis_ratio.sqrt()));
                    let input = TangentialInput {
                        normal: black_box(normal),
                        du: black_box(Vector3::new(1e-8, 2e-9, -3e-9)),
                        normal_force: fn_,
                        stiffness: kt,
                        principal,
                        d_stiffness_d_fn: kt / (3.0 * fn_),
                        contact_radius: (a * bb).sqrt(),
                        g_star: law.g_star,
                        mindlin_shape: tangential_tensor(shape, &normal, &Vector3::x()),
                        friction: friction.during(0.05),
                    };
                    black_box(respond(&state, tl, &input))
                })
            });
        }
    }
}

/// One contact as the contact layer sees it: the normal and the major axis
/// (along the pin for sphere-cylinder, none otherwise), the committed normal
/// force and this evaluation's approach, and the tangential increment.
#[derive(Clone, Copy)]
struct Setting {
    normal: Vector3<f64>,
    major_axis: Vector3<f64>,
    committed_fn: f64,
    approach: f64,
    du: Vector3<f64>,
}

impl Setting {
    fn new(shape: ContactShape, law: &ContactLaw) -> Self {
        // The normal turned slightly since the last commit (as in a seating).
        let normal = Vector3::new(0.0, 0.7072, 0.7070).normalize();
        let major_axis = if shape == ContactShape::SphereCylinder {
            Vector3::new(1.0, 0.0, 0.0)
        } else {
            Vector3::zeros()
        };
        Setting {
            normal,
            major_axis,
            committed_fn: law.hertz.force(4.9e-7),
            approach: 5e-7,
            du: Vector3::new(0.8, 0.6, -0.6).normalize() * 1e-8,
        }
    }

    /// The contact layer's preparation (`evaluate_into`, with the same
    /// `ContactLaw` calls): K_t of the increment from the committed to the new normal force,
    /// its derivative, the MDR shape.
    fn input(
        &self,
        law: &ContactLaw,
        normal_law: &SeriesNormal,
        tl: TangentialLaw,
        friction: Friction,
    ) -> TangentialInput {
        let (fn_, _) = normal_law.force_and_stiffness(self.approach);
        let (a_eff, dlog) = law.increment_semi_axis(self.committed_fn, fn_);
        let (principal, kt, dkt) =
            law.increment_stiffness(a_eff, dlog, &self.normal, &self.major_axis, true);
        let (contact_radius, mindlin_shape) =
            law.mindlin_deresiewicz_inputs(tl, fn_, &self.normal, &self.major_axis);
        TangentialInput {
            normal: self.normal,
            du: self.du,
            normal_force: fn_,
            stiffness: kt,
            principal,
            d_stiffness_d_fn: dkt,
            contact_radius,
            g_star: law.g_star,
            mindlin_shape,
            friction: friction.during(0.05),
        }
    }

    /// A committed state of the old normal that sticks (`slide` false: no
    /// force yet) or slides on (sliding at 0.99 mu_s F_n, so the trial force
    /// leaves the mu_d cone), after one committed update so that a
    /// Mindlin-Deresiewicz contact carries its spring row.
    fn committed(
        &self,
        tl: TangentialLaw,
        input: &TangentialInput,
        slide: bool,
    ) -> TangentialState {
        let old_normal = Vector3::new(0.0, 1.0, 1.0).normalize();
        let tangent = (self.du - old_normal * old_normal.dot(&self.du)).normalize();
        let first =
            TangentialState { normal_force: self.committed_fn, ..TangentialState::new(old_normal) };
        let mut state = if tl == TangentialLaw::MindlinDeresiewicz {
            // Load the row once (a step that ends at the committed force).
            let step = TangentialInput {
                normal: old_normal,
                du: tangent * if slide { 1e-6 } else { 1e-9 },
                normal_force: self.committed_fn,
                ..*input
            };
            respond(&first, tl, &step).state
        } else {
            TangentialState {
                force: tangent * if slide { 0.99 * 0.5 * self.committed_fn } else { 0.0 },
                sliding: slide,
                // The decay law's coefficient at 1 um/s: 0.4 + 0.1 / e.
                slip_velocity: if slide { 1e-6 } else { 0.0 },
                ..first
            }
        };
        state.normal = old_normal;
        state.normal_force = self.committed_fn;
        state
    }
}

/// One shape and law as the contact layer prepares them ([`Setting`]).
struct Case {
    shape: ContactShape,
    law: ContactLaw,
    normal_law: SeriesNormal,
    setting: Setting,
    tl: TangentialLaw,
    friction: Friction,
    label: &'static str,
    input: TangentialInput,
}

/// Every shape with every law of [`laws`].
fn cases() -> Vec<Case> {
    let mut out = Vec::new();
    for shape in ContactShape::ALL {
        let law = law_of(shape);
        let normal_law = SeriesNormal::new(law.hertz, 0.0);
        let setting = Setting::new(shape, &law);
        for (tl, friction, label) in laws() {
            let input = setting.input(&law, &normal_law, tl, friction);
            out.push(Case { shape, law, normal_law, setting, tl, friction, label, input });
        }
    }
    out
}

fn update_alone(c: &mut Criterion) {
    for case in cases() {
        let (tl, label, input) = (case.tl, case.label, &case.input);
        for slide in [false, true] {
            let state = case.setting.committed(tl, input, slide);
            let which = if slide { "slide" } else { "stick" };
            let want = if slide {
                kinrepro::contact::SlipState::Slip
            } else {
                kinrepro::contact::SlipState::Stick
            };
            assert_eq!(
                respond(&state, tl, input).slip,
                want,
                "{label} {} {which}",
                case.shape.name()
            );
            let name = format!("update alone/{label}/{}/{which}", case.shape.name());
            c.bench_function(&name, |b| {
                b.iter(|| respond(black_box(&state), tl, black_box(input)))
            });
        }
    }
}

fn per_evaluation(c: &mut Criterion) {
    for case in cases() {
        let (tl, friction, label, shape) = (case.tl, case.friction, case.label, case.shape.name());
        let state = case.setting.committed(tl, &case.input, true);
        let what = format!("{label}/{shape}");
        in_place(c, &what, &state, tl, &case.input);
        let name = format!("law work per evaluation/{label}/{shape}/slide");
        c.bench_function(&name, |b| {
            b.iter(|| {
                let input =
                    black_box(&case.setting).input(&case.law, &case.normal_law, tl, friction);
                respond(black_box(&state), tl, &input)
            })
        });
    }
}

/// `update in place/WHAT/slide/{tangent,forces}` (module docs).
fn in_place(
    c: &mut Criterion,
    what: &str,
    state: &TangentialState,
    tl: TangentialLaw,
    input: &TangentialInput,
) {
    let mut slot = respond(state, tl, input);
    for (tangent, which) in [(true, "tangent"), (false, "forces")] {
        c.bench_function(&format!("update in place/{what}/slide/{which}"), |b| {
            b.iter(|| {
                black_box(state).update(tl, black_box(input), tangent, &mut slot);
                black_box(&slot.force);
            })
        });
    }
}

/// The law's response with its tangent, in a fresh slot.
fn respond(
    state: &TangentialState,
    tl: TangentialLaw,
    input: &TangentialInput,
) -> TangentialResponse {
    let mut out = TangentialResponse::open(input.normal);
    state.update(tl, input, true, &mut out);
    out
}

/// The elliptical return map (`mindlin::project_on_circle`) of four
/// trial forces: four f64 calls (`return map/4 x f64`) against one call
/// over four lanes (`return map/wide f64x4`: simba's `WideF64x4`, the
/// product's `lane::F64x4`; `return map/auto f64x4`: simba's
/// `AutoF64x4`, arrays the compiler vectorises; `auto f64x4 avx2`: the
/// same compiled for AVX2). The four are 2 mm-pin contacts (k_minor/k_major = 1.07)
/// 0.1 %, 1 %, 10 % and 50 % outside the limit: 1 to 3 Newton steps each.
fn return_map_lanes(c: &mut Criterion) {
    use kinrepro::contact::mindlin::project_on_circle;
    use kinrepro::lane::Lane;
    use nalgebra::Vector2;
    use simba::simd::{AutoF64x4, SimdValue, WideF64x4};
    let k = [2.9e7, 3.1e7];
    let limit = 0.37;
    let trial: [Vector2<f64>; 4] = std::array::from_fn(|i| {
        let r = limit * (1.0 + [1e-3, 1e-2, 0.1, 0.5][i]);
        let angle = 0.3 + 1.4 * i as f64;
        Vector2::new(r * angle.cos(), r * angle.sin())
    });
    fn lanes<T: Lane + From<[f64; 4]>>(v: &[Vector2<f64>; 4]) -> Vector2<T> {
        Vector2::from_fn(|i, _| T::from(v.map(|v| v[i])))
    }
    let mut group = c.benchmark_group("return map");
    group.bench_function("4 x f64", |b| {
        b.iter(|| black_box(&trial).map(|t| project_on_circle(k, &t, limit)))
    });
    let wide: Vector2<WideF64x4> = lanes(&trial);
    group.bench_function("wide f64x4", |b| {
        b.iter(|| {
            project_on_circle(k.map(WideF64x4::splat), black_box(&wide), WideF64x4::splat(limit))
        })
    });
    let auto: Vector2<AutoF64x4> = lanes(&trial);
    group.bench_function("auto f64x4", |b| {
        b.iter(|| {
            project_on_circle(k.map(AutoF64x4::splat), black_box(&auto), AutoF64x4::splat(limit))
        })
    });
    #[target_feature(enable = "avx2")]
    fn avx2(k: [f64; 2], trial: &Vector2<AutoF64x4>, limit: f64) -> Vector2<AutoF64x4> {
        project_on_circle(k.map(AutoF64x4::splat), trial, AutoF64x4::splat(limit)).0
    }
    if std::arch::is_x86_feature_detected!("avx2") {
        group.bench_function("auto f64x4 avx2", |b| {
            b.iter(|| unsafe { avx2(k, black_box(&auto), limit) })
        });
    }
    group.finish();
}

criterion_group!(benches, contact_update, update_alone, per_evaluation, return_map_lanes);
criterion_main!(benches);
