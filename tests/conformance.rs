//! One conformance check for every construction (issue 15): each curve and surface type of the core, built
//! on a small example, goes through the same harness:
//!
//! * **domain**: finite, non-empty;
//! * **finite output**: points and derivatives finite on a sample grid of the domain;
//! * **interpolation where claimed**: the points the construction promises to pass through;
//! * **derivatives**: the analytic first (and, for curves, second) derivatives against central differences
//!   at points away from the joints;
//! * **continuity at joints**: one-sided derivatives (just left of a joint vs at it, the right-hand piece)
//!   agree up to the claimed order (C^k for curves; C¹ across the grid lines for surfaces).
//!
//! Adding a construction = adding one entry to [`curves`] or [`surfaces`] with its claims.
//!   cargo test --test conformance

use glam::{DVec2, DVec3};
use splinelab::b2spline::{B2Curve, B2Options};
use splinelab::bezier::{AlphaTable, BezierSpline, Remodelling};
use splinelab::bspline::BSplineCurve;
use splinelab::criss_cross::CrissCrossSurface;
use splinelab::gordon::GordonSurface;
use splinelab::knot_paths::KnotModifiedSurface;
use splinelab::network::{examples, Network};
use splinelab::quasi_cubic::{Bis, QuasiCubicCurve};
use splinelab::thin_plate::ThinPlateSurface;
use splinelab::{Curve, Surface};

/// A curve and what it claims.
struct CurveCase {
    name: &'static str,
    curve: Box<dyn Curve<DVec2>>,
    /// (u, point) pairs the curve passes through.
    interpolates: Vec<(f64, DVec2)>,
    /// Parameters of the joints (breakpoints, interior knots) inside the domain.
    joints: Vec<f64>,
    /// C^k at every joint (k ≤ 2).
    smoothness: usize,
}

/// A surface and what it claims.
struct SurfaceCase {
    name: &'static str,
    surface: Box<dyn Surface<DVec3>>,
    /// ((u, v), point) pairs the surface passes through.
    interpolates: Vec<((f64, f64), DVec3)>,
    /// Grid lines u = const (v = const) across which the surface is claimed C¹.
    lines_u: Vec<f64>,
    lines_v: Vec<f64>,
}

// ------------------------------------------------------------------------------------------- the cases

fn wave(n: usize) -> Vec<DVec2> {
    (0..n)
        .map(|i| {
            DVec2::new(
                i as f64 + 0.1 * (i * i) as f64,
                (i as f64 * 1.3).sin() * 2.0,
            )
        })
        .collect()
}

fn interior(knots: &[f64], (a, b): (f64, f64)) -> Vec<f64> {
    let mut j: Vec<f64> = knots.iter().copied().filter(|&t| t > a && t < b).collect();
    j.dedup();
    j
}

