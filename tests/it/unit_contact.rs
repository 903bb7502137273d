//! Unit tests of the contact laws: Hertz, elliptic integrals, Mindlin projection, Coulomb, friction readings, quadrature.

mod hertz {
    use kinrepro::contact::hertz::*;
    use std::f64::consts::PI;

    #[test]
    fn circular_law_matches_closed_forms() {
        let (r, e, f) = (5e-3, 115.4e9, 4.7);
        let h = HertzLaw::circular(r, e);
        let a = (3.0 * f * r / (4.0 * e)).cbrt();
        assert!((h.semi_axes(f)[0] / a - 1.0).abs() < 1e-14);
        assert!((h.approach(f) / (a * a / r) - 1.0).abs() < 1e-14);
        assert!((h.max_pressure(f) / (3.0 * f / (2.0 * PI * a * a)) - 1.0).abs() < 1e-14);
        assert!((h.force(h.approach(f)) / f - 1.0).abs() < 1e-14);
        assert_eq!(h.force(-1e-9), 0.0);
        assert_eq!(h.stiffness(-1e-9), 0.0);
    }

    #[test]
    fn cube_root_within_one_ulp_of_libm() {
        // 10^e (1 + u) over 120 decades, a xorshift sequence.
        let mut s: u64 = 0x9E37_79B9_7F4A_7C15;
        for _ in 0..200_000 {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            let e = (s % 1000) as f64 * 0.12 - 60.0;
            let x = 10f64.powf(e) * (1.0 + (s >> 40) as f64 / (1u64 << 24) as f64);
            let ulps = (cbrt(x).to_bits() as i64 - x.cbrt().to_bits() as i64).abs();
            assert!(ulps <= 1, "{x}: {} vs {}", cbrt(x), x.cbrt());
        }
        for x in [0.0, -8.0, f64::INFINITY, 1e-310, f64::NAN] {
            assert_eq!(cbrt(x).to_bits(), x.cbrt().to_bits());
        }
        assert_eq!(cbrt(27.0), 3.0);
    }
}

mod elliptic {
    use kinrepro::contact::elliptic::*;
    use std::f64::consts::PI;

    #[test]
    fn agm_matches_tabulated_values() {
        // Abramowitz & Stegun table 17.1, m = 0.5: K = 1.8540746773013719,
        // E = 1.3506438810476755.
        let i = EllipticIntegrals::from_kp(0.5_f64.sqrt());
        assert!((i.k - 1.854_074_677_301_371_9).abs() < 4e-16);
        assert!((i.e - 1.350_643_881_047_675_5).abs() < 4e-16);
        // m = 0: K = E = pi/2.
        let c = EllipticIntegrals::from_kp(1.0);
        assert_eq!(c.k, PI / 2.0);
        assert_eq!(c.e, PI / 2.0);
        // Legendre relation E K' + E' K - K K' = pi/2 at m = 0.3.
        let m: f64 = 0.3;
        let i = EllipticIntegrals::from_kp((1.0 - m).sqrt());
        let j = EllipticIntegrals::from_kp(m.sqrt());
        let legendre = i.e * j.k + j.e * i.k - i.k * j.k;
        assert!((legendre - PI / 2.0).abs() < 1e-15, "{legendre}");
    }

    #[test]
    fn ellipticity_solve_inverts_the_ratio() {
        for kp in [0.999_999, 0.9, 0.5, 0.1, 0.01] {
            let r = EllipticIntegrals::from_kp(kp).curvature_ratio();
            let back = solve_kp(r);
            assert!((back / kp - 1.0).abs() < 1e-12, "{kp} -> {r} -> {back}");
        }
        assert_eq!(solve_kp(1.0), 1.0);
    }
}

mod mindlin {
    use kinrepro::contact::mindlin::*;
    use nalgebra::{Matrix3, Vector2, Vector3};

    /// A unit normal, a trial force with a normal component (removed by
    /// both projections) and a limit below the trial's tangential size.
    fn case() -> (Vector3<f64>, Vector3<f64>, f64) {
        let n = Vector3::new(0.3, -0.2, 0.9).normalize();
        (n, Vector3::new(2.0, 1.5, -0.7), 0.8)
    }

