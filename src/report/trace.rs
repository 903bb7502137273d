//! The time history of a dynamic seating as CSV (`kinrepro run --solver
//! dynamic --trace FILE.csv`), one row per time step, SI units.
//!
//! The first line says what produced the file (`# kinrepro VERSION (output
//! schema N), solver dynamic, one seating of SCENE (NAME)`), as the study's
//! per-sample CSV does; the header follows.
//!
//! Columns: `time_s, load_fraction, x_m, y_m, z_m, phi_x_rad, phi_y_rad,
//! phi_z_rad, kinetic_energy_j`, then per contact k = 1..6 `fn{k}_n` (normal
//! force, dashpot included), `ft{k}_n` (tangential force magnitude, dashpot
//! included), `approach{k}_m` (Hertz approach, negative = open) and
//! `state{k}` (open | stick | slip). The pose is that of the first
//! evaluation point, from the unloaded touching pose.

use std::io::Write;

use crate::assembly::Coupling;
use crate::solve::PointPose;
use crate::solve::dynamic::TraceSample;
use crate::study::provenance::{SCHEMA_VERSION, VERSION};

/// Writes trace samples as CSV rows.
pub struct TraceWriter<W: Write> {
    out: W,
    point: nalgebra::Vector3<f64>,
    touching: crate::assembly::BodyPose,
}

impl<W: Write> TraceWriter<W> {
    /// Write the provenance line and the header for `coupling` and return
    /// the writer.
    pub fn new(mut out: W, coupling: &Coupling) -> std::io::Result<Self> {
        writeln!(
            out,
            "# kinrepro {VERSION} (output schema {SCHEMA_VERSION}), solver dynamic, one seating of {} ({})",
            coupling.scene.file, coupling.scene.name
        )?;
        let mut head = String::from(
            "time_s,load_fraction,x_m,y_m,z_m,phi_x_rad,phi_y_rad,phi_z_rad,kinetic_energy_j",
        );
        for k in 1..=coupling.contacts.len() {
            head.push_str(&format!(",fn{k}_n,ft{k}_n,approach{k}_m,state{k}"));
        }
        writeln!(out, "{head}")?;
        Ok(TraceWriter {
            out,
            point: coupling.scene.evaluation_points[0].position,
            touching: coupling.touching_pose,
        })
    }

    /// Write one sample.
    pub fn write(&mut self, s: &TraceSample) -> std::io::Result<()> {
        let p = PointPose::between(&self.touching, &s.pose, &self.point);
        let mut row = format!(
            "{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e},{:e}",
            s.time,
            s.load_fraction,
            p.x_m,
            p.y_m,
            p.z_m,
            p.phi_x_rad,
            p.phi_y_rad,
            p.phi_z_rad,
            s.kinetic_energy
        );
        for c in &s.contacts {
            row.push_str(&format!(
                ",{:e},{:e},{:e},{}",
                c.normal_force,
                c.tangential_force,
                c.approach,
                c.state.name()
            ));
        }
        writeln!(self.out, "{row}")
    }

    /// Flush and return the sink.
    pub fn finish(mut self) -> std::io::Result<W> {
        self.out.flush()?;
        Ok(self.out)
    }
}
