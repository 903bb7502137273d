//! The sweep's design points that were not evaluated (invalid, cannot
//! seat, failed) with their reasons, as an SVG list: the chart
//! `sweep_not_evaluated` of `--out DIR` and `--html FILE`, so that a
//! report of charts names every point missing from them and why.

use super::SweepPlotError;
use plotters::coord::Shift;
use plotters::prelude::*;

use crate::explore::{DesignReport, SweepReport, SweptValue};

/// Characters per line before a reason is wrapped.
const WIDTH: usize = 150;
/// Line height [px].
const LINE: i32 = 17;

/// The design points not evaluated (no study statistics).
pub fn not_evaluated(r: &SweepReport) -> Vec<&DesignReport> {
    r.designs.iter().filter(|d| d.points.is_empty()).collect()
}

/// The lines of the list: per design point `#index field = value, ...`,
/// then its status wrapped and indented.
pub fn lines(r: &SweepReport) -> Vec<String> {
    let mut out = Vec::new();
    for d in not_evaluated(r) {
        let values: Vec<String> = r
            .sets
            .iter()
            .map(|s| match d.values.get(&s.field) {
                Some(SweptValue::Number(x)) => format!("{} = {x}", s.field),
                Some(SweptValue::Name(n)) => format!("{} = {n}", s.field),
                None => s.field.clone(),
            })
            .collect();
        out.push(format!("#{}  {}", d.index, values.join(", ")));
        out.extend(wrap(&d.status).into_iter().map(|l| format!("    {l}")));
    }
    out
}

/// Height [px] of the chart for `r`.
pub fn height(r: &SweepReport) -> u32 {
    (60 + LINE * lines(r).len() as i32) as u32
}

/// Draw the list into `area` (the error: plotters' message).
pub fn draw(
    r: &SweepReport,
    area: &DrawingArea<SVGBackend<'_>, Shift>,
) -> Result<(), SweepPlotError> {
    let draw_err = |e: DrawingAreaErrorKind<_>| SweepPlotError::Draw(e.to_string());
    let n = not_evaluated(r).len();
    area.draw(&Text::new(
        format!("{n} of {} design points not evaluated, with the reason", r.designs.len()),
        (12, 10),
        ("sans-serif", 20).into_font(),
    ))
    .map_err(draw_err)?;
    for (i, l) in lines(r).iter().enumerate() {
        area.draw(&Text::new(l.clone(), (12, 40 + LINE * i as i32), ("monospace", 15).into_font()))
            .map_err(draw_err)?;
    }
    Ok(())
}

/// `text` in lines of at most [`WIDTH`] characters, broken at spaces.
fn wrap(text: &str) -> Vec<String> {
    let mut out: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split(' ') {
        if !line.is_empty() && line.chars().count() + 1 + word.chars().count() > WIDTH {
            out.push(std::mem::take(&mut line));
        }
        if !line.is_empty() {
            line.push(' ');
        }
        line.push_str(word);
    }
    out.push(line);
    out
}
