//! The steps exposed for the algorithm steppers of the demos, checked with numbers: de Boor's triangle
//! (`BSplineCurve::de_boor_triangle`), Boehm's knot insertion with its coefficients
//! (`BSplineCurve::insert_knot_steps`), de Casteljau's triangle (`BezierSpline::de_casteljau`) and the
//! B2-spline built with eq. (5) as printed (`B2Curve::new_with_eq5`).

use glam::DVec2;
use splinelab::b2spline::{joint_weights, B2Curve, B2Options, Eq5};
use splinelab::bezier::BezierSpline;
use splinelab::bspline::BSplineCurve;
use splinelab::{Curve, ErrorKind};

fn pts(xy: &[(f64, f64)]) -> Vec<DVec2> {
    xy.iter().map(|&(x, y)| DVec2::new(x, y)).collect()
}

/// The demo's default B-spline: degree 3, 7 points, knots 0,0,0,0,¼,½,¾,1,1,1,1 — plus a non-uniform one.
fn curves() -> Vec<BSplineCurve<DVec2>> {
    let p = pts(&[
        (0.0, 0.0),
        (1.0, 2.2),
        (2.4, 2.6),
        (3.4, 0.6),
        (4.6, 0.2),
        (5.4, 2.4),
        (6.6, 1.8),
    ]);
    vec![
        BSplineCurve::new(
            3,
            vec![0., 0., 0., 0., 0.25, 0.5, 0.75, 1., 1., 1., 1.],
            p.clone(),
        )
        .unwrap(),
        BSplineCurve::new(
            2,
            vec![0., 0., 0., 0.1, 0.15, 0.6, 0.9, 1., 1., 1.],
            p.clone(),
        )
        .unwrap(),
        BSplineCurve::new(4, vec![0., 0., 0., 0., 0., 0.3, 0.7, 1., 1., 1., 1., 1.], p).unwrap(),
    ]
}

#[test]
fn de_boor_triangle_hand_computed_level_one() {
    // degree 3, u = 0.4 in span k = 4 ([0.25, 0.5)): level 0 = P1..P4, α_{i,1} = (u − t_i)/(t_{i+3} − t_i)
    let c = &curves()[0];
    let tri = c.de_boor_triangle(0.4).unwrap();
    assert_eq!(tri.span, 4);
    assert_eq!(tri.levels.len(), 4);
    assert_eq!(tri.levels[0], c.points()[1..=4].to_vec());
    // i = 2: (0.4 − 0)/(0.5 − 0) = 0.8; i = 3: (0.4 − 0)/(0.75 − 0) = 0.5333…; i = 4: (0.4 − 0.25)/(1 − 0.25) = 0.2
    let a = &tri.alphas[1];
    assert!(
        (a[0] - 0.8).abs() < 1e-15
            && (a[1] - 0.4 / 0.75).abs() < 1e-15
            && (a[2] - 0.2).abs() < 1e-15,
        "{a:?}"
    );
    // P^1_2 = 0.2·P1 + 0.8·P2 = (0.2 + 1.92, 0.44 + 2.08) = (2.12, 2.52)
    assert!(
        (tri.levels[1][0] - DVec2::new(2.12, 2.52)).length() < 1e-14,
        "{:?}",
        tri.levels[1][0]
    );
    assert_eq!(tri.first_index(0), 1);
    assert_eq!(tri.first_index(3), 4);
}

#[test]
fn de_boor_last_level_is_the_curve_point() {
    for c in curves() {
        for j in 0..=50 {
            let u = j as f64 / 50.0;
            let tri = c.de_boor_triangle(u).unwrap();
            let p = c.degree();
            for (r, l) in tri.levels.iter().enumerate() {
                assert_eq!(l.len(), p + 1 - r);
                assert_eq!(tri.alphas[r].len(), if r == 0 { 0 } else { p + 1 - r });
            }
            let e = (tri.point() - c.eval(u)).length();
            assert!(e < 1e-12, "degree {p}, u = {u}: |de Boor − eval| = {e}");
        }
    }
}