    /// Circle and ellipse: F on |F| = L in the tangent plane, and the
    /// closest point in the complementary-energy norm of K_t: in the
    /// principal axes F_i (1 + g k_i) = F_trial,i with one g >= 0 (for a
    /// circle F = L times the in-plane direction of the trial force).
    #[test]
    fn principal_projection_is_the_closest_point_on_the_friction_circle() {
        let (n, trial, limit) = case();
        for k in [[3e7, 3e7], [2.9e7, 3.3e7]] {
            let p = PrincipalStiffness::new(k, &n, &Vector3::x());
            let (f, _, _) = p.project(&n, &trial, limit);
            assert!((f.norm() - limit).abs() < 1e-14 * limit, "{k:?}: {f}");
            assert!(f.dot(&n).abs() < 1e-15);
            let in_plane = trial - n * n.dot(&trial);
            match p.axes {
                None => assert!((f - in_plane.normalize() * limit).norm() < 1e-15 * limit),
                Some([e1, e2]) => {
                    let g = [(e1, k[0]), (e2, k[1])]
                        .map(|(e, ki)| (e.dot(&trial) / e.dot(&f) - 1.0) / ki);
                    assert!(g[0] > 0.0 && (g[0] / g[1] - 1.0).abs() < 1e-12, "{g:?}");
                }
            }
        }
    }

    #[test]
    fn projection_derivatives_match_finite_differences() {
        let (n, trial, limit) = case();
        for k in [[3e7, 3e7], [2.9e7, 3.3e7]] {
            let p = PrincipalStiffness::new(k, &n, &Vector3::x());
            let (_, d_trial, d_limit) = p.project(&n, &trial, limit);
            let h = 1e-6;
            for j in 0..3 {
                let e = Vector3::ith(j, h);
                let col = (p.project(&n, &(trial + e), limit).0
                    - p.project(&n, &(trial - e), limit).0)
                    / (2.0 * h);
                assert!((col - d_trial.column(j)).norm() < 1e-8, "{k:?} column {j}");
            }
            let dl = (p.project(&n, &trial, limit + h).0 - p.project(&n, &trial, limit - h).0)
                / (2.0 * h);
            assert!((dl - d_limit).norm() < 1e-8, "{k:?}");
        }
    }

    /// The entry-by-entry K_t against the matrix expressions
    /// k (I - n n^T) and k1 e1 e1^T + k2 e2 e2^T, with e1 the unit major
    /// axis projected into the tangent plane and e2 = n x e1, for circles
    /// and ellipses about many normals.
    #[test]
    fn tensor_is_the_matrix_expression() {
        let mut s: u64 = 0x853C_49E6_748F_EA9B;
        let mut next = move || {
            s ^= s << 13;
            s ^= s >> 7;
            s ^= s << 17;
            (s >> 11) as f64 / (1u64 << 53) as f64 - 0.5
        };
        for case in 0..4000 {
            let n = Vector3::new(next(), next(), next()).normalize();
            let axis = Vector3::new(next(), next(), next());
            let k = if case % 2 == 0 { [3.1e7, 3.1e7] } else { [2.9e7 * (1.0 + next()), 3.3e7] };
            let p = PrincipalStiffness::new(k, &n, &axis);
            let proj = Matrix3::identity() - n * n.transpose();
            let want = match p.axes {
                None => p.k[0] * proj,
                Some([e1, e2]) => {
                    let in_plane = proj * axis;
                    assert!((e1 - in_plane / in_plane.norm()).norm() < 1e-12);
                    assert!((e2 - n.cross(&e1)).norm() < 1e-12);
                    p.k[0] * e1 * e1.transpose() + p.k[1] * e2 * e2.transpose()
                }
            };
            let got = p.tensor(&n);
            assert!((got - want).norm() <= 1e-12 * want.norm(), "{case}");
        }
    }

    /// Trial forces from barely to far outside the limit, on ellipses of
    /// growing anisotropy: the projection ends on |F| = L to rounding, and
    /// is the closest point in the complementary-energy norm, F_i (1 + g
    /// k_i) = F_trial,i with one g >= 0 for both axes (the stopping rule
    /// neither stops short nor walks in the noise).
    #[test]
    fn elliptic_projection_meets_the_circle_and_the_closest_point_condition() {
        for excess in [1e-9, 1e-6, 1e-3, 0.02, 0.3, 4.0] {
            for (aniso, angle) in [(1.07, 0.2), (1.5, 1.1), (4.0, 2.5), (1.0 + 1e-9, 0.7)] {
                let k = [2.9e7, 2.9e7 * aniso];
                let limit = 0.37;
                let r = limit * (1.0 + excess);
                let trial = Vector2::new(r * f64::cos(angle), r * f64::sin(angle));
                let (f, _, _) = project_on_circle(k, &trial, limit);
                assert!((f.norm() / limit - 1.0).abs() < 4.0 * f64::EPSILON, "{excess} {aniso}");
                let g = [0, 1].map(|i| (trial[i] / f[i] - 1.0) / k[i]);
                assert!(g[0] >= 0.0 && g[1] >= 0.0, "{g:?}");
                if excess >= 0.02 {
                    assert!((g[0] / g[1] - 1.0).abs() < 1e-12, "{excess} {aniso}: {g:?}");
                }
            }
        }
    }

