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
//! One concept per file, none of which imports this one: `opts.rs` ([`Opts`]), `out.rs` ([`Out`]), `points.rs`
//! ([`Pts`], [`flat`]), `errors.rs` ([`ApiResult`], [`core_err`], [`err_kind`]), `schema.rs` ([`api_options!`]).
//!
//! Failures are `JsError`s: a JS `Error` with the message `"<field>: <what was expected>"` and the
//! properties `.field` and `.kind` ([`errors`]). Nothing here keeps state, so a failed call leaves the
//! module fully usable.

// A split build (not `all`) leaves some shared helpers without a caller.
#![cfg_attr(not(feature = "all"), allow(dead_code, unused_imports, unused_macros))]

use crate::error::ErrorKind;
use glam::DVec3;
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
#[cfg(feature = "api-facts")]
pub mod facts;
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

// The shared conventions, one concept per file (re-exported so the paths stay `api::Opts`, …).
mod opts;
mod out;
mod points;
pub mod schema;
// Not gated: the readers every group's bindings may share (the linker drops those no export of a group calls).
pub mod readers;
pub use opts::Opts;
pub use out::{
    curve_result, curve_result_curvature, curve_result_for, rows_out, surface_result, Out,
};
pub use schema::api_options;

pub use errors::{core_err, err_kind, ApiResult};
pub use points::{flat, flat_to_pts, rows_to_3d, rows_to_pts, rows_to_pts_named, with_points, Pts};

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
