//! Quasi-cubic curves at explicit parameters (`at`), walked in **runs** as the B-spline kernel walks them
//! ([`crate::kernel::PiecewisePoly::sample_into`]): consecutive parameters that stay in one segment and
//! within [`WINDOW`] of the run's first parameter share one expansion of the segment, so a point costs a
//! short polynomial and no sine or cosine.
//!
//! A segment is p(t) = K₀ + K₁t + K₂ sin πt + K₃ cos πt + K₄ sin θ + K₅ cos θ, θ = πt/2
//! ([`QuasiCubicCurve::segment_coefficients`]). Its derivatives at the run's first local parameter t₀ are
//! exact in closed form (one (sin θ₀, cos θ₀) by [`quarter_sin_cos`]): with f = K₂ sin πt₀ + K₃ cos πt₀,
//! g = K₂ cos πt₀ − K₃ sin πt₀ and F, G the same for K₄, K₅ at θ₀,
//!
//! p⁽ʲ⁾(t₀) = πʲ·(f, g, −f, −g)[j mod 4] + (π/2)ʲ·(F, G, −F, −G)[j mod 4]  (+ K₀ + K₁t₀ at j = 0, + K₁ at j = 1).
//!
//! Around t₀ the segment is its Taylor polynomial of degree [`DEGREE`] in τ = t − t₀, and the m-th
//! derivative the polynomial with coefficients p⁽ʲ⁺ᵐ⁾(t₀)/j!. For |τ| ≤ [`WINDOW`] = 1/256 the first
//! omitted term is at most (π/256)⁷/7! ≈ 8·10⁻¹⁸ of |K₂| + |K₃| (times πᵐ for the m-th derivative, whose
//! own size carries the same πᵐ): below the rounding of the direct formula, so the result is the
//! segment's value to a few units in the last place (`tests/quasi_cubic_at.rs` checks ≤ 10⁻¹³ relative
//! to the direct formula, in any parameter order).
//!
//! A parameter whose successor is not in its window (unsorted parameters) is evaluated on its own by the
//! direct formula (one [`quarter_sin_cos`]), as are parameters of a closed curve outside [0, N] (reduced
//! modulo N per point) and non-finite ones.

use super::curve::{trig_eval, write_sample, QuasiCubicCurve};
use super::trig::quarter_sin_cos;
use crate::point::Point;
use std::f64::consts::{FRAC_PI_2, PI};

/// Degree of the Taylor polynomial of a run (module docs: its error bound at [`WINDOW`]).
const DEGREE: usize = 6;
/// Coefficients per polynomial.
const TERMS: usize = DEGREE + 1;
/// Largest |t − t₀| of a run (module docs).
const WINDOW: f64 = 1.0 / 256.0;

/// 1/j!, j = 0..`TERMS`.
const INV_FACTORIAL: [f64; TERMS] = [
    1.0,
    1.0,
    1.0 / 2.0,
    1.0 / 6.0,
    1.0 / 24.0,
    1.0 / 120.0,
    1.0 / 720.0,
];

/// A segment expanded at a run's first local parameter t₀: the Taylor coefficients p⁽ʲ⁺ᵐ⁾(t₀)/j! of the
/// value (m = 0) and of the first and second derivatives (m = 1, 2; only as far as the run's order needs).
struct RunPolynomials<P: Point> {
    rows: [[P; TERMS]; 3],
}

impl<P: Point> RunPolynomials<P> {
    /// The expansion of the segment with coefficients `k` at `t0`, derivatives up to `order` (≤ 2).
    #[inline(always)]
    fn new(k: &[P; 6], t0: f64, order: usize) -> Self {
        let (s, c) = quarter_sin_cos(t0);
        let (s2, c2) = (2.0 * s * c, (c - s) * (c + s)); // sin πt₀, cos πt₀
                                                         // p⁽ʲ⁾ of the π terms cycles through (f, g, −f, −g)·πʲ, of the π/2 terms through (F, G, −F, −G)·(π/2)ʲ
        let (f, g) = (k[2] * s2 + k[3] * c2, k[2] * c2 - k[3] * s2);
        let (ff, gg) = (k[4] * s + k[5] * c, k[4] * c - k[5] * s);
        let full = [f, g, -f, -g];
        let half = [ff, gg, -ff, -gg];
        let mut der = [P::ZERO; TERMS + 2];
        let (mut wp, mut wh) = (1.0, 1.0);
        for (j, d) in der.iter_mut().enumerate().take(TERMS + order) {
            *d = full[j % 4] * wp + half[j % 4] * wh;
            wp *= PI;
            wh *= FRAC_PI_2;
        }
        der[0] = k[0] + k[1] * t0 + der[0];
        der[1] += k[1];
        let mut rows = [[P::ZERO; TERMS]; 3];
        for (m, row) in rows.iter_mut().enumerate().take(order + 1) {
            for (j, r) in row.iter_mut().enumerate() {
                *r = der[j + m] * INV_FACTORIAL[j];
            }
        }
        RunPolynomials { rows }
    }

    /// Derivative `m` at τ = t − t₀ (Horner).
    #[inline(always)]
    fn at(&self, m: usize, tau: f64) -> P {
        let c = &self.rows[m];
        let mut acc = c[DEGREE];
        for cj in c[..DEGREE].iter().rev() {
            acc = acc * tau + *cj;
        }
        acc
    }
}

