//! The steps of two B-spline algorithms, with every intermediate point and coefficient, for teaching:
//! the triangle of de Boor's algorithm at a parameter ([`DeBoorTriangle`]) and Boehm's insertion of one
//! knot ([`KnotInsertion`]). Both use the conventions of [`crate::knots`] (span k with t_k ≤ u < t_{k+1},
//! the last non-empty span at the right end of the domain).

use super::BSplineCurve;
use crate::error::{Error, Result};
use crate::knots::find_span;
use crate::point::Point;
use crate::sample::Curve;

/// The triangle of de Boor's algorithm at `u` (de Boor 1972; Piegl–Tiller eq. (5.11)).
///
/// With k the span of u and p the degree, level 0 holds the p + 1 control points P_{k−p}..P_k that act at
/// u; level r = 1..p holds the p + 1 − r points
///
/// P^r_i = (1 − α_{i,r})·P^{r−1}_{i−1} + α_{i,r}·P^{r−1}_i,  α_{i,r} = (u − t_i)/(t_{i+p+1−r} − t_i),
/// i = k − p + r ..= k
///
/// (α = 0 where the denominator is 0), and the single point of level p is C(u).
#[derive(Debug, Clone, PartialEq)]
pub struct DeBoorTriangle<P: Point> {
    /// The span k (t_k ≤ u < t_{k+1}).
    pub span: usize,
    /// The parameter.
    pub u: f64,
    /// `levels[r][j]` = P^r_{k−p+r+j}, r = 0..=p (level 0 = the control points acting at u).
    pub levels: Vec<Vec<P>>,
    /// `alphas[r][j]` = α_{k−p+r+j, r} used for `levels[r][j]` (`alphas[0]` is empty).
    pub alphas: Vec<Vec<f64>>,
}

impl<P: Point> DeBoorTriangle<P> {
    /// The index i of the first point of level r: k − p + r.
    pub fn first_index(&self, r: usize) -> usize {
        self.span + 1 + r - self.levels.len()
    }
    /// The curve point C(u) (the last level).
    pub fn point(&self) -> P {
        self.levels
            .last()
            .and_then(|l| l.first())
            .copied()
            .unwrap_or(P::ZERO)
    }
}

/// One knot inserted by Boehm's algorithm (Boehm 1980; Piegl–Tiller eq. (5.15)): with k the span of u,
/// the control points P_0..P_{k−p} and P_k..P_{n−1} stay (P_k.. shifted by one index), and the p points
/// P_{k−p+1}..P_{k−1} are replaced by p new ones
///
/// Q_i = (1 − α_i)·P_{i−1} + α_i·P_i,  α_i = (u − t_i)/(t_{i+p} − t_i),  i = k − p + 1 ..= k.
///
/// The new curve (one more knot and one more control point) is the same curve.
#[derive(Debug, Clone, PartialEq)]
pub struct KnotInsertion<P: Point> {
    /// The span k of u in the old knot vector.
    pub span: usize,
    /// The inserted knot.
    pub u: f64,
    /// The index of the first new point, k − p + 1.
    pub first: usize,
    /// α_i for i = k − p + 1 ..= k.
    pub alphas: Vec<f64>,
    /// The curve after the insertion.
    pub curve: BSplineCurve<P>,
}

impl<P: Point> BSplineCurve<P> {
    fn check_in_domain(&self, u: f64) -> Result<()> {
        let (a, b) = self.domain();
        if !(u >= a && u <= b) {
            return Err(Error::out_of_range(
                "u",
                "expected a parameter in the domain [knots[degree], knots[count]]",
            ));
        }
        Ok(())
    }

    /// Every intermediate point of de Boor's algorithm at `u` (an `OutOfRange` error on `u` outside the
    /// domain or not finite). The last level equals [`Curve::eval`] at u to rounding.
    pub fn de_boor_triangle(&self, u: f64) -> Result<DeBoorTriangle<P>> {
        self.check_in_domain(u)?;
        let p = self.degree();
        let t = self.knots();
        let k = find_span(t, p, self.points().len(), u);
        let mut levels = vec![self.points()[k - p..=k].to_vec()];
        let mut alphas = vec![Vec::new()];
        for r in 1..=p {
            let prev = &levels[r - 1];
            let mut lvl = Vec::with_capacity(p + 1 - r);
            let mut al = Vec::with_capacity(p + 1 - r);
            for j in 0..=p - r {
                let i = k - p + r + j;
                let denom = t[i + p + 1 - r] - t[i];
                let a = if denom != 0.0 {
                    (u - t[i]) / denom
                } else {
                    0.0
                };
                lvl.push(prev[j] * (1.0 - a) + prev[j + 1] * a);
                al.push(a);
            }
            levels.push(lvl);
            alphas.push(al);
        }
        Ok(DeBoorTriangle {
            span: k,
            u,
            levels,
            alphas,
        })
    }

    /// Boehm's insertion of the knot `u` with its coefficients (see [`KnotInsertion`]); `u` must lie in
    /// the domain. The new control points are those of [`BSplineCurve::insert_knot`].
    pub fn insert_knot_steps(&self, u: f64) -> Result<KnotInsertion<P>> {
        self.check_in_domain(u)?;
        let p = self.degree();
        let k = find_span(self.knots(), p, self.points().len(), u);
        let first = k + 1 - p;
        let alphas = (first..=k)
            .map(|i| crate::knots::insertion_alpha(self.knots(), p, i, u))
            .collect();
        Ok(KnotInsertion {
            span: k,
            u,
            first,
            alphas,
            curve: self.insert_knot(u)?,
        })
    }
}
