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
        Self::from_dyn_function(u, v, &mut f)
    }

    /// [`Network::from_function`] compiled once (not once per closure).
    fn from_dyn_function(
        u: &[f64],
        v: &[f64],
        f: &mut dyn FnMut(f64, f64) -> DVec3,
    ) -> Result<Network> {
        let pu = Partition::new("u", u)?;
        let pv = Partition::new("v", v)?;
        let mut finite = |x: f64, y: f64| {
            let p = f(x, y);
            if p.is_finite() {
                Ok(p)
            } else {
                Err(Error::not_finite(
                    "f",
                    "the function returned a non-finite point",
                ))
            }
        };
        Self::try_from_function(&pu, &pv, &mut finite).map_err(|e| match e {
            FromFunctionError::Function(e) | FromFunctionError::Network(e) => e,
        })
    }

    /// [`Network::from_function`] for a function that may fail (e.g. one a caller cannot run): f is called
    /// at the Greville points (ξ_i, η_j), ξ_i = (u_{i−1} + u_i)/2 (ξ_0 = u_0, ξ_{m+1} = u_m), i-major
    /// ((m + 2)(n + 2) calls, i = 0..m+1 outer, j = 0..n+1 inner), and the first failure is returned as is.
    /// (`f` is a trait object so that the loop is compiled once per error type, not once per closure.)
    pub fn try_from_function<E>(
        pu: &Partition,
        pv: &Partition,
        f: &mut dyn FnMut(f64, f64) -> std::result::Result<DVec3, E>,
    ) -> std::result::Result<Network, FromFunctionError<E>> {
        let (xi, eta) = (pu.greville(), pv.greville());
        let mut c = Vec::with_capacity(xi.len());
        for &x in &xi {
            let mut row = Vec::with_capacity(eta.len());
            for &y in &eta {
                row.push(f(x, y).map_err(FromFunctionError::Function)?);
            }
            c.push(row);
        }
        Self::from_control_net(pu.breaks(), pv.breaks(), &c).map_err(FromFunctionError::Network)
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
                }
            }
            None => {}
        }
        let nodes = net.nodes_from_p(&pv);
        for s in 0..=n {
            let k = pivot_of(edited, s, m);
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

    /// [`Network::repair`] with what a caller reports: the repaired network, its C2 residual (eq. (6)) and
    /// which control points Q_i^{(s)} were recomputed, `dependent_q[s·(m+2) + i]` = 1 (else 0): all but the
    /// free pivot of each row, Q_1^{(s)}, or the edited Q_i^{(s)} when 2 ≤ i ≤ m (the end points Q_0,
    /// Q_{m+1} are always recomputed, from the boundary curves).
    pub fn repair_report(&self, edited: Option<NetPoint>) -> Result<Repair> {
        let network = self.repair(edited)?;
        let c2 = network.compatibility()?.c2;
        let (m, n) = (network.m(), network.n());
        let mut dependent_q = vec![1.0; (n + 1) * (m + 2)];
        for (s, row) in dependent_q.chunks_mut(m + 2).enumerate() {
            row[pivot_of(edited, s, m)] = 0.0;
        }
        Ok(Repair {
            network,
            c2,
            dependent_q,
        })
    }
}

/// The free control point of row s that [`Network::repair`] keeps and solves the row outwards from: the
/// edited Q_i^{(s)} when 1 ≤ i ≤ m, else Q_1^{(s)} (the end points Q_0, Q_{m+1} are never free: they lie on
/// the boundary curves φ_0, φ_m).
fn pivot_of(edited: Option<NetPoint>, s: usize, m: usize) -> usize {
    match edited {
        Some(NetPoint::Q { s: es, i }) if es == s && (1..=m).contains(&i) => i,
        _ => 1,
    }
}

/// A failure of [`Network::try_from_function`]: the function's own error, or the network's.
#[derive(Debug, Clone, PartialEq)]
pub enum FromFunctionError<E> {
    /// The function failed (its first failure, returned as is).
    Function(E),
    /// The control net was rejected (e.g. a non-finite point).
    Network(Error),
}

/// What [`Network::repair_report`] gives.
#[derive(Debug, Clone, PartialEq)]
pub struct Repair {
    /// The repaired, compatible network.
    pub network: Network,
    /// Its C2 residual max_{r,s} ‖φ_r(v_s) − ψ_s(u_r)‖∞.
    pub c2: f64,
    /// `dependent_q[s·(m+2) + i]`: 1 when Q_i^{(s)} was recomputed, 0 for the free pivot of row s (numbers, as
    /// the API writes them).
    pub dependent_q: Vec<f64>,
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

#[cfg(test)]
mod tests {
    use super::*;

    fn wavy(u: f64, v: f64) -> DVec3 {
        DVec3::new(u, v, 0.4 * (3.0 * u).sin() * (2.0 * v).cos() + 0.2 * u * v)
    }

