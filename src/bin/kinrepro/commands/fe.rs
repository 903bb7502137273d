//! `kinrepro validate-hertz`: the FE check of the Hertz law.

use super::{emit, print_json};
use crate::args::*;
use crate::error::{CliError, Context};

pub fn validate_hertz(args: ValidateHertzArgs) -> Result<(), CliError> {
    let ValidateHertzArgs {
        scenes,
        mesh,
        convergence,
        json,
    } = args;
    let couplings = if scenes.is_empty() {
        kinrepro::scene::bundled::PAPER_SCENES
            .iter()
            .map(|(file, text)| {
                let s = kinrepro::scene::Scene::parse(text, file)?;
                kinrepro::assembly::Coupling::new(&s).context(file)
            })
            .collect::<Result<Vec<_>, CliError>>()?
    } else {
        scenes
            .iter()
            .map(|p| kinrepro::error::read_coupling(p))
            .collect::<Result<Vec<_>, _>>()?
    };
    let cases = kinrepro::fe::pairs::distinct_pairs(&couplings)
        .map_err(|(f, e)| CliError::from(e).in_context(f))?;
    let mesh = match mesh {
        MeshKind::Default => kinrepro::fe::MeshOptions::default(),
        MeshKind::Coarse => kinrepro::fe::MeshOptions::coarse(),
    };
    let levels = convergence.unwrap_or_default();
    if levels.iter().any(|l| !(l.is_finite() && *l > 0.0)) {
        return Err(CliError::Usage(
            "--convergence: element sizes must be positive numbers".into(),
        ));
    }
    let mut rows = Vec::new();
    for case in &cases {
        eprintln!(
            "validating {} {}/{} at {:.4} N ...",
            case.pair.shape.name(),
            case.pair.material1.name,
            case.pair.material2.name,
            case.load
        );
        rows.push(
            kinrepro::fe::pairs::validate_pair(case, &mesh, &levels).context(format!(
                "{} {}/{}",
                case.pair.shape.name(),
                case.pair.material1.name,
                case.pair.material2.name
            ))?,
        );
    }
    if json {
        print_json(&rows)
    } else {
        emit(&kinrepro::report::validate_hertz::table(&rows))
    }
}
