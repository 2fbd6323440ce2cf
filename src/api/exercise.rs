//! `exerciseCheck(options)`: the measure of a self-checking exercise, computed by the core
//! ([`crate::exercise`]), compared with a tolerance.
//!
//! `exerciseCheck({ check, tol, … })` → `{ check, value, tol, passed, score, … }` (passed: value ≤ tol;
//! score in [0, 1], see [`crate::exercise::Verdict`]). The checks and their inputs:
//!
//! * `"dataDistance"` — `curve`, `data: [[x, y], …]` → + `{ distances, params, worst }`: the largest
//!   distance of the data points to the curve.
//! * `"continuity"` — `curve` (B-spline or Bézier form), `at` (a joint), `order` k → + `{ at, jumps,
//!   relative }`: value = the largest relative jump of the derivatives 0..k.
//! * `"fitError"` — the options of `b2Fit` (`points` = the data, `a`, `tension`, `knots`, …) with
//!   `truthCurve` (a name of `fitNames().curves`) or `truth` (a dense polyline), `errorSamples` (400) →
//!   + `{ rms, max }`: value = the RMS distance of the fit to the known curve.
//! * `"ellipse"` — `points` (4 control points), `alpha`, `samples` (200 per segment): value = the distance
//!   of the closed quasi-cubic curve to its ellipse.
//! * `"networkNorm"` — `network`, `pair` ("SG", "ST", "TG", "SGB", "GGB"), `normSamples` (57), `tolerance`:
//!   value = ‖A − B‖∞.
//! * `"envelopePoint"` — `curve: { order, knots, controlPoints }`, `p`, `up`, `target: [x, y]` → +
//!   `{ curveDistance }`: value = ‖e(u_p) − target‖ (where the moved curve touches the envelope).
//!
//! `curve` is one of `{ degree, knots, controlPoints }` (B-spline; `order` = degree + 1 accepted),
//! `{ degree, breaks, controlPoints }` (Bézier spline: segment I uses b_{mI..mI+m}) or `{ alpha,
//! controlPoints, closed }` (quasi-cubic), 2D points.

use super::readers::{read_b2_options, read_network, read_tolerance};
use super::{api_options, core_err, err_kind, ApiResult, Opts, Out, Pts};
use crate::b2spline;
use crate::bspline::BSplineCurve;
use crate::error::{Error, ErrorKind};
use crate::exercise::{self, Check, ExerciseCurve, Measured, Truth};
use crate::network::Network;
use crate::quasi_cubic::QuasiCubicCurve;
use glam::DVec2;
use js_sys::Array;
use wasm_bindgen::prelude::*;

const CHECKS: &str = "dataDistance, continuity, fitError, ellipse, networkNorm or envelopePoint";

/// A core error about an input inside `curve` (its field gets the `curve.` prefix).
fn in_curve(e: Error) -> JsError {
    let f = format!("curve.{}", e.field());
    core_err(e.in_field(f))
}

fn pts2(o: &Opts, key: &str, field: &str, min: usize) -> ApiResult<Vec<DVec2>> {
    match o.points(key, min) {
        Ok(Pts::D2(p)) => Ok(p),
        Ok(Pts::D3(_)) => Err(super::errors::err_kind(
            ErrorKind::WrongType,
            field,
            "expected 2D points [x, y]",
        )),
        Err(_) if field != key => Err(err_kind(
            ErrorKind::WrongType,
            field,
            format!("expected at least {min} points [x, y], finite"),
        )),
        Err(e) => Err(e),
    }
}

