//! Acceptance tests: FE contact vs. Hertz for the kinrepro contact types.
//! Reference values are closed-form Hertz (Johnson 1985 ch. 4), never FE output.

use kinrepro::fe::{FeCase, FeError, MeshOptions, convergence_study, hertz, solve_case};
use kinrepro::material::{Material, effective_modulus};

fn e_star(m1: &str, m2: &str) -> f64 {
    effective_modulus(
        &Material::builtin(m1).unwrap(),
        &Material::builtin(m2).unwrap(),
    )
}

/// Normal load per contact of a 90° V coupling with six contacts under 20 N preload.
fn load() -> f64 {
    20.0 / (6.0 * std::f64::consts::FRAC_1_SQRT_2)
}

fn steel() -> f64 {
    e_star("steel", "steel")
}

fn sic() -> f64 {
    e_star("steel", "silicon-carbide")
}

/// The five validated pairings: (name, rx, ry, E*).
fn cases() -> Vec<(&'static str, FeCase)> {
    let f = load();
    let cyl_rx = 1.0 / (1.0 / 5e-3 + 1.0 / 2e-3); // across the 2 mm-radius pin
    let sph = 1.0 / (1.0 / 4e-3 + 1.0 / 3e-3);
    let mk = |rx, ry, e_star| FeCase {
        rx,
        ry,
        e_star,
        load: f,
    };
    vec![
        ("sphere-plane steel", mk(5e-3, 5e-3, steel())),
        ("sphere-cylinder steel", mk(cyl_rx, 5e-3, steel())),
        ("sphere-cylinder SiC", mk(cyl_rx, 5e-3, sic())),
        ("sphere-sphere steel", mk(sph, sph, steel())),
        ("sphere-sphere SiC", mk(sph, sph, sic())),
    ]
}

fn check_all(mesh: &MeshOptions, tol_approach: f64, tol_axes: f64) {
    for (name, c) in cases() {
        let h = hertz(c.rx, c.ry, c.e_star, c.load).unwrap();
        let r = solve_case(&c, mesh).unwrap();
        let ea = (r.approach / h.approach - 1.0).abs();
        assert!(ea < tol_approach, "{name}: approach error {ea}");
        for d in 0..2 {
            let es = (r.semi_axes[d] / h.semi_axes[d] - 1.0).abs();
            assert!(es < tol_axes, "{name}: semi-axis {d} error {es}");
        }
        assert!(r.dofs > 0 && r.seconds > 0.0 && r.element_size > 0.0);
        // Signorini: the contact pushes, never pulls (no tensile nodal pressure).
        assert!(
            r.min_pressure >= -1e-9 * r.peak_pressure && r.min_pressure <= r.peak_pressure,
            "{name}: least nodal pressure {} Pa",
            r.min_pressure
        );
    }
}

#[test]
fn coarse_mesh_within_5_percent() {
    check_all(&MeshOptions::coarse(), 0.05, 0.05);
}

#[test]
fn default_mesh_acceptance() {
    check_all(&MeshOptions::default(), 0.02, 0.05);
}

/// Circular contact against the explicit closed form `a = (3FR/4E*)^{1/3}`,
/// `δ = a²/R` (independent of the elliptic-integral code), along the whole
/// force–approach curve.
#[test]
fn sphere_plane_curve_follows_closed_form() {
    let (r, es) = (5e-3, steel());
    let c = FeCase {
        rx: r,
        ry: r,
        e_star: es,
        load: load(),
    };
    let res = solve_case(&c, &MeshOptions::coarse()).unwrap();
    assert_eq!(res.curve.len(), MeshOptions::coarse().curve_levels);
    for &(delta, f) in &res.curve {
        let a = (3.0 * f * r / (4.0 * es)).cbrt();
        assert!((delta / (a * a / r) - 1.0).abs() < 0.05, "F = {f}");
    }
    let a = (3.0 * c.load * r / (4.0 * es)).cbrt();
    let p0 = 3.0 * c.load / (2.0 * std::f64::consts::PI * a * a);
    assert!((res.peak_pressure / p0 - 1.0).abs() < 0.05);
}

#[test]
fn convergence_error_falls() {
    let (_, c) = cases()[1]; // sphere-cylinder steel (elliptical)
    let rows = convergence_study(&c, &[0.45, 0.3, 0.18]).unwrap();
    let err = |r: &kinrepro::fe::ConvergenceRow| {
        r.approach_error_rel
            .abs()
            .max(r.semi_axis_error_rel[0].abs())
            .max(r.semi_axis_error_rel[1].abs())
    };
    let (first, last) = (&rows[0], &rows[rows.len() - 1]);
    assert!(err(last) < err(first), "{rows:?}");
    assert!(err(last) < 0.02, "{rows:?}");
    assert!(last.dofs > first.dofs);
}

#[test]
fn bad_input_is_an_error() {
    let ok = FeCase {
        rx: 5e-3,
        ry: 5e-3,
        e_star: steel(),
        load: 1.0,
    };
    let m = MeshOptions::coarse();
    for bad in [
        FeCase { rx: -1.0, ..ok },
        FeCase { ry: 0.0, ..ok },
        FeCase { load: 0.0, ..ok },
        FeCase {
            e_star: f64::NAN,
            ..ok
        },
    ] {
        assert!(matches!(
            solve_case(&bad, &m),
            Err(FeError::InvalidInput(_))
        ));
    }
    let bad_mesh = MeshOptions {
        element_size_rel: -0.1,
        ..m
    };
    assert!(solve_case(&ok, &bad_mesh).is_err());
    assert!(convergence_study(&ok, &[0.0]).is_err());
}
