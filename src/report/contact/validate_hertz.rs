//! The table printed by `kinrepro validate-hertz`.

use crate::contact::hertz::CONFORMITY_LIMIT;
use crate::fe::conformity::{ConformityStudy, LIMIT};
use crate::fe::pairs::PairValidation;
use crate::report::table::{Table, cells};

/// `a, b` with two decimals.
fn pair(a: f64, b: f64) -> String {
    format!("{a:.2}, {b:.2}")
}

/// One row per pair: loads, FE and Hertz approach and semi-axes, errors in %.
pub fn table(rows: &[PairValidation]) -> String {
    let s = String::from(
        "FE (27-node hexahedra, Boussinesq far field, frictionless Signorini contact) against kinrepro's Hertz law,\nat the largest normal load each pair reaches in the nominal seating. Errors are FE/Hertz - 1.\n\n",
    );
    let mut t = Table::new(
        "<pair; >radii [mm]; <materials; >F_n [N]:.4; >approach [nm]:.3; >err [%]:.3; >semi-axes [um]; >err x, y [%]; >h [um]:.2; >DOFs; >t [s]:.1",
    );
    for r in rows {
        let radii = match r.radii_m {
            [Some(a), Some(b)] => format!("{:.2}/{:.2}", a * 1e3, b * 1e3),
            [Some(a), None] => format!("{:.2}/plane", a * 1e3),
            _ => "-".into(),
        };
        let (a, e) = (r.fe_semi_axes_m, r.semi_axes_error_rel);
        t.row(cells![
            r.shape.name(),
            radii,
            format!("{}/{}", r.materials[0], r.materials[1]),
            r.load_n,
            crate::dof::nano(r.fe_approach_m),
            100.0 * r.approach_error_rel,
            pair(a[0] * 1e6, a[1] * 1e6),
            pair(100.0 * e[0], 100.0 * e[1]),
            r.element_size_m * 1e6,
            r.dofs,
            r.seconds,
        ]);
        if r.convergence.is_empty() {
            continue;
        }
        let mut c =
            Table::new(">h [um]:.2; >b/h:.1; >DOFs; >approach [%]:.3; >semi-axes [%]; >t [s]:.1");
        for k in &r.convergence {
            let e = k.semi_axis_error_rel;
            c.row(cells![
                k.element_size * 1e6,
                1.0 / k.element_size_over_a,
                k.dofs,
                100.0 * k.approach_error_rel,
                pair(100.0 * e[0], 100.0 * e[1]),
                k.seconds,
            ]);
        }
        for (i, line) in c.text().lines().enumerate() {
            let label = if i == 0 { "mesh convergence:" } else { "" };
            t.note(format!("    {label:<17} {line}"));
        }
    }
    s + &t.text()
}

/// What the conformity study can and cannot show (printed under its table).
const CONFORMITY_NOTE: &str = "Both FE bodies are half-spaces with the exact gap of ball and groove: the study shows where Hertz's\nquadratic gap fails, not where the half-space assumption of Hertz fails (that needs the finite ball and\ngroove, and may come first near conformity).";

/// `validate-hertz --conformity`: per sphere-groove pair, a row per ratio
/// R_g / r (FE exact and quadratic gap against Hertz, and exact / quadratic),
/// the ratio where they part by the study's limit and kinrepro's warning ratio.
pub fn conformity_table(studies: &[ConformityStudy]) -> String {
    let mut s = format!(
        "Conformity of a ball in a gothic-arch groove: FE with the exact gap of ball and groove (exact) and with\nHertz's quadratic gap (quad.) against kinrepro's Hertz law (FE/Hertz - 1), and exact/quad. - 1 on the same mesh\n(the error of the quadratic gap alone), as the groove radius R_g closes on the ball radius r at a fixed load.\nSemi-axes: along, across the groove, resolved only to the node spacing (the approach is the criterion).\n* a bisection ratio.\n{CONFORMITY_NOTE}\n"
    );
    for st in studies {
        s += &format!(
            "\nsphere-groove r = {:.2} mm (scene: R_g = {:.3} mm), {}/{}, F_n = {:.4} N ({})\n",
            st.ball_radius_m * 1e3,
            st.groove_radius_m * 1e3,
            st.materials[0],
            st.materials[1],
            st.load_n,
            st.scenes.join(", ")
        );
        let mut t = Table::new(
            ">R_g/r; >a/R_x:.4; >exact: approach [%]:.3; >semi-axes [%]; >quad.: approach [%]:.3; >semi-axes [%]; >exact/quad.: approach [%]:.3; >semi-axes [%]; >DOFs; >t [s]:.1",
        );
        for r in &st.rows {
            let (e, q, g) =
                (r.semi_axes_error_rel, r.quadratic_semi_axes_error_rel, r.gap_effect_rel);
            let star = if r.bisection { "*" } else { "" };
            t.row(cells![
                format!("{star}{:.5}", r.groove_over_ball),
                r.conformity,
                100.0 * r.approach_error_rel,
                pair(100.0 * e[0], 100.0 * e[1]),
                100.0 * r.quadratic_approach_error_rel,
                pair(100.0 * q[0], 100.0 * q[1]),
                100.0 * g[0],
                pair(100.0 * g[1], 100.0 * g[2]),
                r.dofs,
                r.seconds,
            ]);
        }
        s += &t.text();
        s += &conformity_summary(st);
    }
    s
}

/// The lines under a study's table: the limit ratio and the warning ratio.
fn conformity_summary(st: &ConformityStudy) -> String {
    let limit = 100.0 * LIMIT;
    let mut s = match (st.ratio_at_limit, st.conformity_at_limit) {
        (Some(q), Some(c)) => format!(
            "The exact gap's approach parts from the quadratic gap's by {limit:.0} % at R_g/r = {q:.6} (a/R_x = {c:.3}).\n"
        ),
        _ => format!(
            "No bracket of the {limit:.0} % crossing among these ratios (none reaches it, or the first already does).\n"
        ),
    };
    s += &match st.warning_ratio {
        Some(w) => format!(
            "kinrepro's conformity warning (a/R_x above {:.2}) starts at R_g/r = {w:.5} at this load.\n",
            CONFORMITY_LIMIT
        ),
        None => "kinrepro's conformity warning does not start at any ratio at this load.\n".into(),
    };
    s
}
