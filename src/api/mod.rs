//! The JavaScript bindings: the only module that knows about wasm-bindgen.
//!
//! Every export takes **one options object** and returns a **plain object** with `Float64Array`s
//! (`../shared/spec/api.md`). This module holds the shared conventions:
//! * [`Opts`] reads fields of the options object, each with a message naming the field on failure;
//! * [`Pts`] is a validated list of 2D or 3D points (dispatch with [`with_points!`]);
//! * [`Out`] builds the result object; [`curve_result`] / [`surface_result`] give the common shapes.
//!
//! Failures are `JsError`s: a JS `Error` with the message `"<field>: <what was expected>"` and the
//! properties `.field` and `.kind` ([`errors`]). Nothing here keeps state, so a failed call leaves the
//! module fully usable.

// A split build (not `all`) leaves some shared helpers without a caller.
#![cfg_attr(not(feature = "all"), allow(dead_code, unused_imports, unused_macros))]

use crate::error::{Error, ErrorKind};
use crate::point::Point;
use crate::sample::{self, Curve, Surface, MAX_EVAL_POINTS, MAX_INPUT_POINTS};
use glam::{DVec2, DVec3};
use js_sys::{Array, Float64Array, Object, Reflect};
use serde::de::DeserializeOwned;
use wasm_bindgen::prelude::*;

// The binding modules are gated by cargo features (Cargo.toml `[features]`) so that scripts/build-wasm.sh can
// build one smaller wasm module per group of demos; the default feature `all` builds every export. The core is
// never gated: the linker drops what no export reaches.
#[cfg(feature = "api-b2")]
pub mod b2;
#[cfg(feature = "api-bezier")]
pub mod bezier;
#[cfg(feature = "api-bspline")]
pub mod bspline;
pub mod errors;
#[cfg(feature = "api-fit")]
pub mod fit;
#[cfg(feature = "api-gordon")]
pub mod gordon;
#[cfg(feature = "api-knot-paths")]
pub mod knot_paths;
pub mod mesh;
#[cfg(feature = "api-network")]
pub mod network;
#[cfg(feature = "api-quasi-cubic")]
pub mod quasi_cubic;

/// Result type of every export.
pub type ApiResult<T> = Result<T, JsError>;

/// A `JsError` with the message `"<field>: <detail>"`, `.field` and a `.kind` derived from the wording
/// of `detail` ([`errors::kind_of_detail`]); [`errors::err_kind`] states the kind instead.
pub fn err(field: &str, detail: impl std::fmt::Display) -> JsError {
    let detail = detail.to_string();
    errors::err_kind(errors::kind_of_detail(&detail), field, detail)
}

/// Converts a core error (its `Display` already names the field; its kind becomes `.kind`).
pub fn core_err(e: Error) -> JsError {
    errors::to_js(&e)
}

/// A list of points of one dimension, 2 or 3.
pub enum Pts {
    /// Points `[x, y]`.
    D2(Vec<DVec2>),
    /// Points `[x, y, z]`.
    D3(Vec<DVec3>),
}

impl Pts {
    /// The number of points.
    pub fn len(&self) -> usize {
        match self {
            Pts::D2(p) => p.len(),
            Pts::D3(p) => p.len(),
        }
    }
    /// Whether there are no points.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }
    /// The dimension, 2 or 3.
    pub fn dim(&self) -> usize {
        match self {
            Pts::D2(_) => 2,
            Pts::D3(_) => 3,
        }
    }
}

/// Runs `$body` with `$p` bound to the `Vec<DVec2>` or `Vec<DVec3>` inside a [`Pts`].
#[macro_export]
macro_rules! with_points {
    ($pts:expr, $p:ident => $body:expr) => {
        match $pts {
            $crate::api::Pts::D2($p) => $body,
            $crate::api::Pts::D3($p) => $body,
        }
    };
}
pub use with_points;

