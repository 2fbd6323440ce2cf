//! The kernel's fast paths agree with the generic evaluation of every construction to 1e-12.
//!
//! Curves: `eval_curve_into` (per-span sampler when `Curve::piecewise` is `Some`) and `eval_curve_uniform`
//! against `eval_curve_generic_into` (span search + basis per point), values and two derivatives, at
//! parameters inside the domain, exactly at breaks, at the ends, outside it (extrapolation), in random
//! order. Surfaces: `Surface::sample_grid_into` against `grid_generic_into`, values and both partials.
//! Tolerance: 1e-12 × (1 + the largest coordinate of that output).

use glam::{DVec2, DVec3};
use splinelab::b2spline::{B2Curve, B2Options, B2Surface, B2SurfaceOptions};
use splinelab::bezier::{AlphaTable, BezierSpline, Remodelling};
use splinelab::bspline::{BSplineCurve, BSplineSurface};
use splinelab::knot_paths::{KnotModifiedCurve, KnotModifiedSurface};
use splinelab::point::Point;
use splinelab::quasi_cubic::QuasiCubicCurve;
use splinelab::sample::{
    eval_curve_generic_into, eval_curve_into, eval_curve_uniform, eval_surface_grid,
    grid_generic_into, uniform_params,
};
use splinelab::{Curve, Surface};

const TOL: f64 = 1e-12;

/// A small deterministic generator (no dependency).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
}

fn scale(xs: &[f64]) -> f64 {
    1.0 + xs.iter().fold(0.0_f64, |m, x| m.max(x.abs()))
}

fn assert_close(what: &str, fast: &[f64], slow: &[f64]) {
    assert_eq!(fast.len(), slow.len(), "{what}: lengths");
    let s = scale(slow);
    let (worst, at) = fast
        .iter()
        .zip(slow)
        .map(|(a, b)| (a - b).abs())
        .enumerate()
        .fold((0.0_f64, 0), |m, (i, d)| if d > m.0 { (d, i) } else { m });
    assert!(
        worst <= TOL * s,
        "{what}: fast path differs from the generic evaluation by {worst:e} (scale {s:e}) at entry {at}: {} vs {}", fast[at], slow[at]
    );
}

/// Parameters for a curve on `breaks`: uniform, every break, the ends, outside, random order.
fn curve_params(domain: (f64, f64), breaks: &[f64]) -> Vec<f64> {
    let (a, b) = domain;
    let mut t = uniform_params(a, b, 997);
    t.extend_from_slice(breaks);
    t.extend([a, b, a - 0.01 * (b - a), b + 0.01 * (b - a)]);
    let mut r = Lcg(7);
    for _ in 0..500 {
        t.push(a + (b - a) * r.next());
    }
    t
}

/// The fast sampler (which must exist) against the generic path, orders 0, 1, 2, and the uniform
/// sampler against generic uniform samples.
fn check_curve<P: Point, C: Curve<P>>(name: &str, c: &C) {
    check_curve_against(name, c, c)
}

/// [`check_curve`] with the generic evaluation of `reference` (the same curve) as the reference.
fn check_curve_against<P: Point, C: Curve<P>, R: Curve<P>>(name: &str, c: &C, reference: &R) {
    let pp = c
        .piecewise()
        .unwrap_or_else(|| panic!("{name}: no fast path"));
    check_curve_at(name, c, reference, pp.breaks());
}

