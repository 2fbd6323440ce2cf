//! Bi-degree remodelling of a Bézier spline surface (Gânscă–Coman–Ţămbulea §4.2, rebuilt as the curve
//! remodelling in u and then in v): class C^{r,s} kept, corner points interpolated, classical parameters
//! reproduce the surface, bad input named.

use glam::DVec3;
use splinelab::bezier::{
    AlphaTable, BezierSpline, BezierSplineSurface, BiRemodelling, DirectionParams,
};
use splinelab::bspline::BSplineCurve;
use splinelab::sample::uniform_params;
use splinelab::{Curve, Point, Surface};

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

fn knots(rng: &mut Lcg, p: usize, segs: usize) -> Vec<f64> {
    let mut k = vec![0.0; p + 1];
    let mut t = 0.0;
    for _ in 1..segs {
        t += rng.range(0.5, 2.0);
        k.push(t);
    }
    t += rng.range(0.5, 2.0);
    k.extend(std::iter::repeat_n(t, p + 1));
    k
}

/// A random tensor B-spline surface of degrees (m, n) with simple knots (class C^{m−1, n−1}) in Bézier form.
fn random_surface(
    rng: &mut Lcg,
    m: usize,
    n: usize,
    l: usize,
    mm: usize,
) -> BezierSplineSurface<DVec3> {
    let (ku, kv) = (knots(rng, m, l), knots(rng, n, mm));
    let (cu, cv) = (l + m, mm + n);
    let c: Vec<Vec<DVec3>> = (0..cu)
        .map(|_| {
            (0..cv)
                .map(|_| {
                    DVec3::new(
                        rng.range(-5.0, 5.0),
                        rng.range(-5.0, 5.0),
                        rng.range(-5.0, 5.0),
                    )
                })
                .collect()
        })
        .collect();
    // columns to Bézier form in u, then every Bézier row to Bézier form in v
    let cols: Vec<BezierSpline<DVec3>> = (0..cv)
        .map(|j| {
            let pts = (0..cu).map(|i| c[i][j]).collect();
            BezierSpline::from_bspline(&BSplineCurve::new(m, ku.clone(), pts).unwrap()).unwrap()
        })
        .collect();
    let rows = m * l + 1;
    let mut net = Vec::new();
    let mut bu = Vec::new();
    let mut bv = Vec::new();
    for k in 0..rows {
        let pts = (0..cv).map(|j| cols[j].points()[k]).collect();
        let row =
            BezierSpline::from_bspline(&BSplineCurve::new(n, kv.clone(), pts).unwrap()).unwrap();
        net.extend_from_slice(row.points());
        bv = row.breaks().to_vec();
        bu = cols[0].breaks().to_vec();
    }
    BezierSplineSurface::new(m, n, bu, bv, net).unwrap()
}

fn random_table(rng: &mut Lcg, d: usize, segs: usize, max_last: f64) -> AlphaTable {
    let rows = (0..segs)
        .map(|_| {
            (0..d)
                .map(|k| {
                    if k + 1 == d {
                        rng.range(0.05, max_last)
                    } else {
                        rng.range(0.05, 0.95)
                    }
                })
                .collect()
        })
        .collect();
    AlphaTable::new(d, segs, rows).unwrap()
}

fn scale(s: &BezierSplineSurface<DVec3>) -> f64 {
    s.points().iter().map(|p| p.max_abs()).fold(1.0, f64::max)
}

/// The isoparametric curve G(·, v) as a Bézier spline in u: each row of the net is a Bézier spline in v,
/// evaluated at v.
fn u_curve(s: &BezierSplineSurface<DVec3>, v: f64) -> BezierSpline<DVec3> {
    let (m, n) = s.degrees();
    let (rows, cols) = s.size();
    let pts = (0..rows)
        .map(|k| {
            let row = (0..cols).map(|l| s.point(k, l)).collect();
            BezierSpline::new(n, s.breaks_v().to_vec(), row)
                .unwrap()
                .eval(v)
        })
        .collect();
    BezierSpline::new(m, s.breaks_u().to_vec(), pts).unwrap()
}

/// The isoparametric curve G(u, ·) as a Bézier spline in v.
fn v_curve(s: &BezierSplineSurface<DVec3>, u: f64) -> BezierSpline<DVec3> {
    let (m, n) = s.degrees();
    let (rows, cols) = s.size();
    let pts = (0..cols)
        .map(|l| {
            let col = (0..rows).map(|k| s.point(k, l)).collect();
            BezierSpline::new(m, s.breaks_u().to_vec(), col)
                .unwrap()
                .eval(u)
        })
        .collect();
    BezierSpline::new(n, s.breaks_v().to_vec(), pts).unwrap()
}

