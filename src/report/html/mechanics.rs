//! Stiffness and stress results of one coupling at its nominal seating
//! (nominal mu, quasi-static, default solver settings): per contact the
//! seated forces, state, peak Hertz pressure, maximum shear stress and
//! safety factor; per evaluation point the principal stiffnesses.

use crate::analysis::stiffness::CouplingStiffness;
use crate::assembly::Coupling;
use crate::report::table::{Cell, Table, cells};
use crate::scene::Scene;
use crate::solve::Seating;

/// The contact table (N, MPa) and the stiffness table (N/µm, N m/µrad),
/// one below the other: each gets the page's full width.
pub fn mechanics((scene, c): (&Scene, &Coupling), s: &Seating, k: &CouplingStiffness) -> String {
    let mut t = Table::new(
        ">#; >ball; >N [N]:.3; >|T| [N]:.3; >state; >μ_s:.3; >p0 [MPa]:.0; >τ_max [MPa]:.0; >safety:.2",
    );
    for (i, r) in s.contacts.iter().enumerate() {
        t.row(cells![
            i + 1,
            c.contacts[i].ball + 1,
            r.normal_force_n,
            r.tangential_force_n,
            r.state.name(),
            r.mu_static,
            r.max_pressure_pa / 1e6,
            r.max_shear_stress_pa / 1e6,
            r.safety_factor,
        ]);
    }
    let mut o = format!("<h4>Contacts at the nominal seating</h4>{}", t.html(""));
    o.push_str("<p class=\"note\">p0: peak Hertz pressure; τ_max: maximum subsurface shear stress; safety: allowable / actual (the smaller of pressure and shear, where the materials give an allowable).</p>\n");
    let mut t = Table::new(
        "<point; >k_t1 [N/µm]:.2; >k_t2 [N/µm]:.2; >k_t3 [N/µm]:.2; >k_r1 [N m/µrad]:.4; >k_r2 [N m/µrad]:.4; >k_r3 [N m/µrad]:.4",
    );
    for e in &scene.evaluation_points {
        let q = s.pose().apply(&e.position);
        let mut row = cells![&e.name];
        match k.principal_at(&q) {
            Some(p) => {
                let all = p.translational.iter().chain(&p.rotational);
                row.extend(all.map(|(v, _)| Cell::Num(v / 1e6)));
            }
            None => row.extend(
                [Cell::from("not positive definite")]
                    .into_iter()
                    .chain(std::iter::repeat_n(Cell::Missing, 5)),
            ),
        }
        t.row(row);
    }
    o.push_str("<h4>Principal stiffnesses of the seated coupling</h4>");
    o += &t.html("");
    o.push_str("<p class=\"note\">Ascending principal values of the 6×6 stiffness at each point (contacts at rest: static friction sticks; `kinrepro stiffness` prints the matrix and the directions).</p>\n");
    o
}
