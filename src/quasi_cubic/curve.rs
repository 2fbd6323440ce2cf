//! Quasi-cubic trigonometric B-spline curves (the quasi-cubic paper, Definition 2, Eq. (5)).
//!
//! **Open** curves: control points b_0..b_{n+2} (n ≥ 1 segments); segment i = 0..n−1 is
//! p_i(t) = Σ_j B_j(α; t) b_{i+j}, on the global parameter u ∈ [0, n] with i = min(⌊u⌋, n−1), t = u − i
//! (`curves.md` §1). Derivatives are with respect to u (= t, since segments have unit length).
//!
//! **Closed** (periodic) curves: N ≥ 4 control points b_0..b_{N−1}, N segments, u ∈ [0, N]; segment i
//! uses b_i, b_{i+1}, b_{i+2}, b_{i+3} with indices mod N, so the curve closes C² at u = 0 ≡ N. This is
//! the open curve of the wrapped polygon b_0..b_{N−1}, b_0, b_1, b_2. (Three points would be
//! mathematically possible; we require four, as the rhombus/square presets need, so that every segment
//! sees four distinct control points.)
//!
//! By Prop. 3 / Eq. (7)–(8) the joins are C² for every α; C³ only at α = 1.

use super::basis::{basis_derivs, check_alpha};
use super::segment::derivatives_at;
use super::trig::quarter_sin_cos;
use crate::error::{Error, Result};
use crate::point::Point;
use crate::sample::{Curve, MAX_INPUT_POINTS};

/// A quasi-cubic trigonometric B-spline curve with global shape parameter α ∈ [−3, 3].
///
/// # Template
/// * **What**: the quasi-cubic trigonometric B-spline curve Σ B_j(α; t) b_{g+j} of the quasi-cubic paper (eq. (1), the
///   reconstructed basis of `curves.md` §1) with one global shape parameter α.
/// * **Interpolates**: nothing (an approximating spline, like the cubic B-spline it resembles); closed
///   curves are periodic.
/// * **Continuity**: C² for every α, C³ at α = 1.
/// * **Parametrisation**: one unit interval per segment, u ∈ [0, n] for n segments (n + 3 control points).
///
/// # Example
/// ```
/// use glam::DVec2;
/// use splinelab::{quasi_cubic::QuasiCubicCurve, Curve};
/// let b: Vec<DVec2> = (0..6).map(|i| DVec2::new(i as f64, (i % 2) as f64)).collect();
/// let c = QuasiCubicCurve::new(1.0, b)?;
/// assert_eq!(c.domain(), (0.0, 3.0));
/// // C² at the joint u = 1: the one-sided second derivatives agree
/// let (mut l, mut r) = ([DVec2::ZERO; 3], [DVec2::ZERO; 3]);
/// c.eval_derivs(1.0 - 1e-9, 2, &mut l);
/// c.eval_derivs(1.0, 2, &mut r);
/// assert!((l[2] - r[2]).length() < 1e-6);
/// # Ok::<(), splinelab::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct QuasiCubicCurve<P: Point> {
    alpha: f64,
    points: Vec<P>,
    closed: bool,
}

/// Checks a list of control points: count limit and finite coordinates.
pub(crate) fn check_points<P: Point>(field: &'static str, points: &[P]) -> Result<()> {
    if points.len() > MAX_INPUT_POINTS {
        return Err(Error::too_many(
            field,
            format!("at most {MAX_INPUT_POINTS} points, got {}", points.len()),
        ));
    }
    if let Some(i) = points.iter().position(|p| !p.is_finite()) {
        return Err(Error::not_finite(
            format!("{field}[{i}]"),
            "expected finite coordinates",
        ));
    }
    Ok(())
}

impl<P: Point> QuasiCubicCurve<P> {
    /// An open curve through control points b_0..b_{n+2} (at least 4 points).
    pub fn new(alpha: f64, points: Vec<P>) -> Result<Self> {
        check_alpha("alpha", alpha)?;
        check_points("points", &points)?;
        if points.len() < 4 {
            return Err(Error::too_few(
                "points",
                format!(
                    "need at least 4 control points (n ≥ 1 segment), got {}",
                    points.len()
                ),
            ));
        }
        Ok(QuasiCubicCurve {
            alpha,
            points,
            closed: false,
        })
    }

