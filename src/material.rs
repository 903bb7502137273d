//! Materials: elastic constants, the built-in table, and the effective moduli
//! of a contact pair.
//!
//! Effective moduli (Johnson, *Contact Mechanics*, 1985, eq. 4.22 and §7.2):
//!
//! ```text
//! 1/E* = (1 - v1^2)/E1 + (1 - v2^2)/E2
//! 1/G* = (2 - v1)/G1 + (2 - v2)/G2,   G = E / (2 (1 + v))
//! ```

use serde::{Deserialize, Serialize};
use thiserror::Error;

/// An isotropic, linear-elastic material.
#[derive(Debug, Clone, PartialEq, Serialize, Deserialize)]
#[serde(deny_unknown_fields)]
pub struct Material {
    /// Kebab-case name, e.g. `steel`.
    pub name: String,
    /// Young's modulus E [Pa].
    pub youngs_modulus: f64,
    /// Poisson's ratio v [-].
    pub poisson_ratio: f64,
    /// Allowable peak Hertz contact pressure [Pa], if known.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub allowable_pressure: Option<f64>,
    /// Allowable maximum (subsurface) shear stress [Pa], if known.
    #[serde(default, skip_serializing_if = "Option::is_none")]
    pub allowable_shear_stress: Option<f64>,
}

/// A material was unknown or its constants are not physical.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MaterialError {
    #[error("unknown material `{name}` (built-in: {known})")]
    Unknown { name: String, known: String },
    #[error("material `{name}`: {field} = {value} is invalid: {reason}")]
    Invalid {
        name: String,
        field: &'static str,
        value: f64,
        reason: &'static str,
    },
}

/// The built-in table: (name, E [Pa], v, allowable pressure [Pa]).
///
/// Sources:
/// - `steel`: hardened bearing steel (100Cr6 / AISI 52100), E 210 GPa, v 0.30
///   (the paper's values); allowable static contact pressure 4.2 GPa for
///   ball contacts, ISO 76:2006 (static load rating of rolling bearings).
/// - `silicon-carbide`: sintered SiC, E 410 GPa, v 0.14 (the paper's values;
///   e.g. Munro, J. Phys. Chem. Ref. Data 26 (1997) 1195).
/// - `tungsten-carbide`: WC with 6 % Co, E 620 GPa, v 0.22 (Ashby, *Materials
///   Selection in Mechanical Design*, 4th ed., tables of engineering ceramics).
/// - `silicon-nitride`: bearing-grade hot-isostatically-pressed Si3N4, E 310 GPa,
///   v 0.27 (ASTM F2094, typical values).
/// - `alumina`: 99.5 % Al2O3, E 370 GPa, v 0.22 (Munro, J. Am. Ceram. Soc. 80
///   (1997) 1919).
/// - `sapphire`: single-crystal Al2O3 taken as isotropic, E 345 GPa, v 0.29
///   (Dobrovinskaya et al., *Sapphire*, Springer 2009; the true modulus varies
///   with orientation, so treat results for sapphire as approximate).
///
/// The ceramics carry no allowable pressure: their contact strength depends on
/// grade and surface finish; give `allowable_pressure` in the scene file.
/// No built-in material carries an allowable shear stress (no cited value is
/// at hand); give `allowable_shear_stress` in the scene file.
const BUILTIN: &[(&str, f64, f64, Option<f64>)] = &[
    ("steel", 210e9, 0.30, Some(4.2e9)),
    ("silicon-carbide", 410e9, 0.14, None),
    ("tungsten-carbide", 620e9, 0.22, None),
    ("silicon-nitride", 310e9, 0.27, None),
    ("alumina", 370e9, 0.22, None),
    ("sapphire", 345e9, 0.29, None),
];

impl Material {
    /// A material with the given constants, validated.
    pub fn new(
        name: &str,
        youngs_modulus: f64,
        poisson_ratio: f64,
        allowable_pressure: Option<f64>,
    ) -> Result<Self, MaterialError> {
        let m = Material {
            name: name.to_string(),
            youngs_modulus,
            poisson_ratio,
            allowable_pressure,
            allowable_shear_stress: None,
        };
        m.validate()?;
        Ok(m)
    }

    /// This material with an allowable maximum shear stress [Pa], validated.
    pub fn with_allowable_shear_stress(self, tau: Option<f64>) -> Result<Self, MaterialError> {
        let m = Material {
            allowable_shear_stress: tau,
            ..self
        };
        m.validate()?;
        Ok(m)
    }