/// Flattens points to `[x0, y0, (z0,) x1, …]`.
pub fn flat<P: Point>(pts: &[P]) -> Vec<f64> {
    let mut out = vec![0.0; pts.len() * P::DIM];
    for (i, p) in pts.iter().enumerate() {
        p.write_coords(&mut out[i * P::DIM..]);
    }
    out
}

/// Validates raw coordinate rows (`field` names them) into points of one dimension (2 or 3).
pub fn rows_to_pts(field: &str, rows: &[Vec<f64>], min: usize) -> ApiResult<Pts> {
    if rows.len() < min {
        return Err(errors::too_few(
            field,
            min,
            rows.len(),
            format!("need at least {min} points, got {}", rows.len()),
        ));
    }
    if rows.len() > MAX_INPUT_POINTS {
        return Err(errors::too_many(
            field,
            MAX_INPUT_POINTS,
            rows.len(),
            format!("at most {MAX_INPUT_POINTS} points, got {}", rows.len()),
        ));
    }
    let dim = rows.first().map_or(2, |r| r.len());
    if dim != 2 && dim != 3 {
        return Err(err(
            &format!("{field}[0]"),
            format!("expected [x, y] or [x, y, z], got {dim} numbers"),
        ));
    }
    for (i, r) in rows.iter().enumerate() {
        if r.len() != dim {
            return Err(err(
                &format!("{field}[{i}]"),
                format!(
                    "all points must have the same dimension ({dim}), got {} numbers",
                    r.len()
                ),
            ));
        }
        if let Some(k) = r.iter().position(|x| !x.is_finite()) {
            return Err(err(
                &format!("{field}[{i}][{k}]"),
                format!("expected a finite number, got {}", r[k]),
            ));
        }
    }
    Ok(if dim == 2 {
        Pts::D2(rows.iter().map(|r| DVec2::new(r[0], r[1])).collect())
    } else {
        Pts::D3(rows.iter().map(|r| DVec3::new(r[0], r[1], r[2])).collect())
    })
}

/// Validates flat coordinates (`dim` per point, finite already checked) into points (`field` names them).
pub fn flat_to_pts(field: &str, xs: &[f64], dim: usize, min: usize) -> ApiResult<Pts> {
    if !xs.len().is_multiple_of(dim) {
        return Err(err(
            field,
            format!(
                "flat coordinates need a multiple of dim = {dim} numbers, got {}",
                xs.len()
            ),
        ));
    }
    let n = xs.len() / dim;
    if n < min {
        return Err(err(field, format!("need at least {min} points, got {n}")));
    }
    if n > MAX_INPUT_POINTS {
        return Err(err(
            field,
            format!("at most {MAX_INPUT_POINTS} points, got {n}"),
        ));
    }
    Ok(if dim == 2 {
        Pts::D2(xs.chunks_exact(2).map(|c| DVec2::new(c[0], c[1])).collect())
    } else {
        Pts::D3(
            xs.chunks_exact(3)
                .map(|c| DVec3::new(c[0], c[1], c[2]))
                .collect(),
        )
    })
}

/// Validates raw 3D coordinate rows.
pub fn rows_to_3d(field: &str, rows: &[Vec<f64>]) -> ApiResult<Vec<DVec3>> {
    match rows_to_pts(field, rows, 0)? {
        Pts::D3(p) => Ok(p),
        Pts::D2(_) if rows.is_empty() => Ok(Vec::new()),
        Pts::D2(_) => Err(err(field, "expected 3D points [x, y, z]")),
    }
}

/// The options object of one call.
pub struct Opts {
    obj: JsValue,
}

impl Opts {
    /// Wraps the single argument of an export; it must be an object.
    pub fn new(v: JsValue) -> ApiResult<Self> {
        if !v.is_object() || v.is_function() || Array::is_array(&v) {
            return Err(err(
                "options",
                "expected one options object, e.g. { points: [[0,0],[1,1],…] }",
            ));
        }
        Ok(Opts { obj: v })
    }

