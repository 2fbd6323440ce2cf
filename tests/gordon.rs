//! The Gordon boolean sum G and the spline-blended surface GB (`../shared/spec/surfaces.md` §5, §6, §10
//! items 18–20).

use glam::DVec3;
use splinelab::bspline::{basis_all, BSplineSurface};
use splinelab::gordon::{
    self, quadratic_knots, Blend, BlendFunctions, CubicEnd, FnLines, GordonSurface, LineNetwork,
    NetworkLines, SplineBlendedSurface, Tension,
};
use splinelab::network::Network;
use splinelab::sample::Surface;
use splinelab::ErrorKind;

// ---------------------------------------------------------------- network builders (test helpers)

/// Deterministic pseudo-random numbers in [−1, 1).
struct Rng(u64);
impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64 / (1u64 << 53) as f64) * 2.0 - 1.0
    }
    fn p(&mut self) -> DVec3 {
        DVec3::new(self.next(), self.next(), self.next())
    }
}

/// The isocurve network of the biquadratic tensor surface Σ C_ij B_i(u|U) B_j(v|V), `c[i][j]`.
fn network_from_tensor(u: &[f64], v: &[f64], c: &[Vec<DVec3>]) -> Network {
    let (m, n) = (u.len() - 1, v.len() - 1);
    let (uk, vk) = (quadratic_knots(u), quadratic_knots(v));
    let mut row = [Vec::new(), Vec::new(), Vec::new()];
    let p = u
        .iter()
        .map(|&ur| {
            basis_all(&uk, 2, ur, 0, &mut row);
            (0..n + 2)
                .map(|j| (0..m + 2).map(|i| c[i][j] * row[0][i]).sum())
                .collect()
        })
        .collect();
    let q = v
        .iter()
        .map(|&vs| {
            basis_all(&vk, 2, vs, 0, &mut row);
            (0..m + 2)
                .map(|i| (0..n + 2).map(|j| c[i][j] * row[0][j]).sum())
                .collect()
        })
        .collect();
    Network {
        u: u.to_vec(),
        v: v.to_vec(),
        p,
        q,
    }
}

fn tensor(u: &[f64], v: &[f64], c: &[Vec<DVec3>]) -> BSplineSurface<DVec3> {
    let (nu, nv) = (u.len() + 1, v.len() + 1);
    let pts = c.iter().flatten().copied().collect();
    BSplineSurface::new(2, 2, quadratic_knots(u), quadratic_knots(v), nu, nv, pts).unwrap()
}

fn random_net(u: &[f64], v: &[f64], seed: u64) -> Vec<Vec<DVec3>> {
    let mut rng = Rng(seed);
    (0..u.len() + 1)
        .map(|_| (0..v.len() + 1).map(|_| rng.p()).collect())
        .collect()
}

/// Greville abscissae ξ_i = (u_{i−1} + u_i)/2 (ξ_0 = u_0, ξ_{m+1} = u_m).
fn greville(u: &[f64]) -> Vec<f64> {
    let k = quadratic_knots(u);
    (0..u.len() + 1)
        .map(|i| 0.5 * (k[i + 1] + k[i + 2]))
        .collect()
}

/// Tensor coefficients of a separable function a(u) + b(v) + c·uv (a_i, b_j random, c given).
fn separable_net(u: &[f64], v: &[f64], seed: u64) -> Vec<Vec<DVec3>> {
    let mut rng = Rng(seed);
    let a: Vec<DVec3> = (0..u.len() + 1).map(|_| rng.p()).collect();
    let b: Vec<DVec3> = (0..v.len() + 1).map(|_| rng.p()).collect();
    let c = rng.p();
    let (xi, eta) = (greville(u), greville(v));
    (0..u.len() + 1)
        .map(|i| {
            (0..v.len() + 1)
                .map(|j| a[i] + b[j] + c * (xi[i] * eta[j]))
                .collect()
        })
        .collect()
}

/// f(u, v) = (u² − uv + 0.3, 3v² + u, 1 + 2uv − v) and its tensor (blossom) coefficients.
fn p2(u: f64, v: f64) -> DVec3 {
    DVec3::new(u * u - u * v + 0.3, 3.0 * v * v + u, 1.0 + 2.0 * u * v - v)
}
fn p2_net(u: &[f64], v: &[f64]) -> Vec<Vec<DVec3>> {
    let (uk, vk) = (quadratic_knots(u), quadratic_knots(v));
    (0..u.len() + 1)
        .map(|i| {
            let (a, b) = (uk[i + 1], uk[i + 2]);
            (0..v.len() + 1)
                .map(|j| {
                    let (c, d) = (vk[j + 1], vk[j + 2]);
                    let (bu1, bu2, bv1, bv2) = (0.5 * (a + b), a * b, 0.5 * (c + d), c * d);
                    DVec3::new(
                        bu2 - bu1 * bv1 + 0.3,
                        3.0 * bv2 + bu1,
                        1.0 + 2.0 * bu1 * bv1 - bv1,
                    )
                })
                .collect()
        })
        .collect()
}

const PAPER: [f64; 4] = [0.0, 1.0 / 3.0, 2.0 / 3.0, 1.0];
const NONUNI_U: [f64; 5] = [0.0, 0.15, 0.5, 0.6, 1.0];
const NONUNI_V: [f64; 6] = [-1.0, -0.2, 0.1, 0.7, 1.5, 2.0];

fn grids() -> Vec<(Vec<f64>, Vec<f64>)> {
    vec![
        (PAPER.to_vec(), PAPER.to_vec()),
        (NONUNI_U.to_vec(), NONUNI_V.to_vec()),
        (vec![0.0, 1.0, 2.0, 3.0, 4.0, 5.0], vec![0.0, 1.0, 2.0, 3.0]),
        (
            vec![0.0, 0.01, 0.5, 0.51, 0.75, 1.0],
            vec![0.0, 0.3, 0.4, 1.0],
        ),
        (vec![0.0, 0.4, 1.0], vec![0.0, 0.5, 0.7, 1.0]),
    ]
}

fn scale(net: &Network) -> f64 {
    gordon::network_scale(net).max(1.0)
}

