//! Seed 002 (Juhász–Hoffmann, *On the family of B-spline surfaces obtained by knot modification*):
//! the one- and two-parameter families obtained by moving a knot, paths and path-surfaces, their limits
//! (Theorems 3–4) and envelopes (eqs. (6), (8)); the curve case of the same (the paper's ref. \[2\], \[6\]).
//!
//! Conventions follow the paper and `surfaces.md` §7 (binding):
//! * orders `k` (u) and `l` (v), degree = order − 1; full knot vectors `u_0..u_{n+k}`, `v_0..v_{m+l}`,
//!   control net `d_rs`, r = 0..n, s = 0..m. The knot index `p` is the 0-based index into the full
//!   vector (the paper's own index), and must be an **interior** knot, `k ≤ p ≤ n` (so that both
//!   neighbouring intervals lie in the domain `[u_{k−1}, u_{n+1}]` and the limit control points
//!   `d_p`, `d_{p−k}` exist).
//! * **Family** s(u, v; u_p): the knot `u_p` replaced by any finite value. The other knots must be
//!   non-decreasing (validated); the moved one is not. Evaluation is the de Boor recursion as pure algebra
//!   in the knots: the span of `u` is found on the knot vector *with `u_p` removed*; for
//!   `u ∈ [u_{p−1}, u_{p+1})` the piece of span `p` is used if `u ≥ u_p`, else the piece of span `p − 1`
//!   (so values of `u_p` outside `[u_{p−1}, u_{p+1}]` give the **extended** paths of §2 of the paper);
//!   elsewhere the ordinary span. Inside its neighbours this is the ordinary B-spline with the modified knot.
//!   A vanishing denominator of the recursion counts as 0/0 := 0 (Definition 1).
//! * `u_p = ±∞` is accepted by the core and evaluated exactly (the recursion weight with the infinite knot
//!   on its left is 1, on its right 0): the limits of Theorems 3–4. With the corrected list of
//!   `surfaces.md` §8.6: (u_p, v_q) → (−∞, −∞): d_{p,q}; (−∞, +∞): d_{p,q−l}; (+∞, −∞): d_{p−k,q};
//!   (+∞, +∞): d_{p−k,q−l}.
//! * **Envelope** (6): order `k − 1` B-splines on the knot vector `w` = `u` with `u_p` removed, control rows
//!   `p−k+1..p−1`, `w ∈ [u_{p−1}, u_{p+1}]` (that is the piece of `w`-span `p − 1`; outside it the same
//!   polynomial piece is continued). (8): the same in both directions. Contact relations (9), (10) and
//!   Theorems 5–8 hold with this choice (`surfaces.md` §7, §8.7).
//!
//! Derivatives are exact: the recursion is generic over a [`Scalar`], and [`Jet`] (truncated Taylor series)
//! gives derivatives in `u`, `v` or in the moved knot itself (∂s/∂u_p of Theorem 7).

#![allow(clippy::needless_range_loop)] // index loops pair weights with control points

use crate::bspline::{BSplineCurve, BSplineSurface};
use crate::error::{check_finite, Error, Result};
use crate::kernel::{PiecewisePoly, TensorGrid};
use crate::knots::MAX_DEGREE;
use crate::point::Point;
use crate::sample::{Curve, Surface};
use std::ops::{Add, Div, Mul, Sub};

/// The largest order supported (degree ≤ [`MAX_DEGREE`]).
pub const MAX_ORDER: usize = MAX_DEGREE + 1;
const W: usize = MAX_ORDER;

// ---------------------------------------------------------------------------------------------------
// Scalars: f64 and truncated Taylor series
// ---------------------------------------------------------------------------------------------------

/// The number type of the recursion: `f64`, or a [`Jet`] to carry derivatives along.
pub trait Scalar:
    Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self>
{
    /// A constant.
    fn constant(x: f64) -> Self;
    /// The value (the constant Taylor coefficient).
    fn value(self) -> f64;
}

impl Scalar for f64 {
    fn constant(x: f64) -> Self {
        x
    }
    fn value(self) -> f64 {
        self
    }
}

/// A truncated Taylor series `c_0 + c_1 ε + … + c_{N−1} ε^{N−1}` in one variable: arithmetic on jets
/// propagates exact derivatives (the i-th derivative is `i!·c_i`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Jet<const N: usize>(pub [f64; N]);

impl<const N: usize> Jet<N> {
    /// The independent variable at `x` (`x + ε`).
    pub fn variable(x: f64) -> Self {
        let mut c = [0.0; N];
        c[0] = x;
        if N > 1 {
            c[1] = 1.0;
        }
        Jet(c)
    }
    /// The i-th derivative `i!·c_i`.
    pub fn derivative(&self, i: usize) -> f64 {
        self.0[i] * factorial(i)
    }
}

fn factorial(i: usize) -> f64 {
    (1..=i).fold(1.0, |a, b| a * b as f64)
}

