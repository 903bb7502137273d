//! The low-level arguments: what clap parses, one struct per verb, as
//! close to the command line as the types allow (numbers, paths, names of
//! a fixed set). Nothing here checks a value against a range or another
//! flag; [`super::high`] does that, once, for every verb.

use std::path::PathBuf;

use clap::{Args, Parser, Subcommand, ValueEnum};
use kinrepro::contact::{ContactShape, TangentialLaw};

#[derive(Parser)]
#[command(
    name = "kinrepro",
    version,
    about = "Re-seating reproducibility of kinematic couplings"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

pub use super::low_study::{CalibrateArgs, PredictArgs, StudyArgs, SweepArgs};

#[derive(Subcommand)]
pub enum Command {
    /// Evaluate one contact pair (Hertz, Mindlin, tau_max) at a load, or drive
    /// it through a load history (--history).
    Contact(ContactArgs),
    /// Load and validate scenes; print contacts, constraint status and friction limit.
    Check(CheckArgs),
    /// Seat the coupling once and print pose and contact states.
    Run(RunArgs),
    /// Stiffness of the seated coupling: 6x6 matrix, compliance and principal
    /// stiffnesses at a point (contacts at rest: static friction sticks).
    Stiffness(StiffnessArgs),
    /// Apply a force (and moment) after seating, preload held: deflection,
    /// contact forces and the safe load envelope (first separation or slip).
    Load(LoadArgs),
    /// Reproducibility study: seat each scene once per friction sample and
    /// report the scatter of the pose (Table 2 of the paper).
    Study(StudyArgs),
    /// Merge the JSON outputs of sharded studies (or sweeps) into the result of one run.
    Merge(MergeArgs),
    /// Sweep scene fields over a grid or an LHS: reproducibility, stiffness,
    /// safety and friction limit per design point, and the Pareto front.
    Sweep(SweepArgs),
    /// Check the Hertz law of every distinct contact pair of the scenes with
    /// the mini FE solver, at the load the nominal seating reaches.
    ValidateHertz(ValidateHertzArgs),
    /// Print the explicit form of a scene (loads back to the same coupling).
    Expand(ExpandArgs),
    /// Write one self-contained HTML report of study JSON files.
    Report(ReportArgs),
    /// List the built-in materials with E, nu, density, allowable pressure and sources.
    Materials(MaterialsArgs),
    /// Fit the friction spread of a scene to a measured re-seating scatter
    /// (docs/measurements.md) and write a calibration file.
    Calibrate(CalibrateArgs),
    /// Predict sigma of other scenes with a calibrated friction spread, with
    /// a prediction interval.
    Predict(PredictArgs),
}

#[derive(Args)]
pub struct ContactArgs {
    /// sphere-plane | sphere-sphere | sphere-seat | sphere-cylinder
    /// (shorthands of --radii1/--radii2).
    #[arg(long, required_unless_present = "radii1", conflicts_with = "radii1")]
    pub shape: Option<ContactShape>,
    /// Radius of the moving ball [m] (with --shape).
    #[arg(
        long,
        allow_hyphen_values = true,
        required_unless_present = "radii1",
        conflicts_with = "radii1"
    )]
    pub radius1: Option<f64>,
    /// Radius of the fixed sphere, seat or cylinder [m] (with --shape).
    #[arg(long, allow_hyphen_values = true, conflicts_with = "radii1")]
    pub radius2: Option<f64>,
    /// Principal radii RX,RY of body 1, the moving element [m] (negative:
    /// concave, inf: flat).
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        requires = "radii2"
    )]
    pub radii1: Option<Vec<f64>>,
    /// Principal radii RX,RY of body 2, the fixed element [m].
    #[arg(
        long,
        value_delimiter = ',',
        allow_hyphen_values = true,
        requires = "radii1"
    )]
    pub radii2: Option<Vec<f64>>,
    /// Angle from body 1's RX direction to body 2's [deg] (with --radii1).
    #[arg(long, allow_hyphen_values = true, requires = "radii1")]
    pub angle_deg: Option<f64>,
    /// Material of the ball (built-in name, e.g. steel).
    #[arg(long)]
    pub material1: String,
    /// Material of the fixed element.
    #[arg(long)]
    pub material2: String,
    /// Normal load [N] (not with --history, whose file gives the loads).
    #[arg(long, allow_hyphen_values = true, required_unless_present = "history")]
    pub load: Option<f64>,
    /// Print one JSON object instead of a table.
    #[arg(long, conflicts_with = "history")]
    pub json: bool,
    /// Drive the contact through the load history in this CSV (header
    /// P_N,Qx_N,Qy_N) and print step,P_N,Qx_N,Qy_N,sx_m,sy_m,slip.
    #[arg(long, requires = "mu")]
    pub history: Option<PathBuf>,
    /// Static friction coefficient mu_s (with --history).
    #[arg(long, allow_hyphen_values = true, requires = "history")]
    pub mu: Option<f64>,
    /// mu_d = ratio * mu_s, in (0, 1] (with --history).
    #[arg(
        long,
        default_value_t = 0.8,
        allow_hyphen_values = true,
        requires = "history"
    )]
    pub dynamic_ratio: f64,
    /// coulomb | mindlin-deresiewicz (with --history).
    #[arg(long, default_value = "coulomb", requires = "history")]
    pub tangential_law: TangentialLaw,
}