    #[test]
    fn the_function_is_called_at_the_greville_points_i_major() {
        // u = (0, 0.4, 1): ξ = (0, 0.2, 0.7, 1); v = (0, 0.5): η = (0, 0.25, 0.5)
        let (pu, pv) = (
            Partition::new("u", &[0.0, 0.4, 1.0]).unwrap(),
            Partition::new("v", &[0.0, 0.5]).unwrap(),
        );
        let mut calls = Vec::new();
        let net = Network::try_from_function(&pu, &pv, &mut |x, y| {
            calls.push((x, y));
            Ok::<_, ()>(DVec3::new(x, y, x * y))
        })
        .unwrap();
        let want: Vec<(f64, f64)> = [0.0, 0.2, 0.7, 1.0]
            .iter()
            .flat_map(|&x| [0.0, 0.25, 0.5].map(|y| (x, y)))
            .collect();
        assert_eq!(calls.len(), 12);
        for (c, w) in calls.iter().zip(&want) {
            assert!((c.0 - w.0).abs() < 1e-15 && c.1 == w.1, "{c:?} vs {w:?}");
        }
        // f = (u, v, uv) is bilinear: the quasi-interpolant reproduces it, so φ_1(v) = (0.4, v, 0.4v)
        let p = net.phi(1, 0.3)[0];
        assert!((p - DVec3::new(0.4, 0.3, 0.12)).length() < 1e-15, "{p}");
        assert!(net.compatibility().unwrap().c2 < 1e-15);
    }

    #[test]
    fn the_first_failure_of_the_function_is_returned_and_ends_the_calls() {
        let (pu, pv) = (
            Partition::new("u", &[0.0, 0.4, 1.0]).unwrap(),
            Partition::new("v", &[0.0, 0.3, 0.7, 1.0]).unwrap(),
        );
        let mut count = 0;
        let e = Network::try_from_function(&pu, &pv, &mut |x, y| {
            count += 1;
            if count >= 7 {
                Err(format!("failed at ({x}, {y})"))
            } else {
                Ok(wavy(x, y))
            }
        })
        .unwrap_err();
        // call 7 is i = 1 (ξ_1 = 0.2), j = 1 (η_1 = 0.15): 5 calls per row
        assert_eq!(count, 7);
        assert_eq!(
            e,
            FromFunctionError::Function("failed at (0.2, 0.15)".into())
        );
        // a non-finite point is the network's error, named by its control point
        let e = Network::try_from_function(&pu, &pv, &mut |x, _| {
            Ok::<_, ()>(DVec3::new(1.0 / (x - 0.7), 0.0, 0.0))
        })
        .unwrap_err();
        match e {
            FromFunctionError::Network(e) => assert_eq!(e.field(), "C[2][0]"),
            other => panic!("{other:?}"),
        }
        // from_function keeps its own message for a non-finite point
        let e = Network::from_function(&[0.0, 1.0], &[0.0, 1.0], |_, _| DVec3::NAN).unwrap_err();
        assert_eq!(e.field(), "f");
    }

    /// A compatible m = 2, n = 3 network whose every Q is then moved by (1, 1, 1).
    fn shifted() -> Network {
        let mut net =
            Network::from_function(&[0.0, 0.4, 1.0], &[0.0, 0.3, 0.7, 1.0], wavy).unwrap();
        for q in net.q.iter_mut().flatten() {
            *q += DVec3::ONE;
        }
        net
    }

    #[test]
    fn dependent_q_has_one_free_pivot_per_row() {
        let net = shifted();
        let (t, f) = (1.0, 0.0);
        // no edit: the pivot of every row is Q_1
        let r = net.repair_report(None).unwrap();
        assert_eq!(r.dependent_q, [[t, f, t, t]; 4].concat());
        assert!(r.c2 < 1e-14);
        // an edited interior Q_2^(1) is the pivot of row 1
        let r = net.repair_report(Some(NetPoint::Q { s: 1, i: 2 })).unwrap();
        let want = [[t, f, t, t], [t, t, f, t], [t, f, t, t], [t, f, t, t]].concat();
        assert_eq!(r.dependent_q, want);
        // an edited end point Q_0^(2) (or a P) moves a boundary curve; the pivots stay Q_1
        for e in [NetPoint::Q { s: 2, i: 0 }, NetPoint::P { r: 1, j: 2 }] {
            let r = net.repair_report(Some(e)).unwrap();
            assert_eq!(r.dependent_q, [[t, f, t, t]; 4].concat(), "{e:?}");
        }
    }

    #[test]
    fn dependent_q_flags_exactly_the_points_the_repair_changed() {
        let net = shifted();
        for edited in [
            None,
            Some(NetPoint::Q { s: 1, i: 2 }),
            Some(NetPoint::Q { s: 3, i: 1 }),
        ] {
            let r = net.repair_report(edited).unwrap();
            let changed: Vec<f64> = (net.q.iter().flatten())
                .zip(r.network.q.iter().flatten())
                .map(|(a, b)| if (*a - *b).length() > 1e-9 { 1.0 } else { 0.0 })
                .collect();
            assert_eq!(r.dependent_q, changed, "{edited:?}");
            assert!(r.network.compatibility().unwrap().c2 < 1e-14);
        }
    }
}
