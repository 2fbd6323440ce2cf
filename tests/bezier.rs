//! Gânscă–Coman–Ţămbulea remodelling: `curves.md` §3 and §4 items 19–24 as numbers.

use glam::{DVec2, DVec3};
use splinelab::bezier::{
    alpha_roles, elevate, AlphaRole, AlphaTable, BezierSpline, BezierSplineSurface, Remodelling,
    Side, SurfaceRemodelling,
};
use splinelab::bspline::{BSplineCurve, BSplineSurface};
use splinelab::point::curvature;
use splinelab::sample::uniform_params;
use splinelab::{Curve, ErrorKind, Point, Surface};

// ---------------------------------------------------------------------------------------------------
// data

fn example_points() -> Vec<DVec2> {
    [
        [10., 16.],
        [7., 21.],
        [3., 9.],
        [0., 0.],
        [-4., 0.],
        [-8., 0.],
        [-6., 3.],
        [-4., 6.],
        [2., 2.],
        [8., -2.],
        [10., 3.],
    ]
    .iter()
    .map(|p| DVec2::new(p[0], p[1]))
    .collect()
}
const EXAMPLE_BREAKS: [f64; 6] = [0.0, 1.0, 1.75, 2.5, 3.25, 4.0];

fn example() -> BezierSpline<DVec2> {
    BezierSpline::new(2, EXAMPLE_BREAKS.to_vec(), example_points()).unwrap()
}

fn fig1() -> Vec<Vec<f64>> {
    vec![
        vec![2. / 3., 1. / 20.],
        vec![19. / 20., 1. / 3.],
        vec![2. / 3., 1. / 3.],
        vec![2. / 3., 1. / 3.],
        vec![2. / 3., 1. / 10.],
    ]
}
fn fig2() -> Vec<Vec<f64>> {
    vec![
        vec![0.1, 0.1],
        vec![0.9, 1. / 3.],
        vec![2. / 3., 1. / 3.],
        vec![2. / 3., 0.01],
        vec![0.99, 0.2],
    ]
}

/// A small deterministic generator (no dependency).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6364136223846793005)
            .wrapping_add(1442695040888963407);
        ((self.0 >> 11) as f64) / ((1u64 << 53) as f64)
    }
    fn range(&mut self, a: f64, b: f64) -> f64 {
        a + (b - a) * self.next()
    }
}

/// A random irregular clamped B-spline of degree m (simple interior knots, so C^{m−1}) in Bézier form.
fn random_spline<P: Point>(rng: &mut Lcg, m: usize, segments: usize) -> BezierSpline<P> {
    let n_ctrl = segments + m;
    let mut knots = vec![0.0; m + 1];
    let mut t = 0.0;
    for _ in 1..segments {
        t += rng.range(0.5, 2.0);
        knots.push(t);
    }
    t += rng.range(0.5, 2.0);
    knots.extend(std::iter::repeat_n(t, m + 1));
    let pts: Vec<P> = (0..n_ctrl)
        .map(|_| {
            let c: Vec<f64> = (0..P::DIM).map(|_| rng.range(-10.0, 10.0)).collect();
            P::from_coords(&c).unwrap()
        })
        .collect();
    let b = BSplineCurve::new(m, knots, pts).unwrap();
    BezierSpline::from_bspline(&b).unwrap()
}

fn random_alphas(rng: &mut Lcg, m: usize, segments: usize, max_last: f64) -> AlphaTable {
    let rows = (0..segments)
        .map(|_| {
            (0..m)
                .map(|k| {
                    if k + 1 == m {
                        rng.range(0.05, max_last)
                    } else {
                        rng.range(0.05, 0.95)
                    }
                })
                .collect()
        })
        .collect();
    AlphaTable::new(m, segments, rows).unwrap()
}

fn max_diff<P: Point, A: Curve<P>, B: Curve<P>>(a: &A, b: &B, order: usize) -> f64 {
    let (u0, u1) = a.domain();
    let mut worst: f64 = 0.0;
    let (mut oa, mut ob) = ([P::ZERO; 3], [P::ZERO; 3]);
    for u in uniform_params(u0, u1, 401) {
        a.eval_derivs(u, order, &mut oa);
        b.eval_derivs(u, order, &mut ob);
        for k in 0..=order {
            worst = worst.max((oa[k] - ob[k]).max_abs());
        }
    }
    worst
}

fn max_jump(jumps: &[Vec<f64>], order: usize) -> f64 {
    jumps.iter().map(|j| j[order]).fold(0.0, f64::max)
}

/// The same spline as a B-spline with every breakvalue of multiplicity m (an independent evaluator).
fn as_bspline<P: Point>(g: &BezierSpline<P>) -> BSplineCurve<P> {
    let m = g.degree();
    let b = g.breaks();
    let mut knots = vec![b[0]];
    for &u in b {
        knots.extend(std::iter::repeat_n(u, m));
    }
    knots.push(b[b.len() - 1]);
    BSplineCurve::new(m, knots, g.points().to_vec()).unwrap()
}

// ---------------------------------------------------------------------------------------------------
// the spline itself

#[test]
fn evaluation_matches_an_independent_bspline_evaluator() {
    let mut rng = Lcg(7);
    for m in 1..=6 {
        let mut pts: Vec<DVec3> = Vec::new();
        let l = 4;
        for _ in 0..=m * l {
            pts.push(DVec3::new(
                rng.range(-5., 5.),
                rng.range(-5., 5.),
                rng.range(-5., 5.),
            ));
        }
        let g = BezierSpline::new(m, vec![0.0, 0.7, 1.1, 2.9, 3.0], pts).unwrap();
        let b = as_bspline(&g);
        let d = max_diff(&g, &b, 2);
        assert!(d < 1e-9, "m = {m}: {d}");
    }
}

