//! [`BSplineCurve`]: de Boor evaluation of a B-spline curve.

use super::{basis_derivs, W};
use crate::error::{Error, Result};
use crate::kernel::PiecewisePoly;
use crate::knots::{self, find_span};
use crate::point::Point;
use crate::sample::Curve;

/// A B-spline curve of degree `p` with a full knot vector (`points + p + 1` knots).
///
/// # Template
/// * **What**: the polynomial B-spline curve Σ N_{i,p}(u) P_i, with the Cox–de Boor basis (de Boor 1972;
///   Piegl–Tiller eq. (2.5)); the kernel every polynomial construction of the five papers reduces to.
/// * **Interpolates**: its end control points when the knot vector is clamped (end knots of multiplicity
///   p + 1); otherwise nothing.
/// * **Continuity**: C^{p−μ} at a knot of multiplicity μ, polynomial between knots.
/// * **Parametrisation**: u ∈ [t_p, t_{n+1}] (n + 1 points); the right-hand piece at an interior knot.
///
/// # Example
/// ```
/// use glam::DVec2;
/// use splinelab::{bspline::BSplineCurve, Curve};
/// let pts = vec![DVec2::new(0.0, 0.0), DVec2::new(1.0, 2.0), DVec2::new(3.0, 2.0), DVec2::new(4.0, 0.0)];
/// let c = BSplineCurve::new(3, vec![0.0, 0.0, 0.0, 0.0, 1.0, 1.0, 1.0, 1.0], pts.clone())?;
/// assert_eq!(c.domain(), (0.0, 1.0));
/// assert!((c.eval(0.0) - pts[0]).length() < 1e-15 && (c.eval(1.0) - pts[3]).length() < 1e-15);
/// // one Bézier piece: the end tangent is 3 (P1 − P0)
/// let mut d = [DVec2::ZERO; 3];
/// c.eval_derivs(0.0, 1, &mut d);
/// assert!((d[1] - 3.0 * (pts[1] - pts[0])).length() < 1e-12);
/// # Ok::<(), splinelab::Error>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BSplineCurve<P: Point> {
    degree: usize,
    knots: Vec<f64>,
    points: Vec<P>,
}

