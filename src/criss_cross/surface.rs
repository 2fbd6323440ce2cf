//! The surface S through a compatible curve network (Thm 3.2): coefficients (18)–(21), the free C11
//! (default, area-minimising, closed form) and the local cell form.

use super::cell::*;
use super::spline::CrissCrossSpline;
use super::triangulation::CrissCross;
use crate::error::Result;
use crate::network::{Network, COMPATIBILITY_TOL};
use crate::sample::Surface;
use glam::DVec3;

/// The DLR surface S through a compatible network (Thm 3.2), by the local cell form.
///
/// # Template
/// * **What**: the surface S = Σ C_ij B_ij of Dagnino–Lamberti–Remogna (Thm 3.2): C¹ quadratic
///   B-splines B_ij on the criss-cross triangulation of the network's grid, coefficients (18)–(21). S does
///   not depend on the free C11 (the B_ij are linearly dependent), so it is built by its local cell form.
/// * **Interpolates**: every curve of a compatible network, S(u_r, v) = φ_r(v), S(u, v_s) = ψ_s(u).
/// * **Continuity**: C¹ (piecewise quadratic on the triangles).
/// * **Parametrisation**: the network's breakpoints, (u, v) ∈ [u_0, u_m] × [v_0, v_n].
///
/// # Example
/// ```
/// use splinelab::{network::examples, Surface, criss_cross::CrissCrossSurface};
/// let net = examples::uniform_dome();
/// let s = CrissCrossSurface::new(&net)?;
/// assert_eq!(s.domain(), ((net.u[0], net.u[3]), (net.v[0], net.v[3])));
/// // through every network curve: S(u_r, v) = φ_r(v), S(u, v_s) = ψ_s(u)
/// for r in 0..net.u.len() {
///     for v in [0.1, 0.45, 0.8] {
///         assert!((s.eval(net.u[r], v) - net.phi(r, v)[0]).length() < 1e-12);
///     }
/// }
/// for (sv, &v) in net.v.iter().enumerate() {
///     assert!((s.eval(0.3, v) - net.psi(sv, 0.3)[0]).length() < 1e-12);
/// }
/// # Ok::<(), splinelab::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct CrissCrossSurface {
    network: Network,
    cc: CrissCross,
    nets: Vec<CellNet<DVec3>>,
}

impl CrissCrossSurface {
    /// Checks shape and compatibility (C2 residual ≤ 1e-12·max(1, scale)) and builds S.
    pub fn new(network: &Network) -> Result<Self> {
        Self::with_tolerance(network, COMPATIBILITY_TOL)
    }

    /// Like [`CrissCrossSurface::new`] with a custom relative C2 tolerance.
    pub fn with_tolerance(network: &Network, rel_tol: f64) -> Result<Self> {
        network.check_compatible(rel_tol)?;
        let (pu, pv) = network.partitions()?;
        let nodes = network.intersections()?;
        let (m, n) = (pu.cells(), pv.cells());
        let mut nets = Vec::with_capacity(m * n);
        for a in 1..=m {
            for b in 1..=n {
                let corners = [
                    nodes[a - 1][b - 1],
                    nodes[a][b - 1],
                    nodes[a][b],
                    nodes[a - 1][b],
                ];
                let edges = [
                    network.q[b - 1][a],
                    network.p[a][b],
                    network.q[b][a],
                    network.p[a - 1][b],
                ];
                nets.push(cell_net_from_edges(corners, edges));
            }
        }
        Ok(CrissCrossSurface {
            network: network.clone(),
            cc: CrissCross::from_partitions(pu, pv),
            nets,
        })
    }

    /// The interpolated curve network.
    pub fn network(&self) -> &Network {
        &self.network
    }
    /// The criss-cross triangulation of the network’s grid.
    pub fn triangulation(&self) -> &CrissCross {
        &self.cc
    }
    /// The local-form BB net of cell (a, b) (a = 1..m, b = 1..n).
    pub fn cell_net(&self, a: usize, b: usize) -> Option<&CellNet<DVec3>> {
        let n = self.cc.cells().1;
        if a == 0 || b == 0 || b > n {
            return None;
        }
        self.nets.get((a - 1) * n + (b - 1))
    }

