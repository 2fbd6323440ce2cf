//! Native tests of the quasi-cubic paper (quasi-cubic trigonometric B-splines, BIS, surfaces): `curves.md` §4 items 1–8
//! with their tolerances, the exact quadric surfaces, and the bad-input errors.
#![allow(clippy::needless_range_loop)]

use glam::{DVec2, DVec3};
use splinelab::error::ErrorKind;
use splinelab::point::{cross2, signed_curvature};
use splinelab::quasi_cubic::bis::{circle_curvatures, circle_curvatures_signed, C0, C1};
use splinelab::quasi_cubic::presets::{self, check_shape, ExactShape};
use splinelab::quasi_cubic::*;
use splinelab::sample::{Curve, Surface};
use std::f64::consts::PI;

const ALPHAS: [f64; 5] = [-3.0, 0.0, 0.5, 1.0, 3.0];

fn ts(n: usize) -> Vec<f64> {
    (0..=n).map(|i| i as f64 / n as f64).collect()
}

fn v2(x: f64, y: f64) -> DVec2 {
    DVec2::new(x, y)
}

/// The 8 irregular points of the BIS tests (b₋₁..b₆, n = 5) and β* = (1, .3, 1.7, 0, 2, .8) (findings §1.2).
fn bis_data() -> Vec<DVec2> {
    vec![
        v2(0.0, 0.0),
        v2(1.0, 2.1),
        v2(2.7, 2.6),
        v2(3.4, 0.9),
        v2(5.2, 0.4),
        v2(6.1, 2.8),
        v2(8.0, 3.3),
        v2(9.5, 1.2),
    ]
}
const BIS_BETA: [f64; 6] = [1.0, 0.3, 1.7, 0.0, 2.0, 0.8];

// ---------------------------------------------------------------- item 1–3: the basis

#[test]
fn item1_partition_of_unity() {
    for &a in &ALPHAS {
        for t in ts(1000) {
            let b = basis(a, t);
            assert!((b.iter().sum::<f64>() - 1.0).abs() <= 1e-14, "α={a} t={t}");
            for k in 1..=3 {
                let d = basis_deriv(a, t, k);
                assert!(d.iter().sum::<f64>().abs() <= 1e-13, "α={a} t={t} k={k}");
            }
        }
    }
}

#[test]
fn item2_symmetry() {
    for &a in &ALPHAS {
        for t in ts(500) {
            let (b, r) = (basis(a, t), basis(a, 1.0 - t));
            for i in 0..4 {
                assert!((b[i] - r[3 - i]).abs() <= 1e-14, "α={a} t={t} i={i}");
            }
        }
    }
}

#[test]
fn item3_end_values_and_derivatives() {
    for &a in &ALPHAS {
        let [l1, l2, l3, l4] = end_constants(a);
        let tol = 1e-13;
        let close = |x: [f64; 4], y: [f64; 4], what: &str| {
            for i in 0..4 {
                assert!(
                    (x[i] - y[i]).abs() <= tol * y[i].abs().max(1.0),
                    "α={a} {what} i={i}: {x:?} vs {y:?}"
                );
            }
        };
        close(basis_deriv(a, 0.0, 0), [l1, l2, l1, 0.0], "B(0)");
        close(basis_deriv(a, 1.0, 0), [0.0, l1, l2, l1], "B(1)");
        close(basis_deriv(a, 0.0, 1), [-l3, 0.0, l3, 0.0], "B'(0)");
        close(basis_deriv(a, 1.0, 1), [0.0, -l3, 0.0, l3], "B'(1)");
        close(basis_deriv(a, 0.0, 2), [l4, -2.0 * l4, l4, 0.0], "B''(0)");
        close(basis_deriv(a, 1.0, 2), [0.0, l4, -2.0 * l4, l4], "B''(1)");
    }
    // α = 3 (Eq. (11)): B(0) = e₁, l3 = π/2 − 1, l4 = π²/4
    assert!((basis(3.0, 0.0)[1] - 1.0).abs() < 1e-15);
    let [_, _, l3, l4] = end_constants(3.0);
    assert!((l3 - (PI / 2.0 - 1.0)).abs() < 1e-15 && (l4 - PI * PI / 4.0).abs() < 1e-14);
    // … and on a curve: p′(j) = (π/2−1)(b_{j+1} − b_{j−1}), p″(j) = (π²/4)(b_{j−1} − 2b_j + b_{j+1})
    let b = bis_data();
    let c = QuasiCubicCurve::new(3.0, b.clone()).unwrap();
    let mut out = [DVec2::ZERO; 3];
    for j in 1..b.len() - 2 {
        c.eval_derivs(j as f64 - 1.0, 2, &mut out);
        assert!((out[0] - b[j]).length() <= 1e-13);
        assert!((out[1] - (b[j + 1] - b[j - 1]) * (PI / 2.0 - 1.0)).length() <= 1e-13 * 10.0);
        assert!(
            (out[2] - (b[j - 1] - b[j] * 2.0 + b[j + 1]) * (PI * PI / 4.0)).length()
                <= 1e-13 * 10.0
        );
    }
}

