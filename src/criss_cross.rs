//! Seed 004 (Dagnino–Lamberti–Remogna): C¹ quadratic B-splines B_ij on a non-uniform criss-cross
//! triangulation T_mn and the surface S through a compatible curve network.
//!
//! **Cells and BB nets** (`surfaces.md` §2.1): cell (a, b) = [u_{a−1}, u_a]×[v_{b−1}, v_b] (a = 1..m,
//! b = 1..n) with local s = (u − u_{a−1})/h_a, t = (v − v_{b−1})/k_b is cut by its diagonals into the
//! triangles B (bottom), R, T, L. A quadratic on the cell has 13 BB ordinates ([`CellNet`], index
//! constants [`C00`] … [`O`], domain points [`DOMAIN_POINTS`]). A C¹ cell is fixed by its edge traces: the
//! half-diagonal ordinates are the means of the two adjacent edge-midpoint ordinates and the centre is the
//! mean of the four (§2.2).
//!
//! **B_ij** (i = 0..m+1, j = 0..n+1) is the element of S₂¹(T_mn) whose traces on all grid lines equal
//! those of B_i(u|U)B_j(v|V) (eq. (23) and its v-analogue): on cell (a, b), with the Bernstein
//! coefficients α of B_i on column a and β of B_j on row b ([`Partition::bernstein`]),
//! c00 = α0β0, c10 = α2β0, c11 = α2β2, c01 = α0β2, eb = α1β0, er = α2β1, et = α1β2, el = α0β1 (§2.3).
//! They are ≥ 0, sum to 1, reproduce bilinears and P₂, and satisfy the dependence relation
//! Σ_{i=1..m, j=1..n} (−1)^{i+j} h_i k_j B_ij = 0.
//!
//! **S** (Thm 3.2) is evaluated by the local cell form (§3): corners I_rs, edge midpoints the middle
//! Bézier ordinates of the network curves (Q_a^{(b−1)} bottom, P_b^{(a)} right, Q_a^{(b)} top, P_b^{(a−1)}
//! left). The control points C_ij of Lemma 3.1 for a chosen C11 ((18)–(21) and the recursions (17) at
//! i = 1, then (16); the closed form (26)–(27) is [`CrissCrossSurface::control_points_closed_form`]) give
//! the same surface Σ C_ij B_ij ([`CrissCrossSpline`]) for every C11.
//!
//! **Choice of C11** (it changes the control net, never the surface): the paper's minimal area of the
//! bilinear control net ([`CrissCrossSurface::min_area_c11`], convex, reweighted least squares; the API
//! default), or the closed-form minimum of the sum of squared control-net edge lengths
//! ([`CrissCrossSurface::default_c11`], also the starting value of the former).

use crate::error::{Error, Result};
use crate::network::{Network, Partition, COMPATIBILITY_TOL};
use crate::point::Point;
use crate::sample::Surface;
use glam::DVec3;

/// Index of the corner ordinate at (s, t) = (0, 0) in a [`CellNet`].
pub const C00: usize = 0;
/// Corner (1, 0).
pub const C10: usize = 1;
/// Corner (1, 1).
pub const C11: usize = 2;
/// Corner (0, 1).
pub const C01: usize = 3;
/// Bottom edge midpoint (½, 0).
pub const EB: usize = 4;
/// Right edge midpoint (1, ½).
pub const ER: usize = 5;
/// Top edge midpoint (½, 1).
pub const ET: usize = 6;
/// Left edge midpoint (0, ½).
pub const EL: usize = 7;
/// Half-diagonal (¼, ¼).
pub const D00: usize = 8;
/// Half-diagonal (¾, ¼).
pub const D10: usize = 9;
/// Half-diagonal (¾, ¾).
pub const D11: usize = 10;
/// Half-diagonal (¼, ¾).
pub const D01: usize = 11;
/// Centre (½, ½).
pub const O: usize = 12;

