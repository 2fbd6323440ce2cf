//! Seed 003 exports: quasi-cubic trigonometric B-splines, the blended interpolation spline, surfaces.
//!
//! Contract (`../shared/spec/api.md`), with the options this module adds (all optional):
//! * `quasiCubicBasis({ alpha, at | samples, derivatives })` → `{ params, values, d1?, d2?, d3? }`: four values
//!   B_0..B_3 per t (row after row); `derivatives` may be 0..3 (3 adds `d3`). `alpha` default 1, any finite
//!   value with |α| ≤ 1e6 (the curves keep [−3, 3]; §4.5 probes the basis at α = −3.01 and 1.01).
//! * `quasiCubicCurve({ points, alpha, closed, at | samples, derivatives })` → curve result +
//!   `{ domain, segments }`. `points` = b_0..b_{n+2}, u ∈ [0, n]. `alpha` ∈ [−3, 3], default 1.
//!   `closed: true` (default false): a periodic curve of N ≥ 4 points, N segments, u ∈ [0, N] (segment i
//!   uses b_i..b_{i+3} mod N; needed for full circles and ellipses).
//! * `quasiCubicInterpolation({ points, beta, k, alpha, curvature, at | samples, derivatives })` → curve
//!   result + `{ beta, domain, circleCurvature, curvature? }`. `points` = b_{−1}..b_{n+1}; curve(u = j) = b_j.
//!   `beta`: omitted (all 1), n+1 numbers ≥ 0, or `"curvature"`. `k` default 3 (2..=10; k = 2 is only C¹).
//!   `alpha` (default 3) selects Remark 2's blend with the α-spline (interpolates only where β* = 0).
//!   `circleCurvature` = K_j of the circle through b_{j−1}, b_j, b_{j+1} (j = 0..n; signed in 2D, positive
//!   for a left turn; unsigned in 3D). `curvature: true` adds `curvature`, the curve's curvature at
//!   each parameter (signed in 2D).
//! * `quasiCubicSurface({ grid, alpha, periodicU, periodicV, atUV | samplesU/samplesV, derivatives, mesh })`
//!   → surface result (+ `mesh` render buffers when `mesh: true`, see `api::mesh`) + `{ domain }`.
//!   `grid[i][j]` = b_ij, (m+3) × (n+3), domain [0, m] × [0, n]; a periodic direction has N ≥ 4 rows
//!   (or columns) that wrap, and N patches. `alpha` default 1.
//! * `quasiCubicBlendedSurface({ grid, beta, k, alpha, atUV | samplesU/samplesV, derivatives, mesh })` →
//!   surface result + `{ beta, domain }`: the blended interpolation surface (seed 003 Figs. 13, 16, 17;
//!   reading documented in `quasi_cubic::surface`). `grid` (m+3) × (n+3) = b_{−1..m+1, −1..n+1},
//!   interpolating `grid[i+1][j+1]` at (i, j); `beta[i][j]` (m+1) × (n+1) numbers ≥ 0 (default all 1);
//!   `alpha` default 3 (other values: Remark 2's blended surfaces).
//! * `quasiCubicPreset({ name })` → control data, ready to pass back:
//!   curves `"ellipse" | "circle" | "parabola" | "sine"` → `{ name, kind: "curve", alpha, closed, points,
//!   condition }` (points as `number[][]`); surfaces `"sphere" | "cylinder" | "torus" | "bowl" | "wavy"`
//!   → `{ name, kind: "surface", alpha, grid, periodicU, periodicV, exact }` (`exact`: what is constant —
//!   e.g. `{ centre: [0,0,0], radius: 1 }` for the sphere). Optional sizes: `radius`, `a`, `b`, `height`,
//!   `major`, `minor`, `segments`, `m`, `n`.
//! * `quasiCubicShapeCheck({ shape, points, alpha, samples })` → `{ deviation, conditionResidual,
//!   segmentResiduals, alphaOk, condition, analytic, params }`: the largest distance of the curve (closed for ellipse/circle) from
//!   the analytic shape its control points define (`quasi_cubic::presets`), the residual of the shape's
//!   condition on the points (`segmentResiduals`: for the sine, the x and y residual of each segment as
//!   pairs; otherwise one value), and `analytic` (flat 2D points of the analytic shape, for an overlay).
//!   `samples` = samples per segment (default 200).

