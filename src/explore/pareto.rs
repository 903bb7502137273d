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
    fn values(&self, with_safety: bool) -> Vec<f64> {
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

/// Per design: on the front (`Some(true)`), dominated (`Some(false)`), or
/// not evaluated (`None` in, `false` out). The safety-factor objective
/// takes part only if some evaluated design has one.
pub fn front(designs: &[Option<Objectives>]) -> Vec<bool> {
    let with_safety = designs.iter().flatten().any(|o| o.safety_factor.is_some());
    let vals: Vec<Option<Vec<f64>>> = designs
        .iter()
        .map(|o| o.map(|o| o.values(with_safety)))
        .collect();
    vals.iter()
        .map(|a| match a {
            None => false,
            Some(a) => !vals.iter().flatten().any(|b| dominates(b, a)),
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    fn o(s: f64, k: f64, sf: f64) -> Option<Objectives> {
        Some(Objectives {
            sigma_max: s,
            stiffness_min: k,
            safety_factor: Some(sf),
        })
    }

    #[test]
    fn a_hand_checked_front() {
        // 0: best sigma; 1: dominated by 0 (worse sigma, same k and SF);
        // 2: best stiffness; 3: equal to 0 on all (neither dominates);
        // 4: not evaluated.
        let d = [
            o(1.0, 5.0, 2.0),
            o(2.0, 5.0, 2.0),
            o(3.0, 9.0, 1.0),
            o(1.0, 5.0, 2.0),
            None,
        ];
        assert_eq!(front(&d), vec![true, false, true, true, false]);
    }

    #[test]
    fn every_dominated_design_is_beaten_by_one_on_the_front() {
        // A deterministic cloud of designs (a Weyl sequence).
        let d: Vec<_> = (0..60)
            .map(|i| {
                let f = |a: f64| (i as f64 * a).fract();
                o(f(0.618), f(0.414), f(0.732))
            })
            .collect();
        let on = front(&d);
        let v: Vec<Vec<f64>> = d.iter().map(|x| x.unwrap().values(true)).collect();
        for (i, a) in v.iter().enumerate() {
            if on[i] {
                assert!(!v.iter().any(|b| dominates(b, a)));
            } else {
                assert!(v.iter().zip(&on).any(|(b, f)| *f && dominates(b, a)));
            }
        }
        assert!(on.iter().any(|x| *x) && on.iter().any(|x| !*x));
    }
}
