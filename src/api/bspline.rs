//! `bsplineCurve` and `bsplineBasis`: the ordinary B-spline with a full knot vector; `bsplineDeBoor` and
//! `bsplineInsertKnot`: the steps of de Boor's algorithm and of Boehm's knot insertion (for steppers).

use super::{
    api_options, core_err, curve_result_for, err_kind, flat, rows_out, with_points, ApiResult,
    Opts, Out, Pts,
};
use crate::bspline::{basis_all, BSplineCurve};
use crate::error::ErrorKind;
use crate::knots::{self, MAX_DEGREE};
use crate::sample::Curve;
use wasm_bindgen::prelude::*;

api_options! {
    /// The B-spline of `bsplineCurve`, `bsplineDeBoor` and `bsplineInsertKnot`.
    pub struct BsplineOptions extends "FlatDim" |o| {
        /// Degree p (default 3, at most 24).
        degree: usize = "degree", opt "number" => |k| o.usize_or(k, 3, MAX_DEGREE)?;
        /// Control points (at least degree + 1).
        points: Pts = "points", req "Points" => |k| o.points(k, degree + 1)?;
        /// Full knot vector (points + degree + 1 knots); default clamped uniform on [0, 1].
        knots: Vec<f64> = "knots", opt "Numbers" => |k| curve_knots(o, k, degree, points.len())?;
    }
}

/// `knots` checked against the degree and the number of points, or clamped uniform on \[0, 1\] when absent.
fn curve_knots(o: &Opts, key: &'static str, degree: usize, n: usize) -> ApiResult<Vec<f64>> {
    Ok(match o.f64s(key)? {
        Some(k) => {
            knots::validate(key, &k, degree, n).map_err(core_err)?;
            knots::check_separated(key, &k).map_err(core_err)?;
            k
        }
        None => knots::clamped_uniform(n, degree, 0.0, 1.0),
    })
}

api_options! {
    /// One parameter of a B-spline (`bsplineDeBoor`, `bsplineInsertKnot`).
    pub struct BsplineAtOptions extends "BsplineOptions" |o| {
        /// The parameter, in the domain `[knots[degree], knots[len − degree − 1]]` (`out-of-range` otherwise).
        u: f64 = "u", req "number" => |k| o.req_f64(k)?;
    }
}

api_options! {
    /// The basis functions of `bsplineBasis` (where: `at` or `samples`; `derivatives` up to 2).
    pub struct BsplineBasisOptions extends "CurveSampling" |o| {
        /// Degree p (default 3, at most 24).
        degree: usize = "degree", opt "number" => |k| o.usize_or(k, 3, MAX_DEGREE)?;
        /// Full knot vector (required; at least degree + 2 knots).
        knots: Vec<f64> = "knots", req "Numbers" => |k| basis_knots(o, k, degree)?;
    }
}

/// The required full knot vector of `bsplineBasis`: at least degree + 2 knots, valid and separated.
fn basis_knots(o: &Opts, key: &'static str, degree: usize) -> ApiResult<Vec<f64>> {
    let knots = o
        .f64s(key)?
        .ok_or_else(|| err_kind(ErrorKind::Missing, key, "this field is required"))?;
    if knots.len() < degree + 2 {
        return Err(err_kind(
            ErrorKind::TooFew,
            key,
            format!(
                "need at least degree + 2 = {} knots, got {}",
                degree + 2,
                knots.len()
            ),
        ));
    }
    let count = knots.len() - degree - 1;
    knots::validate(key, &knots, degree, count).map_err(core_err)?;
    knots::check_separated(key, &knots).map_err(core_err)?;
    Ok(knots)
}

#[wasm_bindgen(typescript_custom_section)]
const BSPLINE_TS: &str = r#"
/** The options of `bsplineCurve`: the B-spline and where to evaluate it. */
export interface BsplineCurveOptions extends BsplineOptions, CurveSampling {}
export interface BsplineCurveResult extends CurveResult {
  knots: Float64Array;
}
export interface BsplineDeBoorResult {
  dim: number;
  /** k with t_k ≤ u < t_{k+1} (the last non-empty span at the right end). */
  span: number;
  u: number;
  /** `levels[r]` = P^r_i for i = firstIndex[r] … k, flat: level 0 the p + 1 points acting at u, level p = C(u). */
  levels: Float64Array[];
  /** `alphas[r]` = α_{i,r} = (u − t_i)/(t_{i+p+1−r} − t_i) of level r (`alphas[0]` empty). */
  alphas: Float64Array[];
  /** k − p + r per level r. */
  firstIndex: Float64Array;
  /** C(u), the single point of level p. */
  point: Float64Array;
}
export interface BsplineInsertKnotResult {
  dim: number;
  /** k with t_k ≤ u < t_{k+1}. */
  span: number;
  u: number;
  /** k − p + 1: the new Q_first … Q_k replace P_first … P_{k−1}. */
  first: number;
  /** α_i = (u − t_i)/(t_{i+p} − t_i) at `alphas[i − first]`, Q_i = (1 − α_i) P_{i−1} + α_i P_i. */
  alphas: Float64Array;
  /** The new knot vector (one more knot). */
  knots: Float64Array;
  /** The new control points, flat (one more point): the same curve. */
  points: Float64Array;
}
"#;

