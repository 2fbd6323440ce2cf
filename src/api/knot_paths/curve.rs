//! The curve exports of knot modification: knotModifiedCurve, knotDeBoorCurve, knotEnvelopeCurve, knotPathsCurve.

use super::*;
use crate::knot_paths::DeBoorStep;

api_options! {
    /// The options of `knotModifiedCurve` (where: `at` or `samples`).
    pub struct KnotModifiedCurveOptions extends "CurveSampling" |o| {
        /// The curve.
        curve: Box<KnotCurve> = "curve", req "KnotCurve" => |k| read_curve(o, k)?;
        /// The index of the knot that moves (none: the curve as given).
        p: Option<usize> = "p", opt "number" => |k| moved_index(o, k, "up", true)?;
        /// Its new value (required with `p`).
        up: f64 = "up", opt "number" => |k| moved_value(o, k, "p", p, true)?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const KNOT_MODIFIED_CURVE_TS: &str = r#"
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
    let KnotModifiedCurveOptions { curve: c, p, up } = KnotModifiedCurveOptions::read(&o)?;
    let m = p.map(|i| (i, up));
    let order = o.derivatives(2)?;
    with_points!(&c.control_points, pts => {
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

api_options! {
    /// The options of `knotDeBoorCurve`.
    pub struct KnotDeBoorCurveOptions |o| {
        /// The curve.
        curve: Box<KnotCurve> = "curve", req "KnotCurve" => |k| read_curve(o, k)?;
        /// The index of the knot that moves (required).
        p: usize = "p", req "number" => |k| required_index(o, k, "up", true)?;
        /// Its new value (required).
        up: f64 = "up", req "number" => |k| moved_value(o, k, "p", Some(p), true)?;
        /// The curve parameter, in the domain (required).
        u: f64 = "u", req "number" => |k| o.req_f64(k)?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const KNOT_DE_BOOR_CURVE_TS: &str = r#"
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
    let KnotDeBoorCurveOptions { curve: c, p, up, u } = KnotDeBoorCurveOptions::read(&o)?;
    let m = (p, up);
    with_points!(&c.control_points, pts => {
        let curve = build_curve(&c, pts.clone(), Some(m))?;
        let (a, b) = curve.domain();
        if u < a || u > b {
            return Err(err_kind(ErrorKind::OutOfRange, "u", "must lie in the curve's domain (see its `domain`)"));
        }
        let t = curve.de_boor(u, m.1);
        let k = c.order;
        let start: Vec<_> = (0..k).map(|i| pts[t.span + 1 + i - k]).collect();
        let col = |f: &dyn Fn(&DeBoorStep<_>) -> f64| step_column(&t.steps, f);
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

/// One number per step of a de Boor triangle (out of line: the column code inlined at its six uses made
/// the module about 1 KB larger).
#[inline(never)]
fn step_column<P: Point>(steps: &[DeBoorStep<P>], f: &dyn Fn(&DeBoorStep<P>) -> f64) -> Vec<f64> {
    steps.iter().map(f).collect()
}

api_options! {
    /// The options of `knotEnvelopeCurve` (where: `at` or `samples`).
    pub struct KnotEnvelopeCurveOptions extends "CurveSampling" |o| {
        /// The curve.
        curve: Box<KnotCurve> = "curve", req "KnotCurve" => |k| read_curve(o, k)?;
        /// The index of the knot that moves (required).
        p: usize = "p", req "number" => |k| required_index(o, k, "up", false)?;
        /// A value of the moved knot (the envelope does not depend on it).
        up: f64 = "up", opt "number" => |k| moved_value(o, k, "p", Some(p), false)?;
    }
}

/// The envelope of the curve family on [u_{p−1}, u_{p+1}].
///
/// `knotEnvelopeCurve({ curve, p, at | samples, derivatives })`.
#[wasm_bindgen(js_name = knotEnvelopeCurve, unchecked_return_type = "CurveResult & { order: number }")]
pub fn knot_envelope_curve(
    #[wasm_bindgen(unchecked_param_type = "KnotEnvelopeCurveOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let KnotEnvelopeCurveOptions { curve: c, p, .. } = KnotEnvelopeCurveOptions::read(&o)?;
    let order = o.derivatives(2)?;
    with_points!(&c.control_points, pts => {
        let curve = build_curve(&c, pts.clone(), Some((p, 0.0)))?;
        let env = curve.envelope().ok_or_else(|| err_kind(ErrorKind::Invalid, "p", "no moved knot"))?;
        let params = o.curve_params(env.domain())?;
        Ok(crate::api::curve_result_for(&o, &env, &params, order).num("order", (c.order - 1) as f64).build())
    })
}

api_options! {
    /// The options of `knotPathsCurve` (the values of the moved knot: `KnotPathsCurveRange`).
    pub struct KnotPathsCurveOptions extends "KnotPathsCurveRange" |o| {
        /// The curve.
        curve: Box<KnotCurve> = "curve", req "KnotCurve" => |k| read_curve(o, k)?;
        /// The index of the knot that moves (required).
        p: usize = "p", req "number" => |k| required_index(o, k, "up", false)?;
        /// A value of the moved knot (the paths do not depend on it).
        up: f64 = "up", opt "number" => |k| moved_value(o, k, "p", Some(p), false)?;
        /// Curve parameters u of the points to follow (`points` is accepted as its name too).
        params: Option<Vec<f64>> = "params", opt "Numbers" => |k| {
            if o.has(k) { Some(path_params(o, k)?) } else { None }
        };
        /// The parameters under their other name (when `params` is absent).
        points: Option<Vec<f64>> = "points", opt "Numbers" => |k| {
            if params.is_some() { None } else { Some(path_params(o, k)?) }
        };
    }
}

/// The parameters u of the points to follow, under the name `key` (required: `missing` names `params`).
fn path_params(o: &Opts, key: &str) -> ApiResult<Vec<f64>> {
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
    Ok(us)
}

api_options! {
    /// The values the moved knot of `knotPathsCurve` takes, read once the curve is built (the defaults are
    /// the neighbours u_{p−1}, u_{p+1} of the knot).
    pub struct KnotPathsCurveRange |o, neighbours: (f64, f64)| {
        /// The first value of u_p (default u_{p−1}).
        from: f64 = "from", opt "number" => |k| o.f64_or(k, neighbours.0)?;
        /// The last value of u_p (default u_{p+1}).
        to: f64 = "to", opt "number" => |k| o.f64_or(k, neighbours.1)?;
        /// How many values (default 200).
        samples: usize = "samples", opt "number" => |k| read_samples(o, k, 200, false)?.0;
    }
}

/// The paths of curve points as u_p moves.
///
/// `knotPathsCurve({ curve, p, params, from, to, samples })` → `{ dim, paths, params }`.
#[wasm_bindgen(js_name = knotPathsCurve, unchecked_return_type = "{ dim: number; paths: KnotPath[]; params: Float64Array }")]
pub fn knot_paths_curve(
    #[wasm_bindgen(unchecked_param_type = "KnotPathsCurveOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let KnotPathsCurveOptions {
        curve: c,
        p,
        params,
        points,
        ..
    } = KnotPathsCurveOptions::read(&o)?;
    let us = params.or(points).unwrap_or_default();
    with_points!(&c.control_points, pts => {
        let start = c.knots.get(p).copied().unwrap_or(0.0);
        let curve = build_curve(&c, pts.clone(), Some((p, start)))?;
        let neighbours = curve.line().neighbours().unwrap_or((0.0, 1.0));
        let KnotPathsCurveRange { from, to, samples: n } = KnotPathsCurveRange::read(&o, neighbours)?;
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
