//! [`KnotLine`]: one parameter direction of a B-spline with one knot whose value can be moved.

#![allow(clippy::needless_range_loop)] // index loops pair weights with control points

use super::{Scalar, MAX_ORDER, W};
use crate::error::{check_finite, Error, Result};
use crate::point::Point;

// ---------------------------------------------------------------------------------------------------
// One parameter direction
// ---------------------------------------------------------------------------------------------------

/// One parameter direction of a B-spline: order `k`, full knots `u_0..u_{n+k}` for `n + 1` control points,
/// and optionally the index `p` of a knot whose value is replaced at evaluation time.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotLine {
    pub(super) order: usize,
    pub(super) knots: Vec<f64>,
    pub(super) count: usize,
    pub(super) moved: Option<usize>,
    /// Evaluate every parameter on this span (the envelope's single polynomial piece).
    pub(super) fixed_span: Option<usize>,
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
                    format!(
                        "knots must not decrease, but knot {} is less than knot {}",
                        w[1], w[0]
                    ),
                ));
            }
            if b == a {
                run += 1;
                if run > order {
                    return Err(Error::degenerate(
                        format!("{field}[{}]", w[1]),
                        format!("a knot is repeated more than order = {order} times"),
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
                format!("empty domain: knot {} must be < knot {count}", order - 1),
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

    /// The knot vector with the moved knot u_p replaced by `up` whatever its value (the knots themselves
    /// when no knot is moved) — what a caller shows as "the current knots", valid B-spline or not.
    pub fn substituted_knots(&self, up: f64) -> Vec<f64> {
        let mut t = self.knots.clone();
        if let Some(p) = self.moved {
            t[p] = up;
        }
        t
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
    pub(super) fn knot<T: Scalar>(&self, j: usize, up: T) -> T {
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
pub(super) fn span_search(lo: usize, hi: usize, t: impl Fn(usize) -> f64, u: f64) -> usize {
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

pub(super) fn check_points<P: Point>(field: &'static str, points: &[P], cols: usize) -> Result<()> {
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

pub(super) fn check_knot_value(field: &'static str, x: f64) -> Result<()> {
    if x.is_nan() {
        Err(Error::not_finite(field, "expected a number, got NaN"))
    } else {
        Ok(())
    }
}

// ---------------------------------------------------------------------------------------------------