/// The batch samplers of `c` (`Curve::sample_into`, `Curve::sample_uniform_into`) against the generic
/// evaluation of `reference`, with `breaks` among the parameters.
fn check_curve_at<P: Point, C: Curve<P>, R: Curve<P>>(
    name: &str,
    c: &C,
    reference: &R,
    breaks: &[f64],
) {
    let params = curve_params(c.domain(), breaks);
    let n = params.len() * P::DIM;
    for order in 0..=2 {
        let (mut f0, mut f1, mut f2) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        let (mut g0, mut g1, mut g2) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
        eval_curve_into(c, &params, order, &mut f0, &mut f1, &mut f2);
        eval_curve_generic_into(reference, &params, order, &mut g0, &mut g1, &mut g2);
        assert_close(&format!("{name} points (order {order})"), &f0, &g0);
        if order >= 1 {
            assert_close(&format!("{name} d1"), &f1, &g1);
        }
        if order >= 2 {
            assert_close(&format!("{name} d2"), &f2, &g2);
        }
    }
    for count in [1usize, 2, 3, 17, 1000, 20_001] {
        let fast = eval_curve_uniform(c, count);
        let (a, b) = c.domain();
        let u = uniform_params(a, b, count);
        let mut slow = vec![0.0; count * P::DIM];
        eval_curve_generic_into(reference, &u, 0, &mut slow, &mut [], &mut []);
        assert_close(&format!("{name} uniform {count}"), &fast, &slow);
    }
}

fn check_surface<P: Point, S: Surface<P>>(name: &str, s: &S) {
    let ((u0, u1), (v0, v1)) = s.domain();
    let mut us = uniform_params(u0, u1, 41);
    us.push(u0 - 0.05 * (u1 - u0));
    us.push(u1 + 0.05 * (u1 - u0));
    let mut vs = uniform_params(v0, v1, 37);
    let mut r = Lcg(11);
    for _ in 0..10 {
        vs.push(v0 + (v1 - v0) * r.next());
    }
    vs.push(v1 + 0.05 * (v1 - v0));
    for derivs in [false, true] {
        let (p, du, dv) = eval_surface_grid(s, &us, &vs, derivs);
        let n = us.len() * vs.len() * P::DIM;
        let (mut gp, mut gu, mut gv) = (
            vec![0.0; n],
            vec![0.0; if derivs { n } else { 0 }],
            vec![0.0; if derivs { n } else { 0 }],
        );
        grid_generic_into(s, &us, &vs, derivs, &mut gp, &mut gu, &mut gv);
        assert_close(&format!("{name} grid points"), &p, &gp);
        assert_close(&format!("{name} grid du"), &du, &gu);
        assert_close(&format!("{name} grid dv"), &dv, &gv);
    }
}

fn spiral2(n: usize) -> Vec<DVec2> {
    (0..n)
        .map(|i| {
            let t = i as f64 * 0.4;
            DVec2::new(t.cos() * (1.0 + t), t.sin() * (1.0 + t) + 100.0)
        })
        .collect()
}

fn spiral3(n: usize) -> Vec<DVec3> {
    (0..n)
        .map(|i| {
            let t = i as f64 * 0.3;
            DVec3::new(t.cos(), t.sin(), 0.2 * t * t)
        })
        .collect()
}

#[test]
fn bspline_curves_every_degree_with_multiple_knots() {
    for degree in 1..=6 {
        let pts = spiral2(12);
        let c = BSplineCurve::clamped_uniform(degree, pts.clone()).unwrap();
        check_curve(&format!("bspline degree {degree}"), &c);
        // non-uniform interior knots with a double knot (and unclamped ends)
        let n = pts.len();
        let mut knots: Vec<f64> = (0..n + degree + 1).map(|i| (i as f64).powf(1.3)).collect();
        knots[degree + 2] = knots[degree + 1];
        let c = BSplineCurve::new(degree, knots, pts).unwrap();
        check_curve(&format!("bspline degree {degree}, double knot"), &c);
    }
    let c3 = BSplineCurve::clamped_uniform(3, spiral3(9)).unwrap();
    check_curve("bspline 3D", &c3);
    let scalar = BSplineCurve::clamped_uniform(4, vec![1.0, -2.0, 3.0, 0.5, 7.0, 1.0]).unwrap();
    check_curve("bspline scalar", &scalar);
}