#[test]
fn de_boor_rejects_u_outside_the_domain() {
    let c = &curves()[0];
    for u in [-0.01, 1.5, f64::NAN] {
        let e = c.de_boor_triangle(u).unwrap_err();
        assert_eq!(e.kind(), ErrorKind::OutOfRange);
        assert_eq!(e.field(), "u");
    }
}

#[test]
fn knot_insertion_keeps_the_curve_and_matches_de_boor_level_one() {
    for c in curves() {
        let p = c.degree();
        for &u in &[0.05, 0.3, 0.5, 0.62, 0.99] {
            let ins = c.insert_knot_steps(u).unwrap();
            assert_eq!(ins.curve.points().len(), c.points().len() + 1);
            assert_eq!(ins.curve.knots().len(), c.knots().len() + 1);
            assert_eq!(ins.alphas.len(), p);
            assert_eq!(ins.first, ins.span + 1 - p);
            // the same curve, sampled densely
            for j in 0..=200 {
                let v = j as f64 / 200.0;
                let e = (ins.curve.eval(v) - c.eval(v)).length();
                assert!(e < 1e-12, "degree {p}, insert {u}, at {v}: {e}");
            }
            // Q_i = (1 − α_i)P_{i−1} + α_i P_i, and they are de Boor's first level at u
            let tri = c.de_boor_triangle(u).unwrap();
            for (j, &a) in ins.alphas.iter().enumerate() {
                let i = ins.first + j;
                let q = c.points()[i - 1] * (1.0 - a) + c.points()[i] * a;
                assert!((ins.curve.points()[i] - q).length() < 1e-14);
                assert!((tri.alphas[1][j] - a).abs() < 1e-15);
                assert!((tri.levels[1][j] - q).length() < 1e-14);
            }
            // the points before and after are kept
            assert_eq!(&ins.curve.points()[..ins.first], &c.points()[..ins.first]);
            assert_eq!(&ins.curve.points()[ins.span + 1..], &c.points()[ins.span..]);
        }
    }
    // hand value: degree 3, insert 0.4 (span 4): α_2 = 0.4/0.5 = 0.8, α_3 = 0.4/0.75, α_4 = 0.15/0.75 = 0.2
    let ins = curves()[0].insert_knot_steps(0.4).unwrap();
    assert_eq!((ins.span, ins.first), (4, 2));
    assert!((ins.alphas[0] - 0.8).abs() < 1e-15 && (ins.alphas[2] - 0.2).abs() < 1e-15);
    assert_eq!(curves()[0].insert_knot_steps(2.0).unwrap_err().field(), "u");
}

#[test]
fn de_casteljau_levels_and_point() {
    // the remodelling paper's quadratic example: b0..b10, breaks 0, 1, 7/4, 5/2, 13/4, 4
    let b = pts(&[
        (10., 16.),
        (7., 21.),
        (3., 9.),
        (0., 0.),
        (-4., 0.),
        (-8., 0.),
        (-6., 3.),
        (-4., 6.),
        (2., 2.),
        (8., -2.),
        (10., 3.),
    ]);
    let g = BezierSpline::new(2, vec![0., 1., 1.75, 2.5, 3.25, 4.], b).unwrap();
    // u = 1.375: segment 1 (b2, b3, b4), t = 0.5: level 1 = (1.5, 4.5), (−2, 0); point (−0.25, 2.25)
    let dc = g.de_casteljau(1.375).unwrap();
    assert_eq!(dc.segment, 1);
    assert!((dc.t - 0.5).abs() < 1e-15);
    assert!((dc.levels[1][0] - DVec2::new(1.5, 4.5)).length() < 1e-14);
    assert!((dc.levels[1][1] - DVec2::new(-2.0, 0.0)).length() < 1e-14);
    assert!((dc.point() - DVec2::new(-0.25, 2.25)).length() < 1e-14);
    for j in 0..=80 {
        let u = 4.0 * j as f64 / 80.0;
        let dc = g.de_casteljau(u).unwrap();
        assert_eq!(dc.levels.len(), 3);
        assert!((dc.point() - g.eval(u)).length() < 1e-12, "u = {u}");
    }
    // at an interior breakvalue: the right-hand segment at t = 0
    let dc = g.de_casteljau(1.75).unwrap();
    assert_eq!((dc.segment, dc.t), (2, 0.0));
    assert_eq!(g.de_casteljau(4.5).unwrap_err().field(), "u");
}

