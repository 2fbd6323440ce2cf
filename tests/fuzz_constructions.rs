//! Property-based fuzzing of every construction's entry point (issue 9): B2 curves, surfaces and fits,
//! Bézier remodelling, knot modification, curve networks (criss-cross, thin-plate), the mesh builder. For
//! arbitrary finite input of moderate size a constructor returns an `Error` or a value whose evaluation (points
//! and derivatives, over the domain and slightly beyond) is finite — it never panics and never loops.
//!
//! Default case counts keep `cargo test --test fuzz_constructions` to a few seconds per target; the long mode
//! is `PROPTEST_CASES=20000 cargo test --release --test fuzz_constructions`.
#![cfg(not(target_arch = "wasm32"))]

use glam::{DVec2, DVec3};
use proptest::prelude::*;
use proptest::test_runner::{FileFailurePersistence, RngSeed};
use splinelab::b2spline::{
    AutoTension, B2Curve, B2Options, B2Surface, B2SurfaceOptions, Construction, KnotChoice,
    SurfaceKnots, Tension,
};
use splinelab::bezier::{
    AlphaTable, BezierSpline, BezierSplineSurface, Remodelling, SurfaceRemodelling,
};
use splinelab::bspline::BSplineCurve;
use splinelab::criss_cross::{CrissCross, CrissCrossSurface};
use splinelab::fit;
use splinelab::gordon::{Blend, FnLines, GordonSurface, NetworkLines, SplineBlendedSurface};
use splinelab::knot_paths::{KnotModifiedCurve, KnotModifiedSurface, Var};
use splinelab::mesh::Mesh;
use splinelab::network::{NetPoint, Network};
use splinelab::quasi_cubic::{beta_curvature, Bis, BisSurface, QuasiCubicCurve, QuasiCubicSurface};
use splinelab::thin_plate::ThinPlateSurface;
use splinelab::{sample, Curve, Point, Surface};
use std::collections::hash_map::RandomState;
use std::hash::{BuildHasher, Hasher};
use std::sync::atomic::{AtomicUsize, Ordering};
use std::sync::OnceLock;

/// Per target: how many cases ran and how many of them built a construction. A target whose constructor
/// accepts (almost) nothing fuzzes only the rejection path, and one that accepts (almost) everything no longer
/// reaches the rejections: both make the target pass without testing what it claims, so `run_target` asserts
/// the share (the generators are tuned for 10–80 %).
static CASES: [AtomicUsize; 15] = [const { AtomicUsize::new(0) }; 15];
static ACCEPTED: [AtomicUsize; 15] = [const { AtomicUsize::new(0) }; 15];
const TARGETS: [&str; 15] = [
    "b2_curve",
    "b2_surface",
    "b2_fit",
    "bezier_remodel",
    "bezier_surface",
    "bspline_to_bezier",
    "knot_modified_curve",
    "knot_modified_surface",
    "networks",
    "free_data_networks",
    "criss_cross_basis",
    "mesh_from_grid",
    "quasi_cubic",
    "quasi_cubic_surfaces",
    "gordon_and_blended",
];
/// Accepted share per target: at least 1 case in 25 builds a construction, at most 19 in 20 do. With the
/// default 300–400 cases the lowest observed share (bspline_to_bezier, ~10 %) sits 4 standard deviations above
/// the lower bound, the highest (bezier_surface, ~82 %) 6 below the upper one.
const MIN_ACCEPTED: (usize, usize) = (1, 25);
const MAX_ACCEPTED: (usize, usize) = (19, 20);
/// Below this many cases (a small `PROPTEST_CASES`) the share is too noisy to assert; it is only printed.
const MIN_CASES_FOR_SHARE: usize = 200;

