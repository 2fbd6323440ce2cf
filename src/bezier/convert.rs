//! From a B-spline to Bézier form: knot insertion up to multiplicity p at every breakvalue.

use super::spline::BezierSpline;
use super::MAX_BEZIER_DEGREE;
use crate::bspline::BSplineCurve;
use crate::error::{Error, Result};
use crate::knots::find_span;
use crate::point::Point;

impl<P: Point> BezierSpline<P> {
    /// The same curve as a Bézier spline on its domain [t_p, t_n]: every distinct knot value in the domain
    /// (the ends included) is inserted until it has multiplicity p (Boehm); then the control points
    /// Q_{s−p}..Q_s of each span s are that segment's Bézier points (the blossom values
    /// f(u_I^{p−j}, u_{I+1}^j)). The breakvalues are the distinct knots in the domain. Interior knots of
    /// multiplicity p + 1 (a break in the curve) cannot be represented and are an error.
    pub fn from_bspline(curve: &BSplineCurve<P>) -> Result<Self> {
        let p = curve.degree();
        if p == 0 {
            return Err(Error::out_of_range(
                "degree",
                "a Bézier spline needs degree ≥ 1, got 0",
            ));
        }
        if p > MAX_BEZIER_DEGREE {
            return Err(Error::out_of_range(
                "degree",
                format!("at most {MAX_BEZIER_DEGREE}, got {p}"),
            ));
        }
        let knots = curve.knots();
        let n = curve.points().len();
        let (a, b) = (knots[p], knots[n]);
        let mut breaks: Vec<f64> = Vec::new();
        for &t in &knots[p..=n] {
            if breaks.last() != Some(&t) {
                breaks.push(t);
            }
        }
        // knots to insert so that every breakvalue has multiplicity ≥ p
        let mut extra = Vec::new();
        for &u in &breaks {
            let mult = knots.iter().filter(|&&t| t == u).count();
            if mult > p && u > a && u < b {
                return Err(Error::degenerate(
                    "knots",
                    format!("an interior knot has multiplicity {mult} > degree {p}: the curve is broken there"),
                ));
            }
            extra.extend(std::iter::repeat_n(u, p.saturating_sub(mult)));
        }
        let refined = curve.refine(&extra)?;
        let (k2, q) = (refined.knots(), refined.points());
        let n2 = q.len();
        let mut pts = Vec::with_capacity(p * (breaks.len() - 1) + 1);
        for seg in 0..breaks.len() - 1 {
            let mid = 0.5 * (breaks[seg] + breaks[seg + 1]);
            let s = find_span(k2, p, n2, mid);
            let from = if seg == 0 { s - p } else { s - p + 1 };
            pts.extend_from_slice(&q[from..=s]);
        }
        BezierSpline::new(p, breaks, pts)
    }
}
