//! Curve networks of seed 004: the isoparametric C¹ quadratic B-spline curves through which the
//! surfaces S (criss-cross), T (thin-plate), G (Gordon) and GB (spline-blended) pass.
//!
//! Conventions (`../shared/spec/surfaces.md` §9, binding): breakpoints `u = u_0 < … < u_m`,
//! `v = v_0 < … < v_n`; `p[r][j]` = P_j^{(r)} (r = 0..m, j = 0..n+1) are the control points of the curve
//! φ_r(v) = S(u_r, v) on the knots V = {v_0,v_0,v_0,v_1,…,v_{n−1},v_n,v_n,v_n}; `q[s][i]` = Q_i^{(s)}
//! (s = 0..n, i = 0..m+1) those of ψ_s(u) = S(u, v_s) on U.
//!
//! * [`Partition`]: the breakpoints of one direction with h_r, σ_r, σ′_r of eq. (8) (h_0 = h_{m+1} = 0, so
//!   σ_1 = 1, σ′_1 = 0, σ_{m+1} = 0, σ′_{m+1} = 1), the Bernstein coefficients of the univariate quadratic
//!   B-splines B_i(u|U) and the evaluation of quadratic C¹ splines on U by their Bézier form.
//! * Compatibility (C1: common knot vectors, i.e. the shapes of [`Network::check_shape`]; C2, eq. (6):
//!   φ_r(v_s) = ψ_s(u_r), which is (9)–(12) written with σ, τ): [`Network::compatibility`] reports the
//!   residuals, [`Network::check_compatible`] rejects a network naming the worst one and where.
//! * Builders: from a function (Schoenberg quasi-interpolant C*_ij = F(ξ_i, η_j), then isocurves;
//!   [`Network::from_function`]), from a biquadratic control net on U×V ([`Network::from_control_net`]),
//!   from free data (all P free, Q_1^{(s)} free, the other Q from C2; [`Network::from_free_data`]) and
//!   [`Network::repair`], which recomputes the dependent control points after an edit.

use crate::error::{Error, Result};
use crate::point::Point;
use glam::DVec3;

/// Default relative tolerance of the C2 check (`surfaces.md` §10 item 16): residual ≤ 1e-12·max(1, scale).
pub const COMPATIBILITY_TOL: f64 = 1e-12;

/// Largest number of breakpoints per direction accepted by the builders (keeps work bounded).
pub const MAX_BREAKPOINTS: usize = 2001;

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
    pub fn bezier_ordinates<P: Point>(&self, ctrl: &[P], a: usize) -> [P; 3] {
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
    pub fn eval_spline<P: Point>(&self, ctrl: &[P], t: f64) -> [P; 2] {
        let (a, s) = self.locate(t);
        bezier2(&self.bezier_ordinates(ctrl, a), s, self.h[a])
    }

    /// The spline's value at the breakpoint x_r: σ_{r+1} c_r + σ′_{r+1} c_{r+1} (r = 0..m).
    pub fn value_at_break<P: Point>(&self, ctrl: &[P], r: usize) -> P {
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

/// A curve network: `m + 1` curves in v at u = u_r and `n + 1` curves in u at v = v_s.
#[derive(Debug, Clone, PartialEq)]
pub struct Network {
    /// Breakpoints u_0..u_m (strictly increasing).
    pub u: Vec<f64>,
    /// Breakpoints v_0..v_n (strictly increasing).
    pub v: Vec<f64>,
    /// `p[r][j]` = P_j^{(r)}, r = 0..m, j = 0..n+1.
    pub p: Vec<Vec<DVec3>>,
    /// `q[s][i]` = Q_i^{(s)}, s = 0..n, i = 0..m+1.
    pub q: Vec<Vec<DVec3>>,
}

/// Which compatibility equation of seed 004 a network node (r, s) belongs to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Condition {
    /// Interior node: eq. (9).
    Interior,
    /// s = 0 or s = n, interior r: eq. (10).
    UBoundary,
    /// r = 0 or r = m, interior s: eq. (11).
    VBoundary,
    /// A corner: eq. (12).
    Corner,
}

impl Condition {
    /// The paper's equation number, e.g. `"(9)"`.
    pub fn equation(self) -> &'static str {
        match self {
            Condition::Interior => "(9)",
            Condition::UBoundary => "(10)",
            Condition::VBoundary => "(11)",
            Condition::Corner => "(12)",
        }
    }
}

