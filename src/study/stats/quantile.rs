//! Quantiles of the standard normal and Student t distributions (no crate offers them among
//! the project's dependencies; both are short and checked against printed tables).
//!
//! * Normal: Wichura (1988), Algorithm AS 241 `PPND16`, relative accuracy about 1e-16.
//! * Student t with an integer number of degrees of freedom `nu`: the distribution function
//!   in closed form (Abramowitz & Stegun 1964, eq. 26.7.3/26.7.4; with `theta = atan(t/sqrt(nu))`,
//!   `A(t|nu) = P(|T| <= t)`), inverted by bisection to machine precision.

use std::f64::consts::PI;

use super::super::error::{Result, StudyError};

/// Quantile `z_p` of the standard normal distribution, `0 < p < 1` (AS 241, PPND16).
pub fn normal_quantile(p: f64) -> Result<f64> {
    if !(p > 0.0 && p < 1.0) {
        return Err(StudyError::InvalidParameter(format!(
            "normal quantile: probability {p} not in (0, 1)"
        )));
    }
    let q = p - 0.5;
    if q.abs() <= 0.425 {
        let r = 0.180625 - q * q;
        return Ok(q * poly(&A, r) / poly(&B, r));
    }
    let r = if q < 0.0 { p } else { 1.0 - p };
    let r = (-r.ln()).sqrt();
    let z = if r <= 5.0 {
        let r = r - 1.6;
        poly(&C, r) / poly(&D, r)
    } else {
        let r = r - 5.0;
        poly(&E, r) / poly(&F, r)
    };
    Ok(if q < 0.0 { -z } else { z })
}

/// Horner evaluation of `c[0] + c[1] x + ... + c[7] x^7`.
fn poly(c: &[f64; 8], x: f64) -> f64 {
    c.iter().rev().fold(0.0, |acc, &k| acc * x + k)
}

const A: [f64; 8] = [
    3.387_132_872_796_366_5,
    1.331_416_678_917_843_8e2,
    1.971_590_950_306_551_3e3,
    1.373_169_376_550_946e4,
    4.592_195_393_154_987e4,
    6.726_577_092_700_87e4,
    3.343_057_558_358_813e4,
    2.509_080_928_730_122_7e3,
];
const B: [f64; 8] = [
    1.0,
    4.231_333_070_160_091e1,
    6.871_870_074_920_579e2,
    5.394_196_021_424_751e3,
    2.121_379_430_158_659_7e4,
    3.930_789_580_009_271e4,
    2.872_908_573_572_194_3e4,
    5.226_495_278_852_545e3,
];
const C: [f64; 8] = [
    1.423_437_110_749_683_5,
    4.630_337_846_156_546,
    5.769_497_221_460_691,
    3.647_848_324_763_204_5,
    1.270_458_252_452_368_4,
    2.417_807_251_774_506e-1,
    2.272_384_498_926_918_4e-2,
    7.745_450_142_783_414e-4,
];
const D: [f64; 8] = [
    1.0,
    2.053_191_626_637_759,
    1.676_384_830_183_803_8,
    6.897_673_349_851e-1,
    1.481_039_764_274_800_8e-1,
    1.519_866_656_361_645_7e-2,
    5.475_938_084_995_345e-4,
    1.050_750_071_644_416_9e-9,
];
const E: [f64; 8] = [
    6.657_904_643_501_103,
    5.463_784_911_164_114,
    1.784_826_539_917_291_3,
    2.965_605_718_285_048_7e-1,
    2.653_218_952_657_612_4e-2,
    1.242_660_947_388_078_4e-3,
    2.711_555_568_743_487_6e-5,
    2.010_334_399_292_288_1e-7,
];
const F: [f64; 8] = [
    1.0,
    5.998_322_065_558_88e-1,
    1.369_298_809_227_358e-1,
    1.487_536_129_085_061_5e-2,
    7.868_691_311_456_133e-4,
    1.846_318_317_510_054_8e-5,
    1.421_511_758_316_446e-7,
    2.044_263_103_389_939_7e-15,
];

/// Distribution function of Student's t with `nu >= 1` degrees of freedom (A&S 26.7.3/4).
pub fn student_t_cdf(t: f64, nu: usize) -> f64 {
    let theta = (t.abs() / (nu as f64).sqrt()).atan();
    let (s, c) = theta.sin_cos();
    let c2 = c * c;
    // A(t|nu) = P(|T| <= |t|).
    let a = if nu % 2 == 1 {
        // (2/pi) [theta + sin cos (1 + 2/3 cos^2 + 2*4/(3*5) cos^4 + ... up to cos^(nu-3))].
        let (mut term, mut sum) = (1.0, 0.0);
        if nu > 1 {
            sum = 1.0;
            let mut k = 2;
            while k < nu - 1 {
                term *= c2 * k as f64 / (k + 1) as f64;
                sum += term;
                k += 2;
            }
        }
        2.0 / PI * (theta + s * c * sum)
    } else {
        // sin [1 + 1/2 cos^2 + 1*3/(2*4) cos^4 + ... up to cos^(nu-2)].
        let (mut term, mut sum) = (1.0, 1.0);
        let mut k = 1;
        while k < nu - 1 {
            term *= c2 * k as f64 / (k + 1) as f64;
            sum += term;
            k += 2;
        }
        s * sum
    };
    if t >= 0.0 {
        0.5 + 0.5 * a
    } else {
        0.5 - 0.5 * a
    }
}

/// Quantile `t_{p, nu}` of Student's t, `0 < p < 1`, `nu >= 1` (bisection on [`student_t_cdf`]).
pub fn student_t_quantile(p: f64, nu: usize) -> Result<f64> {
    if !(p > 0.0 && p < 1.0) || nu == 0 {
        return Err(StudyError::InvalidParameter(format!(
            "t quantile: need 0 < p < 1 and nu >= 1 (p = {p}, nu = {nu})"
        )));
    }
    if p < 0.5 {
        return Ok(-student_t_quantile(1.0 - p, nu)?);
    }
    let mut hi = 1.0;
    while student_t_cdf(hi, nu) < p {
        hi *= 2.0;
        if hi > 1e300 {
            return Ok(f64::MAX);
        }
    }
    let mut lo = 0.0;
    for _ in 0..200 {
        let mid = 0.5 * (lo + hi);
        if mid <= lo || mid >= hi {
            break;
        }
        if student_t_cdf(mid, nu) < p {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    Ok(0.5 * (lo + hi))
}

#[cfg(test)]
mod tests {
    use super::*;

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
    }
}
