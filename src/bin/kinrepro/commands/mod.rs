//! One function per verb; shared helpers for parsing and printing.

mod analysis;
mod contact;
mod fe;
mod scene;
mod seat;
mod study;

use kinrepro::report::study::StudyReport;

use crate::args::{Command, Format};

pub fn dispatch(command: Command) -> Result<(), String> {
    match command {
        Command::Contact(a) => contact::contact(a),
        Command::Check(a) => scene::check(a),
        Command::Expand(a) => scene::expand(a),
        Command::Run(a) => seat::run(a),
        Command::Stiffness(a) => analysis::stiffness(a),
        Command::Load(a) => analysis::load(a),
        Command::Study(a) => study::study(a),
        Command::Merge(a) => study::merge(a),
        Command::ValidateHertz(a) => fe::validate_hertz(a),
    }
}

pub fn print_study(report: &StudyReport, format: Format) -> Result<(), String> {
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

pub fn vector3(name: &str, v: Option<Vec<f64>>) -> Result<nalgebra::Vector3<f64>, String> {
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
pub fn finite3(name: &str, v: Option<Vec<f64>>) -> Result<nalgebra::Vector3<f64>, String> {
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

pub fn print_json<T: serde::Serialize>(v: &T) -> Result<(), String> {
    println!(
        "{}",
        serde_json::to_string_pretty(v).map_err(|e| e.to_string())?
    );
    Ok(())
}
