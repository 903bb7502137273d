//! Sobol indices in a study report: the text table, one per sensitivity
//! block: per input (e.g. each contact's friction coefficient mu_k) and DOF,
//! the first-order index S and the total index ST with their 90 % bootstrap
//! intervals (see [`crate::study::sensitivity::sobol`]).

use std::fmt::Write;

use crate::study::sensitivity::SensitivityBlock;
use crate::study::sensitivity::sobol::SobolDof;

/// DOF label of an output name `point/x_m` -> `x`.
fn dof_label(output: &str) -> String {
    let comp = output.rsplit_once('/').map_or(output, |(_, c)| c);
    comp.rsplit_once('_').map_or(comp, |(d, _)| d).to_string()
}

/// The Sobol table of one block: inputs down; per DOF the first-order and
/// total index, each with its 90 % interval below.
pub fn sobol_table(s: &mut String, b: &SensitivityBlock) {
    let Some(sob) = &b.sobol else {
        let _ = writeln!(
            s,
            "  Sobol indices of the {} scatter: not computed (a sharded or merged study: they \
             need the whole Saltelli matrices in one run without --shard)",
            b.kind
        );
        return;
    };
    let _ = writeln!(
        s,
        "  Sobol indices of the {} scatter: first-order S and total ST per input and DOF, 90 % \
         bootstrap interval below; base sample size N = {}, {} seatings, seed {} ({})",
        b.kind, sob.base_samples, sob.evaluations, sob.seed, sob.estimator
    );
    let head: Vec<String> = sob
        .dofs
        .iter()
        .map(|d| format!("{:>27}", format!("{} (S | ST)", dof_label(&d.output))))
        .collect();
    let _ = writeln!(s, "  {:<22}{}", "input", head.join(""));
    for (j, name) in b.inputs.iter().enumerate() {
        let cells = |f: &dyn Fn(&SobolDof) -> String| -> String {
            sob.dofs.iter().map(|d| format!("{:>27}", f(d))).collect()
        };
        let est = cells(&|d| {
            d.indices.as_ref().map_or("-".into(), |x| {
                format!("{:.3} | {:.3}", x.first[j], x.total[j])
            })
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
        let _ = writeln!(s, "  {name:<22}{est}");
        let _ = writeln!(s, "  {:<22}{ci}", "");
    }
    let sums = |f: &dyn Fn(&[f64]) -> f64| -> String {
        sob.dofs
            .iter()
            .map(|d| {
                let v = d.indices.as_ref().map_or("-".into(), |x| {
                    format!("{:.3} | {:.3}", f(&x.first), f(&x.total))
                });
                format!("{v:>27}")
            })
            .collect()
    };
    let _ = writeln!(s, "  {:<22}{}", "sum", sums(&|v| v.iter().sum()));
    for d in &sob.dofs {
        if let Some(n) = &d.note {
            let _ = writeln!(s, "  note, {}: {n}", d.output);
        }
    }
}