    /// The local-form BB nets of all cells, `[(a−1)·n + b−1]`.
    pub(crate) fn cell_nets(&self) -> &[CellNet<DVec3>] {
        &self.nets
    }

    /// Control points C_ij (i-major, index i·(n+2)+j) of Lemma 3.1 for `c11`: boundary rows/columns from
    /// (18)–(21), column i = 1 from (17): C_{1,s+1} = (Q_1^{(s)} − τ_{s+1}C_{1,s})/τ′_{s+1}, then
    /// (16): C_{r+1,j} = (P_j^{(r)} − σ_{r+1}C_{r,j})/σ′_{r+1}.
    pub fn control_points(&self, c11: DVec3) -> Vec<DVec3> {
        let (pu, pv) = (self.cc.u(), self.cc.v());
        let (m, n) = self.cc.cells();
        let nv = n + 2;
        let (p, q) = (&self.network.p, &self.network.q);
        let mut c = vec![DVec3::ZERO; (m + 2) * nv];
        boundary_control_points(&mut c, p, q, m, n);
        c[nv + 1] = c11;
        for s in 1..n {
            c[nv + s + 1] = (q[s][1] - c[nv + s] * pv.sigma(s + 1)) * (1.0 / pv.sigma_p(s + 1));
        }
        for r in 1..m {
            for j in 1..=n {
                c[(r + 1) * nv + j] =
                    (p[r][j] - c[r * nv + j] * pu.sigma(r + 1)) * (1.0 / pu.sigma_p(r + 1));
            }
        }
        c
    }

    /// The same control points by the closed form (26)–(27):
    /// C_ij = Γ_ij + (−1)^{i+j} C11 h_i k_j/(h_1 k_1).
    pub fn control_points_closed_form(&self, c11: DVec3) -> Vec<DVec3> {
        let (pu, pv) = (self.cc.u(), self.cc.v());
        let (m, n) = self.cc.cells();
        let nv = n + 2;
        let (p, q) = (&self.network.p, &self.network.q);
        let mut c = vec![DVec3::ZERO; (m + 2) * nv];
        boundary_control_points(&mut c, p, q, m, n);
        let (h, k) = (|r: usize| pu.h(r), |s: usize| pv.h(s));
        for i in 1..=m {
            for j in 1..=n {
                let mut g = DVec3::ZERO;
                for r in 1..i {
                    let sign = if (r + 1) % 2 == 0 { 1.0 } else { -1.0 };
                    let w = (h(i - r) + h(i - r + 1)) * h(i) / (h(i - r) * h(i - r + 1));
                    g += p[i - r][j] * (sign * w);
                }
                let mut g2 = DVec3::ZERO;
                for s in 1..j {
                    let sign = if s % 2 == 0 { 1.0 } else { -1.0 };
                    let w = (k(j - s) + k(j - s + 1)) * k(j) / (k(j - s) * k(j - s + 1));
                    g2 += q[j - s][1] * (sign * w);
                }
                let si = if i % 2 == 0 { 1.0 } else { -1.0 };
                g += g2 * (si * h(i) / h(1));
                let sij = if (i + j) % 2 == 0 { 1.0 } else { -1.0 };
                c[i * nv + j] = g + c11 * (sij * h(i) * k(j) / (h(1) * k(1)));
            }
        }
        c
    }

    /// The weights w_ij = (−1)^{i+j} h_i k_j/(h_1 k_1) of C11 in (26) (0 on the boundary), i-major.
    pub(crate) fn c11_weights(&self) -> Vec<f64> {
        c11_weights(&self.cc)
    }

    /// Default C11: minimises Σ over control-net edges of |C_a − C_b|² (closed form, per coordinate):
    /// with C = Γ + x w, x = −Σ (Γ_a − Γ_b)(w_a − w_b) / Σ (w_a − w_b)².
    pub fn default_c11(&self) -> DVec3 {
        let g = self.control_points(DVec3::ZERO);
        let w = self.c11_weights();
        let (m, n) = self.cc.cells();
        let nv = n + 2;
        let (mut num, mut den) = (DVec3::ZERO, 0.0);
        let mut edge = |a: usize, b: usize| {
            let dw = w[a] - w[b];
            num += (g[a] - g[b]) * dw;
            den += dw * dw;
        };
        for i in 0..m + 2 {
            for j in 0..nv {
                if i + 1 < m + 2 {
                    edge(i * nv + j, (i + 1) * nv + j);
                }
                if j + 1 < nv {
                    edge(i * nv + j, i * nv + j + 1);
                }
            }
        }
        if den > 0.0 {
            -num * (1.0 / den)
        } else {
            DVec3::ZERO
        }
    }

