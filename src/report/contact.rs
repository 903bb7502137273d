//! The table printed by `kinrepro contact`.

use std::fmt::Write;

use crate::contact::hertz::CONFORMITY_LIMIT;
use crate::contact::history::HistoryStep;
use crate::contact::{ContactEvaluation, PairCurvature, SlipState};

/// The words of a contact too conformal for Hertz (a semi-axis above
/// [`CONFORMITY_LIMIT`] of the smaller relative radius), or `None`.
pub fn conformity_warning(e: &ContactEvaluation) -> Option<String> {
    let (a, r) = (e.semi_axes_m[0], e.relative_radii_m[0]);
    (a > CONFORMITY_LIMIT * r).then(|| {
        format!(
            "too conformal for Hertz: the semi-axis a = {:.4} mm is {:.1} % of the smaller relative radius of curvature {:.4} mm (limit {:.0} %); Hertz assumes a contact small against the radii (half-spaces), so these numbers overstate what they know",
            a * 1e3,
            100.0 * a / r,
            r * 1e3,
            100.0 * CONFORMITY_LIMIT
        )
    })
}

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
    pub curvature: PairCurvature,
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
    let c = &p.curvature;
    let _ = writeln!(
        s,
        "# kinrepro {} contact --history {}: {} radii1 {:e},{:e} m radii2 {:e},{:e} m angle {} deg, {} on {}, tangential law {}, mu_s {}, mu_d {}",
        env!("CARGO_PKG_VERSION"),
        p.history_file,
        p.shape,
        c.radii1[0],
        c.radii1[1],
        c.radii2[0],
        c.radii2[1],
        c.angle.to_degrees(),
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
    s.push_str("step,P_N,Qx_N,Qy_N,sx_m,sy_m,slip\n");
    for (i, st) in steps.iter().enumerate() {
        let _ = writeln!(
            s,
            "{},{:e},{:e},{:e},{:e},{:e},{}",
            i + 1,
            st.load.normal_force,
            st.load.tangential_force[0],
            st.load.tangential_force[1],
            st.displacement[0],
            st.displacement[1],
            match st.slip {
                SlipState::Stick => "stick",
                SlipState::Slip => "slip",
            }
        );
    }
    s
}