/// max over 100 points per curve of |F(u_r, v) − φ_r(v)| and |F(u, v_s) − ψ_s(u)|.
fn interpolation_error<S: Surface<DVec3>>(s: &S, net: &Network) -> f64 {
    let lines = NetworkLines::new(net).unwrap();
    let (u0, u1) = (net.u[0], net.u[net.m()]);
    let (v0, v1) = (net.v[0], net.v[net.n()]);
    let mut worst: f64 = 0.0;
    for k in 0..100 {
        let t = k as f64 / 99.0;
        let (u, v) = (u0 + t * (u1 - u0), v0 + t * (v1 - v0));
        lines.v_curves(v, false, &mut |r, p, _| {
            worst = worst.max((s.eval(net.u[r], v) - p).abs().max_element());
        });
        lines.u_curves(u, false, &mut |sj, p, _| {
            worst = worst.max((s.eval(u, net.v[sj]) - p).abs().max_element());
        });
    }
    worst
}

fn max_diff_fn<S: Surface<DVec3>>(s: &S, f: impl Fn(f64, f64) -> DVec3) -> f64 {
    let ((u0, u1), (v0, v1)) = s.domain();
    let mut worst: f64 = 0.0;
    for a in 0..57 {
        for b in 0..57 {
            let (u, v) = (
                u0 + (u1 - u0) * a as f64 / 56.0,
                v0 + (v1 - v0) * b as f64 / 56.0,
            );
            worst = worst.max((s.eval(u, v) - f(u, v)).abs().max_element());
        }
    }
    worst
}

// ---------------------------------------------------------------- G: item 18

#[test]
fn paper_knot_vectors() {
    let c = random_net(&PAPER, &PAPER, 1);
    let g = GordonSurface::new(&network_from_tensor(&PAPER, &PAPER, &c)).unwrap();
    let ubar = [0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0];
    let utilde = [0.0, 0.0, 0.0, 1.0 / 3.0, 0.5, 2.0 / 3.0, 1.0, 1.0, 1.0];
    for (a, b) in [
        (g.knots_u_bar(), &ubar[..]),
        (g.knots_v_bar(), &ubar[..]),
        (g.knots_u(), &utilde[..]),
        (g.knots_v(), &utilde[..]),
    ] {
        assert_eq!(a.len(), b.len());
        for (x, y) in a.iter().zip(b) {
            assert!((x - y).abs() <= 1e-15, "{a:?} vs {b:?}");
        }
    }
    assert_eq!(g.size(), (6, 6));
    assert_eq!(g.control_points().len(), 36);
}

#[test]
fn merged_knot_lengths_and_net_size() {
    for (u, v) in grids() {
        let (m, n) = (u.len() - 1, v.len() - 1);
        let net = network_from_tensor(&u, &v, &random_net(&u, &v, 7));
        let g = GordonSurface::new(&net).unwrap();
        assert_eq!(g.knots_u().len(), 2 * m + 3, "m = {m}");
        assert_eq!(g.knots_v().len(), 2 * n + 3, "n = {n}");
        assert_eq!(g.size(), (2 * m, 2 * n));
        // Ū interior knots are the means of consecutive interior parameters
        let ub = g.knots_u_bar();
        assert_eq!(ub.len(), m + 4);
        for j in 1..m - 1 {
            assert!((ub[j + 2] - 0.5 * (u[j] + u[j + 1])).abs() <= 1e-15);
        }
        // Ũ ⊇ U and Ũ ⊇ Ū
        for k in quadratic_knots(&u).iter().chain(ub) {
            assert!(g.knots_u().contains(k));
        }
    }
}

#[test]
fn refined_sum_equals_direct_boolean_sum() {
    for (k, (u, v)) in grids().into_iter().enumerate() {
        let net = network_from_tensor(&u, &v, &random_net(&u, &v, 11 + k as u64));
        let g = GordonSurface::new(&net).unwrap();
        let direct = |a: f64, b: f64| g.l1().eval(a, b) + g.l2().eval(a, b) - g.tg().eval(a, b);
        let d = max_diff_fn(&g, direct);
        assert!(d <= 1e-13 * scale(&net), "grid {k}: {d:e}");
    }
}

#[test]
fn components_interpolate_their_data() {
    let (u, v) = (NONUNI_U.to_vec(), NONUNI_V.to_vec());
    let net = network_from_tensor(&u, &v, &random_net(&u, &v, 5));
    let g = GordonSurface::new(&net).unwrap();
    let lines = NetworkLines::new(&net).unwrap();
    let tol = 1e-13 * scale(&net);
    for k in 0..20 {
        let t = k as f64 / 19.0;
        let vv = v[0] + t * (v[v.len() - 1] - v[0]);
        let uu = u[0] + t * (u[u.len() - 1] - u[0]);
        lines.v_curves(vv, false, &mut |r, p, _| {
            assert!((g.l1().eval(u[r], vv) - p).abs().max_element() <= tol)
        });
        lines.u_curves(uu, false, &mut |s, p, _| {
            assert!((g.l2().eval(uu, v[s]) - p).abs().max_element() <= tol)
        });
    }
    for r in 0..u.len() {
        for s in 0..v.len() {
            assert!(
                (g.tg().eval(u[r], v[s]) - lines.node(r, s))
                    .abs()
                    .max_element()
                    <= tol
            );
        }
    }
}

#[test]
fn g_interpolates_the_network() {
    for (k, (u, v)) in grids().into_iter().enumerate() {
        let net = network_from_tensor(&u, &v, &random_net(&u, &v, 100 + k as u64));
        let g = GordonSurface::new(&net).unwrap();
        let e = interpolation_error(&g, &net);
        assert!(e <= 1e-13 * scale(&net), "grid {k}: {e:e}");
    }
}

#[test]
fn g_reproduces_p2() {
    for (u, v) in grids() {
        let net = network_from_tensor(&u, &v, &p2_net(&u, &v));
        let g = GordonSurface::new(&net).unwrap();
        let d = max_diff_fn(&g, p2);
        assert!(d <= 1e-13 * scale(&net), "{d:e}");
    }
}

#[test]
fn g_equals_separable_closed_form_and_not_generic_tensor() {
    // item 19 before S exists: for f = a(u) + b(v) + c·uv, G = f (the tensor surface of the net); for a
    // generic network G differs clearly from the biquadratic tensor surface whose isocurves it interpolates
    for (k, (u, v)) in grids().into_iter().enumerate() {
        let c = separable_net(&u, &v, 40 + k as u64);
        let net = network_from_tensor(&u, &v, &c);
        let f = tensor(&u, &v, &c);
        let g = GordonSurface::new(&net).unwrap();
        let d = gordon::difference(&g, &f);
        assert!(d < 1e-13 * scale(&net), "separable grid {k}: {d:e}");
        // generic
        let c = random_net(&u, &v, 60 + k as u64);
        let net = network_from_tensor(&u, &v, &c);
        let g = GordonSurface::new(&net).unwrap();
        let d = gordon::difference(&g, &tensor(&u, &v, &c));
        assert!(d > 1e-3 * scale(&net), "generic grid {k}: {d:e}");
    }
}

