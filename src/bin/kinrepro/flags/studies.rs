//! The flags of the verbs that run studies: `study`, `sweep`, `calibrate`
//! and `predict`.

use std::path::PathBuf;

use clap::Args;
use kinrepro::calibrate::model::{MODEL_SAMPLES, MODEL_SEED};
use kinrepro::solve::Solver;
use kinrepro::study::Varied;

use super::groups::{DesignArg, DesignFlags, OutputFlags, PathFlags, RunFlags, TextFormat};

#[derive(Args)]
pub struct StudyArgs {
    /// Scene files (TOML); the variants are reported side by side.
    #[arg(required = true)]
    pub scenes: Vec<PathBuf>,
    #[command(flatten)]
    pub design: DesignFlags,
    #[command(flatten)]
    pub run: RunFlags,
    #[command(flatten)]
    pub output: OutputFlags,
    /// Reference values of sigma for the --html report (CSV; see `kinrepro report`).
    #[arg(long, requires = "html")]
    pub reference: Option<PathBuf>,
    /// Exit 0 even if a coupling cannot seat (every contact sticks, see `kinrepro check`);
    /// the result still says so.
    #[arg(long)]
    pub allow_unseated: bool,
    #[command(flatten)]
    pub path: PathFlags,
    /// Seating solver.
    #[arg(long, value_enum, default_value_t = Solver::QuasiStatic)]
    pub solver: Solver,
    /// What varies from sample to sample, comma-separated: friction,
    /// preload (point offset and direction tilt, bounds from the scene's
    /// [variation] table), tolerances (manufacturing errors from
    /// [variation], reported separately as interchangeability), start (a
    /// random start pose above the seat; needs --solver dynamic).
    #[arg(long, value_enum, value_delimiter = ',', default_value = "friction")]
    pub vary: Vec<Varied>,
    /// Start variation: half-widths of the x and y offset and the largest
    /// height z above the seat [m].
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub offset_bounds: Option<Vec<f64>>,
    /// Start variation: half-widths of the tilt about x, y, z [rad].
    #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
    pub tilt_bounds: Option<Vec<f64>>,
    /// Also print (and add to the JSON) the share of each DOF's variance
    /// due to each input (standardized regression coefficients, R^2) and
    /// the first-order and total Sobol indices with their 90 % intervals.
    #[arg(long)]
    pub sensitivity: bool,
    /// Sobol indices: base sample size N of the Saltelli matrices (N (d + 2)
    /// extra seatings for d inputs).
    #[arg(
        long,
        default_value_t = kinrepro::study::options::DEFAULT_BASE_SAMPLES,
        requires = "sensitivity"
    )]
    pub sobol_samples: usize,
}

#[derive(Args)]
pub struct SweepArgs {
    /// The high-level scene file (TOML) whose fields are swept.
    pub scene: PathBuf,
    /// FIELD=VALUES: a scene field by its TOML path (e.g. preload.force,
    /// coupling.opening_angle_deg, coupling.groove_material,
    /// materials.NAME.youngs_modulus) and its values: a list 5,10,20, a
    /// range a:b:count, log:a:b:count, or material names. Repeatable.
    #[arg(long = "set", required = true)]
    pub sets: Vec<String>,
    /// grid (every combination) | lhs (--points N, space-filling).
    #[arg(long, value_enum, default_value_t = DesignArg::Grid)]
    pub design: DesignArg,
    /// Design points of an LHS design.
    #[arg(long)]
    pub points: Option<usize>,
    /// Evaluation point whose largest translational sigma is the Pareto
    /// objective (default: the scene's first; without --objective).
    #[arg(long)]
    pub pareto_point: Option<String>,
    /// OUTPUT:min or OUTPUT:max, an objective of the Pareto front
    /// (repeatable; default: the largest translational sigma at
    /// --pareto-point, k_min and sf_p). OUTPUT: sigma:POINT:DOF,
    /// pm3sigma:POINT:DOF (DOF x..phi_z or a direction's name; m, rad),
    /// k_min [N/m], sf_p, friction_margin, or a swept field.
    #[arg(long, conflicts_with = "pareto_point")]
    pub objective: Vec<String>,
    /// OUTPUT<=VALUE or OUTPUT>=VALUE (SI): designs that break it are
    /// listed apart, off the front (repeatable; e.g. sf_p>=3). Objectives
    /// and constraints given replace the scene's [goals] lists.
    #[arg(long)]
    pub constraint: Vec<String>,
    #[command(flatten)]
    pub study: DesignFlags,
    #[command(flatten)]
    pub path: PathFlags,
    #[command(flatten)]
    pub run: RunFlags,
    #[command(flatten)]
    pub output: OutputFlags,
}