    /// Principal values equal but for rounding, or a major axis along the
    /// normal (none in the tangent plane), are a circular contact: the
    /// radial return, finite, never an ellipse oriented by a zero vector.
    #[test]
    fn nearly_equal_values_or_no_axis_give_the_radial_return() {
        let (n, trial, limit) = case();
        let k = 3e7;
        let circle = PrincipalStiffness::new([k, k], &n, &Vector3::x());
        let want = circle.project(&n, &trial, limit).0;
        let near = PrincipalStiffness::new([k, k * (1.0 + f64::EPSILON)], &n, &Vector3::zeros());
        assert!(near.axes.is_none());
        let got = near.project(&n, &trial, limit).0;
        assert!(got.iter().all(|v| v.is_finite()));
        assert!((got - want).norm() <= 1e-15 * limit, "{got} vs {want}");
        let along_normal = PrincipalStiffness::new([k, 0.5 * k], &n, &n);
        assert!(along_normal.axes.is_none());
        assert!(along_normal.project(&n, &trial, limit).0.iter().all(|v| v.is_finite()));
    }
}

mod coulomb {
    use kinrepro::contact::FrictionLaw;
    use kinrepro::contact::coulomb::*;
    use kinrepro::contact::mindlin::PrincipalStiffness;
    use kinrepro::contact::tangential_types::Friction;
    use kinrepro::contact::tangential_types::{
        SlipState, TangentialInput, TangentialResponse, TangentialState,
    };
    use nalgebra::{Matrix3, Vector3};

    /// The closed forms of a circular contact ([`Circle`]) against the
    /// elliptical route with two equal principal values (K_t and dK_t/dF_n
    /// as matrices, the projection in principal axes and its general
    /// tangent), which `tests/it/contact_laws.rs` checks by finite
    /// differences: force and both tangents agree to rounding, about many
    /// normals, sticking, sliding on and starting to slide, for the switch
    /// and the decay law (whose dmu terms the closed form carries too).
    #[test]
    fn circular_closed_forms_are_the_elliptical_route() {
        use rand::{Rng, SeedableRng};
        let mut rng = rand_chacha::ChaCha8Rng::seed_from_u64(0x9E37_79B9);
        let mut next = move || rng.random_range(-0.5..0.5);
        let close = |a: &[f64], b: &[f64], scale: f64| {
            a.iter().zip(b).all(|(x, y)| (x - y).abs() <= 1e-12 * scale)
        };
        let (mut slips, mut sticks) = (0, 0);
        for case in 0..600 {
            let n = Vector3::new(next(), next(), next()).normalize();
            let p = PrincipalStiffness::new([3e7, 3e7], &n, &Vector3::x());
            let in_plane = |v: Vector3<f64>| v - n * n.dot(&v);
            let e1 = in_plane(Vector3::x()).normalize();
            let axes = PrincipalStiffness { axes: Some([e1, n.cross(&e1)]), ..p };
            let du = in_plane(Vector3::new(next(), next(), next()) * 4e-7);
            let old = TangentialState {
                force: in_plane(Vector3::new(next(), next(), next()) * 8.0),
                sliding: case % 3 == 0,
                slip_velocity: 1e-4 * next().abs(),
                normal_force: 10.0,
                ..TangentialState::new(n)
            };
            let law = if case % 2 == 0 {
                FrictionLaw::Switch
            } else {
                FrictionLaw::Decay { coefficient: 1e4 }
            };
            let stiffness = p.tensor(&n);
            let input = TangentialInput {
                normal: n,
                du,
                normal_force: 10.0,
                stiffness,
                principal: p,
                d_stiffness_d_fn: stiffness / 60.0,
                contact_radius: 0.0,
                g_star: 0.0,
                mindlin_shape: Matrix3::zeros(),
                friction: Friction { law, duration: 1e-3, ..Friction::switch(0.5, 0.4) },
            };
            let mut got = TangentialResponse::open(n);
            let mut want = TangentialResponse::open(n);
            update(&old, &input, true, &mut got);
            let elliptical = TangentialInput { principal: axes, ..input };
            update(&old, &elliptical, true, &mut want);
            assert_eq!(got.slip, want.slip, "{case}");
            let f = want.force.norm().max(1e-3);
            assert!(close(got.force.as_slice(), want.force.as_slice(), f), "{case}");
            let k = want.d_force_d_du.norm();
            let (g, w) = (&got.d_force_d_du, &want.d_force_d_du);
            assert!(close(g.as_slice(), w.as_slice(), k), "{case}: {g} {w}");
            let (g, w) = (&got.d_force_d_fn, &want.d_force_d_fn);
            assert!(close(g.as_slice(), w.as_slice(), w.norm() + 1.0), "{case}: {g} {w}");
            let v = got.state.slip_velocity;
            assert!((v - want.state.slip_velocity).abs() <= 1e-12 * v.abs().max(1e-9));
            slips += usize::from(got.slip == SlipState::Slip);
            sticks += usize::from(got.slip == SlipState::Stick);
        }
        assert!(slips > 100 && sticks > 100, "{slips} slips, {sticks} sticks");
    }
}

