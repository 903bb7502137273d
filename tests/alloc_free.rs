//! The seating hot loop allocates nothing: a counting global allocator
//! (per thread, so that other tests of this binary do not disturb the
//! count) around seatings of scenes 01, 02 and 06 in a reused
//! [`Workspace`]. After one warm-up seating has grown the workspace's
//! buffers, the next seatings (other friction vectors, every other one
//! with the preload moved and tilted as a study varying the preload draws
//! it, every increment and Newton iteration of them, at 20 and at 60
//! increments) must make zero allocations, and give the pose of a seating in a fresh workspace (to
//! 1e-12 of the motion: the reuse carries nothing over from one seating to
//! the next). A
//! seating in a fresh workspace, with its per-contact report, does
//! allocate: the counter sees the seating's allocations.

mod common;
use common::load;

use std::alloc::{GlobalAlloc, Layout, System};
use std::cell::Cell;

use kinrepro::solve::quasistatic::{SeatingSetup, Workspace, seat, seat_in};
use kinrepro::solve::{Load, PointPose, SeatingPath, SolverOptions};
use nalgebra::Vector3;

struct Counting;

thread_local! {
    static ALLOCATIONS: Cell<usize> = const { Cell::new(0) };
}

fn count() {
    // `try_with`: the thread's counter may already be gone at thread exit.
    let _ = ALLOCATIONS.try_with(|c| c.set(c.get() + 1));
}

// SAFETY: every call is forwarded unchanged to the system allocator.
unsafe impl GlobalAlloc for Counting {
    unsafe fn alloc(&self, layout: Layout) -> *mut u8 {
        count();
        unsafe { System.alloc(layout) }
    }
    unsafe fn alloc_zeroed(&self, layout: Layout) -> *mut u8 {
        count();
        unsafe { System.alloc_zeroed(layout) }
    }
    unsafe fn realloc(&self, ptr: *mut u8, layout: Layout, new_size: usize) -> *mut u8 {
        count();
        unsafe { System.realloc(ptr, layout, new_size) }
    }
    unsafe fn dealloc(&self, ptr: *mut u8, layout: Layout) {
        unsafe { System.dealloc(ptr, layout) }
    }
}

#[global_allocator]
static GLOBAL: Counting = Counting;

fn allocations() -> usize {
    ALLOCATIONS.with(Cell::get)
}

/// Each preload force moved by up to a millimetre and tilted by up to
/// 10 mrad (fixed by `k`).
fn moved_preload(load: &mut Load, k: usize) {
    let t = k as f64 / 8.0;
    for f in &mut load.preload.forces {
        f.point += Vector3::new(1e-3 * t, -5e-4 * t, 0.0);
        let tilt = nalgebra::UnitQuaternion::from_scaled_axis(Vector3::new(1e-2 * t, 5e-3, 0.0));
        f.direction = tilt * f.direction;
    }
}

/// Friction vectors in mu0 +- spread (fixed, so the count is reproducible).
fn frictions(mu0: f64, spread: f64, n: usize) -> Vec<Vec<f64>> {
    (0..8)
        .map(|k| {
            (0..n)
                .map(|i| {
                    let u = ((7 * k + 3 * i + 1) % 11) as f64 / 10.0;
                    mu0 + spread * (2.0 * u - 1.0)
                })
                .collect()
        })
        .collect()
}

#[test]
fn a_seating_in_a_reused_workspace_allocates_nothing() {
    let opts = SolverOptions::default();
    for name in
        ["01_maxwell_vgroove_steel.toml", "02_maxwell_pins_steel.toml", "06_kelvin_steel.toml"]
    {
        let (scene, c) = load(name);
        let f = &scene.friction;
        // The loads (each friction vector with the scene's preload, or,
        // every other one, with the preload moved and tilted as a study
        // that varies it draws it) are made before any seating is counted.
        let mus: Vec<Load> = frictions(f.mu_static, f.spread, c.contacts.len())
            .iter()
            .enumerate()
            .map(|(k, mu)| {
                let mut load = Load::nominal(&scene).with_mu(mu);
                if k % 2 == 1 {
                    moved_preload(&mut load, k);
                }
                load
            })
            .collect();
        let setup = SeatingSetup::new(&c, &scene.preload);
        let mut ws = Workspace::new();
        seat_in(&setup, &mus[0], &opts, &mut ws).unwrap();
        let before = allocations();
        seat(&c, &mus[0], &opts).unwrap();
        assert!(allocations() > before, "{name}: a fresh workspace allocates");
        // The buffers depend on the contact count only: the count stays
        // zero on 20 and 60 fixed increments (three times the Newton
        // iterations) and under load-path error control (several levels
        // of increments in the one workspace: 3 and 6 at least).
        for (increments, opts) in
            [(20, SolverOptions::fixed(20)), (60, SolverOptions::fixed(60)), (9, opts)]
        {
            let mut poses = Vec::with_capacity(mus.len());
            let before = allocations();
            for mu in &mus[1..] {
                poses.push(seat_in(&setup, mu, &opts, &mut ws).unwrap());
            }
            let made = allocations() - before;
            assert_eq!(made, 0, "{name}, {increments} increments: {made} allocations");
            for (load, seated) in mus[1..].iter().zip(&poses) {
                let mu = &load.mu;
                assert_eq!(seated.path, SeatingPath::Uniform, "{name}: {mu:?}");
                assert!(seated.increments >= increments, "{name}");
                let fresh = seat(&c, load, &opts).unwrap();
                assert_eq!(fresh.seated.path, seated.path, "{name}: {mu:?}");
                assert_eq!(fresh.seated.increments, seated.increments, "{name}: {mu:?}");
                // The motion of the origin from the touching pose (translation
                // and the rotation times the coupling radius).
                let motion = |pose| {
                    let m = PointPose::between(&c.touching_pose, pose, &Vector3::zeros());
                    let l = c.length_scale();
                    let v = m.components();
                    [v[0], v[1], v[2], v[3] * l, v[4] * l, v[5] * l]
                };
                let (a, b) = (motion(&fresh.pose()), motion(&seated.pose));
                let size = a.iter().fold(0.0f64, |m, v| m.max(v.abs()));
                for k in 0..6 {
                    assert!((a[k] - b[k]).abs() <= 1e-12 * size, "{name}: {mu:?}");
                }
            }
        }
    }
}

#[test]
fn the_counter_sees_an_allocation() {
    // The check of the check: a heap allocation on this thread is counted.
    let before = allocations();
    let v = std::hint::black_box(vec![1.0f64; 16]);
    assert_eq!(allocations() - before, 1);
    drop(v);
}
