//! The flags of the verbs that seat a coupling once, look at one contact
//! or a scene, or render and merge outputs (the verbs that run studies:
//! [`super::studies`]).

use std::path::PathBuf;

use clap::Args;
use kinrepro::contact::{ContactShape, TangentialLaw};
use kinrepro::solve::Solver;

use super::groups::{Format, MeshKind, PathFlags};

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
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, requires = "radii2")]
    pub radii1: Option<Vec<f64>>,
    /// Principal radii RX,RY of body 2, the fixed element [m].
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true, requires = "radii1")]
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
    /// Static friction coefficient mu_s, in (0, 2] (with --history).
    #[arg(long, allow_hyphen_values = true, requires = "history")]
    pub mu: Option<f64>,
    /// mu_d = ratio * mu_s, in (0, 1] (with --history).
    #[arg(long, default_value_t = 0.8, allow_hyphen_values = true, requires = "history")]
    pub dynamic_ratio: f64,
    /// coulomb | mindlin-deresiewicz (with --history).
    #[arg(long, default_value = "coulomb", requires = "history")]
    pub tangential_law: TangentialLaw,
    /// A support compliance [m/N] in series with Mindlin's tangential
    /// stiffness (with --history; the coulomb law): a flexure behind the
    /// contact, as `support_compliance = { tangential = ... }` in a scene.
    #[arg(long, default_value_t = 0.0, requires = "history")]
    pub tangential_compliance: f64,
    /// The support's compliance across the major axis [m/N] (y; with
    /// --history): --tangential-compliance is then the compliance along it
    /// (x), as `support_compliance = { along = ..., across = ... }`.
    #[arg(long, requires = "history")]
    pub tangential_compliance_across: Option<f64>,
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
    #[command(flatten)]
    pub path: PathFlags,
    /// Seating solver.
    #[arg(long, value_enum, default_value_t = Solver::QuasiStatic)]
    pub solver: Solver,
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
pub struct ThermalArgs {
    /// Scene file (TOML) with a [thermal] table.
    pub scene: PathBuf,
    /// Static friction coefficients, one per contact (default: nominal).
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub mu: Option<Vec<f64>>,
    /// Temperature changes [K] of the moving and the fixed body from the
    /// seating temperature, visited in order: "dTm,dTf;dTm,dTf;..."
    /// (default: the scene's [thermal] cycle).
    #[arg(long, allow_hyphen_values = true)]
    pub cycle: Option<String>,
    #[command(flatten)]
    pub path: PathFlags,
    /// Print one JSON object (SI units, kelvin) instead of a table.
    #[arg(long)]
    pub json: bool,
}

#[derive(Args)]
pub struct LoadArgs {
    /// Scene file (TOML).
    pub scene: PathBuf,
    /// Force fx,fy,fz [N] (fixed direction; default 0: a moment alone).
    #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
    pub force: Option<Vec<f64>>,
    /// Point of application x,y,z in the moving half [m] (needed with --force).
    #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
    pub at: Option<Vec<f64>>,
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
    /// `kinrepro sweep --shard I/N --format json`, or `kinrepro optimize
    /// --shard I/N --json`).
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
    /// Each study names its scene files; the report reads them (for the
    /// drawings and the scene text) as written, else next to the JSON, and
    /// only from the current folder or the JSON's folder (and below): a
    /// scene elsewhere is refused. Run `report` where the study ran, or
    /// keep the scenes beside the JSON.
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
pub struct CleanArgs {
    /// Folders to clean (those of the outputs a killed run was writing).
    #[arg(required = true)]
    pub dirs: Vec<PathBuf>,
}

#[derive(Args)]
pub struct MaterialsArgs {
    /// table (GPa, MPa, kg/m^3, with sources) | csv (SI) | json (SI).
    #[arg(long, value_enum, default_value_t = Format::Table)]
    pub format: Format,
}
