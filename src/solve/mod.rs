//! Seating solvers and their result types.
//!
//! The quasi-static path-following solver ([`quasistatic`]) ramps the
//! preload and solves the six pose unknowns by Newton at each increment; it
//! shares the compliant contact layer ([`contact_layer`]) with the dynamic
//! solver.

pub mod contact_lanes;
pub mod contact_layer;
pub mod dynamic;
pub mod load;
pub mod preload_forces;
pub mod quasistatic;
pub mod thermal;

use nalgebra::Vector3;
use serde::Serialize;
use thiserror::Error;

use crate::assembly::{AssemblyError, BodyPose, Coupling};
use crate::contact::stress::{LeftOut, contact_stress};
use crate::contact::{Friction, SlipState};
use crate::param::{Param, ParamError};
use contact_layer::ContactEval;
pub use load::{Load, frictions_into, nominal_cycle, nominal_mu, thermal_tolerance};

/// The accepted numbers of nominal load increments (`increments`).
pub const INCREMENTS: std::ops::RangeInclusive<usize> = 1..=100_000;

/// The accepted load-path tolerances (`path_tolerance`): below about
/// 1e-8 the Newton residual tolerance, not the path, bounds the pose.
pub const PATH_TOLERANCES: std::ops::RangeInclusive<f64> = 1e-9..=1e-2;

/// The default load-path tolerance: the estimated discretisation error of
/// a seated pose relative to the seating's motion
/// (`quasistatic::control`).
pub const DEFAULT_PATH_TOLERANCE: f64 = 1e-5;

/// Settings of the quasi-static solver.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct SolverOptions {
    /// Nominal number of load increments (uniform in F^(2/3), i.e. in
    /// approach) of a fixed-step seating; a load path's increments.
    pub increments: usize,
    /// Load-path error control of a seating (`quasistatic::control`): the
    /// tolerance on the estimated relative error of the seated pose, or
    /// `None` for the fixed `increments` (`--increments`).
    pub path_tolerance: Option<f64>,
    /// How often an increment may be halved (stick/slip changes, Newton trouble).
    pub max_splits: u32,
    /// Newton iterations per increment.
    pub max_newton: usize,
    /// Force residual tolerance relative to the preload (moments: to preload x
    /// coupling radius).
    pub tolerance: f64,
}

impl SolverOptions {
    /// A seating on `increments` fixed nominal increments, without
    /// load-path error control (`--increments`).
    pub fn fixed(increments: usize) -> Self {
        SolverOptions { increments, path_tolerance: None, ..Default::default() }
    }
}

impl Default for SolverOptions {
    fn default() -> Self {
        SolverOptions {
            increments: 20,
            path_tolerance: Some(DEFAULT_PATH_TOLERANCE),
            max_splits: 8,
            max_newton: 40,
            tolerance: 1e-10,
        }
    }
}

