//! Curve networks of Dagnino–Lamberti–Remogna: the isoparametric C¹ quadratic B-spline curves through which the
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

//!
//! Files: `partition` (breakpoints, eq. (8), quadratic B-splines on one direction), `compatibility`
//! (conditions C1/C2, the residual report), `build` (the builders and the repair), [`examples`].

mod build;
mod compatibility;
pub mod examples;
mod partition;

pub use build::{FromFunctionError, Repair};
pub use compatibility::{CompatibilityReport, Condition};
pub use partition::Partition;

use crate::error::{Error, Result};
use crate::point::Point;
use build::check_table;
use glam::DVec3;

/// Default relative tolerance of the C2 check (`surfaces.md` §10 item 16): residual ≤ 1e-12·max(1, scale).
pub const COMPATIBILITY_TOL: f64 = 1e-12;

/// Largest number of breakpoints per direction accepted by the builders (keeps work bounded).
pub const MAX_BREAKPOINTS: usize = 2001;

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
