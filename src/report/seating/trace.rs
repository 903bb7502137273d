//! The time history of a dynamic seating as CSV (`kinrepro run --solver
//! dynamic --trace FILE.csv`), one row per time step, SI units.
//!
//! The first line says what produced the file (`# kinrepro VERSION (output
//! schema N), solver dynamic, one seating of SCENE (NAME)`), as the study's
//! per-sample CSV does; the header follows.
//!
//! Columns: `time_s`, `load_fraction`, the six DOFs of the first
//! evaluation point from the unloaded touching pose ([`Dof::si_key`]: `x_m`,
//! ...), `kinetic_energy_j`, then per contact k = 1..6 `fn{k}_n` (normal
//! force, dashpot included), `ft{k}_n` (tangential force magnitude, dashpot
//! included), `approach{k}_m` (Hertz approach, negative = open) and
//! `state{k}` (open | stick | slip). Rows through the `csv` crate.

use std::io::Write;

use crate::assembly::Coupling;
use crate::dof::Dof;
use crate::report::printable::printable;
use crate::scene::Scene;
use crate::solve::PointPose;
use crate::solve::dynamic::TraceSample;
use crate::study::provenance::{SCHEMA_VERSION, VERSION};

/// Writes trace samples as CSV rows.
pub struct TraceWriter<W: Write> {
    out: csv::Writer<W>,
    point: nalgebra::Vector3<f64>,
    touching: crate::assembly::BodyPose,
}

fn io(e: csv::Error) -> std::io::Error {
    std::io::Error::other(e)
}

impl<W: Write> TraceWriter<W> {
    /// Write the provenance line and the header for `scene` assembled as
    /// `coupling` and return the writer.
    pub fn new(mut out: W, scene: &Scene, coupling: &Coupling) -> std::io::Result<Self> {
        writeln!(
            out,
            "# kinrepro {VERSION} (output schema {SCHEMA_VERSION}), solver dynamic, one seating of {} ({})",
            printable(&scene.file),
            printable(&scene.name)
        )?;
        let mut out = csv::Writer::from_writer(out);
        let mut head = vec!["time_s".to_string(), "load_fraction".to_string()];
        head.extend(Dof::ALL.map(Dof::si_key));
        head.push("kinetic_energy_j".to_string());
        for k in 1..=coupling.contacts.len() {
            head.extend([format!("fn{k}_n"), format!("ft{k}_n")]);
            head.extend([format!("approach{k}_m"), format!("state{k}")]);
        }
        out.write_record(&head).map_err(io)?;
        Ok(TraceWriter {
            out,
            point: scene.evaluation_points[0].position,
            touching: coupling.touching_pose,
        })
    }

    /// Write one sample.
    pub fn write(&mut self, s: &TraceSample) -> std::io::Result<()> {
        let p = PointPose::between(&self.touching, &s.pose, &self.point);
        let e = |v: f64| format!("{v:e}");
        let mut row = vec![e(s.time), e(s.load_fraction)];
        row.extend(p.components().map(e));
        row.push(e(s.kinetic_energy));
        for c in &s.contacts {
            row.extend([e(c.normal_force), e(c.tangential_force), e(c.approach)]);
            row.push(c.state.name().to_string());
        }
        self.out.write_record(&row).map_err(io)
    }

    /// Flush and return the sink.
    pub fn finish(self) -> std::io::Result<W> {
        self.out.into_inner().map_err(|e| e.into_error())
    }
}