    /// The raw value of `key` (`undefined` when absent).
    pub fn raw(&self, key: &str) -> JsValue {
        Reflect::get(&self.obj, &JsValue::from_str(key)).unwrap_or(JsValue::UNDEFINED)
    }

    /// Whether `key` is present and neither `undefined` nor `null`.
    pub fn has(&self, key: &str) -> bool {
        let v = self.raw(key);
        !(v.is_undefined() || v.is_null())
    }

    /// Deserializes `key` if present (`undefined`/`null` give `None`).
    pub fn opt<T: DeserializeOwned>(&self, key: &str) -> ApiResult<Option<T>> {
        let v = self.raw(key);
        if v.is_undefined() || v.is_null() {
            return Ok(None);
        }
        check_array_sizes(key, &v, 0)?;
        if Array::is_array(&v) && v.unchecked_ref::<Array>().length() > 1000 {
            // A large array where something else is expected (a name, an object): serde's message
            // would format the whole array (seconds for 10⁵ entries). A two-entry probe fails the same
            // way, cheaply; for sequence types it passes and the full read follows.
            let probe: JsValue = v.unchecked_ref::<Array>().slice(0, 2).into();
            serde_wasm_bindgen::from_value::<T>(probe)
                .map_err(|e| err(key, format!("wrong type ({e})")))?;
        }
        serde_wasm_bindgen::from_value(v)
            .map(Some)
            .map_err(|e| err(key, format!("wrong type ({e})")))
    }

    /// Deserializes the required field `key`.
    pub fn req<T: DeserializeOwned>(&self, key: &str) -> ApiResult<T> {
        self.opt(key)?
            .ok_or_else(|| err(key, "this field is required"))
    }

    /// A finite number, or `default` when absent.
    pub fn f64_or(&self, key: &str, default: f64) -> ApiResult<f64> {
        let v = self.raw(key);
        if v.is_undefined() || v.is_null() {
            return Ok(default);
        }
        let x = v.as_f64().ok_or_else(|| err(key, "expected a number"))?;
        if !x.is_finite() {
            return Err(err(key, format!("expected a finite number, got {x}")));
        }
        Ok(x)
    }

    /// A non-negative integer ≤ `max`, or `default` when absent.
    pub fn usize_or(&self, key: &str, default: usize, max: usize) -> ApiResult<usize> {
        let v = self.raw(key);
        if v.is_undefined() || v.is_null() {
            return Ok(default);
        }
        let x = v
            .as_f64()
            .ok_or_else(|| err(key, "expected a whole number"))?;
        if !x.is_finite() || x < 0.0 || x.fract() != 0.0 {
            return Err(err(key, format!("expected a whole number ≥ 0, got {x}")));
        }
        if x > max as f64 {
            return Err(err(key, format!("at most {max}, got {x}")));
        }
        Ok(x as usize)
    }

    /// A boolean, or `default` when absent.
    pub fn bool_or(&self, key: &str, default: bool) -> ApiResult<bool> {
        let v = self.raw(key);
        if v.is_undefined() || v.is_null() {
            return Ok(default);
        }
        v.as_bool()
            .ok_or_else(|| err(key, "expected true or false"))
    }

    /// A finite number array (e.g. knots), or `None` when absent.
    pub fn f64s(&self, key: &str) -> ApiResult<Option<Vec<f64>>> {
        let v: Option<Vec<f64>> = self.opt(key)?;
        if let Some(xs) = &v {
            if let Some(i) = xs.iter().position(|x| !x.is_finite()) {
                return Err(err(
                    &format!("{key}[{i}]"),
                    format!("expected a finite number, got {}", xs[i]),
                ));
            }
        }
        Ok(v)
    }

