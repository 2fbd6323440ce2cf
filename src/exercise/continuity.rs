//! Continuity at a joint, measured from one-sided derivatives.
//!
//! A piecewise polynomial is C^k at the break u_I when c^{(j)}(u_I⁻) = c^{(j)}(u_I⁺) for j = 0..k. For a
//! Bézier spline of degree m with control points b_{mI−m..mI+m} around the joint this is the remodelling
//! paper's condition (eq. (9) keeps it through degree elevation); for a B-spline of degree p a knot of
//! multiplicity μ leaves C^{p−μ}. The check measures the jumps instead of trusting either rule.

use crate::bspline::BSplineCurve;
use crate::error::{Error, Result};
use crate::kernel::{PiecewisePoly, MAX_FAST_DEGREE};
use glam::DVec2;

/// The jumps of the derivatives 0..=k at one joint.
#[derive(Debug, Clone, PartialEq)]
pub struct Jumps {
    /// The joint u_I.
    pub at: f64,
    /// ‖c^{(j)}(u⁻) − c^{(j)}(u⁺)‖ for j = 0..=k (derivatives with respect to the global parameter).
    pub absolute: Vec<f64>,
    /// absolute\[j\] / scale_j: scale_j = max(‖c^{(j)}(u⁻)‖, ‖c^{(j)}(u⁺)‖) for j ≥ 1; for j = 0 the
    /// largest distance between two break points of the curve (its size). A vanishing scale gives 0.
    pub relative: Vec<f64>,
    /// max_j relative\[j\]: 0 for an exactly C^k joint.
    pub max_relative: f64,
}

/// The Bézier spline of `degree` m with control points b_0..b_{mL} on the breaks u_0 < … < u_L (segment
/// I uses b_{mI..mI+m}) as a piecewise polynomial.
pub fn bezier_spline(
    degree: usize,
    breaks: &[f64],
    points: &[DVec2],
) -> Result<PiecewisePoly<DVec2>> {
    if degree == 0 || degree > MAX_FAST_DEGREE {
        return Err(Error::out_of_range(
            "degree",
            format!("expected 1..={MAX_FAST_DEGREE}, got {degree}"),
        ));
    }
    if breaks.len() < 2 {
        return Err(Error::too_few_of(
            "breaks",
            2,
            breaks.len(),
            "need at least 2 breaks",
        ));
    }
    crate::error::check_finite("breaks", breaks)?;
    if let Some(i) = breaks.windows(2).position(|w| !(w[1] > w[0])) {
        return Err(Error::not_increasing(
            format!("breaks[{}]", i + 1),
            "the breaks must increase strictly",
        ));
    }
    let need = degree * (breaks.len() - 1) + 1;
    if points.len() != need {
        return Err(Error::size_mismatch(
            "controlPoints",
            format!(
                "a Bézier spline of degree {degree} with {} segments has {need} control points, got {}",
                breaks.len() - 1,
                points.len()
            ),
        ));
    }
    crate::error::check_finite(
        "controlPoints",
        &points.iter().flat_map(|p| [p.x, p.y]).collect::<Vec<f64>>(),
    )?;
    Ok(PiecewisePoly::from_bezier(degree, breaks, points))
}

/// The B-spline of `degree` with the full knot vector `knots` and `points` as a piecewise polynomial (one
/// piece per non-empty span).
pub fn bspline_piecewise(
    degree: usize,
    knots: Vec<f64>,
    points: Vec<DVec2>,
) -> Result<PiecewisePoly<DVec2>> {
    let c = BSplineCurve::new(degree, knots, points)?;
    c.to_piecewise().ok_or_else(|| {
        Error::out_of_range(
            "degree",
            format!("expected a degree ≤ {MAX_FAST_DEGREE} and a non-empty domain"),
        )
    })
}

/// The jumps of derivatives 0..=`order` at the interior break `at` of `c` (see [`Jumps`]). `at` must be an
/// interior break (to 1e-9 of the domain's length); `order` at most the degree.
pub fn continuity_jumps(c: &PiecewisePoly<DVec2>, at: f64, order: usize) -> Result<Jumps> {
    let breaks = c.breaks();
    let l = c.segments();
    if order > c.degree() {
        return Err(Error::out_of_range(
            "order",
            format!("expected 0..={} (the degree), got {order}", c.degree()),
        ));
    }
    let (a, b) = c.domain();
    let near = (1..l).min_by(|&i, &j| (breaks[i] - at).abs().total_cmp(&(breaks[j] - at).abs()));
    let seg = match near {
        Some(i) if at.is_finite() && (breaks[i] - at).abs() <= 1e-9 * (b - a) => i,
        _ => {
            return Err(Error::out_of_range(
                "at",
                "expected an interior joint of the curve (one of its interior breaks)",
            ))
        }
    };
    let size = {
        let ends: Vec<DVec2> = (0..l)
            .filter_map(|s| c.segment_end_derivative(s, false, 0))
            .chain(c.segment_end_derivative(l - 1, true, 0))
            .collect();
        let mut d = 0.0_f64;
        for p in &ends {
            for q in &ends {
                d = d.max(p.distance(*q));
            }
        }
        d
    };
    let mut absolute = Vec::with_capacity(order + 1);
    let mut relative = Vec::with_capacity(order + 1);
    for j in 0..=order {
        let left = c
            .segment_end_derivative(seg - 1, true, j)
            .unwrap_or(DVec2::NAN);
        let right = c
            .segment_end_derivative(seg, false, j)
            .unwrap_or(DVec2::NAN);
        let jump = left.distance(right);
        let scale = if j == 0 {
            size
        } else {
            left.length().max(right.length())
        };
        absolute.push(jump);
        relative.push(if scale > 0.0 {
            jump / scale
        } else if jump == 0.0 {
            0.0
        } else {
            f64::INFINITY
        });
    }
    let max_relative = relative.iter().copied().fold(0.0, f64::max);
    Ok(Jumps {
        at: breaks[seg],
        absolute,
        relative,
        max_relative,
    })
}

/// A [`PiecewisePoly`] seen as a [`crate::sample::Curve`] (for the distance checks on Bézier splines).
#[derive(Debug, Clone, PartialEq)]
pub struct PiecewiseCurve(pub PiecewisePoly<DVec2>);

impl crate::sample::Curve<DVec2> for PiecewiseCurve {
    fn domain(&self) -> (f64, f64) {
        self.0.domain()
    }
    fn eval_derivs(&self, u: f64, order: usize, out: &mut [DVec2; 3]) {
        self.0.eval_derivs(u, order.min(2), out);
    }
}
