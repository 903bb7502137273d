//! The kinrepro command line: parse, call the library, print. No physics here.

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};
use kinrepro::contact::{ContactPair, ContactShape};
use kinrepro::material::Material;

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
    /// Seat the coupling once (quasi-static) and print pose and contact states.
    Run {
        /// Scene file (TOML).
        scene: PathBuf,
        /// Static friction coefficients, one per contact in contact order
        /// (default: the scene's nominal mu_static everywhere).
        #[arg(long, value_delimiter = ',', allow_hyphen_values = true)]
        mu: Option<Vec<f64>>,
        /// Nominal number of load increments.
        #[arg(long, default_value_t = 20)]
        increments: usize,
        /// Print one JSON object (SI units) instead of a table.
        #[arg(long)]
        json: bool,
    },
    /// Print the explicit form of a scene (loads back to the same coupling).
    Expand {
        /// Scene file (TOML).
        scene: PathBuf,
    },
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
            json,
        } => {
            let coupling = kinrepro::error::load_coupling(&scene).map_err(|e| e.to_string())?;
            let opts = kinrepro::solve::SolverOptions {
                increments: increments.max(1),
                ..Default::default()
            };
            let nominal_mu = kinrepro::solve::nominal_mu(&coupling);
            let mu = mu.unwrap_or_else(|| nominal_mu.clone());
            let file = coupling.scene.file.clone();
            let seat = |m: &[f64]| {
                kinrepro::solve::quasistatic::seat(&coupling, m, &opts)
                    .map_err(|e| format!("{file}: {e}"))
            };
            let seating = seat(&mu)?;
            let nominal = seat(&nominal_mu)?;
            let report = kinrepro::report::run::RunReport::new(
                &coupling,
                &mu,
                &seating,
                &nominal,
                "quasi-static",
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