fn read_curve(o: &Opts) -> ApiResult<ExerciseCurve> {
    let v = o.raw("curve");
    if !v.is_object() || v.is_function() || Array::is_array(&v) {
        return Err(super::errors::err_kind(
            if v.is_undefined() || v.is_null() { ErrorKind::Missing } else { ErrorKind::WrongType },
            "curve",
            "expected an object { degree, knots | breaks, controlPoints } or { alpha, controlPoints, closed }",
        ));
    }
    let c = Opts::new(v)?;
    let points = pts2(&c, "controlPoints", "curve.controlPoints", 1)?;
    let num = |k: &str| {
        c.f64_or(k, f64::NAN).map_err(|_| {
            err_kind(
                ErrorKind::WrongType,
                &format!("curve.{k}"),
                "expected a number",
            )
        })
    };
    if c.has("alpha") {
        let alpha = num("alpha")?;
        let closed = c.bool_or("closed", false).map_err(|_| {
            err_kind(
                ErrorKind::WrongType,
                "curve.closed",
                "expected true or false",
            )
        })?;
        let q = if closed {
            QuasiCubicCurve::closed(alpha, points)
        } else {
            QuasiCubicCurve::new(alpha, points)
        };
        return q.map(ExerciseCurve::Quasi).map_err(in_curve);
    }
    let degree = if c.has("degree") {
        c.usize_or("degree", 0, crate::knots::MAX_DEGREE)
            .map_err(|_| {
                err_kind(
                    ErrorKind::WrongType,
                    "curve.degree",
                    format!("expected a whole number 1..={}", crate::knots::MAX_DEGREE),
                )
            })?
    } else if c.has("order") {
        c.usize_or("order", 1, crate::knots::MAX_DEGREE + 1)
            .map_err(|_| {
                err_kind(
                    ErrorKind::WrongType,
                    "curve.order",
                    "expected a whole number ≥ 2",
                )
            })?
            .saturating_sub(1)
    } else {
        return Err(super::errors::err_kind(
            ErrorKind::Missing,
            "curve.degree",
            "this field is required",
        ));
    };
    let list = |k: &str| -> ApiResult<Option<Vec<f64>>> {
        c.f64s(k).map_err(|_| {
            err_kind(
                ErrorKind::WrongType,
                &format!("curve.{k}"),
                "expected an array of finite numbers",
            )
        })
    };
    if let Some(breaks) = list("breaks")? {
        return exercise::bezier_spline(degree, &breaks, &points)
            .map(ExerciseCurve::Bezier)
            .map_err(in_curve);
    }
    let knots = list("knots")?.ok_or_else(|| {
        super::errors::err_kind(
            ErrorKind::Missing,
            "curve.knots",
            "give knots (a B-spline) or breaks (a Bézier spline)",
        )
    })?;
    BSplineCurve::new(degree, knots, points)
        .map(ExerciseCurve::BSpline)
        .map_err(in_curve)
}

api_options! {
    /// What every check takes: `passed` = value ≤ tol.
    pub struct ExerciseCheckBase |o| {
        /// The check: each check's options below name theirs (`check: "dataDistance"`, …).
        check: String = "check", ext "ExerciseCheckOptions" => |k| o.req(k)?;
        /// The tolerance (a number ≥ 0, required).
        tol: f64 = "tol", req "number" => |k| {
            if !o.has(k) {
                return Err(super::errors::err_kind(
                    ErrorKind::Missing,
                    k,
                    "the tolerance is required (a number ≥ 0)",
                ));
            }
            o.f64_or(k, 0.0)?
        };
        /// The dimension of flat `data` / `points` (2D only; read with them).
        dim: () = "dim", opt "2" => |_k| ();
    }
}

api_options! {
    /// `check: "dataDistance"`: the largest distance of the data points to the curve.
    pub struct DataDistanceCheckOptions extends "ExerciseCheckBase" |o| {
        /// Chooses this check (read first: `ExerciseCheckBase`).
        check: () = "check", req "'dataDistance'" => |_k| ();
        /// 2D data points.
        data: Vec<DVec2> = "data", req "Points" => |k| pts2(o, k, k, 1)?;
        /// The curve.
        curve: ExerciseCurve = "curve", req "ExerciseCurve" => |_k| read_curve(o)?;
    }
}