#[test]
fn right_hand_piece_at_breakvalues_and_last_piece_at_the_end() {
    // a spline with a kink at u = 1: the derivative there is the right-hand one
    let pts = vec![
        DVec2::new(0., 0.),
        DVec2::new(1., 0.),
        DVec2::new(2., 0.),
        DVec2::new(2., 3.),
        DVec2::new(2., 4.),
    ];
    let g = BezierSpline::new(2, vec![0.0, 1.0, 2.0], pts).unwrap();
    let mut out = [DVec2::ZERO; 3];
    g.eval_derivs(1.0, 1, &mut out);
    assert_eq!(out[0], DVec2::new(2., 0.));
    assert_eq!(out[1], g.end_derivative(1, 1, Side::Right));
    assert_eq!(out[1], DVec2::new(0., 6.));
    assert_eq!(g.end_derivative(1, 1, Side::Left), DVec2::new(2., 0.));
    g.eval_derivs(2.0, 1, &mut out);
    assert_eq!(out[0], DVec2::new(2., 4.));
    assert_eq!(out[1], DVec2::new(0., 2.));
    assert_eq!(g.segment_index(1.0), 1);
    assert_eq!(g.segment_index(0.999), 0);
    assert_eq!(g.segment_index(2.0), 1);
    assert_eq!(g.segment_index(-5.0), 0);
    assert_eq!(g.segment_index(f64::NAN), 0);
    let j = g.joint_jumps(2);
    assert_eq!(j.len(), 1);
    assert_eq!(j[0][0], 0.0);
    assert!(j[0][1] > 1.0);
}

#[test]
fn paper_example_breakvalues_make_the_curve_c1() {
    let g = example();
    assert!(
        g.cr_residual(1) <= 1e-12,
        "(2) residual {}",
        g.cr_residual(1)
    );
    let jumps = g.joint_jumps(2);
    assert!(max_jump(&jumps, 0) <= 1e-12 && max_jump(&jumps, 1) <= 1e-12 * g.joint_scale(1));
    // and they are forced by C¹: Δ_{I−1}/Δ_I = |b_{2I} − b_{2I−1}| / |b_{2I+1} − b_{2I}| = 4/3, 1, 1, 1
    let b = example_points();
    let ratios: Vec<f64> = (1..5)
        .map(|i| b[2 * i].distance(b[2 * i - 1]) / b[2 * i + 1].distance(b[2 * i]))
        .collect();
    for (r, want) in ratios.iter().zip([4. / 3., 1., 1., 1.]) {
        assert!((r - want).abs() < 1e-15);
    }
    // chord-length breakvalues would not be C¹ (curves.md §3.3: residual 4.65)
    let chords: Vec<f64> = (0..5).map(|i| b[2 * i + 2].distance(b[2 * i])).collect();
    let total: f64 = chords.iter().sum();
    let mut u = vec![0.0];
    for c in &chords {
        u.push(u.last().unwrap() + 4.0 * c / total);
    }
    let chord = BezierSpline::new(2, u.clone(), b).unwrap();
    assert!((u[1] - 0.965).abs() < 1e-3 && (u[2] - 2.077).abs() < 1e-3);
    let res = chord.cr_residual(1);
    assert!((res - 4.65).abs() < 0.01, "chord residual {res}");
}

// ---------------------------------------------------------------------------------------------------
// §4 item 19: the breakpoints stay

#[test]
fn item19_breakpoints_and_joint_values_are_kept() {
    let g = example();
    let mut rng = Lcg(19);
    for table in [
        fig1(),
        fig2(),
        random_alphas(&mut rng, 2, 5, 0.95).rows().to_vec(),
    ] {
        let rem = Remodelling::new(g.clone(), AlphaTable::new(2, 5, table).unwrap(), None).unwrap();
        let gs = rem.elevated();
        assert_eq!(gs.degree(), 3);
        assert_eq!(gs.points().len(), 3 * 5 + 1);
        for (i, &u) in EXAMPLE_BREAKS.iter().enumerate() {
            assert!((gs.points()[3 * i] - g.points()[2 * i]).max_abs() <= 1e-14);
            assert!(
                (gs.eval(u) - g.eval(u)).max_abs() <= 1e-14 * 21.0,
                "I = {i}"
            );
        }
    }
}

// ---------------------------------------------------------------------------------------------------
// §4 item 20: the classical elevation reproduces g

#[test]
fn item20_classical_alphas_reproduce_g() {
    let g = example();
    let rem = Remodelling::new(g.clone(), AlphaTable::classical(2, 5), None).unwrap();
    let d = max_diff(rem.elevated(), &g, 0);
    assert!(d <= 1e-12, "{d}");
    // derivatives too (same curve, same parameterisation)
    assert!(max_diff(rem.elevated(), &g, 2) <= 1e-10);
    let mut rng = Lcg(20);
    for m in 1..=7 {
        let g: BezierSpline<DVec3> = random_spline(&mut rng, m, 5);
        let rem = Remodelling::new(g.clone(), AlphaTable::classical(m, 5), None).unwrap();
        let d = max_diff(rem.elevated(), &g, 0);
        assert!(d <= 1e-12 * 10.0, "m = {m}: {d}");
        // classical alphas already satisfy (9) for every admissible r: enforcing changes nothing
        let enforced = AlphaTable::classical(m, 5).enforce(m / 2).unwrap();
        for (a, b) in enforced
            .rows()
            .iter()
            .flatten()
            .zip(AlphaTable::classical(m, 5).rows().iter().flatten())
        {
            assert!((a - b).abs() < 1e-15);
        }
    }
    // a non-classical table does change g
    let rem = Remodelling::new(g.clone(), AlphaTable::new(2, 5, fig1()).unwrap(), None).unwrap();
    assert!(max_diff(rem.elevated(), &g, 0) > 0.1);
}