#[test]
fn g_derivatives_match_finite_differences() {
    let (u, v) = (NONUNI_U.to_vec(), NONUNI_V.to_vec());
    let net = network_from_tensor(&u, &v, &random_net(&u, &v, 9));
    let g = GordonSurface::new(&net).unwrap();
    let h = 1e-6;
    for &(a, b) in &[(0.3, 0.2), (0.07, 1.7), (0.57, -0.5)] {
        let mut out = [DVec3::ZERO; 3];
        g.eval_derivs(a, b, true, &mut out);
        let du = (g.eval(a + h, b) - g.eval(a - h, b)) / (2.0 * h);
        let dv = (g.eval(a, b + h) - g.eval(a, b - h)) / (2.0 * h);
        assert!(
            (out[1] - du).length() < 1e-6 * (1.0 + du.length()),
            "{a} {b} {:?} {du:?}",
            out[1]
        );
        assert!((out[2] - dv).length() < 1e-6 * (1.0 + dv.length()));
    }
}

#[test]
fn g_bad_input() {
    // m = 1
    let (u, v) = (vec![0.0, 1.0], PAPER.to_vec());
    let net = network_from_tensor(&u, &v, &random_net(&u, &v, 3));
    let e = GordonSurface::new(&net).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::TooFew, "network.u"));
    let net = network_from_tensor(&v, &u, &random_net(&v, &u, 3));
    let e = GordonSurface::new(&net).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::TooFew, "network.v"));
    // incompatible: move one control point of φ_1
    let mut net = network_from_tensor(&PAPER, &PAPER, &random_net(&PAPER, &PAPER, 3));
    net.p[1][2].z += 0.25;
    let e = GordonSurface::new(&net).unwrap_err();
    assert_eq!(e.field(), "network");
    assert!(
        e.detail().contains("not compatible")
            && e.detail().contains("φᵣ(vₛ) ≠ ψₛ(uᵣ) at node (r = 1,"),
        "{e}"
    );
    // shapes and non-finite
    let mut net = network_from_tensor(&PAPER, &PAPER, &random_net(&PAPER, &PAPER, 3));
    net.q[2].pop();
    assert_eq!(
        GordonSurface::new(&net).unwrap_err().field(),
        "network.Q[2]"
    );
    let mut net = network_from_tensor(&PAPER, &PAPER, &random_net(&PAPER, &PAPER, 3));
    net.p[0][0].x = f64::NAN;
    assert_eq!(
        GordonSurface::new(&net).unwrap_err().kind(),
        ErrorKind::NotFinite
    );
    let mut net = network_from_tensor(&PAPER, &PAPER, &random_net(&PAPER, &PAPER, 3));
    net.u[2] = net.u[1];
    assert_eq!(
        GordonSurface::new(&net).unwrap_err().kind(),
        ErrorKind::NotIncreasing
    );
}

// ---------------------------------------------------------------- GB: item 20

#[test]
fn cardinal_cubics_are_cardinal_and_satisfy_end_conditions() {
    for nodes in [NONUNI_U.to_vec(), NONUNI_V.to_vec(), PAPER.to_vec()] {
        let m = nodes.len() - 1;
        for end in [CubicEnd::Natural, CubicEnd::NotAKnot] {
            let b = BlendFunctions::cardinal_cubic("uKnots", &nodes, end).unwrap();
            assert_eq!(b.len(), m + 1);
            for r in 0..=m {
                for (q, &t) in nodes.iter().enumerate() {
                    let want = if q == r { 1.0 } else { 0.0 };
                    assert!(
                        (b.eval(r, t)[0] - want).abs() <= 1e-15,
                        "{end:?} {nodes:?} L_{r}(u_{q}) = {:e}",
                        b.eval(r, t)[0] - want
                    );
                }
                let l = |t: f64| b.eval(r, t);
                let mag = (0..=40)
                    .map(|k| l(nodes[0] + (nodes[m] - nodes[0]) * k as f64 / 40.0)[2].abs())
                    .fold(1.0, f64::max);
                match end {
                    CubicEnd::Natural => {
                        assert!(l(nodes[0])[2].abs() <= 1e-12 * mag);
                        assert!(l(nodes[m])[2].abs() <= 1e-12 * mag);
                    }
                    CubicEnd::NotAKnot => {
                        // L″ is linear over [u_0, u_2] and over [u_{m−2}, u_m]
                        for (a, mid, c) in [(0, 1, 2), (m - 2, m - 1, m)] {
                            let (ua, um, uc) = (nodes[a], nodes[mid], nodes[c]);
                            let lerp = l(ua)[2] + (l(uc)[2] - l(ua)[2]) * (um - ua) / (uc - ua);
                            assert!((l(um)[2] - lerp).abs() <= 1e-11 * mag, "{end:?} r={r}");
                        }
                    }
                }
            }
            // partition of unity and linear precision
            for k in 0..=30 {
                let t = nodes[0] + (nodes[m] - nodes[0]) * k as f64 / 30.0;
                let s: f64 = (0..=m).map(|r| b.eval(r, t)[0]).sum();
                let x: f64 = (0..=m).map(|r| nodes[r] * b.eval(r, t)[0]).sum();
                assert!((s - 1.0).abs() < 1e-14 && (x - t).abs() < 1e-14);
            }
        }
    }
}

#[test]
fn not_a_knot_on_four_nodes_is_lagrange() {
    let nodes = [0.0, 0.2, 0.7, 1.3];
    let b = BlendFunctions::cardinal_cubic("uKnots", &nodes, CubicEnd::NotAKnot).unwrap();
    for r in 0..4 {
        for k in 0..=20 {
            let t = 1.3 * k as f64 / 20.0;
            let lag: f64 = (0..4)
                .filter(|&q| q != r)
                .map(|q| (t - nodes[q]) / (nodes[r] - nodes[q]))
                .product();
            assert!((b.eval(r, t)[0] - lag).abs() < 1e-14, "L_{r}({t})");
        }
    }
}

#[test]
fn natural_cardinal_matches_hand_computed_case() {
    // nodes 0, 1, 2: natural cubic cardinal L_1 = (3/2)u − (1/2)u³ on [0, 1] (symmetric)
    let b = BlendFunctions::cardinal_cubic("uKnots", &[0.0, 1.0, 2.0], CubicEnd::Natural).unwrap();
    for &t in &[0.0, 0.25, 0.5, 0.9, 1.0] {
        let want = 1.5 * t - 0.5 * t * t * t;
        assert!((b.eval(1, t)[0] - want).abs() < 1e-15);
        assert!((b.eval(1, 2.0 - t)[0] - want).abs() < 1e-15);
        assert!((b.eval(1, t)[1] - (1.5 - 1.5 * t * t)).abs() < 1e-14);
    }
}

