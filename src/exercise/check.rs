//! One self-check of an exercise, run from its inputs: [`Check`] names the measure and holds what it needs,
//! [`Check::run`] measures and compares with the tolerance ([`Verdict`]), and [`Measured`] carries what the
//! measure found besides its value (the distances of the data, the jumps at the joint, …).

use super::continuity::{continuity_jumps, Jumps, PiecewiseCurve};
use super::distance::{max_distance, DistanceReport};
use super::measures::{ellipse_deviation, envelope_point, fit_error, network_norm};
use super::Verdict;
use crate::b2spline::B2Options;
use crate::bspline::BSplineCurve;
use crate::error::{Error, ErrorKind, Result};
use crate::fit::KnownCurve;
use crate::kernel::PiecewisePoly;
use crate::network::Network;
use crate::quasi_cubic::QuasiCubicCurve;
use glam::DVec2;

/// Points of a named known curve drawn as the truth of [`Check::FitError`].
pub const TRUTH_POLYLINE_POINTS: usize = 2001;
/// The most points a truth polyline may have.
pub const MAX_TRUTH_POINTS: usize = 100_000;

/// The curve a student built, in one of the forms the checks read.
pub enum ExerciseCurve {
    /// A B-spline `{ degree, knots, controlPoints }`.
    BSpline(BSplineCurve<DVec2>),
    /// A Bézier spline `{ degree, breaks, controlPoints }` (segment I on b_{mI..mI+m}).
    Bezier(PiecewisePoly<DVec2>),
    /// A quasi-cubic curve `{ alpha, controlPoints, closed }`.
    Quasi(QuasiCubicCurve<DVec2>),
}

/// The known curve of [`Check::FitError`].
pub enum Truth {
    /// A dense polyline of the curve.
    Polyline(Vec<DVec2>),
    /// A name of [`KnownCurve::from_name`], drawn with [`TRUTH_POLYLINE_POINTS`] points.
    Named(String),
}

/// A check and its inputs (the table of the module [`crate::exercise`]).
pub enum Check {
    /// The largest distance of `data` to `curve`.
    DataDistance {
        /// The curve.
        curve: ExerciseCurve,
        /// The data points D_i.
        data: Vec<DVec2>,
    },
    /// The largest relative jump of the derivatives 0..=`order` of `curve` at the joint `at`.
    Continuity {
        /// A B-spline or Bézier spline (not quasi-cubic).
        curve: ExerciseCurve,
        /// An interior joint.
        at: f64,
        /// k: the derivatives 0..=k compared.
        order: usize,
    },
    /// The RMS distance of the B2 fit L^a of `data` (`options`) to the known curve, at `error_samples`.
    FitError {
        /// The noisy data D_1..D_N.
        data: Vec<DVec2>,
        /// The B2 options of the fit (a, tension, knots).
        options: B2Options,
        /// The known curve.
        truth: Truth,
        /// The parameters the fit is sampled at.
        error_samples: usize,
    },
    /// The distance of the closed quasi-cubic curve of four `points` at `alpha` to its ellipse.
    Ellipse {
        /// The four control points.
        points: Vec<DVec2>,
        /// α.
        alpha: f64,
        /// Samples per segment.
        per_segment: usize,
    },
    /// ‖A − B‖∞ of two surfaces through `network` (`pair` such as `"SG"`) on a `samples²` grid.
    NetworkNorm {
        /// The network.
        network: Network,
        /// Two surface names run together.
        pair: String,
        /// The side of the grid.
        samples: usize,
        /// The network's compatibility tolerance.
        tolerance: f64,
    },
    /// ‖e(u_p) − target‖: where the curve with its knot `p` moved to `up` touches its envelope.
    EnvelopePoint {
        /// A B-spline (its order is degree + 1).
        curve: ExerciseCurve,
        /// The index of the knot that moves.
        p: usize,
        /// Its new value (`None`: the knot's own).
        up: Option<f64>,
        /// The point Q.
        target: DVec2,
    },
}

/// What a check found besides its value.
pub enum Measured {
    /// The distance of every data point, its foot point's parameter, the farthest point.
    DataDistance(DistanceReport),
    /// The jumps at the joint.
    Continuity(Jumps),
    /// The RMS and largest distance of the fit.
    FitError {
        /// RMS distance (the value).
        rms: f64,
        /// Largest distance.
        max: f64,
    },
    /// Nothing besides the value.
    Ellipse,
    /// The pair measured.
    NetworkNorm {
        /// As asked for.
        pair: String,
    },
    /// How far the target is from the moved curve.
    EnvelopePoint {
        /// dist(Q, a(·; u_p)).
        curve_distance: f64,
    },
}