// ---------------------------------------------------------------------------------------------------
// §4 item 21: C^r kept after enforcing (9), C^{r+1} generally lost

fn check_cr_kept<P: Point>(m: usize, r: usize, seed: u64) {
    let mut rng = Lcg(seed);
    let l = 6;
    let g: BezierSpline<P> = random_spline(&mut rng, m, l);
    let max_last = if r >= 2 { 0.95 / r as f64 } else { 0.95 };
    let raw = random_alphas(&mut rng, m, l, max_last);
    let rem = Remodelling::new(g.clone(), raw.clone(), Some(r)).unwrap();
    let gs = rem.elevated();
    let jumps = gs.joint_jumps(r + 1);
    for i in 0..=r {
        let rel = max_jump(&jumps, i) / gs.joint_scale(i);
        assert!(
            rel <= 1e-12,
            "m = {m}, r = {r}, order {i}: relative jump {rel}"
        );
    }
    let res = gs.cr_residual(r);
    let scale = gs
        .points()
        .iter()
        .map(|p| p.max_abs())
        .fold(1.0, f64::max)
        .powi(1)
        * 10f64.powi(r as i32);
    assert!(res <= 1e-12 * scale, "m = {m}, r = {r}: (8) residual {res}");
    // the next order is generally lost (this is what makes the test able to fail)
    let next = max_jump(&jumps, r + 1) / gs.joint_scale(r + 1);
    assert!(
        next > 1e-3,
        "m = {m}, r = {r}: C^{} jump unexpectedly {next}",
        r + 1
    );
    // and without (9) the same random table breaks C¹ (r ≥ 1)
    if r >= 1 {
        let free = Remodelling::new(g, raw, None).unwrap();
        let j = free.elevated().joint_jumps(1);
        assert!(max_jump(&j, 0) <= 1e-12 * 10.0);
        assert!(max_jump(&j, 1) / free.elevated().joint_scale(1) > 1e-3);
    }
}

#[test]
fn item21_enforcing_eq9_keeps_cr() {
    for m in 1..=8 {
        for r in 0..=m / 2 {
            check_cr_kept::<DVec2>(m, r, 100 + (m * 10 + r) as u64);
            check_cr_kept::<DVec3>(m, r, 200 + (m * 10 + r) as u64);
        }
    }
}

#[test]
fn item21_original_must_be_cr_and_example_tables_are_c1() {
    // the paper's Fig. 1 and Fig. 2 tables satisfy (9) for r = 1 already: enforcing changes nothing
    for table in [fig1(), fig2()] {
        let t = AlphaTable::new(2, 5, table.clone()).unwrap();
        let e = t.enforce(1).unwrap();
        for (a, b) in e.rows().iter().flatten().zip(table.iter().flatten()) {
            assert!((a - b).abs() < 1e-15);
        }
        let rem = Remodelling::new(example(), t, Some(1)).unwrap();
        let gs = rem.elevated();
        assert!(
            gs.cr_residual(1) <= 1e-12 * 21.0,
            "(8) residual {}",
            gs.cr_residual(1)
        );
        let j = gs.joint_jumps(2);
        assert!(max_jump(&j, 1) <= 1e-12 * gs.joint_scale(1));
        assert!(max_jump(&j, 2) > 1.0); // C² is not kept (nor was it there)
    }
}

#[test]
fn roles_of_eq9() {
    // m = 5, r = 2, L = 3
    let roles = alpha_roles(5, 3, 2);
    use AlphaRole::*;
    assert_eq!(roles[0], vec![Free, Free, Free, FromOwnLast { p: 2 }, Free]);
    assert_eq!(
        roles[1],
        vec![
            FromPrevious { p: 1 },
            FromPrevious { p: 2 },
            Free,
            FromOwnLast { p: 2 },
            Free
        ]
    );
    assert_eq!(
        roles[2],
        vec![
            FromPrevious { p: 1 },
            FromPrevious { p: 2 },
            Free,
            Free,
            Free
        ]
    );
    assert_eq!(
        FromPrevious { p: 2 }.describe(5, 1, 2),
        "α_2^(1) = 1 − 2·α_5^(0)  (eq. 9)"
    );
    assert_eq!(
        FromOwnLast { p: 2 }.describe(5, 0, 4),
        "α_4^(0) = 2·α_5^(0)  (eq. 9)"
    );
    // one segment, or r = 0: everything free
    assert!(alpha_roles(4, 1, 2).iter().flatten().all(|r| r.is_free()));
    assert!(alpha_roles(4, 3, 0).iter().flatten().all(|r| r.is_free()));
    // the paper's example: α_1^{(I)}, I ≥ 1, fixed
    let roles = alpha_roles(2, 5, 1);
    assert!(roles[0].iter().all(|r| r.is_free()));
    for row in &roles[1..] {
        assert_eq!(row[0], FromPrevious { p: 1 });
        assert!(row[1].is_free());
    }
}

// ---------------------------------------------------------------------------------------------------
// §4 item 22: curvature formulas (13)–(15)

fn direct_curvature<P: Point>(g: &BezierSpline<P>, i: usize) -> f64 {
    let mut out = [P::ZERO; 3];
    g.eval_derivs(g.breaks()[i], 2, &mut out);
    curvature(out[1], out[2])
}

