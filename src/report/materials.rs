//! `kinrepro materials`: the built-in materials ([`crate::material::BUILTIN`])
//! with their constants and the source of each value, as a table (GPa,
//! MPa, kg/m^3), CSV or JSON (SI units).

use std::fmt::Write;

use serde::Serialize;

use crate::material::{BUILTIN, BuiltinMaterial};
use crate::report::study_text::csv_field;
use crate::study::provenance::{SCHEMA_VERSION, VERSION};

/// Header of `kinrepro materials --format csv` (SI units).
pub const MATERIALS_HEADER: &str = "kinrepro_version,name,description,youngs_modulus_pa,poisson_ratio,density_kg_per_m3,allowable_pressure_pa,source_elastic,source_density,source_allowable_pressure";

/// The JSON document of `kinrepro materials --format json`.
#[derive(Debug, Clone, Serialize)]
pub struct MaterialsDoc {
    pub kinrepro_version: &'static str,
    pub schema_version: u32,
    /// One entry per built-in material, SI units (`youngs_modulus` in Pa,
    /// `density` in kg/m^3, `allowable_pressure` in Pa or null).
    pub materials: &'static [BuiltinMaterial],
}

/// The JSON document.
pub fn materials_doc() -> MaterialsDoc {
    MaterialsDoc {
        kinrepro_version: VERSION,
        schema_version: SCHEMA_VERSION,
        materials: BUILTIN,
    }
}

/// CSV, one row per material, SI units; an empty allowable pressure where
/// none is built in. Numbers in Rust's shortest round-trip form, so that
/// they read back exactly.
pub fn materials_csv() -> String {
    let mut s = format!("{MATERIALS_HEADER}\n");
    for m in BUILTIN {
        let _ = writeln!(
            s,
            "{VERSION},{},{},{:e},{},{},{},{},{},{}",
            csv_field(m.name),
            csv_field(m.description),
            m.youngs_modulus,
            m.poisson_ratio,
            m.density,
            m.allowable_pressure
                .map_or(String::new(), |p| format!("{p:e}")),
            csv_field(m.sources.elastic),
            csv_field(m.sources.density),
            csv_field(m.sources.allowable_pressure),
        );
    }
    s
}

/// The human table: constants in GPa, MPa and kg/m^3, then the sources.
pub fn materials_table() -> String {
    let mut s = format!(
        "kinrepro {VERSION}: built-in materials (use their names in scene files)\n\n{:<18} {:>8} {:>6} {:>15} {:>16}  description\n",
        "name", "E [GPa]", "nu", "density [kg/m3]", "p_allow [MPa]"
    );
    for m in BUILTIN {
        let p = m
            .allowable_pressure
            .map_or("-".to_string(), |p| format!("{:.0}", p / 1e6));
        let _ = writeln!(
            s,
            "{:<18} {:>8.0} {:>6.2} {:>15.0} {:>16}  {}",
            m.name,
            m.youngs_modulus / 1e9,
            m.poisson_ratio,
            m.density,
            p,
            m.description
        );
    }
    let _ = writeln!(s, "\nSources:");
    for m in BUILTIN {
        let _ = writeln!(s, "{}:", m.name);
        let _ = writeln!(s, "  E, nu:   {}", m.sources.elastic);
        let _ = writeln!(s, "  density: {}", m.sources.density);
        let _ = writeln!(s, "  p_allow: {}", m.sources.allowable_pressure);
    }
    let _ = writeln!(
        s,
        "\nNo built-in material carries an allowable shear stress; give allowable_shear_stress in the scene file."
    );
    s
}
