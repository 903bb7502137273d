//! Helpers shared by the integration tests.

#![allow(dead_code)]

pub mod synthetic;

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

/// The worked 50-cycle measurement of scene 02 (docs/calibration/).
pub fn worked_measurement() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/calibration/measured_02.csv")
}

/// Load and assemble a bundled scene.
pub fn load(name: &str) -> kinrepro::assembly::Coupling {
    kinrepro::error::read_coupling(&scene(name)).unwrap()
}

/// Steel (E = 210 GPa, nu = 0.3) on steel: E* = E / (2 (1 - nu^2)) (Hertz; Johnson 1985, eq. 4.22).
pub const E_STAR_STEEL: f64 = 210e9 / (2.0 * (1.0 - 0.3 * 0.3));

/// Hertz sphere on a sphere or plane (Johnson 1985, §4.2): contact radius
/// a = (3 F R / (4 E*))^(1/3) and approach delta = a^2 / R.
pub fn hertz_circle(force: f64, radius: f64, e_star: f64) -> (f64, f64) {
    let a = (3.0 * force * radius / (4.0 * e_star)).cbrt();
    (a, a * a / radius)
}

/// Ball centres and contact normals (into the ball) of the symmetric Maxwell
/// coupling of scene 01, from docs/model.md's axes and contact numbering and not from kinrepro: balls at
/// azimuths 90, 210, 330 deg on the 40 mm circle, contacts 2k-1 and 2k with
/// normals +-sin(alpha) s + cos(alpha) e_z, s = e_z x e_r (alpha = 45 deg for
/// the 90-degree groove).
pub fn maxwell_contacts(alpha: f64) -> Vec<(nalgebra::Vector3<f64>, nalgebra::Vector3<f64>)> {
    use nalgebra::Vector3;
    let mut out = Vec::new();
    for az in [90.0f64, 210.0, 330.0] {
        let er = Vector3::new(az.to_radians().cos(), az.to_radians().sin(), 0.0);
        let s = Vector3::z().cross(&er);
        for sign in [1.0, -1.0] {
            out.push((
                er * 0.040,
                s * (sign * alpha.sin()) + Vector3::z() * alpha.cos(),
            ));
        }
    }
    out
}
