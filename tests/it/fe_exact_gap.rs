//! The FE's exact gap of two surfaces: its quadratic and quartic limits
//! (Taylor series of the closed forms), the vertical distance of the
//! surfaces built by parry's ray casts, its range, and FE solves with the
//! exact against the quadratic gap (coarse mesh); the conformity study's
//! search on a synthetic criterion and its report.

use kinrepro::assembly::geometry::parry_shape;
use kinrepro::contact::{ContactPair, ContactShape};
use kinrepro::fe::conformity::{ConformityRow, ConformityStudy, LIMIT, RATIOS, find_crossing};
use kinrepro::fe::pairs::fe_case;
use kinrepro::fe::{FeError, Gap, MeshOptions, hertz, solve_case};
use kinrepro::material::Material;
use kinrepro::scene::SurfaceGeometry;
use nalgebra::Vector3;
use parry3d_f64::math::{Pose, Vector};
use parry3d_f64::query::{Ray, RayCast};
use parry3d_f64::shape::Ball;

fn steel() -> Material {
    Material::builtin("steel").unwrap()
}

fn pair(shape: ContactShape, r1: f64, r2: Option<f64>) -> ContactPair {
    ContactPair::from_shape(shape, r1, r2, steel(), steel()).unwrap()
}

/// The pair's exact gap with the FE's radii [rx, ry] (rx <= ry).
fn exact(p: &ContactPair) -> (Gap, f64, f64) {
    let [rx, ry] = p.law().unwrap().hertz.radii;
    (Gap::exact(&p.curvature, rx, ry).unwrap(), rx, ry)
}

/// (shape, r1, r2, closed-form [R_x, R_y] in the FE's axes, closed-form
/// quartic term of the gap's Taylor series at (x, y)).
type Case = (ContactShape, f64, Option<f64>, [f64; 2], fn(f64, f64) -> f64);

fn cases() -> Vec<Case> {
    vec![
        // ball on a flat: R_x = R_y = r.
        (ContactShape::SpherePlane, 5e-3, None, [5e-3; 2], |x, y| {
            (x * x + y * y).powi(2) / (8.0 * 5e-3f64.powi(3))
        }),
        // ball on ball: 1/R = 1/r1 + 1/r2.
        (
            ContactShape::SphereSphere,
            4e-3,
            Some(3e-3),
            [1.0 / (250.0 + 1000.0 / 3.0); 2],
            |x, y| {
                let u = x * x + y * y;
                u * u / 8.0 * (1.0 / 4e-3f64.powi(3) + 1.0 / 3e-3f64.powi(3))
            },
        ),
        // ball in a spherical seat: 1/R = 1/r - 1/R_s.
        (ContactShape::SphereSeat, 4e-3, Some(5e-3), [1.0 / (250.0 - 200.0); 2], |x, y| {
            let u = x * x + y * y;
            u * u / 8.0 * (1.0 / 4e-3f64.powi(3) - 1.0 / 5e-3f64.powi(3))
        }),
        // ball on a pin of radius 2 mm: x across the pin (1/R_x = 1/r + 1/R_p), y along it.
        (ContactShape::SphereCylinder, 5e-3, Some(2e-3), [1.0 / (200.0 + 500.0), 5e-3], |x, y| {
            (x * x + y * y).powi(2) / (8.0 * 5e-3f64.powi(3)) + x.powi(4) / (8.0 * 2e-3f64.powi(3))
        }),
        // ball in a gothic-arch flank: x along the groove (R_x = r), y across
        // it (R_y = r R_g / (R_g - r)).
        (ContactShape::SphereGroove, 5e-3, Some(5.5e-3), [5e-3, 5e-3 * 5.5e-3 / 0.5e-3], |x, y| {
            (x * x + y * y).powi(2) / (8.0 * 5e-3f64.powi(3))
                - y.powi(4) / (8.0 * 5.5e-3f64.powi(3))
        }),
        // crossed pins at 90 degrees: the 2 mm pin curved along x, the 3 mm one along y.
        (ContactShape::CrossedCylinders, 3e-3, Some(2e-3), [2e-3, 3e-3], |x, y| {
            x.powi(4) / (8.0 * 2e-3f64.powi(3)) + y.powi(4) / (8.0 * 3e-3f64.powi(3))
        }),
    ]
}

