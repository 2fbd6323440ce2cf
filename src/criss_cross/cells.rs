//! The BB ordinates of every cell gathered into flat arrays (of one B_ij, or of S's local form), with their
//! (u, v) domain points and, for B_ij, which triangles it lives on (`surfaces.md` §2.1, §2.3).

use super::cell::{Triangle, DOMAIN_POINTS};
use super::surface::CrissCrossSurface;
use super::triangulation::CrissCross;

/// The 13 BB ordinates of every cell, cell (a, b) at block (a−1)·n + (b−1), ordinates in the order
/// c00, c10, c11, c01, eb, er, et, el, d00, d10, d11, d01, o ([`super::C00`] … [`super::O`]).
#[derive(Debug, Clone, PartialEq)]
pub struct CellOrdinates {
    /// Cells in u.
    pub m: usize,
    /// Cells in v.
    pub n: usize,
    /// Coordinates per ordinate: 1 for B_ij, 3 for S.
    pub dim: usize,
    /// `13 · dim` numbers per cell.
    pub ordinates: Vec<f64>,
    /// (u, v) of each ordinate, 26 numbers per cell ([`CrissCross::domain_points`]).
    pub domain_points: Vec<f64>,
    /// For B_ij: 4 flags per cell (triangles bottom, right, top, left), 1 where B_ij is not identically
    /// zero, i.e. where one of the triangle's 6 ordinates is non-zero, else 0 (numbers, as the API writes
    /// them). `None` for S.
    pub support: Option<Vec<f64>>,
}

impl CellOrdinates {
    /// The local-form BB nets of S (§3: corners I_rs, edge midpoints the network's middle ordinates), xyz.
    pub fn of_surface(s: &CrissCrossSurface) -> Self {
        let cc = s.triangulation();
        let (m, n) = cc.cells();
        let mut ordinates = Vec::with_capacity(m * n * 39);
        for a in 1..=m {
            for b in 1..=n {
                if let Some(net) = s.cell_net(a, b) {
                    for p in net {
                        ordinates.extend_from_slice(&[p.x, p.y, p.z]);
                    }
                }
            }
        }
        CellOrdinates {
            m,
            n,
            dim: 3,
            ordinates,
            domain_points: cc.domain_points(),
            support: None,
        }
    }

    /// The BB nets of B_ij (closed form of §2.3; all zeros outside its support) and its support flags.
    pub fn of_basis(cc: &CrissCross, i: usize, j: usize) -> Self {
        let (m, n) = cc.cells();
        let mut ordinates = Vec::with_capacity(m * n * 13);
        let mut support = Vec::with_capacity(m * n * 4);
        for a in 1..=m {
            for b in 1..=n {
                let net = cc.basis_net(i, j, a, b);
                ordinates.extend_from_slice(&net);
                for tri in Triangle::ALL {
                    let live = tri.ordinates().iter().any(|k| net[*k] != 0.0);
                    support.push(if live { 1.0 } else { 0.0 });
                }
            }
        }
        CellOrdinates {
            m,
            n,
            dim: 1,
            ordinates,
            domain_points: cc.domain_points(),
            support: Some(support),
        }
    }
}