    /// Look a material up in the built-in table by its kebab-case name.
    pub fn builtin(name: &str) -> Result<Self, MaterialError> {
        BUILTIN
            .iter()
            .find(|(n, ..)| *n == name)
            .map(|&(n, e, v, p)| Material {
                name: n.to_string(),
                youngs_modulus: e,
                poisson_ratio: v,
                allowable_pressure: p,
                allowable_shear_stress: None,
            })
            .ok_or_else(|| MaterialError::Unknown {
                name: name.to_string(),
                known: builtin_names().join(", "),
            })
    }

    /// Check that the constants are physical: E > 0, -1 < v < 0.5, p_allow > 0.
    pub fn validate(&self) -> Result<(), MaterialError> {
        let bad = |field, value, reason| MaterialError::Invalid {
            name: self.name.clone(),
            field,
            value,
            reason,
        };
        if !(self.youngs_modulus.is_finite() && self.youngs_modulus > 0.0) {
            return Err(bad(
                "youngs_modulus",
                self.youngs_modulus,
                "must be a positive number of pascals",
            ));
        }
        if !(self.poisson_ratio > -1.0 && self.poisson_ratio < 0.5) {
            return Err(bad(
                "poisson_ratio",
                self.poisson_ratio,
                "must lie in (-1, 0.5)",
            ));
        }
        if let Some(p) = self.allowable_pressure
            && !(p.is_finite() && p > 0.0)
        {
            return Err(bad(
                "allowable_pressure",
                p,
                "must be a positive number of pascals",
            ));
        }
        if let Some(t) = self.allowable_shear_stress
            && !(t.is_finite() && t > 0.0)
        {
            return Err(bad(
                "allowable_shear_stress",
                t,
                "must be a positive number of pascals",
            ));
        }
        Ok(())
    }

    /// Shear modulus G = E / (2 (1 + v)).
    pub fn shear_modulus(&self) -> f64 {
        self.youngs_modulus / (2.0 * (1.0 + self.poisson_ratio))
    }
}

/// Names of the built-in materials.
pub fn builtin_names() -> Vec<&'static str> {
    BUILTIN.iter().map(|(n, ..)| *n).collect()
}

/// Effective (contact) modulus E* of a pair: 1/E* = (1-v1^2)/E1 + (1-v2^2)/E2.
pub fn effective_modulus(m1: &Material, m2: &Material) -> f64 {
    let c = |m: &Material| (1.0 - m.poisson_ratio * m.poisson_ratio) / m.youngs_modulus;
    1.0 / (c(m1) + c(m2))
}

/// Effective tangential modulus G* of a pair: 1/G* = (2-v1)/G1 + (2-v2)/G2
/// (Mindlin 1949; Johnson 1985 eq. 7.29).
pub fn effective_shear_modulus(m1: &Material, m2: &Material) -> f64 {
    let c = |m: &Material| (2.0 - m.poisson_ratio) / m.shear_modulus();
    1.0 / (c(m1) + c(m2))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steel_pair_moduli_match_hand_values() {
        let s = Material::builtin("steel").unwrap();
        // E* = E / (2 (1 - v^2)) for identical materials.
        let e_star = 210e9 / (2.0 * (1.0 - 0.09));
        assert!((effective_modulus(&s, &s) / e_star - 1.0).abs() < 1e-15);
        // G* = G / (2 (2 - v)), G = E / 2.6.
        let g_star = (210e9 / 2.6) / (2.0 * 1.7);
        assert!((effective_shear_modulus(&s, &s) / g_star - 1.0).abs() < 1e-15);
        // 4 G*/E* for steel/steel is ~0.82 (MODEL.md section 3).
        let ratio = 4.0 * g_star / e_star;
        assert!((ratio - 0.8235).abs() < 1e-3, "{ratio}");
    }

    #[test]
    fn unknown_and_invalid_materials_are_errors() {
        let e = Material::builtin("unobtainium").unwrap_err();
        assert!(e.to_string().contains("unobtainium") && e.to_string().contains("steel"));
        assert!(Material::new("x", -1.0, 0.3, None).is_err());
        assert!(Material::new("x", 1e9, 0.5, None).is_err());
        assert!(Material::new("x", 1e9, 0.3, Some(0.0)).is_err());
        assert!(Material::new("x", f64::NAN, 0.3, None).is_err());
        let ok = Material::new("x", 1e9, 0.3, None).unwrap();
        assert!(ok.clone().with_allowable_shear_stress(Some(-1.0)).is_err());
        assert!(
            ok.clone()
                .with_allowable_shear_stress(Some(f64::NAN))
                .is_err()
        );
        assert!(ok.with_allowable_shear_stress(Some(1e9)).is_ok());
        for n in builtin_names() {
            Material::builtin(n).unwrap().validate().unwrap();
        }
    }
}
