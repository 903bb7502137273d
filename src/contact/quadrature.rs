//! Gauss-Legendre quadrature nodes and weights on [-1, 1].
//!
//! The nodes are the roots of the Legendre polynomial P_n, found by Newton's
//! method from Tricomi's initial guess x_i ~ cos(pi (i - 1/4) / (n + 1/2)),
//! with P_n and P_n' from the three-term recurrence
//! (k+1) P_(k+1) = (2k+1) x P_k - k P_(k-1); the weights are
//! w_i = 2 / ((1 - x_i^2) P_n'(x_i)^2) (Abramowitz & Stegun 25.4.29).
//! An n-point rule integrates polynomials of degree 2n - 1 exactly.

use std::cell::RefCell;
use std::f64::consts::PI;
use std::rc::Rc;

/// An n-point Gauss-Legendre rule on [-1, 1]: (nodes, weights).
pub fn gauss_legendre(n: usize) -> (Vec<f64>, Vec<f64>) {
    let mut nodes = vec![0.0; n];
    let mut weights = vec![0.0; n];
    for i in 0..n.div_ceil(2) {
        let mut x = (PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
        let mut dp = 0.0;
        for _ in 0..100 {
            let (p, d) = legendre(n, x);
            dp = d;
            let dx = p / d;
            x -= dx;
            if dx.abs() < 1e-16 {
                break;
            }
        }
        let w = 2.0 / ((1.0 - x * x) * dp * dp);
        nodes[i] = -x;
        nodes[n - 1 - i] = x;
        weights[i] = w;
        weights[n - 1 - i] = w;
    }
    (nodes, weights)
}

/// P_n(x) and P_n'(x) by the three-term recurrence.
fn legendre(n: usize, x: f64) -> (f64, f64) {
    let (mut p0, mut p1) = (1.0, x);
    for k in 1..n {
        let k = k as f64;
        let p2 = ((2.0 * k + 1.0) * x * p1 - k * p0) / (k + 1.0);
        p0 = p1;
        p1 = p2;
    }
    if n == 0 {
        return (1.0, 0.0);
    }
    let d = n as f64 * (x * p1 - p0) / (x * x - 1.0);
    (p1, d)
}

/// The rule mapped to [lo, hi]: (nodes, weights). The rule on [-1, 1] is
/// computed once per n and thread (the stress check maps the same two rules
/// onto thousands of intervals).
pub fn gauss_on(n: usize, lo: f64, hi: f64) -> Vec<(f64, f64)> {
    thread_local! {
        static RULES: RefCell<Vec<(usize, Rc<Rule>)>> = const { RefCell::new(Vec::new()) };
    }
    let rule = RULES.with(|rules| {
        let mut rules = rules.borrow_mut();
        if let Some((_, r)) = rules.iter().find(|(k, _)| *k == n) {
            return Rc::clone(r);
        }
        let r = Rc::new(gauss_legendre(n));
        rules.push((n, Rc::clone(&r)));
        r
    });
    let (x, w) = &*rule;
    let (m, h) = (0.5 * (lo + hi), 0.5 * (hi - lo));
    x.iter().zip(w).map(|(x, w)| (m + h * x, h * w)).collect()
}

/// Nodes and weights of a rule on [-1, 1].
type Rule = (Vec<f64>, Vec<f64>);

/// Golden-section search for the maximum of a unimodal `f` on [lo, hi],
/// to an interval width `tol`: (argmax, max).
pub fn golden_max(f: impl Fn(f64) -> f64, mut lo: f64, mut hi: f64, tol: f64) -> (f64, f64) {
    let g = 0.5 * (5f64.sqrt() - 1.0);
    let mut x1 = hi - g * (hi - lo);
    let mut x2 = lo + g * (hi - lo);
    let (mut f1, mut f2) = (f(x1), f(x2));
    while hi - lo > tol {
        if f1 < f2 {
            lo = x1;
            x1 = x2;
            f1 = f2;
            x2 = lo + g * (hi - lo);
            f2 = f(x2);
        } else {
            hi = x2;
            x2 = x1;
            f2 = f1;
            x1 = hi - g * (hi - lo);
            f1 = f(x1);
        }
    }
    let z = 0.5 * (lo + hi);
    (z, f(z))
}
