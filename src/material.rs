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
    Invalid { name: String, field: &'static str, value: f64, reason: &'static str },
}

/// Where the values of a built-in material come from: one citable handbook,
/// standard, paper or datasheet per value group.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MaterialSources {
    /// Source of Young's modulus and Poisson's ratio.
    pub elastic: &'static str,
    pub density: &'static str,
    /// Source of the allowable contact pressure, or why there is none.
    pub allowable_pressure: &'static str,
}

/// A built-in material: its constants (SI) and their sources.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct BuiltinMaterial {
    /// Kebab-case name, as in scene files.
    pub name: &'static str,
    /// What exactly the entry stands for (grade).
    pub description: &'static str,
    /// Young's modulus E [Pa].
    pub youngs_modulus: f64,
    /// Poisson's ratio v [-].
    pub poisson_ratio: f64,
    /// Density [kg/m^3] (listed for reference; the dynamic solver takes its
    /// masses from `[dynamics]` or its own default).
    pub density: f64,
    /// Allowable peak Hertz contact pressure [Pa], if a cited value exists.
    pub allowable_pressure: Option<f64>,
    pub sources: MaterialSources,
}

/// No allowable pressure is built in for the ceramics: their contact
/// strength depends on grade and surface finish.
const NO_CERAMIC_PRESSURE: &str = "none built in: the contact strength of a ceramic depends on grade and surface finish; give allowable_pressure in the scene file";

/// The built-in table. No built-in material carries an allowable shear
/// stress (no cited value is at hand); give `allowable_shear_stress` in the
/// scene file. Sapphire is anisotropic: its isotropic constants are
/// approximate.
pub const BUILTIN: &[BuiltinMaterial] = &[
    BuiltinMaterial {
        name: "steel",
        description: "hardened bearing steel 100Cr6 / AISI 52100",
        youngs_modulus: 210e9,
        poisson_ratio: 0.30,
        density: 7810.0,
        allowable_pressure: Some(4.2e9),
        sources: MaterialSources {
            elastic: "AISI 52100 / 100Cr6 datasheets give E 190-210 GPa, v 0.27-0.30 (e.g. AZoM, 'AISI 52100 Alloy Steel (UNS G52986)'); E 210 GPa and v 0.30 are the top of that range and the design values for steel of EN 1993-1-1:2005, 3.2.6",
            density: "AISI 52100 datasheet (e.g. ASM / MatWeb 'AISI 52100 Steel'): 7.81 g/cm^3",
            allowable_pressure: "ISO 76:2006 (static load ratings of rolling bearings): 4200 MPa for ball contacts",
        },
    },
    BuiltinMaterial {
        name: "silicon-carbide",
        description: "sintered alpha-SiC",
        youngs_modulus: 410e9,
        poisson_ratio: 0.14,
        density: 3160.0,
        allowable_pressure: None,
        sources: MaterialSources {
            elastic: "Saint-Gobain Hexoloy SA data sheet (pressureless-sintered alpha-SiC): E 410 GPa, v 0.14",
            density: "Munro, J. Phys. Chem. Ref. Data 26 (1997) 1195; NIST SRD 150 (sintered alpha-SiC): 3.16 g/cm^3",
            allowable_pressure: NO_CERAMIC_PRESSURE,
        },
    },
    BuiltinMaterial {
        name: "tungsten-carbide",
        description: "cemented carbide WC with 6 % Co",
        youngs_modulus: 620e9,
        poisson_ratio: 0.22,
        density: 14900.0,
        allowable_pressure: None,
        sources: MaterialSources {
            elastic: "Ashby, Materials Selection in Mechanical Design, 4th ed. (2011), tables of engineering ceramics (WC-Co)",
            density: "Upadhyaya, Cemented Tungsten Carbides (Noyes, 1998), WC-6Co: 14.9 g/cm^3",
            allowable_pressure: NO_CERAMIC_PRESSURE,
        },
    },
    BuiltinMaterial {
        name: "silicon-nitride",
        description: "bearing-grade hot-isostatically-pressed Si3N4 (ASTM F2094 class I)",
        youngs_modulus: 310e9,
        poisson_ratio: 0.27,
        density: 3160.0,
        allowable_pressure: None,
        sources: MaterialSources {
            elastic: "ASTM F2094 (silicon nitride bearing balls), typical values; NBD 200 datasheet (HIP Si3N4): E 310 GPa, v 0.27",
            density: "NBD 200 datasheet (HIP Si3N4 bearing balls): 3.16 g/cm^3",
            allowable_pressure: NO_CERAMIC_PRESSURE,
        },
    },
    BuiltinMaterial {
        name: "alumina",
        description: "99.5 % Al2O3",
        youngs_modulus: 370e9,
        poisson_ratio: 0.22,
        density: 3900.0,
        allowable_pressure: None,
        sources: MaterialSources {
            elastic: "CoorsTek AD-995 datasheet (99.5 % alumina): E 370 GPa, v 0.22 (Munro, J. Am. Ceram. Soc. 80 (1997) 1919 gives 416 GPa for fully dense alpha-Al2O3)",
            density: "CoorsTek AD-995 datasheet: 3.90 g/cm^3",
            allowable_pressure: NO_CERAMIC_PRESSURE,
        },
    },
    BuiltinMaterial {
        name: "sapphire",
        description: "single-crystal Al2O3 taken as isotropic (approximate)",
        youngs_modulus: 345e9,
        poisson_ratio: 0.29,
        density: 3980.0,
        allowable_pressure: None,
        sources: MaterialSources {
            elastic: "Dobrovinskaya, Lytvynov, Pishchik, Sapphire (Springer, 2009); the modulus varies with orientation",
            density: "Dobrovinskaya, Lytvynov, Pishchik, Sapphire (Springer, 2009): 3.98 g/cm^3",
            allowable_pressure: NO_CERAMIC_PRESSURE,
        },
    },
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
