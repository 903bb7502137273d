//! Calibration of the friction spread (issue 15): recovery of a known
//! spread from synthetic measurements (coverage of the 90 % interval over
//! repetitions), transfer of the calibration to other designs against
//! direct studies, and a misfit that no spread can produce.
//!
//! Synthetic measurements are drawn here, independently of the
//! calibration code: mu_s,k = mu0 + spread (2u - 1) with u from a ChaCha
//! stream of the test's own seed, one seating per cycle, plus Gaussian
//! sensor noise (Box-Muller), written as a measurement CSV and parsed.

use crate::common;

use kinrepro::calibrate::file::Parameter;
use kinrepro::calibrate::fit::{fit_at, observed};
use kinrepro::calibrate::grid::ModelGrid;
use kinrepro::calibrate::joint::{JointModel, estimate};
use kinrepro::calibrate::likelihood::{GoodnessOfFit, goodness_of_fit};
use kinrepro::calibrate::model::{MODEL_SAMPLES, MODEL_SEED, StudySpec};
use kinrepro::calibrate::params::{Param, with_values};
use kinrepro::calibrate::{Measurement, calibrate, predict};
use kinrepro::solve::Solver;
use kinrepro::study::options::Settings;
use kinrepro::study::runner::{evaluate_rows, run_variant};
use kinrepro::study::{StudyOptions, StudyPlan, Variant};
use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;

const TRUE_SPREAD: f64 = 0.08;
/// Sensor noise: 1 nm on translations, 20 nrad on rotations.
const NOISE: [f64; 6] = [1e-9, 1e-9, 1e-9, 20e-9, 20e-9, 20e-9];

/// The model `v` with its friction spread replaced by `spread`.
fn with_spread(v: &Variant, spread: f64) -> Variant {
    with_values(v, &[Param::Spread], &[spread])
}

/// The Monte Carlo model study of scene `name` (the calibration's
/// defaults): its plan, whose variant is the scene as given.
fn model_plan(name: &str) -> StudyPlan {
    common::model_plan(name, MODEL_SAMPLES, MODEL_SEED)
}

/// `cycles` re-seatings of point 0 at `spread`, with sensor noise [SI].
fn synthetic(v: &Variant, spread: f64, cycles: usize, rng: &mut ChaCha8Rng) -> Vec<[f64; 6]> {
    let v = with_spread(v, spread);
    let dims = v.coupling.contacts.len();
    let rows: Vec<(usize, Vec<f64>)> =
        (0..cycles).map(|i| (i, (0..dims).map(|_| rng.random::<f64>()).collect())).collect();
    let settings = StudyOptions::monte_carlo(cycles, 1, Solver::QuasiStatic).settings().unwrap();
    let recs = evaluate_rows(&settings, &v, rows, &|| {}).unwrap();
    recs.iter().map(|r| std::array::from_fn(|j| r.outputs[j] + NOISE[j] * gaussian(rng))).collect()
}

