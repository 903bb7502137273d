//! Unit tests of the calibration engine: grid weights, likelihood and goodness of fit, sandwich information, parameter lists.

mod grid {
    use kinrepro::calibrate::grid::*;

    /// Catmull-Rom with quadratic end ghosts reproduces any quadratic
    /// exactly, also in the end intervals; the weights sum to 1.
    #[test]
    fn weights_reproduce_quadratics() {
        let nodes: Vec<f64> = (0..6).map(|i| 0.1 + 0.14 * i as f64).collect();
        let f = |x: f64| 2.0 - 3.0 * x + 5.0 * x * x;
        for v in [0.1, 0.13, 0.2, 0.5, 0.77, 0.8] {
            let w = weights(&nodes, v);
            let sum: f64 = w.iter().sum();
            let interp: f64 = w.iter().zip(&nodes).map(|(w, &x)| w * f(x)).sum();
            assert!((sum - 1.0).abs() < 1e-12);
            assert!((interp - f(v)).abs() < 1e-12, "{v}: {interp} vs {}", f(v));
        }
    }
}

mod likelihood {
    use kinrepro::calibrate::likelihood::*;
    use nalgebra::DMatrix;
    use statrs::distribution::ContinuousCDF;

    #[test]
    fn wilks_threshold_and_p_values_match_closed_forms() {
        // chi^2_1(0.90) = z_0.95^2.
        assert!((wilks_threshold() - 1.644_853_626_951_472_2f64.powi(2)).abs() < 1e-13);
        // Summary of two DOFs against F = I with one fitted parameter: the
        // statistic is sum_j (1 - 1/(3 m)) m (r_j - ln r_j - 1), r_j = sigma_j^2,
        // on p - q = 1 degree of freedom, where P(X > x) = 2 (1 - Phi(sqrt x)).
        let obs = Observed::Sigmas { sigma: vec![1.2, 1.0], cycles: vec![31, 31] };
        let g = goodness_of_fit(&obs, &DMatrix::identity(2, 2), 1);
        let (m, r) = (30.0, 1.44f64);
        let want = (1.0 - 1.0 / (3.0 * m)) * m * (r - r.ln() - 1.0);
        assert_eq!(g.df, 1);
        assert!((g.statistic.unwrap() - want).abs() < 1e-12 * want);
        let phi = statrs::distribution::Normal::standard().cdf(want.sqrt());
        let p = g.p_value.unwrap();
        assert!((p - 2.0 * (1.0 - phi)).abs() < 1e-10 * p, "{p}");
        assert!(g.ok);
    }
}

mod information {
    use kinrepro::calibrate::grid::ModelGrid;
    use kinrepro::calibrate::information::*;
    use kinrepro::calibrate::joint::JointModel;
    use kinrepro::calibrate::joint::{estimate, profile_end};
    use kinrepro::calibrate::likelihood::Observed;
    use kinrepro::calibrate::likelihood::wilks_threshold;
    use kinrepro::calibrate::params::Param;
    use nalgebra::{DMatrix, DVector};
    use rand::{Rng, SeedableRng};

    /// Two DOFs, G(phi) = diag(1, phi), no noise: Sigma = diag(s^2, s^2 phi).
    /// With S = diag(a, b) from n cycles the maximum is s^2 = a, phi = b / a,
    /// and at any s, phi = b / s^2 fits the second DOF exactly, so the
    /// profile of s is the one-DOF curve (n - 1)(r - ln r - 1), r = a / s^2.
    fn separable<'a>(obs: &'a Observed, grid: &'a ModelGrid) -> JointModel<'a> {
        JointModel {
            obs,
            grid,
            params: vec![Param::Spread, Param::DynamicRatio],
            ranges: vec![(0.0, 0.5), (0.3, 1.0)],
            scale: Param::Spread,
            spread_fixed: 0.0,
            mu_fixed: 1.0,
            noise_var: vec![0.0, 0.0],
        }
    }

    fn grid() -> ModelGrid {
        let nodes: Vec<f64> = (0..4).map(|i| 0.3 + 0.7 * i as f64 / 3.0).collect();
        let g = nodes
            .iter()
            .map(|&phi| DMatrix::from_diagonal(&DVector::from_vec(vec![1.0, phi])))
            .collect();
        ModelGrid::from_parts(vec![Param::DynamicRatio], vec![nodes], g, 0.2)
    }

    /// Rows of two independent DOFs with variances (0.04, 0.024): normal or uniform.
    fn samples(n: usize, uniform: bool) -> Vec<Vec<f64>> {
        scaled_samples(n, uniform, &[0.2, 0.024f64.sqrt()])
    }

    /// Rows of independent DOFs with standard deviations `sd`: normal or uniform.
    fn scaled_samples(n: usize, uniform: bool, sd: &[f64]) -> Vec<Vec<f64>> {
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(11);
        let mut unit = || {
            if uniform {
                3f64.sqrt() * (2.0 * rng.random::<f64>() - 1.0)
            } else {
                let (u1, u2): (f64, f64) = (1.0 - rng.random::<f64>(), rng.random());
                (-2.0 * u1.ln()).sqrt() * (std::f64::consts::TAU * u2).cos()
            }
        };
        (0..n).map(|_| sd.iter().map(|s| s * unit()).collect()).collect()
    }

