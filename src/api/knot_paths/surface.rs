//! The surface exports of knot modification: knotModifiedSurface, knotEnvelope, knotPaths.

use super::*;

api_options! {
    /// The moved knots of a surface (`knotModifiedSurface`, `knotEnvelope`, `knotPaths`): knot p of `knotsU`
    /// moved to up and/or knot q of `knotsV` to vq.
    pub struct MovedKnots |o, need_value: bool, none_message: Option<&'static str>| {
        /// The index of the knot of `knotsU` that moves.
        p: Option<usize> = "p", opt "number" => |k| moved_index(o, k, "up", need_value)?;
        /// Its new value (required with `p` by `knotModifiedSurface`; the envelope and the paths do not depend
        /// on it).
        up: f64 = "up", opt "number" => |k| moved_value(o, k, "p", p, need_value)?;
        /// The index of the knot of `knotsV` that moves.
        q: Option<usize> = "q", opt "number" => |k| moved_index(o, k, "vq", need_value)?;
        /// Its new value (as `up`).
        vq: f64 = "vq", opt "number" => |k| {
            let vq = moved_value(o, k, "q", q, need_value)?;
            // `knotEnvelope` and `knotPaths` need `p` and/or `q`
            if let Some(message) = none_message {
                some_knot_moves(p, q, message)?;
            }
            vq
        };
    }
}

