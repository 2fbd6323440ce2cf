//! Native micro-benchmark of the pieces of a curve call with explicit parameters (`at`) against uniform
//! `samples` (benches/README.md §7): copy in, finite check, zeroed output, the evaluation loops.
//! Usage: cargo run --release --example at_path -- [N] [REPS]
mod common;

use common::time;
use glam::DVec2;
use splinelab::bspline::BSplineCurve;
use splinelab::quasi_cubic::QuasiCubicCurve;
use splinelab::sample::{uniform_params, Curve};
use std::hint::black_box;

fn main() {
    let (n, reps) = common::n_and_reps(11);
    // the curve of benches/engine.mjs's `at` row: 100 points on a wobbly spiral, clamped uniform cubic
    let ctrl: Vec<DVec2> = (0..100)
        .map(|i| {
            let t = i as f64 * 0.15;
            DVec2::new(
                (1.0 + t) * t.cos() + 0.1 * (7.0 * t).sin(),
                (1.0 + t) * t.sin(),
            )
        })
        .collect();
    let curve = BSplineCurve::clamped_uniform(3, ctrl.clone()).expect("valid curve");
    let pp = curve.piecewise().expect("a cubic is piecewise polynomial");
    let params = uniform_params(0.0, 1.0, n);
    let mut out = vec![0.0; 2 * n];
    let mut d1 = vec![0.0; 2 * n];
    let mut d2 = vec![0.0; 2 * n];
    let rows: Vec<(&str, (f64, f64))> = vec![
        (
            "copy in: params.to_vec() (8 MB)",
            time(reps, || {
                black_box(black_box(&params).to_vec());
            }),
        ),
        (
            "finite check: position(!is_finite)",
            time(reps, || {
                black_box(black_box(&params).iter().position(|x| !x.is_finite()));
            }),
        ),
        (
            "finite check: splinelab::sample::first_non_finite",
            time(reps, || {
                black_box(splinelab::sample::first_non_finite(black_box(&params)));
            }),
        ),
        (
            "zeroed output: vec![0.0; 2N] (16 MB)",
            time(reps, || {
                black_box(vec![0.0f64; 2 * n]);
            }),
        ),
        (
            "uniform params: uniform_params (8 MB)",
            time(reps, || {
                black_box(uniform_params(0.0, 1.0, n));
            }),
        ),
        (
            "eval at params: PiecewisePoly::sample_into, existing buffer",
            time(reps, || {
                pp.sample_into(black_box(&params), 0, &mut out, &mut [], &mut []);
                black_box(&out);
            }),
        ),
        (
            "eval uniform: PiecewisePoly::sample_uniform_into, existing buffer",
            time(reps, || {
                pp.sample_uniform_into(n, &mut out);
                black_box(&out);
            }),
        ),
        (
            "eval at params, derivatives 2: sample_into, existing buffers",
            time(reps, || {
                pp.sample_into(black_box(&params), 2, &mut out, &mut d1, &mut d2);
                black_box((&out, &d1, &d2));
            }),
        ),
    ];
    // quasi-cubic (α = 1) on the same polygon: explicit parameters vs the uniform rotation recurrence
    let qc = QuasiCubicCurve::new(1.0, ctrl.clone()).expect("valid curve");
    let (a, b) = qc.domain();
    let qparams = uniform_params(a, b, n);
    let mut rows = rows;
    for order in [0usize, 2] {
        rows.push((
            if order == 0 {
                "quasi-cubic at params, values: sample_into"
            } else {
                "quasi-cubic at params, derivatives 2: sample_into"
            },
            time(reps, || {
                qc.sample_into(black_box(&qparams), order, &mut out, &mut d1, &mut d2);
                black_box((&out, &d1, &d2));
            }),
        ));
        rows.push((
            if order == 0 {
                "quasi-cubic uniform, values: sample_uniform_derivs_into"
            } else {
                "quasi-cubic uniform, derivatives 2: sample_uniform_derivs_into"
            },
            time(reps, || {
                qc.sample_uniform_derivs_into(n, order, &mut out, &mut d1, &mut d2);
                black_box((&out, &d1, &d2));
            }),
        ));
    }
    rows.push((
        "quasi-cubic generic eval_derivs per point (libm), derivatives 2",
        time(reps.min(3), || {
            splinelab::sample::eval_curve_generic_into(
                &qc, &qparams, 2, &mut out, &mut d1, &mut d2,
            );
            black_box((&out, &d1, &d2));
        }),
    ));
    rows.push((
        "trig: quarter_sin_cos at 1M parameters t in [0, 1]",
        time(reps, || {
            let mut acc = 0.0;
            for &u in &qparams {
                let (s, c) = splinelab::quasi_cubic::trig::quarter_sin_cos(u - u.floor());
                acc += s * c;
            }
            black_box(acc);
        }),
    ));
    rows.push((
        "trig: libm sin_cos at the same 1M",
        time(reps, || {
            let mut acc = 0.0;
            for &u in &qparams {
                let (s, c) = (std::f64::consts::FRAC_PI_2 * (u - u.floor())).sin_cos();
                acc += s * c;
            }
            black_box(acc);
        }),
    ));
    for (name, (med, min)) in rows {
        println!("{name:<70} {med:>7.3} ms median {min:>7.3} ms min");
    }
}
