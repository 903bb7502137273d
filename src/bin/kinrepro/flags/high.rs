//! The high-level options: each verb's low-level arguments checked once
//! and turned into the typed values the library takes. Every check of a
//! flag's value, or of flags that go together, is here, and each error
//! names the flag and the reason ([`CliError::Usage`]); the commands take
//! these options, call the library and print.

use kinrepro::calibrate::fit::CalibrateOptions;
use kinrepro::calibrate::units::parse_noise;
use kinrepro::contact::{ContactPair, ContactShape, Friction, PairCurvature};
use kinrepro::fe::MeshOptions;
use kinrepro::material::Material;
use kinrepro::solve::Method;
use kinrepro::solve::dynamic::StartPose;
use kinrepro::solve::quasistatic::ExternalLoad;
use kinrepro::study::Shard;
use kinrepro::study::request::{self, StudyRequest, StudySettings};
use kinrepro::study::runner::StudyOptions;
use nalgebra::Vector3;

use super::low::*;
use super::low_study::DesignArg;
use crate::error::{CliError, Context};

/// A verb's arguments, checked, and the typed value made of them: the
/// command takes that value, and the plain arguments (paths, formats,
/// `--force`, `--jobs`) as given.
pub struct Checked<A, T> {
    pub args: A,
    pub opts: T,
}

/// `args` with what `check` makes of them.
pub fn checked<A, T>(
    args: A,
    check: impl FnOnce(&A) -> Result<T, CliError>,
) -> Result<Checked<A, T>, CliError> {
    let opts = check(&args)?;
    Ok(Checked { args, opts })
}

/// `kinrepro contact`: the pair with its materials, and the friction of
/// `--history`.
pub struct ContactInputs {
    pub pair: ContactPair,
    pub history_friction: Option<Friction>,
}

/// `kinrepro calibrate`: the calibration's options and `--delimiter`.
pub struct CalibrateInputs {
    pub options: CalibrateOptions,
    pub delimiter: Option<u8>,
}

fn usage(message: impl Into<String>) -> CliError {
    CliError::Usage(message.into())
}

/// The arguments that need no conversion, checked: `stiffness --at`.
pub fn stiffness(a: &StiffnessArgs) -> Result<Option<Vector3<f64>>, CliError> {
    a.at.as_deref()
        .map(|at| finite3("at", Some(at)))
        .transpose()
}

/// `predict --samples` and `--jobs`.
pub fn predict(a: &PredictArgs) -> Result<(), CliError> {
    model_samples("--samples", a.samples)?;
    jobs(a.jobs)
}

/// The seating solver: for the quasi-static one `--increments N` (fixed
/// steps) or `--path-tolerance TOL` (load-path error control, the
/// default), `start` for the dynamic one (checked by the library,
/// [`request::method`]).
fn method(
    solver: SolverKind,
    increments: Option<usize>,
    path_tolerance: Option<f64>,
    start: StartPose,
) -> Result<Method, CliError> {
    request::method(solver.into(), increments, path_tolerance, start).map_err(|e| usage(e.0))
}

/// `--jobs`: at least one worker thread (capped when the pool is built).
fn jobs(jobs: Option<usize>) -> Result<(), CliError> {
    match jobs {
        Some(0) => Err(usage("--jobs 0: need at least 1 worker thread")),
        _ => Ok(()),
    }
}

/// Three comma-separated values of `--{flag}` (None: zero).
fn vector3(flag: &str, v: Option<&[f64]>) -> Result<Vector3<f64>, CliError> {
    match v {
        None => Ok(Vector3::zeros()),
        Some(&[x, y, z]) => Ok(Vector3::new(x, y, z)),
        Some(v) => Err(usage(format!(
            "--{flag} needs three comma-separated values, got {}",
            v.len()
        ))),
    }
}

/// Three finite values of `--{flag}` (None: zero).
fn finite3(flag: &str, v: Option<&[f64]>) -> Result<Vector3<f64>, CliError> {
    let x = vector3(flag, v)?;
    if x.iter().all(|c| c.is_finite()) {
        Ok(x)
    } else {
        Err(usage(format!(
            "--{flag} needs three finite numbers, got ({}, {}, {})",
            x.x, x.y, x.z
        )))
    }
}

