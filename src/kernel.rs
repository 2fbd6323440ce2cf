//! The evaluation kernel: one fast sampler for every construction that *is* a polynomial spline, and one
//! grid sampler for every tensor-product surface.
//!
//! * [`PiecewisePoly`] — a curve given per segment in the power basis of the local parameter
//!   t = (u − u_I)/(u_{I+1} − u_I). B-spline curves (and so B2-spline curves, knot-modified curves while the
//!   moved knot stays between its neighbours) and Bézier splines (and so the remodelled g*) convert to it
//!   once per call (O(segments · degree²)); then parameters are walked in runs that stay in one segment
//!   (one search per run, a compare per point) and every parameter costs one Horner evaluation that gives
//!   the value **and** its first two derivatives together (so `derivatives: 2` and curvature never
//!   evaluate twice; cubics have the loops unrolled). Uniform samples of cubics use forward differences
//!   re-anchored every 16 samples.
//! * [`TensorGrid`] — a tensor-product B-spline surface sampled on a grid `us × vs` (u-major): the v-basis
//!   rows are computed once per grid column, the u-basis once per grid row together with the isocurve
//!   control points of that row, then each point is a short sum of `q + 1` isocurve points.
//!
//! Conventions are those of the generic path ([`crate::sample::Curve::eval_derivs`]): at an interior
//! break the right-hand piece, at and beyond the end the last piece, before the start the first piece
//! (extrapolation by the polynomial). `tests/samplers.rs` checks every construction's fast path against
//! its generic evaluation to 1e-12.

use crate::basis::basis_derivs;
use crate::knots::{find_span, MAX_DEGREE};
use crate::point::Point;

/// Highest degree the power-basis path is used for: beyond it the Bernstein → monomial conversion loses
/// digits (binomial coefficients grow like 2^degree), and the generic evaluation is used instead.
pub const MAX_FAST_DEGREE: usize = 12;

const W: usize = MAX_DEGREE + 2;

/// A piecewise polynomial curve in the local power basis (see the module docs).
#[derive(Debug, Clone, PartialEq)]
pub struct PiecewisePoly<P: Point> {
    degree: usize,
    /// u_0 < u_1 < … < u_L.
    breaks: Vec<f64>,
    /// 1/(u_{I+1} − u_I).
    inv: Vec<f64>,
    /// c_{I,0..=degree} at `I * (degree + 1)`: segment I is Σ_j c_{I,j} t^j.
    coef: Vec<P>,
}

impl<P: Point> PiecewisePoly<P> {
    /// An empty spline of `degree` (add segments with [`Self::push_segment`]).
    pub(crate) fn with_degree(degree: usize, first_break: f64) -> Self {
        PiecewisePoly {
            degree,
            breaks: vec![first_break],
            inv: Vec::new(),
            coef: Vec::new(),
        }
    }

    /// Appends the segment `[last break, end]` with power coefficients `coef[..=degree]` in its local
    /// parameter. `end` must be greater than the last break.
    pub fn push_segment(&mut self, end: f64, coef: &[P]) {
        let start = self.breaks[self.breaks.len() - 1];
        self.inv.push(1.0 / (end - start));
        self.breaks.push(end);
        self.coef.extend_from_slice(&coef[..=self.degree]);
    }

    /// The Bézier spline of `degree` with control points `points[m·I ..= m·I + m]` on `[breaks[I],
    /// breaks[I+1]]` (strictly increasing breaks): Bernstein → power basis per segment,
    /// c_j = C(m, j) Σ_{i ≤ j} (−1)^{j−i} C(j, i) b_i.
    pub(crate) fn from_bezier(degree: usize, breaks: &[f64], points: &[P]) -> Self {
        let mut pp = Self::with_degree(degree, breaks[0]);
        let mut coef = [P::ZERO; W];
        for seg in 0..breaks.len() - 1 {
            bernstein_to_power(&points[degree * seg..=degree * seg + degree], &mut coef);
            pp.push_segment(breaks[seg + 1], &coef);
        }
        pp
    }

