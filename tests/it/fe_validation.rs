//! Acceptance tests: FE contact vs. Hertz for the kinrepro contact types.
//! Reference values are closed-form Hertz (Johnson 1985 ch. 4), never FE output.

use crate::common;

use kinrepro::fe::contact::ContactModel;
use kinrepro::fe::{FeCase, FeError, Gap, MeshOptions, convergence_study, hertz, solve_case};
use kinrepro::material::{Material, effective_modulus};

fn e_star(m1: &str, m2: &str) -> f64 {
    effective_modulus(&Material::builtin(m1).unwrap(), &Material::builtin(m2).unwrap())
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
    let mk = |rx, ry, e_star| FeCase { rx, ry, e_star, load: f, gap: Gap::Quadratic };
    vec![
        ("sphere-plane steel", mk(5e-3, 5e-3, steel())),
        ("sphere-cylinder steel", mk(cyl_rx, 5e-3, steel())),
        ("sphere-cylinder SiC", mk(cyl_rx, 5e-3, sic())),
        ("sphere-sphere steel", mk(sph, sph, steel())),
        ("sphere-sphere SiC", mk(sph, sph, sic())),
    ]
}

/// The relative errors (approach, semi-axes) of one solve against Hertz.
fn errors(c: &FeCase, mesh: &MeshOptions) -> ([f64; 3], kinrepro::fe::FeResult) {
    let h = hertz(c.rx, c.ry, c.e_star, c.load).unwrap();
    let r = solve_case(c, mesh).unwrap();
    let e = [
        r.approach / h.approach - 1.0,
        r.semi_axes[0] / h.semi_axes[0] - 1.0,
        r.semi_axes[1] / h.semi_axes[1] - 1.0,
    ];
    (e, r)
}

fn check(name: &str, c: &FeCase, mesh: &MeshOptions, tol_approach: f64, tol_axes: f64) -> [f64; 3] {
    let (e, r) = errors(c, mesh);
    assert!(e[0].abs() < tol_approach, "{name}: approach error {}", e[0]);
    for d in 0..2 {
        assert!(e[1 + d].abs() < tol_axes, "{name}: semi-axis {d} error {}", e[1 + d]);
    }
    assert!(r.dofs > 0 && r.seconds > 0.0 && r.element_size > 0.0);
    // Signorini: the contact pushes, never pulls (no tensile nodal pressure).
    // The active set only converges with every active force > -1e-12 F,
    // so this guards the pressure recovery (force / tributary area, all
    // weights positive for 27-node elements); the release of tension
    // nodes is tested in active_set_meets_signorini_and_hertz_on_a_boussinesq_grid.
    assert!(
        r.min_pressure >= -1e-9 * r.peak_pressure && r.min_pressure <= r.peak_pressure,
        "{name}: least nodal pressure {} Pa",
        r.min_pressure
    );
    e
}

/// All five pairings on the coarse mesh, and the scaling law that makes
/// three of them redundant on a finer one. The mesh is graded in units of
/// the Hertz semi-axes and Hertz's problem is self-similar: with x = a ξ,
/// displacements in units of a²/R and F ∝ E* a³/R, two pairings with the
/// same ratio R_x/R_y are the same dimensionless problem whatever R and E*
/// (Johnson 1985 §4.2). So the three circular pairings share one relative
/// error, and so do the two sphere-cylinder ones, to round-off.
#[test]
fn coarse_mesh_within_5_percent_and_errors_follow_the_scaling_law() {
    let mesh = MeshOptions::coarse();
    let errs: Vec<[f64; 3]> =
        cases().iter().map(|(name, c)| check(name, c, &mesh, 0.05, 0.05)).collect();
    // cases(): 0 sphere-plane, 1-2 sphere-cylinder steel/SiC, 3-4 sphere-sphere steel/SiC.
    for (a, b) in [(0, 3), (0, 4), (1, 2)] {
        for (k, (ea, eb)) in errs[a].iter().zip(&errs[b]).enumerate() {
            assert!((ea - eb).abs() < 1e-9, "pairings {a} and {b}, error {k}: {ea} vs {eb}");
        }
    }
    // The scaling is not vacuous: the elliptical problem's error differs.
    assert!((errs[0][0] - errs[1][0]).abs() > 1e-6, "{errs:?}");
}

/// The default mesh within 2 % (approach) and 5 % (semi-axes) of Hertz, with
/// the Signorini conditions, for the circular problem; the elliptical one at
/// the default mesh is the last level of `convergence_error_falls` (within
/// 2 %), and the other pairings follow by the scaling law tested above.
#[test]
fn default_mesh_acceptance() {
    let (name, c) = cases()[0];
    check(name, &c, &MeshOptions::default(), 0.02, 0.05);
}

/// Circular contact against the explicit closed form `a = (3FR/4E*)^{1/3}`,
/// `δ = a²/R` (independent of the elliptic-integral code), along the whole
/// force–approach curve.
#[test]
fn sphere_plane_curve_follows_closed_form() {
    let (r, es) = (5e-3, steel());
    let c = FeCase { rx: r, ry: r, e_star: es, load: load(), gap: Gap::Quadratic };
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
    let rows = convergence_study(&c, &[0.45, 0.18]).unwrap();
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
    // The last level is the default mesh (default_mesh_acceptance relies on it).
    assert_eq!(last.element_size_over_a, MeshOptions::default().element_size_rel);
}

