//! The JavaScript bindings: the only module that knows about wasm-bindgen.
//!
//! Every export takes **one options object** and returns a **plain object** with `Float64Array`s
//! (`../shared/spec/api.md`). This module holds the shared conventions:
//! * [`Opts`] reads fields of the options object, each with a message naming the field on failure;
//! * [`Pts`] is a validated list of 2D or 3D points (dispatch with [`with_points!`]);
//! * [`Out`] builds the result object; [`curve_result`] / [`surface_result`] give the common shapes;
//! * [`readers`] reads the option fields that more than one binding module takes (tensions, the B2 options, curve
//!   networks, the compatibility tolerance), so that no binding module imports another.
//!
//! Failures are `JsError`s: a JS `Error` with the message `"<field>: <what was expected>"` and the
//! properties `.field` and `.kind` ([`errors`]). Nothing here keeps state, so a failed call leaves the
//! module fully usable.

// A split build (not `all`) leaves some shared helpers without a caller.
#![cfg_attr(not(feature = "all"), allow(dead_code, unused_imports, unused_macros))]

use crate::error::{Error, ErrorKind};
use crate::point::Point;
use crate::sample::MAX_INPUT_POINTS;
use glam::{DVec2, DVec3};
use wasm_bindgen::prelude::*;

// The binding modules are gated by cargo features (Cargo.toml `[features]`) so that scripts/build-wasm.sh can
// build one smaller wasm module per group of demos; the default feature `all` builds every export. The core is
// never gated: the linker drops what no export reaches.
#[cfg(feature = "api-b2-surface")]
pub mod b2;
#[cfg(feature = "api-bezier")]
pub mod bezier;
#[cfg(feature = "api-bspline")]
pub mod bspline;
pub mod errors;
#[cfg(feature = "api-exercise")]
pub mod exercise;
#[cfg(feature = "api-fit")]
pub mod fit;
#[cfg(feature = "api-gordon-core")]
pub mod gordon;
#[cfg(feature = "api-knot-paths")]
pub mod knot_paths;
pub mod mesh;
#[cfg(feature = "api-network-core")]
pub mod network;
#[cfg(feature = "api-quasi-cubic")]
pub mod quasi_cubic;

/// Result type of every export.
pub type ApiResult<T> = Result<T, JsError>;

// The shared conventions, one concept per file (re-exported so the paths stay `api::Opts`, …).
mod opts;
mod out;
pub mod schema;
// Not gated: the readers every group's bindings may share (the linker drops those no export of a group calls).
pub mod readers;
pub use opts::Opts;
pub use out::{
    curve_result, curve_result_curvature, curve_result_for, rows_out, surface_result, Out,
};
pub use schema::api_options;

pub use errors::err_kind;

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
    rows_to_pts_named(field, rows, min, |i| format!("{field}[{i}]"))
}

/// [`rows_to_pts`] where `point(i)` names point `i` in errors (a grid's point `i` is `grid[row][col]`).
pub fn rows_to_pts_named(
    field: &str,
    rows: &[Vec<f64>],
    min: usize,
    point: impl Fn(usize) -> String,
) -> ApiResult<Pts> {
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
        return Err(err_kind(
            ErrorKind::WrongType,
            &point(0),
            format!("expected [x, y] or [x, y, z], got {dim} numbers"),
        ));
    }
    for (i, r) in rows.iter().enumerate() {
        if r.len() != dim {
            return Err(err_kind(
                ErrorKind::SizeMismatch,
                &point(i),
                format!(
                    "all points must have the same dimension ({dim}), got {} numbers",
                    r.len()
                ),
            ));
        }
        if let Some(k) = r.iter().position(|x| !x.is_finite()) {
            return Err(err_kind(
                ErrorKind::NotFinite,
                &format!("{}[{k}]", point(i)),
                crate::error::not_finite_detail(r[k]),
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
        return Err(err_kind(
            ErrorKind::Invalid,
            field,
            format!(
                "flat coordinates need a multiple of dim = {dim} numbers, got {}",
                xs.len()
            ),
        ));
    }
    let n = xs.len() / dim;
    if n < min {
        return Err(err_kind(
            ErrorKind::TooFew,
            field,
            format!("need at least {min} points, got {n}"),
        ));
    }
    if n > MAX_INPUT_POINTS {
        return Err(err_kind(
            ErrorKind::TooMany,
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
        Pts::D2(_) => Err(err_kind(
            ErrorKind::SizeMismatch,
            field,
            "expected 3D points [x, y, z]",
        )),
    }
}

/// Calls a JS function `f(u, v)` that must return `[x, y, z]` of finite numbers; `field` names it.
pub fn call_point_fn(field: &str, f: &js_sys::Function, u: f64, v: f64) -> ApiResult<DVec3> {
    let r = f
        .call2(&JsValue::NULL, &JsValue::from_f64(u), &JsValue::from_f64(v))
        .map_err(|e| {
            err_kind(
                ErrorKind::Invalid,
                field,
                format!("the function threw: {}", js_to_string(&e)),
            )
        })?;
    let arr: Vec<f64> = serde_wasm_bindgen::from_value(r).map_err(|_| {
        err_kind(
            ErrorKind::WrongType,
            field,
            "the function must return [x, y, z]; it did not",
        )
    })?;
    if arr.len() != 3 || arr.iter().any(|x| !x.is_finite()) {
        let kind = if arr.len() != 3 {
            ErrorKind::WrongType
        } else {
            ErrorKind::NotFinite
        };
        return Err(err_kind(
            kind,
            field,
            format!(
                "the function must return 3 finite numbers [x, y, z]; it returned {} numbers{}",
                arr.len(),
                if arr.len() == 3 {
                    ", not all finite"
                } else {
                    ""
                }
            ),
        ));
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