#[test]
fn derivatives_match_finite_differences() {
    // closed-form t-derivatives of every order against central differences of the order below
    let h = 1e-5;
    for &a in &[-3.0, 0.3, 1.0, 2.2, 3.0] {
        for t in [0.05, 0.3, 0.5, 0.77, 0.95] {
            for k in 1..=3 {
                let (p, m) = (basis_deriv(a, t + h, k - 1), basis_deriv(a, t - h, k - 1));
                let d = basis_deriv(a, t, k);
                for i in 0..4 {
                    let fd = (p[i] - m[i]) / (2.0 * h);
                    assert!(
                        (fd - d[i]).abs() < 1e-7 * d[i].abs().max(1.0),
                        "α={a} t={t} k={k}"
                    );
                }
            }
        }
    }
    // d/dα B = B¹ − B⁰ (Prop. 4: linear in α)
    for t in ts(20) {
        let (b0, b1, bm) = (basis(0.0, t), basis(1.0, t), basis(0.37, t));
        for i in 0..4 {
            assert!((bm[i] - (0.63 * b0[i] + 0.37 * b1[i])).abs() < 1e-15);
        }
    }
}

// ---------------------------------------------------------------- item 4: joints

fn joint_jumps<P: splinelab::Point>(c: &QuasiCubicCurve<P>) -> [f64; 4] {
    let mut jumps = [0.0; 4];
    let (mut l, mut r) = ([P::ZERO; 4], [P::ZERO; 4]);
    for i in 0..c.segments() - 1 {
        c.eval_segment(i, 1.0, 3, &mut l);
        c.eval_segment(i + 1, 0.0, 3, &mut r);
        for d in 0..4 {
            jumps[d] = f64::max(jumps[d], (l[d] - r[d]).max_abs());
        }
    }
    jumps
}

#[test]
fn item4_c2_joins_and_c3_only_at_alpha_1() {
    let pts: Vec<DVec2> = vec![
        v2(0.0, 0.0),
        v2(1.0, 3.0),
        v2(2.5, -1.0),
        v2(4.0, 2.0),
        v2(5.0, 5.0),
        v2(7.0, 1.0),
        v2(8.0, 0.5),
    ];
    for &a in &ALPHAS {
        let c = QuasiCubicCurve::new(a, pts.clone()).unwrap();
        let j = joint_jumps(&c);
        for d in 0..3 {
            assert!(j[d] <= 1e-12 * 10.0, "α={a} d={d} jump {}", j[d]);
        }
        if a != 1.0 {
            assert!(
                j[3] > 1.0,
                "α={a}: the C³ jump must be visible, got {}",
                j[3]
            );
        } else {
            assert!(j[3] <= 1e-12, "α=1 is C³, got {}", j[3]);
        }
    }
    // The d3 jump is (1−α)(π²/4)(−b_i + 2b_{i+2} − b_{i+4}): with |−b_i + 2b_{i+2} − b_{i+4}| = 4 it is
    // 9.87 (α=0), 4.93 (α=0.5), 0 (α=1), 19.7 (α=3) as in findings §1.1.
    let bump = vec![
        v2(0.0, 0.0),
        v2(1.0, 0.0),
        v2(2.0, 2.0),
        v2(3.0, 0.0),
        v2(4.0, 0.0),
    ];
    for (a, want) in [
        (0.0, PI * PI),
        (0.5, PI * PI / 2.0),
        (1.0, 0.0),
        (3.0, 2.0 * PI * PI),
    ] {
        let c = QuasiCubicCurve::new(a, bump.clone()).unwrap();
        let j = joint_jumps(&c);
        assert!((j[3] - want).abs() < 1e-12, "α={a}: {} vs {want}", j[3]);
    }
    // closed curves join C² at u = 0 ≡ N as well
    let sq = presets::ellipse(v2(0.3, -0.2), 2.0, 1.0);
    let c = QuasiCubicCurve::closed(0.4, sq).unwrap();
    let (mut l, mut r) = ([DVec2::ZERO; 4], [DVec2::ZERO; 4]);
    c.eval_segment(3, 1.0, 2, &mut l);
    c.eval_segment(0, 0.0, 2, &mut r);
    for d in 0..3 {
        assert!((l[d] - r[d]).length() < 1e-13, "closing join d={d}");
    }
    assert!((c.eval(4.0) - c.eval(0.0)).length() < 1e-14);
}

