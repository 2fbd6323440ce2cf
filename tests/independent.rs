//! Independent checks: quantities the library computes with one formula, recomputed here by a different
//! route that shares no helper with it.
//!
//! * The thin-plate energy Π = ∫∫ |T_uu|² + 2|T_uv|² + |T_vv|² of the tensor-product surface T
//!   (Dagnino–Lamberti–Remogna, eqs. (35)–(38)) and its optimal C11*: here Π is integrated with a 4-point
//!   Gauss rule (not the library's 3-point rule) of second derivatives obtained by central differences of
//!   the *evaluated* surface's first partials (not from the control points and basis derivatives), and the
//!   optimum is found by fitting a parabola to three independent energies (not by eq. (38)).
//! * The fallback normals of the mesh (`mesh::Mesh::from_grid`): a grid without partials, a surface whose
//!   partials vanish on a row that is not collapsed, and the collapsed rows (poles) at both ends.
//! * ‖A − B‖∞ of the network surfaces (`gordon::difference`, the measure behind the API's
//!   `surfaceDifferences`) against distances computed point by point from the surfaces' evaluations.
//!   The API export itself is checked the same way in `tests/wasm_independent.rs`.

use glam::DVec3;
use splinelab::bspline::BSplineSurface;
use splinelab::criss_cross::CrissCrossSurface;
use splinelab::gordon::{self, GordonSurface};
use splinelab::mesh::{self, Mesh};
use splinelab::network::{examples, Network};
use splinelab::thin_plate::{energy_for_c11, ThinPlateSurface};
use splinelab::Surface;

fn networks() -> Vec<(&'static str, Network)> {
    vec![
        ("uniform dome", examples::uniform_dome()),
        ("uniform random", examples::uniform_random()),
        ("non-uniform m4n5", examples::nonuniform_dome()),
        ("three-sided m5n3", examples::three_sided()),
        ("strongly non-uniform", examples::strongly_nonuniform()),
        ("separable", examples::separable()),
        ("free data m4n3", examples::free_data()),
    ]
}

// ---------------------------------------------------------------------------------------------------
// (a) thin-plate energy and C11*
// ---------------------------------------------------------------------------------------------------

