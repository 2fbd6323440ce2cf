//! The quasi-cubic uniform sampler (`QuasiCubicCurve::sample_uniform_blocks`: blocks of tabulated sines and
//! cosines, no trig per point) against the direct formula (the basis of `curves.md` §1 per point, libm's sin
//! and cos: `eval_curve_generic_into`) over 10⁶ samples, at α across the whole allowed range [−3, 3].
//!
//! The error is measured relative to the data's size (1 + the largest absolute coordinate of the direct
//! result, per buffer) and must stay ≤ 1e-12, for points, first and second derivatives, open (2D, 3D) and
//! closed curves, and at sample counts that put block and segment ends everywhere.

mod common;
use common::{helix, spiral};
use splinelab::quasi_cubic::QuasiCubicCurve;
use splinelab::sample::{eval_curve_generic_into, uniform_params};
use splinelab::{Curve, Point};

const TOL: f64 = 1e-12;

/// Largest |fast − direct| relative to 1 + max |direct|.
fn rel_err(fast: &[f64], direct: &[f64]) -> f64 {
    assert_eq!(fast.len(), direct.len());
    let scale = 1.0 + direct.iter().fold(0.0_f64, |m, x| m.max(x.abs()));
    let worst = fast
        .iter()
        .zip(direct)
        .fold(0.0_f64, |m, (a, b)| m.max((a - b).abs()));
    worst / scale
}

/// The uniform sampler (values alone, and values with two derivatives) against the direct formula at
/// `count` samples; returns the worst relative error of points, d1, d2.
fn worst_error<P: Point, C: Curve<P>>(name: &str, c: &C, count: usize) -> f64 {
    let (a, b) = c.domain();
    let params = uniform_params(a, b, count);
    let n = count * P::DIM;
    let (mut q, mut e1, mut e2) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    eval_curve_generic_into(c, &params, 2, &mut q, &mut e1, &mut e2);
    let (mut p, mut d1, mut d2) = (vec![0.0; n], vec![0.0; n], vec![0.0; n]);
    c.sample_uniform_derivs_into(count, 2, &mut p, &mut d1, &mut d2);
    let mut v = vec![0.0; n];
    c.sample_uniform_into(count, &mut v);
    let errs = [
        rel_err(&v, &q),
        rel_err(&p, &q),
        rel_err(&d1, &e1),
        rel_err(&d2, &e2),
    ];
    let worst = errs.iter().fold(0.0_f64, |m, &e| m.max(e));
    assert!(
        worst <= TOL,
        "{name}, {count} samples: the uniform sampler differs from the direct formula by {worst:e} \
         (relative; values {:e}, points {:e}, d1 {:e}, d2 {:e})",
        errs[0],
        errs[1],
        errs[2],
        errs[3]
    );
    worst
}

/// 10⁶ samples of the engine benchmark's curve at its α = 0.5, 10⁵ at α ∈ {−3, −0.7, 0, 0.25, 1, 3} and for 3D
/// and closed curves (the sampler has no recurrence: every block of 64 starts again from the table, so the
/// error does not grow with the count; 10⁶ everywhere took 17 s in a debug build): the error stays ≤ 1e-12
/// relative (printed with `--nocapture`).
#[test]
fn uniform_sampler_matches_direct_formula_over_a_million_samples() {
    const M: usize = 100_000;
    let mut worst = 0.0_f64;
    for alpha in [-3.0, -0.7, 0.0, 0.25, 0.5, 1.0, 3.0] {
        let c = QuasiCubicCurve::new(alpha, spiral(100)).unwrap();
        let m = if alpha == 0.5 { 1_000_000 } else { M };
        let e = worst_error(&format!("open 2D α = {alpha}"), &c, m);
        println!("open 2D, 97 segments, α = {alpha}: max relative error {e:.2e} over {m} samples");
        worst = worst.max(e);
    }
    let c3 = QuasiCubicCurve::new(0.5, helix(40)).unwrap();
    let e3 = worst_error("open 3D α = 0.5", &c3, M);
    println!("open 3D, 37 segments, α = 0.5: max relative error {e3:.2e} over {M} samples");
    let cc = QuasiCubicCurve::closed(-0.7, spiral(100)).unwrap();
    let ec = worst_error("closed 2D α = −0.7", &cc, M);
    println!("closed 2D, 100 segments, α = −0.7: max relative error {ec:.2e} over {M} samples");
    worst = worst.max(e3).max(ec);
    println!("worst: {worst:.2e}");
}

/// Small and awkward counts: one sample, two, fewer samples than segments, a block boundary on a
/// segment boundary and next to it, one segment with many samples (blocks of the full table length
/// and a remainder).
#[test]
fn uniform_sampler_at_awkward_counts() {
    for alpha in [-3.0, 0.25, 1.0] {
        let open = QuasiCubicCurve::new(alpha, spiral(100)).unwrap();
        let one = QuasiCubicCurve::new(alpha, spiral(100)[..4].to_vec()).unwrap();
        let closed = QuasiCubicCurve::closed(alpha, spiral(100)[..5].to_vec()).unwrap();
        for count in [1usize, 2, 3, 50, 97, 98, 99, 6209, 6210, 6305, 64 * 97 + 1] {
            worst_error(&format!("open α = {alpha}"), &open, count);
            worst_error(&format!("closed α = {alpha}"), &closed, count);
        }
        for count in [1usize, 2, 63, 64, 65, 129, 1000] {
            worst_error(&format!("one segment α = {alpha}"), &one, count);
        }
    }
}

/// The samples of a closed curve end where they start, and the values-only call writes exactly the
/// requested count (nothing past it).
#[test]
fn uniform_sampler_closes_and_stays_in_bounds() {
    let c = QuasiCubicCurve::closed(0.5, spiral(100)).unwrap();
    let count = 12_345;
    let mut out = vec![f64::NAN; 2 * count + 4];
    c.sample_uniform_into(count, &mut out[..2 * count]);
    assert!(out[..2 * count].iter().all(|x| x.is_finite()));
    assert!(out[2 * count..].iter().all(|x| x.is_nan()));
    let (first, last) = (&out[..2], &out[2 * count - 2..2 * count]);
    assert!((first[0] - last[0]).abs() < 1e-12 && (first[1] - last[1]).abs() < 1e-12);
}