#[test]
fn b2_curves() {
    let w = spiral2(14);
    check_curve(
        "b2 a = 0",
        &B2Curve::new(&w, &B2Options::default()).unwrap(),
    );
    let opts = B2Options {
        a: 0.1,
        ..B2Options::default()
    };
    check_curve("b2 a = 0.1", &B2Curve::new(&w, &opts).unwrap());
    check_curve(
        "b2 3D",
        &B2Curve::new(&spiral3(10), &B2Options::default()).unwrap(),
    );
}

#[test]
fn knot_modified_curves_between_neighbours() {
    let pts = spiral2(9);
    let knots: Vec<f64> = vec![0., 0., 0., 0., 1., 2., 3., 4., 5., 6., 6., 6., 6.];
    for up in [1.2, 1.9, 2.5, 2.99] {
        let c = KnotModifiedCurve::new(4, knots.clone(), pts.clone(), Some(5), up).unwrap();
        check_curve(&format!("knot-modified up = {up}"), &c);
    }
    // a moved knot 0.001 from its neighbour: the family's own (jet) evaluation loses digits in d2 there
    // (1.2e-11 from Cox–de Boor on the modified knots); the fast path agrees with Cox–de Boor to 1e-12
    let c = KnotModifiedCurve::new(4, knots.clone(), pts.clone(), Some(5), 2.999).unwrap();
    check_curve_against("knot-modified up = 2.999", &c, &c.bspline().unwrap());
    // outside the neighbours there is no B-spline: the generic path is used
    let c = KnotModifiedCurve::new(4, knots.clone(), pts.clone(), Some(5), 7.5).unwrap();
    assert!(c.piecewise().is_none());
    let k3 = vec![0., 0., 0., 1., 2., 3., 4., 5., 6., 7., 7., 7.];
    let c = KnotModifiedCurve::new(3, k3, pts, None, 0.0).unwrap();
    check_curve("knot-modified, nothing moved", &c);
}

#[test]
fn bezier_splines_and_remodelling() {
    for m in 1..=7 {
        let breaks = vec![0.0, 0.7, 1.0, 2.5, 2.6];
        let l = breaks.len() - 1;
        let pts = spiral2(m * l + 1);
        let g = BezierSpline::new(m, breaks.clone(), pts).unwrap();
        check_curve(&format!("bezier m = {m}"), &g);
        let r = Remodelling::new(g, AlphaTable::classical(m, l), None).unwrap();
        check_curve(&format!("g* m = {m}"), &r);
    }
    let g = BezierSpline::new(3, vec![0.0, 1.0, 3.0], spiral3(7)).unwrap();
    check_curve("bezier 3D", &g);
}

#[test]
fn tensor_surfaces_on_grids() {
    let (nu, nv) = (7, 6);
    let net: Vec<DVec3> = (0..nu * nv)
        .map(|k| {
            let (i, j) = ((k / nv) as f64, (k % nv) as f64);
            DVec3::new(i, j, (i * 0.7).sin() * (j * 0.5).cos() + 0.1 * i * j)
        })
        .collect();
    for (p, q) in [(3, 3), (2, 4), (1, 2)] {
        let ku: Vec<f64> = (0..nu + p + 1).map(|i| (i as f64).powf(1.2)).collect();
        let kv = splinelab::knots::clamped_uniform(nv, q, 0.0, 2.0);
        let s = BSplineSurface::new(p, q, ku, kv, nu, nv, net.clone()).unwrap();
        check_surface(&format!("bspline surface {p}×{q}"), &s);
    }
    let (rows, cols) = (8, 7);
    let grid: Vec<DVec3> = (0..rows * cols)
        .map(|k| {
            let (i, j) = ((k / cols) as f64, (k % cols) as f64);
            DVec3::new(i, j, (0.3 * i * j).sin())
        })
        .collect();
    let b2 = B2Surface::new(rows, cols, &grid, &B2SurfaceOptions::default()).unwrap();
    check_surface("b2 surface", &b2);
    let ku = vec![0., 0., 0., 0., 1., 2., 3., 4., 4., 4., 4.];
    let kv = vec![0., 0., 0., 1., 2., 3., 4., 5., 5., 5.];
    for (mu, mv) in [
        (Some((5, 2.5)), None),
        (Some((4, 1.3)), Some((5, 3.9))),
        (None, None),
    ] {
        let s = KnotModifiedSurface::new(
            4,
            3,
            ku.clone(),
            kv.clone(),
            nu,
            7,
            {
                let mut pts = net.clone();
                pts.extend(spiral3(7));
                pts
            },
            mu,
            mv,
        )
        .unwrap();
        check_surface(&format!("knot-modified surface {mu:?} {mv:?}"), &s);
    }
}

