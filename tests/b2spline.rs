//! Properties of the Kuklišová B2-splines: `../shared/spec/curves.md` §4 items 9–18 (with their
//! tolerances: |err| ≤ tol·max(1, |scale|)), the findings §2.1–2.6, and every bad-input error.

use glam::{DVec2, DVec3};
use splinelab::b2spline::*;
use splinelab::bspline::{basis_all, basis_derivs, BSplineCurve, BSplineSurface};
use splinelab::knots::find_span;
use splinelab::{Curve, ErrorKind, Point, Surface};

/// Irregular 10-point data (n = 6): uneven spacing, a sharp turn, a near-reversal.
fn data() -> Vec<DVec2> {
    [
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
    ]
    .iter()
    .map(|&(x, y)| DVec2::new(x, y))
    .collect()
}

fn opts(a: f64, p: f64, k: Option<f64>) -> B2Options {
    B2Options {
        a,
        tension: Tension::Scalar(p),
        k,
        ..B2Options::default()
    }
}

fn scale_tol(tol: f64, scale: f64) -> f64 {
    tol * scale.abs().max(1.0)
}

fn params(c: &impl Curve<DVec2>, count: usize) -> Vec<f64> {
    let (a, b) = c.domain();
    (0..count)
        .map(|k| a + (b - a) * k as f64 / (count - 1) as f64)
        .collect()
}

/// The cubic B-spline L^B with control W_0..W_{n+1} and knots u_{−1}, u_{−1}..u_{n+2}, u_{n+2}.
fn direct_bspline(w: &[DVec2], u: &[f64]) -> BSplineCurve<DVec2> {
    let mut t = vec![u[0]];
    t.extend_from_slice(u);
    t.push(u[u.len() - 1]);
    BSplineCurve::new(3, t, w[1..w.len() - 1].to_vec()).unwrap()
}

// ---------- item 9: joint weights ----------

#[test]
fn item09_joint_weights_sum_to_one_and_equal_de_boor() {
    let w = data();
    for k in [None, Some(20.0)] {
        let c = B2Curve::new(&w, &opts(0.0, 1.0 / 6.0, k)).unwrap();
        let s = c.scheme();
        let t = c.knots();
        let mut row = [Vec::new(), Vec::new(), Vec::new()];
        for i in 1..=c.n() {
            let wt = s.eq5_weights(i).unwrap();
            assert!(
                (wt.iter().sum::<f64>() - 1.0).abs() <= 1e-14,
                "sum {:?}",
                wt
            );
            // de Boor: all basis functions at the joint knot u'_{2i} = t[2i+1]
            basis_all(t, 3, t[2 * i + 1], 0, &mut row);
            for r in 0..3 {
                assert!(
                    (row[0][2 * i - 2 + r] - wt[r]).abs() <= 1e-14,
                    "i={i} r={r}"
                );
            }
            if 2 * i + 1 < row[0].len() {
                assert!(row[0][2 * i + 1].abs() <= 1e-15);
            }
        }
    }
    // the printed weights fail: Δ = (1, 2, 3, 4) sums to 1.0444…
    let p = joint_weights_as_printed(1.0, 2.0, 3.0, 4.0);
    let sum: f64 = p.iter().sum();
    assert!(
        (sum - (1.0 + 2.0 / 45.0)).abs() < 1e-14,
        "printed sum {sum}"
    );
    let c = joint_weights(1.0, 2.0, 3.0, 4.0);
    assert!((c.iter().sum::<f64>() - 1.0).abs() < 1e-15);
}

// ---------- item 10: interpolation at a = 0 ----------

#[test]
fn item10_interpolates_at_a0_with_and_without_k() {
    let w = data();
    for k in [None, Some(20.0)] {
        for p in [1.0 / 6.0, 0.13, 0.0] {
            let c = B2Curve::new(&w, &opts(0.0, p, k)).unwrap();
            let us = c.scheme().joint_params();
            for (i, &u) in us.iter().enumerate() {
                let e = (c.eval(u) - w[i + 2]).max_abs();
                assert!(
                    e <= scale_tol(1e-12, w[i + 2].max_abs()),
                    "k={k:?} p={p} i={} err={e}",
                    i + 1
                );
                assert_eq!(c.joints()[i], w[i + 2]);
            }
            // the domain ends are the first and last joints
            let (a, b) = c.domain();
            assert_eq!((a, b), (us[0], us[us.len() - 1]));
        }
    }
    // uniform and explicit knots, 3D data
    let w3: Vec<DVec3> = w
        .iter()
        .enumerate()
        .map(|(i, p)| DVec3::new(p.x, p.y, (i as f64).sin()))
        .collect();
    for knots in [KnotChoice::Uniform, KnotChoice::Chord] {
        let c = B2Curve::new(
            &w3,
            &B2Options {
                knots,
                ..B2Options::default()
            },
        )
        .unwrap();
        for (i, &u) in c.scheme().joint_params().iter().enumerate() {
            assert!((c.eval(u) - w3[i + 2]).max_abs() <= 1e-12);
        }
    }
}

