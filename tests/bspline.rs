//! The B-spline kernel: basis properties, derivatives, de Boor, knot insertion, interpolation, errors.

use glam::{DVec2, DVec3};
use splinelab::bspline::{basis_all, interpolate, interpolate_chord, BSplineCurve, BSplineSurface};
use splinelab::knots;
use splinelab::sample::{Curve, Surface};
use splinelab::ErrorKind;

/// A small deterministic generator for test data.
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

fn knot_vectors() -> Vec<(usize, Vec<f64>)> {
    vec![
        (1, vec![0.0, 0.0, 0.5, 1.0, 1.0]),
        (2, vec![0.0, 0.0, 0.0, 0.3, 0.3, 0.8, 1.0, 1.0, 1.0]),
        (
            3,
            vec![0.0, 0.0, 0.0, 0.0, 0.1, 0.45, 0.5, 0.9, 1.0, 1.0, 1.0, 1.0],
        ),
        (3, vec![-2.0, -1.0, 0.0, 1.5, 2.0, 4.0, 5.0, 7.0, 8.0]), // unclamped
        (
            4,
            vec![
                0.0, 0.0, 0.0, 0.0, 0.0, 0.2, 0.2, 0.6, 1.0, 1.0, 1.0, 1.0, 1.0,
            ],
        ),
    ]
}

fn params_in(k: &[f64], p: usize, count: usize) -> Vec<f64> {
    let (a, b) = (k[p], k[k.len() - p - 1]);
    (0..=count)
        .map(|i| a + (b - a) * i as f64 / count as f64)
        .collect()
}

#[test]
fn basis_is_a_nonnegative_partition_of_unity() {
    let mut rows = [Vec::new(), Vec::new(), Vec::new()];
    for (p, k) in knot_vectors() {
        for u in params_in(&k, p, 97) {
            basis_all(&k, p, u, 2, &mut rows);
            let s: f64 = rows[0].iter().sum();
            assert!((s - 1.0).abs() < 1e-14, "sum {s} at u = {u}, p = {p}");
            assert!(rows[0].iter().all(|&x| x >= 0.0));
            // derivatives of a partition of unity sum to zero
            assert!(rows[1].iter().sum::<f64>().abs() < 1e-10);
            assert!(rows[2].iter().sum::<f64>().abs() < 1e-8);
            // at most p + 1 non-zero
            assert!(rows[0].iter().filter(|&&x| x != 0.0).count() <= p + 1);
        }
    }
}

#[test]
fn basis_derivatives_match_finite_differences() {
    let mut r0 = [Vec::new(), Vec::new(), Vec::new()];
    let mut rp = [Vec::new(), Vec::new(), Vec::new()];
    let mut rm = [Vec::new(), Vec::new(), Vec::new()];
    let h = 1e-6;
    for (p, k) in knot_vectors() {
        for u in params_in(&k, p, 41) {
            // stay away from knots (derivatives jump there)
            if k.iter().any(|t| (t - u).abs() < 1e-4) {
                continue;
            }
            basis_all(&k, p, u, 2, &mut r0);
            basis_all(&k, p, u + h, 2, &mut rp);
            basis_all(&k, p, u - h, 2, &mut rm);
            for i in 0..r0[0].len() {
                let fd1 = (rp[0][i] - rm[0][i]) / (2.0 * h);
                let fd2 = (rp[1][i] - rm[1][i]) / (2.0 * h);
                assert!(
                    (fd1 - r0[1][i]).abs() < 1e-6 * (1.0 + r0[1][i].abs()),
                    "d1 N_{i},{p}({u})"
                );
                assert!(
                    (fd2 - r0[2][i]).abs() < 1e-4 * (1.0 + r0[2][i].abs()),
                    "d2 N_{i},{p}({u})"
                );
            }
        }
    }
}

fn random_curve(p: usize, k: &[f64], seed: u64) -> BSplineCurve<DVec2> {
    let mut g = Lcg(seed);
    let n = k.len() - p - 1;
    let pts = (0..n)
        .map(|_| DVec2::new(g.next() * 10.0 - 5.0, g.next() * 10.0 - 5.0))
        .collect();
    BSplineCurve::new(p, k.to_vec(), pts).unwrap()
}