/// h -> x^2/(2R_x) + y^2/(2R_y) + quartic + O(rho^6) as rho -> 0, with
/// R_x, R_y of the closed forms (Johnson eq. 4.2 by hand).
#[test]
fn exact_gap_tends_to_its_quadratic_and_quartic_limits() {
    for (shape, r1, r2, [rx, ry], quartic) in cases() {
        let p = pair(shape, r1, r2);
        let (gap, fx, fy) = exact(&p);
        assert!((fx / rx - 1.0).abs() < 1e-12 && (fy / ry - 1.0).abs() < 1e-12, "{shape:?}");
        let scale = r1.min(r2.unwrap_or(r1));
        for t in [1e-2, 1e-3] {
            for phi in [0.0, 0.7, std::f64::consts::FRAC_PI_2, 2.0f64] {
                let (x, y) = (t * scale * phi.cos(), t * scale * phi.sin());
                let h = gap.height(rx, ry, x, y).unwrap();
                let quad = x * x / (2.0 * rx) + y * y / (2.0 * ry);
                assert!((h / quad - 1.0).abs() < t * t, "{shape:?} t {t}: {h} vs {quad}");
                let rest = (h - quad) / quartic(x, y);
                assert!(
                    (rest - 1.0).abs() < (10.0 * t * t).max(1e-6),
                    "{shape:?} t {t} phi {phi}: quartic ratio {rest}"
                );
            }
        }
    }
}

/// The first hit of a ray from `origin` along `dir` on `shape` at `pose`.
fn hit(shape: &dyn RayCast, pose: &Pose, origin: [f64; 3], dir: f64, solid: bool) -> f64 {
    let ray = Ray::new(Vector::new(origin[0], origin[1], origin[2]), Vector::new(0.0, 0.0, dir));
    let t = shape.cast_ray(pose, &ray, 1.0, solid).expect("the ray hits");
    origin[2] + dir * t
}

/// The gap against the vertical distance of the two surfaces built by
/// parry: the ball's lower surface (a ball centred at z = r, hit from
/// below) minus body 2's upper surface (a convex body below z = 0 hit from
/// above; a concave one, whose centre lies above, hit from inside).
#[test]
fn exact_gap_is_the_vertical_distance_of_the_surfaces() {
    let v = |x: f64, y: f64, z: f64| Vector3::new(x, y, z);
    let r = 5e-3;
    let ball = Ball::new(r);
    let ball_pose = Pose::from_translation(Vector::new(0.0, 0.0, r));
    // (pair, body 2's surface, convex?, where a concave body's centre lies)
    let bodies = [
        (
            pair(ContactShape::SphereGroove, r, Some(5.5e-3)),
            SurfaceGeometry::ConcaveCylinder {
                axis_point: v(0.0, 0.0, 5.5e-3),
                direction: v(1.0, 0.0, 0.0),
                radius: 5.5e-3,
            },
            false,
            5.5e-3,
        ),
        (
            pair(ContactShape::SphereGroove, r, Some(5.01e-3)),
            SurfaceGeometry::ConcaveCylinder {
                axis_point: v(0.0, 0.0, 5.01e-3),
                direction: v(1.0, 0.0, 0.0),
                radius: 5.01e-3,
            },
            false,
            5.01e-3,
        ),
        (
            pair(ContactShape::SphereCylinder, r, Some(2e-3)),
            SurfaceGeometry::Cylinder {
                axis_point: v(0.0, 0.0, -2e-3),
                direction: v(0.0, 1.0, 0.0),
                radius: 2e-3,
            },
            true,
            0.0,
        ),
        (
            pair(ContactShape::SphereSphere, r, Some(3e-3)),
            SurfaceGeometry::Sphere { centre: v(0.0, 0.0, -3e-3), radius: 3e-3 },
            true,
            0.0,
        ),
        (
            pair(ContactShape::SphereSeat, r, Some(6e-3)),
            SurfaceGeometry::Sphere { centre: v(0.0, 0.0, 6e-3), radius: 6e-3 },
            false,
            6e-3,
        ),
    ];
    for (p, surface, convex, centre_z) in bodies {
        let (gap, rx, ry) = exact(&p);
        let (shape, pose) = parry_shape(&surface, &v(0.0, 0.0, r), 1.0);
        for (fx, fy) in [(0.05, 0.0), (0.0, 0.3), (0.4, 0.4), (-0.2, 0.7), (0.85, -0.3)] {
            // inside the footprints of both bodies (the pin's is |x| < 2 mm)
            let scale = if convex { r.min(p.curvature.radii2[0]) } else { r };
            let (x, y) = (fx * scale, fy * scale);
            let z1 = hit(&ball, &ball_pose, [x, y, -0.1], 1.0, true);
            let z2 = if convex {
                hit(&*shape, &pose, [x, y, 0.1], -1.0, true)
            } else {
                hit(&*shape, &pose, [x, y, centre_z], -1.0, false)
            };
            let h = gap.height(rx, ry, x, y).unwrap();
            // parry casts rays on balls in closed form, on cylinders and
            // capsules by its support-map (GJK) iteration, to about 1e-7.
            let tol = match surface {
                SurfaceGeometry::Sphere { .. } => 1e-9,
                _ => 1e-6,
            };
            assert!(
                (h - (z1 - z2)).abs() < tol * h + 1e-16,
                "{:?} at ({x}, {y}): {h} vs parry {}",
                p.shape,
                z1 - z2
            );
        }
    }
}