#[test]
fn chord_knots_and_domain() {
    let w = data();
    let c = B2Curve::new(&w, &B2Options::default()).unwrap();
    let u = c.data_knots();
    assert_eq!(u.len(), w.len());
    assert_eq!(u[2], 0.0); // u_1 = 0
    for j in 0..w.len() - 1 {
        assert!(((u[j + 1] - u[j]) - w[j + 1].distance(w[j])).abs() < 1e-14);
    }
    assert_eq!(c.domain(), (u[2], u[w.len() - 3]));
    // the full cubic knot vector: [u'_0] + u' + [u'_{2n+2}]
    let n = c.n();
    let t = c.knots();
    assert_eq!(t.len(), 2 * n + 5);
    assert_eq!(t[0], u[1]);
    assert_eq!(t[1], u[1]);
    assert_eq!(t[2], (u[1] + u[2]) / 2.0);
    assert_eq!(t[2 * n + 4], u[n + 2]);
    assert_eq!(c.control_points().len(), 2 * n + 1);
    assert_eq!(c.even_vertices().len(), n + 1);
    assert_eq!(c.tension().len(), n + 1);
    let uni = B2Curve::new(
        &w,
        &B2Options {
            knots: KnotChoice::Uniform,
            ..B2Options::default()
        },
    )
    .unwrap();
    assert_eq!(uni.data_knots()[0], -2.0);
    assert_eq!(uni.domain(), (0.0, (n - 1) as f64));
}

#[test]
fn even_vertices_follow_eq8_9() {
    // direct formula for C_{2i} with per-vertex tension and both c2 conventions
    let w = data();
    let tens: Vec<f64> = (0..=6).map(|i| 0.05 + 0.03 * i as f64).collect();
    for c2 in [1.0, 2.0] {
        let o = B2Options {
            tension: Tension::PerVertex(tens.clone()),
            c2,
            ..B2Options::default()
        };
        let c = B2Curve::new(&w, &o).unwrap();
        let u = c.data_knots();
        let d = |j: usize| u[j + 1] - u[j]; // Δ_{j−1}
        for i in 0..=6usize {
            let (dm, d0, dp) = (d(i), d(i + 1), d(i + 2));
            let pm = 6.0 * tens[i] * d0 * d0 / (d0 * d0 + 5.0 * d0 * dm + c2 * dm * dm);
            let pp = 6.0 * tens[i] * d0 * d0 / (d0 * d0 + 5.0 * d0 * dp + c2 * dp * dp);
            let e = w[i] * -pm + w[i + 1] * (0.5 + pm) + w[i + 2] * (0.5 + pp) - w[i + 3] * pp;
            assert!(
                (c.even_vertices()[i] - e).max_abs() < 1e-13,
                "c2={c2} i={i}"
            );
        }
    }
    // p = 1/6 with equal spacing gives p^± = 1/7 (c2 = 1)
    let c = B2Curve::new(
        &w,
        &B2Options {
            knots: KnotChoice::Uniform,
            ..B2Options::default()
        },
    )
    .unwrap();
    let e = w[1] * (-1.0 / 7.0) + w[2] * (0.5 + 1.0 / 7.0) + w[3] * (0.5 + 1.0 / 7.0)
        - w[4] * (1.0 / 7.0);
    assert!((c.even_vertices()[1] - e).max_abs() < 1e-14);
    // c2 changes the curve by a visible amount on irregular data (findings §2.3: up to ~0.05)
    let c1 = B2Curve::new(&w, &B2Options::default()).unwrap();
    let c2 = B2Curve::new(
        &w,
        &B2Options {
            c2: 2.0,
            ..B2Options::default()
        },
    )
    .unwrap();
    let diff = params(&c1, 400)
        .iter()
        .map(|&u| (c1.eval(u) - c2.eval(u)).length())
        .fold(0.0, f64::max);
    assert!(diff > 1e-3, "c2 made no difference: {diff}");
}

// ---------- item 11: C² at every knot ----------

/// Value and derivatives 0..=3 of the cubic piece on span `s` of `c` at `u`.
fn piece(c: &BSplineCurve<DVec2>, s: usize, u: f64) -> [DVec2; 4] {
    let t = c.knots();
    let mut ders = [[0.0; 25]; 3];
    let mut out = [DVec2::ZERO; 4];
    basis_derivs(t, 3, s, u, 2, &mut ders);
    for k in 0..3 {
        out[k] = (0..4).fold(DVec2::ZERO, |acc, r| {
            acc + c.points()[s - 3 + r] * ders[k][r]
        });
    }
    // the third derivative is constant on a piece: difference of d2 at the span ends
    let mut d_a = [[0.0; 25]; 3];
    basis_derivs(t, 3, s, t[s], 2, &mut d_a);
    let mut d_b = [[0.0; 25]; 3];
    basis_derivs(t, 3, s, t[s + 1], 2, &mut d_b);
    let d2a = (0..4).fold(DVec2::ZERO, |acc, r| {
        acc + c.points()[s - 3 + r] * d_a[2][r]
    });
    let d2b = (0..4).fold(DVec2::ZERO, |acc, r| {
        acc + c.points()[s - 3 + r] * d_b[2][r]
    });
    out[3] = (d2b - d2a) / (t[s + 1] - t[s]);
    out
}

#[test]
fn item11_c2_at_every_knot() {
    let w = data();
    for (a, p, k) in [
        (0.0, 1.0 / 6.0, None),
        (0.1, 0.13, None),
        (0.0, 0.0, Some(20.0)),
        (-0.1, 0.3, Some(20.0)),
    ] {
        let c = B2Curve::new(&w, &opts(a, p, k)).unwrap();
        let b = c.bspline();
        let t = b.knots();
        let nc = b.points().len();
        let mut max_d3_jump: f64 = 0.0;
        for s in 4..nc {
            // interior knot t_s between span s−1 and span s
            let u = t[s];
            assert_eq!(find_span(t, 3, nc, u), s);
            let l = piece(b, s - 1, u);
            let r = piece(b, s, u);
            let scale = l[2].max_abs().max(r[2].max_abs()).max(1.0);
            assert!(
                (l[0] - r[0]).max_abs() <= 1e-12 * l[0].max_abs().max(1.0),
                "d0 jump at {s}"
            );
            assert!(
                (l[1] - r[1]).max_abs() <= 1e-11 * l[1].max_abs().max(1.0),
                "d1 jump at {s}"
            );
            assert!(
                (l[2] - r[2]).max_abs() <= 1e-10 * scale,
                "d2 jump at {s}: {:?} vs {:?}",
                l[2],
                r[2]
            );
            max_d3_jump = max_d3_jump.max((l[3] - r[3]).length());
        }
        // the check can see a jump: the third derivative does jump
        assert!(
            max_d3_jump > 0.05,
            "d3 jumps too small to show the test can fail: {max_d3_jump}"
        );
    }
}