/// A seating that did not end in a valid seated pose.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum SolveError {
    #[error("{} needs {expected} values (one per contact, in contact order), got {got}", Param::Mu)]
    MuCount { expected: usize, got: usize },
    #[error(
        "the static friction coefficient of contact {index} = {value} is outside [0, {max}] \
         (the value given by {}, or drawn from the scene's mu_static +- spread)",
        Param::Mu
    )]
    MuRange { index: usize, value: f64, max: f64 },
    #[error(
        "the seating solve did not converge at {percent:.3} % of the preload (relative residual \
         {residual:.3e} after halving the increment {splits} times)"
    )]
    NotConverged { percent: f64, residual: f64, splits: u32 },
    #[error(
        "the load path did not converge at {percent:.3} % of the applied load (relative \
         residual {residual:.3e} after halving the increment {splits} times)"
    )]
    LoadNotConverged { percent: f64, residual: f64, splits: u32 },
    #[error(
        "the coupling slides away under the load: at {percent:.3} % of the applied load the \
         moving half has moved {displacement_m:.3e} m"
    )]
    LoadSlidAway { percent: f64, displacement_m: f64 },
    #[error(
        "contact {contact} opened completely at {percent:.3} % of the preload: the preload lifts \
         the moving half off that contact instead of seating it"
    )]
    ContactOpened { contact: usize, percent: f64 },
    #[error(
        "the coupling slides away instead of seating: at {percent:.3} % of the preload the \
         moving half has moved {displacement_m:.3e} m"
    )]
    SlidAway { percent: f64, displacement_m: f64 },
    #[error(
        "the coupling does not centre: the moving half came to rest with contact(s) {open} open \
         (largest gap {gap_m:.3e} m) at full preload; friction (largest mu_s {mu_max}) holds it \
         off its seat. The friction limit of this coupling is mu = {mu_limit:.4} (contact \
         {critical_contact} the first to stay open): lower the friction below it"
    )]
    NotCentred {
        /// The open contacts, 1-based, as a list ("2, 5").
        open: String,
        gap_m: f64,
        mu_max: f64,
        mu_limit: f64,
        critical_contact: usize,
    },
    #[error(
        "the dynamic seating did not settle within {time_s:.4e} s ({steps} steps): kinetic \
         energy {kinetic_j:.3e} J, relative force residual {residual:.3e}"
    )]
    NotSettled { time_s: f64, steps: usize, kinetic_j: f64, residual: f64 },
    #[error(
        "the start pose overlaps contact {contact} by {overlap_m:.3e} m: an offset start must \
         leave every ball clear of its surfaces (raise the z offset or reduce the tilt)"
    )]
    StartOverlaps { contact: usize, overlap_m: f64 },
    #[error("invalid dynamic-solver setting: {0}")]
    BadOption(String),
    #[error(
        "the dynamic seating became non-finite at t = {time_s:.4e} s (step {step}): the time \
         step is too large for the contact stiffness"
    )]
    NonFinite { time_s: f64, step: usize },
    #[error(
        "contact {contact} opened completely on the thermal path at temperature changes \
         [{moving_k}, {fixed_k}] K (moving, fixed body): the bodies' mismatch lifts the moving \
         half off it"
    )]
    ThermalContactOpened { contact: usize, moving_k: f64, fixed_k: f64 },
    #[error(
        "the coupling slides away on the thermal path: at temperature changes [{moving_k}, \
         {fixed_k}] K the moving half has moved {displacement_m:.3e} m"
    )]
    ThermalSlidAway { moving_k: f64, fixed_k: f64, displacement_m: f64 },
    #[error(
        "the thermal path did not converge at temperature changes [{moving_k}, {fixed_k}] K \
         (relative residual {residual:.3e} after halving the increment {splits} times)"
    )]
    ThermalNotConverged { moving_k: f64, fixed_k: f64, residual: f64, splits: u32 },
    #[error("{0}")]
    Thermal(#[from] AssemblyError),
    #[error("the thermal path needs the quasi-static solver (the dynamic solver seats only)")]
    ThermalNeedsQuasiStatic,
    #[error("interrupted")]
    Cancelled,
}