    /// A closed (periodic) curve of N ≥ 4 control points and N segments, u ∈ [0, N].
    pub fn closed(alpha: f64, points: Vec<P>) -> Result<Self> {
        check_alpha("alpha", alpha)?;
        check_points("points", &points)?;
        if points.len() < 4 {
            return Err(Error::too_few(
                "points",
                format!(
                    "a closed (periodic) curve needs at least 4 control points, got {}",
                    points.len()
                ),
            ));
        }
        Ok(QuasiCubicCurve {
            alpha,
            points,
            closed: true,
        })
    }

    /// The shape parameter α.
    pub fn alpha(&self) -> f64 {
        self.alpha
    }
    /// The control points.
    pub fn points(&self) -> &[P] {
        &self.points
    }
    /// Whether the curve is closed (periodic).
    pub(crate) fn is_closed(&self) -> bool {
        self.closed
    }
    /// Number of segments n (open: points − 3; closed: points).
    pub fn segments(&self) -> usize {
        if self.closed {
            self.points.len()
        } else {
            self.points.len() - 3
        }
    }

    /// Segment index and local parameter for global `u` (outside the domain, the end segments extend).
    pub fn locate(&self, u: f64) -> (usize, f64) {
        locate(u, self.segments(), self.closed)
    }

    /// Control point `i + j` of segment `i` (wrapping for closed curves).
    #[inline]
    fn ctrl(&self, i: usize, j: usize) -> P {
        let n = self.points.len();
        self.points[(i + j) % n]
    }

    /// Derivatives 0..=order (≤ 3) at `u`: `out[k]` = k-th derivative with respect to u.
    pub(crate) fn eval_derivs3(&self, u: f64, order: usize, out: &mut [P; 4]) {
        let (i, t) = self.locate(u);
        self.eval_segment(i, t, order, out);
    }

    /// Derivatives 0..=order (≤ 3) of segment `i` at local `t` (one-sided values at joints for tests).
    pub fn eval_segment(&self, i: usize, t: f64, order: usize, out: &mut [P; 4]) {
        let order = order.min(3);
        let mut b = [[0.0; 4]; 4];
        basis_derivs(self.alpha, t, order, &mut b);
        let i = i.min(self.segments() - 1);
        for (k, row) in b.iter().enumerate().take(order + 1) {
            let mut acc = P::ZERO;
            for (j, w) in row.iter().enumerate() {
                acc += self.ctrl(i, j) * *w;
            }
            out[k] = acc;
        }
    }
}

/// Segment and local parameter for `u` on `segments` unit segments. Open: i = min(⌊u⌋, n−1) clamped at 0,
/// t = u − i (so outside [0, n] the end segments extrapolate). Closed: u is reduced modulo n first.
pub(crate) fn locate(u: f64, segments: usize, closed: bool) -> (usize, f64) {
    let n = segments.max(1);
    let nf = n as f64;
    let u = if closed && u.is_finite() && !(0.0..=nf).contains(&u) {
        u.rem_euclid(nf)
    } else {
        u
    };
    let fl = u.floor();
    let i = if fl.is_nan() || fl < 0.0 {
        0
    } else if fl >= (n - 1) as f64 {
        n - 1
    } else {
        fl as usize
    };
    (i, u - i as f64)
}

/// π/2.
const HALF_PI: f64 = std::f64::consts::FRAC_PI_2;