impl<P: Point> QuasiCubicCurve<P> {
    /// The values (and derivatives up to `order` ≤ 2) at `params` into flat buffers (each
    /// `params.len() · DIM` entries; unused ones may be empty; a short buffer ends the evaluation there),
    /// in runs (module docs).
    pub(crate) fn sample_params(
        &self,
        params: &[f64],
        order: usize,
        points: &mut [f64],
        d1: &mut [f64],
        d2: &mut [f64],
    ) {
        let order = order.min(2);
        let dim = P::DIM;
        let mut n = params.len().min(points.len() / dim);
        if order >= 1 {
            n = n.min(d1.len() / dim);
        }
        if order >= 2 {
            n = n.min(d2.len() / dim);
        }
        let params = &params[..n];
        let mut seg = usize::MAX;
        let mut k = [P::ZERO; 6];
        let mut i = 0;
        while i < n {
            let u = params[i];
            let (s, t) = self.locate(u);
            if s != seg {
                seg = s;
                k = self.segment_coefficients(s);
            }
            let window = self.run_window(s, u);
            let run = match (window, params.get(i + 1)) {
                (Some((lo, hi)), Some(&next)) => next >= lo && next < hi,
                _ => false,
            };
            let f = i * dim;
            if run {
                let (lo, hi) = window.unwrap_or((u, u));
                let poly = RunPolynomials::new(&k, t, order);
                let (rest, at) = (&params[i..], (u, lo, hi));
                i += match order {
                    0 => run_values(&poly, at, rest, &mut points[f..]),
                    1 => run_derivs::<P, false>(
                        &poly,
                        at,
                        rest,
                        &mut points[f..],
                        &mut d1[f..],
                        &mut [],
                    ),
                    _ => run_derivs::<P, true>(
                        &poly,
                        at,
                        rest,
                        &mut points[f..],
                        &mut d1[f..],
                        &mut d2[f..],
                    ),
                };
            } else {
                let (sn, cs) = quarter_sin_cos(t);
                let mut out = [P::ZERO; 3];
                trig_eval(&k, t, sn, cs, order, &mut out);
                write_sample(&out, order, f, points, d1, d2);
                i += 1;
            }
        }
    }

    /// The parameters `[lo, hi)` that may join a run starting at `u` in segment `s`: within [`WINDOW`] of
    /// `u` and located in `s` with the same local parameter u − s (open curves: the end segments extend
    /// to ±∞; closed ones: [0, N], the end N in the last segment). `None` where a run cannot start: `u`
    /// not finite, or a closed curve's `u` outside [0, N] (reduced modulo N per point).
    fn run_window(&self, s: usize, u: f64) -> Option<(f64, f64)> {
        let n = self.segments();
        let nf = n as f64;
        if !u.is_finite() || (self.is_closed() && !(0.0..=nf).contains(&u)) {
            return None;
        }
        let last = s + 1 == n;
        let (lo, hi) = if self.is_closed() {
            (s as f64, if last { nf.next_up() } else { (s + 1) as f64 })
        } else {
            (
                if s == 0 { f64::NEG_INFINITY } else { s as f64 },
                if last { f64::INFINITY } else { (s + 1) as f64 },
            )
        };
        Some((lo.max(u - WINDOW), hi.min(u + WINDOW)))
    }
}

/// Positions of the run starting at `params[0]` = `u0` (the leading parameters in `[lo, hi)`, at least
/// the first) into `out`; returns how many.
#[inline(always)]
fn run_values<P: Point>(
    poly: &RunPolynomials<P>,
    (u0, lo, hi): (f64, f64, f64),
    params: &[f64],
    out: &mut [f64],
) -> usize {
    let mut k = 0;
    for (&u, o) in params.iter().zip(out.chunks_exact_mut(P::DIM)) {
        if k > 0 && !(u >= lo && u < hi) {
            break;
        }
        poly.at(0, u - u0).write_coords(o);
        k += 1;
    }
    k
}

/// Positions and first (and with `SECOND` second) derivatives of the run starting at `params[0]` = `u0`
/// into `points`, `d1` (and `d2`); returns how many.
#[inline(always)]
fn run_derivs<P: Point, const SECOND: bool>(
    poly: &RunPolynomials<P>,
    (u0, lo, hi): (f64, f64, f64),
    params: &[f64],
    points: &mut [f64],
    d1: &mut [f64],
    d2: &mut [f64],
) -> usize {
    let dim = P::DIM;
    let mut n = params.len().min(points.len() / dim).min(d1.len() / dim);
    if SECOND {
        n = n.min(d2.len() / dim);
    }
    let mut k = 0;
    while k < n {
        let u = params[k];
        if k > 0 && !(u >= lo && u < hi) {
            break;
        }
        let tau = u - u0;
        let o = k * dim;
        poly.at(0, tau).write_coords(&mut points[o..o + dim]);
        poly.at(1, tau).write_coords(&mut d1[o..o + dim]);
        if SECOND {
            poly.at(2, tau).write_coords(&mut d2[o..o + dim]);
        }
        k += 1;
    }
    k
}
