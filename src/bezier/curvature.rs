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

/// The osculating circle of `curve` at `u` (right-hand piece at breakvalues): its centre
/// p + |c′|²·n / |n|² with n = c″ − (c″·c′/|c′|²)·c′ (the normal part of c″), and its radius 1/κ.
/// Where the curvature vanishes (or c′ = 0) there is no circle: the centre is the point and the radius 0.
pub fn osculating_circle<P: Point, C: crate::sample::Curve<P> + ?Sized>(
    curve: &C,
    u: f64,
) -> (P, f64) {
    let mut out = [P::ZERO; 3];
    curve.eval_derivs(u, 2, &mut out);
    let (p, d1, d2) = (out[0], out[1], out[2]);
    let s = d1.dot(d1);
    if s == 0.0 {
        return (p, 0.0);
    }
    let normal = d2 - d1 * (d2.dot(d1) / s);
    let nn = normal.dot(normal);
    if nn.partial_cmp(&1e-300) != Some(std::cmp::Ordering::Greater) || !(s / nn.sqrt()).is_finite()
    {
        return (p, 0.0);
    }
    let radius = s / nn.sqrt();
    (p + normal * (s / nn), radius)
}