#[test]
fn quasi_cubic_curves_by_segment_coefficients_and_rotations() {
    for alpha in [-3.0, -1.0, 0.0, 0.5, 1.0, 3.0] {
        let c = QuasiCubicCurve::new(alpha, spiral2(11)).unwrap();
        let breaks: Vec<f64> = (0..=8).map(|i| i as f64).collect();
        check_curve_at(&format!("quasi-cubic α = {alpha}"), &c, &c, &breaks);
        let c3 = QuasiCubicCurve::new(alpha, spiral3(7)).unwrap();
        check_curve_at(
            &format!("quasi-cubic 3D α = {alpha}"),
            &c3,
            &c3,
            &[1.0, 2.0, 3.0],
        );
    }
    let closed = QuasiCubicCurve::closed(1.0, spiral2(6)).unwrap();
    check_curve_at(
        "quasi-cubic closed",
        &closed,
        &closed,
        &[0.0, 1.0, 5.0, 6.0],
    );
}

#[test]
fn network_surfaces_on_grids() {
    use splinelab::gordon::{Blend, GordonSurface, NetworkLines, SplineBlendedSurface};
    use splinelab::network::Network;
    use splinelab::thin_plate::ThinPlateSurface;
    let u = [0.0, 0.3, 1.0, 1.4, 2.0];
    let v = [0.0, 0.5, 0.9, 1.5];
    let net = Network::from_function(&u, &v, |x, y| {
        DVec3::new(x, y, (1.3 * x).sin() * (0.7 * y).cos() + 0.2 * x * y)
    })
    .unwrap();
    check_surface("gordon", &GordonSurface::new(&net).unwrap());
    check_surface("thin plate", &ThinPlateSurface::new(&net).unwrap());
    let gb =
        SplineBlendedSurface::new(NetworkLines::new(&net).unwrap(), Blend::CubicNatural).unwrap();
    check_surface("spline-blended", &gb);
}

/// The one-call Fig. 3 sweep equals one `Remodelling::new` per value (same floating-point work: exact).
#[test]
fn bezier_curvature_sweep_equals_one_remodelling_per_value() {
    use splinelab::bezier::curvature_sweep;
    let pts = spiral2(11);
    let g = BezierSpline::new(2, vec![0.0, 1.0, 1.75, 2.5, 3.25, 4.0], pts).unwrap();
    let rows = vec![
        vec![2.0 / 3.0, 0.05],
        vec![0.95, 1.0 / 3.0],
        vec![2.0 / 3.0, 1.0 / 3.0],
        vec![2.0 / 3.0, 1.0 / 3.0],
        vec![2.0 / 3.0, 0.1],
    ];
    let table = AlphaTable::new(2, 5, rows.clone()).unwrap();
    let values: Vec<f64> = (0..=60).map(|j| 0.004 + 0.6 * j as f64 / 60.0).collect();
    for enforce in [Some(1), None] {
        for joint in 1..=5 {
            let (k, printed) = curvature_sweep(&g, &table, enforce, joint, &values).unwrap();
            assert_eq!(k.len(), values.len());
            for (j, &a) in values.iter().enumerate() {
                let mut r = rows.clone();
                r[joint - 1][1] = a;
                let rem = Remodelling::new(g.clone(), AlphaTable::new(2, 5, r).unwrap(), enforce)
                    .unwrap();
                assert_eq!(k[j], rem.curvature(joint), "K* joint {joint} value {a}");
                assert_eq!(
                    printed[j],
                    rem.curvature_printed(joint),
                    "printed {joint} {a}"
                );
            }
        }
    }
    // errors name the field: a joint outside 1..=L, a value outside (0, 1)
    let e = curvature_sweep(&g, &table, Some(1), 0, &values).unwrap_err();
    assert_eq!(e.field(), "alphaSweepJoint");
    let e = curvature_sweep(&g, &table, None, 2, &[0.5, 1.5]).unwrap_err();
    assert_eq!(e.field(), "alphaSweep[1]");
}

