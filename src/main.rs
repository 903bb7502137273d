//! The kinrepro command line: parse, call the library, print. No physics here.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand, ValueEnum};
use kinrepro::contact::{ContactPair, ContactShape};
use kinrepro::material::Material;
use kinrepro::report::study::{StudyReport, VariantReport};
use kinrepro::study::runner::{StartBounds, StudyOptions, Variation, design_for, run_variant};
use kinrepro::study::{Sampler, Shard};

#[derive(Parser)]
#[command(
    name = "kinrepro",
    version,
    about = "Re-seating reproducibility of kinematic couplings"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Subcommand)]
enum Command {
    /// Evaluate one contact pair (Hertz normal law and Mindlin stiffness) at a load.
    Contact {
        /// sphere-plane | sphere-sphere | sphere-seat | sphere-cylinder
        #[arg(long)]
        shape: ContactShape,
        /// Radius of the moving ball [m].
        #[arg(long, allow_hyphen_values = true)]
        radius1: f64,
        /// Radius of the fixed sphere, seat or cylinder [m].
        #[arg(long, allow_hyphen_values = true)]
        radius2: Option<f64>,
        /// Material of the ball (built-in name, e.g. steel).
        #[arg(long)]
        material1: String,
        /// Material of the fixed element.
        #[arg(long)]
        material2: String,
        /// Normal load [N].
        #[arg(long, allow_hyphen_values = true)]
        load: f64,
        /// Print one JSON object instead of a table.
        #[arg(long)]
        json: bool,
    },
    /// Load and validate scenes; print contacts, constraint status and friction limit.
    Check {
        /// Scene files (TOML).
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
    },
    /// Seat the coupling once and print pose and contact states.
    Run {
        /// Scene file (TOML).
        scene: PathBuf,
        /// Static friction coefficients, one per contact in contact order
        /// (default: the scene's nominal mu_static everywhere).
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        mu: Option<Vec<f64>>,
        /// Nominal number of load increments (quasi-static solver).
        #[arg(long, default_value_t = 20)]
        increments: usize,
        /// Seating solver.
        #[arg(long, value_enum, default_value_t = SolverKind::QuasiStatic)]
        solver: SolverKind,
        /// Dynamic solver: write the time history (CSV, SI units) to this file.
        #[arg(long)]
        trace: Option<PathBuf>,
        /// Dynamic solver: start offset x,y,z of the moving half from the touching pose [m].
        #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
        offset: Option<Vec<f64>>,
        /// Dynamic solver: start tilt phi_x,phi_y,phi_z (rotation vector about the origin) [rad].
        #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
        tilt: Option<Vec<f64>>,
        /// Print one JSON object (SI units) instead of a table.
        #[arg(long)]
        json: bool,
    },
    /// Stiffness of the seated coupling: 6x6 matrix, compliance and principal
    /// stiffnesses at a point (contacts at rest: static friction sticks).
    Stiffness {
        /// Scene file (TOML).
        scene: PathBuf,
        /// Point of the moving half x,y,z [m] (default: the scene's evaluation points).
        #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
        at: Option<Vec<f64>>,
        /// Static friction coefficients, one per contact (default: nominal).
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        mu: Option<Vec<f64>>,
        /// Print one JSON object (SI units) instead of a table.
        #[arg(long)]
        json: bool,
    },
    /// Apply a force (and moment) after seating, preload held: deflection,
    /// contact forces and the safe load envelope (first separation or slip).
    Load {
        /// Scene file (TOML).
        scene: PathBuf,
        /// Force fx,fy,fz [N] (fixed direction).
        #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
        force: Vec<f64>,
        /// Point of application x,y,z in the moving half [m].
        #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
        at: Vec<f64>,
        /// Moment mx,my,mz [N m] (default 0).
        #[arg(long, value_delimiter = ',', num_args = 1, allow_hyphen_values = true)]
        moment: Option<Vec<f64>>,
        /// Static friction coefficients, one per contact (default: nominal).
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        mu: Option<Vec<f64>>,
        /// Print one JSON object (SI units) instead of a table.
        #[arg(long)]
        json: bool,
    },
    /// Reproducibility study: seat each scene once per friction sample and
    /// report the scatter of the pose (Table 2 of the paper).
    Study {
        /// Scene files (TOML); the variants are reported side by side.
        #[arg(required = true)]
        scenes: Vec<PathBuf>,
        /// Samples per scene (default: the scene's [study] samples; corners: 2^6).
        #[arg(long)]
        samples: Option<usize>,
        /// lhs (space-filling Latin hypercube) | mc (Monte Carlo) | corners (all 2^6 extremes).
        #[arg(long)]
        sampler: Option<Sampler>,
        /// Seed of the design (default: the scene's [study] seed).
        #[arg(long)]
        seed: Option<u64>,
        /// Worker threads (default: all cores).
        #[arg(long)]
        jobs: Option<usize>,
        /// Output: table (nm, nrad) | csv (SI) | json (statistics in nm/nrad, samples in SI).
        #[arg(long, value_enum, default_value_t = Format::Table)]
        format: Format,
        /// Also write per-sample CSV files and SVG plots into this directory.
        #[arg(long)]
        out: Option<PathBuf>,
        /// Run only shard I of N of the samples (1-based, e.g. 3/16); merge the
        /// JSON outputs with `kinrepro merge`.
        #[arg(long)]
        shard: Option<Shard>,
        /// Nominal number of load increments per seating (quasi-static solver).
        #[arg(long, default_value_t = 20)]
        increments: usize,
        /// Seating solver.
        #[arg(long, value_enum, default_value_t = SolverKind::QuasiStatic)]
        solver: SolverKind,
        /// What varies from sample to sample, comma-separated: friction,
        /// preload (point offset and direction tilt, bounds from the scene's
        /// [variation] table), tolerances (manufacturing errors from
        /// [variation], reported separately as interchangeability), start (a
        /// random start pose above the seat; needs --solver dynamic).
        #[arg(long, value_delimiter = ',', default_value = "friction")]
        vary: Vec<VaryKind>,
        /// Start variation: half-widths of the x and y offset and the largest
        /// height z above the seat [m].
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        offset_bounds: Option<Vec<f64>>,
        /// Start variation: half-widths of the tilt about x, y, z [rad].
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        tilt_bounds: Option<Vec<f64>>,
        /// Also print (and add to the JSON) the share of each DOF's variance
        /// due to each input (standardized regression coefficients, R^2).
        #[arg(long)]
        sensitivity: bool,
    },
    /// Merge the JSON outputs of sharded studies into the result of one run.
    Merge {
        /// JSON files written by `kinrepro study --shard I/N --format json`.
        #[arg(required = true)]
        parts: Vec<PathBuf>,
        #[arg(long, value_enum, default_value_t = Format::Json)]
        format: Format,
    },
    /// Check the Hertz law of every distinct contact pair of the scenes with
    /// the mini FE solver, at the load the nominal seating reaches.
    ValidateHertz {
        /// Scene files (default: the seven bundled paper variants).
        scenes: Vec<PathBuf>,
        /// Mesh: default (meets 2 % in approach) or coarse (seconds).
        #[arg(long, value_enum, default_value_t = MeshKind::Default)]
        mesh: MeshKind,
        /// Also run a mesh convergence study at these element sizes (element
        /// size / contact semi-axis, e.g. 0.45,0.3,0.23,0.18).
        #[arg(long, value_delimiter = ',')]
        convergence: Option<Vec<f64>>,
        /// Print a JSON array (SI units) instead of a table.
        #[arg(long)]
        json: bool,
    },
    /// Print the explicit form of a scene (loads back to the same coupling).
    Expand {
        /// Scene file (TOML).
        scene: PathBuf,
    },
}

