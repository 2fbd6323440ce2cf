//! `bsplineCurve` and `bsplineBasis`: the ordinary B-spline with a full knot vector; `bsplineDeBoor` and
//! `bsplineInsertKnot`: the steps of de Boor's algorithm and of Boehm's knot insertion (for steppers).

use super::{core_err, curve_result_for, err, flat, with_points, ApiResult, Opts, Out, Pts};
use crate::bspline::{basis_all, BSplineCurve};
use crate::knots::{self, MAX_DEGREE};
use crate::sample::Curve;
use wasm_bindgen::prelude::*;

/// `degree` (default 3), `points` and `knots` (default: clamped uniform on \[0, 1\]), validated.
fn read_bspline(o: &Opts) -> ApiResult<(usize, Vec<f64>, Pts)> {
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
    Ok((degree, knots, pts))
}

/// A required finite number.
pub(crate) fn req_f64(o: &Opts, key: &str) -> ApiResult<f64> {
    if !o.has(key) {
        return Err(err(key, "this field is required (a number)"));
    }
    o.f64_or(key, 0.0)
}

/// An `Array` of `Float64Array`s (one per row).
pub(crate) fn rows_out(rows: impl IntoIterator<Item = Vec<f64>>) -> js_sys::Array {
    let arr = js_sys::Array::new();
    for r in rows {
        arr.push(&js_sys::Float64Array::from(&r[..]));
    }
    arr
}

/// `bsplineCurve({ degree, knots, points, at | samples, derivatives })` → `{ dim, params, points, d1?, d2? }`.
#[wasm_bindgen(js_name = bsplineCurve)]
pub fn bspline_curve(options: JsValue) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let (degree, knots, pts) = read_bspline(&o)?;
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
        .ok_or_else(|| err("knots", "this field is required"))?;
    if knots.len() < degree + 2 {
        return Err(err(
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
        return Err(err(
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
#[wasm_bindgen(js_name = bsplineDeBoor)]
pub fn bspline_de_boor(options: JsValue) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let (degree, knots, pts) = read_bspline(&o)?;
    let u = req_f64(&o, "u")?;
    let dim = pts.dim() as f64;
    with_points!(pts, p => {
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
#[wasm_bindgen(js_name = bsplineInsertKnot)]
pub fn bspline_insert_knot(options: JsValue) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let (degree, knots, pts) = read_bspline(&o)?;
    let u = req_f64(&o, "u")?;
    let dim = pts.dim() as f64;
    with_points!(pts, p => {
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