/// Quasi-cubic uniform samples with derivatives (rotation recurrence, no `sin_cos` per point) against the
/// generic basis per point, at counts that land on and between the segment ends.
#[test]
fn quasi_cubic_uniform_derivatives_by_rotation() {
    fn check<P: Point, C: Curve<P>>(name: &str, c: &C) {
        let (a, b) = c.domain();
        for count in [1usize, 2, 3, 17, 50, 161, 1001] {
            let params = uniform_params(a, b, count);
            let n = count * P::DIM;
            let (mut p, mut d1, mut d2) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            c.sample_uniform_derivs_into(count, 2, &mut p, &mut d1, &mut d2);
            let (mut q, mut e1, mut e2) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            eval_curve_generic_into(c, &params, 2, &mut q, &mut e1, &mut e2);
            assert_close(&format!("{name} n={count} points"), &p, &q);
            assert_close(&format!("{name} n={count} d1"), &d1, &e1);
            assert_close(&format!("{name} n={count} d2"), &d2, &e2);
            // values only: the same recurrence, order 0
            let mut v = vec![0.0; n];
            c.sample_uniform_into(count, &mut v);
            assert_close(&format!("{name} n={count} uniform values"), &v, &q);
        }
    }
    for alpha in [-3.0, -1.0, 0.0, 0.5, 1.0, 3.0] {
        check(
            &format!("quasi-cubic α = {alpha}"),
            &QuasiCubicCurve::new(alpha, spiral2(11)).unwrap(),
        );
        check(
            &format!("quasi-cubic 3D α = {alpha}"),
            &QuasiCubicCurve::new(alpha, spiral3(7)).unwrap(),
        );
    }
    check(
        "quasi-cubic closed",
        &QuasiCubicCurve::closed(1.0, spiral2(6)).unwrap(),
    );
}

