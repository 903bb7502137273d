//! The built-in materials: the coupling elements' (bearing steel and
//! ceramics) and the bodies' a designer mounts them in (aluminium,
//! stainless steel, Invar, titanium, granite, fused silica, Zerodur), each
//! value with its source.

use serde::Serialize;

/// Where the values of a built-in material come from: one citable handbook,
/// standard, paper or datasheet per value group.
#[derive(Debug, Clone, Copy, PartialEq, Serialize)]
pub struct MaterialSources {
    /// Source of Young's modulus and Poisson's ratio.
    pub elastic: &'static str,
    pub density: &'static str,
    /// Source of the allowable contact pressure, or why there is none.
    pub allowable_pressure: &'static str,
    /// Source of the coefficient of thermal expansion.
    pub thermal_expansion: &'static str,
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
    /// Mean linear coefficient of thermal expansion near 20 C [1/K].
    pub thermal_expansion: f64,
    pub sources: MaterialSources,
}

/// No allowable pressure is built in for the ceramics: their contact
/// strength depends on grade and surface finish.
const NO_CERAMIC_PRESSURE: &str = "none built in: the contact strength of a ceramic depends on grade and surface finish; give allowable_pressure in the scene file";

/// No allowable pressure is built in for the body materials: they carry
/// the hardened elements, not the contacts.
const NO_BODY_PRESSURE: &str = "none built in: the contact limit of a body material depends on its temper and yield strength (metals) or on surface finish and ball size (glasses, stone); give allowable_pressure in the scene file";