/// The 13 BB ordinates of a quadratic on one criss-cross cell, indexed by [`C00`] … [`O`].
pub type CellNet<P> = [P; 13];

/// Local (s, t) domain points of the 13 ordinates.
pub const DOMAIN_POINTS: [(f64, f64); 13] = [
    (0.0, 0.0),
    (1.0, 0.0),
    (1.0, 1.0),
    (0.0, 1.0),
    (0.5, 0.0),
    (1.0, 0.5),
    (0.5, 1.0),
    (0.0, 0.5),
    (0.25, 0.25),
    (0.75, 0.25),
    (0.75, 0.75),
    (0.25, 0.75),
    (0.5, 0.5),
];

/// The four triangles of a cell.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Triangle {
    /// (c00, c10, o).
    Bottom,
    /// (c10, c11, o).
    Right,
    /// (c11, c01, o).
    Top,
    /// (c01, c00, o).
    Left,
}

impl Triangle {
    /// The four triangles of a cell: bottom, right, top, left.
    pub const ALL: [Triangle; 4] = [
        Triangle::Bottom,
        Triangle::Right,
        Triangle::Top,
        Triangle::Left,
    ];

    /// The triangle containing local (s, t): B if t ≤ s and t ≤ 1−s, T if t ≥ s and t ≥ 1−s, R if s ≥ t,
    /// else L (ties are irrelevant: S₂¹ is C¹).
    pub fn locate(s: f64, t: f64) -> Triangle {
        if t <= s && t <= 1.0 - s {
            Triangle::Bottom
        } else if t >= s && t >= 1.0 - s {
            Triangle::Top
        } else if s >= t {
            Triangle::Right
        } else {
            Triangle::Left
        }
    }

    /// Net indices of (b200, b020, b002, b110, b011, b101).
    pub fn ordinates(self) -> [usize; 6] {
        match self {
            Triangle::Bottom => [C00, C10, O, EB, D10, D00],
            Triangle::Right => [C10, C11, O, ER, D11, D10],
            Triangle::Top => [C11, C01, O, ET, D01, D11],
            Triangle::Left => [C01, C00, O, EL, D00, D01],
        }
    }

    /// Barycentric coordinates of local (s, t) and their constant s- and t-derivatives.
    fn barycentric(self, s: f64, t: f64) -> ([f64; 3], [f64; 3], [f64; 3]) {
        match self {
            Triangle::Bottom => (
                [1.0 - s - t, s - t, 2.0 * t],
                [-1.0, 1.0, 0.0],
                [-1.0, -1.0, 2.0],
            ),
            Triangle::Right => (
                [s - t, s + t - 1.0, 2.0 - 2.0 * s],
                [1.0, 1.0, -2.0],
                [-1.0, 1.0, 0.0],
            ),
            Triangle::Top => (
                [s + t - 1.0, t - s, 2.0 - 2.0 * t],
                [1.0, -1.0, 0.0],
                [1.0, 1.0, -2.0],
            ),
            Triangle::Left => (
                [t - s, 1.0 - s - t, 2.0 * s],
                [-1.0, -1.0, 2.0],
                [1.0, -1.0, 0.0],
            ),
        }
    }
}

/// Completes a C¹ cell net from its 4 corners and 4 edge-midpoint ordinates (`surfaces.md` §2.2).
pub fn cell_net_from_edges<P: Point>(corners: [P; 4], edges: [P; 4]) -> CellNet<P> {
    let [c00, c10, c11, c01] = corners;
    let [eb, er, et, el] = edges;
    [
        c00,
        c10,
        c11,
        c01,
        eb,
        er,
        et,
        el,
        (eb + el) * 0.5,
        (eb + er) * 0.5,
        (er + et) * 0.5,
        (et + el) * 0.5,
        (eb + er + et + el) * 0.25,
    ]
}

