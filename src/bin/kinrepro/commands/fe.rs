//! `kinrepro validate-hertz`: the FE check of the Hertz law.

use kinrepro::fe::conformity::{RATIOS, conformity_study};
use kinrepro::fe::pairs::{PairCase, distinct_pairs, validate_pair};

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
    if a.conformity {
        let ratios = a.ratios.unwrap_or_else(|| RATIOS.to_vec());
        return conformity(&cases, &mesh, &ratios, a.json);
    }
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
        emit(&kinrepro::report::contact::validate_hertz::table(&rows))
    }
}

/// `--conformity`: the study of each sphere-groove pair of the scenes.
fn conformity(
    cases: &[PairCase],
    mesh: &MeshOptions,
    ratios: &[f64],
    json: bool,
) -> Result<(), CliError> {
    let grooves: Vec<&PairCase> = cases
        .iter()
        .filter(|c| c.pair.shape == kinrepro::contact::ContactShape::SphereGroove)
        .collect();
    if grooves.is_empty() {
        return Err(CliError::Usage(
            "--conformity: the scenes have no sphere-groove (gothic-arch) contact; \
             give one, e.g. scenes/maxwell_gothic_arch_steel.toml"
                .into(),
        ));
    }
    let mut studies = Vec::new();
    for case in grooves {
        let name = format!(
            "sphere-groove {}/{}",
            case.pair.material1.name, case.pair.material2.name
        );
        eprintln!(
            "conformity study of {name} at {:.4} N (two FE solves per ratio) ...",
            case.load
        );
        studies.push(conformity_study(case, mesh, ratios).context(name)?);
    }
    if json {
        print_json(&studies)
    } else {
        emit(&kinrepro::report::contact::validate_hertz::conformity_table(
            &studies,
        ))
    }
}
