//! Dagnino–Lamberti–Remogna §4.2 i): the biquadratic tensor-product surface T through a compatible curve network, with
//! the free point C11* chosen by minimal thin-plate energy.
//!
//! T(u, v) = Σ C*_ij B_i(u|U) B_j(v|V) (eq. (35)) on the knots U × V of the network. Theorem 3.1 and
//! Lemma 3.1 hold with B*_ij = B_i B_j, so C*_ij = Γ_ij + (−1)^{i+j} C11*·h_i k_j/(h_1 k_1) with the
//! boundary rows/columns from (18)–(21) (`surfaces.md` §4): the same control points as
//! [`CrissCrossSurface::control_points`]. But the B*_ij are independent, so T depends on C11* (eq. (37)).
//!
//! Energy Π = ∫∫ |T_uu|² + 2|T_uv|² + |T_vv|² (summed over x, y, z). With T = T_0 + x·T_w, where
//! T_w = Σ w_ij B*_ij, w_ij = (−1)^{i+j} h_i k_j/(h_1 k_1) (= T_1/(h_1 k_1) of (36)), each coordinate's
//! Π_c(x) = A_c + 2 x B_c + x² D is minimal at x = −B_c/D — eq. (38) componentwise. The integrals are
//! exact per cell with 3×3 Gauss–Legendre nodes: on a cell T is biquadratic, so |T_uu|² has degree (0, 4),
//! |T_uv|² (2, 2), |T_vv|² (4, 0), all ≤ 5 in each variable, the exactness degree of 3-point Gauss.

use crate::bspline::{basis_derivs, BSplineSurface};
use crate::criss_cross::{c11_weights, CrissCross, CrissCrossSurface};
use crate::error::Result;
use crate::knots::{find_span, MAX_DEGREE};
use crate::network::Network;
use crate::point::Point;
use crate::sample::Surface;
use glam::DVec3;

const GAUSS3: [(f64, f64); 3] = [
    (-0.774_596_669_241_483_4, 5.0 / 9.0),
    (0.0, 8.0 / 9.0),
    (0.774_596_669_241_483_4, 5.0 / 9.0),
];

/// The thin-plate surface T with its optimal C11* and energy.
///
/// # Template
/// * **What**: the biquadratic tensor-product surface T of Dagnino–Lamberti–Remogna §4.2 (i), eq. (35), with the free
///   control point C11* of minimal thin-plate energy (eq. (38)).
/// * **Interpolates**: every curve of a compatible network.
/// * **Continuity**: C¹ (a biquadratic B-spline on simple knots).
/// * **Parametrisation**: the network's breakpoints, (u, v) ∈ [u_0, u_m] × [v_0, v_n].
///
/// # Example
/// ```
/// use splinelab::{network::examples, Surface, thin_plate::ThinPlateSurface};
/// let net = examples::uniform_dome();
/// let s = ThinPlateSurface::new(&net)?;
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
pub struct ThinPlateSurface {
    surface: BSplineSurface<DVec3>,
    c11: DVec3,
    energy: f64,
}

impl ThinPlateSurface {
    /// Checks the network (shape, C2) and builds T with C11* of eq. (38).
    pub fn new(network: &Network) -> Result<Self> {
        Self::with_tolerance(network, crate::network::COMPATIBILITY_TOL)
    }

    /// Like [`ThinPlateSurface::new`] with a custom relative C2 tolerance.
    pub fn with_tolerance(network: &Network, rel_tol: f64) -> Result<Self> {
        let s = CrissCrossSurface::with_tolerance(network, rel_tol)?;
        let cc = s.triangulation().clone();
        let g = s.control_points(DVec3::ZERO);
        let w = c11_weights(&cc);
        let (ku, kv) = (cc.u().knots(), cc.v().knots());
        let (m, n) = cc.cells();
        let (nu, nv) = (m + 2, n + 2);
        // Π_c(x) = A_c + 2x B_c + x² D
        let quad = energy_terms(&ku, &kv, nu, nv, &g, &w);
        let c11 = if quad.d > 0.0 {
            -quad.b * (1.0 / quad.d)
        } else {
            DVec3::ZERO
        };
        let energy = (quad.a + quad.b * c11 * 2.0 + c11 * c11 * quad.d).element_sum();
        let ctrl: Vec<DVec3> = g.iter().zip(&w).map(|(gi, wi)| *gi + c11 * *wi).collect();
        let surface = BSplineSurface::new(2, 2, ku, kv, nu, nv, ctrl)?;
        Ok(ThinPlateSurface {
            surface,
            c11,
            energy,
        })
    }

    /// The tensor-product C11* (by (38), componentwise).
    pub fn c11(&self) -> DVec3 {
        self.c11
    }
    /// Π at C11* (summed over x, y, z).
    pub fn energy(&self) -> f64 {
        self.energy
    }
    /// The biquadratic B-spline surface (knots U × V, control points C*_ij).
    pub fn bspline(&self) -> &BSplineSurface<DVec3> {
        &self.surface
    }
    /// C*_ij, i-major ((m+2)(n+2) points).
    pub fn control_points(&self) -> &[DVec3] {
        self.surface.points()
    }
}