fn gb_of(net: &Network, blend: Blend) -> SplineBlendedSurface<NetworkLines> {
    SplineBlendedSurface::new(NetworkLines::new(net).unwrap(), blend).unwrap()
}

#[test]
fn gb_interpolates_the_network() {
    for (k, (u, v)) in grids().into_iter().enumerate() {
        let net = network_from_tensor(&u, &v, &random_net(&u, &v, 200 + k as u64));
        for blend in [Blend::CubicNatural, Blend::CubicNotAKnot] {
            if (u.len() < 4 || v.len() < 4) && blend == Blend::CubicNotAKnot {
                continue;
            }
            let gb = gb_of(&net, blend.clone());
            let e = interpolation_error(&gb, &net);
            assert!(e <= 1e-13 * scale(&net), "grid {k} {blend:?}: {e:e}");
        }
    }
}

#[test]
fn gb_reproduces_p2_and_equals_g_on_separable_networks() {
    for (k, (u, v)) in grids().into_iter().enumerate() {
        let net = network_from_tensor(&u, &v, &p2_net(&u, &v));
        let gb = gb_of(&net, Blend::CubicNatural);
        let d = max_diff_fn(&gb, p2);
        assert!(d <= 1e-13 * scale(&net), "P2 grid {k}: {d:e}");
        let net = network_from_tensor(&u, &v, &separable_net(&u, &v, 300 + k as u64));
        let g = GordonSurface::new(&net).unwrap();
        let d = gordon::difference(&g, &gb_of(&net, Blend::CubicNatural));
        assert!(d <= 1e-13 * scale(&net), "separable grid {k}: {d:e}");
        // generic: GB ≠ G
        let net = network_from_tensor(&u, &v, &random_net(&u, &v, 400 + k as u64));
        let g = GordonSurface::new(&net).unwrap();
        let d = gordon::difference(&g, &gb_of(&net, Blend::CubicNatural));
        assert!(d > 1e-4 * scale(&net), "generic grid {k}: {d:e}");
    }
}

#[test]
fn gb_from_a_function_samples_only_lines_and_agrees_with_the_network_form() {
    let (u, v) = (NONUNI_U.to_vec(), NONUNI_V.to_vec());
    let c = random_net(&u, &v, 77);
    let net = network_from_tensor(&u, &v, &c);
    let f = tensor(&u, &v, &c);
    let off_line = std::cell::Cell::new(0usize);
    let func = |a: f64, b: f64| {
        let on = u.iter().any(|&x| (x - a).abs() < 1e-4) || v.iter().any(|&y| (y - b).abs() < 1e-4);
        if !on {
            off_line.set(off_line.get() + 1);
        }
        f.eval(a, b)
    };
    let gb_f = SplineBlendedSurface::new(
        FnLines::new(func, u.clone(), v.clone()),
        Blend::CubicNatural,
    )
    .unwrap();
    let gb_n = gb_of(&net, Blend::CubicNatural);
    let d = gordon::difference(&gb_f, &gb_n);
    assert!(d < 1e-13 * scale(&net), "{d:e}");
    // derivatives: exact (network) vs central differences along the lines (function)
    for &(a, b) in &[(0.3, 0.2), (0.07, 1.7), (0.95, -0.9)] {
        let (mut x, mut y) = ([DVec3::ZERO; 3], [DVec3::ZERO; 3]);
        gb_f.eval_derivs(a, b, true, &mut x);
        gb_n.eval_derivs(a, b, true, &mut y);
        assert!((x[0] - y[0]).length() < 1e-13);
        assert!(
            (x[1] - y[1]).length() < 1e-7 * (1.0 + y[1].length()),
            "{:?} {:?}",
            x[1],
            y[1]
        );
        assert!((x[2] - y[2]).length() < 1e-7 * (1.0 + y[2].length()));
        // and the exact ones against finite differences of GB itself
        let h = 1e-6;
        let du = (gb_n.eval(a + h, b) - gb_n.eval(a - h, b)) / (2.0 * h);
        assert!((y[1] - du).length() < 1e-6 * (1.0 + du.length()));
    }
    assert_eq!(off_line.get(), 0, "GB read the network off its lines");
}

#[test]
fn gb_bad_input() {
    let e = SplineBlendedSurface::new(
        FnLines::new(
            |_, _| DVec3::ONE,
            vec![0.0, 0.5, 1.0],
            vec![0.0, 0.5, 1.0, 2.0],
        ),
        Blend::CubicNotAKnot,
    )
    .unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::TooFew, "uKnots"));
    let e = SplineBlendedSurface::new(
        FnLines::new(
            |u, _| DVec3::new(1.0 / (u - 0.25), 0.0, 0.0),
            vec![0.0, 0.25, 1.0],
            vec![0.0, 1.0],
        ),
        Blend::CubicNatural,
    )
    .unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::NotFinite, "network"));
    // non-finite only off the nodes, on a line
    let e = SplineBlendedSurface::new(
        FnLines::new(
            |u, v| {
                if u > 0.2 && u < 0.8 && v == 0.0 {
                    DVec3::NAN
                } else {
                    DVec3::ONE
                }
            },
            vec![0.0, 1.0],
            vec![0.0, 1.0],
        ),
        Blend::CubicNatural,
    )
    .unwrap_err();
    assert_eq!(e.field(), "network");
    let e = SplineBlendedSurface::new(
        FnLines::new(|_, _| DVec3::ONE, vec![0.0, 0.0, 1.0], vec![0.0, 1.0]),
        Blend::CubicNatural,
    )
    .unwrap_err();
    assert_eq!(e.kind(), ErrorKind::NotIncreasing);
}

