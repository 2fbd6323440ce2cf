//! The measures of self-checking exercises (`splinelab::exercise`), against values known in closed form.

use glam::DVec2;
use splinelab::b2spline::{B2Curve, B2Options};
use splinelab::bspline::BSplineCurve;
use splinelab::exercise::{
    bezier_spline, bspline_piecewise, continuity_jumps, ellipse_deviation, envelope_point,
    fit_error, foot_point, max_distance, network_norm, PiecewiseCurve, Verdict,
};
use splinelab::knot_paths::KnotModifiedCurve;
use splinelab::network::examples;
use splinelab::quasi_cubic::presets;
use splinelab::{Curve, ErrorKind};

fn v(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// The parabola y = x² on [−1, 1] as one quadratic Bézier segment: b = (−1, 1), (0, −1), (1, 1).
fn parabola() -> PiecewiseCurve {
    PiecewiseCurve(
        bezier_spline(2, &[0.0, 1.0], &[v(-1.0, 1.0), v(0.0, -1.0), v(1.0, 1.0)]).unwrap(),
    )
}

#[test]
fn foot_points_on_a_parabola() {
    let c = parabola();
    // below the vertex: the foot point is the vertex, distance 0.5
    let (u, d) = foot_point(&c, v(0.0, -0.5));
    assert!((d - 0.5).abs() < 1e-12, "{d}");
    assert!((u - 0.5).abs() < 1e-9, "{u}");
    // inside the parabola at (0, 1): x² = 1/2 minimises x² + (x² − 1)², distance √3/2 (not the vertex's 1)
    let (_, d) = foot_point(&c, v(0.0, 1.0));
    assert!((d - 3f64.sqrt() / 2.0).abs() < 1e-12, "{d}");
    // a point on the curve
    let (_, d) = foot_point(&c, v(0.3, 0.09));
    assert!(d < 1e-12, "{d}");
    // beyond the end: the end point
    let (u, d) = foot_point(&c, v(2.0, 1.0));
    assert!(
        (d - 1.0).abs() < 1e-12 && (u - 1.0).abs() < 1e-12,
        "{u} {d}"
    );
}

#[test]
fn max_distance_names_the_worst_point() {
    let c = parabola();
    let r = max_distance(&c, &[v(0.5, 0.25), v(0.0, -0.5), v(-0.2, 0.04)]).unwrap();
    assert!((r.max - 0.5).abs() < 1e-12);
    assert_eq!(r.worst, 1);
    assert!(r.distances[0] < 1e-12 && r.distances[2] < 1e-12);
    let e = max_distance(&c, &[]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::TooFew);
    let e = max_distance(&c, &[v(f64::NAN, 0.0)]).unwrap_err();
    assert_eq!(e.field(), "data[0]");
}

#[test]
fn b2_curve_passes_through_its_data_only_when_interpolating() {
    let w = vec![
        v(-1.0, -0.5),
        v(0.0, 0.0),
        v(1.0, 2.0),
        v(2.5, 2.4),
        v(3.5, 0.5),
        v(5.0, 1.0),
        v(6.0, 2.5),
        v(7.0, 3.0),
    ];
    let data = &w[2..w.len() - 2]; // W_1..W_n (W_{−1}, W_0, W_{n+1}, W_{n+2} only shape the ends)
    let at = |a: f64| {
        let c = B2Curve::new(
            &w,
            &B2Options {
                a,
                ..B2Options::default()
            },
        )
        .unwrap();
        // through its cubic B-spline form, as the page passes it (knots + control points)
        let b = BSplineCurve::new(3, c.knots().to_vec(), c.control_points().to_vec()).unwrap();
        (
            max_distance(&c, data).unwrap().max,
            max_distance(&b, data).unwrap().max,
        )
    };
    let (d0, b0) = at(0.0);
    assert!(d0 < 1e-12 && b0 < 1e-12, "a = 0 interpolates: {d0} {b0}");
    let (d6, b6) = at(1.0 / 6.0);
    assert!(
        d6 > 0.05 && (d6 - b6).abs() < 1e-12,
        "a = 1/6 approximates: {d6} {b6}"
    );
}

#[test]
fn continuity_of_two_quadratic_beziers() {
    // breaks 0, 1, 3 (h0 = 1, h1 = 2); left derivative at the joint 2(b2 − b1)/1 = (2, 0); the right one
    // 2(b3 − b2)/2 = b3 − b2; b3 = b2 + (2, 0) makes it C¹
    let b = [
        v(0.0, 0.0),
        v(1.0, 1.0),
        v(2.0, 1.0),
        v(4.0, 1.0),
        v(5.0, 0.0),
    ];
    let c = bezier_spline(2, &[0.0, 1.0, 3.0], &b).unwrap();
    let j = continuity_jumps(&c, 1.0, 2).unwrap();
    assert!(
        j.absolute[0] < 1e-14 && j.absolute[1] < 1e-13,
        "{:?}",
        j.absolute
    );
    // second derivatives: left 2(b2 − 2b1 + b0)/1 = (0, −2); right 2(b4 − 2b3 + b2)/4 = (−0.5, −0.5)·... exact:
    let left = (b[2] - b[1] * 2.0 + b[0]) * 2.0;
    let right = (b[4] - b[3] * 2.0 + b[2]) * (2.0 / 4.0);
    assert!(
        (j.absolute[2] - left.distance(right)).abs() < 1e-12,
        "{:?}",
        j.absolute
    );
    assert!(
        (j.max_relative - left.distance(right) / left.length().max(right.length())).abs() < 1e-12
    );
    // a kink: move b3 up, the first derivative jumps by exactly that change / h1 · 2
    let mut kinked = b;
    kinked[3] = v(4.0, 1.4);
    let c = bezier_spline(2, &[0.0, 1.0, 3.0], &kinked).unwrap();
    let j = continuity_jumps(&c, 1.0, 1).unwrap();
    assert!((j.absolute[1] - 0.4).abs() < 1e-12, "{:?}", j.absolute);
    // not a joint
    assert_eq!(continuity_jumps(&c, 0.5, 1).unwrap_err().field(), "at");
    assert_eq!(
        bezier_spline(2, &[0.0, 1.0, 3.0], &b[..4])
            .unwrap_err()
            .kind(),
        ErrorKind::SizeMismatch
    );
}

#[test]
fn continuity_of_a_bspline_at_a_double_knot() {
    // cubic, knot 0.5 twice: C¹ there, the second derivative jumps; knot 0.25 simple: C²
    let pts = vec![
        v(0.0, 0.0),
        v(1.0, 2.0),
        v(2.0, 2.5),
        v(3.0, 0.5),
        v(4.0, 0.0),
        v(5.0, 2.0),
        v(6.0, 1.5),
    ];
    let knots = vec![0.0, 0.0, 0.0, 0.0, 0.25, 0.5, 0.5, 1.0, 1.0, 1.0, 1.0];
    let c = bspline_piecewise(3, knots, pts).unwrap();
    let j = continuity_jumps(&c, 0.5, 2).unwrap();
    assert!(
        j.relative[0] < 1e-13 && j.relative[1] < 1e-12,
        "{:?}",
        j.relative
    );
    assert!(j.relative[2] > 0.1, "{:?}", j.relative);
    let j = continuity_jumps(&c, 0.25, 2).unwrap();
    assert!(j.max_relative < 1e-11, "{:?}", j.relative);
}

#[test]
fn quasi_cubic_ellipse_only_at_alpha_one_and_a_parallelogram() {
    let b = presets::ellipse(v(0.0, 0.0), 2.0, 1.0);
    assert!(ellipse_deviation(&b, 1.0, 200).unwrap() < 1e-12);
    assert!(ellipse_deviation(&b, 0.5, 200).unwrap() > 1e-3);
    let mut moved = b.clone();
    moved[0] += v(0.3, 0.0);
    assert!(ellipse_deviation(&moved, 1.0, 200).unwrap() > 1e-3);
    // translating the whole polygon keeps the ellipse
    let shifted: Vec<DVec2> = b.iter().map(|p| *p + v(3.0, -1.0)).collect();
    assert!(ellipse_deviation(&shifted, 1.0, 200).unwrap() < 1e-12);
}

#[test]
fn s_equals_g_on_a_separable_network_only() {
    let sep = network_norm(&examples::separable(), "SG", 21, 1e-9).unwrap();
    assert!(sep < 1e-12, "{sep}");
    let dome = network_norm(&examples::uniform_dome(), "SG", 21, 1e-9).unwrap();
    assert!(dome > 1e-4, "{dome}");
    assert_eq!(
        network_norm(&examples::separable(), "SX", 21, 1e-9)
            .unwrap_err()
            .field(),
        "pair"
    );
}

#[test]
fn envelope_point_of_a_moved_knot() {
    let pts = vec![
        v(0.0, 0.0),
        v(1.0, 2.4),
        v(2.2, 2.8),
        v(3.2, 0.6),
        v(4.4, 0.2),
        v(5.4, 2.6),
        v(6.6, 2.4),
        v(7.4, 0.4),
    ];
    let knots = vec![0.0, 0.0, 0.0, 0.0, 1.0, 2.0, 3.0, 4.0, 5.0, 5.0, 5.0, 5.0];
    let p = 5; // the knot 2.0, between 1.0 and 3.0
    let c = KnotModifiedCurve::new(4, knots.clone(), pts.clone(), Some(p), 2.0).unwrap();
    let env = c.envelope().unwrap();
    let q = env.eval(2.4);
    let (touch, on) = envelope_point(4, knots.clone(), pts.clone(), p, 2.4, q).unwrap();
    assert!(touch < 1e-12 && on < 1e-9, "{touch} {on}");
    // the moved curve touches the envelope there: the curve a(·; 2.4) passes through e(2.4)
    let moved = c.with_up(2.4);
    let (_, d) = foot_point(&moved, q);
    assert!(d < 1e-9, "{d}");
    let (touch, _) = envelope_point(4, knots.clone(), pts.clone(), p, 2.0, q).unwrap();
    assert!(
        (touch - env.eval(2.0).distance(q)).abs() < 1e-15 && touch > 0.01,
        "{touch}"
    );
    assert_eq!(
        envelope_point(4, knots, pts, p, 2.4, v(f64::NAN, 0.0))
            .unwrap_err()
            .field(),
        "target"
    );
}

#[test]
fn fit_error_is_zero_for_a_line_and_grows_with_noise() {
    let line: Vec<DVec2> = (0..=20)
        .map(|i| v(i as f64 * 0.5, 0.3 * i as f64 * 0.5 + 1.0))
        .collect();
    let truth: Vec<DVec2> = (0..=1000)
        .map(|i| v(i as f64 * 0.01, 0.3 * i as f64 * 0.01 + 1.0))
        .collect();
    let opts = B2Options {
        a: 0.1,
        ..B2Options::default()
    };
    let (rms, max) = fit_error(&line, &opts, &truth, 400).unwrap();
    assert!(rms < 1e-12 && max < 1e-12, "{rms} {max}");
    let mut noisy = line.clone();
    for (i, p) in noisy.iter_mut().enumerate() {
        p.y += if i % 2 == 0 { 0.1 } else { -0.1 };
    }
    let (r0, _) = fit_error(&noisy, &B2Options::default(), &truth, 400).unwrap();
    let (r1, _) = fit_error(
        &noisy,
        &B2Options {
            a: 0.2,
            ..B2Options::default()
        },
        &truth,
        400,
    )
    .unwrap();
    assert!(r0 > 0.03 && r1 < r0, "{r0} {r1}");
}

#[test]
fn verdict_scores() {
    let v = Verdict::new(1e-3, 1e-3).unwrap();
    assert!(v.passed && v.score == 1.0);
    let v = Verdict::new(1e-2, 1e-3).unwrap();
    assert!(!v.passed && (v.score - 0.75).abs() < 1e-12);
    let v = Verdict::new(1e-1, 1e-3).unwrap();
    assert!((v.score - 0.5).abs() < 1e-12);
    assert_eq!(Verdict::new(10.0, 1e-3).unwrap().score, 0.0);
    assert!(!Verdict::new(f64::NAN, 1.0).unwrap().passed);
    assert_eq!(Verdict::new(1.0, -1.0).unwrap_err().field(), "tol");
}

// ---------------------------------------------------------------- Check::run (what exerciseCheck runs)

fn parabola_poly() -> splinelab::exercise::ExerciseCurve {
    splinelab::exercise::ExerciseCurve::Bezier(parabola().0)
}

#[test]
fn a_check_measures_compares_and_reports_what_it_found() {
    use splinelab::exercise::{Check, Measured};
    // the parabola y = x²: (0, −0.5) is 0.5 from the vertex, (0.5, 0.25) lies on it
    let check = Check::DataDistance {
        curve: parabola_poly(),
        data: vec![v(0.5, 0.25), v(0.0, -0.5)],
    };
    assert_eq!(check.name(), "dataDistance");
    let r = check.run(0.4).unwrap();
    assert!(
        (r.verdict.value - 0.5).abs() < 1e-12 && !r.verdict.passed,
        "{:?}",
        r.verdict
    );
    // 1.25 times the tolerance: 1 − log10(1.25)/4 = 0.976, clamped to 0.9 (a failed check never scores more)
    assert_eq!(r.verdict.score, 0.9);
    let Measured::DataDistance(d) = r.measured else {
        panic!("the distances")
    };
    assert_eq!(d.worst, 1);
    // the ellipse of a parallelogram at α = 1 is exact (the quasi-cubic paper, §4)
    let para = vec![v(0.0, -1.0), v(2.0, 0.0), v(0.0, 1.0), v(-2.0, 0.0)];
    let r = Check::Ellipse {
        points: para,
        alpha: 1.0,
        per_segment: 50,
    }
    .run(1e-12)
    .unwrap();
    assert!(
        r.verdict.passed && r.verdict.value < 1e-12,
        "{}",
        r.verdict.value
    );
    // the tolerance is judged after the measure, naming tol
    let e = Check::DataDistance {
        curve: parabola_poly(),
        data: vec![v(0.0, 0.0)],
    }
    .run(-1.0)
    .err()
    .unwrap();
    assert_eq!((e.field(), e.kind()), ("tol", ErrorKind::OutOfRange));
}

#[test]
fn a_check_refuses_a_curve_it_does_not_measure_naming_the_field() {
    use splinelab::exercise::{Check, ExerciseCurve, Truth};
    use splinelab::quasi_cubic::QuasiCubicCurve;
    let quad = || vec![v(0.0, 0.0), v(1.0, 1.0), v(2.0, 0.0), v(3.0, 1.0)];
    let quasi = ExerciseCurve::Quasi(QuasiCubicCurve::new(1.0, quad()).unwrap());
    let e = Check::Continuity {
        curve: quasi,
        at: 0.5,
        order: 1,
    }
    .run(1.0)
    .err()
    .unwrap();
    assert_eq!((e.field(), e.kind()), ("curve", ErrorKind::Invalid));
    let e = Check::EnvelopePoint {
        curve: parabola_poly(),
        p: 1,
        up: None,
        target: v(0.0, 0.0),
    }
    .run(1.0)
    .err()
    .unwrap();
    assert_eq!((e.field(), e.kind()), ("curve", ErrorKind::Invalid));
    // a knot index past the knots: at most their count
    let knots = vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0];
    let bs = BSplineCurve::new(
        2,
        knots,
        vec![v(0.0, 0.0), v(1.0, 1.0), v(2.0, 0.0), v(3.0, 1.0)],
    )
    .unwrap();
    let e = Check::EnvelopePoint {
        curve: ExerciseCurve::BSpline(bs),
        p: 9,
        up: None,
        target: v(0.0, 0.0),
    }
    .run(1.0)
    .err()
    .unwrap();
    assert_eq!((e.field(), e.kind()), ("p", ErrorKind::TooMany));
    assert_eq!(e.counts().map(|c| (c.expected, c.got)), Some((7, 9)));
    // the known curve: an unknown name, a polyline too long
    let data = || (0..5).map(|i| v(i as f64, 0.0)).collect::<Vec<_>>();
    let fit = |truth| Check::FitError {
        data: data(),
        options: B2Options::default(),
        truth,
        error_samples: 50,
    };
    let e = fit(Truth::Named("teapot".into())).run(1.0).err().unwrap();
    assert_eq!(e.field(), "truthCurve");
    let long = (0..100_001).map(|i| v(i as f64, 0.0)).collect();
    let e = fit(Truth::Polyline(long)).run(1.0).err().unwrap();
    assert_eq!((e.field(), e.kind()), ("truth", ErrorKind::TooMany));
}
