//! `kinrepro stiffness` and `kinrepro load`: the seated coupling under extra loads.

use kinrepro::analysis::load::{LEVER_RATIO_MAX, envelope, lever_ratio, load_path};
use kinrepro::analysis::stiffness::CouplingStiffness;
use kinrepro::report::coupling::analysis::{LoadReport, StiffnessReport};
use kinrepro::solve::SolverOptions;
use kinrepro::solve::quasistatic::seat;
use nalgebra::Vector3;

use super::*;
use crate::error::{CliError, Context};
use crate::flags::high::Checked;
use crate::flags::low::{LoadArgs, StiffnessArgs};
use kinrepro::solve::quasistatic::ExternalLoad;

/// The scene's evaluation points by name.
fn evaluation_points(coupling: &kinrepro::assembly::Coupling) -> Vec<(String, Vector3<f64>)> {
    let points = &coupling.scene.evaluation_points;
    points
        .iter()
        .map(|p| (p.name.clone(), p.position))
        .collect()
}

pub fn stiffness(o: Checked<StiffnessArgs, Option<Vector3<f64>>>) -> Result<(), CliError> {
    let Checked { args: a, opts: at } = o;
    let coupling = kinrepro::error::read_coupling(&a.scene)?;
    let points = match at {
        Some(at) => vec![("--at".to_string(), at)],
        None => evaluation_points(&coupling),
    };
    let mu =
        a.mu.unwrap_or_else(|| kinrepro::solve::nominal_mu(&coupling));
    let file = coupling.scene.file.clone();
    let seating = seat(&coupling, &mu, &SolverOptions::default()).context(&file)?;
    let k = CouplingStiffness::new(&coupling, &seating, &mu).context(&file)?;
    let report = StiffnessReport::new(&coupling, &mu, &seating, &k, &points).context(&file)?;
    if a.json {
        print_json(&report)
    } else {
        emit(&report.table())
    }
}

pub fn load(o: Checked<LoadArgs, ExternalLoad>) -> Result<(), CliError> {
    let Checked {
        args: a,
        opts: load,
    } = o;
    let coupling = kinrepro::error::read_coupling(&a.scene)?;
    let mu =
        a.mu.unwrap_or_else(|| kinrepro::solve::nominal_mu(&coupling));
    let file = coupling.scene.file.clone();
    let opts = SolverOptions::default();
    let seating = seat(&coupling, &mu, &opts).context(&file)?;
    let (ratio, size) = lever_ratio(&coupling, &load.point);
    if ratio > LEVER_RATIO_MAX {
        return Err(CliError::Usage(format!(
            "--at {}: the load point lies {} m from the origin, more than {LEVER_RATIO_MAX} times the coupling's size ({size} m, its farthest ball centre): a lever that long is no load for this coupling (did you give millimetres? the flags are in SI, m)",
            vector(&load.point),
            number(load.point.amax())
        )));
    }
    let what = format!(
        "{file}: --force {} N at --at {} m, --moment {} N m",
        vector(&load.force),
        vector(&load.point),
        vector(&load.moment)
    );
    let path = load_path(&coupling, &mu, &seating, &load, 1.0, &opts)
        .map_err(|e| {
            CliError::from(e).in_context(format!(
                "{what}: the load path after seating failed (a load far beyond what the seat holds? a smaller load's safe load envelope tells where the seat is lost)"
            ))
        })?;
    let envelope = envelope(&coupling, &mu, &seating, &load, &opts)
        .context(format!("{what}: the envelope search failed"))?;
    let mut points = evaluation_points(&coupling);
    points.push(("load point".to_string(), load.point));
    let report = LoadReport::new(&coupling, &mu, &seating, &load, &path, &envelope, &points);
    if a.json {
        print_json(&report)
    } else {
        emit(&report.table())
    }
}

/// `x,y,z` as the flags take it.
fn vector(v: &Vector3<f64>) -> String {
    format!("{},{},{}", number(v.x), number(v.y), number(v.z))
}
