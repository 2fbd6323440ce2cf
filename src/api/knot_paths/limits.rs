//! knotLimits: the limit control points of a curve or surface as a knot moves to ±∞.

use super::*;

api_options! {
    /// The options of `knotLimits`: a `curve` (with `p`; Theorem 5) or a `surface` (with `p` and/or `q`;
    /// Theorems 3 and 4). With a curve, `q`, `vq` and `samples` are not read.
    pub struct KnotLimitsOptions |o| {
        /// The curve (when given, `surface` is not read).
        curve: Option<Box<KnotCurve>> = "curve", opt "KnotCurve" => |k| {
            if o.has(k) { Some(read_curve(o, k)?) } else { None }
        };
        /// The surface (required without `curve`).
        surface: Option<Box<KnotSurface>> = "surface", opt "KnotSurface" => |k| {
            if curve.is_some() { None } else { Some(read_surface(o, k)?) }
        };
        /// The index of the knot (of the curve, or of `knotsU`) that moves (required for a curve).
        p: Option<usize> = "p", opt "number" => |k| {
            if curve.is_some() { Some(required_index(o, k, "up", false)?) } else { moved_index(o, k, "up", false)? }
        };
        /// A value of u_p (the limits do not depend on it).
        up: f64 = "up", opt "number" => |k| moved_value(o, k, "p", p, false)?;
        /// The index of the knot of `knotsV` that moves (surface).
        q: Option<usize> = "q", opt "number" => |k| {
            if curve.is_some() { None } else { moved_index(o, k, "vq", false)? }
        };
        /// A value of v_q (the limits do not depend on it).
        vq: f64 = "vq", opt "number" => |k| moved_value(o, k, "q", q, false)?;
        /// Samples of each limit curve of a surface (default 200).
        samples: usize = "samples", opt "number" => |k| match surface {
            Some(_) => {
                some_knot_moves(p, q, "give the index p and/or q of the knot that moves")?;
                read_samples(o, k, 200, false)?.0
            }
            None => 0,
        };
    }
}

#[wasm_bindgen(typescript_custom_section)]
const KNOT_LIMITS_TS: &str = r#"
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
    let KnotLimitsOptions {
        curve,
        surface,
        p,
        up,
        q,
        vq,
        samples: n,
    } = KnotLimitsOptions::read(&o)?;
    // a curve comes with its `p` (the reader of `p` refuses a curve without one)
    if let (Some(c), Some(p)) = (curve, p) {
        return with_points!(&c.control_points, pts => {
            let curve = build_curve(&c, pts.clone(), Some((p, c.knots.get(p).copied().unwrap_or(0.0))))?;
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
    // without a curve, the reader of `surface` refused a missing one: not reached
    let Some(s) = surface else {
        return Err(err_kind(
            ErrorKind::Missing,
            "surface",
            "give a curve or a surface",
        ));
    };
    let (mu, mv) = (p.map(|i| (i, up)), q.map(|i| (i, vq)));
    sample::check_eval_count("samples", n.saturating_mul(4)).map_err(core_err)?;
    with_points!(&s.control_points.2, pts => {
        let fam = build_surface(&s, pts.clone(), mu, mv)?;
        let mut out = Out::new().num("dim", pts[0].dim() as f64);
        for (dir, name, order, knots) in [(Var::U, "u", s.order_v, &s.knots_v), (Var::V, "v", s.order_u, &s.knots_u)] {
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