#[test]
fn item22_eq13_and_corrected_eq14_match_the_direct_curvature() {
    let mut rng = Lcg(22);
    for m in 2..=7 {
        for r in 0..=m / 2 {
            let g: BezierSpline<DVec3> = random_spline(&mut rng, m, 5);
            let max_last = if r >= 2 { 0.9 / r as f64 } else { 0.9 };
            let rem = Remodelling::new(g.clone(), random_alphas(&mut rng, m, 5, max_last), Some(r))
                .unwrap();
            for i in 0..=5 {
                let k = direct_curvature(&g, i);
                assert!(
                    (rem.curvature_original(i) - k).abs() <= 1e-12 * k.max(1.0),
                    "(13) m={m} I={i}"
                );
                let ks = direct_curvature(rem.elevated(), i);
                assert!(
                    (rem.curvature(i) - ks).abs() <= 1e-12 * ks.max(1.0),
                    "(14) m={m} I={i}: {} vs {ks}",
                    rem.curvature(i)
                );
                assert!((rem.curvature_measured(i) - ks).abs() <= 1e-15 * ks.max(1.0));
            }
        }
    }
    // the paper's example (planar): same
    let rem = Remodelling::new(example(), AlphaTable::new(2, 5, fig2()).unwrap(), Some(1)).unwrap();
    for i in 0..=5 {
        let ks = direct_curvature(rem.elevated(), i);
        assert!((rem.curvature(i) - ks).abs() <= 1e-12 * ks.max(1.0));
        assert!(ks > 0.0);
    }
}

#[test]
fn item22_eq15_at_the_ends_always_interior_for_r_ge_2_and_right_sided_form_always() {
    let mut rng = Lcg(15);
    let mut printed_wrong_for_r1 = 0.0_f64;
    for m in 2..=7 {
        for r in 0..=m / 2 {
            let g: BezierSpline<DVec2> = random_spline(&mut rng, m, 5);
            let max_last = if r >= 2 { 0.9 / r as f64 } else { 0.9 };
            let rem =
                Remodelling::new(g, random_alphas(&mut rng, m, 5, max_last), Some(r)).unwrap();
            for i in 0..=5 {
                let ks = rem.curvature(i);
                let rel = |x: f64| (x - ks).abs() / ks.max(1e-300);
                // the general right-sided form holds for every r
                assert!(
                    rel(rem.curvature_predicted(i)) <= 1e-10,
                    "m={m} r={r} I={i}: {}",
                    rel(rem.curvature_predicted(i))
                );
                // the printed (15): at the ends always; interior only for r ≥ 2
                if i == 0 || i == 5 || r >= 2 {
                    assert!(
                        rel(rem.curvature_printed(i)) <= 1e-10,
                        "printed m={m} r={r} I={i}"
                    );
                } else if r == 1 {
                    printed_wrong_for_r1 = printed_wrong_for_r1.max(rel(rem.curvature_printed(i)));
                }
            }
        }
    }
    // for r = 1 the printed interior formula is wrong (curves.md §3.2: relative error 7.1, 12.2)
    assert!(printed_wrong_for_r1 > 0.5, "{printed_wrong_for_r1}");
}

#[test]
fn eq15_remarks_b_c_d() {
    // b) m²/(m²−1)
    for (m, want) in [(4, 16. / 15.), (5, 25. / 24.), (6, 36. / 35.)] {
        let g: BezierSpline<DVec2> = random_spline(&mut Lcg(m as u64), m, 1);
        let rem = Remodelling::new(g, AlphaTable::classical(m, 1), None).unwrap();
        // classical: α_2/α_1² = (m−1)(m+1)/m² → ratio 1 exactly; factor alone:
        let a1 = m as f64 / (m as f64 + 1.0);
        let a2 = (m as f64 - 1.0) / (m as f64 + 1.0);
        assert!((rem.curvature_ratio(0) * a1 * a1 / a2 - want).abs() < 1e-15);
    }
    // c) interior ratio 1 at α_m^{(I−1)} = 1/(m+1), strictly decreasing on [0, 1/2]; r = 2 so (9) fixes α_1, α_2
    for m in 4..=8 {
        let g: BezierSpline<DVec2> = random_spline(&mut Lcg(30 + m as u64), m, 2);
        let ratio_at = |am: f64| {
            let mut rows = AlphaTable::classical(m, 2).rows().to_vec();
            rows[0][m - 1] = am;
            let rem =
                Remodelling::new(g.clone(), AlphaTable::new(m, 2, rows).unwrap(), Some(2)).unwrap();
            rem.curvature_ratio(1)
        };
        assert!(
            (ratio_at(1.0 / (m as f64 + 1.0)) - 1.0).abs() <= 3e-16 * 4.0,
            "m = {m}"
        );
        let xs = uniform_params(0.01, 0.49, 60);
        for w in xs.windows(2) {
            assert!(ratio_at(w[1]) < ratio_at(w[0]));
        }
        // and the measured curvature agrees with the ratio
        let mut rows = AlphaTable::classical(m, 2).rows().to_vec();
        rows[0][m - 1] = 0.3;
        let rem =
            Remodelling::new(g.clone(), AlphaTable::new(m, 2, rows).unwrap(), Some(2)).unwrap();
        let k = rem.curvature_original(1);
        assert!(
            (rem.curvature_measured(1) - rem.curvature_ratio(1) * k).abs() <= 1e-10 * k.max(1.0)
        );
    }
    // d) start and end ratios are 1 for the classical end parameters
    for m in 2..=6 {
        let g: BezierSpline<DVec2> = random_spline(&mut Lcg(40 + m as u64), m, 3);
        let rem = Remodelling::new(g, AlphaTable::classical(m, 3), None).unwrap();
        assert!((rem.curvature_ratio(0) - 1.0).abs() < 1e-15);
        assert!((rem.curvature_ratio(3) - 1.0).abs() < 1e-15);
        assert!(
            (rem.curvature(0) - rem.curvature_original(0)).abs()
                <= 1e-12 * rem.curvature_original(0).max(1.0)
        );
    }
}