/// Per-contact state at the end of a seating (SI units).
#[derive(Debug, Clone, PartialEq, Serialize)]
pub struct ContactResult {
    pub normal_force_n: f64,
    /// Tangential (friction) force on the moving half [N].
    pub tangential_force: [f64; 3],
    pub tangential_force_n: f64,
    pub approach_m: f64,
    /// The approach split into the Hertz part (F/K)^(2/3) and the part c F
    /// of the series support compliance c (`contact::series`) [m].
    pub hertz_approach_m: f64,
    pub support_approach_m: f64,
    /// Support compliance c [m/N] (0: none).
    pub support_compliance_m_per_n: f64,
    /// Its tangential support compliance (in series with Mindlin's) [m/N],
    /// along `tangential_support_axis` when that is given; left out of
    /// the JSON when 0.
    #[serde(skip_serializing_if = "crate::scene::is_zero")]
    pub tangential_support_compliance_m_per_n: f64,
    /// An anisotropic support's compliance across its axis [m/N] and the
    /// axis (unit, world frame at the scene pose); absent when isotropic.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tangential_support_compliance_across_m_per_n: Option<f64>,
    #[serde(skip_serializing_if = "Option::is_none")]
    pub tangential_support_axis: Option<[f64; 3]>,
    pub state: SlipState,
    /// Static and dynamic coefficient used.
    pub mu_static: f64,
    pub mu_dynamic: f64,
    pub max_pressure_pa: f64,
    /// Peak pressure / allowable pressure of the weaker material, where known.
    pub pressure_ratio: Option<f64>,
    /// Maximum (subsurface) shear stress, the larger of the two bodies [Pa]
    /// (`contact::stress`: closed form for circles, quadrature for ellipses).
    pub max_shear_stress_pa: f64,
    /// Depth of the maximum shear stress [m] (circular contacts).
    pub max_shear_depth_m: Option<f64>,
    /// Allowable / actual for the pressure, the shear stress, and the smaller
    /// of the two; `None` where no allowable is known.
    pub pressure_safety_factor: Option<f64>,
    pub shear_safety_factor: Option<f64>,
    pub safety_factor: Option<f64>,
    /// Materials a safety factor had to leave out: they lack the allowable
    /// the other body has (`contact::stress`), so the factor does not cover them.
    pub safety_factor_left_out: Vec<LeftOut>,
    pub point_m: [f64; 3],
    pub normal: [f64; 3],
}

impl ContactResult {
    /// The reported state of contact `i` from its evaluation by the contact
    /// layer (shared by both solvers).
    pub fn from_eval(coupling: &Coupling, i: usize, e: &ContactEval, friction: Friction) -> Self {
        let contact = &coupling.contacts[i];
        let ft = -e.tangential.force;
        let support = contact.law.tangential_support;
        let anisotropic = !support.is_isotropic();
        let stress =
            contact_stress(&contact.pair, &contact.law.hertz, &contact.shear, e.normal_force);
        ContactResult {
            normal_force_n: e.normal_force,
            tangential_force: ft.into(),
            tangential_force_n: ft.norm(),
            approach_m: e.approach,
            hertz_approach_m: contact.normal.hertz.approach(e.normal_force),
            support_approach_m: contact.normal.support_approach(e.normal_force),
            support_compliance_m_per_n: contact.normal.compliance,
            tangential_support_compliance_m_per_n: support.along,
            tangential_support_compliance_across_m_per_n: anisotropic.then_some(support.across),
            tangential_support_axis: anisotropic.then_some(support.axis.into()),
            state: e.slip(),
            mu_static: friction.mu_s,
            mu_dynamic: friction.mu_d,
            max_pressure_pa: stress.max_pressure_pa,
            // p0 / allowable is the inverse of the pressure safety factor.
            pressure_ratio: stress.pressure_safety_factor.map(|sf| 1.0 / sf),
            max_shear_stress_pa: stress.max_shear_stress_pa[0].max(stress.max_shear_stress_pa[1]),
            max_shear_depth_m: stress.max_shear_depth_m,
            pressure_safety_factor: stress.pressure_safety_factor,
            shear_safety_factor: stress.shear_safety_factor,
            safety_factor: stress.safety_factor,
            safety_factor_left_out: stress.left_out,
            point_m: e.geometry.point.into(),
            normal: e.geometry.normal.into(),
        }
    }
}

/// A seating with its per-contact report.
#[derive(Debug, Clone, PartialEq)]
pub struct Seating {
    /// The pose-level result.
    pub seated: SeatedPose,
    pub contacts: Vec<ContactResult>,
}

