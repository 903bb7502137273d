//! Materials: elastic constants and thermal expansion, the built-in table
//! (`builtin`), and the effective moduli of a contact pair.
//!
//! Effective moduli (Johnson, *Contact Mechanics*, 1985, eq. 4.22 and §7.2):
//!
//! ```text
//! 1/E* = (1 - v1^2)/E1 + (1 - v2^2)/E2
//! 1/G* = (2 - v1)/G1 + (2 - v2)/G2,   G = E / (2 (1 + v))
//! ```

mod builtin;

use serde::{Deserialize, Serialize};
use thiserror::Error;

pub use builtin::{BUILTIN, BuiltinMaterial, MaterialSources};

/// The largest |thermal_expansion| accepted [1/K]: above every solid's
/// (polymers reach about 2e-4 /K); a value such as 23.6 is a coefficient
/// in 1e-6/K written without its exponent.
pub const MAX_THERMAL_EXPANSION: f64 = 1e-3;

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
    /// Mean linear coefficient of thermal expansion near 20 C [1/K], if
    /// known (every built-in material has one). Not serialised with the
    /// material: a scene with `[thermal]` carries the coefficients it
    /// applies (`scene::ThermalBodies`), so that a scene without one keeps
    /// its canonical form (the study fingerprint) whatever its materials'
    /// expansion.
    #[serde(skip)]
    pub thermal_expansion: Option<f64>,
}

/// A material was unknown or its constants are not physical.
#[derive(Debug, Clone, PartialEq, Error)]
pub enum MaterialError {
    #[error("unknown material `{name}` (built-in: {known})")]
    Unknown { name: String, known: String },
    #[error("material `{name}`: {field} = {value} is invalid: {reason}")]
    Invalid { name: String, field: &'static str, value: f64, reason: &'static str },
}

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
            thermal_expansion: None,
        };
        m.validate()?;
        Ok(m)
    }

    /// This material with a coefficient of thermal expansion [1/K], validated.
    pub fn with_thermal_expansion(self, alpha: Option<f64>) -> Result<Self, MaterialError> {
        let m = Material { thermal_expansion: alpha, ..self };
        m.validate()?;
        Ok(m)
    }

    /// This material with an allowable maximum shear stress [Pa], validated.
    pub fn with_allowable_shear_stress(self, tau: Option<f64>) -> Result<Self, MaterialError> {
        let m = Material { allowable_shear_stress: tau, ..self };
        m.validate()?;
        Ok(m)
    }

    /// Look a material up in the built-in table by its kebab-case name.
    pub fn builtin(name: &str) -> Result<Self, MaterialError> {
        BUILTIN
            .iter()
            .find(|b| b.name == name)
            .map(|b| Material {
                name: b.name.to_string(),
                youngs_modulus: b.youngs_modulus,
                poisson_ratio: b.poisson_ratio,
                allowable_pressure: b.allowable_pressure,
                allowable_shear_stress: None,
                thermal_expansion: Some(b.thermal_expansion),
            })
            .ok_or_else(|| MaterialError::Unknown {
                name: name.to_string(),
                known: builtin_names().join(", "),
            })
    }

    /// Check that the constants are physical: E > 0, -1 < v < 0.5,
    /// p_allow > 0, |alpha| <= [`MAX_THERMAL_EXPANSION`].
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
            return Err(bad("poisson_ratio", self.poisson_ratio, "must lie in (-1, 0.5)"));
        }
        for (field, v) in [
            ("allowable_pressure", self.allowable_pressure),
            ("allowable_shear_stress", self.allowable_shear_stress),
        ] {
            if let Some(v) = v
                && !(v.is_finite() && v > 0.0)
            {
                return Err(bad(field, v, "must be a positive number of pascals"));
            }
        }
        if let Some(a) = self.thermal_expansion
            && !(a.is_finite() && a.abs() <= MAX_THERMAL_EXPANSION)
        {
            return Err(bad(
                "thermal_expansion",
                a,
                "must be a linear expansion coefficient in 1/K of at most 1e-3 in size \
                 (steel: 1.2e-5; a value in 1e-6/K needs its exponent, 23.6e-6)",
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
    BUILTIN.iter().map(|b| b.name).collect()
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