/// The C2 residuals of a network (C1 holds once [`Network::check_shape`] passed: all ψ_s share U, all
/// φ_r share V).
#[derive(Debug, Clone, PartialEq)]
pub struct CompatibilityReport {
    /// `residuals[r][s]` = ‖φ_r(v_s) − ψ_s(u_r)‖∞.
    pub residuals: Vec<Vec<f64>>,
    /// max over (r, s).
    pub c2: f64,
    /// (r, s) of the largest residual.
    pub worst: (usize, usize),
    /// The equation of seed 004 the worst node belongs to.
    pub condition: Condition,
    /// Scale of the network: the largest absolute control-point coordinate.
    pub scale: f64,
}

impl CompatibilityReport {
    /// The tolerance used by [`Network::check_compatible`] for relative tolerance `rel`.
    pub fn tolerance(&self, rel: f64) -> f64 {
        rel * self.scale.max(1.0)
    }
}

/// A control point of the network, for [`Network::repair`].
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum NetPoint {
    /// P_j^{(r)}.
    P {
        /// The curve φ_r, r = 0..m.
        r: usize,
        /// The control point, j = 0..n+1.
        j: usize,
    },
    /// Q_i^{(s)}.
    Q {
        /// The curve ψ_s, s = 0..n.
        s: usize,
        /// The control point, i = 0..m+1.
        i: usize,
    },
}

impl Network {
    /// `m` (number of cells in u).
    pub fn m(&self) -> usize {
        self.u.len().saturating_sub(1)
    }
    /// `n` (number of cells in v).
    pub fn n(&self) -> usize {
        self.v.len().saturating_sub(1)
    }

    /// Checks shapes and finiteness (not compatibility): `u`, `v` strictly increasing with at least two
    /// entries, `p` of shape (m+1) × (n+2), `q` of shape (n+1) × (m+2), all coordinates finite.
    pub fn check_shape(&self) -> Result<()> {
        if self.u.len() < 2 {
            return Err(Error::too_few_of(
                "network.u",
                2,
                self.u.len(),
                format!("need at least 2 breakpoints, got {}", self.u.len()),
            ));
        }
        if self.v.len() < 2 {
            return Err(Error::too_few_of(
                "network.v",
                2,
                self.v.len(),
                format!("need at least 2 breakpoints, got {}", self.v.len()),
            ));
        }
        if self.u.len() > MAX_BREAKPOINTS || self.v.len() > MAX_BREAKPOINTS {
            let (f, l) = if self.u.len() > MAX_BREAKPOINTS {
                ("network.u", self.u.len())
            } else {
                ("network.v", self.v.len())
            };
            return Err(Error::too_many_of(
                f,
                MAX_BREAKPOINTS,
                l,
                format!("at most {MAX_BREAKPOINTS} breakpoints, got {l}"),
            ));
        }
        crate::error::check_finite("network.u", &self.u)?;
        crate::error::check_finite("network.v", &self.v)?;
        crate::knots::check_increasing("network.u", &self.u)?;
        crate::knots::check_increasing("network.v", &self.v)?;
        let (m, n) = (self.m(), self.n());
        check_table("network.P", &self.p, m + 1, n + 2)?;
        check_table("network.Q", &self.q, n + 1, m + 2)?;
        Ok(())
    }

    /// The two partitions (U side, V side), validated.
    pub fn partitions(&self) -> Result<(Partition, Partition)> {
        Ok((
            Partition::new("network.u", &self.u)?,
            Partition::new("network.v", &self.v)?,
        ))
    }

    /// The largest absolute control-point coordinate ("scale" of `surfaces.md` §10).
    pub fn scale(&self) -> f64 {
        self.p
            .iter()
            .chain(self.q.iter())
            .flatten()
            .map(|p| p.max_abs())
            .fold(0.0, f64::max)
    }