impl<P: Point> QuasiCubicCurve<P> {
    /// Segment `i` as K₀ + K₁t + K₂ sin πt + K₃ cos πt + K₄ sin θ + K₅ cos θ (θ = πt/2): the basis of the
    /// module docs expanded once per segment, so a point costs one (sin θ, cos θ) (the polynomials of
    /// [`quarter_sin_cos`]; uniform samples: a table shared by all blocks, [`Self::sample_uniform_blocks`])
    /// and a short sum instead of the basis functions' own sines and cosines.
    pub fn segment_coefficients(&self, i: usize) -> [P; 6] {
        let a = self.alpha;
        let (b, c) = (1.0 - a, 1.0 / (4.0 * std::f64::consts::PI));
        // rows: the coefficients of B_0..B_3 in (1, t, sin πt, cos πt, sin θ, cos θ)
        let rows: [[f64; 6]; 4] = [
            [
                b / 4.0 + a / 4.0,
                -b / 4.0,
                -b * c,
                -a / 12.0,
                -a / 3.0,
                0.0,
            ],
            [b / 2.0 + a / 4.0, -b / 4.0, b * c, a / 12.0, 0.0, a / 3.0],
            [b / 4.0 + a / 4.0, b / 4.0, b * c, -a / 12.0, a / 3.0, 0.0],
            [a / 4.0, b / 4.0, -b * c, a / 12.0, 0.0, -a / 3.0],
        ];
        let i = i.min(self.segments() - 1);
        let mut k = [P::ZERO; 6];
        for (j, row) in rows.iter().enumerate() {
            let p = self.ctrl(i, j);
            for (kk, w) in k.iter_mut().zip(row) {
                *kk += p * *w;
            }
        }
        k
    }
}

impl<P: Point> Curve<P> for QuasiCubicCurve<P> {
    fn domain(&self) -> (f64, f64) {
        (0.0, self.segments() as f64)
    }

    /// A closed curve repeats after its N segments: the period is N.
    fn period(&self) -> Option<f64> {
        self.is_closed().then(|| self.segments() as f64)
    }

    /// Runs of parameters in one segment share one Taylor expansion of it (exact to rounding, no sine or
    /// cosine per point): `QuasiCubicCurve::sample_params` (`explicit.rs`).
    fn sample_into(
        &self,
        params: &[f64],
        order: usize,
        points: &mut [f64],
        d1: &mut [f64],
        d2: &mut [f64],
    ) {
        self.sample_params(params, order, points, d1, d2);
    }

    /// Uniform samples: the block sampler of [`QuasiCubicCurve::sample_uniform_blocks`] (no sine or cosine
    /// per point).
    fn sample_uniform_into(&self, count: usize, out: &mut [f64]) {
        self.sample_uniform_blocks(count, 0, out, &mut [], &mut []);
    }

    /// Uniform samples with derivatives: the same block sampler (every derivative is a sum over the same
    /// tabulated sines and cosines).
    fn sample_uniform_derivs_into(
        &self,
        count: usize,
        order: usize,
        points: &mut [f64],
        d1: &mut [f64],
        d2: &mut [f64],
    ) {
        self.sample_uniform_blocks(count, order, points, d1, d2);
    }
    fn eval_derivs(&self, u: f64, order: usize, out: &mut [P; 3]) {
        let mut o = [P::ZERO; 4];
        self.eval_derivs3(u, order.min(2), &mut o);
        out[..(order.min(2) + 1)].copy_from_slice(&o[..(order.min(2) + 1)]);
    }
}

/// Points per block of the uniform sampler: the block offsets τ_k = k·h (k < `BLOCK`, h the grid step)
/// and their sines and cosines are tabulated once per call ([`OffsetTable`]).
const BLOCK: usize = 64;

/// The offsets τ_k = k·h, k = 0..`BLOCK`, of a uniform grid of step h, as rows
/// `[τ, sin(πτ/2), cos(πτ/2), sin πτ, cos πτ]` (libm, once per call).
struct OffsetTable([[f64; 5]; BLOCK]);

impl OffsetTable {
    fn new(step: f64) -> Self {
        let mut rows = [[0.0; 5]; BLOCK];
        for (k, row) in rows.iter_mut().enumerate() {
            let tau = step * k as f64;
            let (s1, c1) = (HALF_PI * tau).sin_cos();
            let (s2, c2) = (std::f64::consts::PI * tau).sin_cos();
            *row = [tau, s1, c1, s2, c2];
        }
        OffsetTable(rows)
    }
}