/// The built-in table. No built-in material carries an allowable shear
/// stress (no cited value is at hand); give `allowable_shear_stress` in the
/// scene file. Sapphire is anisotropic: its isotropic constants are
/// approximate.
///
/// `thermal_expansion` is the mean coefficient near 20 C (20-100 C where a
/// source gives that range), the one for a few kelvin about room
/// temperature. Ceramic data sheets quote means up to 500-1000 C, 20-35 %
/// above it (the coefficient of a ceramic rises with temperature): the
/// ceramics here carry the near-room-temperature value, each source
/// naming the data-sheet figure beside it.
pub const BUILTIN: &[BuiltinMaterial] = &[
    BuiltinMaterial {
        name: "steel",
        description: "hardened bearing steel 100Cr6 / AISI 52100",
        youngs_modulus: 210e9,
        poisson_ratio: 0.30,
        density: 7810.0,
        allowable_pressure: Some(4.2e9),
        thermal_expansion: 11.4e-6,
        sources: MaterialSources {
            elastic: "AISI 52100 / 100Cr6 datasheets give E 190-210 GPa, v 0.27-0.30 (e.g. AZoM, 'AISI 52100 Alloy Steel (UNS G52986)'); E 210 GPa and v 0.30 are the top of that range and the design values for steel of EN 1993-1-1:2005, 3.2.6",
            density: "AISI 52100 datasheet (e.g. ASM / MatWeb 'AISI 52100 Steel'): 7.81 g/cm^3",
            allowable_pressure: "ISO 76:2006 (static load ratings of rolling bearings): 4200 MPa for ball contacts",
            thermal_expansion: "Lucefin technical card 100Cr6 / 1.3505 (EN ISO 683-17): 11.4e-6 /K, mean 20-100 C (Carter Bearings lists 11.9e-6 /K for 52100)",
        },
    },
    BuiltinMaterial {
        name: "silicon-carbide",
        description: "sintered alpha-SiC",
        youngs_modulus: 410e9,
        poisson_ratio: 0.14,
        density: 3160.0,
        allowable_pressure: None,
        thermal_expansion: 3.4e-6,
        sources: MaterialSources {
            elastic: "Saint-Gobain Hexoloy SA data sheet (pressureless-sintered alpha-SiC): E 410 GPa, v 0.14",
            density: "Munro, J. Phys. Chem. Ref. Data 26 (1997) 1195; NIST SRD 150 (sintered alpha-SiC): 3.16 g/cm^3",
            allowable_pressure: NO_CERAMIC_PRESSURE,
            thermal_expansion: "Li and Bradt, J. Mater. Sci. 21 (1986) 4366: alpha(T) = 3.19e-6 + 3.60e-9 T - 1.68e-12 T^2 /K (T in C), whose mean over 20-100 C is 3.4e-6 /K; the Hexoloy SA data sheet's 4.02e-6 /K is a mean from room temperature to 700 C",
        },
    },
    BuiltinMaterial {
        name: "tungsten-carbide",
        description: "cemented carbide WC with 6 % Co",
        youngs_modulus: 620e9,
        poisson_ratio: 0.22,
        density: 14900.0,
        allowable_pressure: None,
        thermal_expansion: 4.5e-6,
        sources: MaterialSources {
            elastic: "Ashby, Materials Selection in Mechanical Design, 4th ed. (2011), tables of engineering ceramics (WC-Co)",
            density: "Upadhyaya, Cemented Tungsten Carbides (Noyes, 1998), WC-6Co: 14.9 g/cm^3",
            allowable_pressure: NO_CERAMIC_PRESSURE,
            thermal_expansion: "WC-6Co cemented carbide: 4.3-4.9e-6 /K from room temperature to 200-400 C (Upadhyaya, Cemented Tungsten Carbides, Noyes 1998; the coefficient rises with the cobalt content); 4.5e-6 /K taken",
        },
    },
    BuiltinMaterial {
        name: "silicon-nitride",
        description: "bearing-grade hot-isostatically-pressed Si3N4 (ASTM F2094 class I)",
        youngs_modulus: 310e9,
        poisson_ratio: 0.27,
        density: 3160.0,
        allowable_pressure: None,
        thermal_expansion: 2.5e-6,
        sources: MaterialSources {
            elastic: "ASTM F2094 (silicon nitride bearing balls), typical values; NBD 200 datasheet (HIP Si3N4): E 310 GPa, v 0.27",
            density: "NBD 200 datasheet (HIP Si3N4 bearing balls): 3.16 g/cm^3",
            allowable_pressure: NO_CERAMIC_PRESSURE,
            thermal_expansion: "Cardarelli, Materials Handbook, 3rd ed. (Springer, 2018), silicon nitride at room temperature: 2.5e-6 /K (sintered Si3N4 data sheets quote about 3.1e-6 /K as means up to 1000 C)",
        },
    },
    BuiltinMaterial {
        name: "alumina",
        description: "99.5 % Al2O3",
        youngs_modulus: 370e9,
        poisson_ratio: 0.22,
        density: 3900.0,
        allowable_pressure: None,
        thermal_expansion: 5.6e-6,
        sources: MaterialSources {
            elastic: "CoorsTek AD-995 datasheet (99.5 % alumina): E 370 GPa, v 0.22 (Munro, J. Am. Ceram. Soc. 80 (1997) 1919 gives 416 GPa for fully dense alpha-Al2O3)",
            density: "CoorsTek AD-995 datasheet: 3.90 g/cm^3",
            allowable_pressure: NO_CERAMIC_PRESSURE,
            thermal_expansion: "dense alpha-Al2O3 near 20 C expands as the orientation average of its single crystal, (a_par + 2 a_perp)/3 = (6.66 + 2 x 5.0)/3 = 5.6e-6 /K at 323 K (see sapphire); 99.5 % alumina data sheets (CoorsTek AD-995) quote 7-8e-6 /K as means from 25 C to 200-1000 C",
        },
    },
    BuiltinMaterial {
        name: "sapphire",
        description: "single-crystal Al2O3 taken as isotropic (approximate)",
        youngs_modulus: 345e9,
        poisson_ratio: 0.29,
        density: 3980.0,
        allowable_pressure: None,
        thermal_expansion: 5.6e-6,
        sources: MaterialSources {
            elastic: "Dobrovinskaya, Lytvynov, Pishchik, Sapphire (Springer, 2009); the modulus varies with orientation",
            density: "Dobrovinskaya, Lytvynov, Pishchik, Sapphire (Springer, 2009): 3.98 g/cm^3",
            allowable_pressure: NO_CERAMIC_PRESSURE,
            thermal_expansion: "SPI Supplies sapphire data (323 K): 6.66e-6 /K parallel and 5.0e-6 /K perpendicular to the c axis; orientation average (a_par + 2 a_perp)/3 = 5.6e-6 /K (Roditi: 5.8e-6 /K, 20-50 C, 60 deg orientation)",
        },
    },
    BuiltinMaterial {
        name: "aluminium-6061",
        description: "aluminium alloy 6061-T6 (a body material)",
        youngs_modulus: 68.9e9,
        poisson_ratio: 0.33,
        density: 2700.0,
        allowable_pressure: None,
        thermal_expansion: 23.6e-6,
        sources: MaterialSources {
            elastic: "Aluminum Association typical values (ASM / MatWeb 'Aluminum 6061-T6; 6061-T651'): E 68.9 GPa (mean of tension and compression), v 0.33",
            density: "Aluminum Association typical values (ASM / MatWeb 'Aluminum 6061-T6'): 2.70 g/cm^3",
            allowable_pressure: NO_BODY_PRESSURE,
            thermal_expansion: "Aluminum Association typical values (ASM / MatWeb 'Aluminum 6061-T6; 6061-T651'): 23.6e-6 /K, mean 20-100 C",
        },
    },
    BuiltinMaterial {
        name: "stainless-304",
        description: "austenitic stainless steel AISI 304, annealed (a body material)",
        youngs_modulus: 193e9,
        poisson_ratio: 0.29,
        density: 8000.0,
        allowable_pressure: None,
        thermal_expansion: 17.3e-6,
        sources: MaterialSources {
            elastic: "ASM / MatWeb 'AISI Type 304 Stainless Steel': E 193-200 GPa (193 taken), v 0.29",
            density: "ASM / MatWeb 'AISI Type 304 Stainless Steel': 8.00 g/cm^3",
            allowable_pressure: NO_BODY_PRESSURE,
            thermal_expansion: "ASM / MatWeb 'AISI Type 304 Stainless Steel': 17.3e-6 /K, mean 0-100 C",
        },
    },
    BuiltinMaterial {
        name: "invar-36",
        description: "Fe-36Ni low-expansion alloy (Invar 36), annealed (a body material)",
        youngs_modulus: 141e9,
        poisson_ratio: 0.26,
        density: 8050.0,
        allowable_pressure: None,
        thermal_expansion: 1.18e-6,
        sources: MaterialSources {
            elastic: "Invar 36 technical data sheet (CarTech): E 20.5e6 psi = 141 GPa; v 0.26 (E 145 GPa with G 57 GPa, Imphy/CSM data, gives 0.27)",
            density: "CarTech Invar 36 alloy data sheet: specific gravity 8.05",
            allowable_pressure: NO_BODY_PRESSURE,
            thermal_expansion: "Invar 36 technical data sheet (CarTech): 1.18e-6 /K, mean 25-100 C, annealed; 1.2-1.9e-6 /K with heat treatment and ageing (Nilo 36: 1.5e-6 /K, 20-100 C; ASTM F1684: 1.2-2.7e-6 /K, 30-150 C): take the mill certificate's value where it matters",
        },
    },
    BuiltinMaterial {
        name: "ti-6al-4v",
        description: "titanium alloy Ti-6Al-4V (grade 5), annealed (a body material)",
        youngs_modulus: 113.8e9,
        poisson_ratio: 0.342,
        density: 4430.0,
        allowable_pressure: None,
        thermal_expansion: 8.6e-6,
        sources: MaterialSources {
            elastic: "ASM / MatWeb 'Titanium Ti-6Al-4V (Grade 5), Annealed' (Allvac data): E 113.8 GPa, v 0.342",
            density: "ASM / MatWeb 'Titanium Ti-6Al-4V (Grade 5), Annealed': 4.43 g/cm^3",
            allowable_pressure: NO_BODY_PRESSURE,
            thermal_expansion: "ASM / MatWeb 'Titanium Ti-6Al-4V (Grade 5)': 8.6e-6 /K, mean 20-100 C",
        },
    },
    BuiltinMaterial {
        name: "granite",
        description: "black granite (diabase / gabbro) of metrology bases and surface plates (a body material)",
        youngs_modulus: 65.5e9,
        poisson_ratio: 0.27,
        density: 3000.0,
        allowable_pressure: None,
        thermal_expansion: 5.5e-6,
        sources: MaterialSources {
            elastic: "L. S. Starrett (SME Manufacturing Engineering, 'Caring for granite surface plates'): black granite E 9.5e6 psi = 65.5 GPa; v 0.27 for gabbro / diabase (Christensen, J. Geophys. Res. 101 (1996) 3139)",
            density: "surface-plate dolerite about 190 lb/ft^3 = 3040 kg/m^3 against 160-170 lb/ft^3 for true granites (GMT, 'Granite for surface plates'); 3000 kg/m^3 taken",
            allowable_pressure: NO_BODY_PRESSURE,
            thermal_expansion: "black (diabase / gabbro) surface-plate stone: 4-7e-6 /K in surface-plate makers' data, 5.5e-6 /K taken (quartz-rich pink and grey granites: about 7-8e-6 /K); natural stone varies from quarry to quarry: take the plate maker's value where it matters",
        },
    },
    BuiltinMaterial {
        name: "fused-silica",
        description: "synthetic fused silica, Corning 7980 (a body material)",
        youngs_modulus: 72.7e9,
        poisson_ratio: 0.16,
        density: 2201.0,
        allowable_pressure: None,
        thermal_expansion: 0.52e-6,
        sources: MaterialSources {
            elastic: "Corning HPFS 7980 fused silica product information: E 72.7 GPa, v 0.16",
            density: "Corning HPFS 7980 fused silica product information: 2.201 g/cm^3",
            allowable_pressure: NO_BODY_PRESSURE,
            thermal_expansion: "Corning HPFS 7980: 0.52e-6 /K, mean 5-35 C (0.57e-6 /K over 0-200 C)",
        },
    },
    BuiltinMaterial {
        name: "zerodur",
        description: "Schott Zerodur glass ceramic, expansion class 0 (a body material)",
        youngs_modulus: 90.3e9,
        poisson_ratio: 0.243,
        density: 2530.0,
        allowable_pressure: None,
        thermal_expansion: 0.0,
        sources: MaterialSources {
            elastic: "Schott ZERODUR data sheet: E 90.3 GPa, v 0.243",
            density: "Schott ZERODUR data sheet: 2.53 g/cm^3",
            allowable_pressure: NO_BODY_PRESSURE,
            thermal_expansion: "Schott ZERODUR technical details: mean CTE 0-50 C of 0 +- 0.020e-6 /K (expansion class 0), 0 +- 0.050e-6 /K (class 1), 0 +- 0.100e-6 /K (class 2); the nominal 0 taken",
        },
    },
];