/// A sample count of a model study (`flag`): at least
/// [`kinrepro::calibrate::model::MIN_MODEL_SAMPLES`].
fn model_samples(flag: &str, n: usize) -> Result<usize, CliError> {
    kinrepro::calibrate::model::check_model_samples(flag, n).map_err(usage)
}

pub fn contact(a: &ContactArgs) -> Result<ContactInputs, CliError> {
    super::unused::contact(a)?;
    let history_friction = match a.history {
        None => None,
        Some(_) => {
            let mu = a.mu.unwrap_or(f64::NAN);
            if !(mu.is_finite() && mu > 0.0) {
                return Err(usage(format!(
                    "--mu {mu}: the friction coefficient must be positive and finite"
                )));
            }
            let ratio = a.dynamic_ratio;
            if !(ratio > 0.0 && ratio <= 1.0) {
                return Err(usage(format!(
                    "--dynamic-ratio {ratio}: must lie in (0, 1]"
                )));
            }
            Some(Friction::switch(mu, ratio * mu))
        }
    };
    let material1 = Material::builtin(&a.material1).context("--material1")?;
    let material2 = Material::builtin(&a.material2).context("--material2")?;
    let pair = match (a.shape, &a.radii1, &a.radii2) {
        (Some(shape), _, _) => {
            let r1 = a.radius1.unwrap_or(f64::NAN);
            ContactPair::from_shape(shape, r1, a.radius2, material1, material2)?
        }
        (None, Some(r1), Some(r2)) => ContactPair {
            shape: ContactShape::General,
            curvature: PairCurvature {
                radii1: principal_radii("--radii1", r1)?,
                radii2: principal_radii("--radii2", r2)?,
                angle: a.angle_deg.unwrap_or(0.0).to_radians(),
            },
            material1,
            material2,
        },
        _ => {
            return Err(usage(
                "give --shape with --radius1, or --radii1 with --radii2",
            ));
        }
    };
    // A contact that is not a point contact is refused here, in words.
    pair.law()?;
    Ok(ContactInputs {
        pair,
        history_friction,
    })
}

/// The two principal radii RX,RY [m] of `--radii1` or `--radii2`.
fn principal_radii(flag: &str, v: &[f64]) -> Result<[f64; 2], CliError> {
    match v {
        [x, y] => Ok([*x, *y]),
        _ => Err(usage(format!(
            "{flag} needs two comma-separated principal radii RX,RY [m] (inf: flat, negative: concave), got {} value(s)",
            v.len()
        ))),
    }
}

pub fn run(a: &RunArgs) -> Result<Method, CliError> {
    if a.solver == SolverKind::QuasiStatic
        && (a.trace.is_some() || a.offset.is_some() || a.tilt.is_some())
    {
        return Err(usage("--trace, --offset and --tilt need --solver dynamic"));
    }
    let start = StartPose {
        offset: vector3("offset", a.offset.as_deref())?,
        tilt: vector3("tilt", a.tilt.as_deref())?,
    };
    method(a.solver, a.increments, a.path_tolerance, start)
}

pub fn load(a: &LoadArgs) -> Result<ExternalLoad, CliError> {
    let load = ExternalLoad {
        force: finite3("force", Some(&a.force))?,
        point: finite3("at", Some(&a.at))?,
        moment: finite3("moment", a.moment.as_deref())?,
    };
    if load.force.norm() == 0.0 && load.moment.norm() == 0.0 {
        return Err(usage(
            "--force and --moment are both zero: there is no load to apply",
        ));
    }
    Ok(load)
}