impl<P: Point> BSplineCurve<P> {
    /// Validates and builds the curve (see [`knots::validate`]; control points must be finite).
    pub fn new(degree: usize, knots: Vec<f64>, points: Vec<P>) -> Result<Self> {
        if let Some(i) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::not_finite(
                format!("points[{i}]"),
                "expected finite coordinates",
            ));
        }
        knots::validate("knots", &knots, degree, points.len())?;
        Ok(BSplineCurve {
            degree,
            knots,
            points,
        })
    }

    /// A clamped curve with uniform interior knots on `[0, 1]`.
    pub fn clamped_uniform(degree: usize, points: Vec<P>) -> Result<Self> {
        if points.len() < degree + 1 {
            return Err(Error::too_few(
                "points",
                format!(
                    "need at least {} control points for degree {degree}, got {}",
                    degree + 1,
                    points.len()
                ),
            ));
        }
        let k = knots::clamped_uniform(points.len(), degree, 0.0, 1.0);
        Self::new(degree, k, points)
    }

    /// The polynomial degree.
    pub fn degree(&self) -> usize {
        self.degree
    }
    /// The knot vector.
    pub fn knots(&self) -> &[f64] {
        &self.knots
    }
    /// The control points.
    pub fn points(&self) -> &[P] {
        &self.points
    }

    /// The point at `u` by de Boor's algorithm (independent of the basis-function path; used to test it).
    pub fn de_boor(&self, u: f64) -> P {
        let p = self.degree;
        let k = find_span(&self.knots, p, self.points.len(), u);
        let mut d = [P::ZERO; W];
        d[..=p].copy_from_slice(&self.points[k - p..=k]);
        for r in 1..=p {
            for j in (r..=p).rev() {
                let i = j + k - p;
                let denom = self.knots[i + p + 1 - r] - self.knots[i];
                let a = if denom != 0.0 {
                    (u - self.knots[i]) / denom
                } else {
                    0.0
                };
                d[j] = d[j - 1] * (1.0 - a) + d[j] * a;
            }
        }
        d[p]
    }

    /// The blossom (polar form) of the piece on span `span` at the arguments `args` (`degree` of them):
    /// de Boor's algorithm with a different argument at each level. `blossom(u, …, u)` is the point at u.
    pub fn blossom(&self, span: usize, args: &[f64]) -> P {
        let p = self.degree;
        let mut d = [P::ZERO; W];
        d[..=p].copy_from_slice(&self.points[span - p..=span]);
        for r in 1..=p {
            let u = args[r - 1];
            for j in (r..=p).rev() {
                let i = j + span - p;
                let denom = self.knots[i + p + 1 - r] - self.knots[i];
                let a = if denom != 0.0 {
                    (u - self.knots[i]) / denom
                } else {
                    0.0
                };
                d[j] = d[j - 1] * (1.0 - a) + d[j] * a;
            }
        }
        d[p]
    }

    /// Evaluates the curve at `count` uniform parameters over its domain (ends included) into `out`
    /// (`count * DIM` coordinates; shorter buffers are filled as far as they go), fast: through the
    /// kernel's [`PiecewisePoly`] (each span converted once to the power basis in its local parameter, then
    /// forward differences for cubics, Horner otherwise, over the run of samples that fall in it). The
    /// parameters are exactly those of [`crate::sample::uniform_params`]; agrees with [`Curve::eval`] to
    /// rounding (≈1e-13 relative).
    pub fn sample_uniform_into(&self, count: usize, out: &mut [f64]) {
        match self.to_piecewise() {
            Some(pp) => pp.sample_uniform_into(count, out),
            None => {
                let (a, b) = self.domain();
                let params = crate::sample::uniform_params(a, b, count.min(out.len() / P::DIM));
                crate::sample::eval_curve_generic_into(self, &params, 0, out, &mut [], &mut []);
            }
        }
    }

    /// The curve as a piecewise polynomial in the power basis (one piece per non-empty span), or `None`
    /// above [`crate::kernel::MAX_FAST_DEGREE`].
    pub fn to_piecewise(&self) -> Option<PiecewisePoly<P>> {
        let p = self.degree;
        if p > crate::kernel::MAX_FAST_DEGREE {
            return None;
        }
        let n = self.points.len();
        let mut pp = PiecewisePoly::with_degree(p, self.knots[p]);
        let mut coef = [P::ZERO; W];
        for span in p..n {
            let (t0, t1) = (self.knots[span], self.knots[span + 1]);
            if t1 <= t0 {
                continue;
            }
            self.power_coefficients(span, &mut coef);
            pp.push_segment(t1, &coef);
        }
        if pp.segments() == 0 {
            return None;
        }
        Some(pp)
    }

    /// The power-basis coefficients c_0..c_p of the piece on `span` in its local parameter
    /// t = (u − t_span)/(t_{span+1} − t_span): c_k = f^{(k)}(t_span) h^k / k!, the k-th derivative taken
    /// from the derivative control points R^{(k)}_j = (q + 1)(R^{(k−1)}_j − R^{(k−1)}_{j−1})/(t_{j+q+1} − t_j)
    /// (q = p − k) by de Boor's algorithm at t_span. Differences of control points keep the rounding error
    /// relative to the curve's local size (not to its distance from the origin), also on short spans.
    fn power_coefficients(&self, span: usize, coef: &mut [P; W]) {
        let p = self.degree;
        let t = &self.knots;
        let u = t[span];
        let h = t[span + 1] - u;
        // r[j - (span - p)] = R^{(k)}_j for j = span − q ..= span (stored right-aligned)
        let mut r = [P::ZERO; W];
        r[..=p].copy_from_slice(&self.points[span - p..=span]);
        let mut fact_h = 1.0; // h^k / k!
        for k in 0..=p {
            let q = p - k;
            if k > 0 {
                for idx in (k..=p).rev() {
                    let j = span - p + idx;
                    r[idx] = (r[idx] - r[idx - 1]) * ((q + 1) as f64 / (t[j + q + 1] - t[j]));
                }
                fact_h *= h / k as f64;
            }
            // de Boor for degree q on the span, at u = t_span, points r[k..=p]
            let mut d = [P::ZERO; W];
            d[..=q].copy_from_slice(&r[k..=p]);
            for lvl in 1..=q {
                for jj in (lvl..=q).rev() {
                    let i = jj + span - q;
                    let denom = t[i + q + 1 - lvl] - t[i];
                    let a = if denom != 0.0 {
                        (u - t[i]) / denom
                    } else {
                        0.0
                    };
                    d[jj] = d[jj - 1] * (1.0 - a) + d[jj] * a;
                }
            }
            coef[k] = d[q] * fact_h;
        }
    }

    /// Inserts the knot `u` once; the curve is unchanged.
    pub fn insert_knot(&self, u: f64) -> Result<Self> {
        let (k, c) = knots::insert_knot(self.degree, &self.knots, &self.points, u)?;
        Ok(BSplineCurve {
            degree: self.degree,
            knots: k,
            points: c,
        })
    }

    /// Inserts all of `extra`; the curve is unchanged.
    pub fn refine(&self, extra: &[f64]) -> Result<Self> {
        let (k, c) = knots::refine(self.degree, &self.knots, &self.points, extra)?;
        Ok(BSplineCurve {
            degree: self.degree,
            knots: k,
            points: c,
        })
    }
}

impl<P: Point> Curve<P> for BSplineCurve<P> {
    fn domain(&self) -> (f64, f64) {
        (self.knots[self.degree], self.knots[self.points.len()])
    }

    fn piecewise(&self) -> Option<PiecewisePoly<P>> {
        self.to_piecewise()
    }

    fn eval_derivs(&self, u: f64, order: usize, out: &mut [P; 3]) {
        let p = self.degree;
        let span = find_span(&self.knots, p, self.points.len(), u);
        let mut ders = [[0.0; W]; 3];
        basis_derivs(&self.knots, p, span, u, order, &mut ders);
        for (k, o) in out.iter_mut().enumerate().take(order.min(2) + 1) {
            let mut acc = P::ZERO;
            for r in 0..=p {
                acc += self.points[span - p + r] * ders[k][r];
            }
            *o = acc;
        }
    }
}
