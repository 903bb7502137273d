//! `kinrepro sweep` against scaling laws of the physics (scene 01, every
//! groove contact slides from the first increment, so the contact forces
//! are fixed by statics and only the Hertz/Mindlin compliances set the
//! displacements): delta = (9 F^2 / (16 E*^2 R))^(1/3) (Johnson 1985,
//! eq. 4.23) and k_t = 8 G* a with a = (3 F R / (4 E*))^(1/3). The same
//! study seed at every design point makes each law hold sample by sample,
//! so few samples suffice.

use crate::common;

use kinrepro::explore::run::{run, study_plan};
use kinrepro::explore::{DesignKind, SweepSpec};
use kinrepro::explore::{DesignReport, SweepReport};
use kinrepro::study::{Shard, StudyOptions, Varied};

fn scene01() -> String {
    std::fs::read_to_string(common::scene("01_maxwell_vgroove_steel.toml")).unwrap()
}

fn sweep(text: &str, sets: &[&str], samples: usize) -> SweepReport {
    let (scene, base) = kinrepro::error::parse_scene(text, "scene01").unwrap();
    let sets: Vec<String> = sets.iter().map(|s| s.to_string()).collect();
    let spec = SweepSpec::new("scene01", text, &sets, DesignKind::Grid).unwrap();
    let opts =
        StudyOptions { samples: Some(samples), vary: vec![Varied::Friction], ..Default::default() };
    let plan = study_plan(scene, base, &opts).unwrap();
    run(&spec, &plan, Shard::whole(), (None, &Default::default()), &|| {}).unwrap()
}

fn number(d: &DesignReport, field: &str) -> f64 {
    match d.values[field] {
        kinrepro::explore::SweptValue::Number(x) => x,
        _ => panic!("{field} is not a number"),
    }
}

/// Largest |sigma_k(design) / sigma_k(reference) / law - 1| over every DOF
/// and evaluation point.
fn worst(d: &DesignReport, reference: &DesignReport, law: f64) -> f64 {
    assert_eq!(d.status, "ok");
    d.points
        .iter()
        .zip(&reference.points)
        .flat_map(|(p, q)| {
            let (s, r) = (p.sigma.values(), q.sigma.values());
            (0..6).map(move |k| {
                assert!(s[k] > 0.0 && r[k] > 0.0, "{}: zero sigma", p.name);
                (s[k] / r[k] / law - 1.0).abs()
            })
        })
        .fold(0.0, f64::max)
}

#[test]
fn sigma_follows_preload_to_the_two_thirds() {
    let r = sweep(&scene01(), &["preload.force=5,10,20,40"], 10);
    let reference = &r.designs[2];
    assert_eq!(number(reference, "preload.force"), 20.0);
    for d in &r.designs {
        let ratio = number(d, "preload.force") / 20.0;
        let law = ratio.powf(2.0 / 3.0);
        let w = worst(d, reference, law);
        assert!(w < 0.01, "F = {}: off F^(2/3) by {w}", number(d, "preload.force"));
        // The nominal approach follows the same Hertz law.
        let a = d.nominal_approach_m.unwrap() / reference.nominal_approach_m.unwrap();
        assert!((a / law - 1.0).abs() < 0.01, "approach ratio {a} vs {law}");
        // k ~ F^(1/3), p0 ~ F^(1/3): a trade-off, every design is on the front.
        assert_eq!(d.pareto, Some(true));
    }
}

#[test]
fn sigma_follows_the_contact_modulus_to_minus_two_thirds() {
    // Ball and grooves of one custom material whose E is swept (nu fixed):
    // E* = 1 / (2 (1 - nu^2) / E) is proportional to E, and so is G*.
    let text = scene01()
        .replace("ball_material = \"steel\"", "ball_material = \"probe\"")
        .replace("groove_material = \"steel\"", "groove_material = \"probe\"")
        + "\n[[materials]]\nname = \"probe\"\nyoungs_modulus = 210e9\npoisson_ratio = 0.3\nallowable_pressure = 4.2e9\n";
    let r = sweep(&text, &["materials.probe.youngs_modulus=105e9,210e9,420e9"], 10);
    let e_star = |e: f64| 1.0 / (2.0 * (1.0 - 0.3f64.powi(2)) / e);
    let reference = &r.designs[1];
    for d in &r.designs {
        let e = number(d, "materials.probe.youngs_modulus");
        let law = (e_star(e) / e_star(210e9)).powf(-2.0 / 3.0);
        let w = worst(d, reference, law);
        assert!(w < 0.01, "E = {e}: off E*^(-2/3) by {w}");
        // Stiffer: lower sigma and higher k, but a higher p0: all on the front.
        assert_eq!(d.pareto, Some(true));
    }
}