api_options! {
    /// `check: "continuity"`: the largest relative jump of the derivatives 0..k at a joint.
    pub struct ContinuityCheckOptions extends "ExerciseCheckBase" |o| {
        /// Chooses this check (read first: `ExerciseCheckBase`).
        check: () = "check", req "'continuity'" => |_k| ();
        /// The curve.
        curve: ExerciseCurve = "curve", req "ExerciseBSpline | ExerciseBezier" => |_k| read_curve(o)?;
        /// An interior joint.
        at: f64 = "at", req "number" => |k| o.f64_or(k, f64::NAN)?;
        /// The derivatives 0..k compared (default 1).
        order: usize = "order", opt "number" => |k| o.usize_or(k, 1, crate::knots::MAX_DEGREE)?;
    }
}

api_options! {
    /// `check: "fitError"`: the RMS distance of the b2Fit of `points` to the known curve.
    pub struct FitErrorCheckOptions extends "ExerciseCheckBase, B2Options, B2FitMeasureOptions" |o| {
        /// Chooses this check (read first: `ExerciseCheckBase`).
        check: () = "check", req "'fitError'" => |_k| ();
        /// 2D data D_1..D_N (N ≥ 3), as for b2Fit.
        points: Vec<DVec2> = "points", req "Points" => |k| pts2(o, k, k, 3)?;
        /// The options of b2Fit.
        options: b2spline::B2Options = "construction", ext "B2Options" => |_k| read_b2_options(o)?;
        /// The known curve: `truth` (a polyline), else `truthCurve` (a name, required then).
        truth: Truth = "truth", ext "B2FitMeasureOptions" => |k| match o.has(k) {
            true => Truth::Polyline(pts2(o, k, k, 2)?),
            false => Truth::Named(o.req("truthCurve")?),
        };
        /// The samples of the error (default 400, at most 2000).
        error_samples: usize = "errorSamples", ext "B2FitMeasureOptions" => |k| o.usize_or(k, 400, 2000)?;
    }
}

api_options! {
    /// `check: "ellipse"`: the distance of the closed quasi-cubic curve to its ellipse.
    pub struct EllipseCheckOptions extends "ExerciseCheckBase" |o| {
        /// Chooses this check (read first: `ExerciseCheckBase`).
        check: () = "check", req "'ellipse'" => |_k| ();
        /// The 4 control points of the closed quasi-cubic curve.
        points: Vec<DVec2> = "points", req "Points" => |k| pts2(o, k, k, 1)?;
        /// Default 1.
        alpha: f64 = "alpha", opt "number" => |k| o.f64_or(k, 1.0)?;
        /// Samples per segment (default 200).
        samples: usize = "samples", opt "number" => |k| o.usize_or(k, 200, 10_000)?;
    }
}

api_options! {
    /// `check: "networkNorm"`: ‖A − B‖∞ of two surfaces through the network.
    pub struct NetworkNormCheckOptions extends "ExerciseCheckBase, NetworkTolerance" |o| {
        /// Chooses this check (read first: `ExerciseCheckBase`).
        check: () = "check", req "'networkNorm'" => |_k| ();
        /// The curve network.
        network: Network = "network", req "NetworkInput" => |k| read_network(o, k)?;
        /// The two surfaces.
        pair: String = "pair", req "'SG' | 'ST' | 'TG' | 'SGB' | 'GGB'" => |k| o.req(k)?;
        /// Default 57, at most 200 (the network at most 65 breakpoints per direction).
        norm_samples: usize = "normSamples", opt "number"
            => |k| o.usize_or(k, crate::gordon::DIFFERENCE_GRID, crate::gordon::FAMILY_MAX_NORM_SAMPLES)?;
        /// The tolerance of the compatibility check.
        tolerance: f64 = "tolerance", ext "NetworkTolerance" => |_k| read_tolerance(o)?;
    }
}