    /// Points `[[x, y], …]` or `[[x, y, z], …]`, at least `min` of them; or flat coordinates
    /// `[x0, y0, x1, y1, …]` as a `Float64Array` (or a plain array of numbers), read in one copy, with the
    /// dimension from the option `dim` (2 or 3, default 2).
    pub fn points(&self, key: &str, min: usize) -> ApiResult<Pts> {
        // the input limit is checked before deserializing (reading 10⁶ rows costs seconds)
        let raw = self.raw(key);
        if let Some(flat) = self.flat_numbers(key, &raw, MAX_INPUT_POINTS * 3)? {
            let dim = self.usize_or("dim", 2, 3)?;
            if dim < 2 {
                return Err(err("dim", format!("expected 2 or 3, got {dim}")));
            }
            return flat_to_pts(key, &flat, dim, min);
        }
        if Array::is_array(&raw) {
            let n = raw.unchecked_ref::<Array>().length() as usize;
            if n > MAX_INPUT_POINTS {
                return Err(errors::too_many(
                    key,
                    MAX_INPUT_POINTS,
                    n,
                    format!("at most {MAX_INPUT_POINTS} points, got {n}"),
                ));
            }
        }
        let rows: Vec<Vec<f64>> = self.req(key)?;
        rows_to_pts(key, &rows, min)
    }

    /// A grid `grid[i][j] = [x, y(, z)]`, rectangular, of one dimension; returns (rows, cols, points
    /// row-major).
    pub fn grid(
        &self,
        key: &str,
        min_rows: usize,
        min_cols: usize,
    ) -> ApiResult<(usize, usize, Pts)> {
        // the input limit (rows × first row) is checked before deserializing
        let raw = self.raw(key);
        if Array::is_array(&raw) {
            let a: &Array = raw.unchecked_ref();
            let first = a.get(0);
            let cols = if Array::is_array(&first) {
                first.unchecked_ref::<Array>().length() as usize
            } else {
                0
            };
            let n = (a.length() as usize).saturating_mul(cols.max(1));
            if n > MAX_INPUT_POINTS {
                return Err(err(
                    key,
                    format!(
                        "at most {MAX_INPUT_POINTS} points, got {} rows of {cols}",
                        a.length()
                    ),
                ));
            }
        }
        let rows: Vec<Vec<Vec<f64>>> = self.req(key)?;
        let nr = rows.len();
        if nr < min_rows {
            return Err(err(key, format!("need at least {min_rows} rows, got {nr}")));
        }
        let nc = rows[0].len();
        if nc < min_cols {
            return Err(err(
                &format!("{key}[0]"),
                format!("need at least {min_cols} points per row, got {nc}"),
            ));
        }
        if let Some(i) = rows.iter().position(|r| r.len() != nc) {
            return Err(err(
                &format!("{key}[{i}]"),
                format!("rows must all have {nc} points, got {}", rows[i].len()),
            ));
        }
        let flat_rows: Vec<Vec<f64>> = rows.into_iter().flatten().collect();
        let pts = rows_to_pts(key, &flat_rows, 0)?;
        Ok((nr, nc, pts))
    }

    /// The numbers of `raw` when it is a `Float64Array` (one copy) or a plain array whose first entry is a
    /// number (flat coordinates), else `None` (nested arrays take the serde path). Entries must be finite
    /// (`key[i]` names a bad one); at most `max` of them.
    fn flat_numbers(&self, key: &str, raw: &JsValue, max: usize) -> ApiResult<Option<Vec<f64>>> {
        let xs = if let Some(ta) = raw.dyn_ref::<Float64Array>() {
            if ta.length() as usize > max {
                return Err(err(
                    key,
                    format!(
                        "array too long ({} numbers; the limit is {max})",
                        ta.length()
                    ),
                ));
            }
            ta.to_vec()
        } else if Array::is_array(raw) {
            let a: &Array = raw.unchecked_ref();
            if a.length() == 0 || a.get(0).as_f64().is_none() {
                return Ok(None);
            }
            if a.length() as usize > max {
                return Err(err(
                    key,
                    format!(
                        "array too long ({} numbers; the limit is {max})",
                        a.length()
                    ),
                ));
            }
            serde_wasm_bindgen::from_value::<Vec<f64>>(raw.clone())
                .map_err(|e| err(key, format!("wrong type ({e})")))?
        } else {
            return Ok(None);
        };
        if let Some(i) = xs.iter().position(|x| !x.is_finite()) {
            return Err(err(
                &format!("{key}[{i}]"),
                format!("expected a finite number, got {}", xs[i]),
            ));
        }
        Ok(Some(xs))
    }