#[test]
fn sigma_follows_the_ball_radius_to_minus_one_third_within_the_geometric_bound() {
    // Tolerance, derived: each contact point is c - R n (c the ball centre
    // on the circle of radius r_b, n the contact normal), so it moves along
    // its normal when R changes. The moments of the normal forces
    // (p x n = c x n) and the normal approach of a body rotation
    // (w . (p x n)) do not depend on R; R enters through the Hertz and
    // Mindlin laws (the R^(-1/3) law) and through the moment arms of the
    // tangential forces, p x t = c x t - R n x t, whose relative change is
    // at most dR / r_b. The relative deviation from R^(-1/3) is first order
    // in dR / r_b; the test takes dR / r_b itself as the tolerance (unit
    // coefficient), and checks that the deviation shrinks with r_b.
    let r =
        sweep(&scene01(), &["coupling.diameter=0.08,0.4", "coupling.ball_diameter=0.005,0.01"], 10);
    let mut devs = Vec::new();
    for pair in r.designs.chunks(2) {
        let (small, big) = (&pair[0], &pair[1]);
        let r_b = number(small, "coupling.diameter") / 2.0;
        let (r1, r2) = (
            number(small, "coupling.ball_diameter") / 2.0,
            number(big, "coupling.ball_diameter") / 2.0,
        );
        let law = (r1 / r2).powf(-1.0 / 3.0);
        let w = worst(small, big, law);
        let tol = (r2 - r1) / r_b;
        assert!(w < tol, "r_b = {r_b}: off R^(-1/3) by {w}, bound {tol}");
        // The nominal approach has no moment arm in it: exact Hertz.
        let a = small.nominal_approach_m.unwrap() / big.nominal_approach_m.unwrap();
        assert!((a / law - 1.0).abs() < 1e-6, "approach ratio {a} vs {law}");
        devs.push(w);
    }
    // Five times the circle: the geometric deviation falls at least 2x.
    assert!(devs[1] < devs[0] / 2.0, "{devs:?}");
}

#[test]
fn the_largest_ball_dominates_a_ball_sweep() {
    // Larger R: sigma ~ R^(-1/3) lower, k ~ R^(1/3) higher, p0 ~ R^(-2/3)
    // lower (safety factor higher): the largest ball beats every other.
    let r = sweep(&scene01(), &["coupling.ball_diameter=0.008,0.01,0.012"], 10);
    let marks: Vec<Option<bool>> = r.designs.iter().map(|d| d.pareto).collect();
    assert_eq!(marks, vec![Some(false), Some(false), Some(true)]);
}

#[test]
fn the_preload_law_holds_where_contacts_stick_and_contacts_are_elliptical() {
    // Scene 06 (Kelvin: the flat sticks) and scene 02 (pins: elliptical
    // Hertz contacts). The law still holds: stick or slip, Q <= mu P is
    // scale-free, and a stuck contact's tangential displacement dQ / k_t
    // scales as F / F^(1/3) = F^(2/3) like the normal approach (Mindlin
    // k_t ~ a ~ F^(1/3); an ellipse's eccentricity depends on the
    // curvatures alone), so the whole quasi-static path is self-similar.
    for name in ["06_kelvin_steel.toml", "02_maxwell_pins_steel.toml"] {
        let text = std::fs::read_to_string(common::scene(name)).unwrap();
        let r = sweep(&text, &["preload.force=10,20,40"], 10);
        let reference = &r.designs[1];
        for d in &r.designs {
            let law = (number(d, "preload.force") / 20.0).powf(2.0 / 3.0);
            let w = worst(d, reference, law);
            assert!(w < 0.01, "{name}: F = {}: off by {w}", number(d, "preload.force"));
        }
    }
}