impl Surface<DVec3> for ThinPlateSurface {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        self.surface.domain()
    }
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [DVec3; 3]) {
        self.surface.eval_derivs(u, v, derivs, out)
    }
    /// The kernel's grid sampler on the tensor B-spline this surface is.
    fn sample_grid_into(
        &self,
        us: &[f64],
        vs: &[f64],
        derivs: bool,
        points: &mut [f64],
        du: &mut [f64],
        dv: &mut [f64],
    ) {
        self.surface
            .sample_grid_into(us, vs, derivs, points, du, dv)
    }
}

struct Quadratic {
    a: DVec3,
    b: DVec3,
    d: f64,
}

/// Π of Σ (g + x w)_ij B*_ij as A + 2xB + x²D per coordinate.
fn energy_terms(ku: &[f64], kv: &[f64], nu: usize, nv: usize, g: &[DVec3], w: &[f64]) -> Quadratic {
    let mut q = Quadratic {
        a: DVec3::ZERO,
        b: DVec3::ZERO,
        d: 0.0,
    };
    for_each_gauss_point(ku, kv, nu, nv, |wt, du, dv, su, sv| {
        let sg = second_derivs(g, nv, du, dv, su, sv);
        let sw = second_derivs(w, nv, du, dv, su, sv);
        q.a += (sg[0] * sg[0] + sg[1] * sg[1] * 2.0 + sg[2] * sg[2]) * wt;
        q.b += (sg[0] * sw[0] + sg[1] * sw[1] * 2.0 + sg[2] * sw[2]) * wt;
        q.d += (sw[0] * sw[0] + 2.0 * sw[1] * sw[1] + sw[2] * sw[2]) * wt;
    });
    q
}

/// The thin-plate energy Π (per coordinate) of the biquadratic tensor surface with control points
/// `ctrl` (i-major, `nu × nv`) on the quadratic knot vectors `ku`, `kv` (exact 3×3 Gauss per cell).
pub fn thin_plate_energy<P: Point>(ku: &[f64], kv: &[f64], nu: usize, nv: usize, ctrl: &[P]) -> P {
    let mut e = P::ZERO;
    for_each_gauss_point(ku, kv, nu, nv, |wt, du, dv, su, sv| {
        let s = second_derivs(ctrl, nv, du, dv, su, sv);
        let sq = |p: P| -> P {
            // coordinate-wise square
            let mut c = [0.0; 3];
            for (k, x) in c.iter_mut().enumerate().take(P::DIM) {
                *x = p.coord(k) * p.coord(k);
            }
            P::from_coords(&c).unwrap_or(P::ZERO)
        };
        e += (sq(s[0]) + sq(s[1]) * 2.0 + sq(s[2])) * wt;
    });
    e
}

/// The thin-plate energy of the network's T-family member with a given C11 (summed over x, y, z).
pub fn energy_for_c11(network: &Network, c11: DVec3) -> Result<f64> {
    let s = CrissCrossSurface::new(network)?;
    let cc: &CrissCross = s.triangulation();
    let ctrl = s.control_points(c11);
    let (m, n) = cc.cells();
    Ok(thin_plate_energy(&cc.u().knots(), &cc.v().knots(), m + 2, n + 2, &ctrl).element_sum())
}

type Ders = [[f64; MAX_DEGREE + 1]; 3];

/// Calls `f(weight, ders_u, ders_v, span_u, span_v)` at the 3×3 Gauss points of every non-empty cell.
fn for_each_gauss_point(
    ku: &[f64],
    kv: &[f64],
    nu: usize,
    nv: usize,
    mut f: impl FnMut(f64, &Ders, &Ders, usize, usize),
) {
    let mut du = [[0.0; MAX_DEGREE + 1]; 3];
    let mut dv = [[0.0; MAX_DEGREE + 1]; 3];
    for a in 2..nu {
        let (u0, u1) = (ku[a], ku[a + 1]);
        if u1 <= u0 {
            continue;
        }
        for b in 2..nv {
            let (v0, v1) = (kv[b], kv[b + 1]);
            if v1 <= v0 {
                continue;
            }
            let area = 0.25 * (u1 - u0) * (v1 - v0);
            for &(xu, wu) in &GAUSS3 {
                let u = 0.5 * (u0 + u1) + 0.5 * (u1 - u0) * xu;
                let su = find_span(ku, 2, nu, u);
                basis_derivs(ku, 2, su, u, 2, &mut du);
                for &(xv, wv) in &GAUSS3 {
                    let v = 0.5 * (v0 + v1) + 0.5 * (v1 - v0) * xv;
                    let sv = find_span(kv, 2, nv, v);
                    basis_derivs(kv, 2, sv, v, 2, &mut dv);
                    f(area * wu * wv, &du, &dv, su, sv);
                }
            }
        }
    }
}

/// [T_uu, T_uv, T_vv] of Σ c_ij N_i M_j at a point with basis derivatives `du` (span `su`), `dv` (`sv`).
fn second_derivs<P: Point>(
    c: &[P],
    nv: usize,
    du: &Ders,
    dv: &Ders,
    su: usize,
    sv: usize,
) -> [P; 3] {
    let mut out = [P::ZERO; 3];
    for x in 0..3 {
        let i = su - 2 + x;
        for y in 0..3 {
            let j = sv - 2 + y;
            let cij = c[i * nv + j];
            out[0] += cij * (du[2][x] * dv[0][y]);
            out[1] += cij * (du[1][x] * dv[1][y]);
            out[2] += cij * (du[0][x] * dv[2][y]);
        }
    }
    out
}
