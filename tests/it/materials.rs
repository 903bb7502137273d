//! `kinrepro materials`: every built-in material is listed, with values equal
//! to the library's (`Material::builtin`, what scenes use) and a source for
//! each value, in the CSV, the JSON and the table.

use crate::common::kinrepro;
use kinrepro::material::{Material, builtin_names};

/// RFC 4180 fields of one CSV line.
fn fields(line: &str) -> Vec<String> {
    let mut out = vec![String::new()];
    let mut quoted = false;
    let mut chars = line.chars().peekable();
    while let Some(c) = chars.next() {
        match c {
            '"' if quoted && chars.peek() == Some(&'"') => {
                chars.next();
                out.last_mut().unwrap().push('"');
            }
            '"' => quoted = !quoted,
            ',' if !quoted => out.push(String::new()),
            c => out.last_mut().unwrap().push(c),
        }
    }
    out
}

/// A source must name something: at least a few words, not a placeholder.
fn is_source(s: &str) -> bool {
    s.split_whitespace().count() >= 3 && !s.to_lowercase().contains("todo")
}

#[test]
fn csv_lists_every_builtin_with_library_values_and_sources() {
    let (ok, out, err) = kinrepro(&["materials", "--format", "csv"]);
    assert!(ok, "{err}");
    let mut lines = out.lines();
    let header = fields(lines.next().unwrap());
    assert_eq!(
        header,
        [
            "kinrepro_version",
            "name",
            "description",
            "youngs_modulus_pa",
            "poisson_ratio",
            "density_kg_per_m3",
            "allowable_pressure_pa",
            "source_elastic",
            "source_density",
            "source_allowable_pressure",
            "thermal_expansion_per_k",
            "source_thermal_expansion"
        ]
    );
    let rows: Vec<Vec<String>> = lines.map(fields).collect();
    let names: Vec<&str> = rows.iter().map(|r| r[1].as_str()).collect();
    assert_eq!(names, builtin_names());
    for r in &rows {
        assert_eq!(r.len(), header.len(), "{r:?}");
        assert_eq!(r[0], env!("CARGO_PKG_VERSION"));
        let m = Material::builtin(&r[1]).unwrap();
        assert_eq!(r[3].parse::<f64>().unwrap(), m.youngs_modulus, "{}", r[1]);
        assert_eq!(r[4].parse::<f64>().unwrap(), m.poisson_ratio, "{}", r[1]);
        let p = (!r[6].is_empty()).then(|| r[6].parse::<f64>().unwrap());
        assert_eq!(p, m.allowable_pressure, "{}", r[1]);
        // Solids denser than water and lighter than osmium.
        let rho: f64 = r[5].parse().unwrap();
        assert!(rho > 1000.0 && rho < 22_600.0, "{}: density {rho}", r[1]);
        assert_eq!(Some(r[10].parse::<f64>().unwrap()), m.thermal_expansion, "{}", r[1]);
        // Every solid expands by less than 1e-4 /K near room temperature
        // (aluminium 2.4e-5); Zerodur's nominal 0 is the one at zero.
        let alpha: f64 = r[10].parse().unwrap();
        assert!((0.0..1e-4).contains(&alpha), "{}: alpha {alpha}", r[1]);
        for (k, what) in
            [(7, "elastic"), (8, "density"), (9, "allowable pressure"), (11, "thermal expansion")]
        {
            assert!(is_source(&r[k]), "{}: no source for the {what} value: {:?}", r[1], r[k]);
        }
    }
}

#[test]
fn json_and_table_agree_with_the_library() {
    let (ok, out, err) = kinrepro(&["materials", "--format", "json"]);
    assert!(ok, "{err}");
    let doc: serde_json::Value = serde_json::from_str(&out).unwrap();
    assert_eq!(doc["kinrepro_version"], env!("CARGO_PKG_VERSION"));
    let list = doc["materials"].as_array().unwrap();
    assert_eq!(list.len(), builtin_names().len());
    for m in list {
        let name = m["name"].as_str().unwrap();
        let lib = Material::builtin(name).unwrap();
        assert_eq!(m["youngs_modulus"].as_f64().unwrap(), lib.youngs_modulus);
        assert_eq!(m["poisson_ratio"].as_f64().unwrap(), lib.poisson_ratio);
        assert_eq!(m["allowable_pressure"].as_f64(), lib.allowable_pressure);
        assert_eq!(m["thermal_expansion"].as_f64(), lib.thermal_expansion);
        for k in ["elastic", "density", "allowable_pressure", "thermal_expansion"] {
            assert!(is_source(m["sources"][k].as_str().unwrap()), "{name}: {k}");
        }
    }
    let (ok, table, _) = kinrepro(&["materials"]);
    assert!(ok);
    assert!(table.starts_with(&format!("kinrepro {}", env!("CARGO_PKG_VERSION"))));
    assert!(table.contains("E [GPa]") && table.contains("p_allow [MPa]"));
    for name in builtin_names() {
        let lib = Material::builtin(name).unwrap();
        let row = table
            .lines()
            .find(|l| l.split_whitespace().next() == Some(name))
            .unwrap_or_else(|| panic!("{name} not in the table"));
        let cols: Vec<&str> = row.split_whitespace().collect();
        // E in GPa and alpha in 1e-6/K, as the table rounds them.
        let e: f64 = cols[1].parse().unwrap();
        assert!((e - lib.youngs_modulus / 1e9).abs() <= 0.05 + 1e-9, "{name}: E {e}");
        let alpha: f64 = cols[5].parse().unwrap();
        let lib_alpha = lib.thermal_expansion.unwrap() * 1e6;
        assert!((alpha - lib_alpha).abs() <= 0.005 + 1e-9, "{name}: alpha {alpha}");
        assert!(table.contains(&format!("{name}:\n  E, nu:")), "sources of {name}");
    }
}