/// 4-point Gauss–Legendre on [−1, 1] (exact to degree 7; the library uses 3 points).
const GAUSS4: [(f64, f64); 4] = [
    (-0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
    (-0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.339_981_043_584_856_3, 0.652_145_154_862_546_1),
    (0.861_136_311_594_052_6, 0.347_854_845_137_453_9),
];

fn breaks(knots: &[f64]) -> Vec<f64> {
    let mut b: Vec<f64> = knots.to_vec();
    b.dedup();
    b
}

/// First partials of the evaluated surface.
fn partials<S: Surface<DVec3> + ?Sized>(s: &S, u: f64, v: f64) -> (DVec3, DVec3) {
    let mut out = [DVec3::ZERO; 3];
    s.eval_derivs(u, v, true, &mut out);
    (out[1], out[2])
}

/// Π of `s` by quadrature over the cells `bu × bv` of second derivatives from central differences of the
/// evaluated first partials. The step stays inside the cell (the Gauss nodes are ≥ 0.069 half-widths from
/// its edges), where T is biquadratic, so the differences of the (piecewise linear in the differenced
/// variable) partials are exact up to rounding.
fn independent_energy<S: Surface<DVec3> + ?Sized>(s: &S, bu: &[f64], bv: &[f64]) -> f64 {
    let mut e = 0.0;
    for cu in bu.windows(2) {
        for cv in bv.windows(2) {
            let (hu, hv) = (cu[1] - cu[0], cv[1] - cv[0]);
            let (du, dv) = (1e-3 * hu, 1e-3 * hv);
            for &(xu, wu) in &GAUSS4 {
                let u = cu[0] + 0.5 * hu * (1.0 + xu);
                for &(xv, wv) in &GAUSS4 {
                    let v = cv[0] + 0.5 * hv * (1.0 + xv);
                    let (su_p, sv_p) = partials(s, u + du, v);
                    let (su_m, sv_m) = partials(s, u - du, v);
                    let (_, sv_vp) = partials(s, u, v + dv);
                    let (_, sv_vm) = partials(s, u, v - dv);
                    let suu = (su_p - su_m) / (2.0 * du);
                    let suv = (sv_p - sv_m) / (2.0 * du);
                    let svv = (sv_vp - sv_vm) / (2.0 * dv);
                    let f =
                        suu.length_squared() + 2.0 * suv.length_squared() + svv.length_squared();
                    e += 0.25 * hu * hv * wu * wv * f;
                }
            }
        }
    }
    e
}

/// The T-family member (biquadratic tensor surface on the network's knots) with a given C11.
fn member(net: &Network, t: &ThinPlateSurface, c11: DVec3) -> BSplineSurface<DVec3> {
    let s = CrissCrossSurface::new(net).unwrap();
    let b = t.bspline();
    let (nu, nv) = b.size();
    BSplineSurface::new(
        2,
        2,
        b.knots_u().to_vec(),
        b.knots_v().to_vec(),
        nu,
        nv,
        s.control_points(c11),
    )
    .unwrap()
}

#[test]
fn thin_plate_energy_matches_an_independent_quadrature_of_the_evaluated_surface() {
    for (name, net) in networks() {
        let t = ThinPlateSurface::new(&net).unwrap();
        let (bu, bv) = (breaks(t.bspline().knots_u()), breaks(t.bspline().knots_v()));
        let e = independent_energy(&t, &bu, &bv);
        let rel = (e - t.energy()).abs() / e.abs().max(1e-300);
        assert!(
            rel <= 1e-10,
            "{name}: independent Π = {e}, library Π = {} (rel {rel:.2e})",
            t.energy()
        );
        // and the library's Π for an arbitrary C11 (not the optimum)
        let c = t.c11() + DVec3::new(0.3, -0.2, 0.7);
        let e2 = independent_energy(&member(&net, &t, c), &bu, &bv);
        let lib = energy_for_c11(&net, c).unwrap();
        assert!(
            (e2 - lib).abs() <= 1e-10 * e2.abs().max(1e-300),
            "{name}: Π(C11 + d): independent {e2}, library {lib}"
        );
    }
}

#[test]
fn optimal_c11_is_the_minimum_of_the_independent_energy() {
    for (name, net) in networks() {
        let t = ThinPlateSurface::new(&net).unwrap();
        let (bu, bv) = (breaks(t.bspline().knots_u()), breaks(t.bspline().knots_v()));
        let c = t.c11();
        let e0 = independent_energy(&member(&net, &t, c), &bu, &bv);
        for k in 0..3 {
            // Π is quadratic in each component of C11 (the other two fixed): three values fix the parabola.
            let step = 0.5 * c[k].abs().max(1.0);
            let mut d = DVec3::ZERO;
            d[k] = step;
            let ep = independent_energy(&member(&net, &t, c + d), &bu, &bv);
            let em = independent_energy(&member(&net, &t, c - d), &bu, &bv);
            let curv = ep - 2.0 * e0 + em;
            assert!(curv > 0.0, "{name}: Π not convex in component {k}");
            let xmin = c[k] + step * (em - ep) / (2.0 * curv);
            assert!(
                (xmin - c[k]).abs() <= 1e-9 * c[k].abs().max(1.0),
                "{name}: component {k}: independent optimum {xmin}, library C11* {}",
                c[k]
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------------
// (b) fallback normals of the mesh
// ---------------------------------------------------------------------------------------------------

fn normal(m: &Mesh, k: usize) -> DVec3 {
    DVec3::new(
        m.normals[3 * k] as f64,
        m.normals[3 * k + 1] as f64,
        m.normals[3 * k + 2] as f64,
    )
}

fn position(m: &Mesh, k: usize) -> DVec3 {
    DVec3::new(
        m.positions[3 * k] as f64,
        m.positions[3 * k + 1] as f64,
        m.positions[3 * k + 2] as f64,
    )
}

#[test]
fn mesh_without_partials_uses_grid_differences() {
    // z = f(x, y) = 0.5 x² − 0.3 x y + 0.2 y² on [−1, 1]²: the normal is (−f_x, −f_y, 1)/‖·‖
    let (nu, nv) = (41, 33);
    let mut pts = Vec::new();
    for iu in 0..nu {
        for iv in 0..nv {
            let x = -1.0 + 2.0 * iu as f64 / (nu - 1) as f64;
            let y = -1.0 + 2.0 * iv as f64 / (nv - 1) as f64;
            pts.extend_from_slice(&[x, y, 0.5 * x * x - 0.3 * x * y + 0.2 * y * y]);
        }
    }
    let m = Mesh::from_grid(&pts, None, 3, nu, nv).unwrap();
    let mut worst_inner: f64 = 0.0;
    for iu in 0..nu {
        for iv in 0..nv {
            let k = iu * nv + iv;
            let p = position(&m, k);
            let exact = DVec3::new(-(p.x - 0.3 * p.y), -(-0.3 * p.x + 0.4 * p.y), 1.0).normalize();
            let n = normal(&m, k);
            assert!((n.length() - 1.0).abs() < 1e-6, "unit normal at {iu},{iv}");
            let err = (n - exact).length();
            // one-sided differences at the border: first order; central inside: second order (and exact
            // here for a quadratic, up to f32 rounding)
            let inner = iu > 0 && iu + 1 < nu && iv > 0 && iv + 1 < nv;
            if inner {
                worst_inner = worst_inner.max(err);
            } else {
                assert!(err < 0.05, "border normal at {iu},{iv}: {n} vs {exact}");
            }
        }
    }
    assert!(worst_inner < 1e-5, "inner normals off by {worst_inner}");
}

/// S(u, v) = (u³, v, 0.3 v²): ∂S/∂u = 0 on the row u = 0, which is not collapsed.
struct Flat;
impl Surface<DVec3> for Flat {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        ((-1.0, 1.0), (-1.0, 1.0))
    }
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [DVec3; 3]) {
        out[0] = DVec3::new(u * u * u, v, 0.3 * v * v);
        if derivs {
            out[1] = DVec3::new(3.0 * u * u, 0.0, 0.0);
            out[2] = DVec3::new(0.0, 1.0, 0.6 * v);
        }
    }
}

#[test]
fn vanishing_partial_on_an_open_row_falls_back_to_central_differences() {
    let (nu, nv) = (21, 11);
    let m = mesh::tessellate(&Flat, nu, nv).unwrap();
    let iu0 = nu / 2; // u = 0
    assert!(position(&m, iu0 * nv).x.abs() < 1e-12);
    for iu in 0..nu {
        for iv in 0..nv {
            let k = iu * nv + iv;
            let y = position(&m, k).y;
            // (3u², 0, 0) × (0, 1, 0.6v) ∝ (0, −0.6 v, 1), and so is the central difference on u = 0
            let exact = DVec3::new(0.0, -0.6 * y, 1.0).normalize();
            let n = normal(&m, k);
            // on the fallback row the v-difference is one-sided at the two border vertices (first order)
            let tol = if iu == iu0 && (iv == 0 || iv + 1 == nv) {
                0.1
            } else {
                1e-6
            };
            assert!(
                (n - exact).length() < tol,
                "normal at {iu},{iv} (u = 0 row: {}): {n} vs {exact}",
                iu == iu0
            );
        }
    }
}

#[test]
fn collapsed_rows_at_both_ends_get_outward_normals() {
    // a sphere grid with both poles (rows iu = 0 and iu = nu − 1 collapse to a point), given without
    // partials and with partials (∂S/∂v = 0 at the poles)
    let (nu, nv) = (13, 24);
    let (pi, tau) = (std::f64::consts::PI, std::f64::consts::TAU);
    let mut pts = Vec::new();
    let (mut du, mut dv) = (Vec::new(), Vec::new());
    for iu in 0..nu {
        for iv in 0..nv {
            let (u, v) = (
                pi * iu as f64 / (nu - 1) as f64,
                tau * iv as f64 / (nv - 1) as f64,
            );
            pts.extend_from_slice(&[u.sin() * v.cos(), u.sin() * v.sin(), u.cos()]);
            du.extend_from_slice(&[u.cos() * v.cos(), u.cos() * v.sin(), -u.sin()]);
            dv.extend_from_slice(&[-u.sin() * v.sin(), u.sin() * v.cos(), 0.0]);
        }
    }
    for m in [
        Mesh::from_grid(&pts, None, 3, nu, nv).unwrap(),
        Mesh::from_grid(&pts, Some((&du, &dv)), 3, nu, nv).unwrap(),
    ] {
        for iu in 0..nu {
            for iv in 0..nv {
                let k = iu * nv + iv;
                let (p, n) = (position(&m, k), normal(&m, k));
                assert!((n.length() - 1.0).abs() < 1e-6, "unit normal at {iu},{iv}");
                let pole = iu == 0 || iu + 1 == nu;
                // at a pole the fallback uses the neighbouring row's spread: the normal is ±e_z there
                let min = if pole { 0.99 } else { 0.95 };
                assert!(n.dot(p) > min, "outward normal at {iu},{iv}: {n} vs {p}");
            }
        }
    }
}

// ---------------------------------------------------------------------------------------------------
// (c) ‖A − B‖∞ against point-by-point distances
// ---------------------------------------------------------------------------------------------------

/// max over a `k × k` grid of max over coordinates of |A − B|, with the grid built here.
fn sampled_distance<A: Surface<DVec3>, B: Surface<DVec3>>(a: &A, b: &B, k: usize) -> f64 {
    let ((u0, u1), (v0, v1)) = a.domain();
    let mut d: f64 = 0.0;
    for i in 0..k {
        let u = if i + 1 == k {
            u1
        } else {
            u0 + (u1 - u0) * i as f64 / (k - 1) as f64
        };
        for j in 0..k {
            let v = if j + 1 == k {
                v1
            } else {
                v0 + (v1 - v0) * j as f64 / (k - 1) as f64
            };
            let e = a.eval(u, v) - b.eval(u, v);
            d = d.max(e.x.abs()).max(e.y.abs()).max(e.z.abs());
        }
    }
    d
}

#[test]
fn surface_differences_match_point_by_point_distances() {
    for (name, net) in networks() {
        let s = CrissCrossSurface::new(&net).unwrap();
        let t = ThinPlateSurface::new(&net).unwrap();
        let g = GordonSurface::new(&net).unwrap();
        for (pair, lib, ind) in [
            (
                "SG",
                gordon::difference(&s, &g),
                sampled_distance(&s, &g, 57),
            ),
            (
                "ST",
                gordon::difference(&s, &t),
                sampled_distance(&s, &t, 57),
            ),
            (
                "TG",
                gordon::difference(&t, &g),
                sampled_distance(&t, &g, 57),
            ),
        ] {
            assert!(
                (lib - ind).abs() <= 1e-14 * net.scale().max(1.0),
                "{name}: ‖{pair}‖ library {lib}, sampled {ind}"
            );
        }
    }
}
