//! Quasi-cubic curves at explicit parameters (`Curve::sample_into`: runs of parameters in one segment share
//! one Taylor expansion of it, no sine or cosine per point; `src/quasi_cubic/explicit.rs`) against the direct
//! formula (the basis of `curves.md` §1 per point with libm's sin and cos: `eval_curve_generic_into`).
//!
//! Values, first and second derivatives must agree to 1e-13 relative to the data's size: the larger of the
//! direct result's largest magnitude (per buffer) and the control points' (a derivative that is small next to
//! large control points is a cancellation of them, in the direct formula as much as in any other: at the
//! 3D helix's knots at α = −3 the previous per-point formula differed from the direct one by 1.5e-13 of the
//! d2 buffer's own largest magnitude, from rounding alone), for parameters sorted (long runs), descending, shuffled (runs of one), in clusters
//! across segment ends, exactly at the knots and next to them, at the domain ends, outside the domain
//! (open: the end segments extrapolate; closed: reduced modulo N), for open 2D / 3D and closed curves, one
//! segment and many, across α ∈ [−3, 3]; and nothing is written past the parameters' share of a buffer.

mod common;
use common::{helix, spiral};
use splinelab::quasi_cubic::QuasiCubicCurve;
use splinelab::sample::{eval_curve_generic_into, uniform_params};
use splinelab::{Curve, Point};

const TOL: f64 = 1e-13;