api_options! {
    /// `check: "envelopePoint"`: where the moved curve touches the envelope, against a target.
    pub struct EnvelopePointCheckOptions extends "ExerciseCheckBase" |o| {
        /// Chooses this check (read first: `ExerciseCheckBase`).
        check: () = "check", req "'envelopePoint'" => |_k| ();
        /// The curve.
        curve: ExerciseCurve = "curve", req "ExerciseBSpline" => |_k| read_curve(o)?;
        /// The index of the knot that moves (required).
        p: usize = "p", req "number" => |k| {
            if !o.has(k) {
                return Err(super::errors::err_kind(
                    ErrorKind::Missing,
                    k,
                    "the index of the knot that moves is required",
                ));
            }
            o.usize_or(k, 0, usize::MAX)?
        };
        /// Its new value (default the knot's own).
        up: Option<f64> = "up", opt "number" => |k| o.has(k).then(|| o.f64_or(k, 0.0)).transpose()?;
        /// The point the envelope should reach.
        target: DVec2 = "target", req "readonly [number, number] | readonly number[]" => |k| {
            let t: Vec<f64> = o.req(k)?;
            if t.len() != 2 {
                return Err(err_kind(
                    ErrorKind::Invalid,
                    k,
                    format!("expected a point [x, y], got {} numbers", t.len()),
                ));
            }
            DVec2::new(t[0], t[1])
        };
    }
}

#[wasm_bindgen(typescript_custom_section)]
const EXERCISE_CHECK_TS: &str = r#"
// exercise checks

/** A 2D B-spline `{ degree, knots, controlPoints }` (`order` = degree + 1 accepted instead of `degree`). */
export type ExerciseBSpline = ({ degree: number } | { order: number }) & {
  knots: Numbers;
  controlPoints: Points;
  /** Flat `controlPoints` are 2D. */
  dim?: 2;
};
/** A 2D Bézier spline `{ degree, breaks, controlPoints }`: segment I on b_{mI..mI+m}. */
export type ExerciseBezier = ({ degree: number } | { order: number }) & {
  breaks: Numbers;
  controlPoints: Points;
  dim?: 2;
};
/** A 2D quasi-cubic curve `{ alpha, controlPoints, closed }`. */
export interface ExerciseQuasiCubic {
  alpha: number;
  controlPoints: Points;
  closed?: boolean;
  dim?: 2;
}
export type ExerciseCurve = ExerciseBSpline | ExerciseBezier | ExerciseQuasiCubic;

export type ExerciseCheckOptions =
  | DataDistanceCheckOptions | ContinuityCheckOptions | FitErrorCheckOptions | EllipseCheckOptions
  | NetworkNormCheckOptions | EnvelopePointCheckOptions;

/** `{ check, value, tol, passed, score }`. */
export interface ExerciseVerdict<C extends string = string> {
  check: C;
  /** The measure (may be Infinity or NaN). */
  value: number;
  tol: number;
  passed: boolean;
  /** 1 when passed, else 1 − (orders of magnitude above tol)/4, clamped to [0, 0.9]. */
  score: number;
}
export interface DataDistanceVerdict extends ExerciseVerdict<'dataDistance'> {
  distances: Float64Array;
  /** The foot points' parameters. */
  params: Float64Array;
  /** The index of the farthest data point. */
  worst: number;
}
export interface ContinuityVerdict extends ExerciseVerdict<'continuity'> {
  at: number;
  /** ‖c^(j)(u⁻) − c^(j)(u⁺)‖ for j = 0..k. */
  jumps: Float64Array;
  /** The jumps over scale_j. */
  relative: Float64Array;
}
export interface FitErrorVerdict extends ExerciseVerdict<'fitError'> {
  rms: number;
  max: number;
}
export interface NetworkNormVerdict extends ExerciseVerdict<'networkNorm'> {
  pair: string;
}
export interface EnvelopePointVerdict extends ExerciseVerdict<'envelopePoint'> {
  /** The distance of the touching point to the moved curve. */
  curveDistance: number;
}
export type ExerciseCheckResult =
  | DataDistanceVerdict | ContinuityVerdict | FitErrorVerdict | ExerciseVerdict<'ellipse'> | NetworkNormVerdict
  | EnvelopePointVerdict;