#[test]
fn grid_evaluation_equals_point_evaluation() {
    use splinelab::gordon::GridSurface;
    let (u, v) = (NONUNI_U.to_vec(), NONUNI_V.to_vec());
    let net = network_from_tensor(&u, &v, &random_net(&u, &v, 21));
    let g = GordonSurface::new(&net).unwrap();
    let gb = gb_of(&net, Blend::CubicNotAKnot);
    let us: Vec<f64> = (0..13).map(|k| k as f64 / 12.0).collect();
    let vs: Vec<f64> = (0..9).map(|k| -1.0 + 3.0 * k as f64 / 8.0).collect();
    let check = |s: &dyn GridSurface| {
        let grid = s.eval_grid(&us, &vs, true);
        assert_eq!(grid.points.len(), 3 * 13 * 9);
        let mut out = [DVec3::ZERO; 3];
        for (a, &uu) in us.iter().enumerate() {
            for (b, &vv) in vs.iter().enumerate() {
                s.eval_derivs(uu, vv, true, &mut out);
                let k = 3 * (a * vs.len() + b);
                for (buf, want) in [
                    (&grid.points, out[0]),
                    (&grid.du, out[1]),
                    (&grid.dv, out[2]),
                ] {
                    let got = DVec3::from_slice(&buf[k..]);
                    assert!((got - want).length() <= 1e-13 * (1.0 + want.length()));
                }
            }
        }
    };
    check(&g);
    check(&gb);
}

// ---------------------------------------------------------------- S vs G (item 19), with the criss-cross S

#[test]
fn s_equals_g_and_gb_exactly_on_separable_networks() {
    use splinelab::criss_cross::CrissCrossSurface;
    use splinelab::network::examples;
    use splinelab::thin_plate::ThinPlateSurface;
    let mut nets = vec![examples::separable()];
    for (k, (u, v)) in grids().into_iter().enumerate() {
        nets.push(network_from_tensor(
            &u,
            &v,
            &separable_net(&u, &v, 500 + k as u64),
        ));
    }
    for (k, net) in nets.iter().enumerate() {
        let tol = 1e-13 * scale(net);
        let s = CrissCrossSurface::new(net).unwrap();
        let t = ThinPlateSurface::new(net).unwrap();
        let g = GordonSurface::new(net).unwrap();
        let gb = gb_of(net, Blend::CubicNatural);
        let (sg, st, tg) = (
            gordon::difference(&s, &g),
            gordon::difference(&s, &t),
            gordon::difference(&t, &g),
        );
        assert!(sg < tol, "net {k}: ‖S−G‖ = {sg:e}");
        assert!(gordon::difference(&s, &gb) < tol, "net {k}: ‖S−GB‖");
        assert!(
            (st - tg).abs() <= 1e-13,
            "net {k}: ‖S−T‖ = {st:e}, ‖T−G‖ = {tg:e}"
        );
    }
    // the separable example has a non-trivial T (T does not reproduce the class)
    let net = examples::separable();
    let t = ThinPlateSurface::new(&net).unwrap();
    assert!(gordon::difference(&GordonSurface::new(&net).unwrap(), &t) > 1e-5);
}

#[test]
fn s_differs_clearly_from_g_on_generic_networks() {
    use splinelab::criss_cross::CrissCrossSurface;
    use splinelab::network::examples;
    for name in [
        "uniform-random",
        "three-sided",
        "strongly-nonuniform",
        "free-data",
    ] {
        let net = examples::by_name(name).unwrap();
        let s = CrissCrossSurface::new(&net).unwrap();
        let g = GordonSurface::new(&net).unwrap();
        let d = gordon::difference(&s, &g);
        assert!(d > 1e-3 * scale(&net), "{name}: ‖S−G‖ = {d:e}");
        // both interpolate the same network
        assert!(interpolation_error(&g, &net) <= 1e-13 * scale(&net));
    }
}

// ---------------------------------------------------------------- the B2 blend (Kuklišová)

#[test]
fn b2_blend_functions_are_the_b2_curves_of_unit_data() {
    use splinelab::b2spline::{B2Curve, B2Options, KnotChoice};
    use splinelab::gordon::blended::blend_functions;
    use splinelab::sample::Curve;
    let knots = vec![-0.4, 0.0, 0.3, 0.5, 1.1, 1.4, 2.0];
    for (a, p, c2) in [
        (0.0, 1.0 / 6.0, 1.0),
        (0.1, 0.1, 2.0),
        (1.0 / 6.0, 0.2, 1.0),
    ] {
        let blend = Blend::B2 {
            a,
            tension_u: Tension::Scalar(p),
            tension_v: Tension::Scalar(0.0),
            c2,
        };
        let b = blend_functions("uKnots", &knots, &blend, false).unwrap();
        assert_eq!(b.len(), knots.len());
        let opts = B2Options {
            a,
            tension: Tension::Scalar(p),
            knots: KnotChoice::Explicit(knots.clone()),
            c2,
            ..B2Options::default()
        };
        for j in 0..knots.len() {
            let data: Vec<f64> = (0..knots.len())
                .map(|k| if k == j { 1.0 } else { 0.0 })
                .collect();
            let curve = B2Curve::new(&data, &opts).unwrap();
            assert_eq!(curve.domain(), b.domain());
            for k in 0..=20 {
                let t = 0.0 + 1.4 * k as f64 / 20.0;
                assert!(
                    (curve.eval(t) - b.eval(j, t)[0]).abs() < 1e-14,
                    "a={a} L_{j}({t})"
                );
            }
        }
        // a = 0: cardinal at the data knots u_1..u_n (nodes[2..=len−3]; u_{−1}, u_0, u_{n+1}, u_{n+2} are
        // auxiliary)
        if a == 0.0 {
            for j in 0..knots.len() {
                for q in 2..=knots.len() - 3 {
                    let want = if q == j { 1.0 } else { 0.0 };
                    assert!((b.eval(j, knots[q])[0] - want).abs() < 1e-14);
                }
            }
        }
    }
}