fn counter(counters: &'static [AtomicUsize; 15], target: &str) -> &'static AtomicUsize {
    let i = TARGETS.iter().position(|t| *t == target);
    &counters[i.unwrap_or_else(|| panic!("{target} is not in TARGETS"))]
}
fn case(target: &str) {
    counter(&CASES, target).fetch_add(1, Ordering::Relaxed);
}
fn accepted(target: &str) {
    counter(&ACCEPTED, target).fetch_add(1, Ordering::Relaxed);
}

/// The seed of this run's generators: `PROPTEST_RNG_SEED` when set, else a fresh one, so every failure can
/// print the seed that replays it (proptest's own random seed is never shown).
fn run_seed() -> u64 {
    static SEED: OnceLock<u64> = OnceLock::new();
    *SEED.get_or_init(|| {
        std::env::var("PROPTEST_RNG_SEED")
            .ok()
            .and_then(|s| s.parse().ok())
            .unwrap_or_else(|| RandomState::new().build_hasher().finish())
    })
}

/// The command that replays `target` with this run's seed (and case count, when it was set).
fn replay_command(target: &str) -> String {
    let cases = std::env::var("PROPTEST_CASES")
        .map(|c| format!(" PROPTEST_CASES={c}"))
        .unwrap_or_default();
    format!(
        "PROPTEST_RNG_SEED={}{cases} cargo test --test fuzz_constructions -- --exact {target}",
        run_seed()
    )
}

/// Runs one target's cases, then asserts the share of them that built a construction. Any failure (a property
/// or the share) names the seed that replays it.
fn run_target(target: &str, cases: fn()) {
    if let Err(panic) = std::panic::catch_unwind(cases) {
        eprintln!(
            "fuzz_constructions: {target} failed; replay: {}",
            replay_command(target)
        );
        std::panic::resume_unwind(panic);
    }
    let ran = counter(&CASES, target).load(Ordering::Relaxed);
    let ok = counter(&ACCEPTED, target).load(Ordering::Relaxed);
    eprintln!("fuzz_constructions: {target}: {ok} of {ran} cases accepted");
    if ran < MIN_CASES_FOR_SHARE {
        return;
    }
    let (lo, hi) = (MIN_ACCEPTED, MAX_ACCEPTED);
    assert!(
        ok * lo.1 >= ran * lo.0 && ok * hi.1 <= ran * hi.0,
        "{target}: {ok} of {ran} cases built a construction, outside {}/{} … {}/{}: the generator or the \
         constructor's validation changed, so the target no longer fuzzes both paths; replay: {}",
        lo.0,
        lo.1,
        hi.0,
        hi.1,
        replay_command(target)
    );
}

/// Cases per target: `PROPTEST_CASES` when set, else `default`; generators seeded with `run_seed`.
fn config(default: u32) -> ProptestConfig {
    let cases = std::env::var("PROPTEST_CASES")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(default);
    // failures are saved in tests/fuzz_constructions.proptest-regressions (beside this file; proptest's default
    // `SourceParallel` looks for a lib.rs above tests/ and falls back to it with a warning per target) and
    // replayed first on every later run: once the file is committed the case runs for good
    ProptestConfig {
        cases,
        rng_seed: RngSeed::Fixed(run_seed()),
        failure_persistence: Some(Box::new(FileFailurePersistence::WithSource(
            "proptest-regressions",
        ))),
        ..ProptestConfig::default()
    }
}

/// A coordinate: mostly ordinary, sometimes repeated, tiny or large (≤ 1e6: the documented moderate range).
fn coord() -> impl Strategy<Value = f64> {
    prop_oneof![
        6 => -10.0..10.0,
        1 => Just(0.0),
        1 => Just(1.0),
        1 => -1e6..1e6,
        1 => -1e-6..1e-6,
    ]
}

fn p2() -> impl Strategy<Value = DVec2> {
    (coord(), coord()).prop_map(|(x, y)| DVec2::new(x, y))
}

fn p3() -> impl Strategy<Value = DVec3> {
    (coord(), coord(), coord()).prop_map(|(x, y, z)| DVec3::new(x, y, z))
}

/// Points, sometimes with a point repeated (coincident data).
fn pts2(lo: usize, hi: usize) -> impl Strategy<Value = Vec<DVec2>> {
    (prop::collection::vec(p2(), lo..hi), any::<u8>()).prop_map(|(mut v, k)| {
        if k % 4 == 0 && v.len() > 2 {
            let i = (k as usize / 4) % (v.len() - 1);
            v[i + 1] = v[i];
        }
        v
    })
}

/// Breakpoints: increasing with gaps of very different sizes, or arbitrary (possibly unsorted/repeated).
fn breaks(lo: usize, hi: usize) -> impl Strategy<Value = Vec<f64>> {
    prop_oneof![
        4 => (coord(), prop::collection::vec(prop_oneof![0.01..5.0, 1e-6..1e-3, Just(1.0)], lo.saturating_sub(1)..hi))
            .prop_map(|(x0, gaps)| {
                let mut x = vec![x0];
                for g in gaps {
                    let last = *x.last().unwrap();
                    x.push(last + g);
                }
                x
            }),
        1 => prop::collection::vec(coord(), lo..hi),
    ]
}

/// A non-decreasing knot vector of exactly `len` knots (repeated knots, nearly equal ones, ordinary gaps);
/// sometimes (1 in 8) an arbitrary one.
fn knot_vector(len: usize) -> BoxedStrategy<Vec<f64>> {
    prop_oneof![
        7 => (coord(), prop::collection::vec(prop_oneof![3 => 0.05..3.0, 1 => Just(0.0), 1 => Just(1e-6), 1 => Just(1.0)], len.saturating_sub(1)))
            .prop_map(|(x0, gaps)| {
                let mut x = vec![x0];
                for g in gaps {
                    let last = *x.last().unwrap();
                    x.push(last + g);
                }
                x
            }),
        1 => prop::collection::vec(coord(), len),
    ]
    .boxed()
}

fn tension() -> impl Strategy<Value = f64> {
    prop_oneof![Just(1.0 / 6.0), -1.0..2.0, Just(0.0), Just(0.5)]
}

fn curve_finite<P: Point, C: Curve<P> + ?Sized>(c: &C) -> std::result::Result<(), TestCaseError> {
    let (a, b) = c.domain();
    prop_assert!(a.is_finite() && b.is_finite(), "domain {a} {b}");
    let w = b - a;
    for k in 0..=32 {
        let u = a - 0.05 * w + 1.1 * w * k as f64 / 32.0;
        let mut o = [P::ZERO; 3];
        c.eval_derivs(u, 2, &mut o);
        for (i, x) in o.iter().enumerate() {
            prop_assert!(x.is_finite(), "order {i} at u = {u}: {x:?}");
        }
    }
    Ok(())
}

fn surface_finite<P: Point, S: Surface<P> + ?Sized>(
    s: &S,
) -> std::result::Result<(), TestCaseError> {
    let ((u0, u1), (v0, v1)) = s.domain();
    for i in 0..=8 {
        for j in 0..=8 {
            let (u, v) = (
                u0 + (u1 - u0) * i as f64 / 8.0,
                v0 + (v1 - v0) * j as f64 / 8.0,
            );
            let mut o = [P::ZERO; 3];
            s.eval_derivs(u, v, true, &mut o);
            for x in &o {
                prop_assert!(x.is_finite(), "at ({u}, {v}): {o:?}");
            }
        }
    }
    Ok(())
}

fn b2_options() -> impl Strategy<Value = B2Options> {
    (
        -0.5..0.5f64,
        prop_oneof![tension().prop_map(Tension::Scalar), prop::collection::vec(tension(), 0..12).prop_map(Tension::PerVertex)],
        prop_oneof![3 => Just(AutoTension::Off), 1 => (0.0..1.0f64).prop_map(AutoTension::Paper), 1 => (0.0..1.0f64).prop_map(AutoTension::Turning)],
        prop_oneof![3 => Just(KnotChoice::Chord), 1 => Just(KnotChoice::Uniform), 1 => breaks(0, 12).prop_map(KnotChoice::Explicit)],
        prop_oneof![3 => Just(None), 1 => (0.0..100.0f64).prop_map(Some)],
        prop_oneof![Just(1.0), Just(2.0), -1.0..3.0f64],
        prop_oneof![3 => Just(Construction::NonUniform), 1 => Just(Construction::Section3)],
    )
        .prop_map(|(a, tension, auto_tension, knots, k, c2, construction)| B2Options {
            a,
            tension,
            auto_tension,
            knots,
            k,
            c2,
            construction,
        })
}

proptest! {
    #![proptest_config(config(400))]

    fn b2_curve_cases(pts in pts2(0, 12), opts in b2_options()) {
        case("b2_curve");
        if let Ok(c) = B2Curve::new(&pts, &opts) {
            accepted("b2_curve");
            curve_finite(&c)?;
            prop_assert!(c.control_points().iter().all(|p| p.is_finite()));
        }
    }

    fn b2_surface_cases(rows in prop_oneof![1 => 0usize..6, 4 => 6usize..10], cols in prop_oneof![1 => 0usize..6, 4 => 6usize..9], seed in prop::collection::vec(p3(), 81),
                  a in -0.3..0.3f64, tu in tension(), tv in tension(),
                  ku in prop_oneof![Just(SurfaceKnots::Chord), Just(SurfaceKnots::Uniform), breaks(0, 10).prop_map(SurfaceKnots::Explicit)],
                  kv in prop_oneof![Just(SurfaceKnots::Chord), Just(SurfaceKnots::Uniform)]) {
        case("b2_surface");
        let g: Vec<DVec3> = seed[..rows * cols].to_vec();
        let o = B2SurfaceOptions { a, tension_u: Tension::Scalar(tu), tension_v: Tension::Scalar(tv), knots_u: ku, knots_v: kv, ..B2SurfaceOptions::default() };
        if let Ok(s) = B2Surface::new(rows, cols, &g, &o) {
            accepted("b2_surface");
            surface_finite(&s)?;
        }
    }

    fn b2_fit_cases(data in pts2(0, 14), opts in b2_options(), avals in prop::collection::vec(-0.3..0.3f64, 1..4)) {
        case("b2_fit");
        if let Ok(c) = fit::fit(&data, &opts) {
            accepted("b2_fit");
            curve_finite(&c)?;
            let res = fit::residuals(&c);
            prop_assert!(res.iter().all(|r| r.is_finite()), "{res:?}");
            let truth = fit::KnownCurve::ALL[0].polyline(50);
            let (r, m) = fit::curve_distance(&c, &truth, 20);
            prop_assert!(r.is_finite() && m.is_finite());
        }
        if let Ok(rows) = fit::sweep(&data, &opts, &avals, None, 10, data.len() < 10) {
            for r in rows {
                prop_assert!(r.residual_rms.is_finite(), "{:?}", r.residual_rms);
            }
        }
    }

    fn bezier_remodel_cases(m in 1usize..6, segs in 1usize..5, pts in pts2(2, 30), br in breaks(1, 6),
                      alphas in prop::collection::vec(prop_oneof![0.01..0.99f64, Just(0.5), -0.5..1.5f64], 30),
                      r in 0usize..4, enforce in any::<bool>()) {
        case("bezier_remodel");
        let n = m * segs + 1;
        if pts.len() < n { return Ok(()); }
        let b: Vec<DVec2> = pts[..n].to_vec();
        let bk = if br.len() == segs + 1 { br } else { (0..=segs).map(|i| i as f64).collect() };
        if let Ok(g) = BezierSpline::new(m, bk, b) {
            curve_finite(&g)?;
            for i in 0..=g.segments() {
                let _ = g.break_curvature(i);
            }
            let rows: Vec<Vec<f64>> = (0..segs).map(|i| alphas[i * m % 30..][..m.min(30 - i * m % 30)].to_vec()).collect();
            if let Ok(t) = AlphaTable::new(m, segs, rows) {
                if let Ok(rem) = Remodelling::new(g, t, if enforce { Some(r) } else { None }) {
            accepted("bezier_remodel");
                    curve_finite(&rem)?;
                    prop_assert!(rem.elevated().points().iter().all(|p| p.is_finite()));
                }
            }
        }
    }

    fn bezier_surface_cases(m in 1usize..4, n in 1usize..4, segs in 1usize..3, grid in prop::collection::vec(p3(), 60),
                      a1 in 0.01..0.99f64, r in 0usize..2) {
        case("bezier_surface");
        let rows = m * segs + 1;
        let cols = n + 1;
        if rows * cols > grid.len() { return Ok(()); }
        let bu: Vec<f64> = (0..=segs).map(|i| i as f64 * 0.7).collect();
        if let Ok(g) = BezierSplineSurface::new(m, n, bu, vec![0.0, 1.0], grid[..rows * cols].to_vec()) {
            let t = AlphaTable::new(m, segs, vec![vec![a1; m]; segs]).unwrap();
            if let Ok(rem) = SurfaceRemodelling::new(g, t, Some(r)) {
            accepted("bezier_surface");
                surface_finite(&rem)?;
            }
        }
    }

    fn bspline_to_bezier_cases(degree in 1usize..5, pts in pts2(2, 10), br in breaks(2, 8)) {
        case("bspline_to_bezier");
        let n = pts.len();
        let mut k = vec![br[0]; degree];
        k.extend(br.iter().copied());
        k.extend(vec![*br.last().unwrap(); degree]);
        if k.len() == n + degree + 1 {
            if let Ok(c) = BSplineCurve::new(degree, k, pts) {
                if let Ok(g) = BezierSpline::from_bspline(&c) {
            accepted("bspline_to_bezier");
                    curve_finite(&g)?;
                    let (a, b) = c.domain();
                    let u = 0.3 * a + 0.7 * b;
                    let scale = c.points().iter().map(|p| p.abs().max_element()).fold(1.0, f64::max);
                    prop_assert!((g.eval(u) - c.eval(u)).abs().max_element() <= 1e-9 * scale);
                }
            }
        }
    }

    fn knot_modified_curve_cases((order, pts, br) in (1usize..6, pts2(1, 10)).prop_flat_map(|(k, p)| { let n = p.len(); (Just(k), Just(p), knot_vector(n + k)) }),
                           p in 0usize..16,
                           up_raw in prop_oneof![-20.0..20.0f64, Just(1e8), Just(-1e8), Just(f64::INFINITY), Just(f64::NEG_INFINITY)],
                           near in prop::option::of((0usize..16, prop_oneof![Just(0.0), Just(1e-300), Just(-1e-15), Just(1e-6)]))) {
        case("knot_modified_curve");
        // sometimes the moved knot sits on, or within rounding of, another knot
        let n = pts.len();
        let p = if p % 5 == 0 || n <= order { p } else { order + p % (n - order) };
        let up = match near {
            Some((j, d)) if j < br.len() => br[j] + d * br[j].abs().max(1.0),
            _ => up_raw,
        };
        if let Ok(c) = KnotModifiedCurve::new(order, br.clone(), pts.clone(), Some(p), up) {
            accepted("knot_modified_curve");
            // within its neighbours the family is an ordinary B-spline: finite. Outside, it is the extended
            // path, whose poles (u_p at another knot) may overflow: there only "no panic" is required.
            let inside = c.line().neighbours().is_some_and(|(a, b)| a <= up && up <= b);
            if inside {
                curve_finite(&c)?;
            } else {
                let (a, b) = c.domain();
                let _ = c.eval(0.5 * (a + b));
            }
            if let Some(e) = c.envelope() {
                curve_finite(&e)?;
            }
            if let Some(((_, a), (_, b))) = c.limits() {
                prop_assert!(a.is_finite() && b.is_finite());
            }
            let mut out = Vec::new();
            let (a, b) = c.domain();
            c.path_into(0.5 * (a + b), &[-1e8, -1.0, 0.0, 0.5, 1.0, 1e8], &mut out);
            prop_assert_eq!(out.len(), 6);
        }
    }

    fn knot_modified_surface_cases((k, l, nu, nv, ku, kv) in (2usize..5, 2usize..5, 1usize..4, 1usize..4)
                                 .prop_flat_map(|(k, l, du, dv)| (Just(k), Just(l), Just(k + du), Just(l + dv), knot_vector(k + du + k), knot_vector(l + dv + l))),
                             net in prop::collection::vec(p3(), 49),
                             p in 0usize..12, up in -10.0..10.0f64, q in prop::option::of(0usize..12), vq in -10.0..10.0f64) {
        case("knot_modified_surface");
        // interior indices k ≤ p ≤ nu − 1 (and l ≤ q ≤ nv − 1), the raw value now and then
        let p = if p % 5 == 0 { p } else { k + p % (nu - k) };
        let q = q.map(|q| if q % 5 == 0 { q } else { l + q % (nv - l) });
        if let Ok(s) = KnotModifiedSurface::new(k, l, ku, kv, nu, nv, net[..nu * nv].to_vec(), Some((p, up)), q.map(|q| (q, vq))) {
            accepted("knot_modified_surface");
            let inside = |line: &splinelab::knot_paths::KnotLine, x: f64| line.moved().is_none() || line.neighbours().is_some_and(|(a, b)| a <= x && x <= b);
            let (su, sv) = s.knot_values();
            if inside(s.line_u(), su) && inside(s.line_v(), sv) {
                surface_finite(&s)?;
            }
            if let Some(e) = s.envelope() {
                surface_finite(&e)?;
            }
            for dir in [Var::U, Var::V] {
                if let Some(((_, a), (_, b))) = s.limit_curves(dir) {
                    prop_assert!(a.iter().chain(&b).all(|x| x.is_finite()));
                }
            }
            let ((u0, u1), (v0, v1)) = s.domain();
            let mut out = Vec::new();
            s.path_surface_into(0.5 * (u0 + u1), 0.5 * (v0 + v1), &[-1e8, 0.0, 1.0], &[0.0, 1e8], &mut out);
            prop_assert_eq!(out.len(), 6);
        }
    }

    fn networks_cases(u in breaks(2, 6), v in breaks(2, 6), c in prop::collection::vec(p3(), 64), c11 in p3(),
                edit in prop::option::of((any::<bool>(), 0usize..8, 0usize..8))) {
        case("networks");
        let (m, n) = (u.len().saturating_sub(1), v.len().saturating_sub(1));
        if (m + 2) * (n + 2) > c.len() { return Ok(()); }
        let rows: Vec<Vec<DVec3>> = (0..m + 2).map(|i| c[i * (n + 2)..(i + 1) * (n + 2)].to_vec()).collect();
        let Ok(net) = Network::from_control_net(&u, &v, &rows) else { return Ok(()) };
        let rep = net.compatibility();
        prop_assert!(rep.is_ok());
        prop_assert!(rep.unwrap().c2.is_finite());
        if let Ok(s) = CrissCrossSurface::new(&net) {
            accepted("networks");
            surface_finite(&s)?;
            let ctrl = s.control_points(c11);
            prop_assert!(ctrl.iter().all(|p| p.is_finite()));
            prop_assert!(s.default_c11().is_finite());
            if let Ok(sp) = s.spline(c11) {
                surface_finite(&sp)?;
            }
        }
        if let Ok(t) = ThinPlateSurface::new(&net) {
            surface_finite(&t)?;
            prop_assert!(t.energy().is_finite());
        }
        let edited = edit.map(|(p, a, b)| if p { NetPoint::P { r: a, j: b } } else { NetPoint::Q { s: a, i: b } });
        if let Ok(fixed) = net.repair(edited) {
            let c2 = fixed.compatibility().map(|r| r.c2);
            prop_assert!(matches!(c2, Ok(x) if x.is_finite()));
        }
    }

    fn free_data_networks_cases(u in breaks(2, 6), v in breaks(2, 6), ps in prop::collection::vec(p3(), 64), q1 in prop::collection::vec(p3(), 8)) {
        case("free_data_networks");
        let (m, n) = (u.len().saturating_sub(1), v.len().saturating_sub(1));
        if (m + 1) * (n + 2) > ps.len() || n + 1 > q1.len() { return Ok(()); }
        let p: Vec<Vec<DVec3>> = (0..=m).map(|r| ps[r * (n + 2)..(r + 1) * (n + 2)].to_vec()).collect();
        if let Ok(net) = Network::from_free_data(&u, &v, p, &q1[..n + 1]) {
            if let Ok(s) = CrissCrossSurface::new(&net) {
            accepted("free_data_networks");
                surface_finite(&s)?;
            }
        }
    }

    fn criss_cross_basis_cases(u in breaks(2, 7), v in breaks(2, 7), i in 0usize..8, j in 0usize..8, at in prop::collection::vec((-0.2..1.2f64, -0.2..1.2f64), 1..10)) {
        case("criss_cross_basis");
        if let Ok(cc) = CrissCross::new(&u, &v) {
            let ((u0, u1), (v0, v1)) = cc.domain();
            let (m, n) = cc.cells();
            if i <= m + 1 && j <= n + 1 {
            accepted("criss_cross_basis");
                for (s, t) in at {
                    let b = cc.basis(i, j, u0 + s * (u1 - u0), v0 + t * (v1 - v0));
                    prop_assert!(b.iter().all(|x| x.is_finite()), "{b:?}");
                }
            }
        }
    }

    fn mesh_from_grid_cases(nu in 0usize..8, nv in 0usize..8, dim in 1usize..4, xs in prop::collection::vec(coord(), 3 * 64), with_d in any::<bool>()) {
        case("mesh_from_grid");
        let pts = xs[..(nu * nv * dim).min(xs.len())].to_vec();
        let d = if with_d { Some((&xs[..pts.len()], &xs[xs.len() - pts.len()..])) } else { None };
        if let Ok(m) = Mesh::from_grid(&pts, d, dim, nu, nv) {
            accepted("mesh_from_grid");
            prop_assert!(m.normals.iter().all(|x| x.is_finite()), "normals {:?}", m.normals);
            prop_assert!(m.indices.iter().all(|&i| (i as usize) < nu * nv));
        }
    }
}

proptest! {
    #![proptest_config(config(300))]

    fn quasi_cubic_cases(alpha in prop_oneof![-3.5..3.5f64, Just(3.0), Just(-3.0), Just(0.0)], pts in pts2(0, 12), closed in any::<bool>(),
                   beta in prop::option::of(prop::collection::vec(prop_oneof![0.0..3.0f64, Just(0.0), -1.0..0.0], 0..12)), k in 0usize..12, curv in any::<bool>()) {
        case("quasi_cubic");
        let c = if closed { QuasiCubicCurve::closed(alpha, pts.clone()) } else { QuasiCubicCurve::new(alpha, pts.clone()) };
        if let Ok(c) = c {
            curve_finite(&c)?;
        }
        let beta = if curv { beta_curvature(&pts).ok() } else { beta };
        if let Ok(b) = Bis::new(pts.clone(), beta, k) {
            accepted("quasi_cubic");
            curve_finite(&b)?;
        }
    }

    fn quasi_cubic_surfaces_cases(alpha in -3.5..3.5f64, rows in 0usize..8, cols in 0usize..8, grid in prop::collection::vec(p3(), 64),
                            pu in any::<bool>(), pv in any::<bool>(), k in 1usize..11, beta in prop::option::of(prop::collection::vec(0.0..3.0f64, 36))) {
        case("quasi_cubic_surfaces");
        let g = grid[..rows * cols].to_vec();
        if let Ok(s) = QuasiCubicSurface::new(alpha, rows, cols, g.clone(), (pu, pv)) {
            surface_finite(&s)?;
        }
        let len = rows.saturating_sub(2) * cols.saturating_sub(2);
        let b = beta.map(|b| b[..len.min(b.len())].to_vec());
        if let Ok(s) = BisSurface::new(rows, cols, g, b, k) {
            accepted("quasi_cubic_surfaces");
            surface_finite(&s)?;
        }
    }

    fn gordon_and_blended_cases(u in breaks(2, 6), v in breaks(2, 6), c in prop::collection::vec(p3(), 64),
                          blend in prop_oneof![Just(0u8), Just(1u8), Just(2u8)], a in -0.3..0.3f64, t in tension()) {
        case("gordon_and_blended");
        let (m, n) = (u.len().saturating_sub(1), v.len().saturating_sub(1));
        if (m + 2) * (n + 2) > c.len() { return Ok(()); }
        let rows: Vec<Vec<DVec3>> = (0..m + 2).map(|i| c[i * (n + 2)..(i + 1) * (n + 2)].to_vec()).collect();
        let Ok(net) = Network::from_control_net(&u, &v, &rows) else { return Ok(()) };
        if let Ok(g) = GordonSurface::new(&net) {
            accepted("gordon_and_blended");
            surface_finite(&g)?;
        }
        let b = match blend {
            0 => Blend::CubicNatural,
            1 => Blend::CubicNotAKnot,
            _ => Blend::B2 { a, tension_u: Tension::Scalar(t), tension_v: Tension::Scalar(t), c2: 1.0 },
        };
        if !matches!(b, Blend::B2 { .. }) {
            if let Ok(lines) = NetworkLines::new(&net) {
                if let Ok(s) = SplineBlendedSurface::new(lines, b.clone()) {
                    surface_finite(&s)?;
                }
            }
        }
        // a function network on the same nodes (B2 needs the auxiliary lines u_{-1}, u_{m+1}: extend them)
        let ext = |x: &[f64]| { let mut e = vec![x[0] - 1.0]; e.extend_from_slice(x); e.push(x[x.len() - 1] + 1.0); e };
        let (fu, fv) = if matches!(b, Blend::B2 { .. }) { (ext(&u), ext(&v)) } else { (u.clone(), v.clone()) };
        let f = FnLines::new(|x: f64, y: f64| DVec3::new(x, y, (x * 0.7).sin() * y), fu, fv);
        if let Ok(s) = SplineBlendedSurface::new(f, b) {
            surface_finite(&s)?;
        }
    }
}

/// One test per target: its cases, then the share of them that built a construction (`run_target`).
macro_rules! targets {
    ($($target:ident => $cases:ident),+ $(,)?) => {
        $(
            #[test]
            fn $target() {
                run_target(stringify!($target), $cases);
            }
        )+
    };
}
targets! {
    b2_curve => b2_curve_cases,
    b2_surface => b2_surface_cases,
    b2_fit => b2_fit_cases,
    bezier_remodel => bezier_remodel_cases,
    bezier_surface => bezier_surface_cases,
    bspline_to_bezier => bspline_to_bezier_cases,
    knot_modified_curve => knot_modified_curve_cases,
    knot_modified_surface => knot_modified_surface_cases,
    networks => networks_cases,
    free_data_networks => free_data_networks_cases,
    criss_cross_basis => criss_cross_basis_cases,
    mesh_from_grid => mesh_from_grid_cases,
    quasi_cubic => quasi_cubic_cases,
    quasi_cubic_surfaces => quasi_cubic_surfaces_cases,
    gordon_and_blended => gordon_and_blended_cases,
}

/// The generic sampler's limits hold (a sanity check that the fuzz targets above cannot ask for absurd work).
#[test]
fn eval_count_limit() {
    assert!(sample::check_eval_count("samples", sample::MAX_EVAL_POINTS).is_ok());
    assert!(sample::check_eval_count("samples", sample::MAX_EVAL_POINTS + 1).is_err());
}
