//! The criss-cross triangulation T_mn of U × V and its C¹ quadratic B-splines B_ij (eq. (23)).

use super::cell::*;
use crate::error::Result;
use crate::network::Partition;
use crate::point::Point;

/// The criss-cross triangulation T_mn of U × V and its B-splines B_ij.
#[derive(Debug, Clone, PartialEq)]
pub struct CrissCross {
    pu: Partition,
    pv: Partition,
}

impl CrissCross {
    /// The triangulation on the breakpoints `u` (u_0..u_m) and `v` (v_0..v_n).
    pub fn new(u: &[f64], v: &[f64]) -> Result<Self> {
        Ok(CrissCross {
            pu: Partition::new("u", u)?,
            pv: Partition::new("v", v)?,
        })
    }
    /// From validated partitions.
    pub fn from_partitions(pu: Partition, pv: Partition) -> Self {
        CrissCross { pu, pv }
    }
    /// The partition in u.
    pub fn u(&self) -> &Partition {
        &self.pu
    }
    /// The partition in v.
    pub fn v(&self) -> &Partition {
        &self.pv
    }
    /// (m, n).
    pub fn cells(&self) -> (usize, usize) {
        (self.pu.cells(), self.pv.cells())
    }
    /// The parameter rectangle.
    pub fn domain(&self) -> ((f64, f64), (f64, f64)) {
        (self.pu.domain(), self.pv.domain())
    }

    /// Cell (a, b) and local (s, t) of (u, v).
    pub fn locate(&self, u: f64, v: f64) -> (usize, usize, f64, f64) {
        let (a, s) = self.pu.locate(u);
        let (b, t) = self.pv.locate(v);
        (a, b, s, t)
    }

    /// Closed-form BB net of B_ij on cell (a, b) (`surfaces.md` §2.3); all zeros outside the support.
    pub fn basis_net(&self, i: usize, j: usize, a: usize, b: usize) -> CellNet<f64> {
        let al = self.pu.bernstein(i, a);
        let be = self.pv.bernstein(j, b);
        cell_net_from_edges(
            [al[0] * be[0], al[2] * be[0], al[2] * be[2], al[0] * be[2]],
            [al[1] * be[0], al[2] * be[1], al[1] * be[2], al[0] * be[1]],
        )
    }

    /// B_ij(u, v), ∂B_ij/∂u, ∂B_ij/∂v (i = 0..m+1, j = 0..n+1; 0 for other indices).
    pub fn basis(&self, i: usize, j: usize, u: f64, v: f64) -> [f64; 3] {
        let (a, b, s, t) = self.locate(u, v);
        let net = self.basis_net(i, j, a, b);
        let [f, fs, ft] = eval_cell_net(&net, s, t);
        [f, fs / self.pu.h(a), ft / self.pv.h(b)]
    }

    /// The BB net of Σ C_ij B_ij on cell (a, b); `ctrl[i * (n+2) + j]` = C_ij.
    pub(crate) fn combination_net<P: Point>(&self, ctrl: &[P], a: usize, b: usize) -> CellNet<P> {
        let nv = self.pv.cells() + 2;
        let mut net = [P::ZERO; 13];
        for i in a - 1..=a + 1 {
            for j in b - 1..=b + 1 {
                let c = match ctrl.get(i * nv + j) {
                    Some(c) if j < nv => *c,
                    _ => continue,
                };
                let bn = self.basis_net(i, j, a, b);
                for k in 0..13 {
                    net[k] += c * bn[k];
                }
            }
        }
        net
    }

    /// Evaluates a piecewise quadratic given by its cell nets (`nets[(a−1)·n + b−1]`) with gradient.
    pub(crate) fn eval_nets<P: Point>(
        &self,
        nets: &[CellNet<P>],
        u: f64,
        v: f64,
        derivs: bool,
        out: &mut [P; 3],
    ) {
        let (a, b, s, t) = self.locate(u, v);
        let n = self.pv.cells();
        let Some(net) = nets.get((a - 1) * n + (b - 1)) else {
            return;
        };
        let [f, fs, ft] = eval_cell_net(net, s, t);
        out[0] = f;
        if derivs {
            out[1] = fs * (1.0 / self.pu.h(a));
            out[2] = ft * (1.0 / self.pv.h(b));
        }
    }
}
