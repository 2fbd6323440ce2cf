//! The derivative / curvature / period contract of `Curve` and `Surface` (`src/sample.rs`): one curvature
//! formula for every curve type (signed in the plane, unsigned in 3D), from flat buffers the same as per
//! point, and the period of closed curves and periodic surface directions.

use glam::{DVec2, DVec3};
use splinelab::bspline::BSplineCurve;
use splinelab::quasi_cubic::{QuasiCubicCurve, QuasiCubicSurface};
use splinelab::sample::{curvatures, eval_curve, left_normals};
use splinelab::{Curve, Surface};

/// The parabola c(t) = (s·t, t²), t ∈ [0, 1], as a quadratic Bézier (B-spline on [0,0,0,1,1,1]).
fn parabola(s: f64) -> BSplineCurve<DVec2> {
    let pts = vec![DVec2::ZERO, DVec2::new(0.5 * s, 0.0), DVec2::new(s, 1.0)];
    BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0], pts).unwrap()
}

#[test]
fn curvature_of_a_parabola_signed_in_the_plane_unsigned_in_3d() {
    // c = (t, t²): κ = x′y″ − y′x″ / |c′|³ = 2 / (1 + 4t²)^{3/2}, turning left (positive).
    let c = parabola(1.0);
    let mirrored = parabola(-1.0);
    let pts3: Vec<DVec3> = [DVec2::ZERO, DVec2::new(0.5, 0.0), DVec2::new(1.0, 1.0)]
        .iter()
        .map(|p| DVec3::new(p.x, 0.0, p.y))
        .collect();
    let c3 = BSplineCurve::new(2, vec![0.0, 0.0, 0.0, 1.0, 1.0, 1.0], pts3).unwrap();
    for i in 0..=10 {
        let t = i as f64 / 10.0;
        let exact = 2.0 / (1.0 + 4.0 * t * t).powf(1.5);
        assert!((c.curvature(t) - exact).abs() < 1e-13, "t = {t}");
        assert!(
            (mirrored.curvature(t) + exact).abs() < 1e-13,
            "mirrored, t = {t}"
        );
        assert!((c3.curvature(t) - exact).abs() < 1e-13, "3D, t = {t}");
    }
}

#[test]
fn curvatures_from_buffers_equal_the_per_point_curvature() {
    let c = parabola(1.0);
    let params: Vec<f64> = (0..=20).map(|i| i as f64 / 20.0).collect();
    let (_, d1, d2) = eval_curve(&c, &params, 2);
    let kappa = curvatures::<DVec2>(&d1, &d2);
    let normals = left_normals(&d1);
    for (i, &t) in params.iter().enumerate() {
        assert!((kappa[i] - c.curvature(t)).abs() < 1e-13);
        // the left normal of (1, 2t) is (−2t, 1)/|·|
        let s = (1.0 + 4.0 * t * t).sqrt();
        assert!((normals[2 * i] + 2.0 * t / s).abs() < 1e-15);
        assert!((normals[2 * i + 1] - 1.0 / s).abs() < 1e-15);
    }
}

#[test]
fn closed_curves_and_periodic_surfaces_state_their_period() {
    let poly: Vec<DVec2> = (0..5)
        .map(|i| {
            let a = i as f64 * 1.3;
            DVec2::new(a.cos() * (1.0 + 0.1 * i as f64), a.sin())
        })
        .collect();
    let open = QuasiCubicCurve::new(1.0, poly.clone()).unwrap();
    assert_eq!(open.period(), None);
    let closed = QuasiCubicCurve::closed(1.0, poly).unwrap();
    let t = closed.period().expect("a closed curve has a period");
    assert_eq!(t, 5.0);
    let (a, b) = closed.domain();
    assert_eq!(b - a, t);
    // c, c′, c″ repeat after one period
    let (mut x, mut y) = ([DVec2::ZERO; 3], [DVec2::ZERO; 3]);
    closed.eval_derivs(a, 2, &mut x);
    closed.eval_derivs(a + t, 2, &mut y);
    for k in 0..3 {
        assert!((x[k] - y[k]).abs().max_element() < 1e-12, "derivative {k}");
    }
    assert!((closed.curvature(0.3) - closed.curvature(0.3 + t)).abs() < 1e-12);

    let grid: Vec<DVec3> = (0..4 * 5)
        .map(|k| DVec3::new((k / 5) as f64, (k % 5) as f64, ((k * 7) % 3) as f64))
        .collect();
    let s = QuasiCubicSurface::new(1.0, 4, 5, grid.clone(), (true, false)).unwrap();
    assert_eq!(s.periods(), (Some(4.0), None));
    let ((u0, u1), _) = s.domain();
    assert!((s.eval(u0, 0.7) - s.eval(u1, 0.7)).abs().max_element() < 1e-12);
    let s = QuasiCubicSurface::new(1.0, 4, 5, grid, (false, false)).unwrap();
    assert_eq!(s.periods(), (None, None));
}