mod friction {
    use kinrepro::contact::friction::*;

    fn input(law: FrictionLaw, trial: f64, was_sliding: bool) -> SlideInput {
        SlideInput {
            mu_s: 0.5,
            mu_d: 0.4,
            law,
            duration: 0.05,
            trial,
            normal_force: 10.0,
            stiffness: 1e7,
            was_sliding,
            previous_velocity: if was_sliding { 1e-7 } else { 0.0 },
        }
    }

    #[test]
    fn onset_root_lies_on_the_rate_dependent_limit() {
        // Independent check: the returned force T - k gamma equals mu(v) F_n
        // with v = gamma / dt evaluated from the closed-form law. (1e7, 5.1):
        // beta F_n (mu_s - mu_d) > k, the root far from gamma = 0.
        for (c, trial) in [(1e3, 5.2), (1e5, 6.0), (1e7, 5.1), (0.0, 5.5)] {
            let x = input(FrictionLaw::Decay { coefficient: c }, trial, false);
            let s = slide(&x).expect("slides");
            let (mu_v, _) = decay_coefficient(0.5, 0.4, c, s.slip / 0.05);
            assert!((s.mu - mu_v).abs() < 1e-14);
            assert!(((trial - 1e7 * s.slip) / (mu_v * 10.0) - 1.0).abs() < 1e-12);
        }
    }

    #[test]
    fn onset_derivatives_match_finite_differences() {
        let c = 3e4;
        let base = input(FrictionLaw::Decay { coefficient: c }, 5.3, false);
        let s0 = slide(&base).unwrap();
        let fd = |f: &dyn Fn(&mut SlideInput, f64), h: f64| {
            let (mut p, mut m) = (base, base);
            f(&mut p, h);
            f(&mut m, -h);
            (slide(&p).unwrap().mu - slide(&m).unwrap().mu) / (2.0 * h)
        };
        let d_t = fd(&|x, h| x.trial += h, 1e-6);
        let d_fn = fd(&|x, h| x.normal_force += h, 1e-6);
        let d_k = fd(&|x, h| x.stiffness += h, 1.0);
        assert!((d_t / s0.d_mu_d_trial - 1.0).abs() < 1e-5, "{d_t} {s0:?}");
        assert!((d_fn / s0.d_mu_d_fn - 1.0).abs() < 1e-5, "{d_fn} {s0:?}");
        assert!((d_k / s0.d_mu_d_k - 1.0).abs() < 1e-4, "{d_k} {s0:?}");
    }

    #[test]
    fn a_sliding_contact_uses_the_last_increments_velocity() {
        // mu(1e-7 m/s) with c = 1e6 s/m: 0.4 + 0.1 exp(-0.1).
        let law = FrictionLaw::Decay { coefficient: 1e6 };
        let mu = 0.4 + 0.1 * (-0.1_f64).exp();
        assert!(slide(&input(law, 0.999 * mu * 10.0, true)).is_none());
        let s = slide(&input(law, 5.0, true)).unwrap();
        assert!((s.mu - mu).abs() < 1e-15);
        assert!((s.slip - (5.0 - mu * 10.0) / 1e7).abs() < 1e-20);
        assert_eq!((s.d_mu_d_trial, s.d_mu_d_fn, s.d_mu_d_k), (0.0, 0.0, 0.0));
    }