#[test]
fn de_boor_equals_basis_sum() {
    for (s, (p, k)) in knot_vectors().into_iter().enumerate() {
        let c = random_curve(p, &k, s as u64 + 1);
        for u in params_in(&k, p, 123) {
            let a = c.eval(u);
            let b = c.de_boor(u);
            assert!((a - b).length() < 1e-13, "p = {p}, u = {u}: {a:?} vs {b:?}");
        }
    }
}

#[test]
fn curve_derivatives_match_finite_differences() {
    let (p, k) = (3, knot_vectors()[2].1.clone());
    let c = random_curve(p, &k, 7);
    let h = 1e-6;
    for u in [0.05, 0.3, 0.47, 0.7, 0.95] {
        let mut o = [DVec2::ZERO; 3];
        c.eval_derivs(u, 2, &mut o);
        let fd1 = (c.eval(u + h) - c.eval(u - h)) / (2.0 * h);
        let fd2 = (c.eval(u + h) - 2.0 * c.eval(u) + c.eval(u - h)) / (h * h);
        assert!((fd1 - o[1]).length() < 1e-5 * (1.0 + o[1].length()));
        assert!((fd2 - o[2]).length() < 1e-2 * (1.0 + o[2].length()));
    }
}

#[test]
fn end_and_knot_conventions() {
    // clamped: the curve starts and ends at the end control points; at the last knot the last piece is used
    let (p, k) = (3, knot_vectors()[2].1.clone());
    let c = random_curve(p, &k, 3);
    assert!((c.eval(0.0) - c.points()[0]).length() < 1e-15);
    assert!((c.eval(1.0) - *c.points().last().unwrap()).length() < 1e-14);
    // right-hand piece at an interior knot: the second derivative of a C¹ quadratic jumps at 0.3 (double knot)
    let q = random_curve(2, &knot_vectors()[1].1, 5);
    let mut right = [DVec2::ZERO; 3];
    let mut just_right = [DVec2::ZERO; 3];
    q.eval_derivs(0.3, 1, &mut right);
    q.eval_derivs(0.3 + 1e-12, 1, &mut just_right);
    assert!((right[1] - just_right[1]).length() < 1e-6 * (1.0 + right[1].length()));
}

#[test]
fn knot_insertion_leaves_the_curve_unchanged() {
    for (s, (p, k)) in knot_vectors().into_iter().enumerate() {
        let c = random_curve(p, &k, 11 + s as u64);
        let (a, b) = c.domain();
        let extra = [
            a + 0.31 * (b - a),
            a + 0.31 * (b - a),
            a + 0.77 * (b - a),
            b,
        ];
        let r = c.refine(&extra).unwrap();
        assert_eq!(r.points().len(), c.points().len() + extra.len());
        for u in params_in(&k, p, 71) {
            assert!((r.eval(u) - c.eval(u)).length() < 1e-12, "p = {p}, u = {u}");
        }
    }
}

#[test]
fn surface_refinement_and_derivatives() {
    let ku = vec![0.0, 0.0, 0.0, 0.4, 1.0, 1.0, 1.0];
    let kv = vec![0.0, 0.0, 0.0, 0.0, 0.5, 1.0, 1.0, 1.0, 1.0];
    let mut g = Lcg(99);
    let pts: Vec<DVec3> = (0..4 * 5)
        .map(|_| DVec3::new(g.next(), g.next(), g.next()))
        .collect();
    let s = BSplineSurface::new(2, 3, ku, kv, 4, 5, pts).unwrap();
    let r = s.refine(&[0.2, 0.7], &[0.25]).unwrap();
    assert_eq!(r.size(), (6, 6));
    let h = 1e-6;
    for &(u, v) in &[(0.1, 0.2), (0.5, 0.5), (0.9, 0.77), (1.0, 1.0)] {
        assert!((r.eval(u, v) - s.eval(u, v)).length() < 1e-13);
        if u < 1.0 {
            let mut o = [DVec3::ZERO; 3];
            s.eval_derivs(u, v, true, &mut o);
            let fu = (s.eval(u + h, v) - s.eval(u - h, v)) / (2.0 * h);
            let fv = (s.eval(u, v + h) - s.eval(u, v - h)) / (2.0 * h);
            assert!((fu - o[1]).length() < 1e-6 && (fv - o[2]).length() < 1e-6);
        }
    }
}

