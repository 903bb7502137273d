//! SVG plots of a study, drawn with plotters 0.3.7 (`svg_backend` + `line_series`, no default
//! features).
//!
//! No font library is compiled in: plotters then uses its built-in text-size estimate for the
//! layout, and the SVG backend writes every caption, tick and axis label as an SVG `<text>`
//! element (`font-family="sans-serif"`) that the viewer renders. So no system fonts, fontconfig
//! or freetype are needed at build or run time.
//!
//! * [`sigma_bars_svg`]: sigma per variant and DOF as grouped bars with the 90 % interval of
//!   each sigma as an error bar and optional reference values (e.g. the paper's) as black
//!   ticks; translations \[nm\] and rotations \[nrad\] in two panels because the units
//!   differ.
//! * [`xy_scatter_svg`]: x-y scatter of the samples \[nm\], one panel per variant and
//!   evaluation point (each named), common axes.
//! * [`convergence_svg`]: sigma of the first k samples against k, one panel per DOF (all six).
//! * [`sensitivity_svg`]: with `--sensitivity`, the variance shares and the Sobol indices S
//!   and ST (with their 90 % intervals) of each input, one panel per DOF.
//! * [`drift_svg`]: the thermal drift along the cycle (mean and +- 3 sigma band), one panel
//!   per DOF.
//!
//! Each `*_svg` function returns the SVG text (`kinrepro study --out` writes it to a file,
//! the HTML report inlines it; both through `html::charts::study_charts`).
//!
//! Colours: the Okabe & Ito (2008) colour-blind-safe palette (then four of Paul Tol's), by
//! variant (or series) order.

mod bars;
mod convergence;
mod drift;
mod histogram;
mod scatter;
mod sensitivity;

pub use bars::sigma_bars_svg;
pub use convergence::convergence_svg;
pub use drift::drift_svg;
pub use histogram::{HistogramPanel, histogram, histogram_svg, normal_count};
pub use scatter::{ELLIPSE_LEVEL, covariance_ellipse, xy_scatter_svg};
pub use sensitivity::sensitivity_svg;

use plotters::style::RGBColor;
use serde::{Deserialize, Serialize};

use crate::dof::Dof;
use crate::study::StudyError;
use crate::study::stats::ConvergencePoint;

/// A plot that cannot be drawn.
#[derive(Debug, thiserror::Error)]
pub enum PlotError {
    #[error("nothing to plot: {0}")]
    NothingToPlot(String),
    /// NaN or infinity among the values to plot.
    #[error("non-finite value in {what}")]
    NonFinite { what: String },
    /// Series that do not fit together (lengths, ...).
    #[error("invalid parameter: {0}")]
    InvalidParameter(String),
    /// Error reported by the plotting backend.
    #[error("plotting failed: {0}")]
    Backend(String),
    /// The statistics plotted could not be formed.
    #[error(transparent)]
    Study(#[from] StudyError),
}

pub type Result<T> = std::result::Result<T, PlotError>;

/// Sigma of one variant, per DOF in the order of [`Dof::ALL`], in nm and nrad.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct VariantSigma {
    pub variant: String,
    pub sigma: [f64; 6],
    /// The 90 % interval of each sigma, `(low, high)`, where the design admits one.
    #[serde(default)]
    pub interval: Option<([f64; 6], [f64; 6])>,
    /// Reference values of sigma (the paper's, or the user's), per DOF where given.
    #[serde(default)]
    pub reference: Option<[Option<f64>; 6]>,
}

impl VariantSigma {
    /// Sigma without interval or reference.
    pub fn new(variant: impl Into<String>, sigma: [f64; 6]) -> Self {
        VariantSigma { variant: variant.into(), sigma, interval: None, reference: None }
    }
}

/// The x-y errors \[nm\] of every sample of one variant at one evaluation point.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct VariantScatter {
    pub variant: String,
    /// The evaluation point (e.g. `centre`, `trihedral ball`).
    #[serde(default)]
    pub point: String,
    pub xy: Vec<(f64, f64)>,
}

/// Convergence of sigma of one DOF of one variant (unit from `dof`).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ConvergenceSeries {
    pub variant: String,
    pub dof: Dof,
    pub points: Vec<ConvergencePoint>,
}

/// Okabe & Ito's eight colours, then four of Paul Tol's muted scheme (wine,
/// teal, olive, grey) so that up to twelve series differ.
const PALETTE: [RGBColor; 12] = [
    RGBColor(0, 114, 178),
    RGBColor(230, 159, 0),
    RGBColor(0, 158, 115),
    RGBColor(204, 121, 167),
    RGBColor(86, 180, 233),
    RGBColor(213, 94, 0),
    RGBColor(240, 228, 66),
    RGBColor(0, 0, 0),
    RGBColor(136, 34, 85),
    RGBColor(68, 170, 153),
    RGBColor(153, 153, 51),
    RGBColor(136, 136, 136),
];

/// One evaluation point's thermal drift over a study's samples, per cycle
/// point (in the point's units: nm, nrad).
#[derive(Debug, Clone, PartialEq)]
pub struct DriftSeries {
    /// "variant · point".
    pub label: String,
    pub steps: Vec<DriftStep>,
}

/// The drift at one cycle point: its temperature changes [K] and the mean
/// and sigma of each DOF over the samples.
#[derive(Debug, Clone, PartialEq)]
pub struct DriftStep {
    pub delta_t_k: [f64; 2],
    pub mean: [f64; 6],
    pub sigma: [f64; 6],
}

pub(crate) fn color(i: usize) -> RGBColor {
    PALETTE[i % PALETTE.len()]
}

/// Factor on the data maximum that leaves room for a legend of `entries`
/// lines (about 20 px each) at the top of a plot area `plot_px` high.
pub(crate) fn legend_room(entries: usize, plot_px: f64) -> f64 {
    let frac = ((20.0 * entries as f64 + 20.0) / plot_px).min(0.75);
    1.0 / (1.0 - frac)
}

/// The legend of a panel's labelled series, upper right, at `font` px on
/// a translucent white box (every study chart's).
pub(crate) fn draw_legend<'a, DB, CT>(
    chart: &mut plotters::chart::ChartContext<'a, DB, CT>,
    font: u32,
) -> Result<()>
where
    DB: plotters::prelude::DrawingBackend + 'a,
    CT: plotters::coord::CoordTranslate,
{
    use plotters::prelude::{BLACK, Color, SeriesLabelPosition, WHITE};
    chart
        .configure_series_labels()
        .label_font(("sans-serif", font))
        .position(SeriesLabelPosition::UpperRight)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .draw()
        .map_err(plot_err)
}

pub(crate) fn plot_err<E: std::fmt::Display>(e: E) -> PlotError {
    PlotError::Backend(e.to_string())
}

pub(crate) fn check_finite<'a>(
    values: impl IntoIterator<Item = &'a f64>,
    what: &str,
) -> Result<()> {
    if values.into_iter().all(|v| v.is_finite()) {
        Ok(())
    } else {
        Err(PlotError::NonFinite { what: what.into() })
    }
}

/// Upper axis limit: 10 % headroom above `max`, or 1 when everything is 0.
/// Values too large for an axis (overflowing `f64` with the headroom) are an error.
pub(crate) fn headroom(max: f64) -> Result<f64> {
    let top = if max > 0.0 { max * 1.1 } else { 1.0 };
    if top.is_finite() {
        Ok(top)
    } else {
        Err(PlotError::NonFinite { what: "axis range (values too large)".into() })
    }
}
