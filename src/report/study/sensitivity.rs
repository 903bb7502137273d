//! Sobol indices in a study report: the text table, one per sensitivity
//! block: per input (e.g. each contact's friction coefficient mu_k) and DOF,
//! the first-order index S and the total index ST with their 90 % bootstrap
//! intervals (see [`crate::study::sensitivity::sobol`]).

use super::labels::{block_label, output_point};
use crate::report::table::{Cell, Column, Table};
use crate::study::sensitivity::SensitivityBlock;
use crate::study::sensitivity::sobol::SobolDof;

/// The Sobol table of one block: inputs down; per DOF the first-order and
/// total index, each with its 90 % interval below.
pub fn sobol_table(b: &SensitivityBlock) -> String {
    let Some(sob) = &b.sobol else {
        return format!(
            "  Sobol indices of the {} scatter: not computed (a sharded or merged study: they \
             need the whole Saltelli matrices in one run without --shard)\n",
            b.kind
        );
    };
    let mut s = format!(
        "  Sobol indices of the {} scatter: first-order S and total ST per input and DOF, 90 % \
         bootstrap interval below; base sample size N = {}, {} seatings, seed {} ({})\n",
        b.kind, sob.base_samples, sob.evaluations, sob.seed, sob.estimator
    );
    let t = Table::new("<input");
    let point = sob.dofs.first().map_or("", |d| output_point(&d.output));
    let label = |o: &str| block_label(point, o, false);
    let columns = sob.dofs.iter().map(|d| format!("{} (S | ST)", label(&d.output)));
    let mut t = t.with(columns.map(Column::right)).indent(2);
    let cells = |f: &dyn Fn(&SobolDof) -> String| -> Vec<Cell> {
        sob.dofs.iter().map(|d| f(d).into()).collect()
    };
    for (j, input) in b.inputs.iter().enumerate() {
        let est = cells(&|d| {
            d.indices
                .as_ref()
                .map_or("-".into(), |x| format!("{:.3} | {:.3}", x.first[j], x.total[j]))
        });
        let ci = cells(&|d| {
            d.indices.as_ref().map_or(String::new(), |x| {
                format!(
                    "[{:.2},{:.2}]|[{:.2},{:.2}]",
                    x.first_ci90_low[j],
                    x.first_ci90_high[j],
                    x.total_ci90_low[j],
                    x.total_ci90_high[j]
                )
            })
        });
        t.row(std::iter::once(input.name().into()).chain(est).collect());
        t.row(std::iter::once("".into()).chain(ci).collect());
    }
    let sums = cells(&|d| {
        d.indices.as_ref().map_or("-".into(), |x| {
            let sum = |v: &[f64]| v.iter().sum::<f64>();
            format!("{:.3} | {:.3}", sum(&x.first), sum(&x.total))
        })
    });
    t.row(std::iter::once("sum".into()).chain(sums).collect());
    s += &t.text();
    for d in &sob.dofs {
        if let Some(n) = &d.note {
            s += &format!("  note, {}: {n}\n", d.output);
        }
    }
    s
}
