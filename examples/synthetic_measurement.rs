//! Write a synthetic measurement file (docs/measurements.md) for a scene:
//! `cycles` re-seatings with mu_s,k = mu0 + spread (2u - 1), u uniform from
//! a ChaCha8 stream of `seed`, plus Gaussian sensor noise of 1 nm
//! (translations) and 20 nrad (rotations), at the scene's first evaluation
//! point. Used for the worked example in docs/calibration.md:
//!
//! cargo run --release --example synthetic_measurement -- \
//!     scenes/02_maxwell_pins_steel.toml 0.08 50 777 > docs/calibration/measured_02.csv

use std::path::Path;

use kinrepro::calibrate::params::{Param, with_values};
use kinrepro::solve::Solver;
use kinrepro::study::provenance::VERSION;
use kinrepro::study::runner::evaluate_rows;
use kinrepro::study::{StudyOptions, StudyPlan};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

const NOISE: [f64; 6] = [1e-9, 1e-9, 1e-9, 20e-9, 20e-9, 20e-9];

fn main() -> Result<(), String> {
    let a: Vec<String> = std::env::args().skip(1).collect();
    if a.len() != 4 {
        return Err("usage: synthetic_measurement SCENE SPREAD CYCLES SEED".into());
    }
    let num = |i: usize| a[i].parse::<f64>().map_err(|e| format!("{}: {e}", a[i]));
    let (spread, cycles, seed) = (num(1)?, num(2)? as usize, num(3)? as u64);
    let model = kinrepro::error::read_scene(Path::new(&a[0])).map_err(|e| e.to_string())?;
    let options = StudyOptions::monte_carlo(cycles, seed, Solver::QuasiStatic);
    let plan = StudyPlan::new(vec![model], &options).map_err(|e| e.to_string())?;
    let c = with_values(&plan.variants[0], &[Param::Spread], &[spread]);
    let mut rng = ChaCha8Rng::seed_from_u64(seed);
    let rows: Vec<(usize, Vec<f64>)> = (0..cycles)
        .map(|i| (i, (0..c.coupling.contacts.len()).map(|_| rng.random::<f64>()).collect()))
        .collect();
    let recs = evaluate_rows(&plan.settings, &c, rows, &|| {}).map_err(|e| e.to_string())?;
    println!(
        "# synthetic measurement (not measured on a rig): kinrepro {VERSION} example synthetic_measurement"
    );
    println!("# scene: {}, point: {}", a[0], c.scene.evaluation_points[0].name);
    println!("# model: spread {spread}, {cycles} cycles, seed {seed}, quasi-static solver");
    println!("# noise: x=1nm, y=1nm, z=1nm, phi_x=20nrad, phi_y=20nrad, phi_z=20nrad");
    println!("x_nm,y_nm,z_nm,phi_x_nrad,phi_y_nrad,phi_z_nrad");
    for r in recs {
        let cells: Vec<String> = (0..6)
            .map(|j| {
                let u1: f64 = 1.0 - rng.random::<f64>();
                let u2: f64 = rng.random::<f64>();
                let g = (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos();
                format!("{:.4}", (r.outputs[j] + NOISE[j] * g) * 1e9)
            })
            .collect();
        println!("{}", cells.join(","));
    }
    Ok(())
}
