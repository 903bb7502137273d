//! Helpers shared by the integration tests.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::Command;

/// Run the kinrepro binary: (success, stdout, stderr).
pub fn kinrepro(args: &[&str]) -> (bool, String, String) {
    let out = Command::new(env!("CARGO_BIN_EXE_kinrepro"))
        .args(args)
        .output()
        .unwrap();
    (
        out.status.success(),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

/// Path of a bundled scene.
pub fn scene(name: &str) -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .join("scenes")
        .join(name)
}

/// Load and assemble a bundled scene.
pub fn load(name: &str) -> kinrepro::assembly::Coupling {
    kinrepro::error::load_coupling(&scene(name)).unwrap()
}

/// Steel (E = 210 GPa, nu = 0.3) on steel: E* = E / (2 (1 - nu^2)) (Hertz; Johnson 1985, eq. 4.22).
pub const E_STAR_STEEL: f64 = 210e9 / (2.0 * (1.0 - 0.3 * 0.3));

/// Hertz sphere on a sphere or plane (Johnson 1985, §4.2): contact radius
/// a = (3 F R / (4 E*))^(1/3) and approach delta = a^2 / R.
pub fn hertz_circle(force: f64, radius: f64, e_star: f64) -> (f64, f64) {
    let a = (3.0 * force * radius / (4.0 * e_star)).cbrt();
    (a, a * a / radius)
}
