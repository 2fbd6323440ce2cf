//! `b2Curve`, `b2Surface` and `b2Basis`: the Kuklišová B2-splines (seed 000, `curves.md` §2).
//!
//! * `b2Curve({ points, a, tension, autoTension, autoTensionScale, knots, K, c2, construction,
//!   at | samples, derivatives })` → `{ dim, params, points, d1?, d2?, domain, knots, controlPoints, joints,
//!   evenVertices, tension }` plus the extras `dataKnots` (u_{−1}..u_{n+2}) and `jointParams` (where the
//!   joints sit: u′_{2i}, i = 1..n), and for steppers the weights of the construction: `jointWeights` (3 per
//!   joint R_i on W_{i−1}, W_i, W_{i+1}), `evenWeights` (4 per even vertex C_{2i} on W_{i−1}..W_{i+2}),
//!   `eq5Weights` (3 per joint on C_{2i−2}, C_{2i−1}, C_{2i}: the eq. (5) weights that gave the odd
//!   vertices) and `jointResiduals` (|L(u′_{2i}) − R_i|, i = 1..n). `eq5: "printed"` builds the odd
//!   vertices with eq. (5)'s last weight as printed (b/(b+c)·c/(b+c+d)) instead of the corrected
//!   b²/((b+c)(b+c+d)) (`"corrected"`, the default): the paper's typo, live — the curve then misses its
//!   joints where neighbouring spans differ (`jointResiduals`). `points` = W_{−1}..W_{n+2} (n ≥ 2), 2D or 3D. With `curvature: true`
//!   also `curvature` (κ per parameter, signed in 2D) and in 2D `normals` (unit left normals, flat).
//! * `b2Surface({ grid, a, tensionU, tensionV, knotsU, knotsV, c2, atUV | samplesU/samplesV, derivatives })`
//!   → `{ dim, uv, points, du?, dv?, mesh?, domain: [u0, u1, v0, v1], dataKnotsU, dataKnotsV }` (`mesh: true`
//!   adds render buffers, see `api::mesh`). `knotsU`/`knotsV`:
//!   arrays u_{−1}..u_{m+2} / v_{−1}..v_{n+2}, `"uniform"` (the default: u_j = j − 1) or `"chord"` (Δ_i = the
//!   mean chord between neighbouring grid lines; the paper gives no rule for surfaces).
//! * `b2Basis({ points? | knots, a, tension, autoTension, K, c2, construction, at | samples, derivatives })`
//!   → `{ count, params, values, d1?, d2?, domain, dataKnots }`: the n + 4 blending functions
//!   L_{−1}..L_{n+2} at each parameter, row after row (`values[r * count + j + 1]` = L_j(params\[r\])). With
//!   `points` the knots (and automatic tension) come from them exactly as in `b2Curve`; without, `knots`
//!   must be an array u_{−1}..u_{n+2} or `"uniform"` with `count` (= n + 4).

use super::readers::{read_b2_options, read_knot_choice, read_tension};
use super::{api_options, core_err, err_kind, ApiResult, Opts, Out, Pts};
#[cfg(feature = "api-b2")]
use crate::b2spline;
use crate::b2spline::{
    resolve_tension, uniform_knots, AutoTension, B2Curve, B2Scheme, B2Surface,
    B2SurfaceOptions as CoreSurfaceOptions, Eq5, KnotChoice, SurfaceKnots, Tension,
    DEFAULT_TENSION,
};
use crate::error::ErrorKind;
use crate::point::Point;
use crate::sample::{Curve, Surface, MAX_EVAL_POINTS, MAX_INPUT_POINTS};
use wasm_bindgen::prelude::*;

/// The most basis functions `b2Basis` evaluates (it builds a dense (2n+1) × (n+4) matrix).
const MAX_BASIS: usize = 1000;

fn curve_out<P: Point>(c: &B2Curve<P>, o: &Opts) -> ApiResult<JsValue> {
    let order = o.derivatives(2)?;
    let params = o.curve_params(c.domain())?;
    let (d0, d1) = c.domain();
    let out = super::curve_result_curvature(c, &params, order, o)?;
    let s = c.scheme();
    Ok(out
        .f64s("jointWeights", s.joint_weights_all().as_flattened())
        .f64s("evenWeights", s.even_weights().as_flattened())
        .f64s("eq5Weights", s.eq5_weights_all().as_flattened())
        .f64s("jointResiduals", &c.joint_residuals())
        .f64s("domain", &[d0, d1])
        .f64s("knots", c.knots())
        .pts("controlPoints", c.control_points())
        .pts("joints", c.joints())
        .pts("evenVertices", &c.even_vertices())
        .f64s("tension", c.tension())
        .f64s("dataKnots", c.data_knots())
        .f64s("jointParams", &c.scheme().joint_params())
        .build())
}

