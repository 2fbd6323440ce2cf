//! The surface exports of knot modification: knotModifiedSurface, knotEnvelope, knotPaths.

use super::*;

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