    /// Whether the curve parameters are the uniform `samples` (not `at`): the kernel's uniform sampler
    /// applies.
    pub fn uniform_samples(&self) -> bool {
        !self.has("at")
    }

    /// `derivatives: 0 | 1 | … | max` (default 0).
    pub fn derivatives(&self, max: usize) -> ApiResult<usize> {
        self.usize_or("derivatives", 0, max)
    }

    /// A JS function field.
    pub fn function(&self, key: &str) -> ApiResult<js_sys::Function> {
        let v = self.raw(key);
        v.dyn_into::<js_sys::Function>()
            .map_err(|_| err(key, "expected a function"))
    }

    /// Curve parameters: `at` (in the given order, finite) or `samples` (uniform over `domain`, default 200).
    pub fn curve_params(&self, domain: (f64, f64)) -> ApiResult<Vec<f64>> {
        if self.has("at") {
            let raw = self.raw("at");
            if let Some(ta) = raw.dyn_ref::<Float64Array>() {
                // a typed array: one copy, no per-entry crossing
                if ta.length() as usize > MAX_EVAL_POINTS {
                    return Err(err(
                        "at",
                        format!(
                            "at most {MAX_EVAL_POINTS} parameters per call, got {}",
                            ta.length()
                        ),
                    ));
                }
                let at = ta.to_vec();
                if let Some(i) = at.iter().position(|x| !x.is_finite()) {
                    return Err(err(
                        &format!("at[{i}]"),
                        format!("expected a finite number, got {}", at[i]),
                    ));
                }
                return Ok(at);
            }
            let at = self.f64s("at")?.unwrap_or_default();
            if at.len() > MAX_EVAL_POINTS {
                return Err(err(
                    "at",
                    format!(
                        "at most {MAX_EVAL_POINTS} parameters per call, got {}",
                        at.len()
                    ),
                ));
            }
            return Ok(at);
        }
        let n = self.usize_or("samples", 200, MAX_EVAL_POINTS)?;
        Ok(sample::uniform_params(domain.0, domain.1, n))
    }

    /// Surface parameters, flat `[u0, v0, u1, v1, …]`: `atUV` pairs, or the u-major grid
    /// `samplesU × samplesV` (default 40 each) over `domain`.
    pub fn surface_uv(&self, domain: ((f64, f64), (f64, f64))) -> ApiResult<Vec<f64>> {
        if self.has("atUV") {
            let raw = self.raw("atUV");
            // flat pairs [u0, v0, u1, v1, …] (a Float64Array or plain numbers): one copy
            if let Some(uv) = self.flat_numbers("atUV", &raw, 2 * MAX_EVAL_POINTS)? {
                if !uv.len().is_multiple_of(2) {
                    return Err(err(
                        "atUV",
                        format!(
                            "flat (u, v) pairs need an even count of numbers, got {}",
                            uv.len()
                        ),
                    ));
                }
                return Ok(uv);
            }
            let pairs: Vec<Vec<f64>> = self.req("atUV")?;
            if pairs.len() > MAX_EVAL_POINTS {
                return Err(err(
                    "atUV",
                    format!(
                        "at most {MAX_EVAL_POINTS} pairs per call, got {}",
                        pairs.len()
                    ),
                ));
            }
            let mut uv = Vec::with_capacity(2 * pairs.len());
            for (i, p) in pairs.iter().enumerate() {
                if p.len() != 2 || !p[0].is_finite() || !p[1].is_finite() {
                    return Err(err(
                        &format!("atUV[{i}]"),
                        "expected a pair of finite numbers [u, v]",
                    ));
                }
                uv.extend_from_slice(p);
            }
            return Ok(uv);
        }
        let nu = self.usize_or("samplesU", 40, MAX_EVAL_POINTS)?;
        let nv = self.usize_or("samplesV", 40, MAX_EVAL_POINTS)?;
        if nu.saturating_mul(nv) > MAX_EVAL_POINTS {
            return Err(err(
                "samplesU",
                format!("samplesU × samplesV must be at most {MAX_EVAL_POINTS}, got {nu} × {nv}"),
            ));
        }
        Ok(sample::uv_grid(domain, nu, nv))
    }
}