#[cfg(feature = "api-b2")]
#[wasm_bindgen(typescript_custom_section)]
const B2_CURVE_TS: &str = r#"
// B2-splines

export interface B2CurveResult extends CurveResult {
  domain: Float64Array;
  knots: Float64Array;
  controlPoints: Float64Array;
  joints: Float64Array;
  evenVertices: Float64Array;
  tension: Float64Array;
  dataKnots: Float64Array;
  jointParams: Float64Array;
  /** 3 per joint R_i, on W_{i−1}, W_i, W_{i+1}. */
  jointWeights: Float64Array;
  /** 4 per even vertex C_{2i}, on W_{i−1}..W_{i+2}. */
  evenWeights: Float64Array;
  /** 3 per joint: the eq. (5) weights on C_{2i−2}, C_{2i−1}, C_{2i} that gave the odd vertices. */
  eq5Weights: Float64Array;
  /** |L^a(u′_{2i}) − R_i|, i = 1..n (rounding-level unless eq5: "printed"). */
  jointResiduals: Float64Array;
  curvature?: Float64Array;
  normals?: Float64Array;
}
"#;

/// `eq5`: `"corrected"` (also when absent) or `"printed"`.
#[cfg(feature = "api-b2")]
fn read_eq5(o: &Opts, key: &'static str) -> ApiResult<Eq5> {
    let choices = [("corrected", Eq5::Corrected), ("printed", Eq5::AsPrinted)];
    o.choice(key, choices, Eq5::Corrected)
}

#[cfg(feature = "api-b2")]
api_options! {
    /// Options of `b2Curve`: the curve L^a of the points W_{−1}..W_{n+2}.
    pub struct B2CurveOptions extends "B2Options, CurveSampling, FlatDim" |o| {
        /// W_{−1}..W_{n+2} (n ≥ 2).
        points: Pts = "points", req "Points" => |k| o.points(k, 0)?;
        /// The shared B2 options (construction, K, a, tension, autoTension…, knots, c2).
        options: b2spline::B2Options = "construction", ext "B2Options" => |_k| read_b2_options(o)?;
        /// The last weight of eq. (5) for the odd vertices: "corrected" (default) b²/((b+c)(b+c+d)), or
        /// "printed" b·c/((b+c)(b+c+d)) as in the paper (the curve then misses its joints where the spans differ).
        eq5: Eq5 = "eq5", opt "'corrected' | 'printed'" => |k| read_eq5(o, k)?;
        /// Adds `curvature` (and in 2D `normals`); read with the samples, after the curve is built.
        curvature: () = "curvature", opt "boolean" => |_k| ();
    }
}

/// The B2-spline curve L^a.
///
/// `b2Curve(options)`: see the module docs and `../shared/spec/api.md`.
#[cfg(feature = "api-b2")]
#[wasm_bindgen(js_name = b2Curve, unchecked_return_type = "B2CurveResult")]
pub fn b2_curve(
    #[wasm_bindgen(unchecked_param_type = "B2CurveOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let B2CurveOptions {
        points: pts,
        options: opts,
        eq5,
        ..
    } = B2CurveOptions::read(&o)?;
    match pts {
        Pts::D2(p) => curve_out(
            &B2Curve::new_with_eq5(&p, &opts, eq5).map_err(core_err)?,
            &o,
        ),
        Pts::D3(p) => curve_out(
            &B2Curve::new_with_eq5(&p, &opts, eq5).map_err(core_err)?,
            &o,
        ),
    }
}

fn surface_knots(o: &Opts, key: &str) -> ApiResult<SurfaceKnots> {
    if !o.has(key) {
        return Ok(SurfaceKnots::Uniform);
    }
    Ok(match read_knot_choice(o, key)? {
        KnotChoice::Chord => SurfaceKnots::Chord,
        KnotChoice::Uniform => SurfaceKnots::Uniform,
        KnotChoice::Explicit(k) => SurfaceKnots::Explicit(k),
    })
}

fn surface_out<P: Point>(s: &B2Surface<P>, o: &Opts) -> ApiResult<JsValue> {
    let dom = s.domain();
    Ok(super::mesh::surface_output(o, s)?
        .f64s("domain", &[dom.0 .0, dom.0 .1, dom.1 .0, dom.1 .1])
        .f64s("dataKnotsU", s.scheme_u().data_knots())
        .f64s("dataKnotsV", s.scheme_v().data_knots())
        .build())
}

