//! The Bézier spline g of eq. (1) and its C^r conditions (eq. 2).

use super::{falling, forward_difference, segment_derivs, MAX_BEZIER_DEGREE};
use crate::error::{check_finite, Error, Result};
use crate::knots::check_increasing;
use crate::point::Point;
use crate::sample::{Curve, MAX_INPUT_POINTS};

/// Which piece a one-sided derivative at a breakvalue is taken from.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// The piece on the left, [u_{I−1}, u_I] (at t = 1).
    Left,
    /// The piece on the right, [u_I, u_{I+1}] (at t = 0).
    Right,
}

/// A polynomial Bézier spline of degree m (Gânscă–Coman–Ţămbulea, eq. 1):
///
/// g(u) = Σ_{k=0}^{m} B_{m,k}((u − u_I)/(u_{I+1} − u_I)) · b_{mI+k},  u ∈ [u_I, u_{I+1}], I = 0..L−1,
///
/// with control points b_0..b_{mL} (the breakpoints are b_{mI}) and strictly increasing breakvalues
/// u_0..u_L. Derivatives are with respect to the global u. At an interior breakvalue the right-hand piece
/// is used, at u_L (and beyond) the last piece, before u_0 the first piece (extrapolation).
#[derive(Debug, Clone, PartialEq)]
pub struct BezierSpline<P: Point> {
    degree: usize,
    breaks: Vec<f64>,
    points: Vec<P>,
}

impl<P: Point> BezierSpline<P> {
    /// Validates and builds the spline: 1 ≤ m ≤ [`MAX_BEZIER_DEGREE`] + 1 (the elevated degree is allowed),
    /// L ≥ 1 finite strictly increasing breakvalues, exactly mL + 1 finite control points.
    pub fn new(degree: usize, breaks: Vec<f64>, points: Vec<P>) -> Result<Self> {
        if degree == 0 {
            return Err(Error::out_of_range("degree", "need a degree m ≥ 1, got 0"));
        }
        if degree > MAX_BEZIER_DEGREE + 1 {
            return Err(Error::out_of_range(
                "degree",
                format!("at most {MAX_BEZIER_DEGREE}, got {degree}"),
            ));
        }
        if breaks.len() < 2 {
            return Err(Error::too_few(
                "breaks",
                format!(
                    "need at least 2 breakvalues u₀ < u₁ (L ≥ 1 segment), got {}",
                    breaks.len()
                ),
            ));
        }
        check_finite("breaks", &breaks)?;
        check_increasing("breaks", &breaks)?;
        // segments shorter than 1e-12 × the range make derivatives overflow (robustness bug 4)
        crate::knots::check_separated("breaks", &breaks)?;
        let segments = breaks.len() - 1;
        let expected = degree.saturating_mul(segments).saturating_add(1);
        if expected > MAX_INPUT_POINTS {
            return Err(Error::too_many(
                "points",
                format!("at most {MAX_INPUT_POINTS} control points, mL + 1 = {expected}"),
            ));
        }
        if points.len() != expected {
            let detail = format!(
                "a Bézier spline of degree m = {degree} with L = {segments} segments needs mL + 1 = {expected} control points, got {}",
                points.len()
            );
            return Err(if points.len() < expected {
                Error::too_few("points", detail)
            } else {
                Error::size_mismatch("points", detail)
            });
        }
        if let Some(i) = points.iter().position(|p| !p.is_finite()) {
            return Err(Error::not_finite(
                format!("points[{i}]"),
                "expected finite coordinates",
            ));
        }
        Ok(BezierSpline {
            degree,
            breaks,
            points,
        })
    }

    /// The degree m.
    pub fn degree(&self) -> usize {
        self.degree
    }
    /// The breakvalues u_0..u_L.
    pub fn breaks(&self) -> &[f64] {
        &self.breaks
    }
    /// The control points b_0..b_{mL}.
    pub fn points(&self) -> &[P] {
        &self.points
    }
    /// The number of segments L.
    pub fn segments(&self) -> usize {
        self.breaks.len() - 1
    }
    /// The span length Δ_I = u_{I+1} − u_I.
    pub fn span(&self, segment: usize) -> f64 {
        self.breaks[segment + 1] - self.breaks[segment]
    }
    /// The control points b_{mI}..b_{mI+m} of segment I (`segment < L`).
    pub(crate) fn segment_points(&self, segment: usize) -> &[P] {
        let m = self.degree;
        &self.points[m * segment..=m * segment + m]
    }