// ---------------------------------------------------------------- item 5: positivity

#[test]
fn item5_positivity_exactly_on_minus3_to_1() {
    for ai in 0..=40 {
        let a = -3.0 + 0.1 * ai as f64;
        for t in ts(2000) {
            for (i, b) in basis(a, t).iter().enumerate() {
                assert!(*b >= -1e-15, "α={a} t={t} B_{i}={b}");
            }
        }
    }
    let b = basis(-3.01, 0.0);
    assert!(
        (b[1] + 1.0 / 600.0).abs() < 1e-15,
        "B_1(0) at α=−3.01: {}",
        b[1]
    );
    // just above 1 it fails too (findings: −1.8e-9 at α = 1.01, near t = 0 on B_3)
    let min = ts(200_000)
        .into_iter()
        .map(|t| basis(1.01, t).into_iter().fold(f64::INFINITY, f64::min))
        .fold(f64::INFINITY, f64::min);
    assert!(
        min < -1e-10,
        "α=1.01 should be negative somewhere, min {min}"
    );
}

// ---------------------------------------------------------------- item 6: exact shapes

#[test]
fn item6_parabola() {
    // isosceles: apex (xa, ya) = b0 = b2, base b1, b3 on y = yb
    let (a, b1, b3) = (v2(1.0, 3.0), v2(-1.0, 0.5), v2(3.0, 0.5));
    let c = QuasiCubicCurve::new(1.0, presets::parabola(a, b1, b3)).unwrap();
    for t in ts(200) {
        let p = c.eval(t);
        let cc = (PI * t / 2.0).cos();
        let want = v2(
            (b1.x + b3.x) / 2.0 + (b1.x - b3.x) * cc / 3.0,
            (2.0 * a.y + b1.y) / 3.0 + (b1.y - a.y) * cc * cc / 3.0,
        );
        assert!((p - want).length() <= 1e-12, "t={t}");
    }
    let chk = check_shape(
        ExactShape::Parabola,
        1.0,
        &presets::parabola(a, b1, b3),
        100,
    )
    .unwrap();
    assert!(chk.deviation <= 1e-12 && chk.condition_residual == 0.0 && chk.alpha_ok);
    // the analytic overlay is the arc the curve covers (c = cos(πt/2) from 1 to 0), not a wider band: its ends
    // are the curve's ends, and it stays inside the curve's bounding box
    let ends = [c.eval(0.0), c.eval(1.0)];
    let (first, last) = (chk.analytic[0], *chk.analytic.last().unwrap());
    let near = |p: DVec2| {
        ends.iter()
            .map(|e| (p - *e).length())
            .fold(f64::INFINITY, f64::min)
    };
    assert!(
        near(first) <= 1e-12 && near(last) <= 1e-12,
        "overlay ends {first:?} {last:?} vs curve ends {ends:?}"
    );
    assert!(
        (first - last).length() > 1.0,
        "the overlay is an arc, not a point"
    );
    // a non-isosceles triangle is still a parabola (affine invariance), b0 ≠ b2 is not
    let chk = check_shape(
        ExactShape::Parabola,
        1.0,
        &[a, v2(-2.0, 0.0), a, v2(3.5, 1.0)],
        100,
    )
    .unwrap();
    assert!(chk.deviation <= 1e-12);
    let chk = check_shape(
        ExactShape::Parabola,
        1.0,
        &[a, b1, a + v2(0.3, 0.0), b3],
        100,
    )
    .unwrap();
    assert!(chk.deviation > 1e-3, "broken condition: {}", chk.deviation);
    let chk = check_shape(
        ExactShape::Parabola,
        0.5,
        &presets::parabola(a, b1, b3),
        100,
    )
    .unwrap();
    assert!(chk.deviation > 1e-3 && !chk.alpha_ok);
}