#[wasm_bindgen(typescript_custom_section)]
const B2_SURFACE_TS: &str = r#"
export interface B2SurfaceResult extends SurfaceResult {
  domain: Float64Array;
  dataKnotsU: Float64Array;
  dataKnotsV: Float64Array;
}
"#;

api_options! {
    /// Options of `b2Surface`: the tensor-product B2-spline surface of a grid W_ij.
    pub struct B2SurfaceOptions extends "SurfaceSampling, GridDim" |o| {
        /// W_ij, i = −1..m+2, j = −1..n+2 (at least 6 × 6).
        grid: (usize, usize, Pts) = "grid", req "Grid" => |k| {
            let (rows, cols, pts) = o.grid(k, 6, 6)?;
            if rows.saturating_mul(cols) > MAX_INPUT_POINTS {
                return Err(err_kind(
                    ErrorKind::TooMany,
                    k,
                    format!("at most {MAX_INPUT_POINTS} points, got {rows} × {cols}"),
                ));
            }
            (rows, cols, pts)
        };
        /// The family parameter (default 0).
        a: f64 = "a", opt "number" => |k| o.f64_or(k, 0.0)?;
        /// The tension in u (default 1/6).
        tension_u: Tension = "tensionU", opt "Tension" => |k| read_tension(o, k, DEFAULT_TENSION)?;
        /// The tension in v (default 1/6).
        tension_v: Tension = "tensionV", opt "Tension" => |k| read_tension(o, k, DEFAULT_TENSION)?;
        /// "uniform" (default), "chord" or u_{−1}..u_{m+2}.
        knots_u: SurfaceKnots = "knotsU", opt "'chord' | 'uniform' | Numbers" => |k| surface_knots(o, k)?;
        /// "uniform" (default), "chord" or v_{−1}..v_{n+2}.
        knots_v: SurfaceKnots = "knotsV", opt "'chord' | 'uniform' | Numbers" => |k| surface_knots(o, k)?;
        /// 1 (default, as printed) or 2; any number ≥ 0.
        c2: f64 = "c2", opt "number" => |k| o.f64_or(k, 1.0)?;
    }
}

/// The tensor-product B2-spline surface.
///
/// `b2Surface(options)`: the tensor-product B2-spline surface (section 6).
#[wasm_bindgen(js_name = b2Surface, unchecked_return_type = "B2SurfaceResult")]
pub fn b2_surface(
    #[wasm_bindgen(unchecked_param_type = "B2SurfaceOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    for key in ["tension", "autoTension"] {
        if o.has(key) {
            return Err(err_kind(
                ErrorKind::Invalid,
                key,
                "b2Surface takes tensionU and tensionV (numbers or arrays; no automatic tension)",
            ));
        }
    }
    let B2SurfaceOptions {
        grid: (rows, cols, pts),
        a,
        tension_u,
        tension_v,
        knots_u,
        knots_v,
        c2,
    } = B2SurfaceOptions::read(&o)?;
    let opts = CoreSurfaceOptions {
        a,
        tension_u,
        tension_v,
        knots_u,
        knots_v,
        c2,
    };
    match pts {
        Pts::D2(p) => surface_out(
            &B2Surface::new(rows, cols, &p, &opts).map_err(core_err)?,
            &o,
        ),
        Pts::D3(p) => surface_out(
            &B2Surface::new(rows, cols, &p, &opts).map_err(core_err)?,
            &o,
        ),
    }
}

fn basis_out(scheme: &B2Scheme, o: &Opts) -> ApiResult<JsValue> {
    let order = o.derivatives(2)?;
    let params = o.curve_params(scheme.domain())?;
    let count = scheme.n() + 4;
    if count > MAX_BASIS {
        return Err(err_kind(
            ErrorKind::TooMany,
            "knots",
            format!("at most {MAX_BASIS} basis functions (knots/points), got {count}"),
        ));
    }
    if params.len().saturating_mul(count) > MAX_EVAL_POINTS {
        return Err(err_kind(
            ErrorKind::TooMany,
            "samples",
            format!("parameters × basis functions must be at most {MAX_EVAL_POINTS}"),
        ));
    }
    let cmat = scheme.control_matrix();
    let mut row = [Vec::new(), Vec::new(), Vec::new()];
    let mut vals: [Vec<f64>; 3] = Default::default();
    for &u in &params {
        scheme.basis_with(&cmat, u, order, &mut row);
        for k in 0..=order {
            vals[k].extend_from_slice(&row[k]);
        }
    }
    let (d0, d1) = scheme.domain();
    let mut out = Out::new()
        .num("count", count as f64)
        .f64s("params", &params)
        .f64s("values", &vals[0])
        .f64s("domain", &[d0, d1])
        .f64s("dataKnots", scheme.data_knots())
        .f64s("jointParams", &scheme.joint_params());
    if order >= 1 {
        out = out.f64s("d1", &vals[1]);
    }
    if order >= 2 {
        out = out.f64s("d2", &vals[2]);
    }
    Ok(out.build())
}

