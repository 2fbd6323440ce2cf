//! Builders of curve networks: from a biquadratic control net, from a function (Schoenberg
//! quasi-interpolant), from free data, and the repair that recomputes dependent control points.

use super::{NetPoint, Network, Partition};
use crate::error::{Error, Result};
use glam::DVec3;

impl Network {
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
                        "the function returned a non-finite point",
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
}

pub(super) fn check_table(
    field: &'static str,
    t: &[Vec<DVec3>],
    rows: usize,
    cols: usize,
) -> Result<()> {
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
