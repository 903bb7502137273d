//! `kinrepro validate-hertz`: the FE check of the Hertz law.

use std::path::PathBuf;

use kinrepro::fe::MeshOptions;
use kinrepro::fe::conformity::{RATIOS, conformity_study};
use kinrepro::fe::pairs::{PairCase, distinct_pairs, validate_pair};

use super::{emit, print_json, read_scene};
use crate::error::{Context, Error, Result, usage};
use crate::flags::ValidateHertzArgs;
use crate::flags::groups::MeshKind;

/// `kinrepro validate-hertz`, its flags checked.
pub struct ValidateHertz {
    scenes: Vec<PathBuf>,
    mesh: MeshOptions,
    /// Element sizes of a convergence study (empty: none).
    levels: Vec<f64>,
    /// The groove / ball radius ratios of a conformity study.
    conformity: Option<Vec<f64>>,
    json: bool,
}

impl TryFrom<ValidateHertzArgs> for ValidateHertz {
    type Error = Error;

    fn try_from(a: ValidateHertzArgs) -> Result<ValidateHertz> {
        let levels = a.convergence.clone().unwrap_or_default();
        if let Some(l) = levels.iter().find(|l| !(l.is_finite() && **l > 0.0 && **l <= 1.0)) {
            usage!(
                "--convergence {l}: element sizes are fractions of the contact semi-axis, in (0, 1]"
            );
        }
        for &element_size_rel in &levels {
            let level = MeshOptions { element_size_rel, ..MeshOptions::default() };
            level.check_size().context("--convergence")?;
        }
        if let Some(r) = &a.ratios {
            check_ratios(r, a.conformity)?;
        }
        if a.conformity && a.convergence.is_some() {
            usage!("--convergence does not go with --conformity");
        }
        Ok(ValidateHertz {
            scenes: a.scenes,
            mesh: match a.mesh {
                MeshKind::Default => MeshOptions::default(),
                MeshKind::Coarse => MeshOptions::coarse(),
            },
            levels,
            conformity: a.conformity.then(|| a.ratios.unwrap_or_else(|| RATIOS.to_vec())),
            json: a.json,
        })
    }
}

/// `--ratios`: with `--conformity`, numbers above 1, descending.
fn check_ratios(r: &[f64], conformity: bool) -> Result {
    if !conformity {
        usage!("--ratios goes with --conformity");
    }
    if r.is_empty() || r.iter().any(|q| !(q.is_finite() && *q > 1.0)) {
        usage!("--ratios: groove / ball radius ratios must be numbers above 1");
    }
    if r.windows(2).any(|w| w[1] >= w[0]) {
        usage!("--ratios: give the ratios in descending order");
    }
    Ok(())
}

pub fn validate_hertz(v: ValidateHertz) -> Result {
    let models = if v.scenes.is_empty() {
        kinrepro::scene::bundled::PAPER_SCENES
            .iter()
            .map(|(file, text)| Ok(kinrepro::error::parse_scene(text, file)?))
            .collect::<Result<Vec<_>>>()?
    } else {
        v.scenes.iter().map(|p| read_scene(p)).collect::<Result<Vec<_>>>()?
    };
    let cases = distinct_pairs(&models).map_err(|(f, e)| Error::new(format!("{f}: {e}")))?;
    if let Some(ratios) = &v.conformity {
        return conformity(&cases, &v.mesh, ratios, v.json);
    }
    let mut rows = Vec::new();
    for case in &cases {
        let name = format!(
            "{} {}/{}",
            case.pair.shape.name(),
            case.pair.material1.name,
            case.pair.material2.name
        );
        eprintln!("validating {name} at {:.4} N ...", case.load);
        rows.push(validate_pair(case, &v.mesh, &v.levels).context(name)?);
    }
    if v.json {
        print_json(&rows)
    } else {
        emit(&kinrepro::report::contact::validate_hertz::table(&rows))
    }
}

/// `--conformity`: the study of each sphere-groove pair of the scenes.
fn conformity(cases: &[PairCase], mesh: &MeshOptions, ratios: &[f64], json: bool) -> Result {
    let grooves: Vec<&PairCase> = cases
        .iter()
        .filter(|c| c.pair.shape == kinrepro::contact::ContactShape::SphereGroove)
        .collect();
    if grooves.is_empty() {
        usage!(
            "--conformity: the scenes have no sphere-groove (gothic-arch) contact; give one, e.g. scenes/maxwell_gothic_arch_steel.toml"
        );
    }
    let mut studies = Vec::new();
    for case in grooves {
        let name =
            format!("sphere-groove {}/{}", case.pair.material1.name, case.pair.material2.name);
        eprintln!("conformity study of {name} at {:.4} N (two FE solves per ratio) ...", case.load);
        studies.push(conformity_study(case, mesh, ratios).context(name)?);
    }
    if json {
        print_json(&studies)
    } else {
        emit(&kinrepro::report::contact::validate_hertz::conformity_table(&studies))
    }
}