fn curves() -> Vec<CurveCase> {
    let mut out = Vec::new();

    // B-spline: clamped cubic, simple interior knots → C², through its end control points
    let pts = wave(6);
    let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 2.5, 3.0, 3.0, 3.0, 3.0];
    let c = BSplineCurve::new(3, knots.clone(), pts.clone()).unwrap();
    out.push(CurveCase {
        name: "BSplineCurve (cubic, clamped)",
        interpolates: vec![(0.0, pts[0]), (3.0, pts[5])],
        joints: interior(&knots, (0.0, 3.0)),
        smoothness: 2,
        curve: Box::new(c),
    });

    // B2-spline, a = 0: interpolates W_1..W_n at their knots; a cubic B-spline on simple knots → C²
    let w = wave(8);
    let c = B2Curve::new(&w, &B2Options::default()).unwrap();
    let u = c.data_knots().to_vec();
    let n = c.n();
    let dom = c.domain();
    out.push(CurveCase {
        name: "B2Curve (a = 0)",
        interpolates: (1..=n).map(|i| (u[i + 1], w[i + 1])).collect(),
        joints: interior(c.knots(), dom),
        smoothness: 2,
        curve: Box::new(c),
    });
    // … and approximating (a = 1/6), still C²
    let opts = B2Options {
        a: 1.0 / 6.0,
        ..B2Options::default()
    };
    let c = B2Curve::new(&w, &opts).unwrap();
    let dom = c.domain();
    out.push(CurveCase {
        name: "B2Curve (a = 1/6)",
        interpolates: vec![],
        joints: interior(c.knots(), dom),
        smoothness: 2,
        curve: Box::new(c),
    });

    // quasi-cubic trigonometric B-spline: C² for every α, joints at the integers
    for alpha in [-1.0, 1.0, 2.5] {
        let c = QuasiCubicCurve::new(alpha, wave(7)).unwrap();
        out.push(CurveCase {
            name: "QuasiCubicCurve",
            interpolates: vec![],
            joints: (1..4).map(|j| j as f64).collect(),
            smoothness: 2,
            curve: Box::new(c),
        });
    }

    // blended interpolation spline: through b_j at u = j, C² for k = 3
    let p = wave(7);
    let c = Bis::new(p.clone(), Some(vec![1.0, 0.5, 0.0, 2.0, 1.0]), 3).unwrap();
    out.push(CurveCase {
        name: "Bis (k = 3)",
        interpolates: (0..=4).map(|j| (j as f64, p[j + 1])).collect(),
        joints: (1..4).map(|j| j as f64).collect(),
        smoothness: 2,
        curve: Box::new(c),
    });

    // Bézier spline: through b_{mI} at u_I; a general one is C⁰
    let b = wave(7);
    let breaks = vec![0.0, 1.0, 2.5];
    let g = BezierSpline::new(3, breaks.clone(), b.clone()).unwrap();
    out.push(CurveCase {
        name: "BezierSpline (C⁰)",
        interpolates: vec![(0.0, b[0]), (1.0, b[3]), (2.5, b[6])],
        joints: vec![1.0],
        smoothness: 0,
        curve: Box::new(g),
    });

    // remodelled Bézier spline: g* of a C² cubic spline with C¹ enforced keeps the junctions, is C¹
    let bs = BSplineCurve::new(3, knots, wave(6)).unwrap();
    let g = BezierSpline::from_bspline(&bs).unwrap();
    let segments = g.segments();
    let rows = (0..segments).map(|_| vec![0.6, 0.45, 0.3]).collect();
    let alphas = AlphaTable::new(3, segments, rows).unwrap();
    let junctions: Vec<(f64, DVec2)> = g.breaks().iter().map(|&u| (u, g.eval(u))).collect();
    let joints = interior(g.breaks(), g.domain());
    let r = Remodelling::new(g, alphas, Some(1)).unwrap();
    out.push(CurveCase {
        name: "Remodelling (r = 1)",
        interpolates: junctions,
        joints,
        smoothness: 1,
        curve: Box::new(r),
    });

    out
}

/// Points on every network curve: S(u_r, v) = φ_r(v), S(u, v_s) = ψ_s(u).
fn on_network(net: &Network) -> Vec<((f64, f64), DVec3)> {
    let mut pts = Vec::new();
    let (v0, v1) = (net.v[0], net.v[net.v.len() - 1]);
    let (u0, u1) = (net.u[0], net.u[net.u.len() - 1]);
    for t in [0.0, 0.13, 0.5, 0.77, 1.0] {
        let v = v0 + t * (v1 - v0);
        let u = u0 + t * (u1 - u0);
        for (r, &ur) in net.u.iter().enumerate() {
            pts.push(((ur, v), net.phi(r, v)[0]));
        }
        for (s, &vs) in net.v.iter().enumerate() {
            pts.push(((u, vs), net.psi(s, u)[0]));
        }
    }
    pts
}

fn surfaces() -> Vec<SurfaceCase> {
    let mut out = Vec::new();
    for net in [
        examples::uniform_dome(),
        examples::nonuniform_dome(),
        examples::three_sided(),
    ] {
        let inner_u = net.u[1..net.u.len() - 1].to_vec();
        let inner_v = net.v[1..net.v.len() - 1].to_vec();
        let case = |name: &'static str, surface: Box<dyn Surface<DVec3>>| SurfaceCase {
            name,
            surface,
            interpolates: on_network(&net),
            lines_u: inner_u.clone(),
            lines_v: inner_v.clone(),
        };
        out.push(case(
            "CrissCrossSurface",
            Box::new(CrissCrossSurface::new(&net).unwrap()),
        ));
        out.push(case(
            "GordonSurface",
            Box::new(GordonSurface::new(&net).unwrap()),
        ));
        out.push(case(
            "ThinPlateSurface",
            Box::new(ThinPlateSurface::new(&net).unwrap()),
        ));
    }

    // knot-modified surface: order 3 (biquadratic) on simple interior knots → C¹ across them, at the
    // original knot and with u_3 moved
    let knots = vec![0.0, 0.0, 0.0, 0.7, 1.2, 2.0, 2.0, 2.0];
    let pts: Vec<DVec3> = (0..25)
        .map(|i| DVec3::new((i / 5) as f64, (i % 5) as f64, ((i * 7) % 5) as f64 * 0.3))
        .collect();
    for moved in [None, Some((3, 0.9))] {
        let s = KnotModifiedSurface::new(
            3,
            3,
            knots.clone(),
            knots.clone(),
            5,
            5,
            pts.clone(),
            moved,
            None,
        )
        .unwrap();
        let lu = if moved.is_some() {
            vec![0.9, 1.2]
        } else {
            vec![0.7, 1.2]
        };
        out.push(SurfaceCase {
            name: "KnotModifiedSurface",
            surface: Box::new(s),
            interpolates: vec![],
            lines_u: lu,
            lines_v: vec![0.7, 1.2],
        });
    }
    out
}