    /// The paper's choice (§4.1): C11 minimising the area of the bilinear surface of the control net,
    /// A(C11) = Σ_quads ∫∫ |X_s × X_t| ds dt (4×4 Gauss–Legendre per quad). With C = Γ + x w the normal
    /// X_s × X_t = N0 − \[c\]_× x is affine in x, so A is convex; it is minimised by Newton's method with a
    /// damped step (`newton_min_area`) from [`CrissCrossSurface::default_c11`], which it returns when the Hessian
    /// is singular.
    pub fn min_area_c11(&self) -> DVec3 {
        let g = self.control_points(DVec3::ZERO);
        let w = self.c11_weights();
        let (m, n) = self.cc.cells();
        let nv = n + 2;
        const G4: [(f64, f64); 4] = [
            (0.069_431_844_202_973_71, 0.173_927_422_568_726_93),
            (0.330_009_478_207_571_9, 0.326_072_577_431_273_07),
            (0.669_990_521_792_428_1, 0.326_072_577_431_273_07),
            (0.930_568_155_797_026_3, 0.173_927_422_568_726_93),
        ];
        // per quadrature point: (weight, N0, c)
        let mut terms: Vec<(f64, DVec3, DVec3)> = Vec::with_capacity((m + 1) * (n + 1) * 16);
        for i in 0..=m {
            for j in 0..=n {
                let k = |a: usize, b: usize| (i + a) * nv + j + b;
                for &(s, ws) in &G4 {
                    for &(t, wt) in &G4 {
                        let gs =
                            (g[k(1, 0)] - g[k(0, 0)]) * (1.0 - t) + (g[k(1, 1)] - g[k(0, 1)]) * t;
                        let gt =
                            (g[k(0, 1)] - g[k(0, 0)]) * (1.0 - s) + (g[k(1, 1)] - g[k(1, 0)]) * s;
                        let a_s =
                            (w[k(1, 0)] - w[k(0, 0)]) * (1.0 - t) + (w[k(1, 1)] - w[k(0, 1)]) * t;
                        let a_t =
                            (w[k(0, 1)] - w[k(0, 0)]) * (1.0 - s) + (w[k(1, 1)] - w[k(1, 0)]) * s;
                        terms.push((ws * wt, gs.cross(gt), gt * a_s - gs * a_t));
                    }
                }
            }
        }
        let scale = g.iter().map(|p| p.abs().max_element()).fold(1.0, f64::max);
        newton_min_area(&terms, self.default_c11(), scale)
    }

    /// The area of the bilinear control-net surface for `c11` (same quadrature as
    /// [`CrissCrossSurface::min_area_c11`]).
    pub fn control_net_area(&self, c11: DVec3) -> f64 {
        let c = self.control_points(c11);
        let (m, n) = self.cc.cells();
        let nv = n + 2;
        let gauss = [
            0.069_431_844_202_973_71,
            0.330_009_478_207_571_9,
            0.669_990_521_792_428_1,
            0.930_568_155_797_026_3,
        ];
        let wts = [
            0.173_927_422_568_726_93,
            0.326_072_577_431_273_07,
            0.326_072_577_431_273_07,
            0.173_927_422_568_726_93,
        ];
        let mut area = 0.0;
        for i in 0..=m {
            for j in 0..=n {
                let k = |a: usize, b: usize| c[(i + a) * nv + j + b];
                for (s, ws) in gauss.iter().zip(&wts) {
                    for (t, wt) in gauss.iter().zip(&wts) {
                        let xs = (k(1, 0) - k(0, 0)) * (1.0 - t) + (k(1, 1) - k(0, 1)) * *t;
                        let xt = (k(0, 1) - k(0, 0)) * (1.0 - s) + (k(1, 1) - k(1, 0)) * *s;
                        area += ws * wt * xs.cross(xt).length();
                    }
                }
            }
        }
        area
    }

    /// Σ C_ij B_ij for the control points of `c11` (the same surface, up to rounding).
    pub fn spline(&self, c11: DVec3) -> Result<CrissCrossSpline<DVec3>> {
        CrissCrossSpline::new(self.cc.clone(), self.control_points(c11))
    }
}

