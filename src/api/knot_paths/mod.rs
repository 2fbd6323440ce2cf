//! Knot modification (seed 002, `surfaces.md` §7): families, envelopes, paths, limits.
//!
//! Contract exports (`../shared/spec/api.md`):
//! * `knotModifiedSurface({ surface, p, up, q, vq, atUV | samplesU/samplesV, derivatives, mesh })` → surface
//!   result + `{ knotsU, knotsV, domain, affectedSpansU?, affectedRangeU?, affectedSpansV?, affectedRangeV? }`
//!   (`knotsU`/`knotsV` with the moved values substituted; the affected spans are the paper's strip D₁/D₂).
//! * `knotEnvelope({ surface, p, q, atUV | samplesU/samplesV, derivatives, mesh })` → surface result: eq. (6)
//!   when only `p` is given, its v-analogue when only `q`, eq. (8) when both. The default grid covers
//!   `[u_{p−1}, u_{p+1}] × [v_{l−1}, v_{m+1}]` (or the analogue).
//! * `knotPaths({ surface, p, q, points: [u, v][], from, to, samples })` → `{ dim, paths, params | paramsU,
//!   paramsV }`. With `p` (or `q`) alone each path is s(u, v; x) for `samples` (default 200) uniform values x
//!   from `from` to `to` (default the neighbours of the knot). With both, each entry is a path-surface
//!   s(u, v; u_p, v_q) on a `samples × samples` grid (default 40; `samples` may be `[nu, nv]`), `u_p`-major,
//!   and `from`/`to` are `[u_p, v_q]` pairs (a number applies to both). Each path is a `Float64Array` of the
//!   flat points that also carries `dim` and `params` (or `uv` for path-surfaces); no self-reference, so a
//!   result survives `JSON.stringify`.
//!
//! Curve helpers (the demo uses them; `curve = { order, knots, controlPoints }`, 2D or 3D points):
//! * `knotModifiedCurve({ curve, p, up, at | samples, derivatives })` → curve result + `{ knots, domain,
//!   affectedSpans, affectedRange, neighbours }`.
//! * `knotDeBoorCurve({ curve, p, up, u })` → the de Boor triangle at `u` (step-by-step view; see the function).
//! * `knotEnvelopeCurve({ curve, p, at | samples, derivatives })` → curve result on `[u_{p−1}, u_{p+1}]`:
//!   e(w) = Σ_{r=p−k+1}^{p−1} N_r^{k−1}(w) d_r on the knots with `u_p` removed.
//! * `knotPathsCurve({ curve, p, params: number[], from, to, samples })` → `{ dim, paths, params }` (as above;
//!   `points` is accepted for `params`).
//! * `knotLimits({ curve | surface, p, q, samples })` → curve: `{ dim, minus, plus, minusIndex, plusIndex }`
//!   (d_p for u_p → −∞, d_{p−k} for +∞, Theorem 5 of the curve paper). Surface: per moved knot the limit
//!   control rows/columns `uMinus`, `uPlus` (d_{p,·}, d_{p−k,·}), `uMinusIndex`, `uPlusIndex` and the
//!   sampled limit curves `uMinusCurve`, `uPlusCurve` (Theorem 3; likewise `v…` for `q`); with both,
//!   `corners` (4 points, flat) and `cornerIndices` for (−∞,−∞), (−∞,+∞), (+∞,−∞), (+∞,+∞) =
//!   d_{p,q}, d_{p,q−l}, d_{p−k,q}, d_{p−k,q−l} (Theorem 4, corrected list of `surfaces.md` §8.6).
//!
//! Indices `p`, `q` are 0-based into the full knot vectors and must be interior: `k ≤ p ≤ n`.

use super::mesh::{surface_output, surface_output_checked};
use super::{api_options, core_err, err_kind, flat, with_points, ApiResult, Opts, Out, Pts};
use crate::bspline::BSplineCurve;
use crate::error::{Error, ErrorKind};
use crate::knot_paths::{KnotLine, KnotModifiedCurve, KnotModifiedSurface, Var, MAX_ORDER};
use crate::point::Point;
use crate::sample::{self, Curve, MAX_EVAL_POINTS};
use js_sys::{Array, Float64Array, Reflect};
use wasm_bindgen::prelude::*;

mod curve;
pub use curve::*;
mod limits;
pub use limits::*;
mod surface;
pub use surface::*;

