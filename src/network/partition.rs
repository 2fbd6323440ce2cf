//! Breakpoints of one direction of a curve network, the quantities h, σ, σ′ of eq. (8), and quadratic
//! C¹ splines on them in Bézier form.

use super::MAX_BREAKPOINTS;
use crate::error::{Error, Result};
use crate::point::Point;

/// Breakpoints x_0 < … < x_m of one direction and the quantities of eq. (8).
///
/// `h(r)` = x_r − x_{r−1} for r = 1..m and 0 for r = 0, m+1; `sigma(r)` = h_r/(h_{r−1}+h_r),
/// `sigma_p(r)` = h_{r−1}/(h_{r−1}+h_r) for r = 1..m+1. The quadratic B-splines B_i(x|X), i = 0..m+1, live
/// on X = {x_0,x_0,x_0,x_1,…,x_{m−1},x_m,x_m,x_m}; B_i has support [x_{i−2}, x_{i+1}] and
/// B_r(x_r) = σ_{r+1}, B_{r+1}(x_r) = σ′_{r+1}.
#[derive(Debug, Clone, PartialEq)]
pub struct Partition {
    x: Vec<f64>,
    /// h[r], r = 0..=m+1.
    h: Vec<f64>,
    /// sigma[r], r = 0..=m+1 (entry 0 unused, 0).
    sigma: Vec<f64>,
    sigma_p: Vec<f64>,
}

impl Partition {
    /// Validates the breakpoints (at least 2, finite, strictly increasing, at most [`MAX_BREAKPOINTS`]).
    pub fn new(field: &'static str, x: &[f64]) -> Result<Self> {
        if x.len() < 2 {
            return Err(Error::too_few_of(
                field,
                2,
                x.len(),
                format!("need at least 2 breakpoints, got {}", x.len()),
            ));
        }
        if x.len() > MAX_BREAKPOINTS {
            return Err(Error::too_many_of(
                field,
                MAX_BREAKPOINTS,
                x.len(),
                format!("at most {MAX_BREAKPOINTS} breakpoints, got {}", x.len()),
            ));
        }
        crate::error::check_finite(field, x)?;
        crate::knots::check_increasing(field, x)?;
        // cells narrower than 1e-12 × the range make σ, τ and gradients overflow (robustness bug 11)
        crate::knots::check_separated(field, x)?;
        let m = x.len() - 1;
        let mut h = vec![0.0; m + 2];
        for r in 1..=m {
            h[r] = x[r] - x[r - 1];
        }
        let mut sigma = vec![0.0; m + 2];
        let mut sigma_p = vec![0.0; m + 2];
        for r in 1..=m + 1 {
            let d = h[r - 1] + h[r];
            sigma[r] = h[r] / d;
            sigma_p[r] = h[r - 1] / d;
        }
        Ok(Partition {
            x: x.to_vec(),
            h,
            sigma,
            sigma_p,
        })
    }

    /// Number of cells m.
    pub fn cells(&self) -> usize {
        self.x.len() - 1
    }
    /// The breakpoints x_0..x_m.
    pub fn breaks(&self) -> &[f64] {
        &self.x
    }
    /// `[x_0, x_m]`.
    pub fn domain(&self) -> (f64, f64) {
        (self.x[0], self.x[self.x.len() - 1])
    }
    /// h_r (0 for r = 0 and r > m).
    pub fn h(&self, r: usize) -> f64 {
        self.h.get(r).copied().unwrap_or(0.0)
    }
    /// σ_r, r = 1..m+1 (0 elsewhere).
    pub fn sigma(&self, r: usize) -> f64 {
        self.sigma.get(r).copied().unwrap_or(0.0)
    }
    /// σ′_r, r = 1..m+1 (0 elsewhere).
    pub fn sigma_p(&self, r: usize) -> f64 {
        self.sigma_p.get(r).copied().unwrap_or(0.0)
    }
    /// The full quadratic knot vector X (length m + 5).
    pub fn knots(&self) -> Vec<f64> {
        let (a, b) = self.domain();
        let mut k = vec![a, a];
        k.extend_from_slice(&self.x);
        k.push(b);
        k.push(b);
        k
    }
    /// Greville abscissae ξ_i = (x_{i−1} + x_i)/2, i = 0..m+1 (ξ_0 = x_0, ξ_{m+1} = x_m), eqs. (4)–(5).
    pub fn greville(&self) -> Vec<f64> {
        let m = self.cells();
        (0..=m + 1)
            .map(|i| 0.5 * (self.x[i.saturating_sub(1)] + self.x[i.min(m)]))
            .collect()
    }

