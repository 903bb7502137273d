//! The summary printed by `kinrepro check`.

use std::fmt::Write;

use crate::assembly::Coupling;
use crate::assembly::constraint::{analyse, frictionless_preload_forces};
use crate::assembly::friction_limit::friction_limit;
use crate::contact::stress::contact_stress;
use crate::report::coupling::preload;
use crate::report::table::{Table, cells};
use crate::scene::Scene;

/// What the friction limit means for this scene, given why it cannot seat
/// (`cannot_seat`, the verdict of `study::verdict::cannot_seat`), if it
/// cannot; empty below the limit.
pub fn seating_note(scene: &Scene, c: &Coupling, cannot_seat: Option<&str>) -> String {
    let mu_max = scene.largest_mu();
    let limit = friction_limit(c, &scene.preload).mu_limit;
    if let Some(reason) = cannot_seat {
        return format!(
            "  CANNOT SEAT: {reason}; a study of it exits non-zero (its scatter is not a result)\n"
        );
    }
    let truncation = match scene.truncation_warning() {
        Some(w) => format!("  WARNING: {w}\n"),
        None => String::new(),
    };
    if mu_max < limit {
        return truncation;
    }
    let what = if scene.mu_distribution.is_uniform() {
        "mu_static + spread"
    } else {
        "the 99.9 % quantile of mu_s"
    };
    format!(
        "{truncation}  WARNING: {what} = {mu_max:.3} is above the friction limit {limit:.4}: seating from the touching pose (as `study` does) is unaffected, but a half that arrives off-centre (one contact still open) may stick off its seat instead of centring\n"
    )
}

/// What a study of `scene` (assembled as `c`) warns about before it
/// starts, as `check` does: a heavily truncated friction distribution,
/// and contacts too conformal for Hertz at the frictionless preload forces.
pub fn study_warnings(scene: &Scene, c: &Coupling) -> Vec<String> {
    let forces = frictionless_preload_forces(c, &scene.preload);
    let conformity = crate::report::contact::conformity_warnings(c, &forces);
    scene.truncation_warning().into_iter().chain(conformity).collect()
}

/// Summary of one scene assembled as `c`: contacts, constraint status,
/// friction limit.
pub fn check_summary(s: &Scene, c: &Coupling) -> String {
    let mut out = String::new();
    let _ = writeln!(out, "{}  ({})", s.file, s.name);
    let report = analyse(c);
    let _ = writeln!(out, "  constraint: {}", report.describe());
    let limit = friction_limit(c, &s.preload);
    let limit_text = if limit.mu_limit.is_finite() {
        format!(
            "mu < {:.4} (contact {} is the first that can stay open; polyhedral cone: true limit within -{:.2} %)",
            limit.mu_limit,
            limit.critical_contact,
            100.0 * limit.cone_error_bound
        )
    } else {
        "none below mu = 10".to_string()
    };
    let _ = writeln!(out, "  friction limit for seating: {limit_text}");
    let mu = crate::scene::mu::describe_friction(
        (s.friction.mu_static, s.friction.spread),
        s.contact_friction.as_deref(),
        (&s.mu_distribution, s.mu_correlation),
        "(uniform)",
    );
    let _ = writeln!(
        out,
        "  preload: {}; {mu}, mu_d/mu_s = {}, {:?} tangential law",
        preload::summary(&s.preload),
        s.friction.dynamic_ratio,
        s.friction.tangential_law
    );
    out.push_str(&preload::force_lines(&s.preload, "    "));
    out.push_str(&support_lines(s));
    contact_rows(&mut out, s, c);
    out
}

/// The support compliances behind the contacts (`support_compliance`),
/// one line per distinct pair of values; empty where every support is rigid.
fn support_lines(s: &Scene) -> String {
    let mut groups: Vec<((f64, f64, f64), Vec<usize>)> = Vec::new();
    for (i, surface) in s.surfaces.iter().enumerate() {
        let t = &surface.tangential_support;
        let key = (surface.support_compliance, t.along, t.across);
        if key == (0.0, 0.0, 0.0) {
            continue;
        }
        match groups.iter_mut().find(|(k, _)| *k == key) {
            Some((_, contacts)) => contacts.push(i + 1),
            None => groups.push((key, vec![i + 1])),
        }
    }
    let mut out = String::new();
    for ((normal, along, across), contacts) in groups {
        let list: Vec<String> = contacts.iter().map(|c| c.to_string()).collect();
        let tangential = if along == across {
            format!("tangential {along:e} m/N")
        } else {
            format!("tangential {along:e} m/N along its axis, {across:e} m/N across")
        };
        let _ = writeln!(
            out,
            "  support compliance behind contact(s) {}: normal {normal:e} m/N, {tangential}",
            list.join(", ")
        );
    }
    out
}

/// One row per contact at the frictionless preload forces: geometry,
/// moduli, peak stresses and safety factors, with the notes.
fn contact_rows(out: &mut String, s: &Scene, c: &Coupling) {
    let forces = frictionless_preload_forces(c, &s.preload);
    let mut t = Table::new(">#; >ball; <pair; >normal (x, y, z); >Rx, Ry [mm]; >E* [GPa]:.2; >G* [GPa]:.2; >F_n(mu=0) [N]:.4; >p0 [MPa]:.2; >tau_max [MPa]:.2; >SF_p:.2; >SF_tau:.2; >SF:.2")
    .indent(2);
    let mut left_out = Vec::new();
    for (i, k) in c.contacts.iter().enumerate() {
        let n = c.geometry(i, &c.touching_pose).normal;
        let h = &k.law.hertz;
        let st = contact_stress(&k.pair, h, &k.shear, forces[i]);
        t.row(cells![
            i + 1,
            k.ball + 1,
            k.shape.name(),
            format!("({:>6.3}, {:>6.3}, {:>6.3})", n.x, n.y, n.z),
            format!("{:>6.3}, {:>6.3}", h.radii[0] * 1e3, h.radii[1] * 1e3),
            h.e_star / 1e9,
            k.law.g_star / 1e9,
            forces[i],
            st.max_pressure_pa / 1e6,
            st.max_shear_stress_pa[0].max(st.max_shear_stress_pa[1]) / 1e6,
            st.pressure_safety_factor,
            st.shear_safety_factor,
            st.safety_factor,
        ]);
        left_out.push(st.left_out);
    }
    *out += &t.text();
    let _ = writeln!(
        out,
        "  p0, tau_max (subsurface shear on the contact axis: closed form for circles, quadrature for ellipses) and safety factors SF = allowable / actual at the frictionless preload forces; \"-\": no allowable given"
    );
    for note in crate::report::contact::safety::left_out_notes(left_out.iter().map(Vec::as_slice)) {
        let _ = writeln!(out, "  {note}");
    }
    for w in crate::report::contact::conformity_warnings(c, &forces) {
        let _ = writeln!(out, "  WARNING: {w}");
    }
}
