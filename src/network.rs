//! Curve networks of seed 004: the isoparametric C¹ quadratic B-spline curves through which the
//! surfaces S (criss-cross), T (thin-plate), G (Gordon) and GB (spline-blended) pass.
//!
//! Conventions (`../shared/spec/surfaces.md` §9, binding): breakpoints `u = u_0 < … < u_m`,
//! `v = v_0 < … < v_n`; `p[r][j]` = P_j^{(r)} (r = 0..m, j = 0..n+1) are the control points of the curve
//! φ_r(v) = S(u_r, v) on the knots V = {v_0,v_0,v_0,v_1,…,v_{n−1},v_n,v_n,v_n}; `q[s][i]` = Q_i^{(s)}
//! (s = 0..n, i = 0..m+1) those of ψ_s(u) = S(u, v_s) on U.

use crate::error::{Error, Result};
use glam::DVec3;

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
            return Err(Error::too_few(
                "network.u",
                format!("need at least 2 breakpoints, got {}", self.u.len()),
            ));
        }
        if self.v.len() < 2 {
            return Err(Error::too_few(
                "network.v",
                format!("need at least 2 breakpoints, got {}", self.v.len()),
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
