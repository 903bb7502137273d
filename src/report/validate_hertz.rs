//! The table printed by `kinrepro validate-hertz`.

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
