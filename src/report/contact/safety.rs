//! Notes on safety factors that do not cover every material of a pair
//! (`contact::stress::LeftOut`): printed under the `run` and `check` tables.

use crate::contact::stress::LeftOut;

/// One line per (material, missing allowable), naming the contacts
/// (1-based, in the order given) whose factor left that material out.
pub fn left_out_notes<'a>(per_contact: impl IntoIterator<Item = &'a [LeftOut]>) -> Vec<String> {
    let mut groups: Vec<(&LeftOut, Vec<usize>)> = Vec::new();
    for (i, list) in per_contact.into_iter().enumerate() {
        for l in list {
            match groups.iter_mut().find(|(g, _)| *g == l) {
                Some((_, contacts)) => contacts.push(i + 1),
                None => groups.push((l, vec![i + 1])),
            }
        }
    }
    groups
        .into_iter()
        .map(|(l, contacts)| {
            let factor = if l.missing == "allowable_pressure" { "SF_p" } else { "SF_tau" };
            let list: Vec<String> = contacts.iter().map(|c| c.to_string()).collect();
            format!(
                "NOTE: contact{} {}: {factor} and SF leave out `{}`, which has no `{}`; they \
                 cover the other body only (add `{}` to its [[materials]] entry; a built-in \
                 needs `override = true`)",
                if contacts.len() == 1 { "" } else { "s" },
                list.join(", "),
                l.material,
                l.missing,
                l.missing
            )
        })
        .collect()
}