// ---------- item 12: L^{1/6} is the cubic B-spline ----------

#[test]
fn item12_a_one_sixth_is_the_bspline_for_any_tension() {
    let w = data();
    let ps = [0.0, 0.13, 1.0 / 6.0, 0.4];
    for &p in &ps {
        let c = B2Curve::new(&w, &opts(1.0 / 6.0, p, None)).unwrap();
        let b = direct_bspline(&w, c.data_knots());
        assert_eq!(b.domain(), c.domain());
        for u in params(&c, 301) {
            let e = (c.eval(u) - b.eval(u)).max_abs();
            assert!(
                e <= 1e-12 * b.eval(u).max_abs().max(1.0),
                "p={p} u={u} e={e}"
            );
        }
    }
    // per-vertex tension too
    let o = B2Options {
        a: 1.0 / 6.0,
        tension: Tension::PerVertex(vec![0.0, 0.3, 0.1, 0.2, 0.05, 0.0, 0.25]),
        ..B2Options::default()
    };
    let c = B2Curve::new(&w, &o).unwrap();
    let b = direct_bspline(&w, c.data_knots());
    for u in params(&c, 301) {
        assert!((c.eval(u) - b.eval(u)).max_abs() <= 1e-12 * 10.0);
    }
    // findings §2.5: the naive reading (section-3 formulas with a = 1/6, p = 0 on chord knots) is NOT L^B
    let naive_ctrl_gap = {
        let c = B2Curve::new(&w, &opts(1.0 / 6.0, 0.0, None)).unwrap();
        let ev = c.even_vertices();
        (0..ev.len())
            .map(|i| (ev[i] - (w[i + 1] + w[i + 2]) * 0.5).length())
            .fold(0.0, f64::max)
    };
    assert!(
        naive_ctrl_gap > 0.05,
        "midpoints would have been right: {naive_ctrl_gap}"
    );
}

// ---------- item 13: the section-5 blend ----------

#[test]
fn item13_la_is_the_blend_of_lb_and_l() {
    let w = data();
    for p in [1.0 / 6.0, 0.13] {
        let l = B2Curve::new(&w, &opts(0.0, p, None)).unwrap();
        let lb = direct_bspline(&w, l.data_knots());
        for a in [0.0, 0.05, 1.0 / 6.0, 0.3, -0.1] {
            let la = B2Curve::new(&w, &opts(a, p, None)).unwrap();
            for u in params(&la, 257) {
                let want = lb.eval(u) * (6.0 * a) + l.eval(u) * (1.0 - 6.0 * a);
                let e = (la.eval(u) - want).max_abs();
                assert!(e <= 1e-12 * want.max_abs().max(1.0), "a={a} u={u} e={e}");
            }
            // the joints are the blended joints, and L^a passes through them
            for (i, &u) in la.scheme().joint_params().iter().enumerate() {
                let wb = lb.eval(u);
                let want = wb * (6.0 * a) + w[i + 2] * (1.0 - 6.0 * a);
                assert!((la.joints()[i] - want).max_abs() <= 1e-12 * 10.0);
                assert!((la.eval(u) - want).max_abs() <= 1e-12 * 10.0);
            }
        }
    }
}

#[test]
fn with_k_the_b2_vertices_are_blended_on_the_modified_knots() {
    let w = data();
    let k = Some(20.0);
    let l = B2Curve::new(&w, &opts(0.0, 0.13, k)).unwrap();
    let lb = direct_bspline(&w, l.data_knots());
    let a = 0.1;
    let la = B2Curve::new(&w, &opts(a, 0.13, k)).unwrap();
    let u = l.data_knots();
    for i in 1..=l.n() {
        let want = lb.eval(u[i + 1]) * (6.0 * a) + w[i + 1] * (1.0 - 6.0 * a);
        assert!((la.joints()[i - 1] - want).max_abs() < 1e-12 * 10.0);
        // L^a passes through its joints at the modified knots
        let up = la.scheme().joint_params()[i - 1];
        assert!((la.eval(up) - want).max_abs() < 1e-12 * 10.0);
    }
    // K = 1e12 ≈ standard knots (findings §2.4: 3.3e-13)
    for a in [0.0, 0.1] {
        let std = B2Curve::new(&w, &opts(a, 0.13, None)).unwrap();
        let big = B2Curve::new(&w, &opts(a, 0.13, Some(1e12))).unwrap();
        let d = params(&std, 301)
            .iter()
            .map(|&u| (std.eval(u) - big.eval(u)).max_abs())
            .fold(0.0, f64::max);
        assert!(d < 1e-10, "K = 1e12 differs by {d}");
        // and K = 20 does change the curve
        let k20 = B2Curve::new(&w, &opts(a, 0.13, Some(20.0))).unwrap();
        let d = params(&std, 301)
            .iter()
            .map(|&u| (std.eval(u) - k20.eval(u)).max_abs())
            .fold(0.0, f64::max);
        assert!(d > 1e-3);
    }
}

