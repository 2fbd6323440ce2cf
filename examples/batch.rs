//! Native side of `benches/batch.mjs`: evaluates 1,000,000 points of a cubic B-spline and prints
//! "name<TAB>median ms<TAB>min ms" lines. Usage: cargo run --release --example batch -- [N] [REPS]
mod common;

use common::time;
use glam::DVec2;
use splinelab::bspline::BSplineCurve;
use splinelab::sample::{eval_curve_into, uniform_params};
use std::hint::black_box;

fn main() {
    let (n, reps) = common::n_and_reps(7);
    let ctrl: Vec<DVec2> = (0..100)
        .map(|i| {
            let (r, t) = (1.0 + i as f64 * 0.05, i as f64 * 0.3);
            DVec2::new(t.cos() * r, t.sin() * r)
        })
        .collect();
    let curve = BSplineCurve::clamped_uniform(3, ctrl).expect("valid curve");
    let mut rows = Vec::new();

    // like for like with the wasm call: the same outputs (params + points) allocated and filled per call
    rows.push((
        "native Rust like for like: uniform_params + new Vec of 2e6 + sample_uniform_into (fresh allocations)",
        time(reps, || {
            let params = uniform_params(0.0, 1.0, n);
            let mut out = vec![0.0; 2 * n];
            curve.sample_uniform_into(params.len(), &mut out);
            black_box((&params, &out));
        }),
    ));
    let mut out = vec![0.0; 2 * n];
    rows.push((
        "native Rust: sample_uniform_into an existing buffer (compute only)",
        time(reps, || {
            curve.sample_uniform_into(n, &mut out);
            black_box(&out);
        }),
    ));
    let params = uniform_params(0.0, 1.0, n);
    rows.push((
        "native Rust: generic eval_curve_into (span search + Cox–de Boor per point), existing buffer",
        time(reps.min(3), || {
            eval_curve_into(&curve, &params, 0, &mut out, &mut [], &mut []);
            black_box(&out);
        }),
    ));
    rows.push((
        "floor (native): write 16 MB into an existing buffer",
        time(reps, || {
            for (i, x) in out.iter_mut().enumerate() {
                *x = i as f64;
            }
            black_box(&out);
        }),
    ));
    rows.push((
        "floor (native): new Vec of 2e6 f64 and write it (16 MB, fresh pages)",
        time(reps, || {
            let mut v = vec![0.0; 2 * n];
            for (i, x) in v.iter_mut().enumerate() {
                *x = i as f64;
            }
            black_box(&v);
        }),
    ));
    for (name, (med, min)) in rows {
        println!("{name}\t{med:.3}\t{min:.3}");
    }
}