#[test]
fn eq5_as_printed_misses_the_joints_and_the_corrected_one_does_not() {
    let w = pts(&[
        (-1.0, -0.5),
        (0.0, 0.0),
        (0.3, 1.1),
        (1.6, 1.9),
        (2.0, 1.7),
        (4.5, 2.2),
        (5.0, 0.4),
        (5.6, -0.3),
        (7.9, 0.1),
        (8.3, 1.2),
    ]);
    let o = B2Options::default();
    let good = B2Curve::new_with_eq5(&w, &o, Eq5::Corrected).unwrap();
    let bad = B2Curve::new_with_eq5(&w, &o, Eq5::AsPrinted).unwrap();
    let rg = good.joint_residuals();
    let rb = bad.joint_residuals();
    assert_eq!(rg.len(), 6);
    assert!(rg.iter().all(|&r| r < 1e-12), "corrected: {rg:?}");
    let worst = rb.iter().cloned().fold(0.0, f64::max);
    assert!(worst > 1e-3, "printed: {rb:?}");
    // the printed weights: sum = 1 − b(b − c)/((b+c)(b+c+d)) at every joint (findings §2.1), ≠ 1 here
    let s = bad.scheme();
    let t = s.knots();
    for (i, wp) in s.eq5_weights_all().iter().enumerate() {
        let j = 2 * (i + 1) + 1;
        let (a, b, c, d) = (
            t[j - 1] - t[j - 2],
            t[j] - t[j - 1],
            t[j + 1] - t[j],
            t[j + 2] - t[j + 1],
        );
        let sum: f64 = wp.iter().sum();
        assert!((sum - (1.0 - b * (b - c) / ((b + c) * (b + c + d)))).abs() < 1e-14);
        let wc = joint_weights(a, b, c, d);
        assert_eq!(&good.scheme().eq5_weights_all()[i], &wc);
        assert!((wc.iter().sum::<f64>() - 1.0).abs() < 1e-14);
    }
    // uniform data: b = c at every joint, printed = corrected
    let u: Vec<DVec2> = (0..8)
        .map(|i| DVec2::new(i as f64, (i % 2) as f64))
        .collect();
    let ou = B2Options {
        knots: splinelab::b2spline::KnotChoice::Uniform,
        ..B2Options::default()
    };
    let r = B2Curve::new_with_eq5(&u, &ou, Eq5::AsPrinted)
        .unwrap()
        .joint_residuals();
    assert!(r.iter().all(|&x| x < 1e-12), "{r:?}");
    // the weights exposed for the stepper rebuild the joints and the even vertices
    let sch = good.scheme();
    for (i, jw) in sch.joint_weights_all().iter().enumerate() {
        let r = w[i + 1] * jw[0] + w[i + 2] * jw[1] + w[i + 3] * jw[2];
        assert!((r - good.joints()[i]).length() < 1e-14);
    }
    for (i, ew) in sch.even_weights().iter().enumerate() {
        let c = w[i] * ew[0] + w[i + 1] * ew[1] + w[i + 2] * ew[2] + w[i + 3] * ew[3];
        assert!((c - good.control_points()[2 * i]).length() < 1e-13);
        assert!((ew.iter().sum::<f64>() - 1.0).abs() < 1e-14);
    }
}