/// The spatial grid of the fit sweep gives the same distances as brute force over every segment.
#[test]
fn polyline_grid_distance_equals_brute_force() {
    use splinelab::fit::{
        curve_distance, curve_distance_with, distance_to_polyline, fit, noisy_curve, KnownCurve,
        PolylineGrid,
    };
    let mut rng = Lcg(7);
    let mut polys: Vec<Vec<DVec2>> = [
        KnownCurve::Sine,
        KnownCurve::Arc,
        KnownCurve::Lemniscate,
        KnownCurve::Spiral,
        KnownCurve::Step,
    ]
    .iter()
    .map(|c| c.polyline(2001))
    .collect();
    // a random walk, a vertical segment chain, repeated points, two points
    let mut walk = vec![DVec2::ZERO];
    for _ in 0..500 {
        let last = *walk.last().unwrap();
        walk.push(last + DVec2::new(rng.next() - 0.5, rng.next() - 0.5));
    }
    polys.push(walk);
    polys.push((0..50).map(|i| DVec2::new(1.0, i as f64 * 0.1)).collect());
    polys.push(
        vec![DVec2::new(1.0, 1.0); 3]
            .into_iter()
            .chain([DVec2::new(2.0, 3.0)])
            .collect(),
    );
    polys.push(vec![DVec2::new(-1.0, 0.0), DVec2::new(1.0, 0.0)]);
    for (n, poly) in polys.iter().enumerate() {
        let grid = PolylineGrid::new(poly).expect("a grid");
        let (lo, hi) = poly
            .iter()
            .fold((poly[0], poly[0]), |(l, h), &p| (l.min(p), h.max(p)));
        let span = (hi - lo).max(DVec2::splat(1.0));
        for j in 0..3000 {
            // inside the box, just outside it, and far away
            let f = [1.2, 3.0, 200.0][j % 3];
            let p =
                lo + (hi - lo) * 0.5 + DVec2::new(rng.next() - 0.5, rng.next() - 0.5) * span * f;
            let (g, b) = (grid.distance(p), distance_to_polyline(p, poly));
            assert!(
                (g - b).abs() <= TOL * (1.0 + b),
                "polyline {n} query {p}: grid {g} vs brute force {b}"
            );
        }
    }
    // the sweep's distance: grid and brute force agree to 1e-12
    let data = noisy_curve(KnownCurve::Lemniscate, 60, 0.1, 3).unwrap();
    let truth = KnownCurve::Lemniscate.polyline(2001);
    for a in [0.0, 0.05, 0.2] {
        let c = fit(
            &data.noisy,
            &splinelab::b2spline::B2Options {
                a,
                ..Default::default()
            },
        )
        .unwrap();
        let (r1, m1) = curve_distance(&c, &truth, 400);
        let (r2, m2) = curve_distance_with(&c, &truth, None, 400);
        assert!((r1 - r2).abs() <= TOL * (1.0 + r2) && (m1 - m2).abs() <= TOL * (1.0 + m2));
    }
}

/// Quasi-cubic tensor surfaces: the grid sampler (basis rows per grid line, isocurve control points per
/// u-line) against the generic per-point evaluation, open and periodic in either direction.
#[test]
fn quasi_cubic_surfaces_on_grids() {
    use splinelab::quasi_cubic::QuasiCubicSurface;
    let mut rng = Lcg(5);
    let (rows, cols) = (7, 6);
    let grid: Vec<DVec3> = (0..rows * cols)
        .map(|k| DVec3::new((k / cols) as f64, (k % cols) as f64, 3.0 * rng.next() - 1.0))
        .collect();
    for alpha in [-3.0, 0.0, 0.5, 1.0, 3.0] {
        for periodic in [(false, false), (true, false), (false, true), (true, true)] {
            let s = QuasiCubicSurface::new(alpha, rows, cols, grid.clone(), periodic).unwrap();
            check_surface(&format!("quasi-cubic surface α = {alpha} {periodic:?}"), &s);
        }
    }
}

/// Blended interpolation (BIS) surfaces: the grid sampler (the tensor grid sampler, allocated weights per
/// grid line, the product rule per point) against the generic per-point evaluation, for several β*, k, α.
#[test]
fn bis_surfaces_on_grids() {
    use splinelab::quasi_cubic::BisSurface;
    let mut rng = Lcg(9);
    let (rows, cols) = (7, 6);
    let grid: Vec<DVec3> = (0..rows * cols)
        .map(|k| DVec3::new((k / cols) as f64, (k % cols) as f64, 3.0 * rng.next() - 1.0))
        .collect();
    let beta: Vec<f64> = (0..(rows - 2) * (cols - 2))
        .map(|_| 0.2 + 1.5 * rng.next())
        .collect();
    for k in [2, 3, 5] {
        for b in [None, Some(beta.clone())] {
            for alpha in [3.0, 0.5, -1.0] {
                let s = BisSurface::new(rows, cols, grid.clone(), b.clone(), k)
                    .unwrap()
                    .with_alpha(alpha)
                    .unwrap();
                let what = format!(
                    "BIS k = {k} α = {alpha} β* {}",
                    if b.is_some() { "varied" } else { "1" }
                );
                check_surface(&what, &s);
            }
        }
    }
}