    /// Polynomial degree of every segment.
    pub fn degree(&self) -> usize {
        self.degree
    }
    /// Number of segments L.
    pub fn segments(&self) -> usize {
        self.inv.len()
    }
    /// The breaks u_0..u_L.
    pub fn breaks(&self) -> &[f64] {
        &self.breaks
    }
    /// `(u_0, u_L)`.
    pub fn domain(&self) -> (f64, f64) {
        (self.breaks[0], self.breaks[self.breaks.len() - 1])
    }

    /// The segment used at `u`: right-hand piece at interior breaks, first before u_0, last from u_L on.
    #[inline]
    pub fn segment(&self, u: f64) -> usize {
        let l = self.segments();
        self.breaks[1..l].partition_point(|&b| b <= u)
    }

    /// `hint` if `u` lies in its segment (or the next one), else a search.
    #[inline(always)]
    fn segment_from(&self, u: f64, hint: usize) -> usize {
        let l = self.segments();
        let lo_ok = hint == 0 || self.breaks[hint] <= u;
        if lo_ok && (hint + 1 == l || u < self.breaks[hint + 1]) {
            return hint;
        }
        let next = hint + 1;
        if lo_ok && next < l && (next + 1 == l || u < self.breaks[next + 1]) {
            return next;
        }
        self.segment(u)
    }

    /// The `k`-th derivative (any k ≤ degree) of segment `seg` at its start (`at_end = false`, t = 0) or
    /// its end (`at_end = true`, t = 1), with respect to the global parameter u: from the power form
    /// Σ_j c_j t^j, f^{(k)}(t) = h^{−k} Σ_{j ≥ k} j!/(j − k)! c_j t^{j−k} with h = u_{I+1} − u_I. These
    /// are the one-sided derivatives at a break (left: the end of segment I − 1; right: the start of
    /// segment I). `None` when `seg` is out of range or `k > degree`.
    pub(crate) fn segment_end_derivative(&self, seg: usize, at_end: bool, k: usize) -> Option<P> {
        let p = self.degree;
        if seg >= self.segments() || k > p {
            return None;
        }
        let c = &self.coef[seg * (p + 1)..(seg + 1) * (p + 1)];
        let falling = |j: usize| ((j - k + 1)..=j).fold(1.0, |acc, x| acc * x as f64);
        let mut v = P::ZERO;
        if at_end {
            for j in k..=p {
                v += c[j] * falling(j);
            }
        } else {
            v = c[k] * falling(k);
        }
        Some(v * self.inv[seg].powi(k as i32))
    }

    /// Value and derivatives up to `order` (≤ 2) at `u` (entries above `order` left as they were).
    pub fn eval_derivs(&self, u: f64, order: usize, out: &mut [P; 3]) {
        let s = self.segment(u);
        self.eval_in(s, u, order, out);
    }

    #[inline(always)]
    fn eval_in(&self, s: usize, u: f64, order: usize, out: &mut [P; 3]) {
        let p = self.degree;
        let c = &self.coef[s * (p + 1)..(s + 1) * (p + 1)];
        let inv = self.inv[s];
        let t = (u - self.breaks[s]) * inv;
        let mut v = c[p];
        if order == 0 {
            for cj in c[..p].iter().rev() {
                v = v * t + *cj;
            }
            out[0] = v;
            return;
        }
        let mut d = P::ZERO;
        let mut dd = P::ZERO;
        for cj in c[..p].iter().rev() {
            dd = dd * t + d;
            d = d * t + v;
            v = v * t + *cj;
        }
        out[0] = v;
        out[1] = d * inv;
        if order >= 2 {
            out[2] = dd * (2.0 * inv * inv);
        }
    }