use super::mesh::surface_output;
use super::{
    api_options, core_err, curve_result_for, err_kind, with_points, ApiResult, Opts, Out, Pts,
};
use crate::error::ErrorKind;
use crate::quasi_cubic::bis::{circle_curvatures, circle_curvatures_signed, DEFAULT_ORDER};
use crate::quasi_cubic::presets::{self, check_shape, ExactShape, SurfaceNet};
use crate::quasi_cubic::{
    basis_derivs, check_alpha, Bis, BisSurface, QuasiCubicCurve, QuasiCubicSurface,
};
use crate::sample::{Curve, Surface, MAX_EVAL_POINTS};
use glam::{DVec2, DVec3};
use wasm_bindgen::prelude::*;

/// α of a curve or surface: in [−3, 3] (`check_alpha`), `default` when absent.
fn read_alpha(o: &Opts, key: &'static str, default: f64) -> ApiResult<f64> {
    let a = o.f64_or(key, default)?;
    check_alpha(key, a).map_err(core_err)?;
    Ok(a)
}

/// The basis alone accepts any finite α up to |α| ≤ 1e6 (not only the curves' [−3, 3]): `curves.md` §4.5
/// checks the tightness of the positivity interval at α = −3.01 and 1.01 (B_1(0) = −1/600 at −3.01).
fn basis_alpha(o: &Opts, key: &'static str) -> ApiResult<f64> {
    let a = o.f64_or(key, 1.0)?;
    if !a.is_finite() || a.abs() > 1e6 {
        return Err(err_kind(
            ErrorKind::OutOfRange,
            key,
            "expected a finite number with |α| ≤ 1e6",
        ));
    }
    Ok(a)
}

#[wasm_bindgen(typescript_custom_section)]
const QUASI_CUBIC_TS: &str = "\n// quasi-cubic\n";