/// The outcome of [`Check::run`].
pub struct CheckReport {
    /// The value against the tolerance.
    pub verdict: Verdict,
    /// What else the measure found.
    pub measured: Measured,
}

impl Check {
    /// The check's name as exercises and `exerciseCheck` write it.
    pub fn name(&self) -> &'static str {
        match self {
            Check::DataDistance { .. } => "dataDistance",
            Check::Continuity { .. } => "continuity",
            Check::FitError { .. } => "fitError",
            Check::Ellipse { .. } => "ellipse",
            Check::NetworkNorm { .. } => "networkNorm",
            Check::EnvelopePoint { .. } => "envelopePoint",
        }
    }

    /// Measures and compares the value with `tol` (a finite tolerance ≥ 0, else an error naming `tol`).
    /// Errors name the check's inputs: `curve` (a form this check does not measure), `curve.degree` (too
    /// high for a joint measure), `truth`, `truthCurve`, `p`, `target`, `pair`, and those of the measures.
    pub fn run(self, tol: f64) -> Result<CheckReport> {
        let (value, measured) = match self {
            Check::DataDistance { curve, data } => {
                let r = match curve {
                    ExerciseCurve::BSpline(c) => max_distance(&c, &data),
                    ExerciseCurve::Bezier(p) => max_distance(&PiecewiseCurve(p), &data),
                    ExerciseCurve::Quasi(q) => max_distance(&q, &data),
                }?;
                (r.max, Measured::DataDistance(r))
            }
            Check::Continuity { curve, at, order } => {
                let pp = match curve {
                    ExerciseCurve::BSpline(c) => c.to_piecewise().ok_or_else(|| {
                        Error::new(
                            ErrorKind::OutOfRange,
                            "curve.degree",
                            "too high for a joint measure",
                        )
                    })?,
                    ExerciseCurve::Bezier(p) => p,
                    ExerciseCurve::Quasi(_) => return Err(Error::invalid(
                        "curve",
                        "continuity is measured on B-splines and Bézier splines (knots or breaks)",
                    )),
                };
                let j = continuity_jumps(&pp, at, order)?;
                (j.max_relative, Measured::Continuity(j))
            }
            Check::FitError {
                data,
                options,
                truth,
                error_samples,
            } => {
                let truth = match truth {
                    Truth::Polyline(p) => p,
                    Truth::Named(name) => KnownCurve::from_name(&name)
                        .map_err(|e| e.in_field("truthCurve"))?
                        .polyline(TRUTH_POLYLINE_POINTS),
                };
                if truth.len() > MAX_TRUTH_POINTS {
                    return Err(Error::too_many(
                        "truth",
                        format!("at most {MAX_TRUTH_POINTS} points"),
                    ));
                }
                let (rms, max) = fit_error(&data, &options, &truth, error_samples)?;
                (rms, Measured::FitError { rms, max })
            }
            Check::Ellipse {
                points,
                alpha,
                per_segment,
            } => (
                ellipse_deviation(&points, alpha, per_segment)?,
                Measured::Ellipse,
            ),
            Check::NetworkNorm {
                network,
                pair,
                samples,
                tolerance,
            } => {
                let v = network_norm(&network, &pair, samples, tolerance)?;
                (v, Measured::NetworkNorm { pair })
            }
            Check::EnvelopePoint {
                curve,
                p,
                up,
                target,
            } => {
                let ExerciseCurve::BSpline(c) = curve else {
                    return Err(Error::invalid(
                        "curve",
                        "expected a B-spline { order, knots, controlPoints }",
                    ));
                };
                let knots = c.knots().to_vec();
                if p > knots.len() {
                    return Err(Error::too_many_of(
                        "p",
                        knots.len(),
                        p,
                        format!("at most {}, got {p}", knots.len()),
                    ));
                }
                let up = up.unwrap_or_else(|| knots.get(p).copied().unwrap_or(0.0));
                let (touch, on_curve) =
                    envelope_point(c.degree() + 1, knots, c.points().to_vec(), p, up, target)?;
                (
                    touch,
                    Measured::EnvelopePoint {
                        curve_distance: on_curve,
                    },
                )
            }
        };
        Ok(CheckReport {
            verdict: Verdict::new(value, tol)?,
            measured,
        })
    }
}
