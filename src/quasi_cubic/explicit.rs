//! Quasi-cubic curves at explicit parameters (`at`), walked in **runs** as the B-spline kernel walks them
//! ([`crate::kernel::PiecewisePoly::sample_into`]): consecutive parameters that stay in one segment and
//! within [`WINDOW`] of the run's first parameter share one expansion of the segment, so a point costs a
//! short polynomial and no sine or cosine.
//!
//! A segment is p(t) = K₀ + K₁t + K₂ sin πt + K₃ cos πt + K₄ sin θ + K₅ cos θ, θ = πt/2
//! ([`QuasiCubicCurve::segment_coefficients`]). Its derivatives at the run's first local parameter t₀ are
//! exact in closed form ([`derivatives_at`], module `segment`).
//!
//! Around t₀ the segment is its Taylor polynomial of degree [`DEGREE`] in τ = t − t₀, and the m-th
//! derivative the polynomial with coefficients p⁽ʲ⁺ᵐ⁾(t₀)/j!. For |τ| ≤ [`WINDOW`] = 1/256 the first
//! omitted term is at most (π/256)⁷/7! ≈ 8·10⁻¹⁸ of |K₂| + |K₃| (times πᵐ for the m-th derivative, whose
//! own size carries the same πᵐ): below the rounding of the direct formula, so the result is the
//! segment's value to a few units in the last place (`tests/quasi_cubic_at.rs` checks ≤ 10⁻¹³ relative
//! to the direct formula, in any parameter order).
//!
//! A parameter whose successor is not in its window (unsorted parameters), a closed curve's parameter
//! outside [0, N] (reduced modulo N per point) and a non-finite one are evaluated on their own: their value
//! and derivatives are the first terms p⁽⁰⁾..p⁽ᵐ⁾(t₀) of the same closed form ([`derivatives_at`]).

use super::curve::QuasiCubicCurve;
use super::segment::{derivatives_at, DERIVATIVES};
use crate::point::Point;

/// Degree of the Taylor polynomial of a run (module docs: its error bound at [`WINDOW`]).
const DEGREE: usize = 6;
/// Coefficients per polynomial.
const TERMS: usize = DEGREE + 1;
const _: () = assert!(
    TERMS + 2 == DERIVATIVES,
    "a run reads the derivatives j < TERMS + order, order ≤ 2"
);
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
    /// The expansion from the derivatives `der` = p⁽ʲ⁾(t₀), j < `TERMS` + `order` ([`derivatives_at`]).
    #[inline(always)]
    fn new(der: &[P; DERIVATIVES], order: usize) -> Self {
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

    /// The run starting at `params[0]` = `u0`: the leading parameters in `[lo, hi)` (at least the first),
    /// their values and derivatives up to `order` written from entry `from` of the flat buffers on (as far
    /// as every written buffer goes); returns how many.
    fn run(
        &self,
        (u0, lo, hi): (f64, f64, f64),
        order: usize,
        params: &[f64],
        from: usize,
        outs: &mut [&mut [f64]; 3],
    ) -> usize {
        let dim = P::DIM;
        let n = outs[..=order].iter().fold(params.len(), |n, o| {
            n.min(o.len().saturating_sub(from) / dim)
        });
        let mut k = 0;
        if order == 0 {
            // values alone (the common case): one polynomial, no loop over the outputs
            let out = outs[0][from..].chunks_exact_mut(dim);
            for (&u, o) in params[..n].iter().zip(out) {
                if k > 0 && !(u >= lo && u < hi) {
                    break;
                }
                self.at(0, u - u0).write_coords(o);
                k += 1;
            }
            return k;
        }
        while k < n {
            let u = params[k];
            if k > 0 && !(u >= lo && u < hi) {
                break;
            }
            let (tau, o) = (u - u0, from + k * dim);
            for (m, out) in outs.iter_mut().enumerate().take(order + 1) {
                self.at(m, tau).write_coords(&mut out[o..o + dim]);
            }
            k += 1;
        }
        k
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
        let n = crate::kernel::samples_that_fit(params.len(), dim, order, points, d1, d2);
        let params = &params[..n];
        let mut outs = [points, d1, d2];
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
            let (f, next) = (i * dim, params.get(i + 1));
            match (window, next) {
                (Some((lo, hi)), Some(&v)) if v >= lo && v < hi => {
                    let der = derivatives_at(&k, t, TERMS + order);
                    let poly = RunPolynomials::new(&der, order);
                    i += poly.run((u, lo, hi), order, &params[i..], f, &mut outs);
                }
                _ => {
                    // a lone parameter: its value and derivatives are the first of the closed form
                    let der = derivatives_at(&k, t, order + 1);
                    for (d, out) in der.iter().zip(outs.iter_mut()).take(order + 1) {
                        d.write_coords(&mut out[f..f + dim]);
                    }
                    i += 1;
                }
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