#[derive(Args)]
pub struct CheckArgs {
    /// Scene files (TOML).
    #[arg(required = true)]
    pub scenes: Vec<PathBuf>,
}

#[derive(Args)]
pub struct RunArgs {
    /// Scene file (TOML).
    pub scene: PathBuf,
    /// Static friction coefficients, one per contact in contact order
    /// (default: the scene's nominal mu_static everywhere).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub mu: Option<Vec<f64>>,
    /// Fixed load increments (quasi-static solver), 1..=100000, instead
    /// of the load-path error control.
    #[arg(long)]
    pub increments: Option<usize>,
    /// Load-path error control (quasi-static solver, the default): the
    /// tolerance on the estimated error of the seated pose relative to the
    /// seating's motion, 1e-9..=1e-2 [default: 1e-5]; excludes --increments.
    #[arg(long, allow_hyphen_values = true)]
    pub path_tolerance: Option<f64>,
    /// Seating solver.
    #[arg(long, value_enum, default_value_t = SolverKind::QuasiStatic)]
    pub solver: SolverKind,
    /// Dynamic solver: write the time history (CSV, SI units) to this file
    /// (refused if it exists, unless --force).
    #[arg(long)]
    pub trace: Option<PathBuf>,
    /// Replace an existing --trace file.
    #[arg(long, requires = "trace")]
    pub force: bool,
    /// Dynamic solver: start offset x,y,z of the moving half from the touching pose [m].
    #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
    pub offset: Option<Vec<f64>>,
    /// Dynamic solver: start tilt phi_x,phi_y,phi_z (rotation vector about the origin) [rad].
    #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
    pub tilt: Option<Vec<f64>>,
    /// Print one JSON object (SI units) instead of a table.
    #[arg(long)]
    pub json: bool,
}

#[derive(Args)]
pub struct StiffnessArgs {
    /// Scene file (TOML).
    pub scene: PathBuf,
    /// Point of the moving half x,y,z [m] (default: the scene's evaluation points).
    #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
    pub at: Option<Vec<f64>>,
    /// Static friction coefficients, one per contact (default: nominal).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub mu: Option<Vec<f64>>,
    /// Print one JSON object (SI units) instead of a table.
    #[arg(long)]
    pub json: bool,
}

#[derive(Args)]
pub struct LoadArgs {
    /// Scene file (TOML).
    pub scene: PathBuf,
    /// Force fx,fy,fz [N] (fixed direction).
    #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
    pub force: Vec<f64>,
    /// Point of application x,y,z in the moving half [m].
    #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
    pub at: Vec<f64>,
    /// Moment mx,my,mz [N m] (default 0).
    #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
    pub moment: Option<Vec<f64>>,
    /// Static friction coefficients, one per contact (default: nominal).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub mu: Option<Vec<f64>>,
    /// Print one JSON object (SI units) instead of a table.
    #[arg(long)]
    pub json: bool,
}

