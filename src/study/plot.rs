//! SVG plots of a study, drawn with plotters 0.3.7 (`svg_backend` + `line_series`, no default
//! features).
//!
//! No font library is compiled in: plotters then uses its built-in text-size estimate for the
//! layout, and the SVG backend writes every caption, tick and axis label as an SVG `<text>`
//! element (`font-family="sans-serif"`) that the viewer renders. So no system fonts, fontconfig
//! or freetype are needed at build or run time.
//!
//! * [`plot_sigma_bars`]: sigma per variant and DOF as grouped bars; translations x, y, z \[nm\]
//!   and rotations phi_x, phi_y \[nrad\] in two panels because the units differ.
//! * [`plot_xy_scatter`]: x-y scatter of the samples \[nm\], one panel per variant, common axes.
//! * [`plot_convergence`]: sigma of the first k samples against k, one panel per unit.
//!
//! Colours: the Okabe & Ito (2008) colour-blind-safe palette, by variant (or series) order.

mod bars;
mod convergence;
mod scatter;

pub use bars::plot_sigma_bars;
pub use convergence::plot_convergence;
pub use scatter::plot_xy_scatter;

use plotters::style::RGBColor;
use serde::{Deserialize, Serialize};

use super::error::{Result, StudyError};
use super::stats::ConvergencePoint;

/// The degrees of freedom of the re-seating error that kinrepro reports.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Serialize, Deserialize)]
pub enum Dof {
    X,
    Y,
    Z,
    PhiX,
    PhiY,
    PhiZ,
}

impl Dof {
    /// All DOFs, in the order of [`VariantSigma::sigma`].
    pub const ALL: [Dof; 6] = [Dof::X, Dof::Y, Dof::Z, Dof::PhiX, Dof::PhiY, Dof::PhiZ];

    /// Short label used on axes and in legends.
    pub fn label(self) -> &'static str {
        match self {
            Dof::X => "x",
            Dof::Y => "y",
            Dof::Z => "z",
            Dof::PhiX => "φx",
            Dof::PhiY => "φy",
            Dof::PhiZ => "φz",
        }
    }

    /// Unit of the DOF: nm for translations, nrad for rotations.
    pub fn unit(self) -> &'static str {
        if self.is_rotation() { "nrad" } else { "nm" }
    }

    pub fn is_rotation(self) -> bool {
        matches!(self, Dof::PhiX | Dof::PhiY | Dof::PhiZ)
    }
}

/// Sigma of one variant, per DOF in the order of [`Dof::ALL`]: x, y, z \[nm\], phi_x, phi_y, phi_z \[nrad\].
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct VariantSigma {
    pub variant: String,
    pub sigma: [f64; 6],
}

/// The x-y re-seating errors \[nm\] of every sample of one variant.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct VariantScatter {
    pub variant: String,
    pub xy: Vec<(f64, f64)>,
}

/// Convergence of sigma of one DOF of one variant (unit from `dof`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ConvergenceSeries {
    pub variant: String,
    pub dof: Dof,
    pub points: Vec<ConvergencePoint>,
}

const OKABE_ITO: [RGBColor; 8] = [
    RGBColor(0, 114, 178),
    RGBColor(230, 159, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(86, 180, 233),
    RGBColor(213, 94, 0),
    RGBColor(240, 228, 66),
    RGBColor(0, 0, 0),
];

pub(crate) fn color(i: usize) -> RGBColor {
    OKABE_ITO[i % OKABE_ITO.len()]
}

pub(crate) fn plot_err<E: std::fmt::Display>(e: E) -> StudyError {
    StudyError::Plot(e.to_string())
}

pub(crate) fn check_finite<'a>(
    values: impl IntoIterator<Item = &'a f64>,
    what: &str,
) -> Result<()> {
    if values.into_iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(StudyError::NonFinite { what: what.into() })
    }
}

/// Upper axis limit: 10 % headroom above `max`, or 1 when everything is 0.
/// Values too large for an axis (overflowing `f64` with the headroom) are an error.
pub(crate) fn headroom(max: f64) -> Result<f64> {
    let top = if max > 0.0 { max * 1.1 } else { 1.0 };
    if top.is_finite() {
        Ok(top)
    } else {
        Err(StudyError::NonFinite {
            what: "axis range (values too large)".into(),
        })
    }
}