impl<const N: usize> Add for Jet<N> {
    type Output = Self;
    fn add(mut self, o: Self) -> Self {
        for i in 0..N {
            self.0[i] += o.0[i];
        }
        self
    }
}
impl<const N: usize> Sub for Jet<N> {
    type Output = Self;
    fn sub(mut self, o: Self) -> Self {
        for i in 0..N {
            self.0[i] -= o.0[i];
        }
        self
    }
}
impl<const N: usize> Mul for Jet<N> {
    type Output = Self;
    fn mul(self, o: Self) -> Self {
        let mut c = [0.0; N];
        for i in 0..N {
            for j in 0..=i {
                c[i] += self.0[j] * o.0[i - j];
            }
        }
        Jet(c)
    }
}
impl<const N: usize> Div for Jet<N> {
    type Output = Self;
    fn div(self, o: Self) -> Self {
        let mut q = [0.0; N];
        for i in 0..N {
            let mut s = self.0[i];
            for j in 1..=i {
                s -= o.0[j] * q[i - j];
            }
            q[i] = s / o.0[0];
        }
        Jet(q)
    }
}
impl<const N: usize> Scalar for Jet<N> {
    fn constant(x: f64) -> Self {
        let mut c = [0.0; N];
        c[0] = x;
        Jet(c)
    }
    fn value(self) -> f64 {
        self.0[0]
    }
}

// ---------------------------------------------------------------------------------------------------
// One parameter direction
// ---------------------------------------------------------------------------------------------------

/// One parameter direction of a B-spline: order `k`, full knots `u_0..u_{n+k}` for `n + 1` control points,
/// and optionally the index `p` of a knot whose value is replaced at evaluation time.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotLine {
    order: usize,
    knots: Vec<f64>,
    count: usize,
    moved: Option<usize>,
    /// Evaluate every parameter on this span (the envelope's single polynomial piece).
    fixed_span: Option<usize>,
}

impl KnotLine {
    /// Validates a direction: `2 ≤ order ≤ MAX_ORDER`, `count ≥ order` control points, `count + order`
    /// finite knots, non-decreasing and of multiplicity ≤ order apart from the moved one (`moved`, which must
    /// be an interior index `order ≤ p ≤ count − 1`), and a non-empty domain `[u_{k−1}, u_{n+1}]`.
    /// `field`/`order_field`/`index_field` name the inputs in errors (`"knotsU"`, `"orderU"`, `"p"`).
    pub fn new(
        field: &'static str,
        order_field: &'static str,
        index_field: &'static str,
        order: usize,
        knots: Vec<f64>,
        count: usize,
        moved: Option<usize>,
    ) -> Result<Self> {
        if order < 2 {
            return Err(Error::out_of_range(
                order_field,
                format!("the order must be at least 2 (degree ≥ 1), got {order}"),
            ));
        }
        if order > MAX_ORDER {
            return Err(Error::out_of_range(
                order_field,
                format!("the order must be at most {MAX_ORDER}, got {order}"),
            ));
        }
        if count < order {
            return Err(Error::too_few(
                "controlPoints",
                format!("need at least {order} control points along {field} for order {order}, got {count}"),
            ));
        }
        if knots.len() != count + order {
            return Err(Error::size_mismatch(
                field,
                format!(
                    "expected {} knots (control points + order = {count} + {order}), got {}",
                    count + order,
                    knots.len()
                ),
            ));
        }
        check_finite(field, &knots)?;
        if let Some(p) = moved {
            if p < order || p + 1 > count {
                return Err(Error::out_of_range(
                    index_field,
                    format!(
                        "the moved knot must be an interior knot, index {order}..={} (order {order}, {count} control points), got {p}",
                        count - 1
                    ),
                ));
            }
        }
        // the knots other than the moved one: non-decreasing, multiplicity ≤ order
        let idx: Vec<usize> = (0..knots.len()).filter(|&i| Some(i) != moved).collect();
        let mut run = 1;
        for w in idx.windows(2) {
            let (a, b) = (knots[w[0]], knots[w[1]]);
            if b < a {
                return Err(Error::not_increasing(
                    format!("{field}[{}]", w[1]),
                    format!("knots must not decrease, but {b} follows {a}"),
                ));
            }
            if b == a {
                run += 1;
                if run > order {
                    return Err(Error::degenerate(
                        format!("{field}[{}]", w[1]),
                        format!("knot {b} repeated more than order = {order} times"),
                    ));
                }
            } else {
                run = 1;
            }
        }
        let (a, b) = (knots[order - 1], knots[count]);
        if a >= b {
            return Err(Error::degenerate(
                field,
                format!(
                    "empty domain: knot {} = {a} must be < knot {count} = {b}",
                    order - 1
                ),
            ));
        }
        Ok(KnotLine {
            order,
            knots,
            count,
            moved,
            fixed_span: None,
        })
    }

    /// The envelope direction of eq. (6): order `k − 1` on `w` = the knots with `u_p` removed, always
    /// evaluated on the `w`-span `p − 1` (basis functions `N_{p−k+1..p−1}`).
    pub fn envelope(&self) -> Option<KnotLine> {
        let p = self.moved?;
        let mut w = self.knots.clone();
        w.remove(p);
        Some(KnotLine {
            order: self.order - 1,
            knots: w,
            count: self.count,
            moved: None,
            fixed_span: Some(p - 1),
        })
    }

