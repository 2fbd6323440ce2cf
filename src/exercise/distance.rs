//! Distance of points to a curve: foot points by sampling, then Newton on the orthogonality condition.

use crate::error::{Error, Result};
use crate::sample::Curve;
use glam::DVec2;

/// How far data points are from a curve.
#[derive(Debug, Clone, PartialEq)]
pub struct DistanceReport {
    /// max_i dist(D_i, c).
    pub max: f64,
    /// dist(D_i, c) for every point, in order.
    pub distances: Vec<f64>,
    /// The parameter of the foot point of every point.
    pub params: Vec<f64>,
    /// The index of the farthest point.
    pub worst: usize,
}

/// Samples per curve for the first guess (then Newton refines every local minimum).
const SEED_SAMPLES: usize = 512;

/// The foot point of `q` on `c`: the parameter u* minimising ‖c(u) − q‖ over the domain, and that
/// distance. A uniform sample of `SEED_SAMPLES` + 1 parameters gives the local minima of the distance;
/// each is refined by Newton's method on f(u) = (c(u) − q)·c′(u) = 0 (f′ = ‖c′‖² + (c − q)·c″), kept in
/// the bracket between its neighbouring samples (a step that leaves it is halved back); the best wins.
pub fn foot_point(c: &dyn Curve<DVec2>, q: DVec2) -> (f64, f64) {
    let (a, b) = c.domain();
    let n = SEED_SAMPLES;
    let us: Vec<f64> = (0..=n).map(|i| a + (b - a) * i as f64 / n as f64).collect();
    let ds: Vec<f64> = us.iter().map(|&u| c.eval(u).distance(q)).collect();
    let mut best = (us[0], ds[0]);
    for i in 0..=n {
        let left = if i == 0 { f64::INFINITY } else { ds[i - 1] };
        let right = if i == n { f64::INFINITY } else { ds[i + 1] };
        if !(ds[i] <= left && ds[i] <= right) {
            continue;
        }
        let (lo, hi) = (us[i.saturating_sub(1)], us[(i + 1).min(n)]);
        let (u, d) = newton(c, q, us[i], lo, hi);
        let (u, d) = if d <= ds[i] { (u, d) } else { (us[i], ds[i]) };
        if d < best.1 {
            best = (u, d);
        }
    }
    best
}

fn newton(c: &dyn Curve<DVec2>, q: DVec2, u0: f64, lo: f64, hi: f64) -> (f64, f64) {
    let mut u = u0;
    let mut out = [DVec2::ZERO; 3];
    for _ in 0..30 {
        c.eval_derivs(u, 2, &mut out);
        let r = out[0] - q;
        let f = r.dot(out[1]);
        let df = out[1].length_squared() + r.dot(out[2]);
        if !(df > 0.0) {
            break;
        }
        let mut next = u - f / df;
        let mut guard = 0;
        while !(next >= lo && next <= hi) && guard < 40 {
            next = 0.5 * (next + u);
            guard += 1;
        }
        if !(next >= lo && next <= hi) {
            break;
        }
        let step = (next - u).abs();
        u = next;
        if step <= 1e-15 * (1.0 + u.abs()) {
            break;
        }
    }
    (u, c.eval(u).distance(q))
}

/// The distance of every point of `data` to the curve `c` (see [`foot_point`]) and the largest: the
/// check "the curve passes within ε of the data". An interpolating construction (the B2 curve at a = 0,
/// the blended interpolation spline) gives 0 up to rounding.
/// (A trait object: one copy of the search serves every construction, which keeps the wasm small.)
pub fn max_distance(c: &dyn Curve<DVec2>, data: &[DVec2]) -> Result<DistanceReport> {
    if data.is_empty() {
        return Err(Error::too_few_of(
            "data",
            1,
            0,
            "need at least one data point",
        ));
    }
    crate::error::check_finite(
        "data",
        &data.iter().flat_map(|p| [p.x, p.y]).collect::<Vec<f64>>(),
    )?;
    let mut distances = Vec::with_capacity(data.len());
    let mut params = Vec::with_capacity(data.len());
    for &q in data {
        let (u, d) = foot_point(c, q);
        params.push(u);
        distances.push(d);
    }
    let (worst, max) =
        distances
            .iter()
            .copied()
            .enumerate()
            .fold((0, f64::NEG_INFINITY), |(bi, bm), (i, d)| {
                if d > bm || d.is_nan() {
                    (i, d)
                } else {
                    (bi, bm)
                }
            });
    Ok(DistanceReport {
        max,
        distances,
        params,
        worst,
    })
}