// ---------------------------------------------------------------------------------------------------
// the paper's curve example, Fig. 1 / Fig. 2

#[test]
fn fig1_control_points() {
    let rem = Remodelling::new(example(), AlphaTable::new(2, 5, fig1()).unwrap(), Some(1)).unwrap();
    let b = rem.elevated().points();
    let want = [
        DVec2::new(10., 16.),
        DVec2::new(8., 58. / 3.),
        DVec2::new(6.8, 20.4),
        DVec2::new(3., 9.),
    ];
    for (k, w) in want.iter().enumerate() {
        assert!((b[k] - *w).max_abs() <= 1e-14 * 21.0, "b*_{k} = {:?}", b[k]);
    }
    for (a, b) in rem
        .alphas()
        .rows()
        .iter()
        .flatten()
        .zip(fig1().iter().flatten())
    {
        assert!((a - b).abs() < 1e-15);
    }
    // the remark after the example: decreasing α_2^{(I−1)} pulls g* towards the joint b*_{3I} — the
    // curvature there grows
    let mut rows = fig1();
    rows[1][1] = 0.2;
    let k_before = Remodelling::new(example(), AlphaTable::new(2, 5, fig1()).unwrap(), Some(1))
        .unwrap()
        .curvature(2);
    let k_after = Remodelling::new(example(), AlphaTable::new(2, 5, rows).unwrap(), Some(1))
        .unwrap()
        .curvature(2);
    assert!(k_after != k_before);
}

// ---------------------------------------------------------------------------------------------------
// B-spline → Bézier

#[test]
fn bspline_conversion_is_the_same_curve() {
    let mut rng = Lcg(5);
    for p in 1..=5 {
        // unclamped knots with a double interior knot
        let n = p + 6;
        let mut knots: Vec<f64> = (0..n + p + 1)
            .map(|i| i as f64 + 0.3 * rng.next())
            .collect();
        knots.sort_by(|a, b| a.partial_cmp(b).unwrap());
        if p >= 2 {
            knots[p + 2] = knots[p + 1];
        }
        let pts: Vec<DVec2> = (0..n)
            .map(|_| DVec2::new(rng.range(-3., 3.), rng.range(-3., 3.)))
            .collect();
        let b = BSplineCurve::new(p, knots.clone(), pts).unwrap();
        let g = BezierSpline::from_bspline(&b).unwrap();
        assert_eq!(g.domain(), b.domain());
        assert_eq!(g.degree(), p);
        assert!(
            max_diff(&g, &b, 0) <= 1e-12,
            "p = {p}: {}",
            max_diff(&g, &b, 0)
        );
        assert!(max_diff(&g, &b, 2) <= 1e-9);
        // C^{p−1} at simple knots, in Bézier form
        if p >= 2 {
            assert!(g.cr_residual(p - 2) <= 1e-12 * 10.0);
        }
    }
    // a discontinuous B-spline cannot be a Bézier spline
    let b = BSplineCurve::new(
        1,
        vec![0., 0., 1., 1., 2., 2.],
        vec![DVec2::ZERO, DVec2::X, DVec2::Y, DVec2::ONE],
    )
    .unwrap();
    assert_eq!(
        BezierSpline::from_bspline(&b).unwrap_err().kind(),
        ErrorKind::Degenerate
    );
}

// ---------------------------------------------------------------------------------------------------
// surfaces (§4.1, item 23)

fn table_points() -> Vec<DVec3> {
    // b_{k,l}, k = 0..6 along u, l = 0..3 along v (§3.4 of curves.md; repeated rows merged)
    let rows: [[[f64; 3]; 4]; 7] = [
        [[0., 0., 3.], [0., 1., 2.], [0., 3., 1.], [0., 4., 3.]],
        [[1., 0., 1.], [1., 1., 4.], [1., 3., 2.], [1., 4., 4.]],
        [[2., 0., 2.5], [2., 1., 3.], [2., 3., 1.], [2., 4., 3.]],
        [[3., 0., 4.], [3., 1., 2.], [3., 3., 0.], [3., 4., 2.]],
        [[4., 0., 2.5], [4., 1., 3.], [4., 3., 1.], [4., 4., 2.5]],
        [[5., 0., 1.], [5., 1., 4.], [5., 3., 2.], [5., 4., 3.]],
        [[6., 0., 3.], [6., 1., 0.], [6., 3., 1.], [6., 4., 2.]],
    ];
    rows.iter()
        .flatten()
        .map(|p| DVec3::new(p[0], p[1], p[2]))
        .collect()
}

fn table_surface() -> BezierSplineSurface<DVec3> {
    BezierSplineSurface::new(2, 3, vec![0., 1., 2., 3.], vec![0., 1.], table_points()).unwrap()
}