// -------------------------------------------------------------------------------------------- the harness

fn check_curve(case: &CurveCase) -> Result<(), String> {
    let c = &*case.curve;
    let name = case.name;
    let (a, b) = c.domain();
    if !(a.is_finite() && b.is_finite() && a < b) {
        return Err(format!("{name}: domain ({a}, {b})"));
    }
    let d = |u: f64| {
        let mut o = [DVec2::ZERO; 3];
        c.eval_derivs(u, 2, &mut o);
        o
    };
    // finite output, and the scale of the curve for tolerances
    let mut scale: f64 = 1.0;
    for i in 0..=200 {
        let u = a + (b - a) * i as f64 / 200.0;
        let o = d(u);
        if !o.iter().all(|p| p.is_finite()) {
            return Err(format!("{name}: not finite at u = {u}: {o:?}"));
        }
        scale = scale.max(o[0].length());
    }
    // interpolation
    for &(u, p) in &case.interpolates {
        let e = (c.eval(u) - p).length();
        if e > 1e-10 * scale {
            return Err(format!("{name}: C({u}) misses {p} by {e:.2e}"));
        }
    }
    // derivatives against central differences, away from joints
    let h = 1e-5 * (b - a);
    for i in 0..23 {
        let u = a + (b - a) * (i as f64 + 0.37) / 23.0;
        if u - 2.0 * h < a
            || u + 2.0 * h > b
            || case.joints.iter().any(|&j| (u - j).abs() < 4.0 * h)
        {
            continue;
        }
        let (lo, mid, hi) = (d(u - h), d(u), d(u + h));
        for k in 1..=2 {
            let fd = (hi[k - 1] - lo[k - 1]) / (2.0 * h);
            let e = (fd - mid[k]).length();
            if e > 1e-5 * mid[k].length().max(scale) {
                return Err(format!(
                    "{name}: derivative {k} at u = {u}: {} vs central difference {fd} (error {e:.2e})",
                    mid[k]
                ));
            }
        }
    }
    // continuity at joints from one-sided derivatives
    let delta = 1e-9 * (b - a);
    for &j in &case.joints {
        let (left, right) = (d(j - delta), d(j));
        for k in 0..=case.smoothness {
            let e = (left[k] - right[k]).length();
            if e > 1e-5 * right[k].length().max(scale) {
                return Err(format!(
                    "{name}: not C{k} at u = {j}: left {} vs right {} (jump {e:.2e})",
                    left[k], right[k]
                ));
            }
        }
    }
    Ok(())
}