/// Rejects arrays (and nested arrays, one level) longer than the input limit before deserializing them.
fn check_array_sizes(key: &str, v: &JsValue, depth: usize) -> ApiResult<()> {
    const LIMIT: u32 = MAX_EVAL_POINTS as u32;
    if Array::is_array(v) {
        let a: &Array = v.unchecked_ref();
        if a.length() > LIMIT {
            return Err(err(
                key,
                format!(
                    "array too long ({} entries; the limit is {LIMIT})",
                    a.length()
                ),
            ));
        }
        if depth == 0 && a.length() > 0 {
            check_array_sizes(key, &a.get(0), 1)?;
        }
    }
    Ok(())
}

/// Builder of a plain result object.
pub struct Out(Object);

impl Default for Out {
    fn default() -> Self {
        Self::new()
    }
}

impl Out {
    /// An empty result object.
    pub fn new() -> Self {
        Out(Object::new())
    }
    /// Sets any JS value.
    pub fn set(self, key: &str, v: impl Into<JsValue>) -> Self {
        let _ = Reflect::set(&self.0, &JsValue::from_str(key), &v.into());
        self
    }
    /// Sets a number.
    pub fn num(self, key: &str, x: f64) -> Self {
        self.set(key, x)
    }
    /// Sets a `Float64Array` copy of `xs` (one allocation, filled from wasm memory; not zeroed first).
    pub fn f64s(self, key: &str, xs: &[f64]) -> Self {
        let arr = Float64Array::from(xs);
        self.set(key, arr)
    }
    /// Sets a `Float64Array` of flattened points.
    pub fn pts<P: Point>(self, key: &str, pts: &[P]) -> Self {
        self.f64s(key, &flat(pts))
    }
    /// Sets a `Float32Array` copy of `xs` (render buffers).
    pub fn f32s(self, key: &str, xs: &[f32]) -> Self {
        let arr = js_sys::Float32Array::new_with_length(xs.len() as u32);
        arr.copy_from(xs);
        self.set(key, arr)
    }
    /// Sets a `Uint32Array` copy of `xs` (index buffers).
    pub fn u32s(self, key: &str, xs: &[u32]) -> Self {
        let arr = js_sys::Uint32Array::new_with_length(xs.len() as u32);
        arr.copy_from(xs);
        self.set(key, arr)
    }
    /// Sets a serde-serializable value (plain arrays/objects).
    pub fn ser<T: serde::Serialize + ?Sized>(self, key: &str, v: &T) -> Self {
        let js = serde_wasm_bindgen::to_value(v).unwrap_or(JsValue::NULL);
        self.set(key, js)
    }
    /// The finished JS object.
    pub fn build(self) -> JsValue {
        self.0.into()
    }
}

/// The common curve result `{ dim, params, points, d1?, d2? }`.
pub fn curve_result<P: Point, C: Curve<P> + ?Sized>(
    curve: &C,
    params: &[f64],
    order: usize,
) -> Out {
    let (pts, d1, d2) = sample::eval_curve(curve, params, order);
    let mut out = Out::new()
        .num("dim", P::DIM as f64)
        .f64s("params", params)
        .f64s("points", &pts);
    if order >= 1 {
        out = out.f64s("d1", &d1);
    }
    if order >= 2 {
        out = out.f64s("d2", &d2);
    }
    out
}