/// (18)–(21): C_i0 = Q_i^{(0)}, C_{i,n+1} = Q_i^{(n)}, C_0j = P_j^{(0)}, C_{m+1,j} = P_j^{(m)}.
pub(crate) fn boundary_control_points(
    c: &mut [DVec3],
    p: &[Vec<DVec3>],
    q: &[Vec<DVec3>],
    m: usize,
    n: usize,
) {
    let nv = n + 2;
    for i in 0..m + 2 {
        c[i * nv] = q[0][i];
        c[i * nv + n + 1] = q[n][i];
    }
    for j in 0..n + 2 {
        c[j] = p[0][j];
        c[(m + 1) * nv + j] = p[m][j];
    }
}

/// c cᵀ.
/// The minimum of A(x) = Σ w_q |N_q − c_q × x| ([`CrissCrossSurface::min_area_c11`]) by Newton's method from `x`.
/// (Iteratively reweighted least squares, used before, converges slowly along a shallow valley of A: on a 2 × 3
/// network it stopped 3.6e-5 above the minimum after its 60 steps.) With N = N_q − c_q × x: ∇A = Σ w_q c_q × N/|N| and ∇²A = Σ w_q (|c_q|²I − c_q c_qᵀ −
/// (c_q × N)(c_q × N)ᵀ/|N|²)/|N|, positive semidefinite (A is convex). Each step is damped until A decreases
/// (Armijo, halving); stops when a step is below 1e-14·max(1, |x|), or keeps `x` when ∇²A is singular.
fn newton_min_area(terms: &[(f64, DVec3, DVec3)], mut x: DVec3, scale: f64) -> DVec3 {
    let floor = 1e-12 * scale * scale;
    let area = |x: DVec3| -> f64 {
        terms
            .iter()
            .map(|&(wq, n0, c)| wq * (n0 - c.cross(x)).length())
            .sum()
    };
    for _ in 0..60 {
        let (mut a, mut grad, mut hess) = (0.0, DVec3::ZERO, glam::DMat3::ZERO);
        for &(wq, n0, c) in terms {
            let normal = n0 - c.cross(x);
            let r = normal.length().max(floor);
            let cn = c.cross(normal);
            a += wq * r;
            grad += cn * (wq / r);
            let cc = c.length_squared();
            hess += (glam::DMat3::from_diagonal(DVec3::splat(cc))
                - outer(c, c)
                - outer(cn, cn) / (r * r))
                * (wq / r);
        }
        let det = hess.determinant();
        if !det.is_finite() || det.abs() < 1e-300 {
            break;
        }
        let dir = hess.inverse() * grad;
        if !dir.is_finite() {
            break;
        }
        let slope = grad.dot(dir);
        let mut t = 1.0;
        while t > 1e-12 && area(x - dir * t) > a - 1e-4 * t * slope {
            t *= 0.5;
        }
        if t <= 1e-12 {
            break;
        }
        x -= dir * t;
        if (dir * t).abs().max_element() <= 1e-14 * x.abs().max_element().max(1.0) {
            break;
        }
    }
    x
}

fn outer(a: DVec3, b: DVec3) -> glam::DMat3 {
    glam::DMat3::from_cols(a * b.x, a * b.y, a * b.z)
}

/// (−1)^{i+j} h_i k_j/(h_1 k_1) for i = 1..m, j = 1..n, 0 elsewhere; i-major (n+2 per row).
pub fn c11_weights(cc: &CrissCross) -> Vec<f64> {
    let (pu, pv) = (cc.u(), cc.v());
    let (m, n) = cc.cells();
    let nv = n + 2;
    let mut w = vec![0.0; (m + 2) * nv];
    for i in 1..=m {
        for j in 1..=n {
            let sign = if (i + j) % 2 == 0 { 1.0 } else { -1.0 };
            w[i * nv + j] = sign * pu.h(i) * pv.h(j) / (pu.h(1) * pv.h(1));
        }
    }
    w
}

impl Surface<DVec3> for CrissCrossSurface {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        self.cc.domain()
    }
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [DVec3; 3]) {
        self.cc.eval_nets(&self.nets, u, v, derivs, out)
    }
}
