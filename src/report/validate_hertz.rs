//! The table printed by `kinrepro validate-hertz`.

use std::fmt::Write;

use crate::fe::pairs::PairValidation;

/// One row per pair: loads, FE and Hertz approach and semi-axes, errors in %.
pub fn table(rows: &[PairValidation]) -> String {
    let mut s = String::new();
    let _ = writeln!(
        s,
        "FE (27-node hexahedra, Boussinesq far field, frictionless Signorini contact) against kinrepro's Hertz law,\nat the largest normal load each pair reaches in the nominal seating. Errors are FE/Hertz - 1.\n"
    );
    let _ = writeln!(
        s,
        "{:<16} {:>13} {:<26} {:>8} {:>13} {:>8} {:>17} {:>15} {:>8} {:>8} {:>7}",
        "pair",
        "radii [mm]",
        "materials",
        "F_n [N]",
        "approach [nm]",
        "err [%]",
        "semi-axes [um]",
        "err x, y [%]",
        "h [um]",
        "DOFs",
        "t [s]"
    );
    for r in rows {
        let radii = match r.radii_m {
            [Some(a), Some(b)] => format!("{:.2}/{:.2}", a * 1e3, b * 1e3),
            [Some(a), None] => format!("{:.2}/plane", a * 1e3),
            _ => "-".into(),
        };
        let _ = writeln!(
            s,
            "{:<16} {:>13} {:<26} {:>8.4} {:>13.3} {:>8.3} {:>17} {:>15} {:>8.2} {:>8} {:>7.1}",
            r.shape.name(),
            radii,
            format!("{}/{}", r.materials[0], r.materials[1]),
            r.load_n,
            r.fe_approach_m * 1e9,
            100.0 * r.approach_error_rel,
            format!(
                "{:.2}, {:.2}",
                r.fe_semi_axes_m[0] * 1e6,
                r.fe_semi_axes_m[1] * 1e6
            ),
            format!(
                "{:.2}, {:.2}",
                100.0 * r.semi_axes_error_rel[0],
                100.0 * r.semi_axes_error_rel[1]
            ),
            r.element_size_m * 1e6,
            r.dofs,
            r.seconds
        );
        if !r.convergence.is_empty() {
            let _ = writeln!(
                s,
                "    mesh convergence: {:>10} {:>10} {:>9} {:>12} {:>16} {:>7}",
                "h [um]", "b/h", "DOFs", "approach [%]", "semi-axes [%]", "t [s]"
            );
            for c in &r.convergence {
                let _ = writeln!(
                    s,
                    "                      {:>10.2} {:>10.1} {:>9} {:>12.3} {:>16} {:>7.1}",
                    c.element_size * 1e6,
                    1.0 / c.element_size_over_a,
                    c.dofs,
                    100.0 * c.approach_error_rel,
                    format!(
                        "{:.2}, {:.2}",
                        100.0 * c.semi_axis_error_rel[0],
                        100.0 * c.semi_axis_error_rel[1]
                    ),
                    c.seconds
                );
            }
        }
    }
    s
}