/// The pose-level result of a seating, without the per-contact report:
/// what a study keeps of each sample (`quasistatic::seat_in` returns it
/// without allocating).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SeatedPose {
    /// Final pose of the moving half.
    pub pose: BodyPose,
    /// Accepted load increments and Newton iterations in all.
    pub increments: usize,
    pub newton_iterations: usize,
    /// Which path of the solver produced it.
    pub path: SeatingPath,
    /// The decay law's c v_slip (`contact::friction::TRANSITION`): of the
    /// contacts that slid, the value deepest inside the transition; `None`
    /// for the switch law or no slip.
    pub decay_cv: Option<f64>,
    /// Estimated discretisation error of `pose` relative to the seating's
    /// motion (`quasistatic::control`); `None` where not estimated (fixed
    /// increments, the dynamic solver).
    pub path_error: Option<f64>,
    /// Whether a contact slid at some point of the seating (gross sliding
    /// in an accepted increment or a time step; a frictionless contact
    /// always slides). `false`: every contact stuck from the first load
    /// on, the verdict of `study::verdict`.
    pub slid: bool,
}

impl Seating {
    /// Final pose of the moving half.
    pub fn pose(&self) -> BodyPose {
        self.seated.pose
    }
}

/// Which path seated the coupling (`seating_path` in `run --json`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum SeatingPath {
    /// The quasi-static path took the nominal increments s_k = k/N
    /// without halving one.
    Uniform,
    /// The quasi-static path halved an increment (at a stick/slip change
    /// or where Newton failed).
    Adaptive,
    Dynamic,
}

impl SeatingPath {
    /// The name as in `run --json`.
    pub fn name(self) -> &'static str {
        match self {
            SeatingPath::Uniform => "uniform",
            SeatingPath::Adaptive => "adaptive",
            SeatingPath::Dynamic => "dynamic",
        }
    }
}

/// Pose of an evaluation point relative to a reference pose.
pub use crate::dof::PointPose;

impl PointPose {
    /// Motion of body point `p` (scene coordinates) from pose `from` to pose
    /// `to`: translation of the point and the rotation vector of
    /// R R_ref^-1 (finite rotation).
    pub fn between(from: &BodyPose, to: &BodyPose, p: &Vector3<f64>) -> Self {
        let d = to.apply(p) - from.apply(p);
        let phi = (to.rotation * from.rotation.inverse()).scaled_axis();
        PointPose::from_components([d.x, d.y, d.z, phi.x, phi.y, phi.z])
    }
}

/// The seating solver (`solver`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default, clap::ValueEnum)]
pub enum Solver {
    /// Quasi-static path following (Newton per load increment).
    #[default]
    #[value(alias = "quasistatic", alias = "quasi_static")]
    QuasiStatic,
    /// Seating dynamics with rapier3d-f64 and the compliant contact layer.
    Dynamic,
}

impl std::str::FromStr for Solver {
    type Err = ParamError;

    /// `quasi-static` (or `quasistatic`, `quasi_static`), `dynamic`.
    fn from_str(s: &str) -> Result<Self, ParamError> {
        <Solver as clap::ValueEnum>::from_str(s, false).map_err(|_| {
            ParamError::new(
                Param::Solver,
                format!("{}: unknown, need quasi-static or dynamic", Param::Solver.with(s)),
            )
        })
    }
}

/// Which solver seats the coupling, with its settings (serialised as
/// `{"quasi-static": {...}}`, the fingerprint's `solver_settings`).
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Method {
    /// Quasi-static path following (the default).
    QuasiStatic(SolverOptions),
    /// Seating dynamics with rapier3d-f64.
    Dynamic(dynamic::DynamicOptions),
}

impl Default for Method {
    fn default() -> Self {
        Method::QuasiStatic(SolverOptions::default())
    }
}