    /// The order k = degree + 1.
    pub fn order(&self) -> usize {
        self.order
    }
    /// The full knot vector as given (the moved knot at its original value).
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }
    /// Number of control points `n + 1`.
    pub fn count(&self) -> usize {
        self.count
    }
    /// Index of the moved knot.
    pub fn moved(&self) -> Option<usize> {
        self.moved
    }

    /// The parameter domain `[u_{k−1}, u_{n+1}]` (for an envelope direction: `[u_{p−1}, u_{p+1}]`).
    pub fn domain(&self) -> (f64, f64) {
        match self.fixed_span {
            Some(s) => (self.knots[s], self.knots[s + 1]),
            None => (self.knots[self.order - 1], self.knots[self.count]),
        }
    }

    /// The ordinary knot vector this direction is while the moved knot lies strictly between its
    /// neighbours (or no knot is moved): `u_p` replaced by `up`. `None` otherwise (the extended family of
    /// the module docs, or an envelope direction): then there is no B-spline to hand to the kernel.
    pub fn modified_knots(&self, up: f64) -> Option<Vec<f64>> {
        if self.fixed_span.is_some() {
            return None;
        }
        let mut k = self.knots.clone();
        if let Some(p) = self.moved {
            if !(self.knots[p - 1] < up && up < self.knots[p + 1]) {
                return None;
            }
            k[p] = up;
        }
        Some(k)
    }

    /// The neighbours `(u_{p−1}, u_{p+1})` of the moved knot.
    pub fn neighbours(&self) -> Option<(f64, f64)> {
        self.moved.map(|p| (self.knots[p - 1], self.knots[p + 1]))
    }

    /// Spans whose piece depends on `u_p`: `max(p−k+1, k−1) ..= min(p+k−2, n)`, and the parameter range
    /// they cover, `[u_{p−k+1}, u_{p+k−1}] ∩ [u_{k−1}, u_{n+1}]` (paper §2: the strip D₁).
    pub fn affected(&self) -> Option<((usize, usize), (f64, f64))> {
        let p = self.moved?;
        let k = self.order;
        let lo = (p + 1).saturating_sub(k).max(k - 1);
        let hi = (p + k - 2).min(self.count - 1);
        Some(((lo, hi), (self.knots[lo], self.knots[hi + 1])))
    }

    /// Knot `j` of the sequence with `u_p` replaced by `up`.
    fn knot<T: Scalar>(&self, j: usize, up: T) -> T {
        if Some(j) == self.moved {
            up
        } else {
            T::constant(self.knots[j])
        }
    }

    /// The span (in the full, original indexing) whose polynomial piece gives the point at `u` when the
    /// moved knot has the value `up` (module doc). `left`: at `u = u_p` take the piece left of the knot
    /// (and at `u = u_{p+1}` the piece of `[u_{p−1}, u_{p+1})`).
    pub fn span(&self, u: f64, up: f64, left: bool) -> usize {
        if let Some(s) = self.fixed_span {
            return s;
        }
        let k = self.order;
        let n = self.count - 1;
        match self.moved {
            None => span_search(k - 1, n, |j| self.knots[j], u),
            Some(p) => {
                // spans of w (u with u_p removed): w_j = u_j (j < p), u_{j+1} (j ≥ p); w-spans k−1..=n−1
                let w = |j: usize| {
                    if j < p {
                        self.knots[j]
                    } else {
                        self.knots[j + 1]
                    }
                };
                let mut j = span_search(k - 1, n - 1, w, u);
                if left && j == p && u == w(p) {
                    // u = u_{p+1}: the piece on the left is the one of [u_{p−1}, u_{p+1})
                    j = p - 1;
                }
                if j + 1 < p {
                    j
                } else if j + 1 > p {
                    j + 1
                } else {
                    let right = if left { u > up } else { u >= up };
                    if right && up < self.knots[p + 1] {
                        p
                    } else {
                        p - 1
                    }
                }
            }
        }
    }

    /// The `k` non-zero weights `N_{i−k+1..i}` of span `i` at `u` (generic, pure algebra in the knots,
    /// `u_p := up`), by the Cox–de Boor recursion
    /// N_j^r = ω_j^r N_j^{r−1} + (1 − ω_{j+1}^r) N_{j+1}^{r−1}, ω_j^r = (u − u_j)/(u_{j+r−1} − u_j).
    /// An infinite `up` gives ω = 1 when it is the left knot u_j and ω = 0 when it is the right one.
    pub fn weights<T: Scalar>(&self, i: usize, u: T, up: T, out: &mut [T; W]) {
        let k = self.order;
        let inf = up.value().is_infinite();
        let omega = |j: usize, r: usize| -> T {
            if inf && Some(j) == self.moved {
                return T::constant(1.0);
            }
            if inf && Some(j + r - 1) == self.moved {
                return T::constant(0.0);
            }
            let a = self.knot(j, up);
            let den = self.knot(j + r - 1, up) - a;
            if den.value() == 0.0 {
                T::constant(0.0)
            } else {
                (u - a) / den
            }
        };
        out[0] = T::constant(1.0);
        for r in 2..=k {
            // before: out[a] = N_{i−r+2+a}^{r−1}, a = 0..r−2; after: out[a] = N_{i−r+1+a}^{r}, a = 0..r−1
            out[r - 1] = T::constant(0.0);
            for a in (0..r).rev() {
                let j = i + 1 + a - r; // i − r + 1 + a
                let mut v = T::constant(0.0);
                if a >= 1 {
                    v = v + omega(j, r) * out[a - 1];
                }
                if a + 1 < r {
                    v = v + (T::constant(1.0) - omega(j + 1, r)) * out[a];
                }
                out[a] = v;
            }
        }
    }
}