    /// Evaluates at `params` (any order) into flat buffers: positions into `points`, and when `order ≥ 1` /
    /// `2` the derivatives into `d1` / `d2` (each `params.len() · DIM` entries; unused ones may be empty).
    ///
    /// The parameters are walked in **runs** that lie in one segment (one search per run, then a scan
    /// `u_I ≤ u < u_{I+1}` that costs a predictable compare per point, so sorted parameters cost one search
    /// per segment and unsorted ones one per change of segment); each run is evaluated by a loop with the
    /// segment's coefficients in registers (cubics: an unrolled Horner).
    pub fn sample_into(
        &self,
        params: &[f64],
        order: usize,
        points: &mut [f64],
        d1: &mut [f64],
        d2: &mut [f64],
    ) {
        let dim = P::DIM;
        let l = self.segments();
        let n = samples_that_fit(params.len(), dim, order, points, d1, d2);
        let params = &params[..n];
        let mut i = 0;
        let mut s = 0;
        while i < n {
            s = self.segment_from(params[i], s);
            let lo = if s == 0 {
                f64::NEG_INFINITY
            } else {
                self.breaks[s]
            };
            let hi = if s + 1 == l {
                f64::INFINITY
            } else {
                self.breaks[s + 1]
            };
            // the run of parameters from i on that stays in segment s (at least one: NaN ends a run)
            let rest = &params[i..];
            let f = i * dim;
            i += match order {
                0 => self.run_values(s, (lo, hi), rest, &mut points[f..]),
                1 => self.run_derivs::<false>(
                    s,
                    (lo, hi),
                    rest,
                    &mut points[f..],
                    &mut d1[f..],
                    &mut [],
                ),
                _ => self.run_derivs::<true>(
                    s,
                    (lo, hi),
                    rest,
                    &mut points[f..],
                    &mut d1[f..],
                    &mut d2[f..],
                ),
            };
        }
    }

    /// Positions of segment `s` at the leading parameters of `params` that lie in `[lo, hi)` (at least the
    /// first) into `out`; returns how many.
    #[inline(always)]
    fn run_values(&self, s: usize, (lo, hi): (f64, f64), params: &[f64], out: &mut [f64]) -> usize {
        let p = self.degree;
        let c = &self.coef[s * (p + 1)..(s + 1) * (p + 1)];
        let (u0, inv) = (self.breaks[s], self.inv[s]);
        let mut k = 0;
        let chunks = out.chunks_exact_mut(P::DIM);
        if let [c0, c1, c2, c3] = *c {
            for (&u, o) in params.iter().zip(chunks) {
                if k > 0 && !(u >= lo && u < hi) {
                    break;
                }
                let t = (u - u0) * inv;
                (((c3 * t + c2) * t + c1) * t + c0).write_coords(o);
                k += 1;
            }
        } else {
            for (&u, o) in params.iter().zip(chunks) {
                if k > 0 && !(u >= lo && u < hi) {
                    break;
                }
                horner(c, (u - u0) * inv).write_coords(o);
                k += 1;
            }
        }
        k
    }

    /// Positions and first (and with `SECOND` second) derivatives of segment `s` at the leading parameters
    /// of `params` in `[lo, hi)` (at least the first) into `points`, `d1` (and `d2`); returns how many.
    /// Cubics use the derivative polynomials with their factors folded in: c′ = (3c₃t + 2c₂)t + c₁ and
    /// c″ = 6c₃t + 2c₂, times h⁻¹ and h⁻².
    #[inline(always)]
    fn run_derivs<const SECOND: bool>(
        &self,
        s: usize,
        (lo, hi): (f64, f64),
        params: &[f64],
        points: &mut [f64],
        d1: &mut [f64],
        d2: &mut [f64],
    ) -> usize {
        let dim = P::DIM;
        let p = self.degree;
        let c = &self.coef[s * (p + 1)..(s + 1) * (p + 1)];
        let (u0, inv) = (self.breaks[s], self.inv[s]);
        let n = params.len().min(points.len() / dim);
        let mut k = 0;
        if let [c0, c1, c2, c3] = *c {
            let (e1, e2, e3) = (c1 * inv, c2 * (2.0 * inv), c3 * (3.0 * inv));
            let (f2, f3) = (c2 * (2.0 * inv * inv), c3 * (6.0 * inv * inv));
            while k < n {
                let u = params[k];
                if k > 0 && !(u >= lo && u < hi) {
                    break;
                }
                let t = (u - u0) * inv;
                let o = k * dim;
                (((c3 * t + c2) * t + c1) * t + c0).write_coords(&mut points[o..o + dim]);
                ((e3 * t + e2) * t + e1).write_coords(&mut d1[o..o + dim]);
                if SECOND {
                    (f3 * t + f2).write_coords(&mut d2[o..o + dim]);
                }
                k += 1;
            }
        } else {
            let mut out = [P::ZERO; 3];
            let order = if SECOND { 2 } else { 1 };
            while k < n {
                let u = params[k];
                if k > 0 && !(u >= lo && u < hi) {
                    break;
                }
                self.eval_in(s, u, order, &mut out);
                let o = k * dim;
                out[0].write_coords(&mut points[o..o + dim]);
                out[1].write_coords(&mut d1[o..o + dim]);
                if SECOND {
                    out[2].write_coords(&mut d2[o..o + dim]);
                }
                k += 1;
            }
        }
        k
    }