#[wasm_bindgen(typescript_custom_section)]
const KNOT_PATHS_TS: &str = "\n// knot modification\n";

/// A core error about the surface/curve description, reported as `surface.<field>` (`curve.<field>`);
/// errors about `p`, `q`, `up`, `vq` keep their names.
fn desc_err(prefix: &'static str) -> impl Fn(Error) -> JsError {
    move |e: Error| {
        let f = e.field();
        if ["p", "q", "up", "vq"].contains(&f) {
            core_err(e)
        } else {
            let field = format!("{prefix}.{f}");
            core_err(e.clone().in_field(field))
        }
    }
}

fn sub_opts(o: &Opts, key: &str) -> ApiResult<Opts> {
    let v = o.raw(key);
    if !v.is_object() || v.is_function() || Array::is_array(&v) {
        return Err(err_kind(
            ErrorKind::WrongType,
            key,
            "expected an object { order…, knots…, controlPoints }",
        ));
    }
    Opts::new(v)
}

/// A required knot vector `key` of a nested object, errors on `field` (`curve.knots`, `surface.knotsU`, …).
#[inline(never)]
fn required_knots(o: &Opts, key: &str, field: &str) -> ApiResult<Vec<f64>> {
    o.f64s(key)
        .map_err(|_| {
            err_kind(
                ErrorKind::WrongType,
                field,
                "expected an array of finite numbers",
            )
        })?
        .ok_or_else(|| err_kind(ErrorKind::Missing, field, "this field is required"))
}

api_options! {
    /// A B-spline surface `{ orderU, orderV, knotsU, knotsV, controlPoints }` (the option `surface`).
    pub struct KnotSurface extends "GridDim" |o| {
        /// The order k in u (degree + 1; required, with `orderV`).
        order_u: usize = "orderU", req "number" => |k| {
            surface_orders_given(o)?;
            surface_order(o, k, "surface.orderU")?
        };
        /// The order l in v (degree + 1).
        order_v: usize = "orderV", req "number" => |k| surface_order(o, k, "surface.orderV")?;
        /// The knots u_0..u_{n+k}.
        knots_u: Vec<f64> = "knotsU", req "Numbers" => |k| required_knots(o, k, "surface.knotsU")?;
        /// The knots v_0..v_{m+l}.
        knots_v: Vec<f64> = "knotsV", req "Numbers" => |k| required_knots(o, k, "surface.knotsV")?;
        /// The control points, `controlPoints[r][s]` = d_{r,s} (rows along u; flat rows take `dim`).
        control_points: (usize, usize, Pts) = "controlPoints", req "Grid" => |k| surface_points(o, k)?;
    }
}

/// `surface.orderU` and `surface.orderV`: both required (`missing` names the first one absent).
fn surface_orders_given(s: &Opts) -> ApiResult<()> {
    if s.has("orderU") && s.has("orderV") {
        return Ok(());
    }
    let f = if s.has("orderU") { "orderV" } else { "orderU" };
    Err(err_kind(
        ErrorKind::Missing,
        &format!("surface.{f}"),
        "this field is required (the order k = degree + 1)",
    ))
}

fn surface_order(s: &Opts, key: &str, field: &str) -> ApiResult<usize> {
    s.usize_or(key, 0, MAX_ORDER)
        .map_err(|_| err_kind(ErrorKind::OutOfRange, field, "expected a whole number ≥ 2"))
}

fn surface_points(s: &Opts, key: &str) -> ApiResult<(usize, usize, Pts)> {
    let (nu, nv, pts) = s.grid(key, 1, 1).map_err(|_| {
        err_kind(
            ErrorKind::WrongType,
            "surface.controlPoints",
            "expected a rectangular table controlPoints[r][s] of [x, y] or [x, y, z] points",
        )
    })?;
    if nu.saturating_mul(nv) > sample::MAX_INPUT_POINTS {
        return Err(err_kind(
            ErrorKind::TooMany,
            "surface.controlPoints",
            format!("at most {} control points", sample::MAX_INPUT_POINTS),
        ));
    }
    Ok((nu, nv, pts))
}

/// The surface of the nested object `key` (`surface`). Boxed: the options structs and their readers move it
/// as one pointer (about 2 KB less wasm over the eight exports than moving the struct).
#[inline(never)]
fn read_surface(o: &Opts, key: &str) -> ApiResult<Box<KnotSurface>> {
    KnotSurface::read(&sub_opts(o, key)?).map(Box::new)
}