// ---------- item 14: section 3 ----------

fn section3(w: &[DVec2], a: f64, p: f64) -> B2Curve<DVec2> {
    let o = B2Options {
        a,
        tension: Tension::Scalar(p),
        knots: KnotChoice::Uniform,
        construction: Construction::Section3,
        ..B2Options::default()
    };
    B2Curve::new(w, &o).unwrap()
}

#[test]
fn item14_section3() {
    let w = data();
    let n = w.len() - 4;
    // a = 1/6, p = 0: the uniform cubic B-spline on W_0..W_{n+1}
    let c = section3(&w, 1.0 / 6.0, 0.0);
    assert_eq!(c.domain(), (0.0, (n - 1) as f64));
    let b = direct_bspline(&w, &uniform_knots(w.len()));
    for u in params(&c, 201) {
        assert!((c.eval(u) - b.eval(u)).max_abs() <= 1e-12 * 10.0);
    }
    // a = 0 interpolates W_i at u = i − 1 for several p
    for p in [0.0, 0.1, 0.3] {
        let c = section3(&w, 0.0, p);
        for i in 1..=n {
            assert!((c.eval((i - 1) as f64) - w[i + 1]).max_abs() <= 1e-12 * 10.0);
        }
    }
    // the paper's matrices Q_{2i−1}, Q_{2i} (one parameter unit per half-span; P_i at the start of Q_{2i−1})
    const M1: [[f64; 5]; 4] = [
        [-7.0, 18.0, -16.0, 6.0, -1.0],
        [18.0, -36.0, 18.0, 0.0, 0.0],
        [-12.0, 0.0, 12.0, 0.0, 0.0],
        [0.0, 24.0, 0.0, 0.0, 0.0],
    ];
    const M2: [[f64; 5]; 4] = [
        [1.0, -6.0, 16.0, -18.0, 7.0],
        [-3.0, 18.0, -30.0, 18.0, -3.0],
        [3.0, -18.0, 0.0, 18.0, -3.0],
        [-1.0, 6.0, 14.0, 6.0, -1.0],
    ];
    for (a, p) in [(0.0, 0.1), (0.1, 0.0), (-0.1, 0.2)] {
        let c = section3(&w, a, p);
        let d = c.even_vertices();
        let r = c.joints();
        for i in 1..n {
            let v = [d[i - 1], r[i - 1], d[i], r[i], d[i + 1]];
            for s in 0..=8 {
                let t = s as f64 / 8.0;
                let pw = [t * t * t, t * t, t, 1.0];
                for (m, off) in [(&M1, 0.0), (&M2, 0.5)] {
                    let mut q = DVec2::ZERO;
                    for row in 0..4 {
                        for col in 0..5 {
                            q += v[col] * (pw[row] * m[row][col] / 24.0);
                        }
                    }
                    let u = (i - 1) as f64 + off + t / 2.0;
                    assert!(
                        (q - c.eval(u)).max_abs() <= 1e-12 * 10.0,
                        "a={a} p={p} i={i} t={t}"
                    );
                }
            }
        }
    }
}

// ---------- item 15: equal spacing ----------

#[test]
fn item15_equal_spacing_matches_section3_with_effective_tension() {
    let w = data();
    let mut cases = 0;
    for c2 in [1.0, 2.0] {
        for (a, p) in [(0.0, 1.0 / 6.0), (0.1, 0.13), (-0.1, 0.3), (0.05, 0.0)] {
            // knots h·(j − 1) + s: the same curve reparameterised by u ↦ h·u + s
            let (h, s) = (0.7, 3.0);
            let k: Vec<f64> = uniform_knots(w.len()).iter().map(|x| h * x + s).collect();
            let o = B2Options {
                a,
                tension: Tension::Scalar(p),
                knots: KnotChoice::Explicit(k),
                c2,
                ..B2Options::default()
            };
            let nu = B2Curve::new(&w, &o).unwrap();
            let u3 = section3(&w, a, (1.0 - 6.0 * a) * 6.0 * p / (6.0 + c2));
            for u in params(&u3, 201) {
                let e = (nu.eval(h * u + s) - u3.eval(u)).max_abs();
                assert!(e <= 1e-12 * 10.0, "c2={c2} a={a} p={p} u={u} e={e}");
            }
            cases += 1;
        }
    }
    assert_eq!(cases, 8);
}

#[test]
fn tension_one_twelfth_reproduces_cubics() {
    // findings §2.3: the uniform C_{2i} reproduces t² and t³ iff p = 1/12; with c2 = 1 the non-uniform p_i^± =
    // 6p/7 on equal spans, so p = 7/72 (a = 0) reproduces the cubic the data come from, exactly
    let f = |t: f64| DVec2::new(t * t * t - 2.0 * t * t + 0.5, 0.3 * t * t - t);
    let w: Vec<DVec2> = (0..9).map(|j| f(j as f64 - 2.0)).collect();
    let o = B2Options {
        tension: Tension::Scalar(7.0 / 72.0),
        knots: KnotChoice::Uniform,
        ..B2Options::default()
    };
    let c = B2Curve::new(&w, &o).unwrap();
    let mut worst: f64 = 0.0;
    for u in params(&c, 101) {
        worst = worst.max((c.eval(u) - f(u)).max_abs());
    }
    assert!(worst < 1e-12, "{worst}");
    // and the default p = 1/6 does not (the test can fail)
    let c = B2Curve::new(
        &w,
        &B2Options {
            knots: KnotChoice::Uniform,
            ..B2Options::default()
        },
    )
    .unwrap();
    let off = params(&c, 101)
        .iter()
        .map(|&u| (c.eval(u) - f(u)).max_abs())
        .fold(0.0, f64::max);
    assert!(off > 1e-3, "{off}");
}