    /// Positions at the `count` uniform parameters of [`crate::sample::uniform_params`] over the domain
    /// into `out` (`count · DIM` entries; a shorter buffer is filled as far as it goes). Cubics: forward
    /// differences re-anchored every 16 samples (rounding cannot build up); other degrees: Horner.
    pub fn sample_uniform_into(&self, count: usize, out: &mut [f64]) {
        let p = self.degree;
        let (a, b) = self.domain();
        let l = self.segments();
        let count = count.min(out.len() / P::DIM);
        if count == 0 {
            return;
        }
        let out = &mut out[..count * P::DIM];
        let step = if count > 1 {
            (b - a) / (count - 1) as f64
        } else {
            0.0
        };
        let param = |i: usize| {
            if i + 1 == count && count > 1 {
                b
            } else {
                a + step * i as f64
            }
        };
        let mut i = 0usize;
        for seg in 0..l {
            let (t0, t1) = (self.breaks[seg], self.breaks[seg + 1]);
            let last = seg + 1 == l;
            let end = if last {
                count
            } else {
                let guess = ((t1 - a) / step).ceil();
                let mut e = if guess >= 0.0 {
                    (guess as usize).clamp(i, count)
                } else {
                    i
                };
                while e > i && param(e - 1) >= t1 {
                    e -= 1;
                }
                while e < count && param(e) < t1 {
                    e += 1;
                }
                e
            };
            if end > i {
                let coef = &self.coef[seg * (p + 1)..(seg + 1) * (p + 1)];
                let inv = self.inv[seg];
                let body_end = end.min(count - 1).max(i);
                let body = &mut out[i * P::DIM..body_end * P::DIM];
                let u0 = i;
                if p == 3 {
                    const ANCHOR: usize = 16;
                    let (c0, c1, c2, c3) = (coef[0], coef[1], coef[2], coef[3]);
                    let h = step * inv;
                    let mut blocks = body.chunks_exact_mut(P::DIM * ANCHOR);
                    for (bi, block) in (&mut blocks).enumerate() {
                        let t = (a + step * (u0 + bi * ANCHOR) as f64 - t0) * inv;
                        let mut v = ((c3 * t + c2) * t + c1) * t + c0;
                        let mut d1 = c1 * h
                            + c2 * (h * (2.0 * t + h))
                            + c3 * (h * (3.0 * t * t + 3.0 * t * h + h * h));
                        let mut d2 = c2 * (2.0 * h * h) + c3 * (6.0 * h * h * (t + h));
                        let d3 = c3 * (6.0 * h * h * h);
                        for o in block.chunks_exact_mut(P::DIM) {
                            v.write_coords(o);
                            v += d1;
                            d1 += d2;
                            d2 += d3;
                        }
                    }
                    let done = (body_end - u0) / ANCHOR * ANCHOR;
                    for (k, o) in blocks.into_remainder().chunks_exact_mut(P::DIM).enumerate() {
                        let t = (a + step * (u0 + done + k) as f64 - t0) * inv;
                        (((c3 * t + c2) * t + c1) * t + c0).write_coords(o);
                    }
                } else {
                    for (k, o) in body.chunks_exact_mut(P::DIM).enumerate() {
                        let t = (a + step * (u0 + k) as f64 - t0) * inv;
                        horner(coef, t).write_coords(o);
                    }
                }
                if end == count && body_end < count {
                    let t = (param(count - 1) - t0) * inv;
                    horner(coef, t).write_coords(&mut out[(count - 1) * P::DIM..]);
                }
                i = end;
            }
            if i >= count {
                break;
            }
        }
    }
}