fn surface_diff<A: Surface<DVec3>, B: Surface<DVec3>>(a: &A, b: &B, derivs: bool) -> f64 {
    let ((u0, u1), (v0, v1)) = a.domain();
    let (mut oa, mut ob) = ([DVec3::ZERO; 3], [DVec3::ZERO; 3]);
    let mut worst: f64 = 0.0;
    for u in uniform_params(u0, u1, 61) {
        for v in uniform_params(v0, v1, 21) {
            a.eval_derivs(u, v, derivs, &mut oa);
            b.eval_derivs(u, v, derivs, &mut ob);
            let k = if derivs { 3 } else { 1 };
            for i in 0..k {
                worst = worst.max((oa[i] - ob[i]).max_abs());
            }
        }
    }
    worst
}

#[test]
fn surface_evaluation_matches_the_bspline_surface() {
    let g = table_surface();
    let b = BSplineSurface::new(
        2,
        3,
        vec![0., 0., 0., 1., 1., 2., 2., 3., 3., 3.],
        vec![0., 0., 0., 0., 1., 1., 1., 1.],
        7,
        4,
        table_points(),
    )
    .unwrap();
    assert!(surface_diff(&g, &b, true) <= 1e-12);
}

#[test]
fn item23_surface_example() {
    let g = table_surface();
    // the table is C¹ in u but not C²
    let j = g.u_jumps(2);
    assert!(max_jump(&j, 0) == 0.0 && max_jump(&j, 1) <= 1e-12);
    assert!(max_jump(&j, 2) > 1.0);
    // the usual elevation (2/3, 1/3) reproduces G
    let usual = vec![vec![2. / 3., 1. / 3.]; 3];
    let rem =
        SurfaceRemodelling::new(g.clone(), AlphaTable::new(2, 3, usual).unwrap(), Some(1)).unwrap();
    assert!(surface_diff(&rem, &g, false) <= 1e-12);
    assert_eq!(rem.elevated().size(), (10, 4));
    // Fig. 5: C¹ in u
    let fig5 = vec![
        vec![0.5, 1. / 500.],
        vec![499. / 500., 1. / 1000.],
        vec![999. / 1000., 0.8],
    ];
    let rem = SurfaceRemodelling::new(
        g.clone(),
        AlphaTable::new(2, 3, fig5.clone()).unwrap(),
        Some(1),
    )
    .unwrap();
    for (a, b) in rem
        .alphas()
        .rows()
        .iter()
        .flatten()
        .zip(fig5.iter().flatten())
    {
        assert!((a - b).abs() < 1e-15); // the table already satisfies (19)
    }
    let j = rem.elevated().u_jumps(1);
    assert!(
        max_jump(&j, 0) <= 1e-12 && max_jump(&j, 1) <= 1e-12 * 10.0,
        "{j:?}"
    );
    assert!(surface_diff(&rem, &g, false) > 0.1); // it is remodelled
                                                  // every α = 1/3 taken literally: not C¹, ∂G*/∂u jumps by 1.5; G* differs from G by up to 0.294
    let literal = AlphaTable::new(2, 3, vec![vec![1. / 3., 1. / 3.]; 3]).unwrap();
    let rem = SurfaceRemodelling::new(g.clone(), literal.clone(), None).unwrap();
    let j = rem.elevated().u_jumps(1);
    assert!(max_jump(&j, 0) <= 1e-12);
    assert!((max_jump(&j, 1) - 1.5).abs() < 1e-12, "{j:?}");
    let d = surface_diff(&rem, &g, false);
    assert!((d - 0.294).abs() < 0.01, "{d}");
    // enforcing (19) repairs it: α_1^{(I)} becomes 1 − α_2^{(I−1)} = 2/3
    let rem = SurfaceRemodelling::new(g, literal, Some(1)).unwrap();
    assert!((rem.alphas().get(1, 1) - 2. / 3.).abs() < 1e-15);
    assert!(max_jump(&rem.elevated().u_jumps(1), 1) <= 1e-12 * 10.0);
}

#[test]
fn surface_columns_are_remodelled_curves() {
    let g = table_surface();
    let t = AlphaTable::new(
        2,
        3,
        vec![vec![0.5, 0.002], vec![0.998, 0.001], vec![0.999, 0.8]],
    )
    .unwrap();
    let rem = SurfaceRemodelling::new(g.clone(), t.clone(), Some(1)).unwrap();
    for l in 0..4 {
        let curve = BezierSpline::new(2, vec![0., 1., 2., 3.], g.column(l)).unwrap();
        let e = elevate(&curve, &t).unwrap();
        assert_eq!(e.points(), rem.elevated().column(l).as_slice());
    }
}

// ---------------------------------------------------------------------------------------------------
// bad input