// ---------- item 16: reversal symmetry and affine invariance ----------

#[test]
fn item16_reversal_symmetry() {
    let w = data();
    let base = B2Curve::new(&w, &B2Options::default()).unwrap();
    let u = base.data_knots().to_vec();
    let tens: Vec<f64> = vec![0.1, 0.2, 0.05, 0.13, 0.3, 0.0, 0.17];
    let wr: Vec<DVec2> = w.iter().rev().copied().collect();
    let ur: Vec<f64> = u.iter().rev().map(|x| -x).collect();
    let tr: Vec<f64> = tens.iter().rev().copied().collect();
    for a in [0.0, 0.1] {
        for k in [None, Some(20.0)] {
            let o = |w: Vec<f64>, t: Vec<f64>| B2Options {
                a,
                tension: Tension::PerVertex(t),
                knots: KnotChoice::Explicit(w),
                k,
                ..B2Options::default()
            };
            let c = B2Curve::new(&w, &o(u.clone(), tens.clone())).unwrap();
            let r = B2Curve::new(&wr, &o(ur.clone(), tr.clone())).unwrap();
            assert!((c.domain().0 + r.domain().1).abs() < 1e-13);
            for x in params(&c, 211) {
                let e = (c.eval(x) - r.eval(-x)).max_abs();
                assert!(e <= 1e-12 * 10.0, "a={a} k={k:?} u={x} e={e}");
            }
        }
    }
}

#[test]
fn item16_affine_invariance_and_collinear_data() {
    let w = data();
    let map = |p: DVec2| DVec2::new(2.0 * p.x - 0.7 * p.y + 3.0, 0.4 * p.x + 1.5 * p.y - 1.0);
    let wm: Vec<DVec2> = w.iter().map(|&p| map(p)).collect();
    let k = B2Curve::new(&w, &B2Options::default())
        .unwrap()
        .data_knots()
        .to_vec();
    for (a, kk) in [(0.0, None), (0.1, Some(20.0)), (1.0 / 6.0, None)] {
        let o = B2Options {
            a,
            tension: Tension::Scalar(0.13),
            knots: KnotChoice::Explicit(k.clone()),
            k: kk,
            ..B2Options::default()
        };
        let c = B2Curve::new(&w, &o).unwrap();
        let m = B2Curve::new(&wm, &o).unwrap();
        for u in params(&c, 201) {
            let e = (map(c.eval(u)) - m.eval(u)).max_abs();
            assert!(
                e <= 1e-12 * map(c.eval(u)).max_abs().max(1.0),
                "a={a} e={e}"
            );
        }
    }
    // collinear data stays on the line
    let line: Vec<DVec2> = [0.0, 0.5, 2.0, 2.2, 4.0, 7.0, 7.5, 9.0]
        .iter()
        .map(|&t| DVec2::new(1.0 + 2.0 * t, -1.0 + t))
        .collect();
    for a in [0.0, 0.1] {
        let c = B2Curve::new(&line, &opts(a, 0.3, Some(20.0))).unwrap();
        for u in params(&c, 101) {
            let p = c.eval(u);
            assert!((p.x - 1.0 - 2.0 * (p.y + 1.0)).abs() < 1e-12 * 20.0);
        }
    }
}

// ---------- item 18: automatic tension ----------

/// A polygon whose vertex k turns by `turns[k]` degrees (k = 0..len); edges of length `len[k]`.
fn turning_polygon(turns: &[f64], lens: &[f64]) -> Vec<DVec2> {
    let mut p = vec![DVec2::ZERO];
    let mut dir: f64 = 0.0;
    for (k, &l) in lens.iter().enumerate() {
        if k > 0 {
            dir += turns[k - 1].to_radians();
        }
        let last = p[p.len() - 1];
        p.push(last + DVec2::new(dir.cos(), dir.sin()) * l);
    }
    p
}