/// Standard normal by Box-Muller.
fn gaussian(rng: &mut ChaCha8Rng) -> f64 {
    let u1: f64 = 1.0 - rng.random::<f64>();
    let u2: f64 = rng.random::<f64>();
    (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
}

/// The cycles as a measurement file (nm, nrad), with the noise as metadata.
fn csv(rows: &[[f64; 6]]) -> String {
    let mut s = String::from(
        "# rig: synthetic\n# noise: x=1nm, y=1nm, z=1nm, phi_x=20nrad, phi_y=20nrad, phi_z=20nrad\n",
    );
    s.push_str("x_nm,y_nm,z_nm,phi_x_nrad,phi_y_nrad,phi_z_nrad\n");
    for r in rows {
        let cells: Vec<String> = r.iter().map(|v| format!("{:.6}", v * 1e9)).collect();
        s.push_str(&cells.join(","));
        s.push('\n');
    }
    s
}

/// A summary file (dof,unit,sigma,cycles) of a cycles measurement.
fn summary(m: &Measurement) -> String {
    let mut s = String::from("dof,unit,sigma,cycles\n");
    for (j, (&d, sg)) in m.dofs.iter().zip(m.sigma()).enumerate() {
        let dof = kinrepro::dof::Dof::ALL[d];
        s += &format!("{},{},{},{}\n", dof.name(), dof.unit(), sg * 1e9, m.cycles()[j]);
    }
    s
}

fn noise_var() -> Vec<f64> {
    NOISE.iter().map(|v| v * v).collect()
}

/// The reference spread of the fixed-model fits below (scene 02's own).
const S_REF: f64 = 0.05;

/// The spread alone fitted with one model study at [`S_REF`] (scaled by
/// s^2: the linear law the calibration relies on, used here over 0.05 ->
/// 0.08, without the calibration's second pass at the estimate): the
/// engine's estimate, interval and goodness of fit, the fourth moments
/// from the reference study's samples scaled to the estimate.
struct FixedModel {
    grid: ModelGrid,
    samples: Vec<Vec<f64>>,
}

impl FixedModel {
    fn new(plan: &StudyPlan) -> Self {
        let dofs = [0, 1, 2, 3, 4, 5];
        let spec = StudySpec { plan, point: 0, dofs: &dofs };
        let grid = ModelGrid::build(&spec, &[], &[], S_REF).unwrap();
        let samples = spec.run(&with_spread(spec.base(), S_REF)).unwrap().samples_of(&dofs);
        FixedModel { grid, samples }
    }

    fn fit(&self, v: &Variant, m: &Measurement) -> (Parameter, GoodnessOfFit) {
        let obs = observed(m);
        let jm = JointModel::new(&obs, &self.grid, &[Param::Spread], v, &noise_var());
        let (u_hat, l_max) = estimate(&jm);
        let s = jm.theta(&u_hat)[0];
        let x: Vec<Vec<f64>> =
            (self.samples.iter()).map(|r| r.iter().map(|v| v * s / S_REF).collect()).collect();
        let fit = fit_at(&jm, &u_hat, l_max, &x);
        let gof = goodness_of_fit(&obs, &jm.sigma(&[s]).unwrap(), 1);
        (fit.parameters[0].clone(), gof)
    }
}

#[test]
fn recovery_coverage_of_the_spread_interval() {
    let plan = model_plan("02_maxwell_pins_steel.toml");
    let c = &plan.variants[0];
    let model = FixedModel::new(&plan);
    let mut rng = ChaCha8Rng::seed_from_u64(2026);
    let reps = 120;
    let (mut covered, mut abs_err, mut bias) = (0, 0.0, 0.0);
    let (mut flagged, mut covered_summary) = (0, 0);
    for _ in 0..reps {
        let rows = synthetic(c, TRUE_SPREAD, 50, &mut rng);
        let m = Measurement::parse(&csv(&rows), "synthetic.csv", None).unwrap();
        let (f, gof) = model.fit(c, &m);
        flagged += usize::from(!gof.ok);
        // The same cycles as a summary file (sigma per DOF, DOFs taken as independent).
        let sm = Measurement::parse(&summary(&m), "summary.csv", None).unwrap();
        let (fs, _) = model.fit(c, &sm);
        covered_summary += usize::from(fs.low <= TRUE_SPREAD && TRUE_SPREAD <= fs.high);
        assert!(f.low < f.estimate && f.estimate < f.high);
        covered += usize::from(f.low <= TRUE_SPREAD && TRUE_SPREAD <= f.high);
        abs_err += (f.estimate / TRUE_SPREAD - 1.0).abs() / reps as f64;
        bias += (f.estimate / TRUE_SPREAD - 1.0) / reps as f64;
    }
    let coverage = covered as f64 / reps as f64;
    let cov_summary = covered_summary as f64 / reps as f64;
    let false_alarms = flagged as f64 / reps as f64;
    eprintln!(
        "coverage {coverage:.3} (summary file {cov_summary:.3}), mean |error| {abs_err:.4}, mean error {bias:.4}, misfit flags on model data {false_alarms:.3}"
    );
    assert!((0.80..=0.97).contains(&cov_summary), "summary coverage {cov_summary}");
    // The goodness-of-fit test at p < 0.01 flags data drawn from the model rarely.
    assert!(false_alarms <= 0.05, "false misfit flags {false_alarms}");
    assert!((0.80..=0.97).contains(&coverage), "coverage {coverage}");
    assert!(abs_err < 0.05, "mean absolute relative error {abs_err}");
}

#[test]
fn transfer_to_scenes_01_and_04_contains_direct_studies() {
    let plan = model_plan("02_maxwell_pins_steel.toml");
    let c02 = &plan.variants[0];
    let mut rng = ChaCha8Rng::seed_from_u64(31);
    let m = Measurement::parse(&csv(&synthetic(c02, TRUE_SPREAD, 50, &mut rng)), "syn02.csv", None)
        .unwrap();
    let opts = common::synthetic::calibrate_options(&["spread"]);
    let cal = calibrate(&c02.scene, &c02.coupling, &m, &opts).unwrap();
    let sp = cal.spread().expect("the spread is fitted");
    eprintln!("spread {} [{}, {}]", sp.estimate, sp.low, sp.high);
    assert!(cal.goodness_of_fit.ok);
    // The direct studies: at the true spread.
    assert_transfer(&cal, |c| with_spread(c, TRUE_SPREAD));
    // The calibrated design itself carries its measured values.
    let p = predict(
        &c02.scene,
        &c02.coupling,
        &cal,
        "calibration.json",
        (200, MODEL_SEED, Solver::QuasiStatic),
    )
    .unwrap();
    let (point, dofs) = p.measured.expect("scene 02 is the calibrated design");
    assert_eq!(point, "centre");
    assert_eq!(dofs.len(), 6);
}

/// The same with spread and mu_static calibrated jointly on data at
/// (0.08, 0.40): the prediction intervals, which carry the joint
/// uncertainty, contain sigma of direct 2000-sample studies of scenes 01
/// and 04 at the true pair (another seed).
#[test]
fn joint_transfer_to_scenes_01_and_04_contains_direct_studies() {
    let params = [Param::Spread, Param::MuStatic];
    let truth = [TRUE_SPREAD, 0.40];
    let plan = model_plan("02_maxwell_pins_steel.toml");
    let c02 = &plan.variants[0];
    let mut rng = ChaCha8Rng::seed_from_u64(33);
    let rows = synthetic(&with_values(c02, &[Param::MuStatic], &[0.40]), TRUE_SPREAD, 50, &mut rng);
    let m = Measurement::parse(&csv(&rows), "syn02.csv", None).unwrap();
    let opts = common::synthetic::calibrate_options(&["spread", "mu_static"]);
    let cal = calibrate(&c02.scene, &c02.coupling, &m, &opts).unwrap();
    eprintln!("{:?}", cal.parameters);
    assert!(cal.goodness_of_fit.ok);
    assert_transfer(&cal, |c| with_values(c, &params, &truth));
}

/// The prediction of `cal` for scenes 01 and 04, neither of them the
/// calibrated design, contains sigma of the direct study of `truth` applied
/// to each ([`assert_direct_inside`]).
fn assert_transfer(cal: &kinrepro::calibrate::Calibration, truth: impl Fn(&Variant) -> Variant) {
    for name in ["01_maxwell_vgroove_steel.toml", "04_maxwell_balls_steel.toml"] {
        let (scene, c) = common::load(name);
        let p = predict(
            &scene,
            &c,
            cal,
            "calibration.json",
            (MODEL_SAMPLES, MODEL_SEED, Solver::QuasiStatic),
        )
        .unwrap();
        assert!(p.measured.is_none(), "{name} is not the calibrated design");
        let direct = StudyPlan::new(
            vec![(scene, c)],
            &StudyOptions::monte_carlo(2000, 4242, Solver::QuasiStatic),
        )
        .unwrap();
        assert_direct_inside(name, &p, &direct.settings, &truth(&direct.variants[0]));
    }
}

/// sigma of a direct 2000-sample study of `direct` (point 0, seed 4242)
/// lies inside the prediction interval of `p` for every DOF.
fn assert_direct_inside(
    name: &str,
    p: &kinrepro::calibrate::Prediction,
    settings: &Settings,
    direct: &Variant,
) {
    let run = run_variant(settings, direct, &|| {}).unwrap();
    let pt = &p.variant.points[0];
    let (lo, hi) = (pt.sigma_ci90_low.unwrap().values(), pt.sigma_ci90_high.unwrap().values());
    for j in 0..6 {
        let v: Vec<f64> = run.records.iter().map(|r| r.outputs[j]).collect();
        let mean = v.iter().sum::<f64>() / v.len() as f64;
        let sd = (v.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (v.len() as f64 - 1.0))
            .sqrt()
            * 1e9;
        eprintln!("{name} dof {j}: direct {sd:.4} in [{:.4}, {:.4}]", lo[j], hi[j]);
        assert!(
            lo[j] <= sd && sd <= hi[j],
            "{name} dof {j}: direct sigma {sd} outside [{}, {}]",
            lo[j],
            hi[j]
        );
    }
}

#[test]
fn misfit_sigma_z_three_times_sigma_x_is_flagged() {
    let plan = model_plan("01_maxwell_vgroove_steel.toml");
    let c = &plan.variants[0];
    let model = FixedModel::new(&plan);
    let g = model.grid.at(&[]);
    let ratio = (g[(2, 2)] / g[(0, 0)]).sqrt();
    // The model's own ratio is far from 3: no spread can produce it.
    assert!(ratio < 1.0, "model sigma_z / sigma_x = {ratio}");
    let mut rng = ChaCha8Rng::seed_from_u64(5);
    let mut rows = synthetic(c, TRUE_SPREAD, 50, &mut rng);
    let sd = |j: usize, r: &[[f64; 6]]| {
        let m = r.iter().map(|x| x[j]).sum::<f64>() / r.len() as f64;
        (r.iter().map(|x| (x[j] - m).powi(2)).sum::<f64>() / (r.len() as f64 - 1.0)).sqrt()
    };
    let good = Measurement::parse(&csv(&rows), "good.csv", None).unwrap();
    let scale = 3.0 * sd(0, &rows) / sd(2, &rows);
    for r in &mut rows {
        r[2] *= scale;
    }
    let bad = Measurement::parse(&csv(&rows), "bad.csv", None).unwrap();
    let (g_good, g_bad) = (model.fit(c, &good).1, model.fit(c, &bad).1);
    eprintln!("p good {:?}, p bad {:?}", g_good.p_value, g_bad.p_value);
    assert!(g_good.ok, "data drawn from the model flagged: {g_good:?}");
    assert!(!g_bad.ok && g_bad.p_value.unwrap() < 1e-6, "misfit not flagged: {g_bad:?}");
}