    /// φ_r(v) and dφ_r/dv (requires a shape-checked network; r ≤ m).
    pub fn phi(&self, r: usize, v: f64) -> [DVec3; 2] {
        match (Partition::new("network.v", &self.v), self.p.get(r)) {
            (Ok(pv), Some(row)) => pv.eval_spline(row, v),
            _ => [DVec3::ZERO; 2],
        }
    }

    /// ψ_s(u) and dψ_s/du (requires a shape-checked network; s ≤ n).
    pub fn psi(&self, s: usize, u: f64) -> [DVec3; 2] {
        match (Partition::new("network.u", &self.u), self.q.get(s)) {
            (Ok(pu), Some(row)) => pu.eval_spline(row, u),
            _ => [DVec3::ZERO; 2],
        }
    }

    /// The node points I_rs = φ_r(v_s) (from the P side), `[r][s]`.
    pub fn nodes_from_p(&self, pv: &Partition) -> Vec<Vec<DVec3>> {
        self.p
            .iter()
            .map(|row| (0..=self.n()).map(|s| pv.value_at_break(row, s)).collect())
            .collect()
    }

    /// The node points ψ_s(u_r) (from the Q side), `[r][s]`.
    pub fn nodes_from_q(&self, pu: &Partition) -> Vec<Vec<DVec3>> {
        (0..=self.m())
            .map(|r| self.q.iter().map(|row| pu.value_at_break(row, r)).collect())
            .collect()
    }

    /// The network intersection points I_rs = φ_r(v_s) = ψ_s(u_r) (eq. (6)), `[r][s]`, taken as the mean
    /// of the two sides (exactly symmetric under transposition). Requires a shape-checked network.
    pub fn intersections(&self) -> Result<Vec<Vec<DVec3>>> {
        let (pu, pv) = self.partitions()?;
        let a = self.nodes_from_p(&pv);
        let b = self.nodes_from_q(&pu);
        Ok(a.iter()
            .zip(&b)
            .map(|(ra, rb)| ra.iter().zip(rb).map(|(x, y)| (*x + *y) * 0.5).collect())
            .collect())
    }

    /// Which equation node (r, s) belongs to.
    pub fn condition_at(&self, r: usize, s: usize) -> Condition {
        let rb = r == 0 || r == self.m();
        let sb = s == 0 || s == self.n();
        match (rb, sb) {
            (true, true) => Condition::Corner,
            (false, true) => Condition::UBoundary,
            (true, false) => Condition::VBoundary,
            (false, false) => Condition::Interior,
        }
    }

    /// The C2 residual report (checks the shape first).
    pub fn compatibility(&self) -> Result<CompatibilityReport> {
        self.check_shape()?;
        let (pu, pv) = self.partitions()?;
        let a = self.nodes_from_p(&pv);
        let b = self.nodes_from_q(&pu);
        let mut c2 = 0.0;
        let mut worst = (0, 0);
        let residuals: Vec<Vec<f64>> = a
            .iter()
            .zip(&b)
            .enumerate()
            .map(|(r, (ra, rb))| {
                ra.iter()
                    .zip(rb)
                    .enumerate()
                    .map(|(s, (x, y))| {
                        let d = (*x - *y).max_abs();
                        if d > c2 || d.is_nan() {
                            c2 = d;
                            worst = (r, s);
                        }
                        d
                    })
                    .collect()
            })
            .collect();
        Ok(CompatibilityReport {
            residuals,
            c2,
            worst,
            condition: self.condition_at(worst.0, worst.1),
            scale: self.scale(),
        })
    }