/// The largest `j ∈ [lo, hi]` with `t(j) ≤ u < t(j+1)` and `t(j) < t(j+1)` (right-hand piece); parameters
/// at or beyond `t(hi+1)` use the last non-empty span, parameters before `t(lo)` the first one.
fn span_search(lo: usize, hi: usize, t: impl Fn(usize) -> f64, u: f64) -> usize {
    if u >= t(hi + 1) {
        let mut s = hi;
        while s > lo && t(s) >= t(s + 1) {
            s -= 1;
        }
        return s;
    }
    if u <= t(lo) {
        let mut s = lo;
        while s < hi && t(s + 1) <= t(lo) {
            s += 1;
        }
        return s;
    }
    let (mut a, mut b) = (lo, hi + 1);
    while b - a > 1 {
        let mid = (a + b) / 2;
        if u < t(mid) {
            b = mid;
        } else {
            a = mid;
        }
    }
    a
}

fn check_points<P: Point>(field: &'static str, points: &[P], cols: usize) -> Result<()> {
    match points.iter().position(|p| !p.is_finite()) {
        None => Ok(()),
        Some(i) if cols > 0 => Err(Error::not_finite(
            format!("{field}[{}][{}]", i / cols, i % cols),
            "expected finite coordinates",
        )),
        Some(i) => Err(Error::not_finite(
            format!("{field}[{i}]"),
            "expected finite coordinates",
        )),
    }
}

fn check_knot_value(field: &'static str, x: f64) -> Result<()> {
    if x.is_nan() {
        Err(Error::not_finite(field, "expected a number, got NaN"))
    } else {
        Ok(())
    }
}

// ---------------------------------------------------------------------------------------------------
// Curves
// ---------------------------------------------------------------------------------------------------

/// The family a(u; u_p) of a B-spline curve of order `k` (paper's Definition 2) with the knot `u_p`
/// replaced by a value `up` (any number; ±∞ gives the limits). Implements [`Curve`] at its current `up`.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotModifiedCurve<P: Point> {
    line: KnotLine,
    points: Vec<P>,
    up: f64,
}

impl<P: Point> KnotModifiedCurve<P> {
    /// The curve of order `order` with `knots` (`points + order` of them) and control points `points`,
    /// the knot of index `p` replaced by `up` (NaN rejected, ±∞ accepted). `p = None`: the ordinary curve.
    pub fn new(
        order: usize,
        knots: Vec<f64>,
        points: Vec<P>,
        p: Option<usize>,
        up: f64,
    ) -> Result<Self> {
        check_points("controlPoints", &points, 0)?;
        let line = KnotLine::new("knots", "order", "p", order, knots, points.len(), p)?;
        check_knot_value("up", up)?;
        let up = if p.is_some() { up } else { 0.0 };
        Ok(KnotModifiedCurve { line, points, up })
    }

    /// The knot line (knots and the knot that moves).
    pub fn line(&self) -> &KnotLine {
        &self.line
    }
    /// The control points.
    pub fn points(&self) -> &[P] {
        &self.points
    }
    /// The current value of the moved knot.
    pub fn up(&self) -> f64 {
        self.up
    }
    /// The same curve with the moved knot at `up`.
    pub fn with_up(&self, up: f64) -> Self {
        KnotModifiedCurve {
            line: self.line.clone(),
            points: self.points.clone(),
            up,
        }
    }

    /// Taylor coefficients in `u` of the piece used at `u` (`left`: the piece left of the moved knot at
    /// `u = u_p`), with the moved knot at `up`: `out[i]` = (1/i!) dⁱa/duⁱ.
    pub fn taylor_u<const N: usize>(&self, u: f64, up: f64, left: bool) -> [P; N] {
        let i = self.line.span(u, up, left);
        let mut w = [Jet::<N>::constant(0.0); W];
        self.line
            .weights(i, Jet::<N>::variable(u), Jet::constant(up), &mut w);
        self.combine_jets(i, &w)
    }

    fn combine_jets<const N: usize>(&self, i: usize, w: &[Jet<N>; W]) -> [P; N] {
        let k = self.line.order;
        let mut out = [P::ZERO; N];
        for a in 0..k {
            let d = self.points[i + 1 + a - k];
            for (c, o) in out.iter_mut().enumerate() {
                *o += d * w[a].0[c];
            }
        }
        out
    }

    /// The point a(u; up).
    pub fn eval_at(&self, u: f64, up: f64) -> P {
        let i = self.line.span(u, up, false);
        let mut w = [0.0; W];
        self.line.weights(i, u, up, &mut w);
        let k = self.line.order;
        let mut acc = P::ZERO;
        for a in 0..k {
            acc += self.points[i + 1 + a - k] * w[a];
        }
        acc
    }

    /// ∂a/∂u_p at `(u, up)` (the tangent of the path; `left` as in [`Self::taylor_u`]).
    pub fn d_dup(&self, u: f64, up: f64, left: bool) -> P {
        let i = self.line.span(u, up, left);
        let mut w = [Jet::<2>::constant(0.0); W];
        self.line
            .weights(i, Jet::constant(u), Jet::<2>::variable(up), &mut w);
        self.combine_jets(i, &w)[1]
    }

    /// The path of the point with parameter `u`: a(u; up) for each `up` in `ups`, into `out`.
    pub fn path_into(&self, u: f64, ups: &[f64], out: &mut Vec<P>) {
        out.extend(ups.iter().map(|&up| self.eval_at(u, up)));
    }

    /// The limit points of Theorem 5 of \[2\]: `(d_p, d_{p−k})` for `u_p → −∞`, `+∞` (valid for
    /// `u ∈ [u_{p−1}, u_{p+1})`), with their indices.
    pub fn limits(&self) -> Option<((usize, P), (usize, P))> {
        let p = self.line.moved?;
        let k = self.line.order;
        Some(((p, self.points[p]), (p - k, self.points[p - k])))
    }