#[test]
fn item6_ellipse_and_circle() {
    let o = v2(0.5, -1.0);
    let (w, h) = (3.0, 1.2); // half-diagonals of the rhombus
    let rh = vec![
        o + v2(w, 0.0),
        o + v2(0.0, h),
        o + v2(-w, 0.0),
        o + v2(0.0, -h),
    ];
    // an open arc b_i..b_{i+3} of the rhombus (spec's symbolic form, up to the start vertex)
    let arc = QuasiCubicCurve::new(1.0, vec![rh[3], rh[0], rh[1], rh[2]]).unwrap();
    for t in ts(200) {
        let p = arc.eval(t);
        let want = v2(
            o.x + (2.0 * w / 3.0) * (PI * t / 2.0).cos(),
            o.y + (2.0 * h / 3.0) * (PI * t / 2.0).sin(),
        );
        assert!((p - want).length() <= 1e-12, "t={t}");
        let e =
            ((p.x - o.x) / (2.0 * w / 3.0)).powi(2) + ((p.y - o.y) / (2.0 * h / 3.0)).powi(2) - 1.0;
        assert!(e.abs() <= 1e-12);
    }
    // the closed curve is the whole ellipse
    let chk = check_shape(ExactShape::Ellipse, 1.0, &rh, 200).unwrap();
    assert!(chk.deviation <= 1e-12, "{}", chk.deviation);
    assert_eq!(chk.condition_residual, 0.0);
    let moved = vec![rh[0] + v2(0.4, 0.3), rh[1], rh[2], rh[3]];
    let chk = check_shape(ExactShape::Ellipse, 1.0, &moved, 200).unwrap();
    assert!(chk.deviation > 1e-3 && chk.condition_residual > 0.4);
    // square → circle of radius ⅔ of the half-diagonal
    let d = 2.25;
    let sq = presets::circle(o, 1.5);
    assert!((sq[0] - o).length() == d);
    let c = QuasiCubicCurve::closed(1.0, sq.clone()).unwrap();
    for u in ts(400).into_iter().map(|t| 4.0 * t) {
        assert!((c.eval(u).distance(o) - 2.0 * d / 3.0).abs() <= 1e-12);
    }
    // a rotated square too
    let rot: Vec<DVec2> = sq
        .iter()
        .map(|p| o + DVec2::from_angle(0.7).rotate(*p - o))
        .collect();
    let chk = check_shape(ExactShape::Circle, 1.0, &rot, 200).unwrap();
    assert!(chk.deviation <= 1e-12 && chk.condition_residual < 1e-14);
    let chk = check_shape(ExactShape::Circle, 0.0, &rot, 200).unwrap();
    assert!(chk.deviation > 1e-3);
}

#[test]
fn item6_sine() {
    // spec's condition x0+x3 = x1+x2, y0+y1 = y2+y3 on one segment
    let b = vec![v2(0.0, 1.0), v2(1.0, 3.0), v2(3.0, 0.5), v2(4.0, 3.5)];
    let c = QuasiCubicCurve::new(0.0, b.clone()).unwrap();
    let (x0, y0) = (c.eval(0.0).x, c.eval(0.0).y);
    for t in ts(200) {
        let p = c.eval(t);
        let amp = (b[1].y + b[2].y - b[0].y - b[3].y) / (4.0 * PI);
        assert!((p.x - (x0 + t * (b[2].x + b[3].x - b[0].x - b[1].x) / 4.0)).abs() <= 1e-12);
        assert!((p.y - (y0 + amp * (PI * t).sin())).abs() <= 1e-12, "t={t}");
    }
    let chk = check_shape(ExactShape::Sine, 0.0, &b, 200).unwrap();
    assert!(chk.deviation <= 1e-12 && chk.condition_residual == 0.0);
    // the zig-zag preset: one sine wave over all segments, y = (a/π) sin(πu)
    let z = presets::sine(-2.0, 0.5, 0.8, 6);
    let c = QuasiCubicCurve::new(0.0, z.clone()).unwrap();
    for u in ts(600).into_iter().map(|t| 6.0 * t) {
        let p = c.eval(u);
        assert!((p.x - (-2.0 + 0.5 * (u + 1.0))).abs() <= 1e-12);
        assert!((p.y - 0.8 / PI * (PI * u).sin()).abs() <= 1e-12, "u={u}");
    }
    let chk = check_shape(ExactShape::Sine, 0.0, &z, 100).unwrap();
    assert!(chk.deviation <= 1e-12 && chk.condition_residual <= 1e-15);
    let mut broken = z.clone();
    broken[3].y += 0.5;
    let chk = check_shape(ExactShape::Sine, 0.0, &broken, 100).unwrap();
    assert!(chk.deviation > 1e-3);
    // b_3 takes part in the y-relations of segments 0..=3 only (segments 4, 5 use b_4.. b_8)
    let ry: Vec<f64> = chk
        .segment_residuals
        .iter()
        .skip(1)
        .step_by(2)
        .copied()
        .collect();
    assert_eq!(ry.len(), 6);
    assert!(ry[..4].iter().all(|r| (r - 0.5).abs() < 1e-12), "{ry:?}");
    assert!(ry[4..].iter().all(|r| *r < 1e-12));
    broken[3].y += 0.5;
    assert!(
        check_shape(ExactShape::Sine, 0.0, &broken, 100)
            .unwrap()
            .deviation
            > 1e-3
    );
}