    /// Shape check plus C2 with residual ≤ `rel`·max(1, scale) (use [`COMPATIBILITY_TOL`]); the error names
    /// the worst residual, the node (r, s), the equation and how to fix it.
    pub fn check_compatible(&self, rel: f64) -> Result<CompatibilityReport> {
        let rep = self.compatibility()?;
        let tol = rep.tolerance(rel);
        if !(rep.c2 <= tol) {
            let (r, s) = rep.worst;
            return Err(Error::size_mismatch(
                "network",
                format!(
                    "the curves are not compatible (condition C2, eq. {}): φ_{r}(v_{s}) ≠ ψ_{s}(u_{r}) at node (r = {r}, s = {s}), \
                     worst residual {:.3e} > tolerance {:.1e} (P[{r}] vs Q[{s}]); build the network with networkFromFunction \
                     or make it compatible with networkRepair",
                    rep.condition.equation(),
                    rep.c2,
                    tol
                ),
            ));
        }
        Ok(rep)
    }

    /// The isocurve network of the biquadratic tensor surface Σ C_ij B_i(u|U)B_j(v|V): `c[i][j]`,
    /// i = 0..m+1, j = 0..n+1. P_j^{(r)} = σ_{r+1}C_rj + σ′_{r+1}C_{r+1,j}, Q_i^{(s)} = τ_{s+1}C_is + τ′_{s+1}C_{i,s+1}.
    /// The result is compatible up to rounding (both sides equal the surface at (u_r, v_s)).
    pub fn from_control_net(u: &[f64], v: &[f64], c: &[Vec<DVec3>]) -> Result<Network> {
        let pu = Partition::new("u", u)?;
        let pv = Partition::new("v", v)?;
        let (m, n) = (pu.cells(), pv.cells());
        check_table("C", c, m + 2, n + 2)?;
        let p = (0..=m)
            .map(|r| {
                (0..n + 2)
                    .map(|j| c[r][j] * pu.sigma(r + 1) + c[r + 1][j] * pu.sigma_p(r + 1))
                    .collect()
            })
            .collect();
        let q = (0..=n)
            .map(|s| (0..m + 2).map(|i| pv.value_at_break(&c[i], s)).collect())
            .collect();
        Ok(Network {
            u: u.to_vec(),
            v: v.to_vec(),
            p,
            q,
        })
    }

    /// The network of the Schoenberg quasi-interpolant of `f` (`surfaces.md` §9): C*_ij = f(ξ_i, η_j),
    /// then its isocurves. `f` must return finite points.
    pub fn from_function(
        u: &[f64],
        v: &[f64],
        mut f: impl FnMut(f64, f64) -> DVec3,
    ) -> Result<Network> {
        let pu = Partition::new("u", u)?;
        let pv = Partition::new("v", v)?;
        let (xi, eta) = (pu.greville(), pv.greville());
        let mut c = Vec::with_capacity(xi.len());
        for &x in &xi {
            let mut row = Vec::with_capacity(eta.len());
            for &y in &eta {
                let p = f(x, y);
                if !p.is_finite() {
                    return Err(Error::not_finite(
                        "f",
                        format!("the function returned a non-finite point at ({x}, {y})"),
                    ));
                }
                row.push(p);
            }
            c.push(row);
        }
        Self::from_control_net(u, v, &c)
    }

    /// A compatible network from free data (`surfaces.md` §9): all `p[r][j]` free, `q1[s]` = Q_1^{(s)}
    /// free; the other Q_i^{(s)} follow from C2 (Q_0 = φ_0(v_s), Q_{m+1} = φ_m(v_s), and
    /// σ_{r+1}Q_r + σ′_{r+1}Q_{r+1} = φ_r(v_s) solved forward for r = 1..m−1).
    pub fn from_free_data(
        u: &[f64],
        v: &[f64],
        p: Vec<Vec<DVec3>>,
        q1: &[DVec3],
    ) -> Result<Network> {
        let n = v.len().saturating_sub(1);
        let m = u.len().saturating_sub(1);
        if q1.len() != n + 1 {
            return Err(Error::size_mismatch(
                "Q1",
                format!("expected n + 1 = {} points, got {}", n + 1, q1.len()),
            ));
        }
        if let Some(s) = q1.iter().position(|x| !x.is_finite()) {
            return Err(Error::not_finite(
                format!("Q1[{s}]"),
                "expected finite coordinates",
            ));
        }
        let q = q1.iter().map(|x| {
            let mut row = vec![DVec3::ZERO; m + 2];
            if let Some(slot) = row.get_mut(1) {
                *slot = *x;
            }
            row
        });
        let net = Network {
            u: u.to_vec(),
            v: v.to_vec(),
            p,
            q: q.collect(),
        };
        net.check_shape()?;
        net.repair(None)
    }