api_options! {
    /// The quasi-cubic basis of `quasiCubicBasis` on t ∈ [0, 1] (where: `at` or `samples`).
    pub struct QuasiCubicBasisOptions extends "Omit<CurveSampling, 'derivatives'>" |o| {
        /// α (default 1; any finite |α| ≤ 1e6).
        alpha: f64 = "alpha", opt "number" => |k| basis_alpha(o, k)?;
        /// 0..3 (3 adds `d3`).
        derivatives: usize = "derivatives", opt "0 | 1 | 2 | 3" => |k| o.usize_or(k, 0, 3)?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const QUASI_CUBIC_BASIS_TS: &str = r#"
export interface QuasiCubicBasisResult {
  params: Float64Array;
  /** Four values B_0..B_3 per parameter. */
  values: Float64Array;
  d1?: Float64Array;
  d2?: Float64Array;
  d3?: Float64Array;
}
"#;

/// The quasi-cubic trigonometric basis B_0..B_3 on t ∈ [0, 1].
///
/// `quasiCubicBasis({ alpha, at | samples, derivatives })` → `{ params, values, d1?, d2?, d3? }`.
#[wasm_bindgen(js_name = quasiCubicBasis, unchecked_return_type = "QuasiCubicBasisResult")]
pub fn quasi_cubic_basis(
    #[wasm_bindgen(unchecked_param_type = "QuasiCubicBasisOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let QuasiCubicBasisOptions {
        alpha: a,
        derivatives: order,
    } = QuasiCubicBasisOptions::read(&o)?;
    let at = o.curve_params((0.0, 1.0))?;
    if at.len().saturating_mul(4) > MAX_EVAL_POINTS {
        return Err(err_kind(
            ErrorKind::TooMany,
            "at",
            "parameters × 4 basis functions exceeds 1,000,000 values",
        ));
    }
    let mut rows: [Vec<f64>; 4] = Default::default();
    let mut b = [[0.0; 4]; 4];
    for &t in &at {
        basis_derivs(a, t, order, &mut b);
        for k in 0..=order {
            rows[k].extend_from_slice(&b[k]);
        }
    }
    let mut out = Out::new().f64s("params", &at).f64s("values", &rows[0]);
    for (k, name) in [(1, "d1"), (2, "d2"), (3, "d3")] {
        if order >= k {
            out = out.f64s(name, &rows[k]);
        }
    }
    Ok(out.build())
}

api_options! {
    /// The quasi-cubic trigonometric B-spline curve of `quasiCubicCurve` (where: `at` or `samples`).
    pub struct QuasiCubicCurveOptions extends "CurveSampling, FlatDim" |o| {
        /// α ∈ [−3, 3] (default 1).
        alpha: f64 = "alpha", opt "number" => |k| read_alpha(o, k, 1.0)?;
        /// Periodic curve of N ≥ 4 points (default false).
        closed: bool = "closed", opt "boolean" => |k| o.bool_or(k, false)?;
        /// Control points b_0..b_{n+2} (at least 4).
        points: Pts = "points", req "Points" => |k| o.points(k, 0)?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const QUASI_CUBIC_CURVE_TS: &str = r#"
export interface QuasiCubicCurveResult extends CurveResult {
  domain: Float64Array;
  segments: number;
}
"#;

/// The quasi-cubic trigonometric B-spline curve.
///
/// `quasiCubicCurve({ points, alpha, closed, at | samples, derivatives })` → curve result + `{ domain, segments }`.
#[wasm_bindgen(js_name = quasiCubicCurve, unchecked_return_type = "QuasiCubicCurveResult")]
pub fn quasi_cubic_curve(
    #[wasm_bindgen(unchecked_param_type = "QuasiCubicCurveOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let QuasiCubicCurveOptions {
        alpha: a,
        closed,
        points: pts,
    } = QuasiCubicCurveOptions::read(&o)?;
    let order = o.derivatives(2)?;
    with_points!(pts, p => {
        let curve = if closed {
            QuasiCubicCurve::closed(a, p)
        } else {
            QuasiCubicCurve::new(a, p)
        }
        .map_err(core_err)?;
        let params = o.curve_params(curve.domain())?;
        let (d0, d1) = curve.domain();
        Ok(curve_result_for(&o, &curve, &params, order)
            .f64s("domain", &[d0, d1])
            .num("segments", curve.segments() as f64)
            .build())
    })
}

/// Most evaluation points of one `quasiCubicBlendedSurface` call.
const MAX_BLENDED_SURFACE_POINTS: usize = 200_000;

/// Most parameters of one `quasiCubicInterpolation` call with `curvature: true`.
const MAX_CURVATURE_PARAMS: usize = 200_000;

/// `beta` of `quasiCubicInterpolation`: β* matched to the circle curvatures, or numbers (`None`: all 1).
pub enum InterpolationBeta {
    /// `"curvature"`: β* from the circle curvatures (`Bis::curvature_matched`).
    Curvature,
    /// n + 1 numbers ≥ 0, or absent (all 1).
    Values(Option<Vec<f64>>),
}

/// `beta`: the string `"curvature"`, or n + 1 numbers (a `Float64Array` read in one copy, or plain numbers).
fn interpolation_beta(o: &Opts, key: &'static str) -> ApiResult<InterpolationBeta> {
    match o.raw(key).as_string() {
        Some(s) if s == "curvature" => Ok(InterpolationBeta::Curvature),
        Some(s) => Err(err_kind(
            ErrorKind::WrongType,
            key,
            format!("expected an array of n + 1 numbers or \"curvature\", got \"{s}\""),
        )),
        None => Ok(InterpolationBeta::Values(o.f64s(key)?)),
    }
}

api_options! {
    /// The blended interpolation spline of `quasiCubicInterpolation` (where: `at` or `samples`).
    pub struct QuasiCubicInterpolationOptions extends "CurveSampling, FlatDim" |o| {
        /// b_{−1}..b_{n+1}.
        points: Pts = "points", req "Points" => |k| o.points(k, 0)?;
        /// The allocated function's k (2..10, default 3).
        k: usize = "k", opt "number" => |k| o.usize_or(k, DEFAULT_ORDER, 1000)?;
        /// Default 3 (other values: Remark 2's blend with the α-spline).
        alpha: f64 = "alpha", opt "number" => |k| read_alpha(o, k, 3.0)?;
        /// Adds `curvature` at each parameter.
        curvature: bool = "curvature", opt "boolean" => |k| o.bool_or(k, false)?;
        /// n + 1 numbers ≥ 0, or "curvature" (default all 1).
        beta: InterpolationBeta = "beta", opt "Numbers | 'curvature'" => |k| interpolation_beta(o, k)?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const QUASI_CUBIC_INTERPOLATION_TS: &str = r#"
export interface QuasiCubicInterpolationResult extends CurveResult {
  beta: Float64Array;
  domain: Float64Array;
  circleCurvature: Float64Array;
  curvature?: Float64Array;
}
"#;

/// The blended interpolation spline (BIS).
///
/// `quasiCubicInterpolation({ points, beta, k, alpha, curvature, at | samples, derivatives })`.
#[wasm_bindgen(js_name = quasiCubicInterpolation, unchecked_return_type = "QuasiCubicInterpolationResult")]
pub fn quasi_cubic_interpolation(
    #[wasm_bindgen(unchecked_param_type = "QuasiCubicInterpolationOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let QuasiCubicInterpolationOptions {
        points: pts,
        k,
        alpha: a,
        curvature: want_curv,
        beta,
    } = QuasiCubicInterpolationOptions::read(&o)?;
    let order = o.derivatives(2)?;
    let (by_curvature, beta) = match beta {
        InterpolationBeta::Curvature => (true, None),
        InterpolationBeta::Values(b) => (false, b),
    };
    macro_rules! run {
        ($p:expr, $circle:expr) => {{
            let p = $p;
            let circle = $circle(&p);
            let bis = if by_curvature {
                Bis::curvature_matched(p, k)
            } else {
                Bis::new(p, beta, k)
            }
            .map_err(core_err)?;
            let bis = if a != 3.0 {
                bis.with_alpha(a).map_err(core_err)?
            } else {
                bis
            };
            let params = o.curve_params(bis.domain())?;
            if want_curv && params.len() > MAX_CURVATURE_PARAMS {
                // the curvature is a second evaluation pass (robustness bug 6: 1e6 samples took > 2 s)
                return Err(err_kind(ErrorKind::TooMany,
                    "curvature",
                    format!("at most {MAX_CURVATURE_PARAMS} parameters when the curvature is requested, got {}", params.len()),
                ));
            }
            let mut out = curve_result_for(&o, &bis, &params, order)
                .f64s("beta", bis.beta())
                .f64s("domain", &[0.0, bis.segments() as f64])
                .f64s("circleCurvature", &circle);
            if want_curv {
                out = out.f64s("curvature", &params.iter().map(|&u| bis.curvature(u)).collect::<Vec<_>>());
            }
            Ok(out.build())
        }};
    }
    match pts {
        Pts::D2(p) => run!(p, |q: &Vec<DVec2>| circle_curvatures_signed(q)),
        Pts::D3(p) => run!(p, |q: &Vec<DVec3>| circle_curvatures(q)),
    }
}

api_options! {
    /// The tensor-product quasi-cubic surface of `quasiCubicSurface` (where: `atUV` or `samplesU` × `samplesV`).
    pub struct QuasiCubicSurfaceOptions extends "SurfaceSampling, GridDim" |o| {
        /// α ∈ [−3, 3] (default 1).
        alpha: f64 = "alpha", opt "number" => |k| read_alpha(o, k, 1.0)?;
        /// Periodic in u (default false).
        periodic_u: bool = "periodicU", opt "boolean" => |k| o.bool_or(k, false)?;
        /// Periodic in v (default false).
        periodic_v: bool = "periodicV", opt "boolean" => |k| o.bool_or(k, false)?;
        /// (m + 3) × (n + 3) control points.
        grid: (usize, usize, Pts) = "grid", req "Grid" => |k| o.grid(k, 1, 1)?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const QUASI_CUBIC_SURFACE_TS: &str = r#"
export interface QuasiCubicSurfaceResult extends SurfaceResult {
  /** [u0, u1, v0, v1]. */
  domain: Float64Array;
}
"#;

/// The tensor-product quasi-cubic surface.
///
/// `quasiCubicSurface({ grid, alpha, periodicU, periodicV, atUV | samplesU/samplesV, derivatives, mesh })`.
#[wasm_bindgen(js_name = quasiCubicSurface, unchecked_return_type = "QuasiCubicSurfaceResult")]
pub fn quasi_cubic_surface(
    #[wasm_bindgen(unchecked_param_type = "QuasiCubicSurfaceOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let QuasiCubicSurfaceOptions {
        alpha: a,
        periodic_u,
        periodic_v,
        grid,
    } = QuasiCubicSurfaceOptions::read(&o)?;
    let (periodic, (rows, cols, pts)) = ((periodic_u, periodic_v), grid);
    with_points!(pts, p => {
        let s = QuasiCubicSurface::new(a, rows, cols, p, periodic).map_err(core_err)?;
        let ((u0, u1), (v0, v1)) = s.domain();
        Ok(surface_output(&o, &s)?.f64s("domain", &[u0, u1, v0, v1]).build())
    })
}

/// `beta` of `quasiCubicBlendedSurface`: (m + 1) rows of (n + 1) numbers for a grid of `rows` × `cols`,
/// flattened row after row (`None`: all 1).
fn blended_beta(
    o: &Opts,
    key: &'static str,
    rows: usize,
    cols: usize,
) -> ApiResult<Option<Vec<f64>>> {
    let Some(b) = o.opt::<Vec<Vec<f64>>>(key)? else {
        return Ok(None);
    };
    if rows >= 2 && b.len() != rows - 2 {
        return Err(err_kind(
            ErrorKind::SizeMismatch,
            key,
            format!("need (m+1) = {} rows of β*, got {}", rows - 2, b.len()),
        ));
    }
    if let Some(i) = b.iter().position(|r| cols >= 2 && r.len() != cols - 2) {
        return Err(err_kind(
            ErrorKind::SizeMismatch,
            &format!("{key}[{i}]"),
            format!(
                "need (n+1) = {} values, got {}",
                cols.saturating_sub(2),
                b[i].len()
            ),
        ));
    }
    Ok(Some(b.into_iter().flatten().collect()))
}

api_options! {
    /// The blended interpolation surface of `quasiCubicBlendedSurface` (where: `atUV` or `samplesU` × `samplesV`).
    pub struct QuasiCubicBlendedSurfaceOptions extends "SurfaceSampling, GridDim" |o| {
        /// Default 3 (other values: Remark 2's blended surfaces).
        alpha: f64 = "alpha", opt "number" => |k| read_alpha(o, k, 3.0)?;
        /// The allocated function's k (2..10, default 3).
        k: usize = "k", opt "number" => |k| o.usize_or(k, DEFAULT_ORDER, 1000)?;
        /// (m + 3) × (n + 3) = b_{−1..m+1, −1..n+1}.
        grid: (usize, usize, Pts) = "grid", req "Grid" => |k| o.grid(k, 1, 1)?;
        /// (m + 1) × (n + 1) numbers ≥ 0 (default all 1).
        beta: Option<Vec<f64>> = "beta", opt "ReadonlyArray<Numbers>" => |k| blended_beta(o, k, grid.0, grid.1)?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const QUASI_CUBIC_BLENDED_SURFACE_TS: &str = r#"
export interface QuasiCubicBlendedSurfaceResult extends SurfaceResult {
  beta: Float64Array;
  domain: Float64Array;
}
"#;

/// The blended interpolation surface.
///
/// `quasiCubicBlendedSurface({ grid, beta, k, alpha, atUV | samplesU/samplesV, derivatives, mesh })`.
#[wasm_bindgen(js_name = quasiCubicBlendedSurface, unchecked_return_type = "QuasiCubicBlendedSurfaceResult")]
pub fn quasi_cubic_blended_surface(
    #[wasm_bindgen(unchecked_param_type = "QuasiCubicBlendedSurfaceOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let QuasiCubicBlendedSurfaceOptions {
        alpha: a,
        k,
        grid: (rows, cols, pts),
        beta,
    } = QuasiCubicBlendedSurfaceOptions::read(&o)?;
    with_points!(pts, p => {
        let s = BisSurface::new(rows, cols, p, beta, k).map_err(core_err)?;
        let s = if a != 3.0 { s.with_alpha(a).map_err(core_err)? } else { s };
        let ((u0, u1), (v0, v1)) = s.domain();
        // ~3 µs a point: more than 200,000 points would take over a second (robustness bug 10)
        let count = if o.has("atUV") {
            o.raw("atUV").dyn_ref::<js_sys::Array>().map_or(0, |a| a.length() as usize)
        } else {
            o.usize_or("samplesU", 40, usize::MAX)?.saturating_mul(o.usize_or("samplesV", 40, usize::MAX)?)
        };
        if count > MAX_BLENDED_SURFACE_POINTS {
            return Err(err_kind(ErrorKind::TooMany,
                if o.has("atUV") { "atUV" } else { "samplesU" },
                format!("at most {MAX_BLENDED_SURFACE_POINTS} evaluation points for a blended surface, got {count}"),
            ));
        }
        Ok(surface_output(&o, &s)?
            .f64s("beta", s.beta())
            .f64s("domain", &[u0, u1, v0, v1])
            .build())
    })
}

fn rows2(p: &[DVec2]) -> Vec<[f64; 2]> {
    p.iter().map(|q| [q.x, q.y]).collect()
}

fn grid_rows(net: &SurfaceNet) -> Vec<Vec<[f64; 3]>> {
    net.grid
        .chunks(net.cols)
        .map(|r| r.iter().map(|q| [q.x, q.y, q.z]).collect())
        .collect()
}

fn positive(o: &Opts, key: &str, default: f64) -> ApiResult<f64> {
    let x = o.f64_or(key, default)?;
    if x <= 0.0 || x > 1e12 {
        return Err(err_kind(
            ErrorKind::OutOfRange,
            key,
            "expected a positive size",
        ));
    }
    Ok(x)
}

/// `key` of the preset `name` (a positive size, `default` when absent) when `name` is one of `presets`, else
/// `default` (the key is not read).
fn size_of(o: &Opts, key: &str, name: &str, presets: &[&str], default: f64) -> ApiResult<f64> {
    if presets.contains(&name) {
        positive(o, key, default)
    } else {
        Ok(default)
    }
}

/// A count of the preset `name` (1..=`max`, `default` when absent), read only for the preset `only`.
fn count_of(
    o: &Opts,
    key: &str,
    name: &str,
    only: &str,
    default: usize,
    max: usize,
) -> ApiResult<usize> {
    if name == only {
        Ok(o.usize_or(key, default, max)?.max(1))
    } else {
        Ok(default)
    }
}

api_options! {
    /// The exact shape of `quasiCubicPreset` and its sizes (each read only for the shapes it applies to).
    pub struct QuasiCubicPresetOptions |o| {
        /// The shape.
        name: String = "name", req "QuasiCubicCurvePresetName | QuasiCubicSurfacePresetName" => |k| o.req(k)?;
        /// Ellipse half-axes (2, 1).
        a: f64 = "a", opt "number" => |k| size_of(o, k, &name, &["ellipse"], 2.0)?;
        /// Ellipse (1).
        b: f64 = "b", opt "number" => |k| size_of(o, k, &name, &["ellipse"], 1.0)?;
        /// Circle, sphere, cylinder (1).
        radius: f64 = "radius", opt "number" => |k| size_of(o, k, &name, &["circle", "sphere", "cylinder"], 1.0)?;
        /// Cylinder (2).
        height: f64 = "height", opt "number" => |k| size_of(o, k, &name, &["cylinder"], 2.0)?;
        /// Torus (1.5, 0.5).
        major: f64 = "major", opt "number" => |k| size_of(o, k, &name, &["torus"], 1.5)?;
        /// Torus (0.5).
        minor: f64 = "minor", opt "number" => |k| size_of(o, k, &name, &["torus"], 0.5)?;
        /// Sine (4).
        segments: usize = "segments", opt "number" => |k| count_of(o, k, &name, "sine", 4, 1000)?;
        /// Wavy (4, 4).
        m: usize = "m", opt "number" => |k| count_of(o, k, &name, "wavy", 4, 200)?;
        /// Wavy (4).
        n: usize = "n", opt "number" => |k| count_of(o, k, &name, "wavy", 4, 200)?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const QUASI_CUBIC_PRESET_TS: &str = r#"
export type QuasiCubicCurvePresetName = 'ellipse' | 'circle' | 'parabola' | 'sine';
export type QuasiCubicSurfacePresetName = 'sphere' | 'cylinder' | 'torus' | 'bowl' | 'wavy';
export interface QuasiCubicCurvePreset {
  name: string;
  kind: 'curve';
  alpha: number;
  closed: boolean;
  points: number[][];
  condition: string;
}
export interface QuasiCubicSurfacePreset {
  name: string;
  kind: 'surface';
  alpha: number;
  grid: number[][][];
  periodicU: boolean;
  periodicV: boolean;
  exact: { centre?: number[]; radius?: number; axis?: number[]; major?: number; minor?: number };
}
/** Control data of an exact shape, ready to pass back. */
export function quasiCubicPreset(options: QuasiCubicPresetOptions & { name: QuasiCubicCurvePresetName }): QuasiCubicCurvePreset;
export function quasiCubicPreset(options: QuasiCubicPresetOptions & { name: QuasiCubicSurfacePresetName }): QuasiCubicSurfacePreset;
export function quasiCubicPreset(options: QuasiCubicPresetOptions): QuasiCubicCurvePreset | QuasiCubicSurfacePreset;
"#;

/// `quasiCubicPreset({ name, … })` → control data of an exact shape (module docs).
#[wasm_bindgen(js_name = quasiCubicPreset, skip_typescript)]
pub fn quasi_cubic_preset(options: JsValue) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let QuasiCubicPresetOptions {
        name,
        a,
        b,
        radius,
        height,
        major,
        minor,
        segments: segs,
        m,
        n,
    } = QuasiCubicPresetOptions::read(&o)?;
    let curve = |shape: ExactShape, points: Vec<DVec2>| -> JsValue {
        Out::new()
            .ser("name", name.as_str())
            .ser("kind", "curve")
            .num("alpha", shape.alpha())
            .set("closed", shape.closed())
            .ser("points", &rows2(&points))
            .ser("condition", shape.condition())
            .build()
    };
    let surface = |net: SurfaceNet, exact: Out| -> JsValue {
        Out::new()
            .ser("name", name.as_str())
            .ser("kind", "surface")
            .num("alpha", net.alpha)
            .ser("grid", &grid_rows(&net))
            .set("periodicU", net.periodic.0)
            .set("periodicV", net.periodic.1)
            .set("exact", exact.build())
            .build()
    };
    Ok(match name.as_str() {
        "ellipse" => curve(ExactShape::Ellipse, presets::ellipse(DVec2::ZERO, a, b)),
        "circle" => curve(ExactShape::Circle, presets::circle(DVec2::ZERO, radius)),
        "parabola" => curve(
            ExactShape::Parabola,
            presets::parabola(DVec2::new(0.0, 2.0), DVec2::new(-1.5, -0.5), DVec2::new(1.5, -0.5)),
        ),
        "sine" => curve(ExactShape::Sine, presets::sine(-0.5 * (segs as f64 + 2.0), 1.0, 0.5, segs)),
        "sphere" => surface(
            presets::sphere(radius),
            Out::new().ser("centre", &[0.0, 0.0, 0.0]).num("radius", radius),
        ),
        "cylinder" => surface(
            presets::cylinder(radius, height),
            Out::new().ser("axis", &[0.0, 0.0, 1.0]).num("radius", radius),
        ),
        "torus" => surface(presets::torus(major, minor), Out::new().num("major", major).num("minor", minor)),
        "bowl" => surface(presets::bowl(), Out::new()),
        "wavy" => surface(presets::wavy_grid(m, n), Out::new()),
        other => {
            return Err(err_kind(ErrorKind::Invalid,
                "name",
                format!("unknown preset \"{other}\"; expected ellipse, circle, parabola, sine, sphere, cylinder, torus, bowl or wavy"),
            ))
        }
    })
}

/// `shape` of `quasiCubicShapeCheck`: one of the curve presets.
fn read_shape(o: &Opts, key: &'static str) -> ApiResult<ExactShape> {
    let name: String = o.req(key)?;
    ExactShape::parse(&name).ok_or_else(|| {
        err_kind(
            ErrorKind::Invalid,
            key,
            format!("expected \"ellipse\", \"circle\", \"parabola\" or \"sine\", got \"{name}\""),
        )
    })
}

/// Planar control points (the exact shapes are 2D).
fn planar_points(o: &Opts, key: &'static str) -> ApiResult<Vec<DVec2>> {
    match o.points(key, 0)? {
        Pts::D2(p) => Ok(p),
        Pts::D3(_) => Err(err_kind(
            ErrorKind::SizeMismatch,
            key,
            "the exact shapes are planar: expected [x, y] points",
        )),
    }
}

api_options! {
    /// A quasi-cubic curve and the exact shape it is checked against (`quasiCubicShapeCheck`).
    pub struct QuasiCubicShapeCheckOptions extends "FlatDim" |o| {
        /// The exact shape.
        shape: ExactShape = "shape", req "QuasiCubicCurvePresetName" => |k| read_shape(o, k)?;
        /// α ∈ [−3, 3] (default: the shape's).
        alpha: f64 = "alpha", opt "number" => |k| read_alpha(o, k, shape.alpha())?;
        /// Samples per segment (default 200, at most 10,000).
        samples: usize = "samples", opt "number" => |k| o.usize_or(k, 200, 10_000)?;
        /// 2D control points.
        points: Vec<DVec2> = "points", req "Points" => |k| planar_points(o, k)?;
    }
}

#[wasm_bindgen(typescript_custom_section)]
const QUASI_CUBIC_SHAPE_CHECK_TS: &str = r#"
export interface QuasiCubicShapeCheckResult {
  deviation: number;
  conditionResidual: number;
  segmentResiduals: Float64Array;
  alphaOk: boolean;
  condition: string;
  analytic: Float64Array;
  params: Float64Array;
}
"#;

/// How far a quasi-cubic curve is from the exact shape its control points define.
///
/// `quasiCubicShapeCheck({ shape, points, alpha, samples })` → `{ deviation, conditionResidual, alphaOk,
/// condition, analytic, params }`.
#[wasm_bindgen(js_name = quasiCubicShapeCheck, unchecked_return_type = "QuasiCubicShapeCheckResult")]
pub fn quasi_cubic_shape_check(
    #[wasm_bindgen(unchecked_param_type = "QuasiCubicShapeCheckOptions")] options: JsValue,
) -> ApiResult<JsValue> {
    let o = Opts::new(options)?;
    let QuasiCubicShapeCheckOptions {
        shape,
        alpha: a,
        samples: per,
        points: pts,
    } = QuasiCubicShapeCheckOptions::read(&o)?;
    if pts.len().saturating_mul(per) > MAX_EVAL_POINTS {
        return Err(err_kind(
            ErrorKind::TooMany,
            "samples",
            "points × samples exceeds 1,000,000 evaluations",
        ));
    }
    let chk = check_shape(shape, a, &pts, per).map_err(core_err)?;
    Ok(Out::new()
        .num("deviation", chk.deviation)
        .num("conditionResidual", chk.condition_residual)
        .f64s("segmentResiduals", &chk.segment_residuals)
        .set("alphaOk", chk.alpha_ok)
        .ser("condition", shape.condition())
        .pts("analytic", &chk.analytic)
        .f64s("params", &chk.params)
        .build())
}