#[test]
fn bad_input_names_the_field() {
    let pts = example_points();
    let e = BezierSpline::new(2, vec![0., 1., 1., 2., 3., 4.], pts.clone()).unwrap_err();
    assert_eq!(
        (e.kind(), e.field()),
        (ErrorKind::NotIncreasing, "breaks[2]")
    );
    let e = BezierSpline::new(2, vec![0., 1., 2.], pts.clone()).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::SizeMismatch, "points"));
    let e = BezierSpline::new(2, EXAMPLE_BREAKS.to_vec(), pts[..9].to_vec()).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::TooFew, "points"));
    let e = BezierSpline::new(0, EXAMPLE_BREAKS.to_vec(), pts.clone()).unwrap_err();
    assert_eq!(e.field(), "degree");
    let e = BezierSpline::new(2, vec![0.], vec![DVec2::ZERO]).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::TooFew, "breaks"));
    let e = BezierSpline::new(2, vec![0., f64::NAN], pts[..3].to_vec()).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::NotFinite, "breaks[1]"));
    let mut bad = pts.clone();
    bad[4].y = f64::INFINITY;
    let e = BezierSpline::new(2, EXAMPLE_BREAKS.to_vec(), bad).unwrap_err();
    assert_eq!(e.field(), "points[4]");

    let mut t = fig1();
    t[2][1] = 1.0;
    let e = AlphaTable::new(2, 5, t).unwrap_err();
    assert_eq!(
        (e.kind(), e.field()),
        (ErrorKind::OutOfRange, "alphas[2][1]")
    );
    let mut t = fig1();
    t[0][0] = -0.1;
    assert_eq!(
        AlphaTable::new(2, 5, t).unwrap_err().field(),
        "alphas[0][0]"
    );
    let e = AlphaTable::new(2, 5, fig1()[..4].to_vec()).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::SizeMismatch, "alphas"));
    let mut t = fig1();
    t[3].push(0.5);
    assert_eq!(AlphaTable::new(2, 5, t).unwrap_err().field(), "alphas[3]");
    let e = AlphaTable::new(2, 5, fig1())
        .unwrap()
        .enforce(2)
        .unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::OutOfRange, "r"));
    // r = 2 needs α_m < 1/2: α_4^{(0)} = 0.6 would make α_3^{(0)} = 1.2
    let mut rows = AlphaTable::classical(4, 2).rows().to_vec();
    rows[0][3] = 0.6;
    let e = AlphaTable::new(4, 2, rows).unwrap().enforce(2).unwrap_err();
    assert_eq!(e.field(), "alphas[0][3]");
    // a table for another spline
    let e = Remodelling::new(example(), AlphaTable::classical(3, 5), None).unwrap_err();
    assert_eq!(e.field(), "alphas");
    // surfaces
    let e =
        BezierSplineSurface::new(2, 3, vec![0., 1., 2.], vec![0., 1.], table_points()).unwrap_err();
    assert_eq!((e.kind(), e.field()), (ErrorKind::SizeMismatch, "points"));
    let e = BezierSplineSurface::new(2, 3, vec![0., 1., 2., 3.], vec![1., 1.], table_points())
        .unwrap_err();
    assert_eq!(e.field(), "breaksV[1]");
    let e =
        SurfaceRemodelling::new(table_surface(), AlphaTable::classical(2, 2), None).unwrap_err();
    assert_eq!(e.field(), "alphas");
}

#[test]
fn osculating_circle_of_a_parabola_and_of_the_example() {
    use splinelab::bezier::osculating_circle;
    // y = x² on [−1, 1] as one quadratic: curvature 2 at the vertex, centre (0, 1/2)
    let g = BezierSpline::new(
        2,
        vec![-1.0, 1.0],
        vec![DVec2::new(-1., 1.), DVec2::new(0., -1.), DVec2::new(1., 1.)],
    )
    .unwrap();
    let (c, r) = osculating_circle(&g, 0.0);
    assert!((c - DVec2::new(0., 0.5)).length() < 1e-15 && (r - 0.5).abs() < 1e-15);
    // radius = 1/K* at every breakpoint of the remodelled example
    let rem = Remodelling::new(example(), AlphaTable::new(2, 5, fig1()).unwrap(), Some(1)).unwrap();
    for (i, &u) in EXAMPLE_BREAKS.iter().enumerate() {
        let (c, r) = osculating_circle(rem.elevated(), u);
        let k = rem.curvature(i);
        assert!((r * k - 1.0).abs() < 1e-10, "I = {i}");
        assert!(((c - rem.elevated().eval(u)).length() - r).abs() < 1e-10 * r.max(1.0));
    }
    // a straight segment has none
    let line = BezierSpline::new(
        2,
        vec![0.0, 1.0],
        vec![DVec2::ZERO, DVec2::X, DVec2::X * 2.0],
    )
    .unwrap();
    assert_eq!(osculating_circle(&line, 0.5).1, 0.0);
}

// ---------------------------------------------------------------------------------------------------
// robustness: arbitrary input gives an Error or finite values, never a panic

mod fuzz {
    use super::*;
    use proptest::prelude::*;
    use splinelab::bezier::check_r;

    fn coord() -> impl Strategy<Value = f64> {
        prop_oneof![-10.0..10.0, -1e8..1e8, -1e-8..1e-8, Just(0.0)]
    }