#[derive(Clone, Copy, PartialEq, Eq, clap::ValueEnum)]
enum Format {
    Table,
    Csv,
    Json,
}

fn print_study(report: &StudyReport, format: Format) -> Result<(), String> {
    match format {
        Format::Table => print!("{}", report.table()),
        Format::Csv => print!("{}", report.csv()),
        Format::Json => println!(
            "{}",
            serde_json::to_string_pretty(report).map_err(|e| e.to_string())?
        ),
    }
    Ok(())
}

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum MeshKind {
    Default,
    Coarse,
}

/// The seven paper variants, built in so `validate-hertz` works anywhere.
const BUNDLED: [(&str, &str); 7] = [
    (
        "scenes/01_maxwell_vgroove_steel.toml",
        include_str!("../scenes/01_maxwell_vgroove_steel.toml"),
    ),
    (
        "scenes/02_maxwell_pins_steel.toml",
        include_str!("../scenes/02_maxwell_pins_steel.toml"),
    ),
    (
        "scenes/03_maxwell_pins_sic.toml",
        include_str!("../scenes/03_maxwell_pins_sic.toml"),
    ),
    (
        "scenes/04_maxwell_balls_steel.toml",
        include_str!("../scenes/04_maxwell_balls_steel.toml"),
    ),
    (
        "scenes/05_maxwell_balls_sic.toml",
        include_str!("../scenes/05_maxwell_balls_sic.toml"),
    ),
    (
        "scenes/06_kelvin_steel.toml",
        include_str!("../scenes/06_kelvin_steel.toml"),
    ),
    (
        "scenes/07_kelvin_sic.toml",
        include_str!("../scenes/07_kelvin_sic.toml"),
    ),
];

