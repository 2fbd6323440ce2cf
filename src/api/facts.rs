//! `curveFacts`: the facts of a sampled plane curve for a description in words (issue 25; the maths in
//! [`crate::facts`]). Gated by the feature `api-facts`, which every group with a 2D curve demo
//! builds with (www/lib/wasm-groups.js).

use super::{api_options, core_err, err_kind, ApiResult, Opts, Out, Pts};
use crate::error::ErrorKind;
use crate::facts::{curve_facts, CurvePoint};
use wasm_bindgen::prelude::*;

api_options! {
    /// The sampled plane curve of `curveFacts` (and, optionally, data points to measure against).
    pub struct CurveFactsOptions extends "FlatDim" |o| {
        /// The curve's samples (at least 2), in the order of their parameters; plane points only.
        points: Vec<[f64; 2]> = "points", req "Points" => |k| plane(k, o.points(k, 2)?)?;
        /// The parameter of each sample, not decreasing (default: the sample index 0, 1, 2, …).
        params: Vec<f64> = "params", opt "Numbers"
            => |k| o.f64s(k)?.unwrap_or_else(|| (0..points.len()).map(|i| i as f64).collect());
        /// Data points W₀, W₁, … whose distances to the curve are measured.
        data: Option<Vec<[f64; 2]>> = "data", opt "Points"
            => |k| if o.has(k) { Some(plane(k, o.points(k, 0)?)?) } else { None };
    }
}

/// The points as `[x, y]` pairs; 3D points are refused (`field` names them).
fn plane(field: &str, p: Pts) -> ApiResult<Vec<[f64; 2]>> {
    match p {
        Pts::D2(v) => Ok(v.iter().map(|q| [q.x, q.y]).collect()),
        Pts::D3(_) => Err(err_kind(
            ErrorKind::Invalid,
            field,
            "curveFacts measures plane curves: points need 2 coordinates (dim 2)",
        )),
    }
}

#[wasm_bindgen(typescript_custom_section)]
const FACTS_TS: &str = r#"
/** A point of the curve with its parameter. */
export interface CurvePoint { u: number; x: number; y: number; }
export interface CurveFactsResult {
  /** The extremes in x and y, refined by the parabola in u through the three samples around them. */
  leftmost: CurvePoint;
  rightmost: CurvePoint;
  lowest: CurvePoint;
  highest: CurvePoint;
  /** Where the signed curvature changes sign: parameters, and points x, y interleaved. */
  inflectionParams: Float64Array;
  inflectionPoints: Float64Array;
  /** The polyline's length. */
  length: number;
  /** With `data`: each data point's distance to the polyline, the largest and its index, the RMS. */
  distances?: Float64Array;
  maxDistance?: number;
  maxDistanceIndex?: number;
  rmsDistance?: number;
}
"#;

fn point_out(p: &CurvePoint) -> JsValue {
    Out::new().num("u", p.u).num("x", p.x).num("y", p.y).build()
}

/// `curveFacts({ points, params?, data? })` → `{ leftmost, rightmost, lowest, highest, inflectionParams,
/// inflectionPoints, length, distances?, maxDistance?, maxDistanceIndex?, rmsDistance? }`.
#[wasm_bindgen(js_name = curveFacts, unchecked_return_type = "CurveFactsResult")]
pub fn curve_facts_js(
    #[wasm_bindgen(unchecked_param_type = "CurveFactsOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let CurveFactsOptions {
        points,
        params,
        data,
    } = CurveFactsOptions::read(&o)?;
    let f = curve_facts(&params, &points, data.as_deref()).map_err(core_err)?;
    let infl_u: Vec<f64> = f.inflections.iter().map(|p| p.u).collect();
    let infl_xy: Vec<f64> = f.inflections.iter().flat_map(|p| [p.x, p.y]).collect();
    let mut out = Out::new()
        .set("leftmost", point_out(&f.leftmost))
        .set("rightmost", point_out(&f.rightmost))
        .set("lowest", point_out(&f.lowest))
        .set("highest", point_out(&f.highest))
        .f64s("inflectionParams", &infl_u)
        .f64s("inflectionPoints", &infl_xy)
        .num("length", f.length);
    if let Some(d) = f.data {
        out = out
            .f64s("distances", &d.distances)
            .num("maxDistance", d.max)
            .num("maxDistanceIndex", d.max_index as f64)
            .num("rmsDistance", d.rms);
    }
    Ok(out.build())
}