/// Value and local (s, t) derivatives of the quadratic with net `net` at local (s, t):
/// f = Σ b_{ijk}·2/(i!j!k!)·λ1^iλ2^jλ3^k on the triangle containing (s, t).
pub fn eval_cell_net<P: Point>(net: &CellNet<P>, s: f64, t: f64) -> [P; 3] {
    let tri = Triangle::locate(s, t);
    eval_on_triangle(net, tri, s, t)
}

/// Like [`eval_cell_net`] on a given triangle (its polynomial, extended beyond it).
pub fn eval_on_triangle<P: Point>(net: &CellNet<P>, tri: Triangle, s: f64, t: f64) -> [P; 3] {
    let [i200, i020, i002, i110, i011, i101] = tri.ordinates();
    let (b200, b020, b002, b110, b011, b101) = (
        net[i200], net[i020], net[i002], net[i110], net[i011], net[i101],
    );
    let ([l1, l2, l3], ds, dt) = tri.barycentric(s, t);
    let f = b200 * (l1 * l1)
        + b020 * (l2 * l2)
        + b002 * (l3 * l3)
        + b110 * (2.0 * l1 * l2)
        + b011 * (2.0 * l2 * l3)
        + b101 * (2.0 * l1 * l3);
    let g1 = (b200 * l1 + b110 * l2 + b101 * l3) * 2.0;
    let g2 = (b110 * l1 + b020 * l2 + b011 * l3) * 2.0;
    let g3 = (b101 * l1 + b011 * l2 + b002 * l3) * 2.0;
    let fs = g1 * ds[0] + g2 * ds[1] + g3 * ds[2];
    let ft = g1 * dt[0] + g2 * dt[1] + g3 * dt[2];
    [f, fs, ft]
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

    /// The BB net of Σ C_ij B_ij on cell (a, b); `ctrl[i * (n+2) + j]` = C_ij.
    pub fn combination_net<P: Point>(&self, ctrl: &[P], a: usize, b: usize) -> CellNet<P> {
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
    pub fn eval_nets<P: Point>(
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

/// The DLR surface S through a compatible network (Thm 3.2), by the local cell form.
///
/// # Template
/// * **What**: the surface S = Σ C_ij B_ij of seed 004 (Dagnino–Lamberti–Remogna, Thm 3.2): C¹ quadratic
///   B-splines B_ij on the criss-cross triangulation of the network's grid, coefficients (18)–(21) with the
///   free C11 (default: the area-minimising choice).
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
    pub fn c11_weights(&self) -> Vec<f64> {
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
    /// X_s × X_t = N0 − \[c\]_× x is affine in x, so A is convex; it is minimised by iteratively reweighted
    /// least squares from [`CrissCrossSurface::default_c11`] (at most 60 steps; stops when a step is below
    /// 1e-13·max(1, |x|)). Falls back to the start value when the weighted normal matrix is singular.
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
        let start = self.default_c11();
        let mut x = start;
        let scale = g.iter().map(|p| p.abs().max_element()).fold(1.0, f64::max);
        for _ in 0..60 {
            let mut mat = glam::DMat3::ZERO;
            let mut rhs = DVec3::ZERO;
            for &(wq, n0, c) in &terms {
                let normal = n0 - c.cross(x);
                let r = normal.length().max(1e-12 * scale * scale);
                let f = wq / r;
                let cc = c.length_squared();
                mat += (glam::DMat3::from_diagonal(DVec3::splat(cc)) - outer(c, c)) * f;
                rhs -= c.cross(n0) * f;
            }
            let det = mat.determinant();
            if !det.is_finite() || det.abs() < 1e-300 {
                return start;
            }
            let next = mat.inverse() * rhs;
            if !next.is_finite() {
                return start;
            }
            let step = (next - x).abs().max_element();
            x = next;
            if step <= 1e-13 * x.abs().max_element().max(1.0) {
                break;
            }
        }
        x
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
