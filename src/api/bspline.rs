//! `bsplineCurve` and `bsplineBasis`: the ordinary B-spline with a full knot vector.

use super::{core_err, curve_result_for, err_kind, with_points, ApiResult, Opts, Out};
use crate::bspline::{basis_all, BSplineCurve};
use crate::error::ErrorKind;
use crate::knots::{self, MAX_DEGREE};
use crate::sample::Curve;
use wasm_bindgen::prelude::*;

/// `bsplineCurve({ degree, knots, points, at | samples, derivatives })` → `{ dim, params, points, d1?, d2? }`.
#[wasm_bindgen(js_name = bsplineCurve)]
pub fn bspline_curve(options: JsValue) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let degree = o.usize_or("degree", 3, MAX_DEGREE)?;
    let pts = o.points("points", degree + 1)?;
    let n = pts.len();
    let knots = match o.f64s("knots")? {
        Some(k) => {
            knots::validate("knots", &k, degree, n).map_err(core_err)?;
            knots::check_separated("knots", &k).map_err(core_err)?;
            k
        }
        None => knots::clamped_uniform(n, degree, 0.0, 1.0),
    };
    let order = o.derivatives(2)?;
    with_points!(pts, p => {
        let curve = BSplineCurve::new(degree, knots, p).map_err(core_err)?;
        let params = o.curve_params(curve.domain())?;
        Ok(curve_result_for(&o, &curve, &params, order).f64s("knots", curve.knots()).build())
    })
}

/// `bsplineBasis({ degree, knots, at, derivatives })` → `{ count, values, d1?, d2? }`, row after row.
#[wasm_bindgen(js_name = bsplineBasis)]
pub fn bspline_basis(options: JsValue) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let degree = o.usize_or("degree", 3, MAX_DEGREE)?;
    let knots = o
        .f64s("knots")?
        .ok_or_else(|| err_kind(ErrorKind::Missing, "knots", "this field is required"))?;
    if knots.len() < degree + 2 {
        return Err(err_kind(
            ErrorKind::TooFew,
            "knots",
            format!(
                "need at least degree + 2 = {} knots, got {}",
                degree + 2,
                knots.len()
            ),
        ));
    }
    let count = knots.len() - degree - 1;
    knots::validate("knots", &knots, degree, count).map_err(core_err)?;
    knots::check_separated("knots", &knots).map_err(core_err)?;
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