/// Horner's rule: Σ coef[j]·t^j.
#[inline(always)]
pub(crate) fn horner<P: Point>(coef: &[P], t: f64) -> P {
    let mut it = coef.iter().rev();
    let mut v = it.next().copied().unwrap_or(P::ZERO);
    for c in it {
        v = v * t + *c;
    }
    v
}

/// Power coefficients of the Bézier polynomial with control points `bez` (degree m = `bez.len() − 1`):
/// c_j = C(m, j) Δ^j b_0, the forward differences taken by a difference table (so the rounding error is
/// relative to the differences, not to the points' distance from the origin).
pub(crate) fn bernstein_to_power<P: Point>(bez: &[P], coef: &mut [P]) {
    let m = bez.len() - 1;
    let mut d = [P::ZERO; W];
    d[..=m].copy_from_slice(bez);
    let mut binom = 1.0;
    for (j, c) in coef.iter_mut().enumerate().take(m + 1) {
        *c = d[0] * binom;
        for i in 0..m - j {
            d[i] = d[i + 1] - d[i];
        }
        binom = binom * (m - j) as f64 / (j + 1) as f64;
    }
}

/// Basis rows of one B-spline direction at many parameters: for each parameter its span and the
/// `degree + 1` non-zero basis values (and first derivatives when asked), computed once.
#[derive(Debug, Clone)]
pub struct BasisRows {
    degree: usize,
    /// First control index of each parameter's non-zero run (span − degree).
    first: Vec<usize>,
    /// `(degree + 1)` values per parameter.
    values: Vec<f64>,
    /// `(degree + 1)` first derivatives per parameter (empty unless asked for).
    d1: Vec<f64>,
}

impl BasisRows {
    /// The rows of the degree-`degree` basis on `knots` (`count` basis functions) at `params`.
    pub fn new(knots: &[f64], degree: usize, count: usize, params: &[f64], derivs: bool) -> Self {
        let w = degree + 1;
        let mut first = Vec::with_capacity(params.len());
        let mut values = Vec::with_capacity(params.len() * w);
        let mut d1 = Vec::with_capacity(if derivs { params.len() * w } else { 0 });
        let mut ders = [[0.0; MAX_DEGREE + 1]; 3];
        for &u in params {
            let span = find_span(knots, degree, count, u);
            basis_derivs(knots, degree, span, u, usize::from(derivs), &mut ders);
            first.push(span - degree);
            values.extend_from_slice(&ders[0][..w]);
            if derivs {
                d1.extend_from_slice(&ders[1][..w]);
            }
        }
        BasisRows {
            degree,
            first,
            values,
            d1,
        }
    }

    /// Number of parameters.
    pub fn len(&self) -> usize {
        self.first.len()
    }
    /// No parameters.
    pub fn is_empty(&self) -> bool {
        self.first.is_empty()
    }
    /// `(first control index, values, first derivatives)` of parameter `i` (derivatives empty unless
    /// computed).
    #[inline(always)]
    pub fn row(&self, i: usize) -> (usize, &[f64], &[f64]) {
        let w = self.degree + 1;
        let d = if self.d1.is_empty() {
            &[][..]
        } else {
            &self.d1[i * w..(i + 1) * w]
        };
        (self.first[i], &self.values[i * w..(i + 1) * w], d)
    }
}

/// A tensor-product B-spline surface as the grid sampler reads it: S(u, v) = Σ_i Σ_j N_{i,p}(u) N_{j,q}(v) P_ij
/// with the control points `points` row-major (`P_ij` at `i · nv + j`, `size` = (nu, nv)). Plain data, so that
/// the kernel needs no construction type ([`crate::bspline::BSplineSurface`] and the knot-modified surfaces
/// lend theirs).
pub struct TensorNet<'a, P: Point> {
    /// The knot vectors in u and in v.
    pub knots: (&'a [f64], &'a [f64]),
    /// The degrees (p, q).
    pub degrees: (usize, usize),
    /// The number of control points (nu, nv).
    pub size: (usize, usize),
    /// The control points, row-major.
    pub points: &'a [P],
}

