//! The table printed by `kinrepro contact`.

use std::fmt::Write;

use crate::contact::ContactEvaluation;
use crate::contact::history::HistoryStep;
use crate::dof::nano;
use crate::report::table::{Table, cells};

/// A readable table of one contact evaluation (SI values with engineering units).
pub fn contact_table(e: &ContactEvaluation) -> String {
    let mut s = String::new();
    let rows: [(&str, String); 14] = [
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
        ("approach", format!("{:.4} nm", nano(e.approach_m))),
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
            format!(
                "{:.6e} N/m (geometric mean)",
                e.tangential_stiffness_n_per_m
            ),
        ),
        (
            "k_t along a, along b (Mindlin)",
            format!(
                "{:.6e}, {:.6e} N/m",
                e.tangential_stiffness_major_n_per_m, e.tangential_stiffness_minor_n_per_m
            ),
        ),
        (
            "max subsurface shear tau_max",
            format!("{:.4} MPa", e.max_shear_stress_pa / 1e6),
        ),
        (
            "depth of tau_max",
            format!("{:.4} um", e.max_shear_depth_m * 1e6),
        ),
    ];
    for (k, v) in rows {
        let _ = writeln!(s, "{k:<32} {v}");
    }
    s
}

/// What produced a history table (written as `#` lines before the CSV).
pub struct HistoryProvenance<'a> {
    pub shape: &'a str,
    pub radii_m: (f64, Option<f64>),
    pub materials: (&'a str, &'a str),
    pub law: &'a str,
    pub mu_static: f64,
    pub mu_dynamic: f64,
    pub history_file: &'a str,
}

/// The CSV of `kinrepro contact --history`: `#` provenance lines, then the
/// header `step,P_N,Qx_N,Qy_N,sx_m,sy_m,slip` and one row per step (SI
/// units; x along the major axis of the contact ellipse, s the tangential
/// displacement of the ball relative to the fixed body).
pub fn history_csv(p: &HistoryProvenance, steps: &[HistoryStep]) -> String {
    let mut s = String::new();
    let r2 = p.radii_m.1.map_or("-".to_string(), |r| format!("{r:e}"));
    let _ = writeln!(
        s,
        "# kinrepro {} contact --history {}: {} radius1 {:e} m radius2 {r2} m, {} on {}, tangential law {}, mu_s {}, mu_d {}",
        env!("CARGO_PKG_VERSION"),
        p.history_file,
        p.shape,
        p.radii_m.0,
        p.materials.0,
        p.materials.1,
        p.law,
        p.mu_static,
        p.mu_dynamic
    );
    let _ = writeln!(
        s,
        "# force control, one step per row from the unloaded state; x = major axis of the contact ellipse (along the pin), SI units"
    );
    let mut t = Table::new("<step; <P_N:e; <Qx_N:e; <Qy_N:e; <sx_m:e; <sy_m:e; <slip");
    for (i, st) in steps.iter().enumerate() {
        let (q, d) = (st.load.tangential_force, st.displacement);
        let n = st.load.normal_force;
        t.row(cells![i + 1, n, q[0], q[1], d[0], d[1], st.slip.name()]);
    }
    s + &t.csv()
}