// ---------------------------------------------------------------- item 7: BIS

fn bis_jumps(c: &Bis<DVec2>) -> [f64; 3] {
    let mut jumps = [0.0; 3];
    let (mut l, mut r) = ([DVec2::ZERO; 3], [DVec2::ZERO; 3]);
    for g in 0..c.segments() - 1 {
        c.eval_segment(g, 1.0, 2, &mut l);
        c.eval_segment(g + 1, 0.0, 2, &mut r);
        for d in 0..3 {
            jumps[d] = f64::max(jumps[d], (l[d] - r[d]).length());
        }
    }
    jumps
}

#[test]
fn item7_bis() {
    let pts = bis_data();
    let n = pts.len() - 3;
    let spline = QuasiCubicCurve::new(3.0, pts.clone()).unwrap();
    for k in [3, 4] {
        let bis = Bis::new(pts.clone(), Some(BIS_BETA.to_vec()), k).unwrap();
        assert_eq!(bis.domain(), (0.0, n as f64));
        let mut o = [DVec2::ZERO; 3];
        let mut p = [DVec2::ZERO; 3];
        for j in 0..=n {
            bis.eval_derivs(j as f64, 2, &mut o);
            spline.eval_derivs(j as f64, 2, &mut p);
            let b = |i: isize| pts[(i + 1) as usize];
            let ji = j as isize;
            assert!((o[0] - b(ji)).length() <= 1e-12, "interpolation j={j}");
            assert!(
                (o[1] - p[1] * BIS_BETA[j]).length() <= 1e-12,
                "tangent j={j}"
            );
            assert!((o[1] - (b(ji + 1) - b(ji - 1)) * (C0 * BIS_BETA[j])).length() <= 1e-12);
            assert!(
                (o[2] - p[2] * BIS_BETA[j]).length() <= 1e-12 * 10.0,
                "BIS'' j={j}"
            );
        }
        let jm = bis_jumps(&bis);
        assert!(jm.iter().all(|x| *x <= 1e-12 * 10.0), "k={k} jumps {jm:?}");
    }
    // β* ≡ 1: the α = 3 spline
    let one = Bis::new(pts.clone(), None, 3).unwrap();
    for u in ts(500).into_iter().map(|t| n as f64 * t) {
        let mut a = [DVec2::ZERO; 3];
        let mut b = [DVec2::ZERO; 3];
        one.eval_derivs(u, 2, &mut a);
        spline.eval_derivs(u, 2, &mut b);
        for d in 0..3 {
            assert!((a[d] - b[d]).length() <= 1e-12, "u={u} d={d}");
        }
    }
    // k = 2: C¹ but not C² (the spec measures 15.0 on its data; ours gives the value below)
    let k2 = Bis::new(pts.clone(), Some(BIS_BETA.to_vec()), 2).unwrap();
    let jm = bis_jumps(&k2);
    assert!(jm[0] <= 1e-12 && jm[1] <= 1e-12 * 10.0);
    eprintln!("k = 2 second-derivative jump on our data: {}", jm[2]);
    assert!(jm[2] > 1.0, "k = 2 second-derivative jump {}", jm[2]);
    // allocated function: s(0)=0, s(1)=1, s^(l) vanish at the ends for l < k
    for k in 2..=6 {
        let (a0, a1) = (allocated(k, 0.0), allocated(k, 1.0));
        assert_eq!((a0[0], a1[0]), (0.0, 1.0));
        for l in 1..k.min(3) {
            assert!(a0[l].abs() < 1e-12 && a1[l].abs() < 1e-12, "k={k} l={l}");
        }
        let t = 0.37;
        let h = 1e-6;
        for l in 1..3 {
            let fd = (allocated(k, t + h)[l - 1] - allocated(k, t - h)[l - 1]) / (2.0 * h);
            assert!((fd - allocated(k, t)[l]).abs() < 1e-6, "k={k} l={l}");
        }
    }
    let s3 = allocated(3, 0.3);
    assert!((s3[0] - (10.0 * 0.027 - 15.0 * 0.0081 + 6.0 * 0.00243)).abs() < 1e-15);
}