#[test]
fn item18_auto_tension_table() {
    let lens = [1.0, 1.3, 0.8, 1.1, 1.0, 0.9, 1.2, 1.0];
    // constant turn θ at every interior vertex
    for (theta, paper, turning) in [
        (0.0, 0.2, 0.0),
        (
            5.0,
            0.2 * 5f64.to_radians().cos(),
            0.2 * 5f64.to_radians().sin(),
        ),
        (60.0, 0.1, 0.2 * 60f64.to_radians().sin()),
        (90.0, 0.0, 0.2),
    ] {
        let w = turning_polygon(&[theta; 8], &lens);
        let pp = auto_tension(&w, AutoTension::Paper(0.2)).unwrap();
        let pt = auto_tension(&w, AutoTension::Turning(0.2)).unwrap();
        assert_eq!(pp.len(), w.len() - 3);
        for i in 0..pp.len() {
            assert!(
                (pp[i] - paper).abs() <= 1e-14,
                "θ={theta} paper p_{i} = {}",
                pp[i]
            );
            assert!(
                (pt[i] - turning).abs() <= 1e-14,
                "θ={theta} turning p_{i} = {}",
                pt[i]
            );
        }
    }
    // the quoted rounded figures of the table
    let w5 = turning_polygon(&[5.0; 8], &lens);
    assert!((auto_tension(&w5, AutoTension::Paper(0.2)).unwrap()[2] - 0.199).abs() < 5e-4);
    assert!((auto_tension(&w5, AutoTension::Turning(0.2)).unwrap()[2] - 0.017).abs() < 5e-4);
    // reversal 175° next to a straight vertex: vertex 3 (α_3 index = W_3) reverses, W_4 straight
    let mut turns = [0.0; 8];
    turns[3] = 175.0;
    let w = turning_polygon(&turns, &lens);
    // data index k ↔ W_{k−1}; turn index t ↔ data index t + 1 ↔ W_t. p_i uses α_i, α_{i+1} → i = 3
    let pp = auto_tension(&w, AutoTension::Paper(0.2)).unwrap();
    let pt = auto_tension(&w, AutoTension::Turning(0.2)).unwrap();
    let want_p = 0.2 * (5f64.to_radians().cos() - 1.0).abs() / 2.0;
    let want_t = 0.2 * 175f64.to_radians().sin() / 2.0;
    assert!((pp[3] - want_p).abs() <= 1e-14, "{} vs {want_p}", pp[3]);
    assert!((pp[3] - 0.0004).abs() < 5e-5);
    assert!((pt[3] - want_t).abs() <= 1e-14);
    assert!((pt[3] - 0.0087).abs() < 5e-5);
    // turn and return ±30°, ±60°
    for (th, paper) in [(30.0, 0.2 * 30f64.to_radians().cos()), (60.0, 0.1)] {
        let turns: Vec<f64> = (0..8).map(|k| if k % 2 == 0 { th } else { -th }).collect();
        let w = turning_polygon(&turns, &lens);
        let pp = auto_tension(&w, AutoTension::Paper(0.2)).unwrap();
        let pt = auto_tension(&w, AutoTension::Turning(0.2)).unwrap();
        for i in 0..pp.len() {
            assert!((pp[i] - paper).abs() <= 1e-14);
            assert!(pt[i].abs() <= 1e-14);
        }
    }
    assert!((0.2f64 * 30f64.to_radians().cos() - 0.173).abs() < 5e-4);
    // B2Curve uses them
    let w = turning_polygon(&[60.0; 8], &lens);
    let c = B2Curve::new(
        &w,
        &B2Options {
            auto_tension: AutoTension::Paper(0.2),
            ..B2Options::default()
        },
    )
    .unwrap();
    assert!(c.tension().iter().all(|&p| (p - 0.1).abs() < 1e-14));
}

// ---------- scalar data: blending functions ----------

#[test]
fn scalar_data_gives_blending_functions() {
    let w = data();
    let c = B2Curve::new(&w, &opts(0.05, 0.13, None)).unwrap();
    let knots = KnotChoice::Explicit(c.data_knots().to_vec());
    let o = B2Options {
        a: 0.05,
        tension: Tension::Scalar(0.13),
        knots,
        ..B2Options::default()
    };
    let m = w.len();
    let basis: Vec<B2Curve<f64>> = (0..m)
        .map(|j| {
            let e: Vec<f64> = (0..m).map(|k| if k == j { 1.0 } else { 0.0 }).collect();
            B2Curve::new(&e, &o).unwrap()
        })
        .collect();
    let mut row = [Vec::new(), Vec::new(), Vec::new()];
    for u in params(&c, 97) {
        let sum: f64 = basis.iter().map(|b| b.eval(u)).sum();
        assert!(
            (sum - 1.0).abs() < 1e-13,
            "partition of unity at {u}: {sum}"
        );
        let p = basis
            .iter()
            .zip(&w)
            .fold(DVec2::ZERO, |acc, (b, wj)| acc + *wj * b.eval(u));
        assert!((p - c.eval(u)).max_abs() < 1e-12 * 10.0);
        c.scheme().basis(u, 1, &mut row);
        for j in 0..m {
            assert!((row[0][j] - basis[j].eval(u)).abs() < 1e-13);
        }
        assert!(row[1].iter().sum::<f64>().abs() < 1e-10);
    }
    // at a = 0, L_j(u_i) = δ_ij (eq. (2))
    let c0 = B2Curve::new(&w, &B2Options::default()).unwrap();
    for (i, &u) in c0.scheme().joint_params().iter().enumerate() {
        c0.scheme().basis(u, 0, &mut row);
        for j in 0..m {
            let want = if j == i + 2 { 1.0 } else { 0.0 };
            assert!((row[0][j] - want).abs() < 1e-13);
        }
    }
}

// ---------- surfaces ----------

fn grid(rows: usize, cols: usize) -> Vec<DVec3> {
    let mut g = Vec::new();
    for i in 0..rows {
        for j in 0..cols {
            let (x, y) = (
                i as f64 * 1.1 + 0.2 * (j as f64).sin(),
                j as f64 * 0.9 + 0.3 * (i as f64 * 0.7).cos(),
            );
            g.push(DVec3::new(
                x,
                y,
                (0.6 * x).sin() * (0.4 * y).cos() + 0.05 * (i * j) as f64,
            ));
        }
    }
    g
}

