//! Numbers of the explicit scene as `expand` prints them: rounding noise of
//! the trigonometry (cos 90 deg = 6e-17) written as 0, every number to 15
//! significant digits, so that 0.04 reads 0.04 and not 0.040000000000000001.
//!
//! Both changes stay below 1e-15 relative to the vector they belong to, far
//! inside what the scene's numbers mean (tests/it/scenes.rs reloads the
//! expanded form and compares the scene at 1e-12).

/// Significant digits kept (an f64 holds 15 to 17).
const DIGITS: usize = 15;

/// A component below this share of its vector's largest is rounding noise.
const NOISE: f64 = 1e-15;

/// Tidies every float of `v` in place.
pub fn tidy(v: &mut toml::Value) {
    match v {
        toml::Value::Float(x) => *x = significant(*x),
        toml::Value::Table(t) => t.iter_mut().for_each(|(_, v)| tidy(v)),
        toml::Value::Array(a) => {
            let largest =
                a.iter().filter_map(toml::Value::as_float).fold(0.0, |m: f64, x| m.max(x.abs()));
            for e in a.iter_mut() {
                match e {
                    toml::Value::Float(x) if x.abs() < NOISE * largest => *x = 0.0,
                    e => tidy(e),
                }
            }
        }
        _ => {}
    }
}

/// `x` rounded to [`DIGITS`] significant digits.
fn significant(x: f64) -> f64 {
    if !x.is_finite() || x == 0.0 {
        return x;
    }
    format!("{:.*e}", DIGITS - 1, x).parse().unwrap_or(x)
}
