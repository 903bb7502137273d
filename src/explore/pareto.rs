//! The Pareto front of a sweep: the designs that no other design dominates
//! on the three objectives (Deb 2001, "Multi-objective optimization using
//! evolutionary algorithms", def. 2.5): the largest translational sigma at
//! the chosen evaluation point (lower is better), the lowest principal
//! translational stiffness (higher is better) and the smallest pressure
//! safety factor (higher is better). Design b dominates a if b is no worse
//! on every objective and better on at least one.

/// The objectives of one design, oriented so that larger is better.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Objectives {
    /// Largest of sigma_x, sigma_y, sigma_z at the chosen point [m].
    pub sigma_max: f64,
    /// Lowest principal translational stiffness [N/m].
    pub stiffness_min: f64,
    /// Smallest pressure safety factor (None: no allowable pressure known;
    /// then the objective is left out for every design).
    pub safety_factor: Option<f64>,
}

impl Objectives {
    pub fn values(&self, with_safety: bool) -> Vec<f64> {
        let mut v = vec![-self.sigma_max, self.stiffness_min];
        if with_safety {
            v.push(self.safety_factor.unwrap_or(f64::NEG_INFINITY));
        }
        v
    }
}

/// True if `b` dominates `a` (both oriented larger-is-better).
pub fn dominates(b: &[f64], a: &[f64]) -> bool {
    b.iter().zip(a).all(|(b, a)| b >= a) && b.iter().zip(a).any(|(b, a)| b > a)
}

/// Per design: on the front (`true`) or not; a design without values
/// (`None`: not evaluated, infeasible) is never on it and dominates none.
pub fn front_of(values: &[Option<Vec<f64>>]) -> Vec<bool> {
    values
        .iter()
        .map(|a| match a {
            None => false,
            Some(a) => !values.iter().flatten().any(|b| dominates(b, a)),
        })
        .collect()
}
