//! Stiffness and stress results of one coupling at its nominal seating
//! (nominal mu, quasi-static, default solver settings): per contact the
//! seated forces, state, peak Hertz pressure, maximum shear stress and
//! safety factor; per evaluation point the principal stiffnesses.

use std::fmt::Write;

use super::page::{escape, num};
use crate::analysis::stiffness::CouplingStiffness;
use crate::assembly::Coupling;
use crate::contact::SlipState;
use crate::solve::Seating;

/// The contact table (N, MPa) and the stiffness table (N/µm, N m/µrad).
pub fn mechanics(c: &Coupling, s: &Seating, k: &CouplingStiffness) -> String {
    let mut o = String::from(
        "<div class=\"two\"><div><h4>Contacts at the nominal seating</h4><div class=\"scroll\"><table data-check=\"table\"><thead><tr><th>#</th><th>ball</th><th>N [N]</th><th>|T| [N]</th><th>state</th><th>μ_s</th><th>p0 [MPa]</th><th>τ_max [MPa]</th><th>safety</th></tr></thead><tbody>\n",
    );
    for (i, r) in s.contacts.iter().enumerate() {
        let _ = writeln!(
            o,
            "<tr><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td><td>{}</td></tr>",
            i + 1,
            c.contacts[i].ball + 1,
            num(r.normal_force_n, 3),
            num(r.tangential_force_n, 3),
            match r.state {
                SlipState::Stick => "stick",
                SlipState::Slip => "slip",
            },
            num(r.mu_static, 3),
            num(r.max_pressure_pa / 1e6, 0),
            num(r.max_shear_stress_pa / 1e6, 0),
            r.safety_factor.map_or("-".to_string(), |f| num(f, 2)),
        );
    }
    o.push_str("</tbody></table></div><p class=\"note\">p0: peak Hertz pressure; τ_max: maximum subsurface shear stress; safety: allowable / actual (the smaller of pressure and shear, where the materials give an allowable).</p></div>\n");
    o.push_str("<div><h4>Principal stiffnesses of the seated coupling</h4><div class=\"scroll\"><table data-check=\"table\"><thead><tr><th class=\"l\">point</th><th>k_t1</th><th>k_t2</th><th>k_t3 [N/µm]</th><th>k_r1</th><th>k_r2</th><th>k_r3 [N m/µrad]</th></tr></thead><tbody>\n");
    for e in &c.scene.evaluation_points {
        let q = s.pose.apply(&e.position);
        let _ = write!(o, "<tr><td class=\"l\">{}</td>", escape(&e.name));
        match k.principal_at(&q) {
            Some(p) => {
                for (v, _) in p.translational {
                    let _ = write!(o, "<td>{}</td>", num(v / 1e6, 2));
                }
                for (v, _) in p.rotational {
                    let _ = write!(o, "<td>{}</td>", num(v / 1e6, 4));
                }
            }
            None => o.push_str("<td colspan=\"6\">not positive definite</td>"),
        }
        o.push_str("</tr>\n");
    }
    o.push_str("</tbody></table></div><p class=\"note\">Ascending principal values of the 6×6 stiffness at each point (contacts at rest: static friction sticks; `kinrepro stiffness` prints the matrix and the directions).</p></div></div>\n");
    o
}