/// The largest jump of one-sided derivatives of order `order` across the break lines, in u (over
/// isocurves at several v) and in v (over isocurves at several u), relative to the derivative's size.
fn worst_jumps(s: &BezierSplineSurface<DVec3>, order: usize) -> (f64, f64) {
    let ((u0, u1), (v0, v1)) = s.domain();
    let mut ju: f64 = 0.0;
    let mut jv: f64 = 0.0;
    for t in uniform_params(0.0, 1.0, 9) {
        let c = u_curve(s, v0 + (v1 - v0) * t);
        for j in c.joint_jumps(order) {
            ju = ju.max(j[order] / c.joint_scale(order).max(1.0));
        }
        let c = v_curve(s, u0 + (u1 - u0) * t);
        for j in c.joint_jumps(order) {
            jv = jv.max(j[order] / c.joint_scale(order).max(1.0));
        }
    }
    (ju, jv)
}

const CASES: [(usize, usize, usize, usize, usize, usize); 6] = [
    // (m, n, r, s, L, M)
    (4, 4, 2, 2, 3, 3),
    (4, 3, 2, 1, 4, 2),
    (2, 2, 1, 1, 3, 4), // neighbouring v-windows touch (n = 2, s = 1)
    (5, 2, 2, 1, 2, 3),
    (3, 4, 1, 2, 3, 3),
    (2, 3, 0, 1, 2, 2),
];

#[test]
fn classical_parameters_reproduce_the_surface() {
    let mut rng = Lcg(7);
    for (m, n, _, _, l, mm) in CASES {
        let g = random_surface(&mut rng, m, n, l, mm);
        let b = BiRemodelling::new(
            g.clone(),
            DirectionParams::Classical,
            DirectionParams::Classical,
            None,
        )
        .unwrap();
        assert_eq!(b.elevated().degrees(), (m + 1, n + 1));
        assert_eq!(b.elevated().size(), ((m + 1) * l + 1, (n + 1) * mm + 1));
        let ((u0, u1), (v0, v1)) = g.domain();
        let (mut oa, mut ob) = ([DVec3::ZERO; 3], [DVec3::ZERO; 3]);
        for u in uniform_params(u0, u1, 23) {
            for v in uniform_params(v0, v1, 19) {
                g.eval_derivs(u, v, true, &mut oa);
                b.eval_derivs(u, v, true, &mut ob);
                for k in 0..3 {
                    let d = (oa[k] - ob[k]).max_abs();
                    assert!(
                        d <= 1e-12 * scale(&g),
                        "m={m} n={n}: derivative {k} off by {d}"
                    );
                }
            }
        }
    }
}

#[test]
fn enforced_remodelling_keeps_class_c_rs_with_per_line_parameters() {
    let mut rng = Lcg(11);
    for (m, n, r, s, l, mm) in CASES {
        let g = random_surface(&mut rng, m, n, l, mm);
        let (_, cols) = g.size();
        let rows_u = (m + 1) * l + 1;
        let lim = |order: usize| {
            if order == 0 {
                0.95
            } else {
                0.95 / order as f64
            }
        };
        let alphas = (0..cols)
            .map(|_| random_table(&mut rng, m, l, lim(r)))
            .collect();
        let betas = (0..rows_u)
            .map(|_| random_table(&mut rng, n, mm, lim(s)))
            .collect();
        let b = BiRemodelling::new(
            g.clone(),
            DirectionParams::PerLine(alphas),
            DirectionParams::PerLine(betas),
            Some((r, s)),
        )
        .unwrap();
        let e = b.elevated();
        for order in 0..=r.max(s) {
            let (ju, jv) = worst_jumps(e, order);
            if order <= r {
                assert!(
                    ju <= 1e-12,
                    "m={m} n={n} r={r} s={s}: ∂^{order}/∂u^{order} jumps by {ju}"
                );
            }
            if order <= s {
                assert!(
                    jv <= 1e-12,
                    "m={m} n={n} r={r} s={s}: ∂^{order}/∂v^{order} jumps by {jv}"
                );
            }
        }
        // the coefficient-based measure agrees
        let (cu, cv) = b.jumps(r, s);
        let sc = scale(e);
        for row in cu.iter().chain(cv.iter()) {
            for &j in row {
                assert!(j <= 1e-9 * sc, "m={m} n={n}: coefficient jump {j}");
            }
        }
        // corners of every patch are kept, and the surface interpolates G there
        for (i, &u) in g.breaks_u().iter().enumerate() {
            for (j, &v) in g.breaks_v().iter().enumerate() {
                assert_eq!(e.point((m + 1) * i, (n + 1) * j), g.point(m * i, n * j));
                let d = (b.eval(u, v) - g.eval(u, v)).max_abs();
                assert!(d <= 1e-12 * scale(&g), "corner ({i},{j}) off by {d}");
            }
        }
        // and it is a real remodelling: G* ≠ G
        let ((u0, u1), (v0, v1)) = g.domain();
        let (u, v) = (u0 + 0.37 * (u1 - u0), v0 + 0.61 * (v1 - v0));
        assert!((b.eval(u, v) - g.eval(u, v)).max_abs() > 1e-6);
    }
}