    /// The envelope of the family (the curve case of eq. (6)): e(w) = Σ_{r=p−k+1}^{p−1} N_r^{k−1}(w) d_r on
    /// the knots with `u_p` removed, `w ∈ [u_{p−1}, u_{p+1}]`.
    pub fn envelope(&self) -> Option<KnotEnvelopeCurve<P>> {
        Some(KnotEnvelopeCurve {
            line: self.line.envelope()?,
            points: self.points.clone(),
        })
    }
}

impl<P: Point> KnotModifiedCurve<P> {
    /// The B-spline this curve is while `u_p` stays strictly between its neighbours (else `None`).
    pub fn bspline(&self) -> Option<BSplineCurve<P>> {
        let knots = self.line.modified_knots(self.up)?;
        BSplineCurve::new(self.line.order - 1, knots, self.points.clone()).ok()
    }
}

impl<P: Point> Curve<P> for KnotModifiedCurve<P> {
    fn domain(&self) -> (f64, f64) {
        self.line.domain()
    }
    /// The kernel's path while `u_p` stays strictly between its neighbours.
    fn piecewise(&self) -> Option<PiecewisePoly<P>> {
        self.bspline()?.to_piecewise()
    }
    fn eval_derivs(&self, u: f64, order: usize, out: &mut [P; 3]) {
        let t = self.taylor_u::<3>(u, self.up, false);
        out[0] = t[0];
        if order >= 1 {
            out[1] = t[1];
        }
        if order >= 2 {
            out[2] = t[2] * 2.0;
        }
    }
}

/// The envelope curve of the family a(u; u_p) (see [`KnotModifiedCurve::envelope`]).
#[derive(Debug, Clone, PartialEq)]
pub struct KnotEnvelopeCurve<P: Point> {
    line: KnotLine,
    points: Vec<P>,
}

impl<P: Point> KnotEnvelopeCurve<P> {
    /// Taylor coefficients in `w`: `out[i]` = (1/i!) dⁱe/dwⁱ.
    pub fn taylor<const N: usize>(&self, w: f64) -> [P; N] {
        let i = self.line.span(w, 0.0, false);
        let mut wt = [Jet::<N>::constant(0.0); W];
        self.line
            .weights(i, Jet::<N>::variable(w), Jet::constant(0.0), &mut wt);
        let k = self.line.order;
        let mut out = [P::ZERO; N];
        for a in 0..k {
            let d = self.points[i + 1 + a - k];
            for (c, o) in out.iter_mut().enumerate() {
                *o += d * wt[a].0[c];
            }
        }
        out
    }
}

impl<P: Point> Curve<P> for KnotEnvelopeCurve<P> {
    fn domain(&self) -> (f64, f64) {
        self.line.domain()
    }
    fn eval_derivs(&self, w: f64, order: usize, out: &mut [P; 3]) {
        let t = self.taylor::<3>(w);
        out[0] = t[0];
        if order >= 1 {
            out[1] = t[1];
        }
        if order >= 2 {
            out[2] = t[2] * 2.0;
        }
    }
}

// ---------------------------------------------------------------------------------------------------
// Surfaces
// ---------------------------------------------------------------------------------------------------

/// A tensor-product B-spline surface (eq. (1)) with optionally the knot `u_p` and/or `v_q` replaced:
/// the families (5) and (7), extended to any values (module doc). Implements [`Surface`] at the current
/// `(up, vq)`.
///
/// # Template
/// * **What**: the family s(u, v; u_p, v_q) of seed 002 (Juhász–Hoffmann): a tensor B-spline surface (eq. (1))
///   with the knot u_p (and/or v_q) replaced by any finite value (families (5), (7)).
/// * **Interpolates**: nothing in general; with the knot unmoved it is the original surface.
/// * **Continuity**: that of the modified knot vectors (C^{k−1−μ} across a knot of multiplicity μ); across
///   u_p it drops when the moved knot meets a neighbour.
/// * **Parametrisation**: the domain [u_{k−1}, u_{n+1}] × [v_{l−1}, v_{m+1}] of the (modified) knots.
///
/// # Example
/// ```
/// use glam::DVec3;
/// use splinelab::{knot_paths::KnotModifiedSurface, Surface};
/// let knots = vec![0.0, 0.0, 0.0, 1.0, 2.0, 2.0, 2.0]; // order 3, 4 control points, interior knot p = 3
/// let pts: Vec<DVec3> = (0..16).map(|i| DVec3::new((i / 4) as f64, (i % 4) as f64, ((i * 7) % 5) as f64)).collect();
/// let s0 = KnotModifiedSurface::new(3, 3, knots.clone(), knots.clone(), 4, 4, pts.clone(), None, None)?;
/// // moving u_3 to its own value changes nothing
/// let s1 = KnotModifiedSurface::new(3, 3, knots.clone(), knots, 4, 4, pts, Some((3, 1.0)), None)?;
/// for (u, v) in [(0.2, 0.3), (1.0, 1.5), (1.7, 0.9)] {
///     assert!((s0.eval(u, v) - s1.eval(u, v)).length() < 1e-12);
/// }
/// assert_eq!(s0.domain(), ((0.0, 2.0), (0.0, 2.0)));
/// # Ok::<(), splinelab::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct KnotModifiedSurface<P: Point> {
    lu: KnotLine,
    lv: KnotLine,
    /// `d_rs` at `r * nv + s`.
    points: Vec<P>,
    up: f64,
    vq: f64,
}