/// Outside the ball's footprint the exact gap is undefined: `None`, an
/// error naming the point, and a solve whose contact would reach past the
/// ball is an error before any factorisation, not a panic.
#[test]
fn exact_gap_outside_its_footprint_is_an_error() {
    let r = 5e-3;
    let p = pair(ContactShape::SphereGroove, r, Some(5.5e-3));
    let (gap, rx, ry) = exact(&p);
    assert!(gap.height(rx, ry, 0.0, 0.999 * r).is_some());
    assert!(gap.height(rx, ry, 0.61 * r, 0.8 * r).is_none());
    let e = gap.height_in_range(rx, ry, 0.0, 1.2 * r).unwrap_err();
    assert!(
        matches!(e, FeError::GapUndefined(_)) && e.to_string().contains("x^2 + y^2 < r^2"),
        "{e}"
    );
    // A ball on a flat whose Hertz radius a = (3 F r / 4 E*)^(1/3) exceeds r.
    let flat = pair(ContactShape::SpherePlane, r, None);
    let case = fe_case(&flat, 1e7, true).unwrap();
    let e_star = case.e_star;
    assert!((3.0 * 1e7 * r / (4.0 * e_star)).cbrt() > r);
    let err = solve_case(&case, &MeshOptions::coarse()).unwrap_err();
    assert!(matches!(err, FeError::GapUndefined(_)), "{err}");
    // Pins crossed at 60 degrees: their axes are not those of the ellipse.
    let mut crossed = pair(ContactShape::CrossedCylinders, 3e-3, Some(2e-3));
    crossed.curvature.angle = 60f64.to_radians();
    let [cx, cy] = crossed.law().unwrap().hertz.radii;
    assert!(matches!(Gap::exact(&crossed.curvature, cx, cy), Err(FeError::InvalidInput(_))));
}

/// A gothic arch far from conformity (R_g/r = 1.5, a/r = 0.016 at the
/// scene's 3.37 N): the exact gap differs from the quadratic one by about
/// 3/4 (a/r)^2 = 2e-4 at the contact edge, far below the coarse mesh's
/// error, and the two FE solves on the same mesh agree within 0.2 %.
#[test]
fn far_from_conformity_exact_and_quadratic_gaps_agree() {
    let p = pair(ContactShape::SphereGroove, 5e-3, Some(7.5e-3));
    let load = 3.3664;
    let mesh = MeshOptions::coarse();
    let fe = solve_case(&fe_case(&p, load, true).unwrap(), &mesh).unwrap();
    let fq = solve_case(&fe_case(&p, load, false).unwrap(), &mesh).unwrap();
    assert!((fe.approach / fq.approach - 1.0).abs() < 2e-3, "{} vs {}", fe.approach, fq.approach);
    for k in 0..2 {
        assert!((fe.semi_axes[k] / fq.semi_axes[k] - 1.0).abs() < 1e-2, "axis {k}");
    }
}

