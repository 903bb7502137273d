mod common;
use common::load;
use kinrepro::solve::SolverOptions;
use kinrepro::solve::quasistatic::{seat, seat_adaptive};
fn many(name: &str, fast: bool) {
    let c = load(name);
    let mu = [0.46, 0.53, 0.51, 0.47, 0.545, 0.455];
    let mut acc = 0.0;
    for _ in 0..200 {
        acc += if fast {
            seat(&c, &mu, &SolverOptions::default())
        } else {
            seat_adaptive(&c, &mu, &SolverOptions::default())
        }
        .unwrap()
        .pose
        .translation
        .z;
    }
    println!("{acc}");
}
#[test]
fn cg01() {
    many("01_maxwell_vgroove_steel.toml", true);
}
#[test]
fn cg02() {
    many("02_maxwell_pins_steel.toml", true);
}
#[test]
fn cg06() {
    many("06_kelvin_steel.toml", true);
}
#[test]
fn ad01() {
    many("01_maxwell_vgroove_steel.toml", false);
}
#[test]
fn ad02() {
    many("02_maxwell_pins_steel.toml", false);
}
#[test]
fn ad06() {
    many("06_kelvin_steel.toml", false);
}