    /// Makes the network compatible by recomputing the dependent control points from C2, keeping the
    /// free ones: all P, and in each row s the pivot Q_1^{(s)} — or, when `edited` is a Q_i^{(s)} with
    /// 2 ≤ i ≤ m, that point is the pivot of its row. When `edited` is an end point Q_0^{(s)} or
    /// Q_{m+1}^{(s)} (which must equal φ_0(v_s), φ_m(v_s)), the boundary curve φ_0 (φ_m) is moved to pass
    /// through it (its control points P_s, P_{s+1} shift by the difference; the end points P_0 / P_{n+1}
    /// alone at s = 0 / n) before the rows are recomputed. Rows are solved from the pivot outwards:
    /// Q_{r+1} = (I_rs − σ_{r+1}Q_r)/σ′_{r+1}, Q_r = (I_rs − σ′_{r+1}Q_{r+1})/σ_{r+1}.
    pub fn repair(&self, edited: Option<NetPoint>) -> Result<Network> {
        self.check_shape()?;
        let (pu, pv) = self.partitions()?;
        let (m, n) = (self.m(), self.n());
        let mut net = self.clone();
        let mut pivot_row: Option<(usize, usize)> = None;
        match edited {
            Some(NetPoint::P { r, j }) if r > m || j > n + 1 => {
                return Err(Error::out_of_range(
                    "edited",
                    format!("P index ({r}, {j}) outside 0..={m} × 0..={}", n + 1),
                ));
            }
            Some(NetPoint::P { .. }) => {}
            Some(NetPoint::Q { s, i }) => {
                if s > n || i > m + 1 {
                    return Err(Error::out_of_range(
                        "edited",
                        format!("Q index ({s}, {i}) outside 0..={n} × 0..={}", m + 1),
                    ));
                }
                if i == 0 || i == m + 1 {
                    let r = if i == 0 { 0 } else { m };
                    let target = net.q[s][i];
                    let delta = target - pv.value_at_break(&net.p[r], s);
                    if s == 0 {
                        net.p[r][0] += delta;
                    } else if s == n {
                        net.p[r][n + 1] += delta;
                    } else {
                        net.p[r][s] += delta;
                        net.p[r][s + 1] += delta;
                    }
                } else {
                    pivot_row = Some((s, i));
                }
            }
            None => {}
        }
        let nodes = net.nodes_from_p(&pv);
        for s in 0..=n {
            let k = match pivot_row {
                Some((ps, i)) if ps == s => i,
                _ => 1,
            };
            let row = &mut net.q[s];
            let node = |r: usize| nodes[r][s];
            row[0] = node(0);
            row[m + 1] = node(m);
            for r in k..m {
                row[r + 1] = (node(r) - row[r] * pu.sigma(r + 1)) * (1.0 / pu.sigma_p(r + 1));
            }
            for r in (1..k).rev() {
                row[r] = (node(r) - row[r + 1] * pu.sigma_p(r + 1)) * (1.0 / pu.sigma(r + 1));
            }
        }
        if let Some(i) = net.q.iter().flatten().position(|x| !x.is_finite()) {
            return Err(Error::not_finite(
                format!("network.Q[{}][{}]", i / (m + 2), i % (m + 2)),
                "the dependent control points overflowed",
            ));
        }
        Ok(net)
    }

    /// Whether Q_i^{(s)} is recomputed by [`Network::repair`] (`None`): every Q except Q_1^{(s)}.
    pub fn is_dependent_q(&self, i: usize) -> bool {
        i != 1
    }

    /// The transposed network (u ↔ v, P ↔ Q).
    pub fn transposed(&self) -> Network {
        Network {
            u: self.v.clone(),
            v: self.u.clone(),
            p: self.q.clone(),
            q: self.p.clone(),
        }
    }

