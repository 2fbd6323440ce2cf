//! knotLimits: the limit control points of a curve or surface as a knot moves to ±∞.

use super::*;

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