/// Explicit parameters in long runs (sorted ascending, descending, and sorted with repeats at every break)
/// through the kernel's run walk, values and both derivatives, against the generic evaluation; buffers
/// shorter than the parameters end the evaluation there (no hang, no panic), and a NaN parameter ends its
/// run without stopping the walk.
#[test]
fn kernel_runs_sorted_descending_short_buffers() {
    let c = BSplineCurve::clamped_uniform(3, spiral2(40)).unwrap();
    let pp = c.piecewise().unwrap();
    let (a, b) = c.domain();
    let up = uniform_params(a, b, 50_001);
    let down: Vec<f64> = up.iter().rev().copied().collect();
    let mut repeats = Vec::new();
    for &k in pp.breaks() {
        repeats.extend([k, k, k]);
    }
    for (name, params) in [
        ("ascending", &up),
        ("descending", &down),
        ("repeats", &repeats),
    ] {
        let n = params.len() * 2;
        for order in 0..=2 {
            let (mut f0, mut f1, mut f2) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            let (mut g0, mut g1, mut g2) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            pp.sample_into(params, order, &mut f0, &mut f1, &mut f2);
            eval_curve_generic_into(&c, params, order, &mut g0, &mut g1, &mut g2);
            assert_close(&format!("{name} points (order {order})"), &f0, &g0);
            if order >= 1 {
                assert_close(&format!("{name} d1 (order {order})"), &f1, &g1);
            }
            if order == 2 {
                assert_close(&format!("{name} d2"), &f2, &g2);
            }
        }
    }
    // short buffers: as far as each goes
    let mut short = vec![-7.0; 20];
    pp.sample_into(&up[..100], 0, &mut short, &mut [], &mut []);
    let mut g = vec![0.0; 20];
    eval_curve_generic_into(&c, &up[..10], 0, &mut g, &mut [], &mut []);
    assert_close("short buffer", &short, &g);
    let (mut p, mut d1) = (vec![0.0; 200], vec![-7.0; 6]);
    pp.sample_into(&up[..100], 1, &mut p, &mut d1, &mut []);
    assert!(
        p[6..].iter().all(|&x| x == 0.0),
        "stops at the shortest buffer"
    );
    // NaN: its own run, the rest evaluated as usual
    let params = [0.1, f64::NAN, 0.2, 0.3];
    let mut p = vec![0.0; 8];
    pp.sample_into(&params, 0, &mut p, &mut [], &mut []);
    assert!(p[2].is_nan() && p[3].is_nan());
    assert_close(
        "after NaN",
        &p[4..],
        &[c.eval(0.2).x, c.eval(0.2).y, c.eval(0.3).x, c.eval(0.3).y],
    );
}

/// `first_non_finite` (the check of `at` arrays) finds the first NaN / ±∞ wherever it sits (first, last,
/// at block boundaries) and accepts every finite value (including the largest and subnormals).
#[test]
fn first_non_finite_finds_the_first_bad_entry() {
    use splinelab::sample::first_non_finite;
    let mut xs: Vec<f64> = (0..5000).map(|i| i as f64 * 0.37 - 900.0).collect();
    xs.extend([f64::MAX, -f64::MAX, f64::MIN_POSITIVE / 8.0, -0.0, 0.0]);
    assert_eq!(first_non_finite(&xs), None);
    assert_eq!(first_non_finite(&[]), None);
    for bad in [f64::NAN, f64::INFINITY, f64::NEG_INFINITY, -f64::NAN] {
        for at in [0usize, 1, 1023, 1024, 1025, 2047, 4096, xs.len() - 1] {
            let mut ys = xs.clone();
            ys[at] = bad;
            ys[xs.len() - 1] = f64::NAN; // a later one must not win
            let want = at.min(xs.len() - 1);
            assert_eq!(first_non_finite(&ys), Some(want), "{bad} at {at}");
        }
    }
}

