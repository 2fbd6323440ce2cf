//! The criss-cross triangulation T_mn of U × V and its C¹ quadratic B-splines B_ij (eq. (23)).

use super::cell::*;
use crate::error::Result;
use crate::mesh::Mesh;
use crate::network::Partition;
use crate::point::Point;

/// Samples of one B_ij ([`CrissCross::sample_basis`]): values and, when asked for, the two partials.
#[derive(Debug, Clone, PartialEq)]
pub struct BasisSamples {
    /// B_ij at each (u, v).
    pub values: Vec<f64>,
    /// ∂B_ij/∂u at each (u, v) (empty without partials).
    pub du: Vec<f64>,
    /// ∂B_ij/∂v at each (u, v) (empty without partials).
    pub dv: Vec<f64>,
}

impl BasisSamples {
    /// Render buffers of the graph (u, v, B_ij(u, v)) on the u-major `nu × nv` grid `uv` the samples were
    /// taken at ([`Mesh::from_graph`]; the samples must have their partials).
    pub fn graph_mesh(&self, uv: &[f64], nu: usize, nv: usize) -> Result<Mesh> {
        Mesh::from_graph(uv, &self.values, (&self.du, &self.dv), nu, nv)
    }
}

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

    /// B_ij and (when `partials`) ∂B_ij/∂u, ∂B_ij/∂v at the flat (u, v) pairs `uv` ([`CrissCross::basis`]
    /// at each pair; `du`, `dv` empty without `partials`).
    pub fn sample_basis(&self, i: usize, j: usize, uv: &[f64], partials: bool) -> BasisSamples {
        let count = uv.len() / 2;
        let mut values = Vec::with_capacity(count);
        let (mut du, mut dv) = (Vec::new(), Vec::new());
        if partials {
            du.reserve(count);
            dv.reserve(count);
        }
        for w in uv.chunks_exact(2) {
            let [f, fu, fv] = self.basis(i, j, w[0], w[1]);
            values.push(f);
            if partials {
                du.push(fu);
                dv.push(fv);
            }
        }
        BasisSamples { values, du, dv }
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sampled_bases_sum_to_one_with_zero_gradient() {
        // partition of unity Σ_ij B_ij = 1, hence Σ ∂B_ij/∂u = Σ ∂B_ij/∂v = 0 (§2.4)
        let cc = CrissCross::new(&[0.0, 0.3, 0.5, 1.2], &[0.0, 0.4, 1.0, 1.5, 2.0]).unwrap();
        let uv = [0.0, 0.0, 0.1, 0.7, 0.45, 1.9, 0.9, 1.2, 1.2, 2.0];
        let (mut f, mut fu, mut fv) = ([0.0; 5], [0.0; 5], [0.0; 5]);
        for i in 0..5 {
            for j in 0..6 {
                let b = cc.sample_basis(i, j, &uv, true);
                assert_eq!((b.values.len(), b.du.len(), b.dv.len()), (5, 5, 5));
                for k in 0..5 {
                    f[k] += b.values[k];
                    fu[k] += b.du[k];
                    fv[k] += b.dv[k];
                }
            }
        }
        for k in 0..5 {
            assert!((f[k] - 1.0).abs() < 1e-14, "{f:?}");
            assert!(fu[k].abs() < 1e-12 && fv[k].abs() < 1e-12, "{fu:?} {fv:?}");
        }
    }

    #[test]
    fn corner_basis_at_the_corner_and_without_partials() {
        // on the bottom edge B_00(u, v_0) = B_0(u) = (1 − (u − u_0)/h_1)² on the first cell (eq. (23)), so
        // B_00(u_0, v_0) = 1, ∂u = −2/h_1, and likewise ∂v = −2/k_1
        let cc = CrissCross::new(&[1.0, 1.25, 2.0], &[0.0, 0.5, 3.0]).unwrap();
        let b = cc.sample_basis(0, 0, &[1.0, 0.0, 1.125, 0.0], true);
        assert_eq!(b.values[0], 1.0);
        assert!((b.du[0] + 8.0).abs() < 1e-12 && (b.dv[0] + 4.0).abs() < 1e-12);
        assert!((b.values[1] - 0.25).abs() < 1e-15); // s = ½: (1 − ½)²
        let plain = cc.sample_basis(0, 0, &[1.0, 0.0, 1.125, 0.0], false);
        assert_eq!(plain.values, b.values);
        assert!(plain.du.is_empty() && plain.dv.is_empty());
    }
}
