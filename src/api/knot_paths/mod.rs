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
use super::{core_err, err_kind, flat, with_points, ApiResult, Opts, Out, Pts};
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

/// The parsed `surface` option, before building (points row-major in r).
struct SurfaceIn {
    k: usize,
    l: usize,
    ku: Vec<f64>,
    kv: Vec<f64>,
    nu: usize,
    nv: usize,
    pts: Pts,
}

fn read_surface(o: &Opts) -> ApiResult<SurfaceIn> {
    let s = sub_opts(o, "surface")?;
    let pre = |r: ApiResult<usize>, f: &str| {
        r.map_err(|_| {
            err_kind(
                ErrorKind::OutOfRange,
                &format!("surface.{f}"),
                "expected a whole number ≥ 2",
            )
        })
    };
    if !s.has("orderU") || !s.has("orderV") {
        let f = if s.has("orderU") { "orderV" } else { "orderU" };
        return Err(err_kind(
            ErrorKind::Missing,
            &format!("surface.{f}"),
            "this field is required (the order k = degree + 1)",
        ));
    }
    let k = pre(s.usize_or("orderU", 0, MAX_ORDER), "orderU")?;
    let l = pre(s.usize_or("orderV", 0, MAX_ORDER), "orderV")?;
    let ku = s
        .f64s("knotsU")
        .map_err(|_| {
            err_kind(
                ErrorKind::WrongType,
                "surface.knotsU",
                "expected an array of finite numbers",
            )
        })?
        .ok_or_else(|| {
            err_kind(
                ErrorKind::Missing,
                "surface.knotsU",
                "this field is required",
            )
        })?;
    let kv = s
        .f64s("knotsV")
        .map_err(|_| {
            err_kind(
                ErrorKind::WrongType,
                "surface.knotsV",
                "expected an array of finite numbers",
            )
        })?
        .ok_or_else(|| {
            err_kind(
                ErrorKind::Missing,
                "surface.knotsV",
                "this field is required",
            )
        })?;
    let (nu, nv, pts) = s.grid("controlPoints", 1, 1).map_err(|_| {
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
    Ok(SurfaceIn {
        k,
        l,
        ku,
        kv,
        nu,
        nv,
        pts,
    })
}

/// The moved knot `p` (and its value `up` when `need_value`), required: `missing` on `p` when absent.
fn require_moved(o: &Opts, need_value: bool) -> ApiResult<(usize, f64)> {
    read_moved(o, "p", "up", need_value)?.ok_or_else(|| {
        err_kind(
            ErrorKind::Missing,
            "p",
            "the index of the knot that moves is required",
        )
    })
}

/// `p`/`q` (optional index) with its value key (`up`/`vq`), value required when `need_value`.
fn read_moved(
    o: &Opts,
    key: &str,
    value_key: &str,
    need_value: bool,
) -> ApiResult<Option<(usize, f64)>> {
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
    let i = o.usize_or(key, 0, usize::MAX >> 1)?;
    if need_value && !o.has(value_key) {
        return Err(err_kind(
            ErrorKind::Missing,
            value_key,
            format!("the new value of knot {key} is required"),
        ));
    }
    Ok(Some((i, o.f64_or(value_key, 0.0)?)))
}

/// Builds the family from the parsed description (values of the moved knots as given).
fn build_surface<P: Point>(
    s: &SurfaceIn,
    points: Vec<P>,
    mu: Option<(usize, f64)>,
    mv: Option<(usize, f64)>,
) -> ApiResult<KnotModifiedSurface<P>> {
    KnotModifiedSurface::new(
        s.k,
        s.l,
        s.ku.clone(),
        s.kv.clone(),
        s.nu,
        s.nv,
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
    let v = o.raw(key);
    if let Some(x) = v.as_f64() {
        if !x.is_finite() {
            return Err(err_kind(
                ErrorKind::NotFinite,
                key,
                crate::error::not_finite_detail(x),
            ));
        }
        return Ok((x, x));
    }
    let xs = o.f64s(key)?.unwrap_or_default();
    if xs.len() != 2 {
        return Err(err_kind(
            ErrorKind::WrongType,
            key,
            "expected a number or a pair [u_p, v_q]",
        ));
    }
    Ok((xs[0], xs[1]))
}

/// `samples` as a count (default `d`) or, for path-surfaces, `[nu, nv]`.
fn read_samples(o: &Opts, d: usize, pair: bool) -> ApiResult<(usize, usize)> {
    if pair && o.has("samples") && Array::is_array(&o.raw("samples")) {
        let xs = o.f64s("samples")?.unwrap_or_default();
        if xs.len() != 2
            || xs
                .iter()
                .any(|x| *x < 1.0 || x.fract() != 0.0 || *x > MAX_EVAL_POINTS as f64)
        {
            return Err(err_kind(
                ErrorKind::WrongType,
                "samples",
                "expected a whole number ≥ 1 or a pair [nu, nv]",
            ));
        }
        return Ok((xs[0] as usize, xs[1] as usize));
    }
    let n = o.usize_or("samples", d, MAX_EVAL_POINTS)?;
    if n < 1 {
        return Err(err_kind(
            ErrorKind::TooFew,
            "samples",
            "expected at least 1",
        ));
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

struct CurveIn {
    k: usize,
    knots: Vec<f64>,
    pts: Pts,
}

fn read_curve(o: &Opts) -> ApiResult<CurveIn> {
    let c = sub_opts(o, "curve")?;
    if !c.has("order") {
        return Err(err_kind(
            ErrorKind::Missing,
            "curve.order",
            "this field is required (the order k = degree + 1)",
        ));
    }
    let k = c.usize_or("order", 0, MAX_ORDER).map_err(|_| {
        err_kind(
            ErrorKind::OutOfRange,
            "curve.order",
            format!("expected a whole number 2..={MAX_ORDER}"),
        )
    })?;
    let knots = c
        .f64s("knots")
        .map_err(|_| {
            err_kind(
                ErrorKind::WrongType,
                "curve.knots",
                "expected an array of finite numbers",
            )
        })?
        .ok_or_else(|| err_kind(ErrorKind::Missing, "curve.knots", "this field is required"))?;
    let pts = c.points("controlPoints", 1).map_err(|_| {
        err_kind(
            ErrorKind::TooFew,
            "curve.controlPoints",
            "expected at least one point, all [x, y] or all [x, y, z], finite",
        )
    })?;
    Ok(CurveIn { k, knots, pts })
}

fn build_curve<P: Point>(
    c: &CurveIn,
    pts: Vec<P>,
    m: Option<(usize, f64)>,
) -> ApiResult<KnotModifiedCurve<P>> {
    KnotModifiedCurve::new(
        c.k,
        c.knots.clone(),
        pts,
        m.map(|x| x.0),
        m.map_or(0.0, |x| x.1),
    )
    .map_err(desc_err("curve"))
}
