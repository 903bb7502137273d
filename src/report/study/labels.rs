//! Labels of a study's outputs in tables and charts: the evaluation point
//! of an output name and what it measures.

use crate::scene::point::{output_label, split_output};
use crate::study::runner::INTERCHANGE_PREFIX;

/// The evaluation point of an output name (`[interchange/]<point>/<dof>`
/// or `.../along/<direction>_m`).
pub(crate) fn output_point(output: &str) -> &str {
    split_output(output).map_or("", |(head, _)| head.trim_start_matches(INTERCHANGE_PREFIX))
}

/// The label of `output` in a sensitivity block whose first output is at
/// the point `point`: what it measures, after its point's name where that
/// is another (`sample along beam`).
pub(crate) fn block_label(point: &str, output: &str, symbol: bool) -> String {
    let label = output_label(output, symbol);
    match output_point(output) {
        p if p == point => label,
        p => format!("{p} {label}"),
    }
}