#[test]
fn item7_bis_in_3d_and_remark2() {
    let pts: Vec<DVec3> = bis_data()
        .iter()
        .enumerate()
        .map(|(i, p)| p.extend(0.3 * i as f64))
        .collect();
    let bis = Bis::new(pts.clone(), Some(BIS_BETA.to_vec()), 3).unwrap();
    for j in 0..=5 {
        assert!((bis.eval(j as f64) - pts[j + 1]).length() < 1e-12);
    }
    // Remark 2 with α = 0.6: interpolates where β* = 0 only
    let r2 = bis.clone().with_alpha(0.6).unwrap();
    assert!((r2.eval(3.0) - pts[4]).length() < 1e-12); // β*_3 = 0
    assert!((r2.eval(2.0) - pts[3]).length() > 1e-3);
}

// ---------------------------------------------------------------- item 8: curvature matching

#[test]
fn item8_curvature_matching() {
    let pts = bis_data();
    let beta = beta_curvature(&pts).unwrap();
    let n = pts.len() - 3;
    assert_eq!(beta.len(), n + 1);
    let kk = circle_curvatures_signed(&pts);
    let ku = circle_curvatures(&pts);
    let bis = Bis::curvature_matched(pts.clone(), 3).unwrap();
    assert_eq!(bis.beta(), &beta[..]);
    let mut o = [DVec2::ZERO; 3];
    for j in 0..=n {
        // the closed form, written out independently
        let (a, b, c) = (pts[j], pts[j + 1], pts[j + 2]);
        let want = C1 / (C0 * C0) * (b - a).length() * (c - b).length() / (c - a).length_squared();
        assert!((beta[j] - want).abs() <= 1e-12 * want.max(1.0));
        bis.eval_derivs(j as f64, 2, &mut o);
        let kappa = signed_curvature(o[1], o[2]);
        assert!(
            (kappa - kk[j]).abs() <= 1e-12 * kk[j].abs().max(1.0),
            "j={j}: κ {kappa} vs K {}",
            kk[j]
        );
        assert!((kk[j].abs() - ku[j]).abs() < 1e-14);
        // K = 1/R with R the circumradius
        let area2 = cross2(b - a, c - a).abs();
        let r = (b - a).length() * (c - b).length() * (c - a).length() / (2.0 * area2);
        assert!((ku[j] - 1.0 / r).abs() < 1e-14);
    }
    assert!((C1 / (C0 * C0) - 7.5732).abs() < 1e-4);
    // straight, equally spaced: β* = c1/(4c0²) = 1.893
    let line: Vec<DVec2> = (0..6).map(|i| v2(i as f64, 0.0)).collect();
    for b in beta_curvature(&line).unwrap() {
        assert!((b - C1 / (4.0 * C0 * C0)).abs() < 1e-14);
    }
    // coincident neighbours make it undefined
    let e = beta_curvature(&[v2(0.0, 0.0), v2(1.0, 1.0), v2(0.0, 0.0), v2(2.0, 0.0)]).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::Degenerate);
    assert_eq!(e.field(), "points[2]");
}

// ---------------------------------------------------------------- surfaces

fn surf(net: &presets::SurfaceNet) -> QuasiCubicSurface<DVec3> {
    QuasiCubicSurface::new(
        net.alpha,
        net.rows,
        net.cols,
        net.grid.clone(),
        net.periodic,
    )
    .unwrap()
}

#[test]
fn sphere_cylinder_torus_are_exact() {
    let s = surf(&presets::sphere(1.7));
    assert_eq!(s.domain(), ((0.0, 4.0), (0.0, 2.0)));
    assert!(presets::max_radial_error(&s, DVec3::ZERO, 1.7, 81) <= 1e-12);
    // the poles and the equator
    assert!((s.eval(0.3, 0.0) - DVec3::new(0.0, 0.0, 1.7)).length() < 1e-12);
    assert!((s.eval(2.1, 2.0) - DVec3::new(0.0, 0.0, -1.7)).length() < 1e-12);
    // not exact at another α
    let mut off = presets::sphere(1.7);
    off.alpha = 0.5;
    assert!(presets::max_radial_error(&surf(&off), DVec3::ZERO, 1.7, 41) > 1e-3);

    let c = surf(&presets::cylinder(0.8, 3.0));
    assert!(presets::max_axis_error(&c, 0.8, 81) <= 1e-12);
    let t = surf(&presets::torus(2.0, 0.5));
    let uv = splinelab::sample::uv_grid(t.domain(), 61, 61);
    for w in uv.chunks_exact(2) {
        let p = t.eval(w[0], w[1]);
        let rho = p.x.hypot(p.y) - 2.0;
        assert!((rho.hypot(p.z) - 0.5).abs() <= 1e-12);
    }
    // the bowl starts on the axis with a horizontal tangent plane
    let b = surf(&presets::bowl());
    let mut o = [DVec3::ZERO; 3];
    b.eval_derivs(1.3, 0.0, true, &mut o);
    assert!(o[0].x.abs() < 1e-14 && o[0].y.abs() < 1e-14);
    assert!(o[2].z.abs() < 1e-14);
}

