//! The kinrepro command line: parse the flags, turn them into the
//! library's values, call the library, print. No physics here.

mod commands;
mod error;
mod flags;
mod signals;

use std::process::ExitCode;

use clap::Parser;

fn main() -> ExitCode {
    if let Some(why) = kinrepro::lane::cpu_mismatch() {
        say(&format!(
            "error: {why}; build it here (cargo build --release), or for the oldest machine it \
             must run on, e.g. RUSTFLAGS=\"-C target-cpu=x86-64-v2\" cargo build --release"
        ));
        return ExitCode::from(2);
    }
    // Temporaries modified before now are an earlier run's (`output::temporaries`).
    kinrepro::output::temporaries::run_started();
    let cli = match flags::Cli::try_parse() {
        Ok(cli) => cli,
        Err(e) => match flags::negative_value(&e, &std::env::args().collect::<Vec<_>>()) {
            Some(msg) => {
                say(&format!("error: {msg}"));
                return ExitCode::from(2);
            }
            None => e.exit(),
        },
    };
    // The library names its parameters; here they are flags.
    kinrepro::param::set_spelling(flags::spelling);
    // No output of this run replaces a file it read (`output::inputs`).
    kinrepro::output::inputs::track();
    let run = signals::install().and_then(|()| commands::dispatch(cli.command));
    for p in kinrepro::output::temporaries::stale() {
        say(&format!(
            "warning: {}: a temporary file left by an earlier kinrepro run that was killed \
             before it could delete it; `kinrepro clean {}` removes such files",
            p.display(),
            p.parent().map_or(".".into(), |d| d.display().to_string())
        ));
    }
    if let Some((code, msg)) = signals::received() {
        say(&format!("kinrepro: {msg}"));
        return ExitCode::from(code);
    }
    match run {
        Ok(()) => ExitCode::SUCCESS,
        Err(msg) => {
            // One line, whatever the names in it hold.
            let msg = msg.to_string();
            say(&format!("error: {}", kinrepro::report::printable::printable(&msg)));
            ExitCode::FAILURE
        }
    }
}

/// One line to stderr, ignoring a closed stderr (`eprintln!` would panic
/// and turn the exit code into 101).
pub(crate) fn say(line: &str) {
    use std::io::Write;
    let _ = writeln!(std::io::stderr(), "{line}");
}
