//! Exercise checks: the numbers a self-checking exercise compares with its tolerance.
//!
//! An exercise in the playground is a demo state, a task and one *check* with a tolerance ε. Every check
//! here turns a construction of one of the five papers into one non-negative number — *how far off* the
//! student is — and a [`Verdict`] compares it with ε (passed when value ≤ ε). The measures:
//!
//! | check | measure | construction |
//! | --- | --- | --- |
//! | [`max_distance`] | max_i dist(D_i, c) — the data points' distance to the curve (foot points by Newton on (c(u) − D)·c′(u) = 0) | any [`Curve`] (B2 curves of Sohail–Zahra–… through their cubic B-spline form, knot-modified curves, Bézier splines) |
//! | [`continuity_jumps`] | max_{j ≤ k} ‖c^{(j)}(u⁻) − c^{(j)}(u⁺)‖ / scale_j — one-sided derivatives at a joint | piecewise polynomials ([`PiecewisePoly`]: B-splines, Bézier splines of the remodelling paper, eq. (9)) |
//! | [`fit_error`] | RMS distance of the fitted B2 curve L^a to the known curve | the noisy-data fits of the B2-spline paper (Figs. 1–3) |
//! | [`ellipse_deviation`] | max distance of the closed quasi-cubic curve to the ellipse its control points define | quasi-cubic α-B-splines, exact ellipses at α = 1 (§4 of the quasi-cubic paper) |
//! | [`network_norm`] | ‖A − B‖∞ of two surfaces through one network, e.g. ‖S − G‖ | criss-cross S, thin-plate T, Gordon G (§4.2 of the criss-cross paper) |
//! | [`envelope_point`] | ‖e(u_p) − Q‖ — how far the point where the knot-modified curve touches its envelope (eq. (6)) is from Q | knot modification (Definition 2, eq. (6)) |
//!
//! The checks reuse the constructions' own code; none re-implements a spline.

mod check;
mod continuity;
mod distance;
mod measures;

pub use check::{
    Check, CheckReport, ExerciseCurve, Measured, Truth, MAX_TRUTH_POINTS, TRUTH_POLYLINE_POINTS,
};
pub use continuity::{bezier_spline, bspline_piecewise, continuity_jumps, Jumps, PiecewiseCurve};
pub use distance::{foot_point, max_distance, DistanceReport};
pub use measures::{ellipse_deviation, envelope_point, fit_error, network_norm};

use crate::error::{Error, Result};
#[allow(unused_imports)] // doc links
use crate::{kernel::PiecewisePoly, sample::Curve};

/// The outcome of a check: the measured value, the tolerance, whether it passed and a score in \[0, 1\].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Verdict {
    /// How far off (≥ 0; the unit is that of the measure).
    pub value: f64,
    /// The tolerance ε the value is compared with.
    pub tol: f64,
    /// value ≤ ε.
    pub passed: bool,
    /// 1 when passed; otherwise 1 − (orders of magnitude above ε)/4, clamped to \[0, 0.9\]: a value ten
    /// times too large scores 0.75, a hundred times 0.5, ten thousand times or more 0.
    pub score: f64,
}

impl Verdict {
    /// Compares `value` with `tol` (a finite tolerance ≥ 0; a NaN value never passes).
    pub fn new(value: f64, tol: f64) -> Result<Self> {
        if !(tol.is_finite() && tol >= 0.0) {
            return Err(Error::out_of_range(
                "tol",
                "expected a finite tolerance ≥ 0",
            ));
        }
        let passed = value <= tol;
        let score = if passed {
            1.0
        } else if value.is_finite() && tol > 0.0 {
            (1.0 - (value / tol).log10() / 4.0).clamp(0.0, 0.9)
        } else {
            0.0
        };
        Ok(Verdict {
            value,
            tol,
            passed,
            score,
        })
    }
}