/// A small deterministic generator (uniform in [0, 1)).
struct Lcg(u64);
impl Lcg {
    fn next(&mut self) -> f64 {
        self.0 = self
            .0
            .wrapping_mul(6_364_136_223_846_793_005)
            .wrapping_add(1_442_695_040_888_963_407);
        (self.0 >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Fisher–Yates.
    fn shuffle(&mut self, v: &mut [f64]) {
        for i in (1..v.len()).rev() {
            let j = ((self.next() * (i + 1) as f64) as usize).min(i);
            v.swap(i, j);
        }
    }
}

/// The parameter sets of the module docs for a curve with domain [0, n] (`closed`: periodic).
fn parameter_sets(n: f64, closed: bool) -> Vec<(&'static str, Vec<f64>)> {
    let mut r = Lcg(0x5eed);
    let sorted = uniform_params(0.0, n, 20_001);
    let mut descending = sorted.clone();
    descending.reverse();
    let mut shuffled = sorted.clone();
    r.shuffle(&mut shuffled);
    // every knot exactly, its neighbouring floats and points 10⁻⁹ and 10⁻³ away, then the domain ends
    let mut knots = Vec::new();
    for k in 0..=(n as usize) {
        let k = k as f64;
        for d in [-1e-3, -1e-9, 0.0, 1e-9, 1e-3] {
            knots.push(k + d);
        }
        knots.extend([k.next_down(), k.next_up()]);
    }
    knots.extend([0.0, n, 0.0, n]);
    let mut knots_shuffled = knots.clone();
    r.shuffle(&mut knots_shuffled);
    // sorted clusters around random centres, some across a segment end, some wider than a run's window
    let mut clusters = Vec::new();
    for c in 0..400 {
        let centre = if c % 4 == 0 {
            (r.next() * n).round()
        } else {
            r.next() * n
        };
        let (len, step) = (1 + (r.next() * 40.0) as usize, r.next() * 1e-3);
        clusters.extend((0..len).map(|j| centre + step * (j as f64 - len as f64 / 2.0)));
    }
    // outside the domain: open curves extrapolate (runs there too), closed ones reduce modulo N
    let outside: Vec<f64> = (0..200)
        .map(|j| -0.3 + 0.0015 * j as f64)
        .chain((0..200).map(|j| n + 0.0015 * j as f64))
        .chain([-2.5 * n - 0.25, 3.0 * n + 0.125, -n, 2.0 * n])
        .collect();
    let mut sets = vec![
        ("sorted", sorted),
        ("descending", descending),
        ("shuffled", shuffled),
        ("knots", knots),
        ("knots shuffled", knots_shuffled),
        ("clusters", clusters),
        ("outside the domain", outside),
    ];
    if closed {
        // the closed curve's end N is its start: both ends within a short run
        sets.push(("across the period", vec![n - 1e-4, n, n, 0.0, 1e-4]));
    }
    sets
}

/// Largest |fast − direct| relative to the larger of the largest |direct| of the buffer and `data`.
fn rel_err(fast: &[f64], direct: &[f64], data: f64) -> f64 {
    assert_eq!(fast.len(), direct.len());
    let scale = direct.iter().fold(data, |m, x| m.max(x.abs()));
    let worst = fast
        .iter()
        .zip(direct)
        .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
    worst / scale.max(f64::MIN_POSITIVE)
}

/// `c.sample_into` against the direct formula at every parameter set, orders 0, 1, 2; returns the worst
/// relative error.
fn check<P: Point>(name: &str, c: &QuasiCubicCurve<P>) -> f64 {
    let (_, n) = c.domain();
    let closed = c.period().is_some();
    let data = c.points().iter().fold(0.0_f64, |m, p| m.max(p.max_abs()));
    let mut worst = 0.0_f64;
    for (set, params) in parameter_sets(n, closed) {
        let len = params.len() * P::DIM;
        let (mut q0, mut q1, mut q2) = (vec![0.0; len], vec![0.0; len], vec![0.0; len]);
        eval_curve_generic_into(c, &params, 2, &mut q0, &mut q1, &mut q2);
        for order in 0..=2 {
            // one entry more than the parameters need, as a sentinel that must stay untouched
            let buf = |used: bool| vec![f64::NAN; if used { len + 1 } else { 0 }];
            let (mut p0, mut p1, mut p2) = (buf(true), buf(order >= 1), buf(order >= 2));
            c.sample_into(&params, order, &mut p0, &mut p1, &mut p2);
            let mut errs = vec![("points", rel_err(&p0[..len], &q0, data))];
            if order >= 1 {
                errs.push(("d1", rel_err(&p1[..len], &q1, data)));
            }
            if order >= 2 {
                errs.push(("d2", rel_err(&p2[..len], &q2, data)));
            }
            for (what, e) in errs {
                assert!(
                    e <= TOL,
                    "{name}, {set} parameters, derivatives {order}: {what} differ from the direct \
                     formula by {e:e} (relative)"
                );
                worst = worst.max(e);
            }
            for b in [&p0, &p1, &p2] {
                assert!(
                    b.is_empty() || b[len].is_nan(),
                    "{name}, {set}: wrote past the end"
                );
            }
        }
    }
    worst
}

/// Every curve and parameter set of the module docs; prints each curve's worst relative error
/// (`--nocapture`).
#[test]
fn explicit_parameters_match_the_direct_formula() {
    let mut worst = 0.0_f64;
    let mut note = |name: String, e: f64| {
        println!("{name}: worst relative error {e:.2e}");
        worst = worst.max(e);
    };
    for alpha in [-3.0, -0.7, 0.0, 0.5, 1.0, 3.0] {
        let curves2 = [
            ("open 2D", QuasiCubicCurve::new(alpha, spiral(100))),
            ("one segment", QuasiCubicCurve::new(alpha, spiral(4))),
            ("closed 2D", QuasiCubicCurve::closed(alpha, spiral(100))),
            ("closed 5 points", QuasiCubicCurve::closed(alpha, spiral(5))),
        ];
        for (what, c) in curves2 {
            let name = format!("{what} α = {alpha}");
            note(name.clone(), check(&name, &c.unwrap()));
        }
        let curves3 = [
            ("open 3D", QuasiCubicCurve::new(alpha, helix(40))),
            ("closed 3D", QuasiCubicCurve::closed(alpha, helix(12))),
        ];
        for (what, c) in curves3 {
            let name = format!("{what} α = {alpha}");
            note(name.clone(), check(&name, &c.unwrap()));
        }
    }
    println!("explicit parameters vs the direct formula: worst relative error {worst:.2e}");
}

/// Short buffers end the evaluation where they end (the `Curve::sample_into` contract), with runs too.
#[test]
fn explicit_parameters_stop_at_a_short_buffer() {
    let c = QuasiCubicCurve::new(0.5, spiral(10)).unwrap();
    let params = uniform_params(0.0, 7.0, 1000);
    let mut pts = vec![f64::NAN; 2 * 1000];
    let mut d1 = vec![f64::NAN; 2 * 300];
    c.sample_into(&params, 1, &mut pts, &mut d1, &mut []);
    assert!(pts[..600].iter().all(|x| x.is_finite()));
    assert!(pts[600..].iter().all(|x| x.is_nan()));
    assert!(d1.iter().all(|x| x.is_finite()));
}