/// The index of a moved knot (`p`, or `q`), optional: `None` when absent. Absent with its value `value_key`
/// given is an error when the value is needed.
#[inline(never)]
fn moved_index(o: &Opts, key: &str, value_key: &str, need_value: bool) -> ApiResult<Option<usize>> {
    if !o.has(key) {
        if o.has(value_key) && need_value {
            return Err(err_kind(
                ErrorKind::SizeMismatch,
                key,
                format!("give the knot index {key} together with {value_key}"),
            ));
        }
        return Ok(None);
    }
    Ok(Some(o.usize_or(key, 0, usize::MAX >> 1)?))
}

/// The index `p` of the knot that moves, required: `missing` when absent.
#[inline(never)]
fn required_index(o: &Opts, key: &str, value_key: &str, need_value: bool) -> ApiResult<usize> {
    moved_index(o, key, value_key, need_value)?.ok_or_else(|| {
        err_kind(
            ErrorKind::Missing,
            key,
            "the index of the knot that moves is required",
        )
    })
}

/// The new value `key` (`up`, `vq`) of the moved knot `index_key`: read only when that index was given
/// (0 otherwise), required then when `need_value`.
#[inline(never)]
fn moved_value(
    o: &Opts,
    key: &str,
    index_key: &str,
    index: Option<usize>,
    need_value: bool,
) -> ApiResult<f64> {
    if index.is_none() {
        return Ok(0.0);
    }
    if need_value && !o.has(key) {
        return Err(err_kind(
            ErrorKind::Missing,
            key,
            format!("the new value of knot {index_key} is required"),
        ));
    }
    o.f64_or(key, 0.0)
}

/// A moved knot of a surface is required (`p` and/or `q`): `invalid` on `p` with `message` otherwise.
fn some_knot_moves(p: Option<usize>, q: Option<usize>, message: &str) -> ApiResult<()> {
    if p.is_none() && q.is_none() {
        return Err(err_kind(ErrorKind::Invalid, "p", message));
    }
    Ok(())
}

/// Builds the family from the parsed description (values of the moved knots as given).
fn build_surface<P: Point>(
    s: &KnotSurface,
    points: Vec<P>,
    mu: Option<(usize, f64)>,
    mv: Option<(usize, f64)>,
) -> ApiResult<KnotModifiedSurface<P>> {
    KnotModifiedSurface::new(
        s.order_u,
        s.order_v,
        s.knots_u.clone(),
        s.knots_v.clone(),
        s.control_points.0,
        s.control_points.1,
        points,
        mu,
        mv,
    )
    .map_err(desc_err("surface"))
}

fn affected(out: Out, line: &KnotLine, suffix: &str) -> Out {
    match line.affected() {
        Some(((lo, hi), (a, b))) => out
            .f64s(&format!("affectedSpans{suffix}"), &[lo as f64, hi as f64])
            .f64s(&format!("affectedRange{suffix}"), &[a, b])
            .f64s(
                &format!("neighbours{suffix}"),
                &line.neighbours().map_or(vec![], |(a, b)| vec![a, b]),
            ),
        None => out,
    }
}

/// Non-finite evaluations come from the poles of an extended family (a moved knot, outside its neighbours,
/// within rounding of another knot: the curve or surface there is larger than f64 can hold). Reported as an
/// error on `field` instead of returning NaN or ±∞.
fn check_finite_eval(field: &str, xs: &[f64]) -> ApiResult<()> {
    if xs.iter().all(|x| x.is_finite()) {
        return Ok(());
    }
    let at = if field == "to" {
        "on the way from `from` to `to`".to_string()
    } else {
        format!("at the given `{field}`")
    };
    Err(err_kind(ErrorKind::TooMany,
        field,
        format!(
            "the modified family overflows {at} (a pole: the moved knot is, outside its neighbours, \
             within rounding of another knot); keep it further from the other knots"
        ),
    ))
}

/// `from`/`to` as one number or a `[u_p, v_q]` pair.
fn read_range_pair(o: &Opts, key: &str, default: (f64, f64)) -> ApiResult<(f64, f64)> {
    if !o.has(key) {
        return Ok(default);
    }
    if let Some(x) = o.finite_if_number(key)? {
        return Ok((x, x));
    }
    let xs = o.f64s(key)?.unwrap_or_default();
    if xs.len() != 2 {
        return Err(err_kind(
            ErrorKind::WrongType,
            key,
            "expected a number or a pair [u, v]",
        ));
    }
    Ok((xs[0], xs[1]))
}