    /// Cell a (1..=m) with x_{a−1} ≤ t < x_a (last cell closed) and the local s = (t − x_{a−1})/h_a.
    /// Parameters outside the domain use the first/last cell (s outside [0, 1]: polynomial extension).
    pub fn locate(&self, t: f64) -> (usize, f64) {
        let m = self.cells();
        // number of breakpoints x_1..x_{m−1} that are ≤ t
        let a = 1 + self.x[1..m].partition_point(|&b| b <= t);
        let a = a.min(m);
        (a, (t - self.x[a - 1]) / self.h[a])
    }

    /// Bernstein coefficients (α0, α1, α2) of B_i(x|X) on cell a (`surfaces.md` §2.3 table):
    /// a = i−1: (0, 0, σ′_i); a = i: (σ′_i, 1, σ_{i+1}); a = i+1: (σ_{i+1}, 0, 0); otherwise 0.
    pub fn bernstein(&self, i: usize, a: usize) -> [f64; 3] {
        if a + 1 == i {
            [0.0, 0.0, self.sigma_p(i)]
        } else if a == i {
            [self.sigma_p(i), 1.0, self.sigma(i + 1)]
        } else if a == i + 1 {
            [self.sigma(i + 1), 0.0, 0.0]
        } else {
            [0.0; 3]
        }
    }

    /// B_i(t|X) and its derivative.
    pub fn basis(&self, i: usize, t: f64) -> [f64; 2] {
        let (a, s) = self.locate(t);
        let c = self.bernstein(i, a);
        bezier2(&c, s, self.h[a])
    }

    /// The Bézier ordinates of the quadratic spline Σ ctrl_i B_i on cell a (1..=m):
    /// (σ_a c_{a−1} + σ′_a c_a, c_a, σ_{a+1} c_a + σ′_{a+1} c_{a+1}). `ctrl.len()` must be m + 2.
    pub(crate) fn bezier_ordinates<P: Point>(&self, ctrl: &[P], a: usize) -> [P; 3] {
        let g = |k: usize| ctrl.get(k).copied().unwrap_or(P::ZERO);
        let prev = a
            .checked_sub(1)
            .and_then(|k| ctrl.get(k))
            .copied()
            .unwrap_or(P::ZERO);
        [
            prev * self.sigma(a) + g(a) * self.sigma_p(a),
            g(a),
            g(a) * self.sigma(a + 1) + g(a + 1) * self.sigma_p(a + 1),
        ]
    }

    /// Value and derivative of Σ ctrl_i B_i(t|X) (`ctrl.len()` = m + 2).
    pub(crate) fn eval_spline<P: Point>(&self, ctrl: &[P], t: f64) -> [P; 2] {
        let (a, s) = self.locate(t);
        bezier2(&self.bezier_ordinates(ctrl, a), s, self.h[a])
    }

    /// The spline's value at the breakpoint x_r: σ_{r+1} c_r + σ′_{r+1} c_{r+1} (r = 0..m).
    pub(crate) fn value_at_break<P: Point>(&self, ctrl: &[P], r: usize) -> P {
        let g = |k: usize| ctrl.get(k).copied().unwrap_or(P::ZERO);
        g(r) * self.sigma(r + 1) + g(r + 1) * self.sigma_p(r + 1)
    }
}

/// Quadratic Bézier value and derivative (w.r.t. the global parameter; cell length `h`) at local `s`.
fn bezier2<P: Point>(b: &[P; 3], s: f64, h: f64) -> [P; 2] {
    let r = 1.0 - s;
    let val = b[0] * (r * r) + b[1] * (2.0 * r * s) + b[2] * (s * s);
    let der = ((b[1] - b[0]) * r + (b[2] - b[1]) * s) * (2.0 / h);
    [val, der]
}