    proptest! {
        #![proptest_config(ProptestConfig { cases: 1500, ..ProptestConfig::default() })]

        #[test]
        fn remodelling_never_panics(
            degree in 0usize..7,
            breaks in prop::collection::vec(-3.0..3.0f64, 0..6),
            pts in prop::collection::vec((coord(), coord()), 0..40),
            alphas in prop::collection::vec(-0.2..1.2f64, 0..40),
            r in 0usize..5,
            enforce in any::<bool>(),
            at in prop::collection::vec(-10.0..10.0f64, 0..10),
        ) {
            let pts: Vec<DVec2> = pts.into_iter().map(|(x, y)| DVec2::new(x, y)).collect();
            let Ok(g) = BezierSpline::new(degree, breaks, pts) else { return Ok(()) };
            let (m, l) = (g.degree(), g.segments());
            let rows: Vec<Vec<f64>> = (0..l).map(|i| (0..m).map(|k| alphas.get(i * m + k).copied().unwrap_or(0.5)).collect()).collect();
            let Ok(table) = AlphaTable::new(m, l, rows) else { return Ok(()) };
            let en = if enforce && check_r(m, r).is_ok() { Some(r) } else { None };
            let Ok(rem) = Remodelling::new(g, table, en) else { return Ok(()) };
            for &u in &at {
                let mut o = [DVec2::ZERO; 3];
                rem.eval_derivs(u, 2, &mut o);
                prop_assert!(o[0].is_finite());
            }
            for i in 0..=l {
                let _ = (rem.curvature(i), rem.curvature_original(i), rem.curvature_measured(i), rem.curvature_predicted(i), rem.curvature_printed(i));
            }
            let _ = rem.elevated().joint_jumps(r + 1);
            let _ = rem.elevated().cr_residual(r);
        }

        #[test]
        fn bspline_conversion_never_panics(degree in 0usize..6, pts in prop::collection::vec((coord(), coord()), 0..12), raw in prop::collection::vec(-5.0..5.0f64, 0..20)) {
            let pts: Vec<DVec2> = pts.into_iter().map(|(x, y)| DVec2::new(x, y)).collect();
            let mut k = raw;
            k.sort_by(|a, b| a.partial_cmp(b).unwrap());
            if let Ok(c) = BSplineCurve::new(degree, k, pts) {
                if let Ok(g) = BezierSpline::from_bspline(&c) {
                    let (a, b) = c.domain();
                    for u in uniform_params(a, b, 7) {
                        let (p, q) = (g.eval(u), c.eval(u));
                        let scale = c.points().iter().map(|p| p.max_abs()).fold(1.0, f64::max);
                        prop_assert!((p - q).max_abs() <= 1e-9 * scale, "{p:?} vs {q:?}");
                    }
                }
            }
        }

        #[test]
        fn surface_never_panics(mu in 0usize..4, nv in 0usize..4, lu in 1usize..4, uv in prop::collection::vec((-1.0..4.0f64, -1.0..2.0f64), 0..10), al in 0.01..0.99f64) {
            let rows = mu * lu + 1;
            let cols = nv + 1;
            let pts: Vec<DVec3> = (0..rows * cols).map(|i| DVec3::new(i as f64, (i % 3) as f64, (i % 5) as f64)).collect();
            let breaks_u: Vec<f64> = (0..=lu).map(|i| i as f64).collect();
            let Ok(s) = BezierSplineSurface::new(mu, nv, breaks_u, vec![0.0, 1.0], pts) else { return Ok(()) };
            let Ok(rem) = SurfaceRemodelling::new(s, AlphaTable::new(mu, lu, vec![vec![al; mu]; lu]).unwrap(), None) else { return Ok(()) };
            for (u, v) in uv {
                let mut o = [DVec3::ZERO; 3];
                rem.eval_derivs(u, v, true, &mut o);
                prop_assert!(o[0].is_finite() && o[1].is_finite() && o[2].is_finite());
            }
            let _ = rem.elevated().u_jumps(2);
        }
    }
}

/// Regression (found by the API fuzzer): α = 1e-300 made the predicted curvature α_2/α_1² infinite. α must
/// now stay at least 1e-9 from 0 and 1, with an error naming the entry.
#[test]
fn alphas_too_close_to_the_ends_are_rejected() {
    use splinelab::bezier::AlphaTable;
    let e = AlphaTable::new(2, 1, vec![vec![1e-300, 0.5]]).unwrap_err();
    assert_eq!(e.field(), "alphas[0][0]");
    let e = AlphaTable::new(2, 1, vec![vec![0.5, 1.0 - 1e-12]]).unwrap_err();
    assert_eq!(e.field(), "alphas[0][1]");
    assert!(AlphaTable::new(2, 1, vec![vec![1e-6, 0.5]]).is_ok());
}

/// The work arrays of the segment evaluator hold `MAX_BEZIER_DEGREE + 2` points: the largest spline it takes
/// (degree MAX + 1, the elevation of a degree-MAX input) is evaluated with all its control points. Checked against
/// the Bernstein sum Σ C(d, i) tⁱ (1 − t)^(d − i) Pᵢ computed here, with its derivative by the same sum of
/// d·(Pᵢ₊₁ − Pᵢ) (a work array one point short drops the last control points: the values differ by ~1).
#[test]
fn the_largest_degree_is_evaluated_with_every_control_point() {
    use splinelab::bezier::MAX_BEZIER_DEGREE;
    let d = MAX_BEZIER_DEGREE + 1;
    let pts: Vec<DVec2> = (0..=d)
        .map(|i| DVec2::new(i as f64, ((i * 7) % 5) as f64 - 2.0))
        .collect();
    let spline = BezierSpline::new(d, vec![0.0, 2.0], pts.clone()).unwrap();
    let bernstein = |p: &[DVec2], t: f64| {
        let n = p.len() - 1;
        let mut c = 1.0_f64; // C(n, i), updated in the loop
        let mut s = DVec2::ZERO;
        for (i, q) in p.iter().enumerate() {
            s += *q * (c * t.powi(i as i32) * (1.0 - t).powi((n - i) as i32));
            c *= (n - i) as f64 / (i + 1) as f64;
        }
        s
    };
    let diffs: Vec<DVec2> = pts.windows(2).map(|w| (w[1] - w[0]) * d as f64).collect();
    for k in 0..=10 {
        let t = k as f64 / 10.0;
        let mut out = [DVec2::ZERO; 3];
        spline.eval_derivs(2.0 * t, 1, &mut out);
        let want = bernstein(&pts, t);
        let want_d = bernstein(&diffs, t) / 2.0; // d/du = (1/h) d/dt, h = 2
        assert!(
            (out[0] - want).length() < 1e-9,
            "t = {t}: {:?} vs {:?}",
            out[0],
            want
        );
        assert!(
            (out[1] - want_d).length() < 1e-7,
            "t = {t}: derivative {:?} vs {:?}",
            out[1],
            want_d
        );
    }
}