/// [`curve_result`] for the sampling options in `o`: uniform `samples` at order 0 go through the kernel's
/// uniform sampler ([`sample::eval_curve_uniform`]: forward differences for cubics), with derivatives
/// through [`Curve::sample_uniform_derivs_into`] (the quasi-cubic rotation recurrence).
pub fn curve_result_for<P: Point, C: Curve<P> + ?Sized>(
    o: &Opts,
    curve: &C,
    params: &[f64],
    order: usize,
) -> Out {
    if order == 0 && o.uniform_samples() {
        let pts = sample::eval_curve_uniform(curve, params.len());
        return Out::new()
            .num("dim", P::DIM as f64)
            .f64s("params", params)
            .f64s("points", &pts);
    }
    if o.uniform_samples() {
        let (n, dim) = (params.len(), P::DIM);
        let order = order.min(2);
        let mut pts = vec![0.0; n * dim];
        let mut d1 = vec![0.0; if order >= 1 { n * dim } else { 0 }];
        let mut d2 = vec![0.0; if order >= 2 { n * dim } else { 0 }];
        curve.sample_uniform_derivs_into(n, order, &mut pts, &mut d1, &mut d2);
        let mut out = Out::new()
            .num("dim", dim as f64)
            .f64s("params", params)
            .f64s("points", &pts);
        if order >= 1 {
            out = out.f64s("d1", &d1);
        }
        if order >= 2 {
            out = out.f64s("d2", &d2);
        }
        return out;
    }
    curve_result(curve, params, order)
}

/// The common surface result `{ dim, uv, points, du?, dv? }`.
pub fn surface_result<P: Point, S: Surface<P> + ?Sized>(
    surface: &S,
    uv: &[f64],
    derivs: bool,
) -> Out {
    let (pts, du, dv) = sample::eval_surface(surface, uv, derivs);
    let mut out = Out::new()
        .num("dim", P::DIM as f64)
        .f64s("uv", uv)
        .f64s("points", &pts);
    if derivs {
        out = out.f64s("du", &du).f64s("dv", &dv);
    }
    out
}

/// Calls a JS function `f(u, v)` that must return `[x, y, z]` of finite numbers; `field` names it.
pub fn call_point_fn(field: &str, f: &js_sys::Function, u: f64, v: f64) -> ApiResult<DVec3> {
    let r = f
        .call2(&JsValue::NULL, &JsValue::from_f64(u), &JsValue::from_f64(v))
        .map_err(|e| {
            err(
                field,
                format!("the function threw at ({u}, {v}): {}", js_to_string(&e)),
            )
        })?;
    let arr: Vec<f64> = serde_wasm_bindgen::from_value(r).map_err(|_| {
        err(
            field,
            format!("the function must return [x, y, z]; at ({u}, {v}) it did not"),
        )
    })?;
    if arr.len() != 3 || arr.iter().any(|x| !x.is_finite()) {
        let kind = if arr.len() != 3 {
            ErrorKind::WrongType
        } else {
            ErrorKind::NotFinite
        };
        return Err(errors::err_kind(kind, field, format!("the function must return 3 finite numbers [x, y, z]; at ({u}, {v}) it returned {arr:?}")));
    }
    Ok(DVec3::new(arr[0], arr[1], arr[2]))
}

/// A short string of any JS value (for messages).
pub fn js_to_string(v: &JsValue) -> String {
    if let Some(e) = v.dyn_ref::<js_sys::Error>() {
        return String::from(e.message());
    }
    v.as_string().unwrap_or_else(|| format!("{v:?}"))
}

/// The library version (`splinelab.version()`).
#[wasm_bindgen]
pub fn version() -> String {
    env!("CARGO_PKG_VERSION").to_string()
}
