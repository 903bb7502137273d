//! Unit tests of the study statistics (moments, quantiles, intervals, bootstrap quantiles) and the provenance hash.

mod moments {
    use kinrepro::study::stats::moments::*;

    fn two_pass(v: &[f64]) -> (f64, f64, f64, f64) {
        let n = v.len() as f64;
        let mean = v.iter().sum::<f64>() / n;
        let m = |p: i32| v.iter().map(|x| (x - mean).powi(p)).sum::<f64>();
        (mean, m(2), m(3), m(4))
    }

    #[test]
    fn push_and_merge_equal_two_pass() {
        // A skewed, offset sequence (deterministic).
        let v: Vec<f64> = (0..1000)
            .map(|i| 1e3 + ((i * 7919) % 1000) as f64 / 1000.0 + ((i % 13) as f64).powi(2) * 1e-2)
            .collect();
        let (mean, m2, m3, m4) = two_pass(&v);
        let mut all = Moments::new();
        v.iter().for_each(|&x| all.push(x));
        let mut a = Moments::new();
        let mut b = Moments::new();
        v[..317].iter().for_each(|&x| a.push(x));
        v[317..].iter().for_each(|&x| b.push(x));
        a.merge(&b);
        for m in [all, a] {
            assert_eq!(m.n, 1000);
            assert!((m.mean - mean).abs() < 1e-12 * mean);
            assert!((m.m2 - m2).abs() < 1e-9 * m2);
            assert!((m.m3 - m3).abs() < 1e-8 * m2.powf(1.5));
            assert!((m.m4 - m4).abs() < 1e-9 * m4);
        }
        // Uniform values have kurtosis 1.8.
        let mut u = Moments::new();
        (0..100_000).for_each(|i| u.push(i as f64));
        assert!((u.kurtosis() - 1.8).abs() < 1e-3);
    }
}

mod quantile {
    use kinrepro::study::stats::quantile::*;

    #[test]
    fn normal_quantiles_match_tables() {
        // Abramowitz & Stegun Table 26.5 / R's qnorm.
        for (p, z) in [
            (0.95, 1.644_853_626_951_472_2),
            (0.975, 1.959_963_984_540_054),
            (0.5, 0.0),
            (1e-10, -6.361_340_902_404_056),
        ] {
            let got = normal_quantile(p).unwrap();
            assert!((got - z).abs() < 1e-14 * z.abs().max(1.0), "{p}: {got}");
        }
        assert!(normal_quantile(1.0).is_err());
    }

    #[test]
    fn t_quantiles_match_tables() {
        // R: qt(0.95, c(1, 2, 4, 9, 30)); qt(0.975, 4) (checked with mpmath, 30 digits).
        for (p, nu, t) in [
            (0.95, 1, 6.313_751_514_675_041),
            (0.95, 2, 2.919_985_580_353_725),
            (0.95, 4, 2.131_846_786_326_649),
            (0.95, 9, 1.833_112_932_653_634),
            (0.95, 30, 1.697_260_886_593_957),
            (0.975, 4, 2.776_445_105_197_793),
        ] {
            let got = student_t_quantile(p, nu).unwrap();
            assert!((got - t).abs() < 1e-10 * t, "nu {nu}: {got} vs {t}");
            assert!((student_t_quantile(1.0 - p, nu).unwrap() + t).abs() < 1e-10 * t);
        }
        assert!(student_t_quantile(0.95, 0).is_err());
    }
}

mod interval {
    use kinrepro::study::stats::interval::*;
    use kinrepro::study::stats::moments::Moments;
    use kinrepro::study::stats::quantile::normal_quantile;

    #[test]
    fn bonett_reduces_to_delta_method_for_large_n() {
        // Normal data: kurtosis 3, Var(ln s^2) ~ 2/(n-1): half-width z sqrt(2/(n-1))/2 on ln s.
        let mut m = Moments::new();
        let n = 1_000_000u64;
        // Deterministic normal scores (quantiles), kurtosis -> 3.
        for i in 0..n {
            m.push(normal_quantile((i as f64 + 0.5) / n as f64).unwrap());
        }
        let iv = sigma_interval_from_moments(&m, 0.9).unwrap();
        let s = m.sigma();
        let half = 1.644_853_626_951_472 * (2.0 / (n as f64 - 1.0)).sqrt() / 2.0;
        assert!(((iv.upper / s).ln() - half).abs() < 0.02 * half);
        assert!(((s / iv.lower).ln() - half).abs() < 0.02 * half);
    }

    #[test]
    fn replicated_estimate_is_pooled_variance_with_divisor_corrected() {
        // Two replicates whose means agree: sigma^2_hat = mean within mean square (divisor m).
        let (s, iv) = sigma_replicated(&[0.0, 2.0, 1.0, 1.0, 3.0, 1.0, 2.0, 2.0], 2, 0.9).unwrap();
        // Replicate 1: mean 1, v = (1+1+0+0)/4 = 0.5; replicate 2: mean 2, v = 0.5;
        // grand 1.5, w_j = 0.5 + 2 * 0.25 = 1.0 each: sigma^2 = 1, zero spread of w.
        assert!((s - 1.0).abs() < 1e-15);
        assert!((iv.lower - 1.0).abs() < 1e-15 && (iv.upper - 1.0).abs() < 1e-15);
        assert!(sigma_replicated(&[1.0; 9], 2, 0.9).is_err());
    }
}

mod bootstrap {
    use kinrepro::study::stats::bootstrap::quantile_sorted;

    #[test]
    fn type7_quantiles_match_r() {
        // R: quantile(c(1,2,3,4,10), c(0.05, 0.5, 0.95)) -> 1.2 3.0 8.8
        let x = [1.0, 2.0, 3.0, 4.0, 10.0];
        assert!((quantile_sorted(&x, 0.05) - 1.2).abs() < 1e-12);
        assert_eq!(quantile_sorted(&x, 0.5), 3.0);
        assert!((quantile_sorted(&x, 0.95) - 8.8).abs() < 1e-12);
    }
}

mod provenance {
    use kinrepro::study::provenance::fnv1a64;

    #[test]
    fn fnv1a64_matches_published_vectors() {
        // Test vectors of the FNV reference (Noll, "FNV hash", test suite).
        assert_eq!(fnv1a64(b""), 0xcbf2_9ce4_8422_2325);
        assert_eq!(fnv1a64(b"a"), 0xaf63_dc4c_8601_ec8c);
        assert_eq!(fnv1a64(b"foobar"), 0x8594_4171_f739_67e8);
    }
}
