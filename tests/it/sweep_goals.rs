//! A sweep's front on the objectives the designer picks, among the designs
//! that meet the constraints (issue 44, item 2): checked against the
//! definition of dominance on the JSON's own numbers, and drawn in those
//! objectives.

use crate::common::{kinrepro, scene};

/// sigma_x at the centre [m], k_min [N/m], SF_p of a design (None: not evaluated).
fn values(d: &serde_json::Value) -> Option<(f64, f64, f64)> {
    let s = d["points"][0]["sigma"]["x_nm"].as_f64()? * 1e-9;
    Some((
        s,
        d["principal_stiffness_n_per_m"][0].as_f64()?,
        d["min_pressure_safety_factor"].as_f64()?,
    ))
}

#[test]
fn the_front_holds_exactly_the_non_dominated_designs_that_meet_the_constraints() {
    let dir = tempfile::tempdir().unwrap();
    let s = scene("01_maxwell_vgroove_steel.toml");
    let out = dir.path().join("out");
    let args = [
        "sweep",
        s.to_str().unwrap(),
        "--set",
        "preload.force=5:40:4",
        "--set",
        "coupling.opening_angle_deg=60:140:5",
        "--objective",
        "sigma:centre:x:min",
        "--objective",
        "k_min:max",
        "--constraint",
        "sf_p>=5",
        "--samples",
        "10",
        "--format",
        "json",
        "--out",
        out.to_str().unwrap(),
    ];
    let (ok, json, err) = kinrepro(&args);
    assert!(ok, "{err}");
    let r: serde_json::Value = serde_json::from_str(&json).unwrap();
    let designs = r["designs"].as_array().unwrap();
    let feasible: Vec<(f64, f64)> =
        designs.iter().filter_map(values).filter(|v| v.2 >= 5.0).map(|v| (v.0, v.1)).collect();
    let dominated = |a: (f64, f64)| {
        feasible.iter().any(|b| b.0 <= a.0 && b.1 >= a.1 && (b.0 < a.0 || b.1 > a.1))
    };
    let (mut front, mut off) = (0, 0);
    for d in designs {
        let broken: Vec<&str> = d["broken_constraints"]
            .as_array()
            .map_or(Vec::new(), |b| b.iter().map(|x| x.as_str().unwrap()).collect());
        let on = d["pareto"].as_bool().unwrap();
        let Some(v) = values(d) else {
            assert!(!on, "a design not evaluated is on the front");
            continue;
        };
        assert_eq!(v.2 < 5.0, broken == ["sf_p>=5"], "design {}: {broken:?}", d["index"]);
        if v.2 < 5.0 {
            assert!(!on, "a design breaking sf_p>=5 is on the front");
            off += 1;
        } else {
            assert_eq!(on, !dominated((v.0, v.1)), "design {}", d["index"]);
            front += on as usize;
        }
    }
    assert!(front >= 2 && off >= 1, "front {front}, infeasible {off}");
    // Drawn in its objectives, the designs that break a constraint as crosses.
    let svg = std::fs::read_to_string(out.join("sweep_pareto.svg")).unwrap();
    assert!(svg.contains("front: sigma:centre:x:min and k_min:max"));
    assert!(svg.contains("sigma:centre:x:min [nm]") && svg.contains("k_min:max [N/µm]"));
    let text: String = svg.split_whitespace().collect();
    let labels = (0..designs.len()).filter(|i| text.contains(&format!(">#{i}<"))).count();
    assert_eq!(labels, front, "one label per front design");
}

#[test]
fn a_sweep_goal_that_cannot_be_read_is_refused() {
    let s = scene("01_maxwell_vgroove_steel.toml");
    let base = ["sweep", s.to_str().unwrap(), "--set", "preload.force=5,10", "--samples", "4"];
    for (args, says) in [
        (["--objective", "coupling.diameter:max"], "not among those varied"),
        (["--constraint", "sigma:centre:q<=1e-9"], "neither a DOF"),
        (["--objective", "sigma:centre:x:least"], "OUTPUT:min or OUTPUT:max"),
    ] {
        let (ok, _, err) = kinrepro(&[&base[..], &args[..]].concat());
        assert!(!ok && err.contains(says), "{args:?}: {err}");
    }
}