#[test]
fn b2_blended_surface_interpolates_the_inner_lines() {
    let f = |u: f64, v: f64| DVec3::new(u, v, (2.0 * u).sin() * (1.0 + v * v) + u * v);
    // u_{−1}, u_0 and u_{m+1}, u_{m+2} are auxiliary lines; the domain is [u_1, u_m] × [v_1, v_n]
    let u = vec![-0.3, -0.1, 0.0, 0.25, 0.6, 1.0, 1.2, 1.3];
    let v = vec![-0.2, -0.1, 0.0, 0.4, 0.5, 0.9, 1.0, 1.1, 1.3];
    let blend = Blend::B2 {
        a: 0.0,
        tension_u: Tension::Scalar(1.0 / 6.0),
        tension_v: Tension::Scalar(0.1),
        c2: 1.0,
    };
    let gb = SplineBlendedSurface::new(FnLines::new(f, u.clone(), v.clone()), blend).unwrap();
    assert_eq!(gb.domain(), ((0.0, 1.0), (0.0, 1.0)));
    for k in 0..=50 {
        let t = k as f64 / 50.0;
        for &ur in &u[2..u.len() - 2] {
            assert!(
                (gb.eval(ur, t) - f(ur, t)).abs().max_element() < 1e-13,
                "u = {ur}"
            );
        }
        for &vs in &v[2..v.len() - 2] {
            assert!(
                (gb.eval(t, vs) - f(t, vs)).abs().max_element() < 1e-13,
                "v = {vs}"
            );
        }
    }
    // with a > 0 it no longer interpolates
    let blend = Blend::B2 {
        a: 1.0 / 6.0,
        tension_u: Tension::Scalar(1.0 / 6.0),
        tension_v: Tension::Scalar(1.0 / 6.0),
        c2: 1.0,
    };
    let gb =
        SplineBlendedSurface::new(FnLines::new(f, u.clone(), v.clone()), blend.clone()).unwrap();
    assert!((gb.eval(0.25, 0.5) - f(0.25, 0.5)).length() > 1e-4);
    // too few lines, bad knots
    let e = SplineBlendedSurface::new(
        FnLines::new(f, vec![0.0, 0.5, 1.0, 2.0, 3.0], v.clone()),
        blend.clone(),
    )
    .unwrap_err();
    assert_eq!(e.field(), "uKnots");
    let e = SplineBlendedSurface::new(
        FnLines::new(f, u.clone(), vec![0.0, 0.5, 0.4, 1.0, 2.0, 3.0]),
        blend,
    )
    .unwrap_err();
    assert!(e.field().starts_with("vKnots"), "{e}");
}

#[test]
fn b2_blend_with_per_line_tensions() {
    use splinelab::b2spline::{B2Curve, B2Options, KnotChoice};
    use splinelab::gordon::blended::blend_functions;
    use splinelab::sample::Curve;
    let knots = vec![-1.0, 0.0, 0.5, 1.5, 2.0, 3.0, 3.5];
    let ps = vec![0.1, 0.2, 1.0 / 6.0, 0.05]; // p_0..p_n, n = 3
    let blend = Blend::B2 {
        a: 0.05,
        tension_u: Tension::PerVertex(ps.clone()),
        tension_v: Tension::Scalar(0.0),
        c2: 1.0,
    };
    let b = blend_functions("uKnots", &knots, &blend, false).unwrap();
    let opts = B2Options {
        a: 0.05,
        tension: Tension::PerVertex(ps),
        knots: KnotChoice::Explicit(knots.clone()),
        ..B2Options::default()
    };
    for j in 0..knots.len() {
        let data: Vec<f64> = (0..knots.len())
            .map(|k| f64::from(u8::from(k == j)))
            .collect();
        let c = B2Curve::new(&data, &opts).unwrap();
        for k in 0..=10 {
            let t = 0.5 + 1.5 * k as f64 / 10.0;
            assert!((c.eval(t) - b.eval(j, t)[0]).abs() < 1e-14);
        }
    }
    let blend = Blend::B2 {
        a: 0.0,
        tension_u: Tension::Scalar(0.1),
        tension_v: Tension::PerVertex(vec![0.1, 0.2]),
        c2: 1.0,
    };
    let e = blend_functions("vKnots", &knots, &blend, true).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::SizeMismatch, "tensionV"));
}

#[test]
fn refined_net_matches_an_independent_refinement() {
    // C̃ via the kernel's Boehm insertion (BSplineSurface::refine), independent of the one-pass insertion
    for (k, (u, v)) in grids().into_iter().enumerate() {
        let net = network_from_tensor(&u, &v, &random_net(&u, &v, 700 + k as u64));
        let g = GordonSurface::new(&net).unwrap();
        let (ut, vt) = (g.knots_u().to_vec(), g.knots_v().to_vec());
        let refine = |s: &BSplineSurface<DVec3>| {
            s.refine(
                &splinelab::knots::missing_knots(s.knots_u(), &ut),
                &splinelab::knots::missing_knots(s.knots_v(), &vt),
            )
            .unwrap()
        };
        let (a, b, c) = (refine(g.l1()), refine(g.l2()), refine(g.tg()));
        assert_eq!(a.knots_u(), &ut[..]);
        assert_eq!(c.knots_v(), &vt[..]);
        let cmax = g
            .control_points()
            .iter()
            .map(|p| p.abs().max_element())
            .fold(1.0, f64::max);
        for (i, p) in g.control_points().iter().enumerate() {
            let q = a.points()[i] + b.points()[i] - c.points()[i];
            assert!(
                (*p - q).abs().max_element() <= 1e-12 * cmax,
                "grid {k}, C̃[{i}]"
            );
        }
    }
}

/// Natural cubic spline through (x_i, y_i) by the classical second-derivative (moment) tridiagonal system.
fn natural_spline(x: &[f64], y: &[f64], t: f64) -> f64 {
    let n = x.len() - 1;
    let h: Vec<f64> = (0..n).map(|i| x[i + 1] - x[i]).collect();
    // M_0 = M_n = 0; for i = 1..n−1: h_{i−1}M_{i−1} + 2(h_{i−1}+h_i)M_i + h_iM_{i+1} = 6(Δ_i − Δ_{i−1})
    let mut a = vec![0.0; n + 1];
    let mut b = vec![1.0; n + 1];
    let mut c = vec![0.0; n + 1];
    let mut d = vec![0.0; n + 1];
    for i in 1..n {
        a[i] = h[i - 1];
        b[i] = 2.0 * (h[i - 1] + h[i]);
        c[i] = h[i];
        d[i] = 6.0 * ((y[i + 1] - y[i]) / h[i] - (y[i] - y[i - 1]) / h[i - 1]);
    }
    for i in 1..=n {
        let w = a[i] / b[i - 1];
        b[i] -= w * c[i - 1];
        d[i] -= w * d[i - 1];
    }
    let mut mm = vec![0.0; n + 1];
    mm[n] = d[n] / b[n];
    for i in (0..n).rev() {
        mm[i] = (d[i] - c[i] * mm[i + 1]) / b[i];
    }
    let i = (0..n).rfind(|&i| x[i] <= t).unwrap_or(0);
    let (s, e) = (t - x[i], x[i + 1] - t);
    mm[i] * e.powi(3) / (6.0 * h[i])
        + mm[i + 1] * s.powi(3) / (6.0 * h[i])
        + (y[i] / h[i] - mm[i] * h[i] / 6.0) * e
        + (y[i + 1] / h[i] - mm[i + 1] * h[i] / 6.0) * s
}

