//! `kinrepro stiffness` and `kinrepro load`: the seated coupling under extra loads.

use super::*;
use crate::args::*;

pub fn stiffness(args: StiffnessArgs) -> Result<(), String> {
    let StiffnessArgs {
        scene,
        at,
        mu,
        json,
    } = args;
    let coupling = kinrepro::error::load_coupling(&scene).map_err(|e| e.to_string())?;
    let points = match at {
        Some(_) => vec![("--at".to_string(), finite3("at", at)?)],
        None => coupling
            .scene
            .evaluation_points
            .iter()
            .map(|p| (p.name.clone(), p.position))
            .collect(),
    };
    let mu = mu.unwrap_or_else(|| kinrepro::solve::nominal_mu(&coupling));
    let file = coupling.scene.file.clone();
    let seating = kinrepro::solve::quasistatic::seat(&coupling, &mu, &Default::default())
        .map_err(|e| format!("{file}: {e}"))?;
    let k = kinrepro::analysis::stiffness::CouplingStiffness::new(&coupling, &seating, &mu)
        .map_err(|e| format!("{file}: {e}"))?;
    let report =
        kinrepro::report::analysis::StiffnessReport::new(&coupling, &mu, &seating, &k, &points)
            .map_err(|e| format!("{file}: {e}"))?;
    if json {
        print_json(&report)
    } else {
        emit(&report.table())
    }
}

pub fn load(args: LoadArgs) -> Result<(), String> {
    let LoadArgs {
        scene,
        force,
        at,
        moment,
        mu,
        json,
    } = args;
    let force = finite3("force", Some(force))?;
    let point = finite3("at", Some(at))?;
    let moment = finite3("moment", moment)?;
    if force.norm() == 0.0 && moment.norm() == 0.0 {
        return Err("--force and --moment are both zero: there is no load to apply".into());
    }
    let coupling = kinrepro::error::load_coupling(&scene).map_err(|e| e.to_string())?;
    let mu = mu.unwrap_or_else(|| kinrepro::solve::nominal_mu(&coupling));
    let file = coupling.scene.file.clone();
    let opts = kinrepro::solve::SolverOptions::default();
    let seating = kinrepro::solve::quasistatic::seat(&coupling, &mu, &opts)
        .map_err(|e| format!("{file}: {e}"))?;
    let load = kinrepro::solve::quasistatic::ExternalLoad {
        force,
        point,
        moment,
    };
    let path = kinrepro::analysis::load::load_path(&coupling, &mu, &seating, &load, 1.0, &opts)
        .map_err(|e| format!("{file}: the load path failed: {e}"))?;
    let envelope = kinrepro::analysis::load::envelope(&coupling, &mu, &seating, &load, &opts)
        .map_err(|e| format!("{file}: the envelope search failed: {e}"))?;
    let mut points: Vec<(String, nalgebra::Vector3<f64>)> = coupling
        .scene
        .evaluation_points
        .iter()
        .map(|p| (p.name.clone(), p.position))
        .collect();
    points.push(("load point".to_string(), point));
    let report = kinrepro::report::analysis::LoadReport::new(
        &coupling, &mu, &seating, &load, &path, &envelope, &points,
    );
    if json {
        print_json(&report)
    } else {
        emit(&report.table())
    }
}