/// A limit control row or column with its index (Theorem 3).
pub type LimitRow<P> = (usize, Vec<P>);

/// Which knot a derivative is taken with respect to.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Var {
    /// The surface parameter u.
    U,
    /// The surface parameter v.
    V,
    /// The moved knot u_p.
    Up,
    /// The moved knot v_q.
    Vq,
}

impl<P: Point> KnotModifiedSurface<P> {
    /// The surface of orders `(k, l)` with knots `knots_u` (`nu + k`), `knots_v` (`nv + l`) and the control
    /// net `points[r * nv + s]` = d_rs (`nu × nv`), with knot `p` of u replaced by `up` and knot `q` of v by
    /// `vq` (either, both or none).
    #[allow(clippy::too_many_arguments)]
    pub fn new(
        order_u: usize,
        order_v: usize,
        knots_u: Vec<f64>,
        knots_v: Vec<f64>,
        nu: usize,
        nv: usize,
        points: Vec<P>,
        moved_u: Option<(usize, f64)>,
        moved_v: Option<(usize, f64)>,
    ) -> Result<Self> {
        if points.len() != nu * nv {
            return Err(Error::size_mismatch(
                "controlPoints",
                format!("expected {nu} × {nv} control points, got {}", points.len()),
            ));
        }
        check_points("controlPoints", &points, nv)?;
        let lu = KnotLine::new(
            "knotsU",
            "orderU",
            "p",
            order_u,
            knots_u,
            nu,
            moved_u.map(|m| m.0),
        )?;
        let lv = KnotLine::new(
            "knotsV",
            "orderV",
            "q",
            order_v,
            knots_v,
            nv,
            moved_v.map(|m| m.0),
        )?;
        let up = moved_u.map_or(0.0, |m| m.1);
        let vq = moved_v.map_or(0.0, |m| m.1);
        check_knot_value("up", up)?;
        check_knot_value("vq", vq)?;
        Ok(KnotModifiedSurface {
            lu,
            lv,
            points,
            up,
            vq,
        })
    }

    /// The knot line in u.
    pub fn line_u(&self) -> &KnotLine {
        &self.lu
    }
    /// The knot line in v.
    pub fn line_v(&self) -> &KnotLine {
        &self.lv
    }
    /// `(nu, nv)`.
    pub fn size(&self) -> (usize, usize) {
        (self.lu.count, self.lv.count)
    }
    /// The control point (r, s): r along u, s along v.
    pub fn point(&self, r: usize, s: usize) -> P {
        self.points[r * self.lv.count + s]
    }
    /// The current values `(up, vq)` of the moved knots.
    pub fn knot_values(&self) -> (f64, f64) {
        (self.up, self.vq)
    }
    /// The same surface with the moved knots at `(up, vq)`.
    pub fn with_knots(&self, up: f64, vq: f64) -> Self {
        KnotModifiedSurface {
            lu: self.lu.clone(),
            lv: self.lv.clone(),
            points: self.points.clone(),
            up,
            vq,
        }
    }

    /// Σ_a Σ_b wu[a]_i wv[b]_j d: the Taylor coefficients `out[i][j]` of a tensor combination.
    fn combine<const N: usize, const M: usize>(
        &self,
        (iu, iv): (usize, usize),
        wu: &[Jet<N>; W],
        wv: &[Jet<M>; W],
    ) -> [[P; M]; N] {
        let (k, l) = (self.lu.order, self.lv.order);
        let nv = self.lv.count;
        let mut out = [[P::ZERO; M]; N];
        for a in 0..k {
            let r = iu + 1 + a - k;
            let mut row = [P::ZERO; M];
            for b in 0..l {
                let d = self.points[r * nv + iv + 1 + b - l];
                for (j, x) in row.iter_mut().enumerate() {
                    *x += d * wv[b].0[j];
                }
            }
            for (i, o) in out.iter_mut().enumerate() {
                for j in 0..M {
                    o[j] += row[j] * wu[a].0[i];
                }
            }
        }
        out
    }

    /// The Taylor coefficients `out[i][j]` = (1/(i! j!)) ∂^{i+j}/∂xⁱ∂yʲ of s(u, v; up, vq), where `x` is
    /// `u` or `up` (per `xu`) and `y` is `v` or `vq` (per `yv`). `left_u`/`left_v`: at `u = u_p`
    /// (`v = v_q`) use the piece on the left of the moved knot.
    #[allow(clippy::too_many_arguments)]
    pub fn taylor<const N: usize, const M: usize>(
        &self,
        u: f64,
        v: f64,
        up: f64,
        vq: f64,
        x: Var,
        y: Var,
        (left_u, left_v): (bool, bool),
    ) -> [[P; M]; N] {
        let iu = self.lu.span(u, up, left_u);
        let iv = self.lv.span(v, vq, left_v);
        let mut wu = [Jet::<N>::constant(0.0); W];
        let mut wv = [Jet::<M>::constant(0.0); W];
        match x {
            Var::Up => self
                .lu
                .weights(iu, Jet::constant(u), Jet::variable(up), &mut wu),
            _ => self
                .lu
                .weights(iu, Jet::variable(u), Jet::constant(up), &mut wu),
        }
        match y {
            Var::Vq => self
                .lv
                .weights(iv, Jet::constant(v), Jet::variable(vq), &mut wv),
            _ => self
                .lv
                .weights(iv, Jet::variable(v), Jet::constant(vq), &mut wv),
        }
        self.combine((iu, iv), &wu, &wv)
    }