/// `bsplineCurve({ degree, knots, points, at | samples, derivatives })` → `{ dim, params, points, d1?, d2? }`.
#[wasm_bindgen(js_name = bsplineCurve, unchecked_return_type = "BsplineCurveResult")]
pub fn bspline_curve(
    #[wasm_bindgen(unchecked_param_type = "BsplineCurveOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let BsplineOptions {
        degree,
        points,
        knots,
    } = BsplineOptions::read(&o)?;
    let order = o.derivatives(2)?;
    with_points!(points, p => {
        let curve = BSplineCurve::new(degree, knots, p).map_err(core_err)?;
        let params = o.curve_params(curve.domain())?;
        Ok(curve_result_for(&o, &curve, &params, order).f64s("knots", curve.knots()).build())
    })
}

/// `bsplineBasis({ degree, knots, at, derivatives })` → `{ count, values, d1?, d2? }`, row after row.
#[wasm_bindgen(js_name = bsplineBasis, unchecked_return_type = "BasisResult")]
pub fn bspline_basis(
    #[wasm_bindgen(unchecked_param_type = "BsplineBasisOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let BsplineBasisOptions { degree, knots } = BsplineBasisOptions::read(&o)?;
    let count = knots.len() - degree - 1;
    let domain = (knots[degree], knots[count]);
    let at = o.curve_params(domain)?;
    if at.len().saturating_mul(count) > crate::sample::MAX_EVAL_POINTS {
        return Err(err_kind(
            ErrorKind::TooMany,
            "at",
            "parameters × basis functions exceeds 1,000,000 values",
        ));
    }
    let order = o.derivatives(2)?;
    let mut values = Vec::with_capacity(at.len() * count);
    let mut d1 = Vec::new();
    let mut d2 = Vec::new();
    let mut row = [Vec::new(), Vec::new(), Vec::new()];
    for &u in &at {
        basis_all(&knots, degree, u, order, &mut row);
        values.extend_from_slice(&row[0]);
        if order >= 1 {
            d1.extend_from_slice(&row[1]);
        }
        if order >= 2 {
            d2.extend_from_slice(&row[2]);
        }
    }
    let mut out = Out::new()
        .num("count", count as f64)
        .f64s("params", &at)
        .f64s("values", &values);
    if order >= 1 {
        out = out.f64s("d1", &d1);
    }
    if order >= 2 {
        out = out.f64s("d2", &d2);
    }
    Ok(out.build())
}

/// `bsplineDeBoor({ degree, knots, points, u })` → `{ dim, span, u, levels, alphas, firstIndex, point }`:
/// the triangle of de Boor's algorithm at u. `levels[r]` (a `Float64Array`, flat points) holds P^r_i for
/// i = `firstIndex[r]` = k − p + r ..= k (level 0 = the p + 1 control points acting at u), `alphas[r]` the
/// α_{i,r} = (u − t_i)/(t_{i+p+1−r} − t_i) that made them (`alphas[0]` empty); `point` = C(u).
#[wasm_bindgen(js_name = bsplineDeBoor, unchecked_return_type = "BsplineDeBoorResult")]
pub fn bspline_de_boor(
    #[wasm_bindgen(unchecked_param_type = "BsplineAtOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let BsplineOptions {
        degree,
        points,
        knots,
    } = BsplineOptions::read(&o)?;
    let BsplineAtOptions { u } = BsplineAtOptions::read(&o)?;
    let dim = points.dim() as f64;
    with_points!(points, p => {
        let curve = BSplineCurve::new(degree, knots, p).map_err(core_err)?;
        let tri = curve.de_boor_triangle(u).map_err(core_err)?;
        let first: Vec<f64> = (0..tri.levels.len()).map(|r| tri.first_index(r) as f64).collect();
        Ok(Out::new()
            .num("dim", dim)
            .num("span", tri.span as f64)
            .num("u", u)
            .set("levels", rows_out(tri.levels.iter().map(|l| flat(l))))
            .set("alphas", rows_out(tri.alphas.iter().cloned()))
            .f64s("firstIndex", &first)
            .pts("point", &[tri.point()])
            .build())
    })
}

/// `bsplineInsertKnot({ degree, knots, points, u })` → `{ dim, span, u, first, alphas, knots, points }`:
/// Boehm's insertion of the knot u. The new control points Q_i = (1 − α_i)P_{i−1} + α_i P_i for
/// i = `first` = k − p + 1 ..= k (`alphas[i − first]` = α_i) replace P_first..P_{k−1}; `knots` and `points`
/// (flat) are the whole new curve, the same curve as before.
#[wasm_bindgen(js_name = bsplineInsertKnot, unchecked_return_type = "BsplineInsertKnotResult")]
pub fn bspline_insert_knot(
    #[wasm_bindgen(unchecked_param_type = "BsplineAtOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let BsplineOptions {
        degree,
        points,
        knots,
    } = BsplineOptions::read(&o)?;
    let BsplineAtOptions { u } = BsplineAtOptions::read(&o)?;
    let dim = points.dim() as f64;
    with_points!(points, p => {
        let curve = BSplineCurve::new(degree, knots, p).map_err(core_err)?;
        let ins = curve.insert_knot_steps(u).map_err(core_err)?;
        Ok(Out::new()
            .num("dim", dim)
            .num("span", ins.span as f64)
            .num("u", u)
            .num("first", ins.first as f64)
            .f64s("alphas", &ins.alphas)
            .f64s("knots", ins.curve.knots())
            .pts("points", ins.curve.points())
            .build())
    })
}