impl Method {
    /// The seating method of `solver`. Quasi-static: `increments` N fixed
    /// load increments ([`SolverOptions::fixed`], not error-controlled), or
    /// else load-path error control to `path_tolerance` (None:
    /// [`SolverOptions::default`]'s); the two exclude each other. Dynamic:
    /// its time step comes from the contact frequencies, so increments and
    /// a path tolerance are refused there.
    pub fn new(
        solver: Solver,
        increments: Option<usize>,
        path_tolerance: Option<f64>,
    ) -> Result<Method, ParamError> {
        let (inc, tol) = (Param::Increments, Param::PathTolerance);
        let fail = |p: Param, m: String| Err(ParamError::new(p, m));
        match (solver, increments, path_tolerance) {
            (Solver::Dynamic, Some(n), _) => fail(
                inc,
                format!(
                    "{}: has no effect with {} (load increments belong to the quasi-static solver; the dynamic one steps in time)",
                    inc.with(n),
                    Param::Solver.with("dynamic")
                ),
            ),
            (Solver::Dynamic, None, Some(t)) => fail(
                tol,
                format!(
                    "{}: has no effect with {} (the load path belongs to the quasi-static solver; the dynamic one steps in time)",
                    tol.with(t),
                    Param::Solver.with("dynamic")
                ),
            ),
            (Solver::Dynamic, None, None) => Ok(Method::Dynamic(Default::default())),
            (Solver::QuasiStatic, Some(n), Some(t)) => fail(
                inc,
                format!(
                    "{} and {} exclude each other: fixed load increments are not error-controlled (give one)",
                    inc.with(n),
                    tol.with(t)
                ),
            ),
            (Solver::QuasiStatic, Some(n), None) if !INCREMENTS.contains(&n) => fail(
                inc,
                format!(
                    "{}: out of range, need {}..={} load increments",
                    inc.with(n),
                    INCREMENTS.start(),
                    INCREMENTS.end()
                ),
            ),
            (Solver::QuasiStatic, Some(n), None) => {
                Ok(Method::QuasiStatic(SolverOptions::fixed(n)))
            }
            (Solver::QuasiStatic, None, Some(t)) if !PATH_TOLERANCES.contains(&t) => fail(
                tol,
                format!(
                    "{}: out of range, need {:e}..={:e} (the estimated error of the seated pose relative to the seating's motion)",
                    tol.with(t),
                    PATH_TOLERANCES.start(),
                    PATH_TOLERANCES.end()
                ),
            ),
            (Solver::QuasiStatic, None, t) => Ok(Method::QuasiStatic(SolverOptions {
                path_tolerance: t.or(SolverOptions::default().path_tolerance),
                ..Default::default()
            })),
        }
    }

    /// The load-path tolerance of a quasi-static seating (None: fixed
    /// increments, or the dynamic solver).
    pub fn path_tolerance(&self) -> Option<f64> {
        match self {
            Method::QuasiStatic(o) => o.path_tolerance,
            Method::Dynamic(_) => None,
        }
    }

    /// The solver's name, as on the command line.
    pub fn name(&self) -> &'static str {
        match self {
            Method::QuasiStatic(_) => "quasi-static",
            Method::Dynamic(_) => "dynamic",
        }
    }

    /// Seat the coupling under `load` (the dynamic solver starts at
    /// `load.start`, the quasi-static one from the touching pose).
    pub fn seat(&self, coupling: &Coupling, load: &Load) -> Result<Seating, SolveError> {
        match self {
            Method::QuasiStatic(o) => quasistatic::seat(coupling, load, o),
            Method::Dynamic(o) => dynamic::seat(coupling, load, o),
        }
    }

    /// Seat the coupling under `load` and follow its temperature cycle
    /// (`load.cycle`, the coupling's `[thermal]` bodies): the quasi-static
    /// solver only ([`quasistatic::seat_and_cycle`]).
    pub fn seat_and_cycle(
        &self,
        coupling: &Coupling,
        load: &Load,
    ) -> Result<(Seating, thermal::ThermalPath), SolveError> {
        match self {
            Method::QuasiStatic(o) => quasistatic::seat_and_cycle(coupling, load, o),
            Method::Dynamic(_) => Err(SolveError::ThermalNeedsQuasiStatic),
        }
    }
}
