//! The kinrepro command line: parse and check the flags, call the library,
//! print. No physics here.

mod commands;
mod error;
mod flags;

use std::process::ExitCode;

use clap::Parser;

fn main() -> ExitCode {
    let cli = flags::Cli::parse();
    match commands::dispatch(cli.command) {
        Ok(()) => ExitCode::SUCCESS,
        Err(msg) => {
            // One line, whatever the names in it hold.
            let msg = msg.to_string();
            eprintln!("error: {}", kinrepro::report::printable::printable(&msg));
            ExitCode::FAILURE
        }
    }
}
