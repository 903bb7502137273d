//! `kinrepro stiffness` and `kinrepro load`: the seated coupling under extra loads.

use std::path::PathBuf;

use kinrepro::analysis::load::{LEVER_RATIO_MAX, envelope, lever_ratio, load_path};
use kinrepro::analysis::stiffness::CouplingStiffness;
use kinrepro::report::coupling::analysis::{LoadReport, StiffnessReport};
use kinrepro::scene::Scene;
use kinrepro::solve::quasistatic::{ExternalLoad, seat};
use kinrepro::solve::{Load, SolverOptions};
use nalgebra::Vector3;

use super::{emit, finite3, number, print_json, read_scene};
use crate::error::{Context, Error, Result, usage};
use crate::flags::{LoadArgs, StiffnessArgs};

/// The scene's evaluation points by name.
fn evaluation_points(scene: &Scene) -> Vec<(String, Vector3<f64>)> {
    let points = &scene.evaluation_points;
    points.iter().map(|p| (p.name.clone(), p.position)).collect()
}

/// The scene's nominal load with the static coefficients `mu` if given.
fn load_of(scene: &Scene, mu: &Option<Vec<f64>>) -> Load {
    let nominal = Load::nominal(scene);
    match mu {
        Some(mu) => nominal.with_mu(mu),
        None => nominal,
    }
}

/// `kinrepro stiffness`, its flags checked.
pub struct Stiffness {
    scene: PathBuf,
    at: Option<Vector3<f64>>,
    mu: Option<Vec<f64>>,
    json: bool,
}

impl TryFrom<StiffnessArgs> for Stiffness {
    type Error = Error;

    fn try_from(a: StiffnessArgs) -> Result<Stiffness> {
        Ok(Stiffness {
            at: a.at.as_deref().map(|at| finite3("at", Some(at))).transpose()?,
            scene: a.scene,
            mu: a.mu,
            json: a.json,
        })
    }
}

pub fn stiffness(s: Stiffness) -> Result {
    let (scene, coupling) = read_scene(&s.scene)?;
    let points = match s.at {
        Some(at) => vec![("--at".to_string(), at)],
        None => evaluation_points(&scene),
    };
    let load = load_of(&scene, &s.mu);
    let file = &scene.file;
    let seating = seat(&coupling, &load, &SolverOptions::default()).context(file)?;
    let k = CouplingStiffness::new(&coupling, &seating, &load).context(file)?;
    let report = StiffnessReport::new(&scene, &load.mu, &seating, &k, &points).context(file)?;
    if s.json { print_json(&report) } else { emit(&report.table()) }
}

/// `kinrepro load`, its flags checked.
pub struct LoadCommand {
    scene: PathBuf,
    external: ExternalLoad,
    mu: Option<Vec<f64>>,
    json: bool,
}

impl TryFrom<LoadArgs> for LoadCommand {
    type Error = Error;

    fn try_from(a: LoadArgs) -> Result<LoadCommand> {
        if a.force.is_none() && a.moment.is_none() {
            usage!("give --force FX,FY,FZ with --at X,Y,Z, or --moment MX,MY,MZ, or both");
        }
        if a.force.is_some() && a.at.is_none() {
            usage!("--force needs --at X,Y,Z: the point of the moving half it acts at [m]");
        }
        let external = ExternalLoad {
            force: finite3("force", a.force.as_deref())?,
            point: finite3("at", a.at.as_deref())?,
            moment: finite3("moment", a.moment.as_deref())?,
        };
        if external.force.norm() == 0.0 && external.moment.norm() == 0.0 {
            usage!("--force and --moment are both zero: there is no load to apply");
        }
        Ok(LoadCommand { scene: a.scene, external, mu: a.mu, json: a.json })
    }
}

pub fn load(c: LoadCommand) -> Result {
    let (scene, coupling) = read_scene(&c.scene)?;
    let ext = c.external;
    let load = load_of(&scene, &c.mu);
    let file = &scene.file;
    let opts = SolverOptions::default();
    let seating = seat(&coupling, &load, &opts).context(file)?;
    let (ratio, size) = lever_ratio(&coupling, &ext.point);
    if ratio > LEVER_RATIO_MAX {
        usage!(
            "--at {}: the load point lies {} m from the origin, more than {LEVER_RATIO_MAX} times the coupling's size ({size} m, its farthest ball centre): a lever that long is no load for this coupling (did you give millimetres? the flags are in SI, m)",
            vector(&ext.point),
            number(ext.point.amax())
        );
    }
    let what = format!(
        "{file}: --force {} N at --at {} m, --moment {} N m",
        vector(&ext.force),
        vector(&ext.point),
        vector(&ext.moment)
    );
    let path = load_path(&coupling, &load, &seating, &ext, 1.0, &opts).context(format!(
        "{what}: the load path after seating failed (a load far beyond what the seat holds? a smaller load's safe load envelope tells where the seat is lost)"
    ))?;
    let envelope = envelope(&coupling, &load, &seating, &ext, &opts)
        .context(format!("{what}: the envelope search failed"))?;
    let mut points = evaluation_points(&scene);
    points.push(("load point".to_string(), ext.point));
    let report = LoadReport::new(&scene, &load.mu, &seating, &ext, &path, &envelope, &points);
    if c.json { print_json(&report) } else { emit(&report.table()) }
}

/// `x,y,z` as the flags take it.
fn vector(v: &Vector3<f64>) -> String {
    format!("{},{},{}", number(v.x), number(v.y), number(v.z))
}