    /// The image of every control point under `f` (an affine map keeps the network compatible).
    pub fn mapped(&self, f: impl Fn(DVec3) -> DVec3) -> Network {
        let map = |t: &Vec<Vec<DVec3>>| {
            t.iter()
                .map(|row| row.iter().map(|p| f(*p)).collect())
                .collect()
        };
        Network {
            u: self.u.clone(),
            v: self.v.clone(),
            p: map(&self.p),
            q: map(&self.q),
        }
    }
}

fn check_table(field: &'static str, t: &[Vec<DVec3>], rows: usize, cols: usize) -> Result<()> {
    if t.len() != rows {
        return Err(Error::size_mismatch(
            field,
            format!("expected {rows} rows, got {}", t.len()),
        ));
    }
    for (r, row) in t.iter().enumerate() {
        if row.len() != cols {
            return Err(Error::size_mismatch(
                format!("{field}[{r}]"),
                format!("expected {cols} points, got {}", row.len()),
            ));
        }
        if let Some(j) = row.iter().position(|p| !p.is_finite()) {
            return Err(Error::not_finite(
                format!("{field}[{r}][{j}]"),
                "expected finite coordinates",
            ));
        }
    }
    Ok(())
}

/// Example networks (the test set of `surfaces.md` §2.4/§3 and the presets of the demos). All are
/// compatible up to rounding.
pub mod examples {
    use super::Network;
    use glam::DVec3;