/// `samples` as a count (default `d`) or, for path-surfaces, `[nu, nv]`.
fn read_samples(o: &Opts, key: &str, d: usize, pair: bool) -> ApiResult<(usize, usize)> {
    if pair && o.has(key) && Array::is_array(&o.raw(key)) {
        let xs = o.f64s(key)?.unwrap_or_default();
        if xs.len() != 2
            || xs
                .iter()
                .any(|x| *x < 1.0 || x.fract() != 0.0 || *x > MAX_EVAL_POINTS as f64)
        {
            return Err(err_kind(
                ErrorKind::WrongType,
                key,
                "expected a whole number ≥ 1 or a pair [nu, nv]",
            ));
        }
        return Ok((xs[0] as usize, xs[1] as usize));
    }
    let n = o.usize_or(key, d, MAX_EVAL_POINTS)?;
    if n < 1 {
        return Err(err_kind(ErrorKind::TooFew, key, "expected at least 1"));
    }
    Ok((n, if pair { n } else { 1 }))
}

/// Attaches `dim`, `points` (itself) and `params`/`uv` to a flat path array.
fn path_array(points: &[f64], dim: usize, key: &str, params: &[f64]) -> JsValue {
    let arr = Float64Array::new_with_length(points.len() as u32);
    arr.copy_from(points);
    let p = Float64Array::new_with_length(params.len() as u32);
    p.copy_from(params);
    let _ = Reflect::set(&arr, &"dim".into(), &JsValue::from_f64(dim as f64));
    let _ = Reflect::set(&arr, &key.into(), &p);
    arr.into()
}

/// The dimension of a point value (helper for the generic macro bodies).
trait PointDim {
    fn dim(&self) -> usize;
}
impl<P: Point> PointDim for P {
    fn dim(&self) -> usize {
        P::DIM
    }
}

// ---------------------------------------------------------------------------------------------------
// Curves
// ---------------------------------------------------------------------------------------------------

api_options! {
    /// A B-spline curve `{ order, knots, controlPoints }` (the option `curve`; 2D or 3D points).
    pub struct KnotCurve extends "FlatDim" |o| {
        /// The order k (degree + 1).
        order: usize = "order", req "number" => |k| curve_order(o, k)?;
        /// The knots u_0..u_{n+k}.
        knots: Vec<f64> = "knots", req "Numbers" => |k| required_knots(o, k, "curve.knots")?;
        /// The control points d_0..d_n (flat coordinates take `dim`).
        control_points: Pts = "controlPoints", req "Points" => |k| curve_points(o, k)?;
    }
}

fn curve_order(c: &Opts, key: &str) -> ApiResult<usize> {
    if !c.has(key) {
        return Err(err_kind(
            ErrorKind::Missing,
            "curve.order",
            "this field is required (the order k = degree + 1)",
        ));
    }
    c.usize_or(key, 0, MAX_ORDER).map_err(|_| {
        err_kind(
            ErrorKind::OutOfRange,
            "curve.order",
            format!("expected a whole number 2..={MAX_ORDER}"),
        )
    })
}

fn curve_points(c: &Opts, key: &str) -> ApiResult<Pts> {
    c.points(key, 1).map_err(|_| {
        err_kind(
            ErrorKind::TooFew,
            "curve.controlPoints",
            "expected at least one point, all [x, y] or all [x, y, z], finite",
        )
    })
}

/// The curve of the nested object `key` (`curve`), boxed as the surface (`read_surface`).
#[inline(never)]
fn read_curve(o: &Opts, key: &str) -> ApiResult<Box<KnotCurve>> {
    KnotCurve::read(&sub_opts(o, key)?).map(Box::new)
}

fn build_curve<P: Point>(
    c: &KnotCurve,
    pts: Vec<P>,
    m: Option<(usize, f64)>,
) -> ApiResult<KnotModifiedCurve<P>> {
    KnotModifiedCurve::new(
        c.order,
        c.knots.clone(),
        pts,
        m.map(|x| x.0),
        m.map_or(0.0, |x| x.1),
    )
    .map_err(desc_err("curve"))
}