#[test]
fn surface_partials_and_c2() {
    let net = presets::wavy_grid(4, 3);
    for alpha in [0.0, 1.0, 3.0] {
        let s = QuasiCubicSurface::new(alpha, net.rows, net.cols, net.grid.clone(), (false, false))
            .unwrap();
        // Surface trait partials = partial()
        let mut o = [DVec3::ZERO; 3];
        s.eval_derivs(1.37, 2.2, true, &mut o);
        assert!((o[1] - s.partial(1.37, 2.2, 1, 0)).length() < 1e-14);
        assert!((o[2] - s.partial(1.37, 2.2, 0, 1)).length() < 1e-14);
        // C² across u joints, one-sided patch partials
        for i in 0..3 {
            for t in [0.0, 0.4, 1.0] {
                for (a, b) in [(0, 0), (1, 0), (2, 0), (1, 1), (0, 2), (2, 2)] {
                    let l = s.patch_partial(i, 1, 1.0, t, a, b);
                    let r = s.patch_partial(i + 1, 1, 0.0, t, a, b);
                    assert!((l - r).length() < 1e-12 * 10.0, "α={alpha} ({a},{b})");
                }
            }
        }
    }
    // α = 3 interpolates the grid: S(i, j) = grid[i+1][j+1]
    let s =
        QuasiCubicSurface::new(3.0, net.rows, net.cols, net.grid.clone(), (false, false)).unwrap();
    for i in 0..=4 {
        for j in 0..=3 {
            assert!(
                (s.eval(i as f64, j as f64) - net.grid[(i + 1) * net.cols + j + 1]).length()
                    < 1e-12
            );
        }
    }
}

#[test]
fn bis_surface() {
    let net = presets::wavy_grid(4, 3);
    let (m, n) = (4, 3);
    let mut beta = vec![1.0; (m + 1) * (n + 1)];
    beta[2 * (n + 1) + 2] = 0.0; // the paper's Fig. 13 style: one local parameter changed
    beta[n + 2] = 1.8; // (1, 1)
    beta[3 * (n + 1)] = 0.4; // (3, 0)
    let s = BisSurface::new(net.rows, net.cols, net.grid.clone(), Some(beta.clone()), 3).unwrap();
    let t =
        QuasiCubicSurface::new(3.0, net.rows, net.cols, net.grid.clone(), (false, false)).unwrap();
    for i in 0..=m {
        for j in 0..=n {
            let (u, v) = (i as f64, j as f64);
            assert!(
                (s.eval(u, v) - s.data_point(i, j)).length() < 1e-12,
                "interpolation"
            );
            // first partials scale by β* (tangent-length ratio)
            let b = beta[i * (n + 1) + j];
            assert!((s.partial(u, v, 1, 0) - t.partial(u, v, 1, 0) * b).length() < 1e-12);
            assert!((s.partial(u, v, 0, 1) - t.partial(u, v, 0, 1) * b).length() < 1e-12);
        }
    }
    // C² across patch borders in both directions (k = 3)
    for i in 0..m - 1 {
        for j in 0..n {
            for tt in [0.0, 0.3, 0.8, 1.0] {
                for (a, b) in [(0, 0), (1, 0), (0, 1), (2, 0), (1, 1), (0, 2)] {
                    let l = s.patch_partial(i, j, 1.0, tt, a, b);
                    let r = s.patch_partial(i + 1, j, 0.0, tt, a, b);
                    assert!(
                        (l - r).length() < 1e-11,
                        "u-joint ({a},{b}) {}",
                        (l - r).length()
                    );
                    if j + 1 < n {
                        let l = s.patch_partial(i, j, tt, 1.0, a, b);
                        let r = s.patch_partial(i, j + 1, tt, 0.0, a, b);
                        assert!((l - r).length() < 1e-11, "v-joint ({a},{b})");
                    }
                }
            }
        }
    }
    // β* ≡ 1 gives the α = 3 interpolation surface
    let one = BisSurface::new(net.rows, net.cols, net.grid.clone(), None, 3).unwrap();
    assert!(splinelab::sample::max_difference(&one, &t, 23) < 1e-12);
    // partials against finite differences
    let h = 1e-6;
    let (u, v) = (1.37, 2.21);
    let fd = (s.eval(u + h, v) - s.eval(u - h, v)) / (2.0 * h);
    assert!((fd - s.partial(u, v, 1, 0)).length() < 1e-6);
    let fd = (s.partial(u, v + h, 1, 0) - s.partial(u, v - h, 1, 0)) / (2.0 * h);
    assert!((fd - s.partial(u, v, 1, 1)).length() < 1e-5);
    // Remark 2 surface (Figs. 16/17): α = 0.6, β* = 0 at a point pins it to the control point
    let r2 = s.clone().with_alpha(0.6).unwrap();
    assert!((r2.eval(2.0, 2.0) - s.data_point(2, 2)).length() < 1e-12);
    assert!((r2.eval(1.0, 2.0) - s.data_point(1, 2)).length() > 1e-4);
}

