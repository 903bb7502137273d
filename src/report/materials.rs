//! `kinrepro materials`: the built-in materials ([`crate::material::BUILTIN`])
//! with their constants and the source of each value, as a table (GPa,
//! MPa, kg/m^3, 1e-6/K), CSV or JSON (SI units).

use std::fmt::Write;

use serde::Serialize;

use crate::material::{BUILTIN, BuiltinMaterial};
use crate::report::table::{Column, Table, cells};
use crate::study::provenance::{SCHEMA_VERSION, VERSION};

/// Header of `kinrepro materials --format csv` (SI units).
pub const MATERIALS_HEADER: &str = "kinrepro_version,name,description,youngs_modulus_pa,poisson_ratio,density_kg_per_m3,allowable_pressure_pa,source_elastic,source_density,source_allowable_pressure,thermal_expansion_per_k,source_thermal_expansion";

/// The JSON document of `kinrepro materials --format json`.
#[derive(Debug, Clone, Serialize)]
pub struct MaterialsDoc {
    pub kinrepro_version: &'static str,
    pub schema_version: u32,
    /// One entry per built-in material, SI units (`youngs_modulus` in Pa,
    /// `density` in kg/m^3, `allowable_pressure` in Pa or null,
    /// `thermal_expansion` in 1/K).
    pub materials: &'static [BuiltinMaterial],
}

/// The JSON document.
pub fn materials_doc() -> MaterialsDoc {
    MaterialsDoc { kinrepro_version: VERSION, schema_version: SCHEMA_VERSION, materials: BUILTIN }
}

/// CSV, one row per material, SI units; an empty allowable pressure where
/// none is built in. Numbers in Rust's shortest round-trip form, so that
/// they read back exactly.
pub fn materials_csv() -> String {
    let mut t = Table::of(MATERIALS_HEADER.split(',').map(Column::left));
    for m in BUILTIN {
        let e = format!("{:e}", m.youngs_modulus);
        let p = m.allowable_pressure.map_or(String::new(), |p| format!("{p:e}"));
        t.row(cells![
            VERSION,
            m.name,
            m.description,
            e,
            format!("{}", m.poisson_ratio),
            format!("{}", m.density),
            p,
            m.sources.elastic,
            m.sources.density,
            m.sources.allowable_pressure,
            format!("{:e}", m.thermal_expansion),
            m.sources.thermal_expansion,
        ]);
    }
    t.csv()
}

/// The human table: constants in GPa, MPa and kg/m^3, then the sources.
pub fn materials_table() -> String {
    let mut s =
        format!("kinrepro {VERSION}: built-in materials (use their names in scene files)\n\n");
    let mut t = Table::new(
        "<name; >E [GPa]:.1; >nu:.3; >density [kg/m3]:.0; >p_allow [MPa]:.0; >alpha [1e-6/K]:.2; <description",
    );
    for m in BUILTIN {
        t.row(cells![
            m.name,
            m.youngs_modulus / 1e9,
            m.poisson_ratio,
            m.density,
            m.allowable_pressure.map(|p| p / 1e6),
            m.thermal_expansion * 1e6,
            m.description,
        ]);
    }
    s += &t.text();
    s += "\nSources:\n";
    for m in BUILTIN {
        let _ = writeln!(s, "{}:", m.name);
        let _ = writeln!(s, "  E, nu:   {}", m.sources.elastic);
        let _ = writeln!(s, "  density: {}", m.sources.density);
        let _ = writeln!(s, "  p_allow: {}", m.sources.allowable_pressure);
        let _ = writeln!(s, "  alpha:   {}", m.sources.thermal_expansion);
    }
    s += "\nNo built-in material carries an allowable shear stress; give allowable_shear_stress in the scene file.\n";
    s
}
