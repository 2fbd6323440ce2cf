//! The two choices of the surface S that do not change it (`surfaces.md` §3): the free control point C11 of
//! Lemma 3.1 and the form S is evaluated by; [`CrissCrossSurface::resolve`] turns them into everything a
//! caller reports (C11, the control points C_ij, the evaluator, the C2 residual) in one call.

use super::spline::CrissCrossSpline;
use super::surface::CrissCrossSurface;
use crate::error::Result;
use glam::DVec3;

/// The free control point C11 of Lemma 3.1: a given point, or the rule that picks it.
///
/// The B_ij are linearly dependent (Σ_{i=1..m, j=1..n} (−1)^{i+j} h_i k_j B_ij = 0), so every C11 gives the
/// same surface S; it only changes the control net C_ij = Γ_ij + (−1)^{i+j} C11 h_i k_j/(h_1 k_1) ((26)–(27)).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum C11Choice {
    /// This point.
    Point(DVec3),
    /// Minimal area of the bilinear control net (the paper's choice, §4.1; [`CrissCrossSurface::min_area_c11`]).
    #[default]
    Area,
    /// Minimal sum of squared control-net edge lengths ([`CrissCrossSurface::default_c11`]).
    Edges,
}

impl C11Choice {
    /// The point C11 this choice gives for the surface `s`.
    pub fn resolve(self, s: &CrissCrossSurface) -> DVec3 {
        match self {
            C11Choice::Point(c) => c,
            C11Choice::Area => s.min_area_c11(),
            C11Choice::Edges => s.default_c11(),
        }
    }
}

/// How S is evaluated (both give the same surface up to rounding ∝ max|C_ij|).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Evaluation {
    /// The local BB form of each cell (§3: corners I_rs, edge midpoints the network's middle ordinates).
    #[default]
    Local,
    /// Σ C_ij B_ij (eq. (13)) with the control points of the chosen C11.
    Sum,
}

/// What [`CrissCrossSurface::resolve`] gives: the C11 used, S in the chosen form with the control points of
/// that C11, and the network's C2 residual.
#[derive(Debug, Clone, PartialEq)]
pub struct ResolvedSurface {
    /// The C11 used.
    pub c11: DVec3,
    /// S = Σ C_ij B_ij: its control points C_ij of Lemma 3.1 for that C11 (i-major, index i·(n+2)+j,
    /// [`CrissCrossSpline::control_points`]) and its cell nets, those of the local form
    /// ([`Evaluation::Local`]) or of the sum ([`Evaluation::Sum`]).
    pub surface: CrissCrossSpline<DVec3>,
    /// The C2 residual max_{r,s} ‖φ_r(v_s) − ψ_s(u_r)‖∞ of the network (eq. (6)).
    pub c2: f64,
}