/// The grid sampler of tensor-product B-spline surfaces (module docs).
pub struct TensorGrid;

impl TensorGrid {
    /// Samples `s` on the u-major grid `us × vs` (point `iu · vs.len() + iv`) into flat buffers; `du`, `dv`
    /// only when `derivs` (each `us.len() · vs.len() · DIM` entries, unused ones may be empty).
    pub fn sample_into<P: Point>(
        s: &TensorNet<'_, P>,
        us: &[f64],
        vs: &[f64],
        derivs: bool,
        points: &mut [f64],
        du: &mut [f64],
        dv: &mut [f64],
    ) {
        let (p, q) = s.degrees;
        let (nu, nv) = s.size;
        let (knots_u, knots_v) = s.knots;
        let ctrl = s.points;
        let rows_v = BasisRows::new(knots_v, q, nv, vs, derivs);
        let mut iso = vec![P::ZERO; nv];
        let mut iso_d = vec![P::ZERO; if derivs { nv } else { 0 }];
        let dim = P::DIM;
        let mut ders = [[0.0; MAX_DEGREE + 1]; 3];
        let m = vs.len();
        for (iu, &u) in us.iter().enumerate() {
            let span = find_span(knots_u, p, nu, u);
            basis_derivs(knots_u, p, span, u, usize::from(derivs), &mut ders);
            // isocurve control points of this grid row (and of ∂/∂u)
            for (j, x) in iso.iter_mut().enumerate() {
                let mut acc = P::ZERO;
                for a in 0..=p {
                    acc += ctrl[(span - p + a) * nv + j] * ders[0][a];
                }
                *x = acc;
            }
            if derivs {
                for (j, x) in iso_d.iter_mut().enumerate() {
                    let mut acc = P::ZERO;
                    for a in 0..=p {
                        acc += ctrl[(span - p + a) * nv + j] * ders[1][a];
                    }
                    *x = acc;
                }
            }
            let base = iu * m;
            for iv in 0..m {
                let (f, nvals, nd) = rows_v.row(iv);
                let mut acc = P::ZERO;
                for b in 0..=q {
                    acc += iso[f + b] * nvals[b];
                }
                acc.write_coords(&mut points[(base + iv) * dim..]);
                if derivs {
                    let (mut au, mut av) = (P::ZERO, P::ZERO);
                    for b in 0..=q {
                        au += iso_d[f + b] * nvals[b];
                        av += iso[f + b] * nd[b];
                    }
                    au.write_coords(&mut du[(base + iv) * dim..]);
                    av.write_coords(&mut dv[(base + iv) * dim..]);
                }
            }
        }
    }
}

/// How many of `count` samples the flat output buffers hold (`dim` coordinates each): `points`, and `d1`, `d2`
/// where `order` asks for them. The batch samplers stop there: a short buffer ends the evaluation.
pub(crate) fn samples_that_fit(
    count: usize,
    dim: usize,
    order: usize,
    points: &[f64],
    d1: &[f64],
    d2: &[f64],
) -> usize {
    let mut n = count.min(points.len() / dim);
    if order >= 1 {
        n = n.min(d1.len() / dim);
    }
    if order >= 2 {
        n = n.min(d2.len() / dim);
    }
    n
}

#[cfg(test)]
mod tests {
    use super::samples_that_fit;

    #[test]
    fn a_short_buffer_ends_the_samples_only_where_it_is_written() {
        let (p, d) = ([0.0; 20], [0.0; 20]);
        // 2D: 10 samples fit each full buffer; a d2 of 8 numbers holds 4, an empty unused one does not count
        assert_eq!(samples_that_fit(12, 2, 2, &p, &d, &[0.0; 8]), 4);
        assert_eq!(samples_that_fit(12, 2, 1, &p, &d, &[]), 10);
        assert_eq!(samples_that_fit(12, 2, 0, &p, &[], &[]), 10);
        assert_eq!(samples_that_fit(3, 2, 2, &p, &d, &d), 3);
        assert_eq!(samples_that_fit(12, 2, 1, &p, &[0.0; 5], &[]), 2);
    }
}