#[test]
fn natural_cardinals_match_the_moment_method() {
    let nodes = NONUNI_V.to_vec();
    let b = BlendFunctions::cardinal_cubic("vKnots", &nodes, CubicEnd::Natural).unwrap();
    for r in 0..nodes.len() {
        let y: Vec<f64> = (0..nodes.len())
            .map(|q| f64::from(u8::from(q == r)))
            .collect();
        for k in 0..=60 {
            let t = -1.0 + 3.0 * k as f64 / 60.0;
            let want = natural_spline(&nodes, &y, t);
            assert!(
                (b.eval(r, t)[0] - want).abs() < 1e-13,
                "L_{r}({t}): {} vs {want}",
                b.eval(r, t)[0]
            );
        }
    }
}

#[test]
fn surface_family_builds_only_what_is_asked_for() {
    use splinelab::gordon::SurfaceFamily;
    let (u, v) = (NONUNI_U.to_vec(), NONUNI_V.to_vec());
    let net = network_from_tensor(&u, &v, &random_net(&u, &v, 8));
    let all = SurfaceFamily::new(&net, Blend::CubicNatural, 1e-9).unwrap();
    // G alone: S, T, GB are not built, so no norms and no network curves
    let g = SurfaceFamily::with_only(&net, Blend::CubicNatural, 1e-9, &["G"]).unwrap();
    assert!(g.get("G").is_some() && g.get("Tg").is_some());
    assert!(g.get("S").is_none() && g.get("T").is_none() && g.get("GB").is_none());
    assert!(g.norms(9).is_empty());
    assert!(g.network_curves(5).is_none());
    // S and G: the one norm between them, equal to that of the full family; the surfaces are the same
    let sg = SurfaceFamily::with_only(&net, Blend::CubicNatural, 1e-9, &["S", "X"]).unwrap();
    assert_eq!(sg.norms(9), vec![("SG", all.norms(9)[0].1)]);
    let us = [0.0, 0.3, 1.0];
    let (a, b) = (sg.get("S").unwrap(), all.get("S").unwrap());
    assert_eq!(
        a.eval_grid(&us, &us, true).points,
        b.eval_grid(&us, &us, true).points
    );
}

#[test]
fn surface_family_names_norms_pairs_and_network_curves() {
    use splinelab::gordon::{distance_map, SurfaceFamily, FAMILY_PAIRS};
    let (u, v) = (NONUNI_U.to_vec(), NONUNI_V.to_vec());
    // separable data: G = S (surfaces.md §1.3), so ‖S − G‖∞ vanishes; every pair of the paper is reported
    let net = network_from_tensor(&u, &v, &separable_net(&u, &v, 7));
    let fam = SurfaceFamily::new(&net, Blend::CubicNatural, 1e-9).unwrap();
    let norms = fam.norms(21);
    let keys: Vec<&str> = norms.iter().map(|(k, _)| *k).collect();
    assert_eq!(keys, FAMILY_PAIRS.map(|(k, _, _)| k).to_vec());
    let sg = norms.iter().find(|(k, _)| *k == "SG").unwrap().1;
    assert!(sg < 1e-12 * scale(&net), "SG = {sg:e}");
    // generic data: S and G differ
    let generic = network_from_tensor(&u, &v, &random_net(&u, &v, 8));
    let fam2 = SurfaceFamily::new(&generic, Blend::CubicNatural, 1e-9).unwrap();
    let sg2 = fam2.norms(21)[0].1;
    assert!(sg2 > 1e-4 * scale(&generic), "generic SG = {sg2:e}");
    // names and pairs
    assert_eq!(fam.pair("GGB"), Some(("G", "GB")));
    assert_eq!(fam.pair("SG"), Some(("S", "G")));
    assert_eq!(fam.pair("GG"), None);
    assert!(fam.get("Tg").is_some() && fam.get("X").is_none());
    // the sampled network curves lie on G (which interpolates them)
    let k = 9;
    let (phi, psi) = fam.network_curves(k).unwrap();
    assert_eq!((phi.len(), psi.len()), (u.len(), v.len()));
    let ((u0, u1), (v0, v1)) = fam.domain();
    let g = fam.gordon();
    for (r, c) in phi.iter().enumerate() {
        assert_eq!(c.len(), 3 * k);
        for (i, t) in splinelab::sample::uniform_params(v0, v1, k)
            .into_iter()
            .enumerate()
        {
            let p = g.eval(u[r], t);
            let d = (p - DVec3::new(c[3 * i], c[3 * i + 1], c[3 * i + 2]))
                .abs()
                .max_element();
            assert!(d < 1e-12 * scale(&net), "phi[{r}] at {t}: {d:e}");
        }
    }
    for (s, c) in psi.iter().enumerate() {
        for (i, t) in splinelab::sample::uniform_params(u0, u1, k)
            .into_iter()
            .enumerate()
        {
            let p = g.eval(t, v[s]);
            let d = (p - DVec3::new(c[3 * i], c[3 * i + 1], c[3 * i + 2]))
                .abs()
                .max_element();
            assert!(d < 1e-12 * scale(&net), "psi[{s}] at {t}: {d:e}");
        }
    }
    // the distance map is the per-vertex max-coordinate distance
    let d = distance_map(
        &[0.0, 0.0, 0.0, 1.0, 2.0, 3.0],
        &[0.5, -1.0, 2.25, 1.0, 2.0, 3.0],
    );
    assert_eq!(d, vec![2.25, 0.0]);
}

#[test]
fn surface_family_refuses_work_beyond_its_limits() {
    use splinelab::gordon::{
        check_norm_samples, SurfaceFamily, FAMILY_MAX_LINES, FAMILY_MAX_NORM_SAMPLES,
    };
    use splinelab::ErrorKind;
    let lines = |k: usize| (0..k).map(|i| i as f64).collect::<Vec<f64>>();
    // at the limit the family builds; one breakpoint more (in either direction) is refused, naming it
    let (u, v) = (lines(FAMILY_MAX_LINES), lines(3));
    let net = network_from_tensor(&u, &v, &random_net(&u, &v, 3));
    assert!(SurfaceFamily::new(&net, Blend::CubicNatural, 1e-9).is_ok());
    for (u, v, field) in [
        (lines(FAMILY_MAX_LINES + 1), lines(3), "network.u"),
        (lines(3), lines(FAMILY_MAX_LINES + 1), "network.v"),
    ] {
        let net = network_from_tensor(&u, &v, &random_net(&u, &v, 3));
        let e = SurfaceFamily::with_only(&net, Blend::CubicNatural, 1e-9, &["G"])
            .err()
            .expect("over the limit");
        assert_eq!((e.field(), e.kind()), (field, ErrorKind::TooMany));
        let c = e.counts().unwrap();
        assert_eq!(
            (c.expected, c.got),
            (FAMILY_MAX_LINES, FAMILY_MAX_LINES + 1)
        );
    }
    // the norms' grid side: 2 ..= FAMILY_MAX_NORM_SAMPLES
    assert!(check_norm_samples("samples", FAMILY_MAX_NORM_SAMPLES).is_ok());
    let e = check_norm_samples("samples", FAMILY_MAX_NORM_SAMPLES + 1).unwrap_err();
    assert_eq!((e.field(), e.kind()), ("samples", ErrorKind::TooMany));
    assert_eq!(
        check_norm_samples("samples", 1).unwrap_err().kind(),
        ErrorKind::TooFew
    );
}