/// sin θ, cos θ on a quasi-cubic segment (θ = πt/2, t ∈ [0, 1]) by the polynomials of
/// `quasi_cubic::trig` agree with libm to 1e-15 at 10⁵ random t, the ends, the middle and next to them;
/// outside [0, 1] they are libm's.
#[test]
fn quarter_sin_cos_matches_libm() {
    use splinelab::quasi_cubic::trig::quarter_sin_cos;
    let mut ts = vec![
        0.0,
        1.0,
        0.5,
        0.25,
        0.75,
        1e-300,
        5e-324,
        1.0 - f64::EPSILON / 2.0,
    ];
    ts.extend([f64::EPSILON, 0.5 + f64::EPSILON, 0.5 - f64::EPSILON / 2.0]);
    let mut r = Lcg(11);
    ts.extend((0..100_000).map(|_| r.next()));
    let mut worst = 0.0_f64;
    for &t in &ts {
        let (s, c) = quarter_sin_cos(t);
        let (s0, c0) = (std::f64::consts::FRAC_PI_2 * t).sin_cos();
        worst = worst.max((s - s0).abs()).max((c - c0).abs());
        assert!(
            (s - s0).abs() <= 1e-15 && (c - c0).abs() <= 1e-15,
            "t = {t}: ({s}, {c}) vs libm ({s0}, {c0})"
        );
    }
    assert!(worst > 0.0 || ts.len() < 10, "compared something");
    for t in [-0.5, 1.5, -3.0, 7.25] {
        assert_eq!(
            quarter_sin_cos(t),
            (std::f64::consts::FRAC_PI_2 * t).sin_cos()
        );
    }
}

/// Quasi-cubic curves at explicit parameters (runs of one Taylor expansion per segment, no libm
/// call per point) agree with the generic evaluation (the basis functions' own libm sines and cosines) to
/// 1e-13 × scale, values and both derivatives, at 20,000 random parameters plus every segment end and its
/// neighbours, every α of the presets' range, open (with extrapolation) and closed, 2D and 3D.
#[test]
fn quasi_cubic_at_params_to_1e13() {
    fn check<P: Point, C: Curve<P>>(name: &str, c: &C) {
        let (a, b) = c.domain();
        let mut params = Vec::new();
        let mut r = Lcg(5);
        params.extend((0..20_000).map(|_| a + (b - a) * r.next()));
        for k in (a as i64)..=(b as i64) {
            let k = k as f64;
            params.extend([
                k,
                k - 1e-15 * k.max(1.0),
                k + 1e-15 * k.max(1.0),
                k - 1e-9,
                k + 1e-9,
            ]);
        }
        params.extend([a - 0.3, b + 0.3]);
        let n = params.len() * P::DIM;
        for order in 0..=2 {
            let (mut f0, mut f1, mut f2) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            let (mut g0, mut g1, mut g2) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
            c.sample_into(&params, order, &mut f0, &mut f1, &mut f2);
            eval_curve_generic_into(c, &params, order, &mut g0, &mut g1, &mut g2);
            for (what, f, g) in [("points", &f0, &g0), ("d1", &f1, &g1), ("d2", &f2, &g2)] {
                let s = scale(g);
                let worst = f
                    .iter()
                    .zip(g.iter())
                    .map(|(x, y)| (x - y).abs())
                    .fold(0.0, f64::max);
                assert!(
                    worst <= 1e-13 * s,
                    "{name} {what} (order {order}): differs by {worst:e} (scale {s:e})"
                );
            }
        }
    }
    for alpha in [-3.0, -1.0, 0.0, 0.5, 1.0, 3.0] {
        check(
            &format!("quasi-cubic α = {alpha}"),
            &QuasiCubicCurve::new(alpha, spiral2(30)).unwrap(),
        );
        check(
            &format!("quasi-cubic 3D α = {alpha}"),
            &QuasiCubicCurve::new(alpha, spiral3(12)).unwrap(),
        );
        check(
            &format!("quasi-cubic closed α = {alpha}"),
            &QuasiCubicCurve::closed(alpha, spiral2(9)).unwrap(),
        );
    }
}
