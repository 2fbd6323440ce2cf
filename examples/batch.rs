//! Native side of `benches/batch.mjs`: evaluates 1,000,000 points of a cubic B-spline and prints
//! "name<TAB>median ms" lines. Usage: cargo run --release --example batch -- [N] [REPS]
use glam::DVec2;
use splinelab::bspline::BSplineCurve;
use splinelab::sample::{eval_curve_into, uniform_params};
use std::time::Instant;

fn main() {
    let args: Vec<String> = std::env::args().collect();
    let n: usize = args
        .get(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1_000_000);
    let reps: usize = args.get(2).and_then(|s| s.parse().ok()).unwrap_or(7);
    let ctrl: Vec<DVec2> = (0..100)
        .map(|i| {
            let (r, t) = (1.0 + i as f64 * 0.05, i as f64 * 0.3);
            DVec2::new(t.cos() * r, t.sin() * r)
        })
        .collect();
    let curve = BSplineCurve::clamped_uniform(3, ctrl).expect("valid curve");
    let mut times = Vec::new();
    let mut fast = Vec::new();
    let mut out = vec![0.0; 2 * n];
    for _ in 0..=reps {
        let t0 = Instant::now();
        let params = uniform_params(0.0, 1.0, n);
        eval_curve_into(&curve, &params, 0, &mut out, &mut [], &mut []);
        std::hint::black_box(&out);
        let t1 = Instant::now();
        curve.sample_uniform_into(n, &mut out);
        fast.push(t1.elapsed().as_secs_f64() * 1e3);
        times.push(t0.elapsed().as_secs_f64() * 1e3);
    }
    for t in [&mut times, &mut fast] {
        t.remove(0);
        t.sort_by(|a, b| a.partial_cmp(b).unwrap());
    }
    println!(
        "native Rust, generic eval_curve_into (span search + Cox–de Boor per point)\t{:.3}",
        times[times.len() / 2]
    );
    println!(
        "native Rust, sample_uniform_into (per-span power basis, Horner)\t{:.3}",
        fast[fast.len() / 2]
    );
    std::hint::black_box(&out);
}