#[test]
fn surface_interpolates_at_a0_and_is_tensor_bspline_at_one_sixth() {
    let (rows, cols) = (7, 8); // m = 3, n = 4
    let g = grid(rows, cols);
    for knots in [SurfaceKnots::Chord, SurfaceKnots::Uniform] {
        let o = B2SurfaceOptions {
            knots_u: knots.clone(),
            knots_v: knots.clone(),
            ..B2SurfaceOptions::default()
        };
        let s = B2Surface::new(rows, cols, &g, &o).unwrap();
        let (uk, vk) = (
            s.scheme_u().data_knots().to_vec(),
            s.scheme_v().data_knots().to_vec(),
        );
        for i in 2..rows - 2 {
            for j in 2..cols - 2 {
                let e = (s.eval(uk[i], vk[j]) - g[i * cols + j]).max_abs();
                assert!(e <= 1e-12 * 10.0, "({i}, {j}) {e}");
            }
        }
        // a = 1/6: the tensor B-spline with control W_{0..m+1, 0..n+1}
        let o6 = B2SurfaceOptions {
            a: 1.0 / 6.0,
            tension_u: Tension::Scalar(0.3),
            ..o.clone()
        };
        let s6 = B2Surface::new(rows, cols, &g, &o6).unwrap();
        let ext = |k: &[f64]| {
            let mut t = vec![k[0]];
            t.extend_from_slice(k);
            t.push(k[k.len() - 1]);
            t
        };
        let mut inner = Vec::new();
        for i in 1..rows - 1 {
            for j in 1..cols - 1 {
                inner.push(g[i * cols + j]);
            }
        }
        let b = BSplineSurface::new(3, 3, ext(&uk), ext(&vk), rows - 2, cols - 2, inner).unwrap();
        assert_eq!(b.domain(), s6.domain());
        let ((u0, u1), (v0, v1)) = s6.domain();
        for a in 0..=12 {
            for c in 0..=12 {
                let (u, v) = (
                    u0 + (u1 - u0) * a as f64 / 12.0,
                    v0 + (v1 - v0) * c as f64 / 12.0,
                );
                let mut o1 = [DVec3::ZERO; 3];
                let mut o2 = [DVec3::ZERO; 3];
                s6.eval_derivs(u, v, true, &mut o1);
                b.eval_derivs(u, v, true, &mut o2);
                for k in 0..3 {
                    assert!((o1[k] - o2[k]).max_abs() <= 1e-12 * 10.0);
                }
            }
        }
    }
    // the surface along a grid line u = u_i is the B2 curve of that row (tensor product)
    let o = B2SurfaceOptions {
        a: 0.07,
        tension_v: Tension::Scalar(0.1),
        knots_u: SurfaceKnots::Uniform,
        knots_v: SurfaceKnots::Uniform,
        ..B2SurfaceOptions::default()
    };
    let s = B2Surface::new(rows, cols, &g, &o).unwrap();
    let co = B2Options {
        a: 0.07,
        tension: Tension::Scalar(0.1),
        knots: KnotChoice::Uniform,
        ..B2Options::default()
    };
    // S(u, v) = Σ_i L_i(u) C^i(v)
    let rowc: Vec<B2Curve<DVec3>> = (0..rows)
        .map(|i| B2Curve::new(&g[i * cols..(i + 1) * cols], &co).unwrap())
        .collect();
    let mut lu = [Vec::new(), Vec::new(), Vec::new()];
    for (u, v) in [(0.3, 1.7), (1.0, 2.0), (1.9, 0.2)] {
        s.scheme_u().basis(u, 0, &mut lu);
        let want = (0..rows).fold(DVec3::ZERO, |acc, i| acc + rowc[i].eval(v) * lu[0][i]);
        assert!((s.eval(u, v) - want).max_abs() < 1e-12 * 10.0);
    }
}

// ---------- bad input ----------