    /// The spread alone on one DOF, G = 1, no noise, S = 0.09 from 40
    /// cycles, as a cycles file and as a summary: the maximum is s^2 = S,
    /// the Wilks ends solve 39 (r - ln r - 1) = chi^2_1(0.90), r = S / s^2,
    /// the sandwich factor is 1 for normal and 2 / Var(u^2) = 2.5 for
    /// uniform scatter (unit-variance u), and the model error of ln s from
    /// N normal samples is sqrt(1 / (2 N)).
    #[test]
    fn one_parameter_closed_forms() {
        let grid = ModelGrid::from_parts(vec![], vec![], vec![DMatrix::identity(1, 1)], 0.3);
        for obs in [
            Observed::Covariance { s: DMatrix::from_element(1, 1, 0.09), n: 40 },
            Observed::Sigmas { sigma: vec![0.3], cycles: vec![40] },
        ] {
            let jm = JointModel {
                obs: &obs,
                grid: &grid,
                params: vec![Param::Spread],
                ranges: vec![(0.0, 1.0)],
                scale: Param::Spread,
                spread_fixed: 0.0,
                mu_fixed: 1.0,
                noise_var: vec![0.0],
            };
            let (u_hat, l_max) = estimate(&jm);
            let theta = jm.theta(&u_hat);
            // l is flat to rounding at its maximum: s to sqrt(eps |l| / l'') ~ 5e-9.
            assert!((theta[0] - 0.3).abs() < 1e-8, "{obs:?}: {theta:?}");
            for dir in [-1.0, 1.0] {
                let e = profile_end(&jm, 0, 1.0, &u_hat, l_max, dir);
                let r = 0.09 / jm.theta(&e.point)[0].powi(2);
                let d = 39.0 * (r - r.ln() - 1.0);
                assert!((d - wilks_threshold()).abs() < 1e-6, "{obs:?} {dir}: {d}");
            }
            for (uniform, want) in [(false, 1.0), (true, 2.5)] {
                let x = scaled_samples(200_000, uniform, &[0.3]);
                let k = information(&jm, &theta, &x).unwrap().derived().k[0];
                assert!((k / want - 1.0).abs() < 0.02, "uniform {uniform}: k {k}");
            }
            let nx = 20_000;
            let x = scaled_samples(nx, false, &[0.3]);
            let sd = information(&jm, &theta, &x).unwrap().derived().model_sd[0] / theta[0];
            let rel = sd / (1.0 / (2.0 * nx as f64)).sqrt();
            assert!((rel - 1.0).abs() < 0.03, "model sd ratio {rel}");
        }
    }

    #[test]
    fn separable_model_closed_forms() {
        let (a, b, n) = (0.04, 0.024, 40);
        let obs =
            Observed::Covariance { s: DMatrix::from_diagonal(&DVector::from_vec(vec![a, b])), n };
        let grid = grid();
        let jm = separable(&obs, &grid);
        let (u_hat, l_max) = estimate(&jm);
        let theta = jm.theta(&u_hat);
        assert!((theta[0] - 0.2).abs() < 1e-6 && (theta[1] - 0.6).abs() < 1e-5, "{theta:?}");
        // Profile ends of the spread: 39 (r - ln r - 1) = chi^2_1(0.90).
        for dir in [-1.0, 1.0] {
            let e = profile_end(&jm, 0, 1.0, &u_hat, l_max, dir);
            let s = jm.theta(&e.point)[0];
            let r = a / (s * s);
            let d = (n as f64 - 1.0) * (r - r.ln() - 1.0);
            assert!(!e.at_bound && (d - wilks_threshold()).abs() < 1e-4, "{dir}: s {s}, {d}");
        }
        // Sandwich factors: normal scatter 1, uniform 2 / Var(u^2) = 2.5 (unit-variance u).
        for (uniform, want) in [(false, 1.0), (true, 2.5)] {
            let d = information(&jm, &theta, &samples(200_000, uniform)).unwrap().derived();
            for k in &d.k {
                assert!((k / want - 1.0).abs() < 0.02, "uniform {uniform}: k {k}");
            }
        }
        // Model error of s from N normal samples: sd(ln s) = sqrt(1 / (2 N)).
        let nx = 20_000;
        let d = information(&jm, &theta, &samples(nx, false)).unwrap().derived();
        let rel = d.model_sd[0] / theta[0] / (1.0 / (2.0 * nx as f64)).sqrt();
        assert!((rel - 1.0).abs() < 0.03, "model sd ratio {rel}");
    }
}

mod params {
    use kinrepro::calibrate::CalibrateError;
    use kinrepro::calibrate::params::*;

    fn names(v: &[&str]) -> Vec<String> {
        v.iter().map(|s| s.to_string()).collect()
    }

    #[test]
    fn fit_lists() {
        let p = parse_fit(&names(&["support_compliance", "spread"])).unwrap();
        assert_eq!(p, vec![Param::Spread, Param::SupportCompliance]);
        assert!(matches!(
            parse_fit(&names(&["spread", "spread"])),
            Err(CalibrateError::DuplicateParameter(_))
        ));
        assert!(matches!(parse_fit(&names(&["mu"])), Err(CalibrateError::UnknownParameter(_))));
        assert!(matches!(parse_fit(&[]), Err(CalibrateError::EmptyFit)));
        assert!(matches!(parse_fit(&names(&["spread", ""])), Err(CalibrateError::EmptyFit)));
    }
}
