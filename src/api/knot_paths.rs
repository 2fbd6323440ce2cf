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

#[wasm_bindgen(typescript_custom_section)]
const KNOT_MODIFIED_SURFACE_TS: &str = r#"
// knot modification

/** A B-spline surface `{ orderU, orderV, knotsU, knotsV, controlPoints[r][s] }`. */
export interface KnotSurface {
  orderU: number;
  orderV: number;
  knotsU: Numbers;
  knotsV: Numbers;
  controlPoints: Grid;
  /** The dimension of flat rows of `controlPoints` (default 3). */
  dim?: 2 | 3;
}
/** A B-spline curve `{ order, knots, controlPoints }`. */
export interface KnotCurve {
  order: number;
  knots: Numbers;
  controlPoints: Points;
  /** The dimension of flat `controlPoints` (default 2). */
  dim?: 2 | 3;
}
/** The moved knots: index p (into knotsU) with its value up, and/or q (knotsV) with vq. */
export interface MovedKnots {
  p?: number;
  up?: number;
  q?: number;
  vq?: number;
}

export interface KnotModifiedSurfaceOptions extends MovedKnots, SurfaceSampling {
  surface: KnotSurface;
}
export interface KnotModifiedSurfaceResult extends SurfaceResult {
  knotsU: Float64Array;
  knotsV: Float64Array;
  domain: Float64Array;
  affectedSpansU?: Float64Array;
  affectedRangeU?: Float64Array;
  neighboursU?: Float64Array;
  affectedSpansV?: Float64Array;
  affectedRangeV?: Float64Array;
  neighboursV?: Float64Array;
}
"#;

/// The surface with knot p replaced by up (and/or q by vq).
///
/// `knotModifiedSurface({ surface, p, up, q, vq, atUV | samplesU/samplesV, derivatives, mesh })`.
#[wasm_bindgen(js_name = knotModifiedSurface, unchecked_return_type = "KnotModifiedSurfaceResult")]
pub fn knot_modified_surface(
    #[wasm_bindgen(unchecked_param_type = "KnotModifiedSurfaceOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let s = read_surface(&o)?;
    let mu = read_moved(&o, "p", "up", true)?;
    let mv = read_moved(&o, "q", "vq", true)?;
    with_points!(&s.pts, p => {
        let fam = build_surface(&s, p.clone(), mu, mv)?;
        let (up, vq) = fam.knot_values();
        let field = if mu.is_some() { "up" } else { "vq" };
        let mut out = surface_output_checked(&o, &fam, &|xs| check_finite_eval(field, xs))?
            .f64s("knotsU", &fam.line_u().substituted_knots(up))
            .f64s("knotsV", &fam.line_v().substituted_knots(vq));
        let ((a, b), (c, d)) = crate::sample::Surface::domain(&fam);
        out = out.f64s("domain", &[a, b, c, d]);
        out = affected(out, fam.line_u(), "U");
        out = affected(out, fam.line_v(), "V");
        Ok(out.build())
    })
}

#[wasm_bindgen(typescript_custom_section)]
const KNOT_ENVELOPE_TS: &str = r#"
export interface KnotEnvelopeOptions extends MovedKnots, SurfaceSampling {
  surface: KnotSurface;
}
"#;