#[test]
fn bad_input_is_an_error() {
    let ok = FeCase { rx: 5e-3, ry: 5e-3, e_star: steel(), load: 1.0, gap: Gap::Quadratic };
    let m = MeshOptions::coarse();
    for bad in [
        FeCase { rx: -1.0, ..ok },
        FeCase { ry: 0.0, ..ok },
        FeCase { load: 0.0, ..ok },
        FeCase { e_star: f64::NAN, ..ok },
    ] {
        assert!(matches!(solve_case(&bad, &m), Err(FeError::InvalidInput(_))));
    }
    let bad_mesh = MeshOptions { element_size_rel: -0.1, ..m };
    assert!(solve_case(&ok, &bad_mesh).is_err());
    assert!(convergence_study(&ok, &[0.0]).is_err());
}

/// A condensed contact problem built here, independently of the FE mesh: a
/// sphere (radius `r`) on an elastic half-space (`e_star`), quarter model on
/// an `n` x `n` grid of square patches of side `s` centred at
/// ((i + 1/2) s, (j + 1/2) s), each patch's load mirrored into the other
/// three quadrants. Compliance from Boussinesq's point load (Johnson 1985
/// ch. 3): w = F / (pi E* d) between patches, and at a patch's own centre
/// the uniformly loaded square, w = p / (pi E*) int 1/r dA
/// = 4 ln(1 + sqrt 2) F / (pi E* s). Gap profile h = (x^2 + y^2) / (2 r).
fn boussinesq_grid(r: f64, e_star: f64, s: f64, n: usize) -> (ContactModel, Vec<(f64, f64)>) {
    let pos: Vec<(f64, f64)> =
        (0..n * n).map(|k| (((k % n) as f64 + 0.5) * s, ((k / n) as f64 + 0.5) * s)).collect();
    let own = 4.0 * (1.0 + 2f64.sqrt()).ln() / (std::f64::consts::PI * e_star * s);
    let c = faer::Mat::<f64>::from_fn(n * n, n * n, |i, j| {
        let (xi, yi) = pos[i];
        let (xj, yj) = pos[j];
        [(1.0, 1.0), (-1.0, 1.0), (1.0, -1.0), (-1.0, -1.0)]
            .iter()
            .map(|&(sx, sy)| {
                let d = (xi - sx * xj).hypot(yi - sy * yj);
                if d < 1e-3 * s { own } else { 1.0 / (std::f64::consts::PI * e_star * d) }
            })
            .sum()
    });
    let model = ContactModel {
        h: pos.iter().map(|&(x, y)| (x * x + y * y) / (2.0 * r)).collect(),
        c,
        w_unit: vec![0.0; n * n],
        h_other: Vec::new(),
        c_other: faer::Mat::zeros(0, n * n),
        w_unit_other: Vec::new(),
        on_zone_edge: (0..n * n).map(|k| k % n == n - 1 || k / n == n - 1).collect(),
    };
    (model, pos)
}

/// The active-set solver of the FE check on a problem it did not build, from
/// two starts: its own guess, and every candidate within 1.5 a in contact (so
/// that the outer ones must be released from tension). Checked node by node:
/// the Signorini conditions (f >= 0, g >= 0, f g = 0); then the load balance
/// 4 sum f = F and the result against Hertz (approach, contact area, and
/// p(r) = p0 sqrt(1 - r^2/a^2) where a patch lies well inside the edge,
/// r < 0.8 a) within the allowance of a grid of 8 patches per contact radius
/// (measured: approach 0.5 %, area 3.5 %, pressure 0.8 %).
#[test]
fn active_set_meets_signorini_and_hertz_on_a_boussinesq_grid() {
    let (r, e_star, load) = (5e-3, common::E_STAR_STEEL, 8.0);
    let (a, delta) = common::hertz_circle(load, r, e_star);
    let p0 = 3.0 * load / (2.0 * std::f64::consts::PI * a * a);
    let s = a / 8.0;
    let n = 16;
    let (model, pos) = boussinesq_grid(r, e_star, s, n);
    let wide: Vec<bool> = pos.iter().map(|&(x, y)| x.hypot(y) < 1.5 * a).collect();
    for init in [None, Some(wide.as_slice())] {
        let st = model.solve(load, delta, init).unwrap();
        let fmax = st.forces.iter().cloned().fold(0.0, f64::max);
        for (k, (&f, &g)) in st.forces.iter().zip(&st.gaps).enumerate() {
            assert!(f >= -1e-9 * fmax, "init {:?}: node {k} pulls: {f} N", init.is_some());
            assert!(g >= -1e-9 * delta, "init {:?}: node {k} penetrates: {g} m", init.is_some());
            assert!(f.max(0.0) * g.max(0.0) <= 1e-9 * fmax * delta, "node {k}: f {f}, g {g}");
        }
        let total = 4.0 * st.forces.iter().sum::<f64>();
        assert!((total / load - 1.0).abs() < 1e-9, "{total} N vs {load} N");
        assert!((st.approach / delta - 1.0).abs() < 0.02, "{} vs {delta}", st.approach);
        // Contact area: the loaded patches cover pi a^2 / 4 of the quarter.
        let loaded = st.forces.iter().filter(|&&f| f > 0.0).count() as f64 * s * s;
        let area = std::f64::consts::PI * a * a / 4.0;
        assert!((loaded / area - 1.0).abs() < 0.1, "area {loaded} vs {area}");
        // Pressure inside r < 0.8 a, where the patch average follows p(r).
        for (k, &(x, y)) in pos.iter().enumerate() {
            let rr = x.hypot(y) / a;
            if rr < 0.8 {
                let hertz = p0 * (1.0 - rr * rr).sqrt();
                let p = st.forces[k] / (s * s);
                assert!((p / hertz - 1.0).abs() < 0.03, "r/a {rr}: {p} Pa vs Hertz {hertz} Pa");
            }
        }
    }
}