/// A segment (coefficients K₀..K₅ of [`QuasiCubicCurve::segment_coefficients`]) moved to a block start t₀
/// by the angle-addition formulas: for τ ≥ 0,
///
/// p(t₀ + τ) = l + K₁τ + u₁ sin(πτ/2) + v₁ cos(πτ/2) + u₂ sin πτ + v₂ cos πτ,
///
/// with l = K₀ + K₁t₀, u₁ = K₄ cos θ₀ − K₅ sin θ₀, v₁ = K₄ sin θ₀ + K₅ cos θ₀ (θ₀ = πt₀/2) and u₂, v₂ the
/// same for K₂, K₃ at πt₀. The derivatives in τ use the same sines and cosines; `w` holds the scaled
/// pairs (π/2·u₁, π/2·v₁, π·u₂, π·v₂) and `z` the second-derivative ones ((π/2)²·u₁, …, π²·v₂).
struct BlockCoefficients<P: Point> {
    l: P,
    k1: P,
    uv: [P; 4],
    w: [P; 4],
    z: [P; 4],
}

impl<P: Point> BlockCoefficients<P> {
    #[inline(always)]
    fn new(k: &[P; 6], t0: f64) -> Self {
        let pi = std::f64::consts::PI;
        let (s, c) = quarter_sin_cos(t0);
        let (s2, c2) = (2.0 * s * c, (c - s) * (c + s)); // sin πt₀, cos πt₀
        let uv = [
            k[4] * c - k[5] * s,
            k[4] * s + k[5] * c,
            k[2] * c2 - k[3] * s2,
            k[2] * s2 + k[3] * c2,
        ];
        let (h2, p2) = (HALF_PI * HALF_PI, pi * pi);
        BlockCoefficients {
            l: k[0] + k[1] * t0,
            k1: k[1],
            uv,
            w: [uv[0] * HALF_PI, uv[1] * HALF_PI, uv[2] * pi, uv[3] * pi],
            z: [uv[0] * h2, uv[1] * h2, uv[2] * p2, uv[3] * p2],
        }
    }

    /// The point at table row `r` = [τ, sin(πτ/2), cos(πτ/2), sin πτ, cos πτ].
    #[inline(always)]
    fn value(&self, r: &[f64; 5]) -> P {
        let uv = &self.uv;
        self.l + self.k1 * r[0] + uv[0] * r[1] + uv[1] * r[2] + uv[2] * r[3] + uv[3] * r[4]
    }

    /// The first derivative at table row `r`.
    #[inline(always)]
    fn d1(&self, r: &[f64; 5]) -> P {
        let w = &self.w;
        self.k1 + w[0] * r[2] - w[1] * r[1] + w[2] * r[4] - w[3] * r[3]
    }

    /// The second derivative at table row `r`.
    #[inline(always)]
    fn d2(&self, r: &[f64; 5]) -> P {
        let z = &self.z;
        -(z[0] * r[1] + z[1] * r[2] + z[2] * r[3] + z[3] * r[4])
    }
}