    /// The point s(u, v; up, vq) (allocation-free; used for paths and path-surfaces).
    pub fn eval_at(&self, u: f64, v: f64, up: f64, vq: f64) -> P {
        self.taylor::<1, 1>(u, v, up, vq, Var::U, Var::V, (false, false))[0][0]
    }

    /// `(∂s/∂u_p, ∂s/∂v_q)` at `(u, v; up, vq)` (Theorems 7–8).
    pub fn d_dknots(&self, u: f64, v: f64, up: f64, vq: f64, left: (bool, bool)) -> (P, P) {
        let a = self.taylor::<2, 1>(u, v, up, vq, Var::Up, Var::V, left);
        let b = self.taylor::<1, 2>(u, v, up, vq, Var::U, Var::Vq, left);
        (a[1][0], b[0][1])
    }

    /// The path of the point `(u, v)` as `u_p` runs through `ups` (v_q at its current value), into `out`.
    pub fn path_into(&self, u: f64, v: f64, ups: &[f64], out: &mut Vec<P>) {
        out.extend(ups.iter().map(|&up| self.eval_at(u, v, up, self.vq)));
    }

    /// The path of `(u, v)` as `v_q` runs through `vqs` (u_p at its current value).
    pub fn path_v_into(&self, u: f64, v: f64, vqs: &[f64], out: &mut Vec<P>) {
        out.extend(vqs.iter().map(|&vq| self.eval_at(u, v, self.up, vq)));
    }

    /// The path-surface of `(u, v)`: s(u, v; up, vq) on the grid `ups × vqs`, `up`-major, into `out`.
    pub fn path_surface_into(&self, u: f64, v: f64, ups: &[f64], vqs: &[f64], out: &mut Vec<P>) {
        for &up in ups {
            out.extend(vqs.iter().map(|&vq| self.eval_at(u, v, up, vq)));
        }
    }

    /// The limit control curves of Theorem 3 (as control-point rows/columns of the net): for `u_p → −∞`
    /// row `p` (d_{p,s}), for `+∞` row `p − k`; for `v_q → −∞` column `q`, for `+∞` column `q − l`.
    /// Returns `(index, control points)` for (−∞, +∞) in the direction asked for.
    pub fn limit_curves(&self, dir: Var) -> Option<(LimitRow<P>, LimitRow<P>)> {
        let (nu, nv) = self.size();
        match dir {
            Var::U | Var::Up => {
                let p = self.lu.moved?;
                let row = |r: usize| (0..nv).map(|s| self.point(r, s)).collect::<Vec<P>>();
                Some(((p, row(p)), (p - self.lu.order, row(p - self.lu.order))))
            }
            Var::V | Var::Vq => {
                let q = self.lv.moved?;
                let col = |s: usize| (0..nu).map(|r| self.point(r, s)).collect::<Vec<P>>();
                Some(((q, col(q)), (q - self.lv.order, col(q - self.lv.order))))
            }
        }
    }

    /// The limit control points of Theorem 4 (corrected list, `surfaces.md` §8.6) for
    /// (u_p, v_q) → (−∞, −∞), (−∞, +∞), (+∞, −∞), (+∞, +∞): d_{p,q}, d_{p,q−l}, d_{p−k,q}, d_{p−k,q−l},
    /// each with its index pair.
    pub fn limit_points(&self) -> Option<[((usize, usize), P); 4]> {
        let (p, q) = (self.lu.moved?, self.lv.moved?);
        let (k, l) = (self.lu.order, self.lv.order);
        let at = |r: usize, s: usize| ((r, s), self.point(r, s));
        Some([at(p, q), at(p, q - l), at(p - k, q), at(p - k, q - l)])
    }

    /// The envelope (6) (only `u_p` moved), its v-analogue (only `v_q`), or (8) (both).
    pub fn envelope(&self) -> Option<KnotEnvelopeSurface<P>> {
        let eu = self.lu.envelope();
        let ev = self.lv.envelope();
        if eu.is_none() && ev.is_none() {
            return None;
        }
        Some(KnotEnvelopeSurface {
            lu: eu.unwrap_or_else(|| self.lu.clone()),
            lv: ev.unwrap_or_else(|| self.lv.clone()),
            points: self.points.clone(),
        })
    }
}

impl<P: Point> KnotModifiedSurface<P> {
    /// The tensor B-spline this surface is while both moved knots stay strictly between their
    /// neighbours (else `None`).
    pub fn bspline(&self) -> Option<BSplineSurface<P>> {
        let ku = self.lu.modified_knots(self.up)?;
        let kv = self.lv.modified_knots(self.vq)?;
        BSplineSurface::new(
            self.lu.order - 1,
            self.lv.order - 1,
            ku,
            kv,
            self.lu.count,
            self.lv.count,
            self.points.clone(),
        )
        .ok()
    }
}

impl<P: Point> Surface<P> for KnotModifiedSurface<P> {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        (self.lu.domain(), self.lv.domain())
    }
    /// The kernel's grid sampler while the moved knots stay strictly between their neighbours.
    fn sample_grid_into(
        &self,
        us: &[f64],
        vs: &[f64],
        derivs: bool,
        points: &mut [f64],
        du: &mut [f64],
        dv: &mut [f64],
    ) {
        match self.bspline() {
            Some(b) => TensorGrid::sample_into(&b, us, vs, derivs, points, du, dv),
            None => crate::sample::grid_generic_into(self, us, vs, derivs, points, du, dv),
        }
    }
    fn eval_derivs(&self, u: f64, v: f64, derivs: bool, out: &mut [P; 3]) {
        if derivs {
            let t = self.taylor::<2, 2>(u, v, self.up, self.vq, Var::U, Var::V, (false, false));
            out[0] = t[0][0];
            out[1] = t[1][0];
            out[2] = t[0][1];
        } else {
            out[0] = self.eval_at(u, v, self.up, self.vq);
        }
    }
}