#[cfg(feature = "api-b2")]
#[wasm_bindgen(typescript_custom_section)]
const B2_BASIS_TS: &str = r#"
export interface B2BasisResult extends BasisResult {
  domain: Float64Array;
  dataKnots: Float64Array;
  jointParams: Float64Array;
}
"#;

#[cfg(feature = "api-b2")]
api_options! {
    /// Options of `b2Basis`: the blending functions of a B2-spline, from data points or from knots.
    pub struct B2BasisOptions extends "B2Options, CurveSampling, FlatDim" |o| {
        /// The shared B2 options (construction, K, a, tension, autoTension…, knots, c2).
        options: b2spline::B2Options = "construction", ext "B2Options" => |_k| read_b2_options(o)?;
        /// Data points (the knots and automatic tension come from them), or give `knots`.
        points: Option<Pts> = "points", opt "Points" => |k| if o.has(k) { Some(o.points(k, 0)?) } else { None };
        /// n + 4 (with knots: "uniform"); read only then.
        count: () = "count", opt "number" => |_k| ();
    }
}

/// The blending functions L_{−1}..L_{n+2}.
///
/// `b2Basis(options)`: the blending functions L_{−1}..L_{n+2} of a B2-spline (see the module docs).
#[cfg(feature = "api-b2")]
#[wasm_bindgen(js_name = b2Basis, unchecked_return_type = "B2BasisResult")]
pub fn b2_basis(
    #[wasm_bindgen(unchecked_param_type = "B2BasisOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let B2BasisOptions {
        options: opts,
        points,
        ..
    } = B2BasisOptions::read(&o)?;
    if let Some(pts) = points {
        let scheme = match pts {
            Pts::D2(p) => B2Curve::new(&p, &opts).map_err(core_err)?.scheme().clone(),
            Pts::D3(p) => B2Curve::new(&p, &opts).map_err(core_err)?.scheme().clone(),
        };
        return basis_out(&scheme, &o);
    }
    let knots = match opts.knots {
        KnotChoice::Explicit(k) => k,
        KnotChoice::Uniform => {
            let count = o.usize_or("count", 0, MAX_INPUT_POINTS)?;
            if count < 6 {
                return Err(err_kind(
                    ErrorKind::OutOfRange,
                    "count",
                    format!("with knots: \"uniform\" give count = n + 4 ≥ 6, got {count}"),
                ));
            }
            uniform_knots(count)
        }
        KnotChoice::Chord => {
            return Err(err_kind(
                ErrorKind::Invalid,
                "knots",
                "without points, give knots as an array u₋₁..uₙ₊₂ or \"uniform\" with count",
            ))
        }
    };
    if knots.len() < 6 {
        return Err(err_kind(
            ErrorKind::TooFew,
            "knots",
            format!(
                "need at least 6 knots u₋₁..uₙ₊₂ (n ≥ 2), got {}",
                knots.len()
            ),
        ));
    }
    if knots.len() > MAX_INPUT_POINTS {
        return Err(err_kind(
            ErrorKind::TooMany,
            "knots",
            format!("at most {MAX_INPUT_POINTS} knots, got {}", knots.len()),
        ));
    }
    if opts.auto_tension != AutoTension::Off {
        return Err(err_kind(
            ErrorKind::SizeMismatch,
            "autoTension",
            "automatic tension needs points",
        ));
    }
    let n = knots.len() - 4;
    // the same resolver as b2Curve: a scalar, p_0..p_n or the paper's p_1..p_n-1
    let tension = resolve_tension(&opts.tension, n).map_err(core_err)?;
    let scheme = B2Scheme::new(knots, tension, opts.a, opts.k, opts.c2, opts.construction)
        .map_err(core_err)?;
    basis_out(&scheme, &o)
}
