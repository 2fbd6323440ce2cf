//! Writing results: [`Out`] builds the plain result object (typed arrays in one allocation each);
//! [`curve_result`], [`curve_result_for`] and [`surface_result`] give the common shapes.

use super::errors::ApiResult;
use super::opts::Opts;
use super::points::flat;
use crate::point::Point;
use crate::sample::{self, Curve, Surface};
use js_sys::{Float64Array, Object, Reflect};
use wasm_bindgen::prelude::*;

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

/// Parameters per block of [`curve_result`]'s evaluation (≤ 192 KB of scratch per output in 3D, so a
/// block is still in cache when it is copied out).
const BLOCK: usize = 8192;

/// The common curve result `{ dim, params, points, d1?, d2? }`.
///
/// Evaluated straight into the result's `Float64Array`s, block by block through a small scratch buffer
/// (no whole-result buffer in wasm memory: no zero-fill of it and no second pass over it); the curve's
/// piecewise polynomial ([`Curve::piecewise`]) is built once for all blocks.
pub fn curve_result<P: Point>(curve: &dyn Curve<P>, params: &[f64], order: usize) -> Out {
    let (n, dim) = (params.len(), P::DIM);
    let want = [true, order >= 1, order >= 2];
    let arrays = want.map(|w| w.then(|| Float64Array::new_with_length((n * dim) as u32)));
    let pp = curve.piecewise();
    let cap = n.min(BLOCK) * dim;
    let mut scratch = want.map(|w| vec![0.0; if w { cap } else { 0 }]);
    for (b, blk) in params.chunks(BLOCK).enumerate() {
        let m = blk.len() * dim;
        let [p0, p1, p2] = scratch.each_mut().map(|v| {
            let k = m.min(v.len());
            &mut v[..k]
        });
        match &pp {
            Some(pp) => pp.sample_into(blk, order.min(2), p0, p1, p2),
            None => curve.sample_into(blk, order, p0, p1, p2),
        }
        let from = (b * BLOCK * dim) as u32;
        for (arr, buf) in arrays.iter().zip(&scratch) {
            if let Some(arr) = arr {
                arr.subarray(from, from + m as u32).copy_from(&buf[..m]);
            }
        }
    }
    let [pts, d1, d2] = arrays;
    let mut out = Out::new().num("dim", dim as f64).f64s("params", params);
    for (key, arr) in [("points", pts), ("d1", d1), ("d2", d2)] {
        if let Some(arr) = arr {
            out = out.set(key, arr);
        }
    }
    out
}

/// `{ dim, params, points, d1?, d2? }` from evaluated buffers (derivatives up to `order`).
fn curve_out<P: Point>(params: &[f64], pts: &[f64], d1: &[f64], d2: &[f64], order: usize) -> Out {
    let mut out = Out::new()
        .num("dim", P::DIM as f64)
        .f64s("params", params)
        .f64s("points", pts);
    if order >= 1 {
        out = out.f64s("d1", d1);
    }
    if order >= 2 {
        out = out.f64s("d2", d2);
    }
    out
}

/// The curve result for the sampling options in `o` and, with `curvature: true`, `curvature` (κ at each
/// parameter; signed in 2D, ≥ 0 in 3D) and, in 2D, `normals` (unit left normals, flat) — what a curvature
/// plot or comb needs. The curve is evaluated once (values and both derivatives by the kernel's sampler);
/// curvature is computed from those buffers.
pub fn curve_result_curvature<P: Point>(
    c: &dyn Curve<P>,
    params: &[f64],
    order: usize,
    o: &Opts,
) -> ApiResult<Out> {
    if !o.bool_or("curvature", false)? {
        return Ok(curve_result_for(o, c, params, order));
    }
    let (pts, d1, d2) = sample::eval_curve(c, params, 2);
    let mut out = curve_out::<P>(params, &pts, &d1, &d2, order)
        .f64s("curvature", &sample::curvatures::<P>(&d1, &d2));
    if P::DIM == 2 {
        out = out.f64s("normals", &sample::left_normals(&d1));
    }
    Ok(out)
}

/// [`curve_result`] for the sampling options in `o`: uniform `samples` at order 0 go through the kernel's
/// uniform sampler ([`sample::eval_curve_uniform`]: forward differences for cubics), with derivatives
/// through [`Curve::sample_uniform_derivs_into`] (the quasi-cubic block sampler: a table of sines and cosines
/// per call, none per point).
pub fn curve_result_for<P: Point>(
    o: &Opts,
    curve: &dyn Curve<P>,
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
pub fn surface_result<P: Point>(surface: &dyn Surface<P>, uv: &[f64], derivs: bool) -> Out {
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

/// An `Array` of `Float64Array`s (one per row), e.g. the levels of de Boor's or de Casteljau's triangle.
pub fn rows_out(rows: impl IntoIterator<Item = Vec<f64>>) -> js_sys::Array {
    let arr = js_sys::Array::new();
    for r in rows {
        arr.push(&Float64Array::from(&r[..]));
    }
    arr
}
