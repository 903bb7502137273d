//! The table printed by `kinrepro contact`.

use std::fmt::Write;

use crate::contact::ContactEvaluation;

/// A readable table of one contact evaluation (SI values with engineering units).
pub fn contact_table(e: &ContactEvaluation) -> String {
    let mut s = String::new();
    let rows: [(&str, String); 11] = [
        ("shape", e.shape.name().to_string()),
        ("normal load", format!("{:.6} N", e.load_n)),
        (
            "effective modulus E*",
            format!("{:.4} GPa", e.effective_modulus_pa / 1e9),
        ),
        (
            "effective shear modulus G*",
            format!("{:.4} GPa", e.effective_shear_modulus_pa / 1e9),
        ),
        (
            "relative radii Rx, Ry",
            format!(
                "{:.6}, {:.6} mm",
                e.relative_radii_m[0] * 1e3,
                e.relative_radii_m[1] * 1e3
            ),
        ),
        (
            "Hertz constant K (F = K d^1.5)",
            format!("{:.6e} N/m^1.5", e.hertz_constant),
        ),
        ("approach", format!("{:.4} nm", e.approach_m * 1e9)),
        (
            "semi-axes a, b",
            format!(
                "{:.4}, {:.4} um",
                e.semi_axes_m[0] * 1e6,
                e.semi_axes_m[1] * 1e6
            ),
        ),
        (
            "peak pressure p0",
            format!("{:.4} MPa", e.max_pressure_pa / 1e6),
        ),
        (
            "normal stiffness dF/dd",
            format!("{:.6e} N/m", e.normal_stiffness_n_per_m),
        ),
        (
            "tangential stiffness k_t",
            format!("{:.6e} N/m", e.tangential_stiffness_n_per_m),
        ),
    ];
    for (k, v) in rows {
        let _ = writeln!(s, "{k:<32} {v}");
    }
    s
}