    /// The segment used at `u`: the I with u_I ≤ u < u_{I+1} (right-hand piece), the last one at u ≥ u_L,
    /// the first one before u_0 (and for NaN).
    pub fn segment_index(&self, u: f64) -> usize {
        let l = self.segments();
        self.breaks[..l]
            .partition_point(|&b| b <= u)
            .saturating_sub(1)
    }

    /// The `order`-th derivative at the breakvalue u_`joint` from one side:
    /// left = (m)_k/Δ_{I−1}^k · Δ^k b_{mI−k}, right = (m)_k/Δ_I^k · Δ^k b_{mI}, where (m)_k is the falling
    /// factorial (0 for k > m). `Left` at I = 0 and `Right` at I = L fall back to the existing side.
    pub fn end_derivative(&self, joint: usize, order: usize, side: Side) -> P {
        let m = self.degree;
        let l = self.segments();
        let joint = joint.min(l);
        let side = match (joint, side) {
            (0, _) => Side::Right,
            (j, _) if j == l => Side::Left,
            (_, s) => s,
        };
        if order > m {
            return P::ZERO;
        }
        match side {
            Side::Right => {
                let h = self.span(joint);
                forward_difference(&self.points[m * joint..], order)
                    * (falling(m, order) / h.powi(order as i32))
            }
            Side::Left => {
                let h = self.span(joint - 1);
                forward_difference(&self.points[m * joint - order..], order)
                    * (falling(m, order) / h.powi(order as i32))
            }
        }
    }

    /// Measured continuity: `jumps[I − 1][i]` = ‖g^{(i)}(u_I⁺) − g^{(i)}(u_I⁻)‖ (largest coordinate, the ∞-norm: the measure
    /// `curves.md` §3 quotes, e.g. the chord-length residual 4.65 and the surface jump 1.5) for the
    /// interior breakvalues I = 1..L−1 and i = 0..=max_order. Empty when L = 1.
    pub fn joint_jumps(&self, max_order: usize) -> Vec<Vec<f64>> {
        (1..self.segments())
            .map(|joint| {
                (0..=max_order)
                    .map(|i| {
                        (self.end_derivative(joint, i, Side::Right)
                            - self.end_derivative(joint, i, Side::Left))
                        .max_abs()
                    })
                    .collect()
            })
            .collect()
    }

    /// The largest one-sided derivative of order `order` at the interior breakvalues (a scale for
    /// relative jumps; at least 1).
    pub fn joint_scale(&self, order: usize) -> f64 {
        (1..self.segments())
            .flat_map(|j| {
                [
                    self.end_derivative(j, order, Side::Left),
                    self.end_derivative(j, order, Side::Right),
                ]
            })
            .map(|d| d.max_abs())
            .fold(1.0, f64::max)
    }

    /// The residual of the C^r conditions in difference form (eq. 2, and eq. 8 for g*):
    /// max over I = 1..L−1 and i = 0..=r of ‖Δ_I^i Δ^i b_{mI−i} − Δ_{I−1}^i Δ^i b_{mI}‖ (orders above m,
    /// which the spline cannot have, are skipped).
    pub fn cr_residual(&self, r: usize) -> f64 {
        let m = self.degree;
        let mut worst: f64 = 0.0;
        for joint in 1..self.segments() {
            let (hl, hr) = (self.span(joint - 1), self.span(joint));
            for i in 0..=r.min(m) {
                let left = forward_difference(&self.points[m * joint - i..], i) * hr.powi(i as i32);
                let right = forward_difference(&self.points[m * joint..], i) * hl.powi(i as i32);
                worst = worst.max((left - right).max_abs());
            }
        }
        worst
    }
}

impl<P: Point> Curve<P> for BezierSpline<P> {
    fn domain(&self) -> (f64, f64) {
        (self.breaks[0], self.breaks[self.segments()])
    }

    /// The kernel's per-segment sampler (up to degree [`crate::kernel::MAX_FAST_DEGREE`]).
    fn piecewise(&self) -> Option<crate::kernel::PiecewisePoly<P>> {
        (self.degree <= crate::kernel::MAX_FAST_DEGREE).then(|| {
            crate::kernel::PiecewisePoly::from_bezier(self.degree, &self.breaks, &self.points)
        })
    }

    fn eval_derivs(&self, u: f64, order: usize, out: &mut [P; 3]) {
        let i = self.segment_index(u);
        let h = self.span(i);
        let t = (u - self.breaks[i]) / h;
        segment_derivs(self.segment_points(i), t, h, order, out);
    }
}