/// The envelope of the family as the knot moves.
///
/// `knotEnvelope({ surface, p, q, atUV | samplesU/samplesV, derivatives, mesh })`.
#[wasm_bindgen(js_name = knotEnvelope, unchecked_return_type = "SurfaceResult & { orderU: number; orderV: number }")]
pub fn knot_envelope(
    #[wasm_bindgen(unchecked_param_type = "KnotEnvelopeOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let s = read_surface(&o)?;
    let mu = read_moved(&o, "p", "up", false)?;
    let mv = read_moved(&o, "q", "vq", false)?;
    if mu.is_none() && mv.is_none() {
        return Err(err_kind(
            ErrorKind::Invalid,
            "p",
            "give the index p (eq. (6)) and/or q (eq. (8)) of the knot that moves",
        ));
    }
    with_points!(&s.pts, p => {
        let fam = build_surface(&s, p.clone(), mu, mv)?;
        let env = fam.envelope().ok_or_else(|| err_kind(ErrorKind::Invalid, "p", "no moved knot"))?;
        let (ou, ov) = env.orders();
        Ok(surface_output(&o, &env)?.num("orderU", ou as f64).num("orderV", ov as f64).build())
    })
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

#[wasm_bindgen(typescript_custom_section)]
const KNOT_PATHS_TS: &str = r#"
/** A path (flat points) that also carries `dim` and `params` (or `uv` for path-surfaces). */
export type KnotPath = Float64Array & { dim: number; params?: Float64Array; uv?: Float64Array };

export interface KnotPathsOptions extends MovedKnots {
  surface: KnotSurface;
  /** (u, v) pairs of the surface points to follow. */
  points: ReadonlyArray<readonly [number, number] | readonly number[]>;
  from?: number | readonly [number, number];
  to?: number | readonly [number, number];
  samples?: number | readonly [number, number];
}
export interface KnotPathsResult {
  dim: number;
  paths: KnotPath[];
  params?: Float64Array;
  paramsU?: Float64Array;
  paramsV?: Float64Array;
}
"#;

/// The paths of surface points as the knot moves (path-surfaces with p and q).
///
/// `knotPaths({ surface, p, q, points: [u, v][], from, to, samples })` → `{ dim, paths, … }`.
#[wasm_bindgen(js_name = knotPaths, unchecked_return_type = "KnotPathsResult")]
pub fn knot_paths(
    #[wasm_bindgen(unchecked_param_type = "KnotPathsOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let s = read_surface(&o)?;
    let mu = read_moved(&o, "p", "up", false)?;
    let mv = read_moved(&o, "q", "vq", false)?;
    if mu.is_none() && mv.is_none() {
        return Err(err_kind(
            ErrorKind::Invalid,
            "p",
            "give the index p and/or q of the knot that moves",
        ));
    }
    let uv: Vec<Vec<f64>> = o.req("points")?;
    if uv.len() > sample::MAX_INPUT_POINTS {
        return Err(err_kind(
            ErrorKind::TooMany,
            "points",
            format!("at most {} points", sample::MAX_INPUT_POINTS),
        ));
    }
    for (i, w) in uv.iter().enumerate() {
        if w.len() != 2 || !w[0].is_finite() || !w[1].is_finite() {
            return Err(err_kind(
                ErrorKind::WrongType,
                &format!("points[{i}]"),
                "expected a parameter pair [u, v] of finite numbers",
            ));
        }
    }
    with_points!(&s.pts, pts => {
        // the moved knots start at their given values (index validity is checked here)
        let mu0 = mu.map(|(i, _)| (i, s.ku.get(i).copied().unwrap_or(0.0)));
        let mv0 = mv.map(|(i, _)| (i, s.kv.get(i).copied().unwrap_or(0.0)));
        let fam = build_surface(&s, pts.clone(), mu0, mv0)?;
        let dim = pts.first().map_or(2, |q| q.dim());
        let nu_ = fam.line_u().neighbours();
        let nv_ = fam.line_v().neighbours();
        let paths = Array::new();
        let mut out = Out::new().num("dim", dim as f64);
        match (nu_, nv_) {
            (Some((a, b)), Some((c, d))) => {
                let (f0, f1) = read_range_pair(&o, "from", (a, c))?;
                let (t0, t1) = read_range_pair(&o, "to", (b, d))?;
                let (n1, n2) = read_samples(&o, 40, true)?;
                sample::check_eval_count("samples", uv.len().saturating_mul(n1).saturating_mul(n2)).map_err(core_err)?;
                let (xs, ys) = (sample::uniform_params(f0, t0, n1), sample::uniform_params(f1, t1, n2));
                let grid: Vec<f64> = xs.iter().flat_map(|&x| ys.iter().flat_map(move |&y| [x, y])).collect();
                let mut buf = Vec::new();
                for w in &uv {
                    buf.clear();
                    fam.path_surface_into(w[0], w[1], &xs, &ys, &mut buf);
                    check_finite_eval("to", &flat(&buf))?;
                    paths.push(&path_array(&flat(&buf), dim, "uv", &grid));
                }
                out = out.f64s("paramsU", &xs).f64s("paramsV", &ys);
            }
            _ => {
                let (a, b) = nu_.or(nv_).unwrap_or((0.0, 1.0));
                let from = o.f64_or("from", a)?;
                let to = o.f64_or("to", b)?;
                let (n, _) = read_samples(&o, 200, false)?;
                sample::check_eval_count("samples", uv.len().saturating_mul(n)).map_err(core_err)?;
                let xs = sample::uniform_params(from, to, n);
                let mut buf = Vec::new();
                for w in &uv {
                    buf.clear();
                    if nu_.is_some() {
                        fam.path_into(w[0], w[1], &xs, &mut buf);
                    } else {
                        fam.path_v_into(w[0], w[1], &xs, &mut buf);
                    }
                    check_finite_eval("to", &flat(&buf))?;
                    paths.push(&path_array(&flat(&buf), dim, "params", &xs));
                }
                out = out.f64s("params", &xs);
            }
        }
        Ok(out.set("paths", paths).build())
    })
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

#[wasm_bindgen(typescript_custom_section)]
const KNOT_MODIFIED_CURVE_TS: &str = r#"
export interface KnotModifiedCurveOptions extends CurveSampling {
  curve: KnotCurve;
  p?: number;
  up?: number;
}
export interface KnotModifiedCurveResult extends CurveResult {
  knots: Float64Array;
  domain: Float64Array;
  affectedSpans?: Float64Array;
  affectedRange?: Float64Array;
  neighbours?: Float64Array;
}
"#;

/// The curve with knot p replaced by up.
///
/// `knotModifiedCurve({ curve, p, up, at | samples, derivatives })`.
#[wasm_bindgen(js_name = knotModifiedCurve, unchecked_return_type = "KnotModifiedCurveResult")]
pub fn knot_modified_curve(
    #[wasm_bindgen(unchecked_param_type = "KnotModifiedCurveOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let c = read_curve(&o)?;
    let m = read_moved(&o, "p", "up", true)?;
    let order = o.derivatives(2)?;
    with_points!(&c.pts, pts => {
        let curve = build_curve(&c, pts.clone(), m)?;
        let params = o.curve_params(curve.domain())?;
        let (a, b) = curve.domain();
        // evaluated once: checked (poles of the extended family), then returned as `curve_result` would
        let (p0, p1, p2) = sample::eval_curve(&curve, &params, order);
        for xs in [&p0, &p1, &p2] {
            check_finite_eval("up", xs)?;
        }
        let mut out = Out::new()
            .num("dim", pts.first().map_or(2, |q| q.dim()) as f64)
            .f64s("params", &params)
            .f64s("points", &p0);
        if order >= 1 {
            out = out.f64s("d1", &p1);
        }
        if order >= 2 {
            out = out.f64s("d2", &p2);
        }
        let out = out
            .f64s("knots", &curve.line().substituted_knots(curve.up()))
            .f64s("domain", &[a, b]);
        Ok(affected(out, curve.line(), "").build())
    })
}

#[wasm_bindgen(typescript_custom_section)]
const KNOT_DE_BOOR_CURVE_TS: &str = r#"
export interface KnotDeBoorCurveOptions {
  curve: KnotCurve;
  /** The index of the knot that moves (required). */
  p: number;
  /** Its new value (required). */
  up: number;
  /** The curve parameter, in the domain (required). */
  u: number;
}
export interface KnotDeBoorCurveResult {
  dim: number;
  /** The span i of u (the family's span rule, extended paths included). */
  span: number;
  u: number;
  up: number;
  /** The knot vector with u_p replaced by up. */
  knots: Float64Array;
  /** d_{i−k+1}..d_i, flat. */
  start: Float64Array;
  startIndices: Float64Array;
  /** One entry per intermediate point d_j^r, level by level: its level r. */
  levels: Float64Array;
  /** Its index j. */
  indices: Float64Array;
  /** The knot indices lo, hi of α_j^r = (u − u_lo)/(u_hi − u_lo). */
  knotLo: Float64Array;
  knotHi: Float64Array;
  alphas: Float64Array;
  /** d_j^r, flat; the last is a(u; up). */
  points: Float64Array;
  /** 1 where α_j^r contains the moved knot, else 0. */
  usesUp: Float64Array;
}
"#;

/// The de Boor triangle at u with knot p moved to up (Theorem 1's recursion, for steppers).
///
/// `knotDeBoorCurve({ curve, p, up, u })` → `{ dim, span, u, up, knots, start, startIndices, levels, indices,
/// knotLo, knotHi, alphas, points, usesUp }`: the de Boor triangle at `u` with the knot `p` moved to `up`
/// (the recursion of the paper's Theorem 1, for the step-by-step view). `start` = d_{i−k+1..i} (flat) with
/// their indices; then one entry per intermediate point d_j^r, level by level: `levels` r, `indices` j,
/// `knotLo`/`knotHi` the knot indices of α_j^r = (u − u_lo)/(u_hi − u_lo), `alphas`, `points` (flat), and
/// `usesUp` (1 when α_j^r contains the moved knot). The last point is a(u; up).
#[wasm_bindgen(js_name = knotDeBoorCurve, unchecked_return_type = "KnotDeBoorCurveResult")]
pub fn knot_de_boor_curve(
    #[wasm_bindgen(unchecked_param_type = "KnotDeBoorCurveOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let c = read_curve(&o)?;
    let m = require_moved(&o, true)?;
    let u = o.req_f64("u")?;
    with_points!(&c.pts, pts => {
        let curve = build_curve(&c, pts.clone(), Some(m))?;
        let (a, b) = curve.domain();
        if u < a || u > b {
            return Err(err_kind(ErrorKind::OutOfRange, "u", "must lie in the curve's domain (see its `domain`)"));
        }
        let t = curve.de_boor(u, m.1);
        let k = c.k;
        let start: Vec<_> = (0..k).map(|i| pts[t.span + 1 + i - k]).collect();
        let col = |f: &dyn Fn(&crate::knot_paths::DeBoorStep<_>) -> f64| -> Vec<f64> { t.steps.iter().map(f).collect() };
        let uses = col(&|s| f64::from(u8::from(s.knots.0 == m.0 || s.knots.1 == m.0)));
        let pts_out: Vec<_> = t.steps.iter().map(|s| s.point).collect();
        Ok(Out::new()
            .num("dim", pts.first().map_or(2, |q| q.dim()) as f64)
            .num("span", t.span as f64)
            .num("u", u)
            .num("up", m.1)
            .f64s("knots", &curve.line().substituted_knots(m.1))
            .pts("start", &start)
            .f64s("startIndices", &(0..k).map(|i| (t.span + 1 + i - k) as f64).collect::<Vec<_>>())
            .f64s("levels", &col(&|s| s.level as f64))
            .f64s("indices", &col(&|s| s.index as f64))
            .f64s("knotLo", &col(&|s| s.knots.0 as f64))
            .f64s("knotHi", &col(&|s| s.knots.1 as f64))
            .f64s("alphas", &col(&|s| s.alpha))
            .pts("points", &pts_out)
            .f64s("usesUp", &uses)
            .build())
    })
}

#[wasm_bindgen(typescript_custom_section)]
const KNOT_ENVELOPE_CURVE_TS: &str = r#"
export interface KnotEnvelopeCurveOptions extends CurveSampling {
  curve: KnotCurve;
  p: number;
  up?: number;
}
"#;

/// The envelope of the curve family on [u_{p−1}, u_{p+1}].
///
/// `knotEnvelopeCurve({ curve, p, at | samples, derivatives })`.
#[wasm_bindgen(js_name = knotEnvelopeCurve, unchecked_return_type = "CurveResult & { order: number }")]
pub fn knot_envelope_curve(
    #[wasm_bindgen(unchecked_param_type = "KnotEnvelopeCurveOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let c = read_curve(&o)?;
    let m = require_moved(&o, false)?;
    let order = o.derivatives(2)?;
    with_points!(&c.pts, pts => {
        let curve = build_curve(&c, pts.clone(), Some((m.0, 0.0)))?;
        let env = curve.envelope().ok_or_else(|| err_kind(ErrorKind::Invalid, "p", "no moved knot"))?;
        let params = o.curve_params(env.domain())?;
        Ok(super::curve_result_for(&o, &env, &params, order).num("order", (c.k - 1) as f64).build())
    })
}

#[wasm_bindgen(typescript_custom_section)]
const KNOT_PATHS_CURVE_TS: &str = r#"
export interface KnotPathsCurveOptions {
  curve: KnotCurve;
  p: number;
  up?: number;
  /** Curve parameters u of the points to follow (`points` is accepted as its name too). */
  params?: Numbers;
  points?: Numbers;
  from?: number;
  to?: number;
  samples?: number;
}
"#;

/// The paths of curve points as u_p moves.
///
/// `knotPathsCurve({ curve, p, params, from, to, samples })` → `{ dim, paths, params }`.
#[wasm_bindgen(js_name = knotPathsCurve, unchecked_return_type = "{ dim: number; paths: KnotPath[]; params: Float64Array }")]
pub fn knot_paths_curve(
    #[wasm_bindgen(unchecked_param_type = "KnotPathsCurveOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let c = read_curve(&o)?;
    let m = require_moved(&o, false)?;
    let key = if o.has("params") { "params" } else { "points" };
    let us = o.f64s(key)?.ok_or_else(|| {
        err_kind(
            ErrorKind::Missing,
            "params",
            "the curve parameters u of the points to follow are required",
        )
    })?;
    if us.len() > sample::MAX_INPUT_POINTS {
        return Err(err_kind(
            ErrorKind::TooMany,
            key,
            format!("at most {} parameters", sample::MAX_INPUT_POINTS),
        ));
    }
    with_points!(&c.pts, pts => {
        let start = c.knots.get(m.0).copied().unwrap_or(0.0);
        let curve = build_curve(&c, pts.clone(), Some((m.0, start)))?;
        let (a, b) = curve.line().neighbours().unwrap_or((0.0, 1.0));
        let from = o.f64_or("from", a)?;
        let to = o.f64_or("to", b)?;
        let (n, _) = read_samples(&o, 200, false)?;
        sample::check_eval_count("samples", us.len().saturating_mul(n)).map_err(core_err)?;
        let xs = sample::uniform_params(from, to, n);
        let paths = Array::new();
        let mut buf = Vec::new();
        let dim = pts.first().map_or(2, |q| q.dim());
        for &u in &us {
            buf.clear();
            curve.path_into(u, &xs, &mut buf);
            check_finite_eval("to", &flat(&buf))?;
            paths.push(&path_array(&flat(&buf), dim, "params", &xs));
        }
        Ok(Out::new().num("dim", dim as f64).f64s("params", &xs).set("paths", paths).build())
    })
}

#[wasm_bindgen(typescript_custom_section)]
const KNOT_LIMITS_TS: &str = r#"
export interface KnotLimitsOptions extends MovedKnots {
  curve?: KnotCurve;
  surface?: KnotSurface;
  samples?: number;
}
export interface KnotLimitsCurveResult {
  dim: number;
  minus: Float64Array;
  plus: Float64Array;
  minusIndex: number;
  plusIndex: number;
}
export interface KnotLimitsSurfaceResult {
  dim: number;
  uMinus?: Float64Array;
  uPlus?: Float64Array;
  uMinusIndex?: number;
  uPlusIndex?: number;
  uMinusCurve?: Float64Array;
  uPlusCurve?: Float64Array;
  vMinus?: Float64Array;
  vPlus?: Float64Array;
  vMinusIndex?: number;
  vPlusIndex?: number;
  vMinusCurve?: Float64Array;
  vPlusCurve?: Float64Array;
  corners?: Float64Array;
  cornerIndices?: number[][];
}
/** Where the family goes as the knot tends to ±∞ (curve or surface). */
export function knotLimits(options: KnotLimitsOptions & { curve: KnotCurve }): KnotLimitsCurveResult;
export function knotLimits(options: KnotLimitsOptions & { surface: KnotSurface }): KnotLimitsSurfaceResult;
export function knotLimits(options: KnotLimitsOptions): KnotLimitsCurveResult | KnotLimitsSurfaceResult;
"#;

/// `knotLimits({ curve | surface, p, q, samples })` (see the module doc).
#[wasm_bindgen(js_name = knotLimits, skip_typescript)]
pub fn knot_limits(options: JsValue) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    if o.has("curve") {
        let c = read_curve(&o)?;
        let m = require_moved(&o, false)?;
        return with_points!(&c.pts, pts => {
            let curve = build_curve(&c, pts.clone(), Some((m.0, c.knots.get(m.0).copied().unwrap_or(0.0))))?;
            let ((im, lm), (ip, lp)) = curve.limits().ok_or_else(|| err_kind(ErrorKind::Invalid, "p", "no moved knot"))?;
            Ok(Out::new()
                .num("dim", lm.dim() as f64)
                .f64s("minus", &flat(&[lm]))
                .f64s("plus", &flat(&[lp]))
                .num("minusIndex", im as f64)
                .num("plusIndex", ip as f64)
                .build())
        });
    }
    let s = read_surface(&o)?;
    let mu = read_moved(&o, "p", "up", false)?;
    let mv = read_moved(&o, "q", "vq", false)?;
    if mu.is_none() && mv.is_none() {
        return Err(err_kind(
            ErrorKind::Invalid,
            "p",
            "give the index p and/or q of the knot that moves",
        ));
    }
    let (n, _) = read_samples(&o, 200, false)?;
    sample::check_eval_count("samples", n.saturating_mul(4)).map_err(core_err)?;
    with_points!(&s.pts, pts => {
        let fam = build_surface(&s, pts.clone(), mu, mv)?;
        let mut out = Out::new().num("dim", pts[0].dim() as f64);
        for (dir, name, order, knots) in [(Var::U, "u", s.l, &s.kv), (Var::V, "v", s.k, &s.ku)] {
            if let Some(((im, rm), (ip, rp))) = fam.limit_curves(dir) {
                let curve_of = |row: &Vec<_>| -> ApiResult<Vec<f64>> {
                    let c = BSplineCurve::new(order - 1, knots.clone(), row.clone()).map_err(core_err)?;
                    let params = sample::uniform_params(c.domain().0, c.domain().1, n);
                    Ok(sample::eval_curve(&c, &params, 0).0)
                };
                out = out
                    .f64s(&format!("{name}Minus"), &flat(&rm))
                    .f64s(&format!("{name}Plus"), &flat(&rp))
                    .num(&format!("{name}MinusIndex"), im as f64)
                    .num(&format!("{name}PlusIndex"), ip as f64)
                    .f64s(&format!("{name}MinusCurve"), &curve_of(&rm)?)
                    .f64s(&format!("{name}PlusCurve"), &curve_of(&rp)?);
            }
        }
        if let Some(c) = fam.limit_points() {
            let pts: Vec<_> = c.iter().map(|x| x.1).collect();
            let idx: Vec<Vec<usize>> = c.iter().map(|x| vec![x.0 .0, x.0 .1]).collect();
            out = out.f64s("corners", &flat(&pts)).ser("cornerIndices", &idx);
        }
        Ok(out.build())
    })
}