// ---------------------------------------------------------------- render_family (what networkSurfaces draws)

fn request(names: &[&str], nu: usize, nv: usize) -> splinelab::gordon::FamilyRequest {
    splinelab::gordon::FamilyRequest {
        surfaces: names.iter().map(|s| s.to_string()).collect(),
        samples_u: nu,
        samples_v: nv,
        norm_samples: 0,
        color_by: None,
        curve_samples: 0,
    }
}

#[test]
fn render_family_samples_the_asked_surfaces_on_one_grid() {
    use splinelab::gordon::render_family;
    // p2 lies in the class {a(u) + b(v) + c·uv} that G and S reproduce (surfaces.md §1.3): every sampled point of
    // both is p2 at its grid node, the u-major grid of the domain [0, 1] × [−1, 2]
    let (u, v) = (NONUNI_U.to_vec(), NONUNI_V.to_vec());
    let net = network_from_tensor(&u, &v, &p2_net(&u, &v));
    let (nu, nv) = (7, 5);
    let r = render_family(
        &net,
        Blend::CubicNatural,
        1e-9,
        &request(&["G", "S"], nu, nv),
    )
    .unwrap();
    let names: Vec<&str> = r.surfaces.iter().map(|s| s.name.as_str()).collect();
    assert_eq!(names, ["G", "S"], "in the order asked");
    for s in &r.surfaces {
        assert_eq!(s.points.len(), 3 * nu * nv, "{}", s.name);
        for i in 0..nu {
            for j in 0..nv {
                let (a, b) = (
                    i as f64 / (nu - 1) as f64,
                    -1.0 + 3.0 * j as f64 / (nv - 1) as f64,
                );
                let k = 3 * (i * nv + j);
                let d = (DVec3::from_slice(&s.points[k..k + 3]) - p2(a, b))
                    .abs()
                    .max_element();
                assert!(d < 1e-12 * scale(&net), "{} at ({a}, {b}): {d:e}", s.name);
            }
        }
        assert_eq!(
            s.mesh.positions.len(),
            3 * nu * nv,
            "{}: one mesh vertex per sample",
            s.name
        );
    }
    // nothing else was asked for: no norms, colours or curves; only G and S were built
    assert!(r.norms.is_none() && r.colors.is_none() && r.curves.is_none());
    assert!(r.family.get("T").is_none() && r.family.get("GB").is_none());
}

#[test]
fn render_family_adds_norms_colours_and_curves_when_asked() {
    use splinelab::gordon::render_family;
    let (u, v) = (NONUNI_U.to_vec(), NONUNI_V.to_vec());
    let net = network_from_tensor(&u, &v, &random_net(&u, &v, 8));
    let (nu, nv) = (9, 6);
    let mut req = request(&["G"], nu, nv);
    req.norm_samples = 21;
    req.color_by = Some("SG".into());
    req.curve_samples = 5;
    let r = render_family(&net, Blend::CubicNatural, 1e-9, &req).unwrap();
    // the norms of the full family (all four surfaces built for them)
    let all = splinelab::gordon::SurfaceFamily::new(&net, Blend::CubicNatural, 1e-9).unwrap();
    assert_eq!(r.norms.as_deref(), Some(all.norms(21).as_slice()));
    // the colours: per vertex, the largest coordinate difference of S and G at that grid node
    let colors = r.colors.unwrap();
    assert_eq!(colors.len(), nu * nv);
    let g = &r.surfaces[0].points;
    let s = all.get("S").unwrap();
    let mut largest = 0.0f32;
    for i in 0..nu {
        for j in 0..nv {
            let (a, b) = (
                i as f64 / (nu - 1) as f64,
                -1.0 + 3.0 * j as f64 / (nv - 1) as f64,
            );
            let k = i * nv + j;
            let want = (s.eval(a, b) - DVec3::from_slice(&g[3 * k..3 * k + 3]))
                .abs()
                .max_element();
            assert!(
                (colors[k] as f64 - want).abs() <= 1e-6 * want.max(1.0),
                "({i}, {j}): {} vs {want}",
                colors[k]
            );
            largest = largest.max(colors[k]);
        }
    }
    assert!(
        largest as f64 > 1e-4 * scale(&net),
        "generic data: S and G differ ({largest:e})"
    );
    // the network curves: one per breakpoint, 5 points each
    let (phi, psi) = r.curves.unwrap();
    assert_eq!((phi.len(), psi.len()), (u.len(), v.len()));
    assert!(phi.iter().chain(&psi).all(|c| c.len() == 15));
}

#[test]
fn render_family_names_the_field_of_a_bad_request() {
    use splinelab::gordon::{render_family, FAMILY_MAX_GRID_POINTS};
    let (u, v) = (PAPER.to_vec(), PAPER.to_vec());
    let net = network_from_tensor(&u, &v, &random_net(&u, &v, 3));
    let err = |req| {
        render_family(&net, Blend::CubicNatural, 1e-9, &req)
            .err()
            .unwrap()
    };
    let e = err(request(&["G", "X"], 4, 4));
    assert_eq!((e.field(), e.kind()), ("surfaces[1]", ErrorKind::Invalid));
    let e = err(request(&["G"; 9], 4, 4));
    assert_eq!((e.field(), e.kind()), ("surfaces", ErrorKind::TooMany));
    let e = err(request(&["S", "T", "G", "GB"], 250, 250));
    assert_eq!((e.field(), e.kind()), ("samplesU", ErrorKind::TooMany));
    let c = e.counts().unwrap();
    assert_eq!((c.expected, c.got), (FAMILY_MAX_GRID_POINTS, 250 * 250 * 4));
    let mut bad_pair = request(&["G"], 4, 4);
    bad_pair.color_by = Some("GG".into());
    let e = err(bad_pair);
    assert_eq!((e.field(), e.kind()), ("colorBy", ErrorKind::Invalid));
}
