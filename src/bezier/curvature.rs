//! Curvature at the breakvalues from the control points (eqs. 13–14) and the ratio K*/K of eq. (15).

use super::spline::BezierSpline;
use crate::point::Point;

/// ‖a ∧ b‖ in any dimension: √(|a|²|b|² − (a·b)²).
pub fn wedge_norm<P: Point>(a: P, b: P) -> f64 {
    (a.dot(a) * b.dot(b) - a.dot(b).powi(2)).max(0.0).sqrt()
}

impl<P: Point> BezierSpline<P> {
    /// The curvature at the breakvalue u_I from the control points, eq. (13) for g (and eq. (14),
    /// corrected, for the elevated g*): with d the degree,
    /// * I < L (right-hand piece): (d − 1)/d · ‖Δb_{dI+1} ∧ Δb_{dI}‖ / ‖Δb_{dI}‖³;
    /// * I = L (end of the last piece): (d − 1)/d · ‖Δb_{dL−2} ∧ Δb_{dL−1}‖ / ‖Δb_{dL−1}‖³.
    ///
    /// (The printed eq. (14) has Δb*_{Im−1} ∧ Δb*_{Im} at I = L; the correct indices are the ones above
    /// with d = m + 1, `curves.md` §3.2.) Degree 1 and a zero first difference give 0.
    pub fn break_curvature(&self, joint: usize) -> f64 {
        let d = self.degree();
        if d < 2 {
            return 0.0;
        }
        let l = self.segments();
        let b = self.points();
        let (first, second) = if joint < l {
            (
                b[d * joint + 1] - b[d * joint],
                b[d * joint + 2] - b[d * joint + 1],
            )
        } else {
            (b[d * l] - b[d * l - 1], b[d * l - 1] - b[d * l - 2])
        };
        let s = first.length();
        if s == 0.0 {
            return 0.0;
        }
        (d as f64 - 1.0) / d as f64 * wedge_norm(first, second) / (s * s * s)
    }
}
