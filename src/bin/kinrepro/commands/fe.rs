//! `kinrepro validate-hertz`: the FE check of the Hertz law.

use kinrepro::fe::pairs::{distinct_pairs, validate_pair};

use super::{emit, print_json};
use crate::error::{CliError, Context};
use crate::flags::high::Checked;
use crate::flags::low::ValidateHertzArgs;
use kinrepro::fe::MeshOptions;

pub fn validate_hertz(o: Checked<ValidateHertzArgs, MeshOptions>) -> Result<(), CliError> {
    let Checked {
        args: a,
        opts: mesh,
    } = o;
    let couplings = if a.scenes.is_empty() {
        kinrepro::scene::bundled::PAPER_SCENES
            .iter()
            .map(|(file, text)| {
                let s = kinrepro::scene::Scene::parse(text, file)?;
                kinrepro::assembly::Coupling::new(&s).context(file)
            })
            .collect::<Result<Vec<_>, CliError>>()?
    } else {
        a.scenes
            .iter()
            .map(|p| kinrepro::error::read_coupling(p))
            .collect::<Result<Vec<_>, _>>()?
    };
    let cases = distinct_pairs(&couplings).map_err(|(f, e)| CliError::from(e).in_context(f))?;
    let levels = a.convergence.unwrap_or_default();
    let mut rows = Vec::new();
    for case in &cases {
        let name = format!(
            "{} {}/{}",
            case.pair.shape.name(),
            case.pair.material1.name,
            case.pair.material2.name
        );
        eprintln!("validating {name} at {:.4} N ...", case.load);
        rows.push(validate_pair(case, &mesh, &levels).context(name)?);
    }
    if a.json {
        print_json(&rows)
    } else {
        emit(&kinrepro::report::validate_hertz::table(&rows))
    }
}