#[test]
fn bad_input_names_the_field() {
    let w = data();
    let err = |pts: &[DVec2], o: B2Options| B2Curve::new(pts, &o).unwrap_err();
    let e = err(&w[..5], B2Options::default());
    assert_eq!((e.kind(), e.field()), (ErrorKind::TooFew, "points"));
    assert!(e.to_string().contains("n ≥ 2"));
    let mut bad = w.clone();
    bad[3] = bad[2];
    let e = err(&bad, B2Options::default());
    assert_eq!((e.kind(), e.field()), (ErrorKind::Degenerate, "points[3]"));
    // coincident neighbours are fine with uniform knots (documented), but not with automatic tension
    assert!(B2Curve::new(
        &bad,
        &B2Options {
            knots: KnotChoice::Uniform,
            ..B2Options::default()
        }
    )
    .is_ok());
    let e = err(
        &bad,
        B2Options {
            knots: KnotChoice::Uniform,
            auto_tension: AutoTension::Paper(0.2),
            ..B2Options::default()
        },
    );
    assert_eq!(e.field(), "points[3]");
    let mut nan = w.clone();
    nan[4].y = f64::NAN;
    let e = err(&nan, B2Options::default());
    assert_eq!((e.kind(), e.field()), (ErrorKind::NotFinite, "points[4]"));
    let mut k = uniform_knots(w.len());
    k[5] = k[4];
    let e = err(
        &w,
        B2Options {
            knots: KnotChoice::Explicit(k),
            ..B2Options::default()
        },
    );
    assert_eq!(
        (e.kind(), e.field()),
        (ErrorKind::NotIncreasing, "knots[5]")
    );
    let e = err(
        &w,
        B2Options {
            knots: KnotChoice::Explicit(vec![0.0, 1.0, 2.0]),
            ..B2Options::default()
        },
    );
    assert_eq!((e.kind(), e.field()), (ErrorKind::SizeMismatch, "knots"));
    let mut k = uniform_knots(w.len());
    k[2] = f64::INFINITY;
    assert_eq!(
        err(
            &w,
            B2Options {
                knots: KnotChoice::Explicit(k),
                ..B2Options::default()
            }
        )
        .field(),
        "knots[2]"
    );
    let e = err(
        &w,
        B2Options {
            tension: Tension::PerVertex(vec![0.1; 3]),
            ..B2Options::default()
        },
    );
    assert_eq!((e.kind(), e.field()), (ErrorKind::SizeMismatch, "tension"));
    assert_eq!(
        err(
            &w,
            B2Options {
                tension: Tension::Scalar(f64::NAN),
                ..B2Options::default()
            }
        )
        .field(),
        "tension"
    );
    let s3 = B2Options {
        construction: Construction::Section3,
        ..B2Options::default()
    };
    let e = err(&w, s3.clone());
    assert_eq!(e.field(), "construction");
    assert!(e.to_string().contains("knots"));
    let e = err(
        &w,
        B2Options {
            knots: KnotChoice::Explicit(data_knots_chord(&w)),
            ..s3.clone()
        },
    );
    assert_eq!(e.field(), "construction");
    let e = err(
        &w,
        B2Options {
            knots: KnotChoice::Uniform,
            tension: Tension::PerVertex(vec![0.1; 7]),
            ..s3.clone()
        },
    );
    assert_eq!(e.field(), "tension");
    assert!(B2Curve::new(
        &w,
        &B2Options {
            knots: KnotChoice::Uniform,
            ..s3
        }
    )
    .is_ok());
    assert_eq!(
        err(
            &w,
            B2Options {
                k: Some(-1.0),
                ..B2Options::default()
            }
        )
        .field(),
        "K"
    );
    assert_eq!(
        err(
            &w,
            B2Options {
                k: Some(f64::NAN),
                ..B2Options::default()
            }
        )
        .field(),
        "K"
    );
    assert_eq!(
        err(
            &w,
            B2Options {
                c2: -1.0,
                ..B2Options::default()
            }
        )
        .field(),
        "c2"
    );
    assert_eq!(
        err(
            &w,
            B2Options {
                a: f64::INFINITY,
                ..B2Options::default()
            }
        )
        .field(),
        "a"
    );
    let w3: Vec<DVec3> = w.iter().map(|p| DVec3::new(p.x, p.y, 0.0)).collect();
    let e = B2Curve::new(
        &w3,
        &B2Options {
            auto_tension: AutoTension::Turning(0.2),
            ..B2Options::default()
        },
    )
    .unwrap_err();
    assert_eq!(e.field(), "autoTension");
    assert!(B2Curve::new(
        &w3,
        &B2Options {
            auto_tension: AutoTension::Paper(0.2),
            ..B2Options::default()
        }
    )
    .is_ok());
    // surfaces
    let g = grid(7, 8);
    let e = B2Surface::new(5, 8, &g[..40], &B2SurfaceOptions::default()).unwrap_err();
    assert_eq!(e.field(), "grid");
    let e = B2Surface::new(
        7,
        8,
        &g,
        &B2SurfaceOptions {
            tension_u: Tension::PerVertex(vec![0.1; 5]),
            ..B2SurfaceOptions::default()
        },
    )
    .unwrap_err();
    assert_eq!(e.field(), "tensionU");
    let e = B2Surface::new(
        7,
        8,
        &g,
        &B2SurfaceOptions {
            knots_v: SurfaceKnots::Explicit(vec![0.0; 8]),
            ..B2SurfaceOptions::default()
        },
    )
    .unwrap_err();
    assert_eq!(e.field(), "knotsV[1]");
    let mut gn = g.clone();
    gn[10].z = f64::NAN;
    assert_eq!(
        B2Surface::new(7, 8, &gn, &B2SurfaceOptions::default())
            .unwrap_err()
            .field(),
        "grid[1][2]"
    );
}

fn data_knots_chord(w: &[DVec2]) -> Vec<f64> {
    chord_knots(w).unwrap()
}

// Issue 30, item 3: the scheme's own accessors report what the curve was built with (a mutant that returns a
// constant or an empty slice from B2Scheme::a / B2Scheme::tension fails here).
#[test]
fn scheme_accessors_report_a_and_the_tensions_used() {
    let w = [
        DVec2::new(-1.0, 0.0),
        DVec2::new(0.0, 0.0),
        DVec2::new(1.0, 2.0),
        DVec2::new(2.5, 2.5),
        DVec2::new(4.0, 0.5),
        DVec2::new(5.0, 2.0),
        DVec2::new(6.0, 1.0),
        DVec2::new(7.0, 1.0),
    ];
    for (a, p) in [(0.0, 1.0 / 6.0), (0.05, 0.1), (1.0 / 6.0, 0.0), (-0.1, 0.3)] {
        let c = B2Curve::new(
            &w,
            &B2Options {
                a,
                tension: Tension::Scalar(p),
                ..B2Options::default()
            },
        )
        .unwrap();
        let s = c.scheme();
        assert_eq!(s.a(), a, "B2Scheme::a");
        assert_eq!(s.tension().len(), c.n() + 1, "one tension per joint");
        assert!(
            s.tension().iter().all(|&q| q == p),
            "B2Scheme::tension {:?} for p = {p}",
            s.tension()
        );
        assert_eq!(s.tension(), c.tension());
    }
    // automatic tension: per-joint values, different from each other, the same the curve reports
    let c = B2Curve::new(
        &w,
        &B2Options {
            auto_tension: AutoTension::Paper(0.2),
            ..B2Options::default()
        },
    )
    .unwrap();
    let t = c.scheme().tension();
    assert_eq!(t.len(), c.n() + 1);
    assert!(
        t.iter().any(|&q| (q - t[0]).abs() > 1e-6),
        "automatic tensions vary: {t:?}"
    );
    assert_eq!(t, c.tension());
}