/** How far a construction is from what a self-checking exercise asks, against a tolerance. */
export function exerciseCheck(options: DataDistanceCheckOptions): DataDistanceVerdict;
export function exerciseCheck(options: ContinuityCheckOptions): ContinuityVerdict;
export function exerciseCheck(options: FitErrorCheckOptions): FitErrorVerdict;
export function exerciseCheck(options: EllipseCheckOptions): ExerciseVerdict<'ellipse'>;
export function exerciseCheck(options: NetworkNormCheckOptions): NetworkNormVerdict;
export function exerciseCheck(options: EnvelopePointCheckOptions): EnvelopePointVerdict;
export function exerciseCheck(options: ExerciseCheckOptions): ExerciseCheckResult;
"#;

/// `exerciseCheck({ check, tol, … })` (see the module doc).
#[wasm_bindgen(js_name = exerciseCheck, skip_typescript)]
pub fn exercise_check(options: JsValue) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let ExerciseCheckBase { check, tol, .. } = ExerciseCheckBase::read(&o)?;
    let check = match check.as_str() {
        "dataDistance" => {
            let DataDistanceCheckOptions { data, curve, .. } = DataDistanceCheckOptions::read(&o)?;
            Check::DataDistance { data, curve }
        }
        "continuity" => {
            let ContinuityCheckOptions {
                curve, at, order, ..
            } = ContinuityCheckOptions::read(&o)?;
            Check::Continuity { curve, at, order }
        }
        "fitError" => {
            let FitErrorCheckOptions {
                points,
                options,
                truth,
                error_samples,
                ..
            } = FitErrorCheckOptions::read(&o)?;
            Check::FitError {
                data: points,
                options,
                truth,
                error_samples,
            }
        }
        "ellipse" => {
            let EllipseCheckOptions {
                points,
                alpha,
                samples,
                ..
            } = EllipseCheckOptions::read(&o)?;
            Check::Ellipse {
                points,
                alpha,
                per_segment: samples,
            }
        }
        "networkNorm" => {
            let NetworkNormCheckOptions {
                network,
                pair,
                norm_samples,
                tolerance,
                ..
            } = NetworkNormCheckOptions::read(&o)?;
            Check::NetworkNorm {
                network,
                pair,
                samples: norm_samples,
                tolerance,
            }
        }
        "envelopePoint" => {
            let EnvelopePointCheckOptions {
                curve,
                p,
                up,
                target,
                ..
            } = EnvelopePointCheckOptions::read(&o)?;
            Check::EnvelopePoint {
                curve,
                p,
                up,
                target,
            }
        }
        other => {
            return Err(super::errors::err_kind(
                ErrorKind::Invalid,
                "check",
                format!("unknown check {other:?}; expected {CHECKS}"),
            ))
        }
    };
    let name = check.name();
    let r = check.run(tol).map_err(core_err)?;
    let extra = match r.measured {
        Measured::DataDistance(d) => Out::new()
            .f64s("distances", &d.distances)
            .f64s("params", &d.params)
            .num("worst", d.worst as f64),
        Measured::Continuity(j) => Out::new()
            .num("at", j.at)
            .f64s("jumps", &j.absolute)
            .f64s("relative", &j.relative),
        Measured::FitError { rms, max } => Out::new().num("rms", rms).num("max", max),
        Measured::Ellipse => Out::new(),
        Measured::NetworkNorm { pair } => Out::new().ser("pair", pair.as_str()),
        Measured::EnvelopePoint { curve_distance } => {
            Out::new().num("curveDistance", curve_distance)
        }
    };
    let v = r.verdict;
    let mut out = extra
        .ser("check", name)
        .num("value", v.value)
        .num("tol", v.tol)
        .set("passed", v.passed)
        .num("score", v.score);
    if !v.value.is_finite() {
        out = out.set("value", JsValue::from_f64(v.value));
    }
    Ok(out.build())
}
