//! [`DeCasteljau`]: every intermediate point of de Casteljau's algorithm on one segment of a Bézier spline,
//! for teaching (the algorithm the paper's eq. (1) is evaluated by).

use super::BezierSpline;
use crate::error::{Error, Result};
use crate::point::Point;
use crate::sample::Curve;

/// The triangle of de Casteljau's algorithm on segment I of a Bézier spline of degree m at the global
/// parameter u, with the local t = (u − u_I)/(u_{I+1} − u_I):
///
/// b^0_k = b_{mI+k} (k = 0..m),  b^r_k = (1 − t)·b^{r−1}_k + t·b^{r−1}_{k+1} (k = 0..m − r),
///
/// and b^m_0 = g(u).
#[derive(Debug, Clone, PartialEq)]
pub struct DeCasteljau<P: Point> {
    /// The segment I (the right-hand piece at an interior breakvalue, the last one at u_L).
    pub segment: usize,
    /// The global parameter u.
    pub u: f64,
    /// The local parameter t ∈ \[0, 1\].
    pub t: f64,
    /// `levels[r][k]` = b^r_k, r = 0..=m.
    pub levels: Vec<Vec<P>>,
}

impl<P: Point> DeCasteljau<P> {
    /// The point g(u) (the last level).
    pub fn point(&self) -> P {
        self.levels
            .last()
            .and_then(|l| l.first())
            .copied()
            .unwrap_or(P::ZERO)
    }
}

impl<P: Point> BezierSpline<P> {
    /// De Casteljau's algorithm at `u` with every level (an `OutOfRange` error on `u` outside
    /// \[u_0, u_L\] or not finite). The last level equals [`Curve::eval`] at u to rounding.
    pub fn de_casteljau(&self, u: f64) -> Result<DeCasteljau<P>> {
        let (a, b) = self.domain();
        if !(u >= a && u <= b) {
            return Err(Error::out_of_range(
                "u",
                "expected a parameter in the domain",
            ));
        }
        let segment = self.segment_index(u);
        let t = (u - self.breaks()[segment]) / self.span(segment);
        let mut levels = vec![self.segment_points(segment).to_vec()];
        for r in 1..=self.degree() {
            let prev = &levels[r - 1];
            let lvl = (0..prev.len() - 1)
                .map(|k| prev[k] * (1.0 - t) + prev[k + 1] * t)
                .collect();
            levels.push(lvl);
        }
        Ok(DeCasteljau {
            segment,
            u,
            t,
            levels,
        })
    }
}
