//! The one rule for a coupling that cannot seat, applied by every command
//! that seats a coupling (`check`, `study` with either solver, `merge`,
//! `sweep`, `predict`).
//!
//! Rule: seat the coupling quasi-statically from the touching pose with
//! every mu_s at the low and at the high end of its range (mu0 -+ spread;
//! mu0 -+ 10 % for a scene without spread). If in neither seating a
//! contact slid (`SeatedPose::slid`: every contact stuck from the first
//! load increment to the end), the seated pose is the elastic response to
//! the preload and does not depend on friction: the coupling does not
//! centre, so the scatter a study would report (zero for the quasi-static
//! solver, numerical noise for the dynamic one) is not a result. The
//! verdict is read from the contacts' stick/slip state, not from equal
//! poses: a spread of 1e-17, or mu_d near 0, gives equal poses of a
//! coupling whose contacts all slide. The probe is quasi-static for either
//! solver: whether the contacts stick is a question of the coupling's
//! statics.
//!
//! A frictionless coupling (mu_s = 0, no spread) always slides into its
//! one equilibrium: it seats, and its zero scatter is the true answer.

use super::StudyError;
use crate::assembly::Coupling;
use crate::scene::Scene;
use crate::solve::{Load, Method};

/// Why `scene`, assembled as `coupling`, cannot seat (one line, without
/// the scene file), or `None` if it seats; an error only if a probe
/// seating fails. The probe seats under the scene's preload with
/// `method`'s options if it is quasi-static, else with the default
/// quasi-static solver.
pub fn cannot_seat(
    scene: &Scene,
    coupling: &Coupling,
    method: &Method,
) -> Result<Option<String>, StudyError> {
    let f = &scene.friction;
    if scene.largest_mu() == 0.0 {
        return Ok(None);
    }
    let n = coupling.contacts.len();
    // Each contact at the ends of its range (`Scene::mu_range`: mu0 -+
    // spread where uniform), or at mu0 -+ 10 % where the range is a point.
    let probe = |sign: f64| -> Vec<f64> {
        (0..n)
            .map(|k| {
                let (lo, hi) = scene.mu_range(k);
                if lo < hi {
                    return if sign < 0.0 { lo.max(0.0) } else { hi };
                }
                // Within the coefficients a scene may give ([0, MU_MAX]):
                // mu0 = 2 is probed at 1.8 and 2.
                let mu0 = scene.friction_of(k).0;
                (mu0 + sign * 0.1 * mu0).clamp(0.0, crate::scene::resolve::MU_MAX)
            })
            .collect()
    };
    let method = match method {
        Method::QuasiStatic(_) => *method,
        _ => Method::default(),
    };
    let nominal = Load::nominal(scene);
    let mut slid = false;
    for mu in [probe(-1.0), probe(1.0)] {
        let load = nominal.with_mu(&mu);
        let s = method.seat(coupling, &load).map_err(|source| {
            StudyError::FrictionProbe { mu: load.mu.clone(), source }.in_file(&scene.file)
        })?;
        slid |= s.seated.slid;
    }
    let why = || {
        match (&scene.contact_friction, scene.mu_distribution.is_uniform()) {
        (None, true) => reason(f.mu_static, f.spread),
        (Some(_), true) => "with each contact's mu_s at its mu_static +- spread every contact sticks from the first load increment: the seated pose does not depend on friction and the coupling does not centre".to_string(),
        (_, false) => "with each contact's mu_s at the 0.1 % and 99.9 % quantiles of its distribution every contact sticks from the first load increment: the seated pose does not depend on friction and the coupling does not centre".to_string(),
    }
    };
    Ok((!slid).then(why))
}

/// The verdict's text for friction mu0 +- spread.
pub fn reason(mu_static: f64, spread: f64) -> String {
    format!(
        "with mu_s = {mu_static} +- {spread} every contact sticks from the first load increment: the seated pose does not depend on friction and the coupling does not centre"
    )
}