/// The envelope surface e(w, v) of eq. (6), its v-analogue e(u, z), or e(w, z) of eq. (8)
/// (see [`KnotModifiedSurface::envelope`]). Implements [`Surface`] on `[u_{p−1}, u_{p+1}] × …`.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotEnvelopeSurface<P: Point> {
    lu: KnotLine,
    lv: KnotLine,
    points: Vec<P>,
}

impl<P: Point> KnotEnvelopeSurface<P> {
    /// Taylor coefficients `out[i][j]` = (1/(i! j!)) ∂^{i+j}e/∂wⁱ∂zʲ.
    pub fn taylor<const N: usize, const M: usize>(&self, w: f64, z: f64) -> [[P; M]; N] {
        let iu = self.lu.span(w, 0.0, false);
        let iv = self.lv.span(z, 0.0, false);
        let mut wu = [Jet::<N>::constant(0.0); W];
        let mut wv = [Jet::<M>::constant(0.0); W];
        self.lu
            .weights(iu, Jet::variable(w), Jet::constant(0.0), &mut wu);
        self.lv
            .weights(iv, Jet::variable(z), Jet::constant(0.0), &mut wv);
        let (k, l) = (self.lu.order, self.lv.order);
        let nv = self.lv.count;
        let mut out = [[P::ZERO; M]; N];
        for a in 0..k {
            let r = iu + 1 + a - k;
            for b in 0..l {
                let d = self.points[r * nv + iv + 1 + b - l];
                for (i, o) in out.iter_mut().enumerate() {
                    for (j, x) in o.iter_mut().enumerate() {
                        *x += d * (wu[a].0[i] * wv[b].0[j]);
                    }
                }
            }
        }
        out
    }
    /// The orders `(k − 1 or k, l − 1 or l)` of the envelope.
    pub fn orders(&self) -> (usize, usize) {
        (self.lu.order, self.lv.order)
    }
}

impl<P: Point> Surface<P> for KnotEnvelopeSurface<P> {
    fn domain(&self) -> ((f64, f64), (f64, f64)) {
        (self.lu.domain(), self.lv.domain())
    }
    fn eval_derivs(&self, w: f64, z: f64, derivs: bool, out: &mut [P; 3]) {
        let t = self.taylor::<2, 2>(w, z);
        out[0] = t[0][0];
        if derivs {
            out[1] = t[1][0];
            out[2] = t[0][1];
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn jets_differentiate() {
        // f(x) = x² / (1 + x) at x = 2: f = 4/3, f' = (2x(1+x) − x²)/(1+x)² = 8/9
        let x = Jet::<3>::variable(2.0);
        let f = x * x / (Jet::constant(1.0) + x);
        assert!((f.value() - 4.0 / 3.0).abs() < 1e-15);
        assert!((f.derivative(1) - 8.0 / 9.0).abs() < 1e-15);
        // f'' = 2/(1+x)³ = 2/27
        assert!((f.derivative(2) - 2.0 / 27.0).abs() < 1e-15);
    }

    #[test]
    fn weights_partition_unity_even_when_extended() {
        let line = KnotLine::new(
            "k",
            "o",
            "p",
            4,
            vec![0., 0., 0., 0., 1., 2., 3., 4., 4., 4., 4.],
            7,
            Some(5),
        )
        .unwrap();
        let mut w = [0.0; W];
        for &up in &[1.5, 2.0, -7.0, 9.0] {
            for &u in &[0.3, 1.2, 1.9, 2.5, 3.7] {
                let i = line.span(u, up, false);
                line.weights(i, u, up, &mut w);
                let s: f64 = w[..4].iter().sum();
                assert!((s - 1.0).abs() < 1e-12, "up {up} u {u} sum {s}");
            }
        }
        assert_eq!(line.span(1.5, 9.0, false), 4);
        assert_eq!(line.span(2.5, -7.0, false), 5);
        assert_eq!(line.affected(), Some(((3, 6), (0.0, 4.0))));
    }

    #[test]
    fn bad_knot_index_and_orders() {
        let k = vec![0., 0., 0., 1., 2., 2., 2.];
        assert_eq!(
            KnotLine::new("knots", "order", "p", 3, k.clone(), 4, Some(2))
                .unwrap_err()
                .field(),
            "p"
        );
        assert_eq!(
            KnotLine::new("knots", "order", "p", 3, k.clone(), 4, Some(4))
                .unwrap_err()
                .field(),
            "p"
        );
        assert!(KnotLine::new("knots", "order", "p", 3, k.clone(), 4, Some(3)).is_ok());
        assert_eq!(
            KnotLine::new("knots", "order", "p", 1, k.clone(), 6, None)
                .unwrap_err()
                .field(),
            "order"
        );
        let mut bad = k.clone();
        bad[3] = 5.0; // the moved one may be anywhere
        assert!(KnotLine::new("knots", "order", "p", 3, bad.clone(), 4, Some(3)).is_ok());
        assert_eq!(
            KnotLine::new("knots", "order", "p", 3, bad, 4, None)
                .unwrap_err()
                .field(),
            "knots[4]"
        );
    }
}