#[test]
fn without_the_constraints_the_class_is_lost() {
    let mut rng = Lcg(5);
    let (m, n, l, mm) = (4, 4, 3, 3);
    let g = random_surface(&mut rng, m, n, l, mm);
    let (_, cols) = g.size();
    let alphas = (0..cols)
        .map(|_| random_table(&mut rng, m, l, 0.45))
        .collect();
    let betas = (0..(m + 1) * l + 1)
        .map(|_| random_table(&mut rng, n, mm, 0.45))
        .collect();
    let b = BiRemodelling::new(
        g,
        DirectionParams::PerLine(alphas),
        DirectionParams::PerLine(betas),
        None,
    )
    .unwrap();
    let (ju, jv) = worst_jumps(b.elevated(), 1);
    assert!(ju > 1e-3 && jv > 1e-3, "first-derivative jumps {ju}, {jv}");
    // C^0 always holds (end rows and columns are kept)
    let (ju, jv) = worst_jumps(b.elevated(), 0);
    assert!(ju <= 1e-12 && jv <= 1e-12);
}

#[test]
fn shared_tables_and_the_window_rule() {
    let mut rng = Lcg(3);
    let (m, n, r, s, l, mm) = (4, 4, 2, 2, 3, 3);
    let g = random_surface(&mut rng, m, n, l, mm);
    let a = random_table(&mut rng, m, l, 0.45);
    let bt = random_table(&mut rng, n, mm, 0.45);
    let b = BiRemodelling::new(
        g.clone(),
        DirectionParams::Shared(a.clone()),
        DirectionParams::Shared(bt),
        Some((r, s)),
    )
    .unwrap();
    assert_eq!(b.alphas().len(), n * mm + 1);
    assert_eq!(b.betas().len(), (m + 1) * l + 1);
    let enforced = a.enforce(r).unwrap();
    assert!(b.alphas().iter().all(|t| *t == enforced));
    let (ju, jv) = worst_jumps(b.elevated(), 2);
    assert!(ju <= 1e-12 && jv <= 1e-11);
    // per-line: the columns nJ − s..nJ + s share the table of column nJ
    let (_, cols) = g.size();
    let tabs: Vec<AlphaTable> = (0..cols)
        .map(|_| random_table(&mut rng, m, l, 0.45))
        .collect();
    let b = BiRemodelling::new(
        g,
        DirectionParams::PerLine(tabs.clone()),
        DirectionParams::Classical,
        Some((r, s)),
    )
    .unwrap();
    // (here n = 2s, so the windows of v_1 and v_2 touch at column 6 and form one group: columns 2..10
    // all take the table of column 4)
    let mut source = None;
    let mut prev_hi = None;
    for j in 1..mm {
        let c = n * j;
        if !matches!(prev_hi, Some(h) if c - s <= h) {
            source = Some(c);
        }
        for w in c - s..=c + s {
            assert_eq!(
                b.alphas()[w],
                tabs[source.unwrap()].enforce(r).unwrap(),
                "column {w}"
            );
        }
        prev_hi = Some(c + s);
    }
    assert_eq!(source, Some(4));
    assert_eq!(b.alphas()[0], tabs[0].enforce(r).unwrap());
}

#[test]
fn bad_parameters_are_named() {
    let mut rng = Lcg(1);
    let g = random_surface(&mut rng, 4, 3, 2, 2);
    let (_, cols) = g.size();
    let e = BiRemodelling::new(
        g.clone(),
        DirectionParams::PerLine(vec![AlphaTable::classical(4, 2); cols - 1]),
        DirectionParams::Classical,
        None,
    )
    .unwrap_err();
    assert_eq!(e.field(), "alphas");
    let mut tabs = vec![AlphaTable::classical(4, 2); cols];
    tabs[3] = AlphaTable::classical(4, 3);
    let e = BiRemodelling::new(
        g.clone(),
        DirectionParams::PerLine(tabs),
        DirectionParams::Classical,
        None,
    )
    .unwrap_err();
    assert_eq!(e.field(), "alphas[3]");
    let e = BiRemodelling::new(
        g.clone(),
        DirectionParams::Classical,
        DirectionParams::Shared(AlphaTable::classical(2, 2)),
        None,
    )
    .unwrap_err();
    assert_eq!(e.field(), "betas");
    // s > ⌊n/2⌋
    let e = BiRemodelling::new(
        g.clone(),
        DirectionParams::Classical,
        DirectionParams::Classical,
        Some((2, 2)),
    )
    .unwrap_err();
    assert!(e.field().starts_with("betas["), "{}", e.field());
    // α_m ≥ 1/r makes eq. (9) leave (0, 1): the responsible entry is named with its column
    let mut rows = AlphaTable::classical(4, 2).rows().to_vec();
    rows[0][3] = 0.7;
    let bad = AlphaTable::new(4, 2, rows).unwrap();
    let mut tabs = vec![AlphaTable::classical(4, 2); cols];
    tabs[0] = bad;
    let e = BiRemodelling::new(
        g,
        DirectionParams::PerLine(tabs),
        DirectionParams::Classical,
        Some((2, 1)),
    )
    .unwrap_err();
    assert_eq!(e.field(), "alphas[0][0][3]");
}
