//! One contact pair rendered: the table printed by `kinrepro contact` and
//! its load history's CSV (here), Hertz's validity at a load
//! ([`validity`]), the notes on what a safety factor leaves out
//! ([`safety`]) and the FE check of the Hertz law ([`validate_hertz`]).

pub mod safety;
pub mod validate_hertz;
pub mod validity;

use std::fmt::Write;

use crate::contact::hertz::CONFORMITY_LIMIT;
use crate::contact::history::HistoryStep;
use crate::contact::{ContactEvaluation, HertzLaw, PairCurvature, TangentialSupport};
use crate::dof::nano;
use crate::report::table::{Table, cells};

/// Why a contact at `load` is too conformal for Hertz (its major
/// semi-axis above [`CONFORMITY_LIMIT`] of the smaller relative radius of
/// curvature), or `None`.
pub fn conformity_warning(h: &HertzLaw, load: f64) -> Option<String> {
    let (a, r) = (h.semi_axes(load)[0], h.radii[0]);
    (h.conformity(load) > CONFORMITY_LIMIT).then(|| {
        format!(
            "too conformal for Hertz: the semi-axis a = {:.4} mm is {:.1} % of the smaller relative radius of curvature {:.4} mm (limit {:.0} %); Hertz treats both bodies as half-spaces, which needs a contact small against the radii, so these numbers are only indicative",
            a * 1e3,
            100.0 * a / r,
            r * 1e3,
            100.0 * CONFORMITY_LIMIT
        )
    })
}

/// One line per contact of `c` too conformal for Hertz at its normal
/// force in `forces` [N] (`contact i: too conformal ...`,
/// [`conformity_warning`]): `check` at the frictionless preload forces,
/// `run` at the seated ones, `study` before it starts.
pub fn conformity_warnings(c: &crate::assembly::Coupling, forces: &[f64]) -> Vec<String> {
    (c.contacts.iter().zip(forces).enumerate())
        .filter_map(|(i, (k, &f))| {
            conformity_warning(&k.law.hertz, f).map(|w| format!("contact {}: {w}", i + 1))
        })
        .collect()
}

/// A readable table of one contact evaluation (SI values with engineering units).
pub fn contact_table(e: &ContactEvaluation) -> String {
    let mut s = String::new();
    let mut row = |k: &str, v: String| {
        let _ = writeln!(s, "{k:<32} {v}");
    };
    let [rx, ry] = e.relative_radii_m.map(|r| r * 1e3);
    let [a, b] = e.semi_axes_m.map(|r| r * 1e6);
    row("shape", e.shape.name().to_string());
    row("normal load", format!("{:.6} N", e.load_n));
    let gpa = |v: f64| format!("{:.4} GPa", v / 1e9);
    row("effective modulus E*", gpa(e.effective_modulus_pa));
    row("effective shear modulus G*", gpa(e.effective_shear_modulus_pa));
    row("relative radii Rx, Ry", format!("{rx:.6}, {ry:.6} mm"));
    let k = e.hertz_constant;
    row("Hertz constant K (F = K d^1.5)", format!("{k:.6e} N/m^1.5"));
    row("approach", format!("{:.4} nm", nano(e.approach_m)));
    row("semi-axes a, b", format!("{a:.4}, {b:.4} um"));
    let mpa = |v: f64| format!("{:.4} MPa", v / 1e6);
    row("peak pressure p0", mpa(e.max_pressure_pa));
    let k = e.normal_stiffness_n_per_m;
    row("normal stiffness dF/dd", format!("{k:.6e} N/m"));
    let k = e.tangential_stiffness_n_per_m;
    row("tangential stiffness k_t", format!("{k:.6e} N/m (geometric mean)"));
    let (ka, kb) = (e.tangential_stiffness_major_n_per_m, e.tangential_stiffness_minor_n_per_m);
    row("k_t along a, along b (Mindlin)", format!("{ka:.6e}, {kb:.6e} N/m"));
    row("max subsurface shear tau_max", mpa(e.max_shear_stress_pa));
    let d = e.max_shear_depth_m * 1e6;
    row("depth of tau_max", format!("{d:.4} um"));
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
    /// A support compliance in series with Mindlin's [m/N] (rigid: none);
    /// an anisotropic one along x (its axis) and across it.
    pub tangential_support: TangentialSupport,
    /// The command that drove it, as its user wrote it (e.g. the CLI's
    /// `contact --history`).
    pub command: &'a str,
}

/// The tangential support of a history's header: one compliance, or the
/// two along x and across it (y).
fn support_text(s: &TangentialSupport) -> String {
    if s.is_isotropic() {
        format!("{:e} m/N", s.along)
    } else {
        format!("{:e} m/N along x, {:e} m/N along y", s.along, s.across)
    }
}

/// The CSV of `kinrepro contact --history`: `#` provenance lines, then the
/// header `step,P_N,Qx_N,Qy_N,sx_m,sy_m,slip` and one row per step (SI
/// units; x along the major axis of the contact ellipse, s the tangential
/// displacement of the ball relative to the fixed body).
pub fn history_csv(p: &HistoryProvenance, steps: &[HistoryStep]) -> String {
    let mut s = String::new();
    let [c1, c2] = [p.curvature.radii1, p.curvature.radii2];
    let _ = writeln!(
        s,
        "# kinrepro {} {} {}: {} radii1 {:e},{:e} m radii2 {:e},{:e} m angle {} deg, {} on {}, tangential law {}, mu_s {}, mu_d {}, tangential support compliance {}",
        env!("CARGO_PKG_VERSION"),
        p.command,
        p.history_file,
        p.shape,
        c1[0],
        c1[1],
        c2[0],
        c2[1],
        p.curvature.angle.to_degrees(),
        p.materials.0,
        p.materials.1,
        p.law,
        p.mu_static,
        p.mu_dynamic,
        support_text(&p.tangential_support)
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