// ---------------------------------------------------------------- bad input

#[test]
fn bad_input_is_an_error_naming_the_field() {
    let p3 = vec![v2(0.0, 0.0), v2(1.0, 1.0), v2(2.0, 0.0)];
    let e = QuasiCubicCurve::new(1.0, p3.clone()).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::TooFew, "points"));
    let e = QuasiCubicCurve::closed(1.0, p3.clone()).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::TooFew, "points"));
    assert!(e.detail().contains("closed"));
    for a in [3.01, -3.5, f64::NAN, f64::INFINITY] {
        let e = QuasiCubicCurve::new(a, bis_data()).unwrap_err();
        assert_eq!(e.field(), "alpha");
    }
    let e = QuasiCubicCurve::new(
        1.0,
        vec![v2(0.0, 0.0), v2(f64::NAN, 1.0), v2(2.0, 0.0), v2(3.0, 0.0)],
    )
    .unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::NotFinite, "points[1]"));
    let e = Bis::new(p3, None, 3).unwrap_err();
    assert_eq!(e.field(), "points");
    let e = Bis::new(bis_data(), Some(vec![1.0; 5]), 3).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::SizeMismatch, "beta"));
    let e = Bis::new(bis_data(), Some(vec![1.0, 1.0, -0.1, 1.0, 1.0, 1.0]), 3).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::OutOfRange, "beta[2]"));
    let e = Bis::new(bis_data(), None, 1).unwrap_err();
    assert_eq!(e.field(), "k");
    let e = Bis::new(bis_data(), None, 3)
        .unwrap()
        .with_alpha(4.0)
        .unwrap_err();
    assert_eq!(e.field(), "alpha");
    let net = presets::sphere(1.0);
    let e = QuasiCubicSurface::new(1.0, 3, 5, net.grid[..15].to_vec(), (true, false)).unwrap_err();
    assert_eq!(e.field(), "grid");
    assert!(e.detail().contains("periodic"));
    let e = QuasiCubicSurface::new(1.0, 4, 5, net.grid[..19].to_vec(), (true, false)).unwrap_err();
    assert_eq!(e.kind(), ErrorKind::SizeMismatch);
    let e = QuasiCubicSurface::new(1.0, 4, 3, net.grid[..12].to_vec(), (false, false)).unwrap_err();
    assert_eq!(e.field(), "grid[0]");
    let e =
        BisSurface::new(net.rows, net.cols, net.grid.clone(), Some(vec![1.0; 5]), 3).unwrap_err();
    assert_eq!(e.field(), "beta");
    let e = check_shape(ExactShape::Ellipse, 1.0, &bis_data(), 10).unwrap_err();
    assert_eq!(e.field(), "points");
    // evaluation outside the domain extrapolates, never panics
    let c = QuasiCubicCurve::new(1.0, bis_data()).unwrap();
    for u in [-5.0, 1e300, f64::NAN, -0.0] {
        let _ = c.eval(u);
    }
}

/// Regression (found by the API fuzzer): a parabola check on a degenerate polygon (coincident points) returned
/// an infinite deviation; it is now an error naming `points`.
#[test]
fn shape_check_on_a_degenerate_polygon_is_an_error() {
    use glam::DVec2;
    use splinelab::quasi_cubic::presets::{check_shape, ExactShape};
    let pts = vec![
        DVec2::new(0.0, 2.0),
        DVec2::new(0.0, 2.0),
        DVec2::new(0.0, 2.0),
        DVec2::new(1.5, -0.5),
    ];
    let e = check_shape(ExactShape::Parabola, 1.0, &pts, 20).unwrap_err();
    assert_eq!(e.field(), "points");
}