impl CrissCrossSurface {
    /// Applies the two choices: C11 by `c11`, the control points C_ij for it ((18)–(21), (17), (16)) and S
    /// evaluated by `evaluate`. Fails only when Σ C_ij B_ij is asked for and a C_ij is not finite.
    pub fn resolve(&self, c11: C11Choice, evaluate: Evaluation) -> Result<ResolvedSurface> {
        let c11 = c11.resolve(self);
        let ctrl = self.control_points(c11);
        let cc = self.triangulation().clone();
        let surface = match evaluate {
            Evaluation::Local => CrissCrossSpline::with_nets(cc, ctrl, self.cell_nets().to_vec()),
            Evaluation::Sum => CrissCrossSpline::new(cc, ctrl)?,
        };
        let c2 = self.network().compatibility()?.c2;
        Ok(ResolvedSurface { c11, surface, c2 })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::network::Network;
    use crate::sample::Surface;

    /// f(u, v) = (u, v, 1 + 2u − v + 3uv): bilinear, so the quasi-interpolant's network is its isocurves
    /// and S = f exactly (bilinear precision of the B_ij, §2.4).
    fn bilinear(u: f64, v: f64) -> DVec3 {
        DVec3::new(u, v, 1.0 + 2.0 * u - v + 3.0 * u * v)
    }

    fn network() -> Network {
        Network::from_function(&[0.0, 0.4, 1.0], &[0.0, 0.3, 0.7, 1.0], |u, v| {
            DVec3::new(u, v, 0.4 * (3.0 * u).sin() * (2.0 * v).cos() + 0.2 * u * v)
        })
        .unwrap()
    }

    /// Σ |C_a − C_b|² over the horizontal and vertical edges of the (m+2) × (n+2) control net.
    fn edge_energy(c: &[DVec3], rows: usize, cols: usize) -> f64 {
        let mut e = 0.0;
        for i in 0..rows {
            for j in 0..cols {
                if i + 1 < rows {
                    e += (c[i * cols + j] - c[(i + 1) * cols + j]).length_squared();
                }
                if j + 1 < cols {
                    e += (c[i * cols + j] - c[i * cols + j + 1]).length_squared();
                }
            }
        }
        e
    }

    #[test]
    fn a_given_point_is_c11_of_the_control_net() {
        let s = CrissCrossSurface::new(&network()).unwrap();
        let p = DVec3::new(0.25, -1.5, 2.0);
        let r = s.resolve(C11Choice::Point(p), Evaluation::Local).unwrap();
        assert_eq!(r.c11, p);
        // m = 2, n = 3: 4 × 5 control points, C11 at index 1·5 + 1
        let ctrl = r.surface.control_points();
        assert_eq!(ctrl.len(), 20);
        assert_eq!(ctrl[6], p);
        // the boundary rows are the network's end curves ((18)–(21)): C_0j = P_j^(0), C_i0 = Q_i^(0)
        let net = s.network();
        assert_eq!(ctrl[2], net.p[0][2]);
        assert_eq!(ctrl[3 * 5], net.q[0][3]);
    }

    #[test]
    fn edges_minimises_the_squared_edge_lengths_and_area_lowers_the_net_area() {
        let s = CrissCrossSurface::new(&network()).unwrap();
        let edges = s.resolve(C11Choice::Edges, Evaluation::Local).unwrap();
        let area = s.resolve(C11Choice::Area, Evaluation::Local).unwrap();
        let e0 = edge_energy(edges.surface.control_points(), 4, 5);
        // the area rule lowers the net area below the edge rule's and every point 0.05 away from it
        // (and Newton's method lands on the minimum: tests/criss_cross.rs checks it against a pattern search)
        let a0 = s.control_net_area(area.c11);
        assert!(a0 < s.control_net_area(edges.c11));
        for d in [
            DVec3::X,
            DVec3::Y,
            DVec3::Z,
            -DVec3::X,
            -DVec3::Y,
            -DVec3::Z,
        ] {
            let moved = s.control_points(edges.c11 + d * 1e-3);
            assert!(
                edge_energy(&moved, 4, 5) > e0,
                "edge energy not minimal along {d}"
            );
            let a1 = s.control_net_area(area.c11 + d * 0.05);
            assert!(a1 > a0, "area not lower than along {d}: {a1} vs {a0}");
        }
    }

    #[test]
    fn local_and_sum_are_the_same_bilinear_and_c2_is_rounding() {
        let (u, v) = ([0.0, 0.5, 1.5, 2.0], [0.0, 1.0, 1.25]);
        let s = CrissCrossSurface::new(&Network::from_function(&u, &v, bilinear).unwrap()).unwrap();
        let local = s.resolve(C11Choice::Area, Evaluation::Local).unwrap();
        let sum = s
            .resolve(
                C11Choice::Point(DVec3::new(3.0, -2.0, 7.0)),
                Evaluation::Sum,
            )
            .unwrap();
        // the local form's nets (corners I_rs, edge midpoints from the network) or the sum's
        assert_eq!(local.surface.cell_net(2, 1), s.cell_net(2, 1));
        let o = sum.surface.cell_net(2, 1).unwrap()[crate::criss_cross::O];
        assert!((o - s.cell_net(2, 1).unwrap()[crate::criss_cross::O]).length() < 1e-12);
        assert!(local.c2 < 1e-14 && sum.c2 == local.c2);
        for (x, y) in [(0.1, 0.2), (0.7, 1.1), (1.9, 0.05), (2.0, 1.25)] {
            let want = bilinear(x, y);
            // ∂f/∂u = (1, 0, 2 + 3v), ∂f/∂v = (0, 1, −1 + 3u)
            let (du, dv) = (
                DVec3::new(1.0, 0.0, 2.0 + 3.0 * y),
                DVec3::new(0.0, 1.0, 3.0 * x - 1.0),
            );
            for r in [&local, &sum] {
                let mut out = [DVec3::ZERO; 3];
                r.surface.eval_derivs(x, y, true, &mut out);
                assert!((out[0] - want).length() < 1e-12, "{x} {y}: {}", out[0]);
                assert!((out[1] - du).length() < 1e-11 && (out[2] - dv).length() < 1e-11);
            }
        }
    }

    #[test]
    fn sum_rejects_a_non_finite_control_point() {
        let s = CrissCrossSurface::new(&network()).unwrap();
        let e = s
            .resolve(
                C11Choice::Point(DVec3::new(f64::NAN, 0.0, 0.0)),
                Evaluation::Sum,
            )
            .unwrap_err();
        assert_eq!(e.field(), "C[1][1]");
        // the local form does not use the control points
        assert!(s
            .resolve(
                C11Choice::Point(DVec3::new(f64::NAN, 0.0, 0.0)),
                Evaluation::Local
            )
            .is_ok());
    }
}