impl<P: Point> QuasiCubicCurve<P> {
    /// `count` uniform samples over the domain ([`crate::sample::uniform_params`]) with derivatives up to
    /// `order` (≤ 2) into flat buffers, without a sine or cosine per point: every segment of the grid is
    /// cut into blocks of up to 64 consecutive samples; each block starts at its own t₀ (one
    /// [`quarter_sin_cos`]) and its samples lie at t₀ + k·h, so the segment moved to t₀
    /// (`BlockCoefficients`) is combined with one table of sines and cosines of k·h shared by all
    /// blocks. No recurrence, so no drift: the error is that of the direct formula (a few ulps of the
    /// coefficients; `tests/quasi_cubic_uniform.rs` checks ≤ 1e-12 relative over 10⁶ samples). The last
    /// sample is evaluated at exactly the domain's end.
    pub fn sample_uniform_blocks(
        &self,
        count: usize,
        order: usize,
        points: &mut [f64],
        d1: &mut [f64],
        d2: &mut [f64],
    ) {
        let order = order.min(2);
        let dim = P::DIM;
        let count = count.min(points.len() / dim);
        if count == 0 {
            return;
        }
        let (a, b) = self.domain();
        let step = if count > 1 {
            (b - a) / (count - 1) as f64
        } else {
            0.0
        };
        let param = |j: usize| {
            if j + 1 == count && count > 1 {
                b
            } else {
                a + step * j as f64
            }
        };
        let table = OffsetTable::new(step);
        let n = self.segments();
        let mut start = 0usize;
        for seg in 0..n {
            let end = if seg + 1 == n {
                count
            } else {
                segment_end(seg as f64 + 1.0, a, step, start, count, param)
            };
            // the samples of this segment, the last sample of the grid (u = b exactly) apart
            let body_end = end.min(count - 1).max(start);
            if body_end > start {
                let k = self.segment_coefficients(seg);
                let mut j = start;
                while j < body_end {
                    let len = (body_end - j).min(BLOCK);
                    let bc = BlockCoefficients::new(&k, param(j) - seg as f64);
                    let rows = &table.0[..len];
                    let span = j * dim..(j + len) * dim;
                    fill_block(&bc, rows, order, points, d1, d2, span);
                    j += len;
                }
            }
            start = end;
        }
        // the last sample at exactly u = b (the end of a closed curve meets its start to rounding)
        let last = count - 1;
        let (i, t) = self.locate(param(last));
        let k = self.segment_coefficients(i);
        let der = derivatives_at(&k, t, order + 1);
        write_sample(&der, order, last * dim, points, d1, d2);
    }
}

/// The first grid index at or after `start` whose parameter `param(j)` reaches `t1` (the next segment's
/// start), from the step's guess corrected against the exact parameters.
fn segment_end(
    t1: f64,
    a: f64,
    step: f64,
    start: usize,
    count: usize,
    param: impl Fn(usize) -> f64,
) -> usize {
    let guess = ((t1 - a) / step).ceil();
    let mut e = if guess >= 0.0 {
        (guess as usize).clamp(start, count)
    } else {
        start
    };
    while e > start && param(e - 1) >= t1 {
        e -= 1;
    }
    while e < count && param(e) < t1 {
        e += 1;
    }
    e
}

/// Writes one block: the points (and derivatives up to `order`) at the table rows `rows` into the
/// entries `span` of the flat buffers.
#[inline(always)]
fn fill_block<P: Point>(
    bc: &BlockCoefficients<P>,
    rows: &[[f64; 5]],
    order: usize,
    points: &mut [f64],
    d1: &mut [f64],
    d2: &mut [f64],
    span: std::ops::Range<usize>,
) {
    let dim = P::DIM;
    let pts = points[span.clone()].chunks_exact_mut(dim);
    match order {
        0 => {
            for (o, r) in pts.zip(rows) {
                bc.value(r).write_coords(o);
            }
        }
        1 => {
            let e1 = d1[span].chunks_exact_mut(dim);
            for ((o, o1), r) in pts.zip(e1).zip(rows) {
                bc.value(r).write_coords(o);
                bc.d1(r).write_coords(o1);
            }
        }
        _ => {
            let e1 = d1[span.clone()].chunks_exact_mut(dim);
            let e2 = d2[span].chunks_exact_mut(dim);
            for (((o, o1), o2), r) in pts.zip(e1).zip(e2).zip(rows) {
                bc.value(r).write_coords(o);
                bc.d1(r).write_coords(o1);
                bc.d2(r).write_coords(o2);
            }
        }
    }
}

/// Writes one sample's value and its derivatives up to `order` (0–2) at offset `at` of the flat buffers.
fn write_sample<P: Point>(
    res: &[P],
    order: usize,
    at: usize,
    points: &mut [f64],
    d1: &mut [f64],
    d2: &mut [f64],
) {
    res[0].write_coords(&mut points[at..]);
    if order >= 1 {
        res[1].write_coords(&mut d1[at..]);
    }
    if order >= 2 {
        res[2].write_coords(&mut d2[at..]);
    }
}