fn check_surface(case: &SurfaceCase) -> Result<(), String> {
    let s = &*case.surface;
    let name = case.name;
    let ((u0, u1), (v0, v1)) = s.domain();
    if !(u0.is_finite() && u1.is_finite() && v0.is_finite() && v1.is_finite() && u0 < u1 && v0 < v1)
    {
        return Err(format!("{name}: domain ({u0}, {u1}) × ({v0}, {v1})"));
    }
    let d = |u: f64, v: f64| {
        let mut o = [DVec3::ZERO; 3];
        s.eval_derivs(u, v, true, &mut o);
        o
    };
    let mut scale: f64 = 1.0;
    for i in 0..=30 {
        for j in 0..=30 {
            let (u, v) = (
                u0 + (u1 - u0) * i as f64 / 30.0,
                v0 + (v1 - v0) * j as f64 / 30.0,
            );
            let o = d(u, v);
            if !o.iter().all(|p| p.is_finite()) {
                return Err(format!("{name}: not finite at ({u}, {v}): {o:?}"));
            }
            scale = scale.max(o[0].length());
        }
    }
    for &((u, v), p) in &case.interpolates {
        let e = (s.eval(u, v) - p).length();
        if e > 1e-10 * scale {
            return Err(format!("{name}: S({u}, {v}) misses {p} by {e:.2e}"));
        }
    }
    let (hu, hv) = (1e-5 * (u1 - u0), 1e-5 * (v1 - v0));
    let near = |x: f64, lines: &[f64], h: f64| lines.iter().any(|&l| (x - l).abs() < 4.0 * h);
    for i in 0..9 {
        for j in 0..9 {
            let u = u0 + (u1 - u0) * (i as f64 + 0.41) / 9.0;
            let v = v0 + (v1 - v0) * (j as f64 + 0.29) / 9.0;
            if near(u, &case.lines_u, hu) || near(v, &case.lines_v, hv) {
                continue;
            }
            let mid = d(u, v);
            let fu = (s.eval(u + hu, v) - s.eval(u - hu, v)) / (2.0 * hu);
            let fv = (s.eval(u, v + hv) - s.eval(u, v - hv)) / (2.0 * hv);
            for (k, fd) in [(1, fu), (2, fv)] {
                let e = (fd - mid[k]).length();
                if e > 1e-4 * mid[k].length().max(scale) {
                    return Err(format!(
                        "{name}: {} at ({u}, {v}): {} vs central difference {fd} (error {e:.2e})",
                        ["", "du", "dv"][k],
                        mid[k]
                    ));
                }
            }
        }
    }
    // C¹ across the grid lines: one-sided values and partials agree
    let (du, dv) = (1e-9 * (u1 - u0), 1e-9 * (v1 - v0));
    for t in [0.11, 0.5, 0.83] {
        let v = v0 + t * (v1 - v0);
        let u = u0 + t * (u1 - u0);
        let pairs = case
            .lines_u
            .iter()
            .map(|&l| ((l - du, v), (l, v)))
            .chain(case.lines_v.iter().map(|&l| ((u, l - dv), (u, l))));
        for ((ul, vl), (ur, vr)) in pairs {
            let (left, right) = (d(ul, vl), d(ur, vr));
            for k in 0..3 {
                let e = (left[k] - right[k]).length();
                if e > 1e-5 * right[k].length().max(scale) {
                    return Err(format!(
                        "{name}: not C¹ across ({ur}, {vr}): {} left {} vs right {} (jump {e:.2e})",
                        ["S", "du", "dv"][k],
                        left[k],
                        right[k]
                    ));
                }
            }
        }
    }
    Ok(())
}

#[test]
fn every_curve_conforms() {
    let cases = curves();
    assert!(cases.len() >= 9);
    let failures: Vec<String> = cases.iter().filter_map(|c| check_curve(c).err()).collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

#[test]
fn every_surface_conforms() {
    let cases = surfaces();
    assert!(cases.len() >= 11);
    let failures: Vec<String> = cases
        .iter()
        .filter_map(|c| check_surface(c).err())
        .collect();
    assert!(failures.is_empty(), "{}", failures.join("\n"));
}

/// The harness can fail: a C⁰ Bézier spline claimed C¹, a curve claimed through a point it misses, and a
/// surface whose derivative is wrong are all caught.
#[test]
fn the_harness_catches_false_claims() {
    let b = wave(7);
    let g = BezierSpline::new(3, vec![0.0, 1.0, 2.5], b.clone()).unwrap();
    let c1 = CurveCase {
        name: "C⁰ claimed C¹",
        curve: Box::new(g.clone()),
        interpolates: vec![],
        joints: vec![1.0],
        smoothness: 1,
    };
    assert!(check_curve(&c1).unwrap_err().contains("not C1"));
    let miss = CurveCase {
        name: "misses",
        curve: Box::new(g),
        interpolates: vec![(0.5, b[1])],
        joints: vec![1.0],
        smoothness: 0,
    };
    assert!(check_curve(&miss).unwrap_err().contains("misses"));

    /// A surface whose du is off by a factor 2.
    struct WrongDu;
    impl Surface<DVec3> for WrongDu {
        fn domain(&self) -> ((f64, f64), (f64, f64)) {
            ((0.0, 1.0), (0.0, 1.0))
        }
        fn eval_derivs(&self, u: f64, v: f64, _derivs: bool, out: &mut [DVec3; 3]) {
            out[0] = DVec3::new(u, v, u * u + v);
            out[1] = DVec3::new(1.0, 0.0, 4.0 * u);
            out[2] = DVec3::new(0.0, 1.0, 1.0);
        }
    }
    let wrong = SurfaceCase {
        name: "wrong du",
        surface: Box::new(WrongDu),
        interpolates: vec![],
        lines_u: vec![],
        lines_v: vec![],
    };
    assert!(check_surface(&wrong).unwrap_err().contains("du"));
}