    #[test]
    fn decay_limits_are_the_switch_law() {
        // c = 0: mu = mu_s whenever sliding, and a sliding contact sticks below mu_s F_n.
        let zero = FrictionLaw::Decay { coefficient: 0.0 };
        assert!((slide(&input(zero, 5.5, false)).unwrap().mu - 0.5).abs() < 1e-15);
        assert!((slide(&input(zero, 5.01, true)).unwrap().mu - 0.5).abs() < 1e-15);
        assert!(slide(&input(zero, 4.9, true)).is_none());
        // c huge: mu = mu_d exactly, sliding on above mu_d F_n, as the switch law.
        let huge = FrictionLaw::Decay { coefficient: 1e30 };
        for (trial, sliding) in [(5.5, false), (4.5, true), (4.01, true)] {
            let d = slide(&input(huge, trial, sliding)).unwrap();
            let s = slide(&input(FrictionLaw::Switch, trial, sliding)).unwrap();
            assert_eq!(d.mu, s.mu);
        }
        assert!(slide(&input(huge, 3.99, true)).is_none());
        assert!(slide(&input(huge, 4.99, false)).is_none());
    }
}

mod quadrature {
    use kinrepro::contact::quadrature::*;

    #[test]
    fn gauss_rule_is_exact_to_degree_2n_minus_1() {
        for n in [1, 2, 5, 16, 33] {
            let rule = gauss_on(n, 0.0, 2.0);
            for deg in 0..(2 * n) {
                let sum: f64 = rule.iter().map(|(x, w)| w * x.powi(deg as i32)).sum();
                let exact = 2f64.powi(deg as i32 + 1) / (deg as f64 + 1.0);
                assert!((sum / exact - 1.0).abs() < 1e-12, "n {n} deg {deg}");
            }
        }
    }
}

mod curvature {
    use kinrepro::contact::{ContactError, PairCurvature, RelativeCurvature};

    const INF: f64 = f64::INFINITY;

    fn pair(
        radii1: [f64; 2],
        radii2: [f64; 2],
        deg: f64,
    ) -> Result<RelativeCurvature, ContactError> {
        PairCurvature { radii1, radii2, angle: deg.to_radians() }.relative()
    }

    #[test]
    fn the_checks_of_johnson_section_4_1() {
        // Equal crossed cylinders at 90 degrees: A = B = 1/(2 r), a sphere
        // of that radius on a flat.
        let r = pair([0.004, INF], [0.004, INF], 90.0).unwrap();
        assert!((r.a * 0.008 - 1.0).abs() < 1e-15 && (r.b * 0.008 - 1.0).abs() < 1e-15);
        // A ball r in a concave cylinder R_g: across r R_g/(R_g - r), along r.
        let (rb, rg) = (0.005, 0.0052);
        let [rx, ry] = pair([rb, rb], [-rg, INF], 0.0).unwrap().radii();
        assert!((ry / (rb * rg / (rg - rb)) - 1.0).abs() < 1e-12, "{ry}");
        assert!((rx / rb - 1.0).abs() < 1e-15);
        // Negative A: a ball larger than its seat; A = 0: a pin on a flat.
        for (r1, r2) in [([0.005; 2], [-0.004; 2]), ([0.005, INF], [INF, INF])] {
            let e = pair(r1, r2, 0.0).unwrap_err();
            assert!(matches!(e, ContactError::NotPointContact { .. }), "{e}");
        }
        // A zero radius and a non-finite angle are errors, not NaN.
        assert!(matches!(
            pair([0.0, 1.0], [1.0, 1.0], 0.0),
            Err(ContactError::BadPrincipalRadius { .. })
        ));
        assert!(matches!(pair([1.0, 1.0], [1.0, 1.0], f64::NAN), Err(ContactError::BadAngle(_))));
    }

    #[test]
    fn crossed_cylinders_follow_johnson_eq_4_2_in_closed_form() {
        // Two cylinders R1, R2 crossed at theta (Johnson 1985 §4.1):
        // A + B = (1/R1 + 1/R2)/2,
        // B - A = 1/2 sqrt(1/R1^2 + 1/R2^2 + 2 cos(2 theta)/(R1 R2)).
        let (r1, r2) = (0.003, 0.002);
        for deg in [10.0, 30.0, 45.0, 60.0, 90.0, 135.0] {
            let t = f64::to_radians(deg);
            let sum = 0.5 * (1.0 / r1 + 1.0 / r2);
            let diff = 0.5
                * (1.0 / (r1 * r1) + 1.0 / (r2 * r2) + 2.0 * (2.0 * t).cos() / (r1 * r2)).sqrt();
            let c = pair([r1, INF], [r2, INF], deg).unwrap();
            assert!((c.a / (0.5 * (sum - diff)) - 1.0).abs() < 1e-12, "{deg}");
            assert!((c.b / (0.5 * (sum + diff)) - 1.0).abs() < 1e-12, "{deg}");
        }
    }
}