/// `kinrepro study`: the flags as the library's [`StudyRequest`], checked
/// there (the Python package's `study` makes the same request).
pub fn study(a: &StudyArgs) -> Result<StudySettings, CliError> {
    super::unused::study(a)?;
    jobs(a.jobs)?;
    let triple = |flag: &str, v: Option<&[f64]>| {
        v.map(|v| vector3(flag, Some(v)).map(Into::into))
            .transpose()
    };
    StudyRequest {
        sampler: a.sampler,
        samples: a.samples,
        seed: a.seed,
        shard: a.shard.unwrap_or_else(Shard::whole),
        solver: a.solver.into(),
        increments: a.increments,
        path_tolerance: a.path_tolerance,
        vary: a.vary.iter().map(|&v| v.into()).collect(),
        offset_bounds: triple("offset-bounds", a.offset_bounds.as_deref())?,
        tilt_bounds: triple("tilt-bounds", a.tilt_bounds.as_deref())?,
        sensitivity: a.sensitivity,
        sobol_samples: a.sensitivity.then_some(a.sobol_samples),
        replicates: a.replicates,
    }
    .check()
    .map_err(|e| usage(e.0))
}

/// `kinrepro sweep`: each design point's study, friction varied and
/// quasi-static, as the library's [`StudyRequest`].
pub fn sweep(a: &SweepArgs) -> Result<StudyOptions, CliError> {
    super::unused::sweep(a)?;
    match (a.design, a.points) {
        (DesignArg::Grid, Some(_)) => return Err(usage("--points needs --design lhs")),
        (DesignArg::Lhs, None) => return Err(usage("--design lhs needs --points N")),
        _ => jobs(a.jobs)?,
    }
    let request = StudyRequest {
        sampler: a.sampler,
        samples: a.samples,
        seed: a.seed,
        shard: a.shard.unwrap_or_else(Shard::whole),
        increments: a.increments,
        path_tolerance: a.path_tolerance,
        replicates: a.replicates,
        ..StudyRequest::default()
    };
    Ok(request.check().map_err(|e| usage(e.0))?.options)
}

pub fn validate_hertz(a: &ValidateHertzArgs) -> Result<MeshOptions, CliError> {
    let levels = a.convergence.as_deref().unwrap_or_default();
    if let Some(l) = levels
        .iter()
        .find(|l| !(l.is_finite() && **l > 0.0 && **l <= 1.0))
    {
        return Err(usage(format!(
            "--convergence {l}: element sizes are fractions of the contact semi-axis, in (0, 1]"
        )));
    }
    for &element_size_rel in levels {
        let level = MeshOptions {
            element_size_rel,
            ..MeshOptions::default()
        };
        level.check_size().context("--convergence")?;
    }
    if let Some(r) = &a.ratios {
        if !a.conformity {
            return Err(usage("--ratios goes with --conformity"));
        }
        if r.is_empty() || r.iter().any(|q| !(q.is_finite() && *q > 1.0)) {
            return Err(usage(
                "--ratios: groove / ball radius ratios must be numbers above 1",
            ));
        }
        if r.windows(2).any(|w| w[1] >= w[0]) {
            return Err(usage("--ratios: give the ratios in descending order"));
        }
    }
    if a.conformity && a.convergence.is_some() {
        return Err(usage("--convergence does not go with --conformity"));
    }
    Ok(match a.mesh {
        MeshKind::Default => MeshOptions::default(),
        MeshKind::Coarse => MeshOptions::coarse(),
    })
}

pub fn calibrate(a: &CalibrateArgs) -> Result<CalibrateInputs, CliError> {
    let mut noise = [None; 6];
    if let Some(n) = &a.noise {
        parse_noise(n, &mut noise).map_err(|e| usage(format!("--noise: {e}")))?;
    }
    jobs(a.jobs)?;
    Ok(CalibrateInputs {
        delimiter: (a.delimiter.as_deref())
            .map(kinrepro::delimited::delimiter_named)
            .transpose()
            .map_err(usage)?,
        options: CalibrateOptions {
            fit: a.fit.iter().map(|s| s.trim().to_string()).collect(),
            noise,
            point: a.point.clone(),
            samples: model_samples("--model-samples", a.model_samples)?,
            seed: a.seed,
            method: Method::default(),
        },
    })
}