impl CrissCross {
    /// The (u, v) domain points of the 13 ordinates of every cell, 26 numbers per cell in the order of
    /// [`CellOrdinates`]: (u_{a−1} + s·h_a, v_{b−1} + t·k_b) for the local (s, t) of [`DOMAIN_POINTS`].
    pub fn domain_points(&self) -> Vec<f64> {
        let (m, n) = self.cells();
        let (pu, pv) = (self.u(), self.v());
        let mut out = Vec::with_capacity(m * n * 26);
        for a in 1..=m {
            for b in 1..=n {
                let (u0, v0) = (pu.breaks()[a - 1], pv.breaks()[b - 1]);
                for (s, t) in DOMAIN_POINTS {
                    out.push(u0 + s * pu.h(a));
                    out.push(v0 + t * pv.h(b));
                }
            }
        }
        out
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::criss_cross::{C00, C10, EB, O};
    use crate::network::Network;
    use crate::sample::Surface;
    use glam::DVec3;

    #[test]
    fn basis_ordinates_sum_to_one_on_every_cell() {
        // partition of unity: all 13 ordinates of Σ_ij B_ij equal 1 on every cell (§2.4)
        let cc = CrissCross::new(&[0.0, 0.3, 0.5, 1.2], &[0.0, 0.4, 1.0, 1.5, 2.0]).unwrap();
        let (m, n) = cc.cells();
        let mut total = vec![0.0; m * n * 13];
        for i in 0..m + 2 {
            for j in 0..n + 2 {
                let c = CellOrdinates::of_basis(&cc, i, j);
                assert_eq!((c.m, c.n, c.dim), (3, 4, 1));
                for (t, x) in total.iter_mut().zip(&c.ordinates) {
                    *t += x;
                }
            }
        }
        assert!(total.iter().all(|t| (t - 1.0).abs() < 1e-15), "{total:?}");
    }

    #[test]
    fn corner_basis_lives_on_two_triangles_of_the_first_cell() {
        // B_00: the single non-zero ordinate c00 = 1 on cell (1, 1) (§2.3), so it lives on the triangles
        // bottom (c00, c10, o) and left (c01, c00, o) of that cell and nowhere else
        let cc = CrissCross::new(&[0.0, 0.4, 1.0], &[0.0, 0.3, 0.7, 1.0]).unwrap();
        let c = CellOrdinates::of_basis(&cc, 0, 0);
        assert_eq!(c.ordinates.len(), 2 * 3 * 13);
        assert_eq!(c.ordinates[C00], 1.0);
        assert_eq!(c.ordinates.iter().filter(|x| **x != 0.0).count(), 1);
        let mut want = vec![0.0; 2 * 3 * 4];
        want[0] = 1.0; // cell (1, 1), bottom
        want[3] = 1.0; // cell (1, 1), left
        assert_eq!(c.support.unwrap(), want);
        // and B_00(u_0, v_0) = 1 at that domain point
        assert_eq!(cc.basis(0, 0, 0.0, 0.0)[0], 1.0);
    }

    #[test]
    fn support_flags_match_where_the_basis_is_non_zero() {
        // an interior B_ij lives on 28 triangles (octagonal support, §2.3); each flag is checked against
        // the value of B_ij at the triangle's centroid (non-zero inside the support: B_ij > 0 there)
        let cc = CrissCross::new(
            &[0.0, 1.0, 2.0, 3.5, 4.0, 5.0],
            &[0.0, 0.5, 1.0, 2.0, 3.0, 3.2],
        )
        .unwrap();
        let c = CellOrdinates::of_basis(&cc, 3, 3);
        let flags = c.support.unwrap();
        assert_eq!(flags.iter().filter(|f| **f == 1.0).count(), 28);
        let centroids = [
            (0.5, 1.0 / 6.0),
            (5.0 / 6.0, 0.5),
            (0.5, 5.0 / 6.0),
            (1.0 / 6.0, 0.5),
        ];
        let (pu, pv) = (cc.u().clone(), cc.v().clone());
        for a in 1..=5 {
            for b in 1..=5 {
                for (k, (s, t)) in centroids.iter().enumerate() {
                    let u = pu.breaks()[a - 1] + s * pu.h(a);
                    let v = pv.breaks()[b - 1] + t * pv.h(b);
                    let value = cc.basis(3, 3, u, v)[0];
                    let flag = flags[((a - 1) * 5 + b - 1) * 4 + k];
                    assert_eq!(flag == 1.0, value > 1e-15, "{a} {b} {k}");
                }
            }
        }
    }

    #[test]
    fn domain_points_are_the_local_points_on_each_cell() {
        let cc = CrissCross::new(&[0.0, 0.4, 1.0], &[0.0, 0.5]).unwrap();
        let d = cc.domain_points();
        assert_eq!(d.len(), 2 * 26);
        // cell (1, 1), corner c10 at (1, 0)
        assert_eq!((d[2 * C10], d[2 * C10 + 1]), (0.4, 0.0));
        // cell (2, 1) = [0.4, 1] × [0, 0.5]: centre o at (0.7, 0.25), bottom midpoint eb at (0.7, 0)
        let cell2 = &d[26..];
        assert!((cell2[2 * O] - 0.7).abs() < 1e-15 && cell2[2 * O + 1] == 0.25);
        assert!((cell2[2 * EB] - 0.7).abs() < 1e-15 && cell2[2 * EB + 1] == 0.0);
    }

    #[test]
    fn surface_ordinates_are_the_values_at_corners_and_the_network_midpoints() {
        let net = Network::from_function(&[0.0, 0.4, 1.0], &[0.0, 0.3, 0.7, 1.0], |u, v| {
            DVec3::new(u, v, (3.0 * u).sin() * v)
        })
        .unwrap();
        let s = CrissCrossSurface::new(&net).unwrap();
        let c = CellOrdinates::of_surface(&s);
        assert_eq!((c.m, c.n, c.dim, c.support.is_none()), (2, 3, 3, true));
        assert_eq!(c.ordinates.len(), 6 * 39);
        for a in 1..=2 {
            for b in 1..=3 {
                let block = &c.ordinates[((a - 1) * 3 + b - 1) * 39..];
                let at = |k: usize| DVec3::new(block[3 * k], block[3 * k + 1], block[3 * k + 2]);
                // corner c00 = S(u_{a−1}, v_{b−1}) = φ_{a−1}(v_{b−1})
                let corner = net.phi(a - 1, net.v[b - 1])[0];
                assert!((at(C00) - corner).length() < 1e-14);
                let dp = &c.domain_points[((a - 1) * 3 + b - 1) * 26..];
                assert!((s.eval(dp[0], dp[1]) - corner).length() < 1e-14);
                // bottom midpoint eb = Q_a^(b−1), the middle Bézier ordinate of ψ_{b−1} on cell a
                assert_eq!(at(EB), net.q[b - 1][a]);
            }
        }
    }
}