api_options! {
    /// The options of `knotModifiedSurface`: knot p of `knotsU` moved to up and/or q of `knotsV` to vq
    /// (where: `atUV` or `samplesU`/`samplesV`).
    pub struct KnotModifiedSurfaceOptions extends "SurfaceSampling, MovedKnots" |o| {
        /// The surface.
        surface: Box<KnotSurface> = "surface", req "KnotSurface" => |k| read_surface(o, k)?;
        /// The moved knots (each value required with its index).
        moved: MovedKnots = "p", ext "MovedKnots" => |_k| MovedKnots::read(o, true, None)?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const KNOT_MODIFIED_SURFACE_TS: &str = r#"
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
    let KnotModifiedSurfaceOptions {
        surface: s,
        moved: MovedKnots { p, up, q, vq },
    } = KnotModifiedSurfaceOptions::read(&o)?;
    let (mu, mv) = (p.map(|i| (i, up)), q.map(|i| (i, vq)));
    with_points!(&s.control_points.2, p => {
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

api_options! {
    /// The options of `knotEnvelope`: eq. (6) with `p` alone, its v-analogue with `q` alone, eq. (8) with both
    /// (where: `atUV` or `samplesU`/`samplesV`; the default grid covers the neighbours of the moved knots).
    pub struct KnotEnvelopeOptions extends "SurfaceSampling, MovedKnots" |o| {
        /// The surface.
        surface: Box<KnotSurface> = "surface", req "KnotSurface" => |k| read_surface(o, k)?;
        /// The moved knots (`p` and/or `q` required; the envelope does not depend on their values).
        moved: MovedKnots = "p", ext "MovedKnots" => |_k| MovedKnots::read(o, false,
            Some("give the index p (eq. (6)) and/or q (eq. (8)) of the knot that moves"))?;
    }
}

/// The envelope of the family as the knot moves.
///
/// `knotEnvelope({ surface, p, q, atUV | samplesU/samplesV, derivatives, mesh })`.
#[wasm_bindgen(js_name = knotEnvelope, unchecked_return_type = "SurfaceResult & { orderU: number; orderV: number }")]
pub fn knot_envelope(
    #[wasm_bindgen(unchecked_param_type = "KnotEnvelopeOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let KnotEnvelopeOptions {
        surface: s,
        moved: MovedKnots { p, up, q, vq },
    } = KnotEnvelopeOptions::read(&o)?;
    let (mu, mv) = (p.map(|i| (i, up)), q.map(|i| (i, vq)));
    with_points!(&s.control_points.2, p => {
        let fam = build_surface(&s, p.clone(), mu, mv)?;
        let env = fam.envelope().ok_or_else(|| err_kind(ErrorKind::Invalid, "p", "no moved knot"))?;
        let (ou, ov) = env.orders();
        Ok(surface_output(&o, &env)?.num("orderU", ou as f64).num("orderV", ov as f64).build())
    })
}

api_options! {
    /// The options of `knotPaths` (the values of the moved knots: `KnotPathsRange`).
    pub struct KnotPathsOptions extends "KnotPathsRange, MovedKnots" |o| {
        /// The surface.
        surface: Box<KnotSurface> = "surface", req "KnotSurface" => |k| read_surface(o, k)?;
        /// The moved knots (`p` and/or `q` required; the paths do not depend on their values).
        moved: MovedKnots = "p", ext "MovedKnots"
            => |_k| MovedKnots::read(o, false, Some("give the index p and/or q of the knot that moves"))?;
        /// (u, v) pairs of the surface points to follow.
        points: Vec<Vec<f64>> = "points", req "ReadonlyArray<readonly [number, number] | readonly number[]>"
            => |k| uv_pairs(o, k)?;
    }
}

/// The (u, v) pairs of the points to follow: finite pairs, at most `MAX_INPUT_POINTS`.
fn uv_pairs(o: &Opts, key: &str) -> ApiResult<Vec<Vec<f64>>> {
    let uv: Vec<Vec<f64>> = o.req(key)?;
    if uv.len() > sample::MAX_INPUT_POINTS {
        return Err(err_kind(
            ErrorKind::TooMany,
            key,
            format!("at most {} points", sample::MAX_INPUT_POINTS),
        ));
    }
    for (i, w) in uv.iter().enumerate() {
        if w.len() != 2 || !w[0].is_finite() || !w[1].is_finite() {
            return Err(err_kind(
                ErrorKind::WrongType,
                &format!("{key}[{i}]"),
                "expected a parameter pair [u, v] of finite numbers",
            ));
        }
    }
    Ok(uv)
}

api_options! {
    /// The values the moved knots of `knotPaths` take, read once the surface is built. With `p` (or `q`) alone:
    /// numbers, from the knot's lower neighbour to its upper one by default. With both (path-surfaces): pairs
    /// `[u_p, v_q]` (a number applies to both), `samples` a count or `[nu, nv]`.
    pub struct KnotPathsRange |o, lo: (f64, f64), hi: (f64, f64), both: bool| {
        /// The first value(s) of the moved knot(s).
        from: (f64, f64) = "from", opt "number | readonly [number, number]" => |k| path_end(o, k, lo, both)?;
        /// The last value(s).
        to: (f64, f64) = "to", opt "number | readonly [number, number]" => |k| path_end(o, k, hi, both)?;
        /// How many values (default 200; with both knots 40 × 40).
        samples: (usize, usize) = "samples", opt "number | readonly [number, number]"
            => |k| read_samples(o, k, if both { 40 } else { 200 }, both)?;
    }
}

/// `from`/`to` of `knotPaths`: a `[u_p, v_q]` pair (or one number for both) when both knots move, else a number.
fn path_end(o: &Opts, key: &str, default: (f64, f64), both: bool) -> ApiResult<(f64, f64)> {
    if both {
        return read_range_pair(o, key, default);
    }
    let x = o.f64_or(key, default.0)?;
    Ok((x, x))
}

#[wasm_bindgen(typescript_custom_section)]
const KNOT_PATHS_TS: &str = r#"
/** A path (flat points) that also carries `dim` and `params` (or `uv` for path-surfaces). */
export type KnotPath = Float64Array & { dim: number; params?: Float64Array; uv?: Float64Array };

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
    let KnotPathsOptions {
        surface: s,
        moved: MovedKnots { p, q, .. },
        points: uv,
    } = KnotPathsOptions::read(&o)?;
    with_points!(&s.control_points.2, pts => {
        // the moved knots start at their given values (index validity is checked here)
        let mu0 = p.map(|i| (i, s.knots_u.get(i).copied().unwrap_or(0.0)));
        let mv0 = q.map(|i| (i, s.knots_v.get(i).copied().unwrap_or(0.0)));
        let fam = build_surface(&s, pts.clone(), mu0, mv0)?;
        let dim = pts.first().map_or(2, |q| q.dim());
        let nu_ = fam.line_u().neighbours();
        let nv_ = fam.line_v().neighbours();
        let paths = Array::new();
        let mut out = Out::new().num("dim", dim as f64);
        let (lo, hi, both) = match (nu_, nv_) {
            (Some((a, b)), Some((c, d))) => ((a, c), (b, d), true),
            _ => {
                let (a, b) = nu_.or(nv_).unwrap_or((0.0, 1.0));
                ((a, a), (b, b), false)
            }
        };
        let KnotPathsRange { from, to, samples } = KnotPathsRange::read(&o, lo, hi, both)?;
        if both {
            let ((f0, f1), (t0, t1), (n1, n2)) = (from, to, samples);
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
        } else {
            let n = samples.0;
            sample::check_eval_count("samples", uv.len().saturating_mul(n)).map_err(core_err)?;
            let xs = sample::uniform_params(from.0, to.0, n);
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
        Ok(out.set("paths", paths).build())
    })
}
