//! Σ C_ij B_ij for given control points (eq. (13)), evaluated through its cell nets.

use super::cell::CellNet;
use super::triangulation::CrissCross;
use crate::error::{Error, Result};
use crate::point::Point;
use crate::sample::Surface;

/// Σ C_ij B_ij for given control points (eq. (13)), evaluated through its cell nets.
#[derive(Debug, Clone, PartialEq)]
pub struct CrissCrossSpline<P: Point> {
    cc: CrissCross,
    ctrl: Vec<P>,
    nets: Vec<CellNet<P>>,
}

impl<P: Point> CrissCrossSpline<P> {
    /// `ctrl[i * (n+2) + j]` = C_ij, (m+2)(n+2) finite points.
    pub fn new(cc: CrissCross, ctrl: Vec<P>) -> Result<Self> {
        let (m, n) = cc.cells();
        if ctrl.len() != (m + 2) * (n + 2) {
            return Err(Error::size_mismatch(
                "C",
                format!(
                    "expected (m+2)(n+2) = {} control points, got {}",
                    (m + 2) * (n + 2),
                    ctrl.len()
                ),
            ));
        }
        if let Some(k) = ctrl.iter().position(|c| !c.is_finite()) {
            return Err(Error::not_finite(
                format!("C[{}][{}]", k / (n + 2), k % (n + 2)),
                "expected finite coordinates",
            ));
        }
        let mut nets = Vec::with_capacity(m * n);
        for a in 1..=m {
            for b in 1..=n {
                nets.push(cc.combination_net(&ctrl, a, b));
            }
        }
        Ok(CrissCrossSpline { cc, ctrl, nets })
    }
    /// Σ C_ij B_ij with cell nets computed elsewhere (S's local form: the same surface up to rounding), not
    /// checked; `nets[(a−1)·n + b−1]`.
    pub(crate) fn with_nets(cc: CrissCross, ctrl: Vec<P>, nets: Vec<CellNet<P>>) -> Self {
        CrissCrossSpline { cc, ctrl, nets }
    }
    /// The triangulation the spline lives on.
    pub fn triangulation(&self) -> &CrissCross {
        &self.cc
    }
    /// The B-spline coefficients, index `i * (n + 2) + j`.
    pub fn control_points(&self) -> &[P] {
        &self.ctrl
    }
    /// BB net of cell (a, b), a = 1..m, b = 1..n.
    pub fn cell_net(&self, a: usize, b: usize) -> Option<&CellNet<P>> {
        let n = self.cc.cells().1;
        if a == 0 || b == 0 || b > n {
            return None;
        }
        self.nets.get((a - 1) * n + (b - 1))
    }
}

impl<P: Point> Surface<P> for CrissCrossSpline<P> {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        self.cc.domain()
    }
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [P; 3]) {
        self.cc.eval_nets(&self.nets, u, v, derivs, out)
    }
}
