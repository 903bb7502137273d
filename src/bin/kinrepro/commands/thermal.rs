//! `kinrepro thermal`: the seating, then the scene's temperature cycle.

use std::path::PathBuf;

use kinrepro::report::thermal::ThermalReport;
use kinrepro::scene::Temperatures;
use kinrepro::scene::thermal::cycle_of;
use kinrepro::solve::{Load, Method, Solver};

use super::{emit, print_json, read_scene};
use crate::error::{Context, Error, Result, usage};
use crate::flags::ThermalArgs;

/// `kinrepro thermal`, its flags checked.
pub struct Thermal {
    scene: PathBuf,
    mu: Option<Vec<f64>>,
    /// The cycle of `--cycle` (None: the scene's).
    cycle: Option<Vec<Temperatures>>,
    method: Method,
    path_tolerance: Option<f64>,
    json: bool,
}

impl TryFrom<ThermalArgs> for Thermal {
    type Error = Error;

    fn try_from(a: ThermalArgs) -> Result<Thermal> {
        let method = Method::new(Solver::QuasiStatic, a.path.increments, a.path.path_tolerance)?;
        let path_tolerance = method.path_tolerance();
        Ok(Thermal {
            cycle: a.cycle.as_deref().map(parse_cycle).transpose()?,
            scene: a.scene,
            mu: a.mu,
            method,
            path_tolerance,
            json: a.json,
        })
    }
}

/// `--cycle "dTm,dTf;dTm,dTf;..."`: pairs separated by `;`, the two changes
/// of a pair by `,` [K]; the values checked by the library.
fn parse_cycle(text: &str) -> Result<Vec<Temperatures>> {
    let mut pairs = Vec::new();
    for (k, pair) in text.split(';').map(str::trim).enumerate() {
        let values: Vec<&str> = pair.split(',').map(str::trim).collect();
        let numbers: Vec<f64> = values.iter().filter_map(|v| v.parse().ok()).collect();
        if values.len() != 2 || numbers.len() != 2 {
            usage!(
                "--cycle: point {} is \"{pair}\": each point is two temperature changes \"dT_moving,dT_fixed\" in K, points separated by ';' (e.g. --cycle \"5,0;0,0\")",
                k + 1
            );
        }
        pairs.push([numbers[0], numbers[1]]);
    }
    Ok(cycle_of(&pairs)?)
}

pub fn thermal(t: Thermal) -> Result {
    let (scene, coupling) = read_scene(&t.scene)?;
    let file = scene.file.clone();
    let mut load = Load::nominal(&scene);
    if let Some(mu) = &t.mu {
        load = load.with_mu(mu);
    }
    if let Some(cycle) = t.cycle {
        load.cycle = cycle;
    }
    let (seating, path) = t.method.seat_and_cycle(&coupling, &load).context(&file)?;
    let report = ThermalReport::new((&scene, &coupling), &load, &seating, &path, t.path_tolerance)
        .context(&file)?;
    if t.json { print_json(&report) } else { emit(&report.table()) }
}
