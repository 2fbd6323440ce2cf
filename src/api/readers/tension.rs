//! The tension of a B2-spline: `tension` (`b2Curve`, `b2Basis`, `b2Fit`, …) and `tensionU` / `tensionV`
//! (`b2Surface`, `splineBlendedSurface`).

use crate::api::{err_kind, ApiResult, Opts};
use crate::b2spline::Tension;
use crate::error::ErrorKind;
use js_sys::Array;
use wasm_bindgen::prelude::*;

#[wasm_bindgen(typescript_custom_section)]
const TENSION_TS: &str = r#"
/** A number or one per vertex p_0..p_n. */
export type Tension = number | Numbers;
"#;

/// Reads a tension field at `key`: absent or `null` gives `default`, a finite number one tension for all
/// vertices, an array of numbers one per vertex (their count and values are checked by the core).
///
/// Errors: a number that is not finite (`not-finite`), anything else neither a number nor an array
/// (`wrong-type`, "expected a number or an array of numbers p₀..pₙ"); an array as `Opts::f64s` reads it.
pub fn read_tension(o: &Opts, key: &str, default: f64) -> ApiResult<Tension> {
    let v = o.raw(key);
    if v.is_undefined() || v.is_null() {
        return Ok(Tension::Scalar(default));
    }
    if let Some(x) = o.finite_if_number(key)? {
        return Ok(Tension::Scalar(x));
    }
    if Array::is_array(&v) {
        return Ok(Tension::PerVertex(o.f64s(key)?.unwrap_or_default()));
    }
    Err(err_kind(
        ErrorKind::WrongType,
        key,
        "expected a number or an array of numbers p₀..pₙ",
    ))
}
