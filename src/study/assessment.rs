//! The design's assessment beside its scatter, the part of a design
//! review's verdict a study's samples do not give: the friction limit for
//! seating against the coefficients the study draws, and each contact's
//! safety factors at the frictionless preload forces with the materials
//! they leave out. Computed once here from the scene and its coupling (the
//! numbers `kinrepro check` prints); the text table, the JSON
//! (`assessment` of each variant) and the HTML report's verdict show it.

use serde::{Deserialize, Serialize};

use crate::assembly::Coupling;
use crate::assembly::constraint::frictionless_preload_forces;
use crate::assembly::friction_limit::friction_limit;
use crate::contact::stress::contact_stress;
use crate::scene::Scene;

/// Friction limit and contact safety of one scene (module docs).
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct Assessment {
    /// mu_lim: the largest mu at which no contact can stay open while the
    /// others hold the preload in their friction cones
    /// (`assembly::friction_limit`); null where none is below
    /// mu = 10.
    pub friction_limit: Option<f64>,
    /// The contact that can stay open first (1-based); null with the limit.
    pub friction_limit_contact: Option<usize>,
    /// The largest static coefficient the study draws (mu0 + spread, or the
    /// 99.9 % quantile of a distribution).
    pub mu_max: f64,
    /// mu_max at or above the limit: seating from the touching pose (as a
    /// study does) is unaffected, but a half that arrives off-centre may
    /// stick off its seat.
    pub above_friction_limit: bool,
    /// Each contact's safety factors at the frictionless preload forces.
    pub contacts: Vec<ContactSafety>,
}

/// One contact's safety against its materials' allowables.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
pub struct ContactSafety {
    /// 1-based.
    pub contact: usize,
    /// The moving element's material and the fixed element's.
    pub materials: [String; 2],
    /// Allowable / actual for the peak pressure, the subsurface shear
    /// stress, and the smaller of the two; null where no allowable is known.
    pub pressure_safety_factor: Option<f64>,
    pub shear_safety_factor: Option<f64>,
    pub safety_factor: Option<f64>,
    /// Materials a factor leaves out (they lack the allowable the other
    /// body has), each with the key it lacks.
    pub left_out: Vec<LeftOutMaterial>,
}

/// A material a safety factor does not cover, and the key it lacks
/// (`allowable_pressure` or `allowable_shear_stress`).
#[derive(Debug, Clone, PartialEq, Eq, Serialize, Deserialize)]
pub struct LeftOutMaterial {
    pub material: String,
    pub missing: String,
}

impl Assessment {
    /// The assessment of `scene` assembled as `coupling`.
    pub fn new(scene: &Scene, coupling: &Coupling) -> Self {
        let limit = friction_limit(coupling, &scene.preload);
        let finite = limit.mu_limit.is_finite();
        let mu_max = scene.largest_mu();
        let forces = frictionless_preload_forces(coupling, &scene.preload);
        let contacts = (coupling.contacts.iter().zip(&forces).enumerate())
            .map(|(i, (k, &f))| {
                let st = contact_stress(&k.pair, &k.law.hertz, &k.shear, f);
                ContactSafety {
                    contact: i + 1,
                    materials: [k.pair.material1.name.clone(), k.pair.material2.name.clone()],
                    pressure_safety_factor: st.pressure_safety_factor,
                    shear_safety_factor: st.shear_safety_factor,
                    safety_factor: st.safety_factor,
                    left_out: (st.left_out.iter())
                        .map(|l| LeftOutMaterial {
                            material: l.material.clone(),
                            missing: l.missing.to_string(),
                        })
                        .collect(),
                }
            })
            .collect();
        Assessment {
            friction_limit: finite.then_some(limit.mu_limit),
            friction_limit_contact: finite.then_some(limit.critical_contact),
            mu_max,
            above_friction_limit: finite && mu_max >= limit.mu_limit,
            contacts,
        }
    }

    /// The contact with the smallest safety factor, if any has one.
    pub fn weakest(&self) -> Option<&ContactSafety> {
        (self.contacts.iter())
            .filter(|c| c.safety_factor.is_some())
            .min_by(|a, b| a.safety_factor.partial_cmp(&b.safety_factor).expect("finite"))
    }
}