#[derive(Clone, Copy, PartialEq, Eq, ValueEnum)]
enum VaryKind {
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
enum SolverKind {
    /// Quasi-static path following (Newton per load increment).
    QuasiStatic,
    /// Seating dynamics with rapier3d-f64 and the compliant contact layer.
    Dynamic,
}

fn vector3(name: &str, v: Option<Vec<f64>>) -> Result<nalgebra::Vector3<f64>, String> {
    match v {
        None => Ok(nalgebra::Vector3::zeros()),
        Some(v) if v.len() == 3 => Ok(nalgebra::Vector3::new(v[0], v[1], v[2])),
        Some(v) => Err(format!(
            "--{name} needs three comma-separated values, got {}",
            v.len()
        )),
    }
}

/// A finite three-vector option (None -> zero).
fn finite3(name: &str, v: Option<Vec<f64>>) -> Result<nalgebra::Vector3<f64>, String> {
    let x = vector3(name, v)?;
    if x.iter().all(|c| c.is_finite()) {
        Ok(x)
    } else {
        Err(format!(
            "--{name} needs three finite numbers, got ({}, {}, {})",
            x.x, x.y, x.z
        ))
    }
}

fn print_json<T: serde::Serialize>(v: &T) -> Result<(), String> {
    println!(
        "{}",
        serde_json::to_string_pretty(v).map_err(|e| e.to_string())?
    );
    Ok(())
}

fn main() -> ExitCode {
    let cli = Cli::parse();
    match run(cli) {
        Ok(()) => ExitCode::SUCCESS,
        Err(msg) => {
            eprintln!("error: {msg}");
            ExitCode::FAILURE
        }
    }
}

fn run(cli: Cli) -> Result<(), String> {
    match cli.command {
        Command::Contact {
            shape,
            radius1,
            radius2,
            material1,
            material2,
            load,
            json,
        } => {
            let pair = ContactPair {
                shape,
                radius1,
                radius2,
                material1: Material::builtin(&material1)
                    .map_err(|e| format!("--material1: {e}"))?,
                material2: Material::builtin(&material2)
                    .map_err(|e| format!("--material2: {e}"))?,
            };
            let eval = pair.evaluate(load).map_err(|e| e.to_string())?;
            if json {
                println!(
                    "{}",
                    serde_json::to_string_pretty(&eval).map_err(|e| e.to_string())?
                );
            } else {
                print!("{}", kinrepro::report::contact::contact_table(&eval));
            }
            Ok(())
        }
        Command::Check { scenes } => {
            let mut failed = 0;
            for path in &scenes {
                match kinrepro::error::load_coupling(path) {
                    Ok(c) => println!("{}", kinrepro::report::check::check_summary(&c)),
                    Err(e) => {
                        eprintln!("error: {e}");
                        failed += 1;
                    }
                }
            }
            if failed > 0 {
                return Err(format!("{failed} of {} scenes are invalid", scenes.len()));
            }
            Ok(())
        }
        Command::Run {
            scene,
            mu,
            increments,
            solver,
            trace,
            offset,
            tilt,
            json,
        } => {
            use kinrepro::solve::dynamic::{DynamicOptions, StartPose, seat_traced};
            let coupling = kinrepro::error::load_coupling(&scene).map_err(|e| e.to_string())?;
            if solver == SolverKind::QuasiStatic
                && (trace.is_some() || offset.is_some() || tilt.is_some())
            {
                return Err("--trace, --offset and --tilt need --solver dynamic".to_string());
            }
            let opts = kinrepro::solve::SolverOptions {
                increments: increments.max(1),
                ..Default::default()
            };
            let dyn_opts = DynamicOptions {
                start: StartPose {
                    offset: vector3("offset", offset)?,
                    tilt: vector3("tilt", tilt)?,
                },
                ..Default::default()
            };
            let nominal_mu = kinrepro::solve::nominal_mu(&coupling);
            let mu = mu.unwrap_or_else(|| nominal_mu.clone());
            let file = coupling.scene.file.clone();
            let seat = |m: &[f64]| {
                match solver {
                    SolverKind::QuasiStatic => {
                        kinrepro::solve::quasistatic::seat(&coupling, m, &opts)
                    }
                    SolverKind::Dynamic => kinrepro::solve::dynamic::seat(&coupling, m, &dyn_opts),
                }
                .map_err(|e| format!("{file}: {e}"))
            };
            let seating = match (&trace, solver) {
                (Some(path), SolverKind::Dynamic) => {
                    let name = path.display().to_string();
                    let f = std::fs::File::create(path)
                        .map_err(|e| format!("{name}: cannot create the trace file: {e}"))?;
                    let mut w = kinrepro::report::trace::TraceWriter::new(
                        std::io::BufWriter::new(f),
                        &coupling,
                    )
                    .map_err(|e| format!("{name}: {e}"))?;
                    let mut io_err = None;
                    let result = seat_traced(&coupling, &mu, &dyn_opts, &mut |s| {
                        if io_err.is_none() {
                            io_err = w.write(s).err();
                        }
                    });
                    if let Some(e) = io_err {
                        return Err(format!("{name}: writing the trace failed: {e}"));
                    }
                    w.finish().map_err(|e| format!("{name}: {e}"))?;
                    result.map_err(|e| format!("{file}: {e} (trace written to {name})"))?
                }
                _ => seat(&mu)?,
            };
            let nominal = seat(&nominal_mu)?;
            let report = kinrepro::report::run::RunReport::new(
                &coupling,
                &mu,
                &seating,
                &nominal,
                match solver {
                    SolverKind::QuasiStatic => "quasi-static",
                    SolverKind::Dynamic => "dynamic",
                },
            );
            if json {
                println!(
                    "{}",
                    serde_json::to_string_pretty(&report).map_err(|e| e.to_string())?
                );
            } else {
                print!("{}", report.table());
            }
            Ok(())
        }
        Command::Stiffness {
            scene,
            at,
            mu,
            json,
        } => {
            let coupling = kinrepro::error::load_coupling(&scene).map_err(|e| e.to_string())?;
            let points = match at {
                Some(_) => vec![("--at".to_string(), finite3("at", at)?)],
                None => coupling
                    .scene
                    .evaluation_points
                    .iter()
                    .map(|p| (p.name.clone(), p.position))
                    .collect(),
            };
            let mu = mu.unwrap_or_else(|| kinrepro::solve::nominal_mu(&coupling));
            let file = coupling.scene.file.clone();
            let seating = kinrepro::solve::quasistatic::seat(&coupling, &mu, &Default::default())
                .map_err(|e| format!("{file}: {e}"))?;
            let k = kinrepro::analysis::stiffness::CouplingStiffness::new(&coupling, &seating, &mu)
                .map_err(|e| format!("{file}: {e}"))?;
            let report = kinrepro::report::analysis::StiffnessReport::new(
                &coupling, &mu, &seating, &k, &points,
            )
            .map_err(|e| format!("{file}: {e}"))?;
            if json {
                print_json(&report)
            } else {
                print!("{}", report.table());
                Ok(())
            }
        }
        Command::Load {
            scene,
            force,
            at,
            moment,
            mu,
            json,
        } => {
            let force = finite3("force", Some(force))?;
            let point = finite3("at", Some(at))?;
            let moment = finite3("moment", moment)?;
            if force.norm() == 0.0 && moment.norm() == 0.0 {
                return Err("--force and --moment are both zero: there is no load to apply".into());
            }
            let coupling = kinrepro::error::load_coupling(&scene).map_err(|e| e.to_string())?;
            let mu = mu.unwrap_or_else(|| kinrepro::solve::nominal_mu(&coupling));
            let file = coupling.scene.file.clone();
            let opts = kinrepro::solve::SolverOptions::default();
            let seating = kinrepro::solve::quasistatic::seat(&coupling, &mu, &opts)
                .map_err(|e| format!("{file}: {e}"))?;
            let load = kinrepro::solve::quasistatic::ExternalLoad {
                force,
                point,
                moment,
            };
            let path =
                kinrepro::analysis::load::load_path(&coupling, &mu, &seating, &load, 1.0, &opts)
                    .map_err(|e| format!("{file}: the load path failed: {e}"))?;
            let envelope =
                kinrepro::analysis::load::envelope(&coupling, &mu, &seating, &load, &opts)
                    .map_err(|e| format!("{file}: the envelope search failed: {e}"))?;
            let mut points: Vec<(String, nalgebra::Vector3<f64>)> = coupling
                .scene
                .evaluation_points
                .iter()
                .map(|p| (p.name.clone(), p.position))
                .collect();
            points.push(("load point".to_string(), point));
            let report = kinrepro::report::analysis::LoadReport::new(
                &coupling, &mu, &seating, &load, &path, &envelope, &points,
            );
            if json {
                print_json(&report)
            } else {
                print!("{}", report.table());
                Ok(())
            }
        }
        Command::Study {
            scenes,
            samples,
            sampler,
            seed,
            jobs,
            format,
            out,
            shard,
            increments,
            solver,
            vary,
            offset_bounds,
            tilt_bounds,
            sensitivity,
        } => {
            if let Some(j) = jobs {
                rayon::ThreadPoolBuilder::new()
                    .num_threads(j.max(1))
                    .build_global()
                    .map_err(|e| format!("--jobs: {e}"))?;
            }
            let opts = StudyOptions {
                sampler,
                samples,
                seed,
                shard: shard.unwrap_or_else(Shard::whole),
                method: match solver {
                    SolverKind::QuasiStatic => {
                        kinrepro::solve::Method::QuasiStatic(kinrepro::solve::SolverOptions {
                            increments: increments.max(1),
                            ..Default::default()
                        })
                    }
                    SolverKind::Dynamic => kinrepro::solve::Method::Dynamic(Default::default()),
                },
                sensitivity,
                variation: Variation {
                    friction: vary.contains(&VaryKind::Friction),
                    preload: vary.contains(&VaryKind::Preload),
                    tolerances: vary.contains(&VaryKind::Tolerances),
                    start: if vary.contains(&VaryKind::Start) {
                        let bounds = |name: &str, v: Option<Vec<f64>>| -> Result<_, String> {
                            let v = vector3(name, v)?;
                            if v.iter().any(|x| !x.is_finite() || *x < 0.0) {
                                return Err(format!("--{name}: bounds must be finite and >= 0"));
                            }
                            Ok(v)
                        };
                        Some(StartBounds {
                            offset: bounds("offset-bounds", offset_bounds)?,
                            tilt: bounds("tilt-bounds", tilt_bounds)?,
                        })
                    } else {
                        if offset_bounds.is_some() || tilt_bounds.is_some() {
                            return Err(
                                "--offset-bounds and --tilt-bounds need --vary start".into()
                            );
                        }
                        None
                    },
                },
            };
            let couplings = scenes
                .iter()
                .map(|p| kinrepro::error::load_coupling(p).map_err(|e| e.to_string()))
                .collect::<Result<Vec<_>, _>>()?;
            let mut total = 0;
            for c in &couplings {
                kinrepro::study::runner::check_options(c, &opts).map_err(|e| e.to_string())?;
                let d = design_for(c, &opts).map_err(|e| format!("{}: {e}", c.scene.file))?;
                total += opts
                    .shard
                    .range(d.n)
                    .map_err(|e| format!("--shard: {e}"))?
                    .len();
            }
            let bar = if std::io::IsTerminal::is_terminal(&std::io::stderr()) {
                let b = indicatif::ProgressBar::new(total as u64);
                b.set_style(
                    indicatif::ProgressStyle::with_template(
                        "{elapsed_precise} [{bar:40}] {pos}/{len} seatings ({eta})",
                    )
                    .map_err(|e| e.to_string())?,
                );
                b
            } else {
                indicatif::ProgressBar::hidden()
            };
            let mut variants = Vec::new();
            for c in &couplings {
                let run = run_variant(c, &opts, &|| bar.inc(1)).map_err(|e| e.to_string())?;
                variants.push(
                    VariantReport::new(c, run, &opts)
                        .map_err(|e| format!("{}: {e}", c.scene.file))?,
                );
            }
            bar.finish_and_clear();
            let report = StudyReport::new(variants, opts.shard);
            if let Some(dir) = out {
                for f in report.write_files(&dir, &couplings)? {
                    eprintln!("wrote {f}");
                }
            }
            print_study(&report, format)
        }
        Command::Merge { parts, format } => {
            let docs = parts
                .iter()
                .map(|p| {
                    let text = std::fs::read_to_string(p)
                        .map_err(|e| format!("{}: cannot read: {e}", p.display()))?;
                    serde_json::from_str::<StudyReport>(&text)
                        .map_err(|e| format!("{}: not a kinrepro study JSON: {e}", p.display()))
                })
                .collect::<Result<Vec<_>, _>>()?;
            let merged = StudyReport::merge(docs).map_err(|e| format!("merge: {e}"))?;
            print_study(&merged, format)
        }
        Command::ValidateHertz {
            scenes,
            mesh,
            convergence,
            json,
        } => {
            let couplings = if scenes.is_empty() {
                BUNDLED
                    .iter()
                    .map(|(file, text)| {
                        let s =
                            kinrepro::scene::Scene::parse(text, file).map_err(|e| e.to_string())?;
                        kinrepro::assembly::Coupling::new(&s).map_err(|e| format!("{file}: {e}"))
                    })
                    .collect::<Result<Vec<_>, String>>()?
            } else {
                scenes
                    .iter()
                    .map(|p| kinrepro::error::load_coupling(p).map_err(|e| e.to_string()))
                    .collect::<Result<Vec<_>, String>>()?
            };
            let cases = kinrepro::fe::pairs::distinct_pairs(&couplings)
                .map_err(|(f, e)| format!("{f}: {e}"))?;
            let mesh = match mesh {
                MeshKind::Default => kinrepro::fe::MeshOptions::default(),
                MeshKind::Coarse => kinrepro::fe::MeshOptions::coarse(),
            };
            let levels = convergence.unwrap_or_default();
            if levels.iter().any(|l| !(l.is_finite() && *l > 0.0)) {
                return Err("--convergence: element sizes must be positive numbers".into());
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
                    kinrepro::fe::pairs::validate_pair(case, &mesh, &levels).map_err(|e| {
                        format!(
                            "{} {}/{}: {e}",
                            case.pair.shape.name(),
                            case.pair.material1.name,
                            case.pair.material2.name
                        )
                    })?,
                );
            }
            if json {
                println!(
                    "{}",
                    serde_json::to_string_pretty(&rows).map_err(|e| e.to_string())?
                );
            } else {
                print!("{}", kinrepro::report::validate_hertz::table(&rows));
            }
            Ok(())
        }
        Command::Expand { scene } => {
            let file = scene.display().to_string();
            let source = std::fs::read_to_string(&scene)
                .map_err(|e| format!("{file}: cannot read the file: {e}"))?;
            let text =
                kinrepro::scene::Scene::expand_text(&source, &file).map_err(|e| e.to_string())?;
            // The explicit form must assemble too.
            let explicit =
                kinrepro::scene::Scene::parse(&text, &file).map_err(|e| e.to_string())?;
            kinrepro::assembly::Coupling::new(&explicit).map_err(|e| format!("{file}: {e}"))?;
            print!("{text}");
            Ok(())
        }
    }
}
