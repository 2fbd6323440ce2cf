//! What the native micro-benchmarks (`examples/batch.rs`, `examples/at_path.rs`) share: the timing loop and
//! the command line `[N] [REPS]`.
use std::time::Instant;

/// Runs `f` once to warm up, then `reps` times; returns (median, min) in ms.
pub fn time(reps: usize, mut f: impl FnMut()) -> (f64, f64) {
    f();
    let mut t: Vec<f64> = (0..reps)
        .map(|_| {
            let t0 = Instant::now();
            f();
            t0.elapsed().as_secs_f64() * 1e3
        })
        .collect();
    t.sort_by(|a, b| a.total_cmp(b));
    (t[t.len() / 2], t[0])
}

/// `(N, REPS)` from the command line: the points per call (default 1,000,000) and the repetitions.
pub fn n_and_reps(default_reps: usize) -> (usize, usize) {
    let args: Vec<String> = std::env::args().collect();
    let n = args
        .get(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(1_000_000);
    let reps = args
        .get(2)
        .and_then(|s| s.parse().ok())
        .unwrap_or(default_reps);
    (n, reps)
}
