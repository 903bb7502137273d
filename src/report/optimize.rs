//! The optimisation's text table (`kinrepro optimize`): what produced it,
//! the objective and constraints, the optimum with its margins, the
//! statistical error of its objective and its study, then the history of
//! the candidates.

use std::fmt::Write;

use crate::explore::SweptValue;
use crate::explore::optimize::{Candidate, OptimizeReport};
use crate::report::study::text::detail;
use crate::report::table::{Cell, Column, Table, cells};

/// Six significant digits.
fn sig(v: f64) -> String {
    crate::report::table::significant(v, 6)
}

fn fields_text(fields: &std::collections::BTreeMap<String, SweptValue>) -> String {
    let each: Vec<String> = fields.iter().map(|(k, v)| format!("{k} = {v}")).collect();
    each.join(", ")
}

impl OptimizeReport {
    /// Which searches the document holds and why each stopped:
    /// `searches 1-4 of 4: 1 Solver converged after 2 runs; 2 ...`.
    pub fn searches_text(&self) -> String {
        let first = self.shard.range(self.searches).map_or(0, |r| r.start);
        let each: Vec<String> = (self.termination.iter().enumerate())
            .map(|(k, t)| format!("{} {t}", first + k + 1))
            .collect();
        let held = match each.len() {
            0 => "no search".to_string(),
            1 => format!("search {}", first + 1),
            n => format!("searches {}-{}", first + 1, first + n),
        };
        let shard = match self.shard.count {
            1 => String::new(),
            _ => format!(
                " (shard {}: merged with the other shards, the whole optimisation)",
                self.shard
            ),
        };
        format!("{held} of {}{shard}; why each stopped: {}", self.searches, each.join("; "))
    }

    /// The terminal table.
    pub fn table(&self) -> String {
        let mut s = String::new();
        let _ = writeln!(s, "{}", self.produced_by());
        let objective = self.goals.objectives.iter().map(|o| o.name()).collect::<Vec<_>>();
        let constraints = self.goals.constraints.iter().map(|c| c.name()).collect::<Vec<_>>();
        let _ = writeln!(
            s,
            "Optimisation of {} ({}): objective {}; constraints {} (SI units).",
            self.name,
            self.scene,
            objective.join(", "),
            if constraints.is_empty() { "none".to_string() } else { constraints.join(", ") }
        );
        let _ = writeln!(s, "method: {}", self.method);
        let _ = writeln!(s, "{}", self.searches_text());
        match &self.optimum {
            None => {
                let _ = writeln!(
                    s,
                    "NO FEASIBLE DESIGN: none of the {} candidates meets every constraint (see the history)",
                    self.history.len()
                );
            }
            Some(o) => {
                let unit = self.goals.objectives[0].output.unit();
                let of = if self.shard.count > 1 { " of this shard" } else { "" };
                let _ = writeln!(
                    s,
                    "\noptimum{of} (candidate {}): {}",
                    o.evaluation,
                    fields_text(&o.fields)
                );
                let _ =
                    writeln!(s, "  objective {} = {} {unit}", objective.join(""), sig(o.objective));
                for m in &o.constraint_margins {
                    let _ = writeln!(s, "  constraint {}: margin {}", m.constraint, sig(m.margin));
                }
                let _ = writeln!(s, "  statistical error: {}", o.statistical_error);
                let _ = writeln!(s, "  re-seating scatter at the optimum:");
                s += &detail(&o.design.points);
            }
        }
        let _ = writeln!(s, "\nhistory ({} candidates):", self.history.len());
        s + &history_table(&self.history).text()
    }
}

/// One row per candidate: its fields, objective (SI), feasibility and cost.
fn history_table(h: &[Candidate]) -> Table {
    let mut t = Table::of([Column::right("#"), Column::left("fields")])
        .with(Column::list(">objective:.6g; <feasible; >cost:.6g; <status"))
        .indent(2);
    for c in h {
        t.row(cells![
            c.evaluation,
            fields_text(&c.fields),
            c.objective.map_or(Cell::Missing, Cell::Num),
            if c.feasible { "yes" } else { "no" },
            c.cost,
            &c.status
        ]);
    }
    t
}