#[derive(Args)]
pub struct CalibrateArgs {
    /// Scene file (TOML) of the measured coupling.
    pub scene: PathBuf,
    /// Measurement file: one row per re-seating cycle (columns such as
    /// x_nm, phi_x_nrad), or a summary (dof,unit,sigma,cycles).
    #[arg(long)]
    pub measured: PathBuf,
    /// Field separator of the measurement file: `,`, `;`, `tab` (or any one
    /// ASCII character); default: detected from its header line.
    #[arg(long)]
    pub delimiter: Option<String>,
    /// Parameters to fit, comma-separated: the scale of the scene's friction
    /// distribution (spread for uniform, sd for normal or lognormal; the
    /// default), mu_static, dynamic_ratio, support_compliance (the others
    /// held at the scene's values; docs/calibration.md gives the ranges).
    #[arg(long, value_delimiter = ',')]
    pub fit: Vec<String>,
    /// Sensor noise sigma per DOF, e.g. x=1nm,y=1nm,phi_x=20nrad (a number
    /// without unit is SI: m or rad); overrides the file's `# noise:`.
    #[arg(long)]
    pub noise: Option<String>,
    /// Evaluation point measured (default: the file's `point` column, else
    /// the scene's first).
    #[arg(long)]
    pub point: Option<String>,
    /// Samples of each Monte Carlo model study.
    #[arg(long, default_value_t = MODEL_SAMPLES)]
    pub model_samples: usize,
    /// Seed of the model studies.
    #[arg(long, default_value_t = MODEL_SEED)]
    pub seed: u64,
    #[arg(long, value_enum, default_value_t = TextFormat::Table)]
    pub format: TextFormat,
    /// Write the calibration file (JSON) here.
    #[arg(long)]
    pub out: Option<PathBuf>,
    /// Replace an existing --out file.
    #[arg(long, requires = "out")]
    pub force: bool,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub jobs: Option<usize>,
}

#[derive(Args)]
pub struct PredictArgs {
    /// Scene files (TOML) to predict.
    #[arg(required = true)]
    pub scenes: Vec<PathBuf>,
    /// Calibration file written by `kinrepro calibrate --out`.
    #[arg(long)]
    pub calibration: PathBuf,
    /// Samples of each Monte Carlo study (per scene: one at the estimate
    /// and one per point of the calibration's parameter region).
    #[arg(long, default_value_t = MODEL_SAMPLES)]
    pub samples: usize,
    /// Seed of the studies.
    #[arg(long, default_value_t = MODEL_SEED)]
    pub seed: u64,
    #[arg(long, value_enum, default_value_t = TextFormat::Table)]
    pub format: TextFormat,
    /// Also draw the predicted intervals into this SVG.
    #[arg(long)]
    pub plot: Option<PathBuf>,
    /// Replace an existing --plot file.
    #[arg(long, requires = "plot")]
    pub force: bool,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub jobs: Option<usize>,
}

#[derive(Args)]
pub struct OptimizeArgs {
    /// The high-level scene file (TOML) whose fields are searched.
    pub scene: PathBuf,
    /// FIELD=LOW:HIGH, a scene field by its TOML path searched between
    /// LOW and HIGH (log:LOW:HIGH: in its logarithm), or FIELD=A,B,...
    /// (each value tried: materials, keywords, numbers). Repeatable.
    #[arg(long = "vary", required = true)]
    pub vary: Vec<String>,
    /// OUTPUT:min or OUTPUT:max, the one objective. OUTPUT is
    /// sigma:POINT:DOF or pm3sigma:POINT:DOF (DOF: x, y, z, phi_x, phi_y,
    /// phi_z, or a direction's name at the point; m or rad),
    /// drift:POINT:DOF or residual:POINT:DOF (a [thermal] cycle's largest
    /// and final |mean drift|), k_min (the
    /// lowest principal translational stiffness, N/m), sf_p (the smallest
    /// contact pressure safety factor), friction_margin (mu_lim -
    /// (mu_static + spread)) or a varied field such as preload.force.
    /// Default: the scene's [goals] objectives (exactly one).
    #[arg(long)]
    pub objective: Option<String>,
    /// OUTPUT<=VALUE or OUTPUT>=VALUE, VALUE in the output's SI unit
    /// (e.g. sf_p>=3, k_min>=2e8, sigma:centre:x<=5e-9). Repeatable;
    /// given, they replace the scene's [goals] constraints.
    #[arg(long)]
    pub constraint: Vec<String>,
    /// Most iterations of each Nelder-Mead search.
    #[arg(long, default_value_t = kinrepro::explore::optimize::MAX_ITERATIONS)]
    pub max_iterations: u64,
    /// Searches per combination of listed values: from the centre of the
    /// ranges, then from STARTS - 1 points of a Latin hypercube (seeded by
    /// --seed); the best feasible candidate of all is the optimum. For
    /// objectives with several local minima.
    #[arg(long, default_value_t = 1)]
    pub starts: usize,
    /// Make only shard I of N (1-based, e.g. 2/4) of the searches
    /// (combinations of listed values x starts); `kinrepro merge` of the
    /// shards' --json outputs is the whole optimisation.
    #[arg(long)]
    pub shard: Option<kinrepro::study::Shard>,
    #[command(flatten)]
    pub study: DesignFlags,
    #[command(flatten)]
    pub path: PathFlags,
    /// Output: table (nm, nrad) | json (docs/output.md, "Optimisations": SI).
    #[arg(long, value_enum, default_value_t = TextFormat::Table)]
    pub format: TextFormat,
    /// Shorthand for --format json.
    #[arg(long, conflicts_with = "format")]
    pub json: bool,
    /// Also write the self-contained HTML page of the optimisation (the
    /// optimum, its constraints, the history and its convergence plot).
    #[arg(long)]
    pub html: Option<PathBuf>,
    /// Replace an existing --html file.
    #[arg(long, requires = "html")]
    pub force: bool,
    /// Worker threads (default: all cores).
    #[arg(long)]
    pub jobs: Option<usize>,
}
