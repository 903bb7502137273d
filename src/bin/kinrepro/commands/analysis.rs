//! `kinrepro stiffness` and `kinrepro load`: the seated coupling under extra loads.

use super::*;
use crate::args::*;
use crate::error::{CliError, Context};

pub fn stiffness(args: StiffnessArgs) -> Result<(), CliError> {
    let StiffnessArgs {
        scene,
        at,
        mu,
        json,
    } = args;
    let coupling = kinrepro::error::read_coupling(&scene)?;
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
    let seating =
        kinrepro::solve::quasistatic::seat(&coupling, &mu, &Default::default()).context(&file)?;
    let k = kinrepro::analysis::stiffness::CouplingStiffness::new(&coupling, &seating, &mu)
        .context(&file)?;
    let report =
        kinrepro::report::analysis::StiffnessReport::new(&coupling, &mu, &seating, &k, &points)
            .context(&file)?;
    if json {
        print_json(&report)
    } else {
        emit(&report.table())
    }
}

pub fn load(args: LoadArgs) -> Result<(), CliError> {
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
        return Err(CliError::Usage(
            "--force and --moment are both zero: there is no load to apply".into(),
        ));
    }
    let coupling = kinrepro::error::read_coupling(&scene)?;
    let mu = mu.unwrap_or_else(|| kinrepro::solve::nominal_mu(&coupling));
    let file = coupling.scene.file.clone();
    let opts = kinrepro::solve::SolverOptions::default();
    let seating = kinrepro::solve::quasistatic::seat(&coupling, &mu, &opts).context(&file)?;
    let load = kinrepro::solve::quasistatic::ExternalLoad {
        force,
        point,
        moment,
    };
    let path = kinrepro::analysis::load::load_path(&coupling, &mu, &seating, &load, 1.0, &opts)
        .context(format!("{file}: the load path failed"))?;
    let envelope = kinrepro::analysis::load::envelope(&coupling, &mu, &seating, &load, &opts)
        .context(format!("{file}: the envelope search failed"))?;
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
