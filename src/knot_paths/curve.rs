//! Curves: the family a(u; u_p) of Definition 2 and its envelope.

#![allow(clippy::needless_range_loop)] // index loops pair weights with control points

use super::knot_line::{check_knot_value, check_points};
use super::{Jet, KnotLine, Scalar, W};
use crate::bspline::BSplineCurve;
use crate::error::Result;
use crate::kernel::PiecewisePoly;
use crate::point::Point;
use crate::sample::Curve;

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

    /// The de Boor triangle at `u` with the moved knot at `up` (the recursion the paper's Theorem 1 reads
    /// the paths from): on the span `i` of [`KnotLine::span`], d_j⁰ = d_j (j = i−k+1..i) and, for
    /// r = 1..k−1, j = i−k+1+r..i,
    /// d_j^r = (1 − α_j^r) d_{j−1}^{r−1} + α_j^r d_j^{r−1}, α_j^r = (u − u_j)/(u_{j+k−r} − u_j)
    /// (0/0 := 0, Definition 1), with `u_p := up`. The last entry is a(u; up).
    pub fn de_boor(&self, u: f64, up: f64) -> DeBoorTriangle<P> {
        let k = self.line.order;
        let i = self.line.span(u, up, false);
        let mut level: Vec<P> = (0..k).map(|a| self.points[i + 1 + a - k]).collect();
        let mut steps = Vec::with_capacity(k * (k - 1) / 2);
        for r in 1..k {
            // level[a] holds d_{i−k+1+a}^{r−1}; update from the top so level[a−1] is still of level r−1
            for a in (r..k).rev() {
                let j = i + 1 + a - k;
                let (lo, hi) = (j, j + k - r);
                let left = self.line.knot::<f64>(lo, up);
                let den = self.line.knot::<f64>(hi, up) - left;
                let alpha = if den == 0.0 { 0.0 } else { (u - left) / den };
                level[a] = level[a - 1] * (1.0 - alpha) + level[a] * alpha;
                steps.push(DeBoorStep {
                    level: r,
                    index: j,
                    knots: (lo, hi),
                    alpha,
                    point: level[a],
                });
            }
        }
        // within a level the entries were produced from the top; list them by increasing index
        steps.sort_by_key(|s| (s.level, s.index));
        DeBoorTriangle { span: i, steps }
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

/// One point of the de Boor triangle (see [`KnotModifiedCurve::de_boor`]).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DeBoorStep<P: Point> {
    /// The level r (1..k−1).
    pub level: usize,
    /// The index j of d_j^r.
    pub index: usize,
    /// The knot indices (j, j+k−r) of α_j^r = (u − u_j)/(u_{j+k−r} − u_j).
    pub knots: (usize, usize),
    /// α_j^r.
    pub alpha: f64,
    /// d_j^r.
    pub point: P,
}

/// The de Boor triangle at one parameter: the span and the points level by level.
#[derive(Debug, Clone, PartialEq)]
pub struct DeBoorTriangle<P: Point> {
    /// The span i whose control points d_{i−k+1..i} start the recursion.
    pub span: usize,
    /// The points d_j^r, level by level, increasing j within a level.
    pub steps: Vec<DeBoorStep<P>>,
}