#[derive(Args)]
pub struct MergeArgs {
    /// JSON files written by `kinrepro study --shard I/N --format json` (or
    /// `kinrepro sweep --shard I/N --format json`).
    #[arg(required = true)]
    pub parts: Vec<PathBuf>,
    #[arg(long, value_enum, default_value_t = Format::Json)]
    pub format: Format,
    /// Exit 0 even if a merged study's coupling cannot seat (as `study
    /// --allow-unseated`); the result still says so.
    #[arg(long)]
    pub allow_unseated: bool,
}

#[derive(Args)]
pub struct ValidateHertzArgs {
    /// Scene files (default: the seven bundled paper variants).
    pub scenes: Vec<PathBuf>,
    /// Mesh: default (meets 2 % in approach) or coarse (seconds).
    #[arg(long, value_enum, default_value_t = MeshKind::Default)]
    pub mesh: MeshKind,
    /// Also run a mesh convergence study at these element sizes (element
    /// size / contact semi-axis, e.g. 0.45,0.3,0.23,0.18).
    #[arg(long, value_delimiter = ',')]
    pub convergence: Option<Vec<f64>>,
    /// Instead of the table of pairs: the conformity study of each
    /// sphere-groove (gothic-arch) pair of the scenes, FE with the exact gap
    /// of ball and groove against Hertz as the groove radius closes on the
    /// ball's, and the ratio R_g/r at which they part by 2 %.
    #[arg(long)]
    pub conformity: bool,
    /// The groove / ball radius ratios of --conformity (each > 1,
    /// descending; default 1.5,1.1,1.01,1.003,1.001,1.0003,1.0001,1.00005).
    #[arg(long, value_delimiter = ',')]
    pub ratios: Option<Vec<f64>>,
    /// Print a JSON array (SI units) instead of a table.
    #[arg(long)]
    pub json: bool,
}

#[derive(Args)]
pub struct ExpandArgs {
    /// Scene file (TOML).
    pub scene: PathBuf,
}

#[derive(Args)]
pub struct ReportArgs {
    /// Study JSON files (`kinrepro study --format json`, or `kinrepro merge`).
    #[arg(required = true)]
    pub studies: Vec<PathBuf>,
    /// The HTML file to write.
    #[arg(long)]
    pub out: PathBuf,
    /// Reference values of sigma to show with the results (CSV, header
    /// label,scene,point,x_nm,y_nm,z_nm,phi_x_nrad,phi_y_nrad,phi_z_nrad;
    /// e.g. docs/reference/paper_table2.csv).
    #[arg(long)]
    pub reference: Option<PathBuf>,
    /// Replace an existing --out file.
    #[arg(long)]
    pub force: bool,
}

#[derive(Args)]
pub struct MaterialsArgs {
    /// table (GPa, MPa, kg/m^3, with sources) | csv (SI) | json (SI).
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum Format {
    Table,
    Csv,
    Json,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum MeshKind {
    Default,
    Coarse,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum VaryKind {
    /// The six static friction coefficients.
    Friction,
    /// The start pose of the moving half (dynamic solver).
    Start,
    /// The preload point and direction (scene [variation] bounds).
    Preload,
    /// Manufacturing tolerances (scene [variation] bounds): interchangeability.
    Tolerances,
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
pub enum SolverKind {
    /// Quasi-static path following (Newton per load increment).
    QuasiStatic,
    /// Seating dynamics with rapier3d-f64 and the compliant contact layer.
    Dynamic,
}

impl From<VaryKind> for kinrepro::study::request::Varied {
    fn from(v: VaryKind) -> Self {
        match v {
            VaryKind::Friction => Self::Friction,
            VaryKind::Start => Self::Start,
            VaryKind::Preload => Self::Preload,
            VaryKind::Tolerances => Self::Tolerances,
        }
    }
}

impl From<SolverKind> for kinrepro::study::request::Solver {
    fn from(s: SolverKind) -> Self {
        match s {
            SolverKind::QuasiStatic => Self::QuasiStatic,
            SolverKind::Dynamic => Self::Dynamic,
        }
    }
}