    /// A small deterministic pseudo-random generator (values in [−1, 1)).
    pub struct Lcg(u64);
    impl Lcg {
        /// A generator seeded with `seed`.
        pub fn new(seed: u64) -> Self {
            Lcg(seed
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407))
        }
        /// The next value, in [−1, 1).
        #[allow(
            clippy::should_implement_trait,
            reason = "an endless f64 stream: as an Iterator every call site would unwrap an Option"
        )]
        pub fn next(&mut self) -> f64 {
            self.0 = self
                .0
                .wrapping_mul(6364136223846793005)
                .wrapping_add(1442695040888963407);
            ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
        }
        /// A point with three coordinates in [−1, 1).
        pub fn point(&mut self) -> DVec3 {
            DVec3::new(self.next(), self.next(), self.next())
        }
    }

    fn dome(u: f64, v: f64, (u0, u1): (f64, f64), (v0, v1): (f64, f64)) -> DVec3 {
        let x = (u - u0) / (u1 - u0) * 2.0 - 1.0;
        let y = (v - v0) / (v1 - v0) * 2.0 - 1.0;
        DVec3::new(u, v, 0.6 * (1.0 - 0.5 * (x * x + y * y)) + 0.1 * x * y * y)
    }

    fn from_dome(u: &[f64], v: &[f64]) -> Network {
        let du = (u[0], u[u.len() - 1]);
        let dv = (v[0], v[v.len() - 1]);
        Network::from_function(u, v, |a, b| dome(a, b, du, dv)).expect("valid example")
    }

    fn random_net(u: &[f64], v: &[f64], seed: u64) -> Network {
        let mut g = Lcg::new(seed);
        let c: Vec<Vec<DVec3>> = (0..u.len() + 1)
            .map(|_| (0..v.len() + 1).map(|_| g.point()).collect())
            .collect();
        Network::from_control_net(u, v, &c).expect("valid example")
    }

    /// The paper's m = n = 3 uniform grid on \[0,1\]² (U = V = {0,0,0,1/3,2/3,1,1,1}).
    pub const UNIFORM3: [f64; 4] = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0];

    /// Uniform m = n = 3, a dome sampled by the Schoenberg quasi-interpolant.
    pub fn uniform_dome() -> Network {
        from_dome(&UNIFORM3, &UNIFORM3)
    }
    /// Uniform m = n = 3, a random control net's isocurves.
    pub fn uniform_random() -> Network {
        random_net(&UNIFORM3, &UNIFORM3, 7)
    }
    /// Non-uniform m = 4, n = 5 dome.
    pub fn nonuniform_dome() -> Network {
        from_dome(
            &[0.0, 0.1, 0.35, 0.6, 1.0],
            &[0.0, 0.15, 0.3, 0.55, 0.8, 1.0],
        )
    }
    /// §4.3: m = 5, n = 3 on \[0,5\]×\[0,3\] with all ψ_0 ≡ Q^{(0)} and ψ_3 ≡ Q^{(3)} (three-sided facets).
    pub fn three_sided() -> Network {
        let u = [0.0, 1.0, 2.0, 3.0, 4.0, 5.0];
        let v = [0.0, 1.0, 2.0, 3.0];
        let (bottom, top) = (DVec3::new(0.0, 0.0, 0.0), DVec3::new(0.0, 0.0, 3.0));
        let c: Vec<Vec<DVec3>> = (0..7)
            .map(|i| {
                let th = std::f64::consts::PI * i as f64 / 6.0;
                (0..5)
                    .map(|j| match j {
                        0 => bottom,
                        4 => top,
                        _ => {
                            let r = [0.0, 1.2, 1.6, 1.2, 0.0][j];
                            DVec3::new(r * th.cos(), r * th.sin(), 0.75 * j as f64)
                        }
                    })
                    .collect()
            })
            .collect();
        Network::from_control_net(&u, &v, &c).expect("valid example")
    }
    /// Strongly non-uniform m = 5, n = 3 (h-ratio 50: u = 0, .01, .5, .51, .75, 1), random net.
    pub fn strongly_nonuniform() -> Network {
        random_net(
            &[0.0, 0.01, 0.5, 0.51, 0.75, 1.0],
            &[0.0, 0.4, 0.45, 1.0],
            11,
        )
    }
    /// Separable network on the uniform m = n = 3 grid: x = u, y = v, z = a(u) + b(v) + c·uv (the class
    /// where S = G, `surfaces.md` §5).
    pub fn separable() -> Network {
        Network::from_function(&UNIFORM3, &UNIFORM3, |u, v| {
            DVec3::new(u, v, 0.8 * u * u - 0.5 * v * v + 0.7 * u * v + 0.2)
        })
        .expect("valid example")
    }
    /// Free data m = 4, n = 3: random P and Q_1, the other Q from C2.
    pub fn free_data() -> Network {
        let u = [0.0, 0.2, 0.5, 0.7, 1.0];
        let v = [0.0, 0.3, 0.6, 1.0];
        let mut g = Lcg::new(3);
        let p: Vec<Vec<DVec3>> = (0..5)
            .map(|r| {
                (0..5)
                    .map(|j| DVec3::new(u[r], j as f64 / 4.0, 0.0) + g.point() * 0.2)
                    .collect()
            })
            .collect();
        let q1: Vec<DVec3> = (0..4)
            .map(|s| DVec3::new(0.1, v[s], 0.0) + g.point() * 0.2)
            .collect();
        Network::from_free_data(&u, &v, p, &q1).expect("valid example")
    }
    /// A 10 × 10 dome (m = n = 9 uniform on \[0,1\]²), for the speed target.
    pub fn dome10() -> Network {
        let b: Vec<f64> = (0..10).map(|i| i as f64 / 9.0).collect();
        from_dome(&b, &b)
    }

    /// Names accepted by [`by_name`].
    pub const NAMES: [&str; 8] = [
        "uniform-dome",
        "uniform-random",
        "nonuniform-dome",
        "three-sided",
        "strongly-nonuniform",
        "separable",
        "free-data",
        "dome10",
    ];

    /// The example network called `name`.
    pub fn by_name(name: &str) -> Option<Network> {
        Some(match name {
            "uniform-dome" => uniform_dome(),
            "uniform-random" => uniform_random(),
            "nonuniform-dome" => nonuniform_dome(),
            "three-sided" => three_sided(),
            "strongly-nonuniform" => strongly_nonuniform(),
            "separable" => separable(),
            "free-data" => free_data(),
            "dome10" => dome10(),
            _ => return None,
        })
    }
}