#[test]
fn interpolation_passes_through_the_data() {
    let data: Vec<DVec2> = (0..9)
        .map(|i| DVec2::new(i as f64, ((i * i) as f64 * 0.7).sin()))
        .collect();
    for p in 1..=4 {
        let c = interpolate_chord(p, &data).unwrap();
        let t = knots::chord_length_params("points", &data).unwrap();
        for (ti, d) in t.iter().zip(&data) {
            assert!((c.eval(*ti) - *d).length() < 1e-12, "p = {p}");
        }
    }
    // explicit parameters and knots: the quadratic through 3 points on [0, 1]
    let c = interpolate(
        2,
        &[0.0, 0.0, 0.0, 1.0, 1.0, 1.0],
        &[0.0, 0.5, 1.0],
        &[0.0, 1.0, 0.0],
    )
    .unwrap();
    assert!((c[1] - 2.0).abs() < 1e-14); // middle control point of the parabola 4u(1−u)
}

#[test]
fn errors_name_the_bad_input() {
    let pts = vec![DVec2::ZERO, DVec2::X, DVec2::Y];
    let e = BSplineCurve::new(3, vec![0.0; 7], pts.clone()).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::TooFew, "points"));
    let e = BSplineCurve::new(1, vec![0.0, 0.0, 0.7, 0.5, 1.0], pts.clone()).unwrap_err();
    assert_eq!(
        (e.kind(), e.field()),
        (ErrorKind::NotIncreasing, "knots[3]")
    );
    let e = BSplineCurve::new(1, vec![0.0, 0.0, f64::NAN, 1.0, 1.0], pts.clone()).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::NotFinite, "knots[2]"));
    let e = BSplineCurve::new(
        1,
        vec![0.0, 0.0, 0.5, 1.0, 1.0],
        vec![DVec2::ZERO, DVec2::NAN, DVec2::X],
    )
    .unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::NotFinite, "points[1]"));
    let e = BSplineCurve::new(1, vec![0.0, 0.5, 1.0], pts.clone()).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::SizeMismatch);
    let e = interpolate_chord(2, &[DVec2::ZERO, DVec2::X, DVec2::X]).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::Degenerate, "points[2]"));
    let e = splinelab::knots::insert_knot(1, &[0.0, 0.0, 0.5, 1.0, 1.0], &pts, 2.0).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::OutOfRange);
}

#[test]
fn uniform_fast_sampling_agrees_with_evaluation() {
    for (s, (p, k)) in knot_vectors().into_iter().enumerate() {
        let c = random_curve(p, &k, 21 + s as u64);
        for count in [1usize, 2, 7, 1000] {
            let mut fast = vec![0.0; 2 * count];
            c.sample_uniform_into(count, &mut fast);
            let (a, b) = c.domain();
            let params = splinelab::sample::uniform_params(a, b, count);
            for (i, &u) in params.iter().enumerate() {
                let e = c.eval(u);
                let f = DVec2::new(fast[2 * i], fast[2 * i + 1]);
                assert!(
                    (e - f).length() < 1e-12 * (1.0 + e.length()),
                    "p = {p}, count = {count}, u = {u}: {e:?} vs {f:?}"
                );
            }
        }
    }
}

/// Regression (found by tests/fuzz_core.rs): very unevenly spaced data made the collocation system so
/// ill-conditioned that the plain solve missed the data by 6e-6 relative. Now the result passes through the
/// data to 1e-9 relative or the call returns a `Degenerate` error.
#[test]
fn ill_conditioned_interpolation_is_refined_or_rejected() {
    let data = [
        DVec2::new(-5.071822008197138, 0.0),
        DVec2::new(0.0, 0.0),
        DVec2::new(-8.084070113349163, 0.0),
        DVec2::new(0.0, 0.0),
        DVec2::new(-13233070.355722087, 1.0),
        DVec2::new(2.1665777772915847e-9, 0.0),
        DVec2::new(3.0, 1.0),
    ];
    match interpolate_chord(4, &data) {
        Ok(c) => {
            let t = knots::chord_length_params("points", &data).unwrap();
            for (ti, d) in t.iter().zip(&data) {
                assert!((c.eval(*ti) - *d).abs().max_element() <= 1e-9 * 13233070.4);
            }
        }
        Err(e) => assert_eq!(e.kind(), ErrorKind::Degenerate),
    }
}