/// Close to conformity (R_g/r = 1.01 at 70 N: a/r about 0.2) the exact gap
/// exceeds the quadratic one everywhere (each convex sag grows faster than
/// its parabola and each concave one recedes faster, and the ball's
/// quartic term outweighs the larger groove's), so the indenter must go
/// deeper to carry the same load: a larger approach and no larger contact
/// across the groove. A rigid profile scaled by 1 + e needs (1 + e)^(1/3)
/// times the approach (delta ~ R^(-1/3)), so with e the largest excess of
/// the exact gap over the quadratic one in the Hertz ellipse (at its end
/// across the groove, by the closed form) the approach grows by at most
/// (1 + e)^(1/3) - 1.
#[test]
fn near_conformity_the_exact_gap_needs_a_larger_approach() {
    let (r, rg, load) = (5e-3, 5.05e-3, 70.0);
    let p = pair(ContactShape::SphereGroove, r, Some(rg));
    // Both gaps on one mesh: their ratio is what is tested, and it hardly
    // depends on the mesh (effect 0.0042 at 0.45 a, 0.0040 at the coarse
    // 0.3 a, against a bound of 0.0099), so the coarser mesh serves.
    let mesh = MeshOptions { element_size_rel: 0.45, ..MeshOptions::default() };
    let (ce, cq) = (fe_case(&p, load, true).unwrap(), fe_case(&p, load, false).unwrap());
    let hz = hertz(cq.rx, cq.ry, cq.e_star, load).unwrap();
    let a = hz.semi_axes[1]; // across the groove
    assert!(a / r > 0.15 && a / r < 0.3, "a/r = {}", a / r);
    let exact_edge = (r - (r * r - a * a).sqrt()) - (rg - (rg * rg - a * a).sqrt());
    let e = exact_edge / (a * a / (2.0 * cq.ry)) - 1.0;
    let fe = solve_case(&ce, &mesh).unwrap();
    let fq = solve_case(&cq, &mesh).unwrap();
    let effect = fe.approach / fq.approach - 1.0;
    assert!(effect > 0.0 && effect < (1.0 + e).cbrt() - 1.0, "effect {effect}, edge excess {e}");
    assert!(fe.semi_axes[1] <= fq.semi_axes[1] * (1.0 + 1e-12));
}

/// A row of the study with approach effect `g` (the rest zero).
fn row(ratio: f64, g: f64) -> ConformityRow {
    ConformityRow {
        groove_over_ball: ratio,
        groove_radius_m: ratio * 5e-3,
        conformity: 0.1,
        hertz_approach_m: 1e-7,
        hertz_semi_axes_m: [1e-5, 1e-4],
        approach_error_rel: g,
        semi_axes_error_rel: [0.0; 2],
        quadratic_approach_error_rel: 0.0,
        quadratic_semi_axes_error_rel: [0.0; 2],
        gap_effect_rel: [g, 0.0, -g],
        bisection: false,
        dofs: 1,
        seconds: 0.0,
    }
}

/// The search on a synthetic effect g = LIMIT (e*/e)^0.8, e = R_g/r - 1,
/// which crosses the limit at e* = 2e-4: the table ratios down to the
/// first over the limit, three bisections, and the crossing within 5 % in e.
#[test]
fn the_search_brackets_and_bisects_the_crossing() {
    let g = |q: f64| LIMIT * (2e-4 / (q - 1.0)).powf(0.8);
    let (rows, at) = find_crossing(&RATIOS, |q| Ok(row(q, g(q)))).unwrap();
    let first_over = RATIOS.iter().position(|&q| g(q) >= LIMIT).unwrap();
    assert_eq!(rows.len(), first_over + 1 + 3);
    assert_eq!(rows.iter().filter(|r| r.bisection).count(), 3);
    let found = at.unwrap() - 1.0;
    assert!((found / 2e-4 - 1.0).abs() < 0.05, "{found}");
    // never over the limit, or over it at the first ratio: no crossing.
    let (rows, at) = find_crossing(&RATIOS, |q| Ok(row(q, 1e-3))).unwrap();
    assert_eq!((rows.len(), at), (RATIOS.len(), None));
    let (rows, at) = find_crossing(&RATIOS, |q| Ok(row(q, 0.5))).unwrap();
    assert_eq!((rows.len(), at), (1, None));
}

/// The report says what the study cannot show and gives both ratios.
#[test]
fn the_conformity_report_states_its_limits_and_ratios() {
    let st = ConformityStudy {
        ball_radius_m: 5e-3,
        groove_radius_m: 5.5e-3,
        materials: ["steel".into(), "steel".into()],
        scenes: vec!["s.toml".into()],
        load_n: 3.0,
        rows: vec![row(1.5, 1e-4), row(1.0002, 0.03)],
        ratio_at_limit: Some(1.00025),
        conformity_at_limit: Some(0.33),
        warning_ratio: Some(1.004),
    };
    let text = kinrepro::report::contact::validate_hertz::conformity_table(&[st]);
    for needle in [
        "not where the half-space assumption",
        "R_g/r = 1.000250",
        "a/R_x = 0.330",
        "starts at R_g/r = 1.00400",
    ] {
        assert!(text.contains(needle), "{needle}:\n{text}");
    }
}
